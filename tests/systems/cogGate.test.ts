import { describe, expect, it } from 'vitest'
import { cogRadius, createBallPhysics, rollRatioDelta, timeToDistance } from '../../src/index'
import { EXACT, sequence, settle, shoot } from '../helpers'

/** A speed inside the rim band at offset δ: above the capture window, below the skip speed. */
const rimBand = (delta: number) => {
  const k = Math.sqrt(1 - (delta * delta) / 324)
  return 620 * k
}

describe('COG gate system (Stage 6)', () => {
  it('the gate radius is R − r/2 = 12.5 px and the roll threshold 0.814·12.5 ≈ 10.19 px with the defaults', () => {
    expect(cogRadius(18, 11)).toBe(12.5)
    expect(rollRatioDelta(18, 11, 1.4)).toBeCloseTo((12.5 * 1.4) / Math.sqrt(1 + 1.96), 12)
    expect(rollRatioDelta(18, 11, 1.4)).toBeCloseTo(10.172, 3)
  })

  for (const delta of [12.5, 13, 15, 17]) {
    it(`a tangential brush (δ = ${delta} ≥ R − r/2) bounces at the lip crossing and never rolls or scores`, () => {
      const v = rimBand(delta)
      const { sim, ball } = shoot(delta, v, {}, 60)
      const ev = settle(sim)
      expect(sequence(ev)).toEqual(['bounce', 'nearMiss', 'rest'])
      // bounced at the lip crossing itself, 60 px from the start
      const a = sim.config.ROLLING_DECEL
      expect(Math.abs(ev[0]!.time - timeToDistance(60, Math.sqrt(v * v + 2 * a * 60), a))).toBeLessThan(EXACT)
      const st = sim.ballState(ball)
      expect(Math.hypot(st.x, st.y)).toBeGreaterThanOrEqual(18)
    })
  }

  it('a ball that passes the gate travels on to the contact circle, where the contact is taken', () => {
    const delta = 6
    const v = rimBand(delta)
    const { sim } = shoot(delta, v, {}, 60)
    const a = sim.config.ROLLING_DECEL
    const ev = settle(sim)
    expect(ev[0]!.type).toBe('bounce')
    // the contact is where the path meets ρ_c = 12.5: from the start, lead + (h_R − h_c) px
    const hR = Math.sqrt(18 * 18 - delta * delta)
    const hc = Math.sqrt(12.5 * 12.5 - delta * delta)
    const v0 = Math.sqrt(v * v + 2 * a * 60)
    expect(Math.abs(ev[0]!.time - timeToDistance(60 + hR - hc, v0, a))).toBeLessThan(EXACT)
    // the event still carries the lip crossing's (δ, v)
    expect(ev[0]!.delta).toBeCloseTo(delta, 9)
    expect(ev[0]!.speed).toBeCloseTo(v, 9)
  })

  it('rolls just above the ratio threshold and bounces just below it', () => {
    const d0 = rollRatioDelta(18, 11, 1.4)
    const above = sequence(settle(shoot(d0 + 1e-6, rimBand(d0)).sim))
    const below = sequence(settle(shoot(d0 - 1e-6, rimBand(d0)).sim))
    expect(above[0]).toBe('rimRoll')
    expect(below[0]).toBe('bounce')
  })

  it("uses each ball's own radius: δ = 10.5 rolls for r = 11 but is a brush for r = 17 (ρ_c = 9.5)", () => {
    // a bigger ball needs longer to fall (v_skip ∝ 1/√r): with V_MAX = 400 both radii have a rim band here
    const v = 450 * Math.sqrt(1 - (10.5 * 10.5) / 324)
    const run = (radius: number) => {
      const sim = createBallPhysics({ V_MAX: 400 })
      sim.addHole({ x: 0, y: 0 })
      const a = sim.config.ROLLING_DECEL
      const lipX = -Math.sqrt(18 * 18 - 10.5 * 10.5)
      sim.addBall({ x: lipX - 60, y: 10.5, vx: Math.sqrt(v * v + 2 * a * 60), vy: 0, radius })
      return sequence(settle(sim))
    }
    expect(run(11)[0]).toBe('rimRoll')
    expect(run(17)).toEqual(['bounce', 'nearMiss', 'rest'])
  })
})
