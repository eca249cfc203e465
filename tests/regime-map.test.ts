// The (δ, v) regime map of one hole: every cell's outcome against the closed-form boundaries, written
// out here from the design (not imported), with the contact taken on the circle ρ_c = R − r/2.
import { describe, expect, it } from 'vitest'
import { sequence, settle, shoot } from './helpers'

const R = 18
const r = 11
const RHO = R - r / 2
const V_MAX = 600
const V_SKIP = 640
const DECEL = 300
const POP_ARC = 0.565 * 2 * Math.PI * R

function expected(delta: number, v: number): string {
  const k = Math.sqrt(1 - (delta * delta) / (R * R))
  if (v > V_SKIP * k) return 'skip'
  if (v <= V_MAX && delta <= R * Math.sqrt(1 - (v / V_MAX) ** 2)) return 'capture:clean'
  if (delta >= RHO) return 'bounce'
  const hc = Math.sqrt(RHO * RHO - delta * delta)
  const vc = Math.sqrt(v * v - 2 * DECEL * (R * k - hc)) // speed on reaching the contact circle
  if (delta / hc <= 1.4) return 'bounce'
  const vt = (vc * delta) / RHO
  return (vt - 110) / 5 > POP_ARC ? 'rimRoll>lipOut' : 'rimRoll>capture:rimRoll'
}

describe('regime map: a (δ, v) grid at one hole, against the closed-form boundaries', () => {
  it('every cell matches, and all four regions plus the bounce region appear', () => {
    const counts = new Map<string, number>()
    let cells = 0
    for (let delta = 0.05; delta < R; delta += 0.3) {
      for (let v = 10; v <= 700; v += 3.7) {
        const want = expected(delta, v)
        const seq = sequence(settle(shoot(delta, v).sim, 1 / 30))
        const got = seq[0] === 'rimRoll' ? `rimRoll>${seq[1]}` : seq[0]!
        if (got !== want) throw new Error(`δ = ${delta}, v = ${v}: expected ${want}, got ${seq.join(',')}`)
        counts.set(want, (counts.get(want) ?? 0) + 1)
        cells++
      }
    }
    expect(cells).toBeGreaterThan(10000)
    for (const region of ['skip', 'capture:clean', 'bounce', 'rimRoll>lipOut', 'rimRoll>capture:rimRoll']) {
      expect(counts.get(region) ?? 0, region).toBeGreaterThan(0)
    }
  })
})
