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

describe('stores that cannot grow', () => {
  it('an addBall whose stores fail to grow (out of memory) throws a RangeError naming the entity, and leaves no entity with Ball behind: the world steps on', async () => {
    const { createBallWorld, addBall, listBalls, runSchedule, DEFAULT_SCHEDULE } = await import('../src/ecs.js')
    const { query } = await import('bitecs')
    for (const contacts of ['off', 'on', 'fixed'] as const) {
      const w = createBallWorld({ BALL_COLLISIONS: contacts }, { capacity: 64 })
      while (w.capacity === 64) addBall(w, { x: 30 * listBalls(w).length, y: 100, vx: 50, vy: 0 })
      const before = listBalls(w).length
      const real = globalThis.Float64Array
      let failures = 0
      // the next growth's first Float64Array of its new size fails, as an exhausted heap would
      globalThis.Float64Array = new Proxy(real, {
        construct(target, args: [number]) {
          if (typeof args[0] === 'number' && args[0] >= 2 * w.capacity && failures === 0) {
            failures++
            throw new RangeError('Array buffer allocation failed')
          }
          return new target(...args)
        },
      })
      // fill up to the capacity, so the next ball grows the stores
      let err: unknown
      try {
        while (listBalls(w).length < w.capacity + 1) addBall(w, { x: 30 * (listBalls(w).length % 100), y: 200 + 30 * Math.floor(listBalls(w).length / 100), vx: 50, vy: 0 })
      } catch (e) {
        err = e
      } finally {
        globalThis.Float64Array = real
      }
      expect(failures, contacts).toBe(1)
      expect(err, contacts).toBeInstanceOf(RangeError)
      expect(String(err), contacts).toMatch(/the ball stores could not grow to hold entity \d+ \(Array buffer allocation failed\); the entity is left as it was/)
      // every entity bitECS lists with Ball is a ball of the simulation's
      expect([...query(w, [w.Ball])].sort((a, b) => a - b), contacts).toEqual([...listBalls(w)].sort((a, b) => a - b))
      expect(listBalls(w).length, contacts).toBeGreaterThan(before)
      const more = addBall(w, { x: 5, y: 900, vx: 10, vy: 0 })
      expect(w.Ball.live[more], contacts).toBe(1)
      for (let f = 0; f < 10; f++) runSchedule(w, DEFAULT_SCHEDULE, 1 / 60)
      expect(listBalls(w).every((b) => Number.isFinite(w.Ball.x[b]!) && Number.isFinite(w.Ball.y[b]!)), contacts).toBe(true)
    }
  })
})
