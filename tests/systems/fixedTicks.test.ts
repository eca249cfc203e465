// The fixed-tick method's clock: a step that ends on a contact tick ends solved, even when the world's
// time, summed from the steps, is a few ulps off k·CONTACT_TICK.
import { describe, expect, it } from 'vitest'
import { createBallPhysics } from '../../src/index'
import { rng } from '../helpers'

function gas(seed: number) {
  const r = rng(seed)
  const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 0.9, ROLLING_DECEL: 0 })
  sim.setWalls({ minX: 0, minY: 0, maxX: 300, maxY: 300, restitution: 0.9 })
  const placed: [number, number][] = []
  while (placed.length < 60) {
    const x = 15 + 270 * r()
    const y = 15 + 270 * r()
    if (placed.some(([px, py]) => Math.hypot(px - x, py - y) < 23)) continue
    placed.push([x, y])
    const a = 2 * Math.PI * r()
    sim.addBall({ x, y, vx: 300 * Math.cos(a), vy: 300 * Math.sin(a) })
  }
  return sim
}

describe('contact ticks and step ends', () => {
  it.each([120, 60, 30])('at %i Hz every step ends on its tick with that tick solved, and the clock stays on the ticks', (hz) => {
    const sim = gas(5)
    const F = sim.world.fixed!
    const perStep = 120 / hz
    for (let i = 0; i < 600; i++) {
      sim.step(1 / hz)
      // the tick at time 0 and every tick up to the step's end, this one included
      expect(F.ticks, `step ${i}`).toBe(1 + (i + 1) * perStep)
      expect(sim.time).toBe((i + 1) * perStep * F.tick)
    }
  })

  it('ending on the tick moves no solve: the same events at the same times as steps of 1/240 s', () => {
    const a = gas(9)
    const b = gas(9)
    const events = (sim: ReturnType<typeof gas>) => sim.drainEvents().map((e) => `${e.type} ${e.ball} ${e.time}`)
    const got: string[] = []
    const want: string[] = []
    for (let i = 0; i < 240; i++) {
      a.step(1 / 120)
      got.push(...events(a))
    }
    // every other step of 1/240 s ends between ticks
    for (let i = 0; i < 480; i++) {
      b.step(1 / 240)
      want.push(...events(b))
    }
    expect(got.length).toBeGreaterThan(100)
    expect(got).toEqual(want)
  })
})
