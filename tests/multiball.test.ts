import { describe, expect, it } from 'vitest'
import { DEFAULT_PANEL, addPanel, createBallPhysics } from '../src/index'
import { rng } from './helpers'

describe('multi-ball', () => {
  it('10,000 balls thrown at the 5 × 5 panel until all stop: every ball accounted for, no NaN anywhere', () => {
    const sim = createBallPhysics({}, { capacity: 16384 })
    addPanel(sim)
    expect(DEFAULT_PANEL.holes).toHaveLength(25)
    const rand = rng(2024)
    const n = 10000
    for (let i = 0; i < n; i++) {
      sim.throwBall({
        x: DEFAULT_PANEL.launch.x + (rand() - 0.5) * 300,
        y: DEFAULT_PANEL.launch.y,
        power: rand(),
        angle: (rand() - 0.5) * 1.4,
      })
    }
    const ends = new Map<number, string>()
    const counts: Record<string, number> = {}
    for (let i = 0; i < 60 * 30 && ends.size < n; i++) {
      sim.step(1 / 60)
      for (const e of sim.drainEvents()) {
        counts[e.type] = (counts[e.type] ?? 0) + 1
        if (e.type === 'capture' || e.type === 'rest') {
          expect(ends.has(e.ball)).toBe(false) // one ending per ball
          ends.set(e.ball, e.type)
        }
      }
    }
    const modes = { captured: 0, resting: 0, rolling: 0, rimRoll: 0, out: 0, held: 0 }
    for (const b of sim.balls()) modes[sim.ballState(b).mode]++
    expect(modes.captured + modes.resting).toBe(n)
    expect(ends.size).toBe(n)
    expect([...ends.values()].filter((t) => t === 'capture')).toHaveLength(modes.captured)
    for (const k of ['skip', 'capture', 'bounce', 'rimRoll', 'lipOut', 'nearMiss', 'rest']) expect(counts[k] ?? 0, k).toBeGreaterThan(0)
    let nonFinite = 0
    for (const store of [sim.world.Ball, sim.world.Path, sim.world.RimContact]) {
      for (const arr of Object.values(store) as Float64Array[]) {
        for (let i = 0; i < arr.length; i++) if (!Number.isFinite(arr[i]!)) nonFinite++
      }
    }
    expect(nonFinite).toBe(0)
  })
})
