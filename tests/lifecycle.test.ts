import { describe, expect, it } from 'vitest'
import { DEFAULT_PANEL, addPanel, createBallPhysics } from '../src/index'
import { clearBallRows } from '../src/world/balls'
import { HOT } from '../src/world/pathHot'
import { rng } from './helpers'

describe('entity lifecycle', () => {
  it('200,000 throws with finished balls removed: stores and ids stay bounded by the peak of live balls', () => {
    const sim = createBallPhysics()
    addPanel(sim)
    const rand = rng(77)
    const live = new Set<number>()
    let thrown = 0
    let peak = 0
    let maxId = 0
    const throwsPerStep = 50
    while (thrown < 200_000) {
      for (let i = 0; i < throwsPerStep; i++) {
        const b = sim.throwBall({ x: DEFAULT_PANEL.launch.x, y: DEFAULT_PANEL.launch.y, power: rand(), angle: (rand() - 0.5) * 1.2 })
        live.add(b)
        maxId = Math.max(maxId, b)
        thrown++
      }
      sim.step(1 / 60)
      for (const e of sim.drainEvents()) {
        if (e.type === 'capture' || e.type === 'rest') {
          sim.removeBall(e.ball)
          live.delete(e.ball)
        }
      }
      peak = Math.max(peak, live.size)
    }
    expect(peak).toBeLessThan(thrown / 50) // far fewer live at once than thrown
    // ids are recycled: the largest id stays near the peak of live entities (25 holes + balls)
    expect(maxId).toBeLessThanOrEqual(peak + 25 + throwsPerStep)
    expect(sim.world.capacity).toBeLessThanOrEqual(4096)
    expect(sim.balls().length).toBe(live.size)
  })

  it("clearBallRows zeroes every field of Ball, Path and the ball's path row, and a removed ball's rows are zeroed", () => {
    const sim = createBallPhysics()
    const w = sim.world
    const b = sim.addBall({ x: 10, y: 20, vx: 30, vy: 40 })
    const stores = { Ball: w.Ball, Path: w.Path } as unknown as Record<string, Record<string, Float64Array>>
    for (const [name, store] of Object.entries(stores)) {
      for (const key of Object.keys(store)) store[key]![b] = 7
      expect(Object.keys(store).length, name).toBeGreaterThan(5)
    }
    w.pathHot.fill(7, b * HOT, b * HOT + HOT)
    clearBallRows(w, b)
    for (const [name, store] of Object.entries(stores)) {
      for (const key of Object.keys(store)) expect(store[key]![b], `${name}.${key}`).toBe(0)
    }
    expect([...w.pathHot.subarray(b * HOT, b * HOT + HOT)]).toEqual(new Array(HOT).fill(0))
    // and through the API: a ball removed, its rows zeroed
    const c = sim.addBall({ x: 1, y: 2, vx: 3, vy: 4 })
    w.Path.markOther[c] = 9
    w.Ball.hero[c] = 1
    sim.removeBall(c)
    expect([w.Path.markOther[c], w.Ball.hero[c], w.Ball.x[c], w.Ball.live[c], w.pathHot[c * HOT]]).toEqual([0, 0, 0, 0, 0])
  })
})
