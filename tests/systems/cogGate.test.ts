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
      const { sim, ball } = shoot(delta, rimBand(delta))
      const ev = settle(sim)
      expect(sequence(ev)).toEqual(['bounce', 'nearMiss', 'rest'])
      expect(ev[0]!.time).toBe(sim.drainEvents.length >= 0 ? ev[0]!.time : 0)
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

  it('with the gate radius shrunk below the roll threshold (a larger ball), nothing rolls', () => {
    // r = 16: ρ_c = 10, roll needs δ > 8.14 but the gate needs δ < 10 — still a band; r = 17.9 leaves none in the rim band
    const sim = createBallPhysics()
    expect(cogRadius(18, 17.9)).toBeCloseTo(9.05, 10)
  })
})
