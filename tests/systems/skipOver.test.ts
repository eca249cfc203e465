import { describe, expect, it } from 'vitest'
import { createBallPhysics, vSkip } from '../../src/index'
import { sequence, settle, shoot } from '../helpers'

const G = createBallPhysics().config.GRAVITY

describe('skip-over system (Stage 5)', () => {
  for (const delta of [0, 5, 10, 15, 17.5]) {
    it(`skips just above v_skip(δ) and not just below it, δ = ${delta}`, () => {
      const vs = vSkip(delta, 18, 11, G)
      const above = settle(shoot(delta, vs * (1 + 1e-6)).sim)
      expect(above[0]!.type).toBe('skip')
      const below = settle(shoot(delta, vs * (1 - 1e-6)).sim)
      expect(below[0]!.type).not.toBe('skip')
    })
  }

  it('v_skip at δ = 0 is V_SKIP_MAX = 640 px/s with the default constants', () => {
    expect(vSkip(0, 18, 11, G)).toBeCloseTo(640, 9)
  })

  it('locks the hole for the whole transit: no capture, rim contact or near miss, and the path is unchanged', () => {
    const { sim, ball } = shoot(4, 660)
    const ev = settle(sim)
    expect(sequence(ev)).toEqual(['skip', 'rest'])
    const st = sim.ballState(ball)
    expect(st.y).toBe(4) // flew straight over
    expect(st.x).toBeGreaterThan(18)
  })

  it('a skipping ball that runs out of speed over the hole falls in', () => {
    // a deceleration so strong that the ball stops within the chord
    const { sim } = shoot(0, 650, { ROLLING_DECEL: 20000 })
    expect(sequence(settle(sim))).toEqual(['skip', 'capture:rest'])
  })
})
