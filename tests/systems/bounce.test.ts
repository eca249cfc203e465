import fc from 'fast-check'
import { describe, expect, it } from 'vitest'
import { createBallPhysics } from '../../src/index'
import { sequence, settle, shoot } from '../helpers'

const NO_DECEL = { ROLLING_DECEL: 0 }

/** Velocity of the ball right after its first event (decel 0: constant until the next event). */
function velocityAfterFirstEvent(delta: number, v: number) {
  const { sim, ball } = shoot(delta, v, NO_DECEL, 30)
  // with no deceleration the velocity is constant between events, so a coarse step reads it exactly
  for (let i = 0; i < 4000; i++) {
    sim.step(1 / 200)
    const ev = sim.drainEvents()
    if (ev.length > 0) return { ev, st: sim.ballState(ball) }
  }
  throw new Error('no event')
}

describe('bounce system (Stages 2 and 4)', () => {
  it('a head-on rim bounce loses 91 % of the normal kinetic energy (e = 0.30), to 1e-9', () => {
    const { ev, st } = velocityAfterFirstEvent(0, 620)
    expect(ev[0]!.type).toBe('bounce')
    const keBefore = 620 * 620
    const keAfter = st.vx * st.vx + st.vy * st.vy
    expect(Math.abs(1 - keAfter / keBefore - 0.91)).toBeLessThan(1e-9)
    expect(st.vx).toBeLessThan(0) // caroms back
  })

  it('a 45° contact loses 71 % of its kinetic energy (e = μ_t = 0.30), to 1e-9', () => {
    // at the contact circle |v_t| = |v_n| where δ = ρ_c/√2
    const delta = 12.5 / Math.SQRT2
    const { ev, st } = velocityAfterFirstEvent(delta, 540)
    expect(ev[0]!.type).toBe('bounce')
    const loss = 1 - (st.vx * st.vx + st.vy * st.vy) / (540 * 540)
    expect(Math.abs(loss - (1 - (0.09 + 0.49) / 2))).toBeLessThan(1e-9)
  })

  it('head-on contacts carom back and glancing ones skim forward: one rule, asymmetric outcomes', () => {
    const head = velocityAfterFirstEvent(0, 620).st
    const glance = velocityAfterFirstEvent(15, 0.97 * 640 * Math.sqrt(1 - 225 / 324)).st
    expect(head.vx).toBeLessThan(0)
    expect(glance.vx).toBeGreaterThan(0)
  })

  it('kinetic energy never rises at a rim contact (property, random δ and v in the rim band)', () => {
    fc.assert(
      fc.property(fc.double({ min: 0, max: 17.99, noNaN: true }), fc.double({ min: 0, max: 1, noNaN: true }), (delta, u) => {
        const k = Math.sqrt(1 - (delta * delta) / 324)
        const v = (600 + 40 * u) * k
        const { st } = velocityAfterFirstEvent(delta, v)
        return st.vx * st.vx + st.vy * st.vy <= v * v * (1 + 1e-12)
      }),
      { numRuns: 300, seed: 42 },
    )
  })

  it('every bounced ball ends outside the hole, over the whole rim band (defaults)', () => {
    let bounces = 0
    for (let delta = 0; delta < 18; delta += 0.5) {
      const k = Math.sqrt(1 - (delta * delta) / 324)
      for (let v = 600 * k + 0.5; v <= 640 * k; v += 4) {
        const { sim, ball } = shoot(delta, v)
        const seq = sequence(settle(sim, 1 / 30))
        if (seq[0] !== 'bounce') continue
        bounces++
        expect(seq.at(-1)).toBe('rest')
        const st = sim.ballState(ball)
        expect(Math.hypot(st.x, st.y)).toBeGreaterThanOrEqual(18)
      }
    }
    expect(bounces).toBeGreaterThan(50)
  })

  it('a bounce with e = 0 and a head-on contact leaves the ball dead inside the hole: it falls in', () => {
    const sim = createBallPhysics({ RIM_RESTITUTION: 0, ROLLING_DECEL: 0 })
    sim.addHole({ x: 0, y: 0 })
    sim.addBall({ x: -60, y: 0, vx: 620, vy: 0 })
    expect(sequence(settle(sim))).toEqual(['bounce', 'nearMiss', 'capture:rest'])
  })
})
