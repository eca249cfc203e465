import { describe, expect, it } from 'vitest'
import { createBallPhysics, type BallEvent } from '../../src/index'
import { rng } from '../helpers'

function randomScene(seed: number, broadphase: 'grid' | 'scan', holes: number, balls: number, decel: number) {
  const rand = rng(seed)
  const sim = createBallPhysics({ ROLLING_DECEL: decel }, { broadphase })
  const size = Math.sqrt(holes) * 70
  let placed = 0
  for (let tries = 0; placed < holes && tries < holes * 50; tries++) {
    const R = 10 + 15 * rand()
    try {
      sim.addHole({ x: rand() * size, y: rand() * size, radius: R })
      placed++
    } catch {
      // overlapping: try another spot
    }
  }
  for (let i = 0; i < balls; i++) {
    const ang = rand() * 2 * Math.PI
    const speed = 50 + 1500 * rand()
    sim.addBall({ x: rand() * size, y: rand() * size, vx: speed * Math.cos(ang), vy: speed * Math.sin(ang), radius: 4 + 10 * rand() })
  }
  return sim
}

function run(sim: ReturnType<typeof createBallPhysics>, steps: number, dt: number): BallEvent[] {
  const out: BallEvent[] = []
  for (let i = 0; i < steps; i++) {
    sim.step(dt)
    out.push(...sim.drainEvents())
  }
  return out
}

describe('hole broadphase (uniform grid)', () => {
  for (const [seed, holes, decel] of [
    [1, 200, 300],
    [2, 1000, 100],
    [3, 400, 0],
    [4, 2000, 600],
  ] as const) {
    it(`gives the same events as the full scan on a random scene (seed ${seed}, ${holes} holes, ROLLING_DECEL ${decel})`, () => {
      const a = run(randomScene(seed, 'grid', holes, 300, decel), 120, 1 / 60)
      const b = run(randomScene(seed, 'scan', holes, 300, decel), 120, 1 / 60)
      expect(a.length).toBeGreaterThan(100)
      expect(a).toEqual(b)
    })
  }

  it('finds holes added after balls started rolling', () => {
    const sim = createBallPhysics({ ROLLING_DECEL: 0 }, { broadphase: 'grid' })
    for (let i = 0; i < 40; i++) sim.addHole({ x: 100 * i, y: 1000 })
    sim.addBall({ x: 0, y: 0, vx: 1000, vy: 0 })
    sim.step(0.1)
    sim.addHole({ x: 500, y: 2 })
    sim.step(0.25)
    sim.step(0.25)
    expect(sim.drainEvents().map((e) => e.type)).toEqual(['skip'])
  })
})
