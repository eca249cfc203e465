import { describe, expect, it } from 'vitest'
import { DEFAULT_PANEL, addPanel, createBallPhysics } from '../src/index'
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
})
