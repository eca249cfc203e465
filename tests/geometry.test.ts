import { describe, expect, it } from 'vitest'
import { captureWindow, capturesClean, midRimDropSpeed, rollArc, rollDropTime, rollPopTime, rollSpeed, speedAtDistance, stopDistance, timeToDistance, vSkip } from '../src/index'

const G = (640 * 640 * 11) / (2 * 18 * 18)

describe('regime curves', () => {
  it('v_skip and δ_eff have the same √(1 − δ²/R²) shape: parallel curves 600 and 640 px/s at δ = 0', () => {
    for (const d of [0, 3, 9, 14, 17.9]) {
      const k = Math.sqrt(1 - (d * d) / 324)
      expect(vSkip(d, 18, 11, G)).toBeCloseTo(640 * k, 9)
      // δ_eff(v) inverts the same ellipse: at v = 600·k the window is exactly d
      expect(captureWindow(600 * k, 18, 600, 'ellipse')).toBeCloseTo(d, 9)
    }
    expect(vSkip(18, 18, 11, G)).toBe(0)
    expect(vSkip(25, 18, 11, G)).toBe(0)
    expect(captureWindow(0, 18, 600, 'ellipse')).toBe(18)
    expect(captureWindow(700, 18, 600, 'ellipse')).toBe(0)
    expect(capturesClean(0, 600, 18, 600, 'ellipse')).toBe(true)
    expect(capturesClean(0, 600.0001, 18, 600, 'ellipse')).toBe(false)
  })

  it('guards the unused Region 2 formula where its radicand is negative (δ < (R − r)^1.5/√R ≈ 4.4 px)', () => {
    const edge = Math.pow(7, 1.5) / Math.sqrt(18)
    expect(edge).toBeCloseTo(4.365, 3)
    expect(midRimDropSpeed(edge * 0.99, 18, 11, G, 0.4)).toBeUndefined()
    expect(midRimDropSpeed(0, 18, 11, G, 0.4)).toBeUndefined()
    const v = midRimDropSpeed(10, 18, 11, G, 0.4)!
    expect(Number.isFinite(v) && v > 0).toBe(true)
  })
})

describe('closed forms of motion', () => {
  it('timeToDistance inverts s(τ) = v0·τ − a·τ²/2 to 1e-12 relative, including a·d ≪ v0²', () => {
    for (const [d, v0, a] of [
      [10, 500, 300],
      [1e-9, 1e5, 300],
      [400, 500, 300],
      [50, 100, 0],
    ] as const) {
      const t = timeToDistance(d, v0, a)
      expect(Math.abs(v0 * t - 0.5 * a * t * t - d) / d).toBeLessThan(1e-12)
      expect(speedAtDistance(d, v0, a)).toBeCloseTo(v0 - a * t, 9)
    }
    expect(timeToDistance(stopDistance(500, 300) * 1.0001, 500, 300)).toBe(Infinity)
    expect(stopDistance(500, 0)).toBe(Infinity)
  })

  it('rim-roll end times agree with the arc and speed closed forms', () => {
    const vt0 = 440
    const mu = 5
    const td = rollDropTime(vt0, mu, 110)
    expect(rollSpeed(td, vt0, mu)).toBeCloseTo(110, 9)
    expect(rollArc(td, vt0, mu)).toBeCloseTo((vt0 - 110) / mu, 9)
    const tp = rollPopTime(vt0, mu, 60)
    expect(rollArc(tp, vt0, mu)).toBeCloseTo(60, 9)
    expect(rollPopTime(vt0, mu, vt0 / mu)).toBe(Infinity) // the asymptote is never reached
    expect(rollPopTime(vt0, 0, 88)).toBeCloseTo(0.2, 12)
    expect(rollDropTime(100, mu, 110)).toBe(0)
  })
})
