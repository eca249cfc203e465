// Accuracy of the methods against the exact reference on a small seeded sample (npm run accuracy runs the
// 10,000-throw sweep): the exact core matches it, the tick-sampled methods converge towards it with rate.
import { describe, expect, it } from 'vitest'
import { METHOD_SPECS, measureAccuracy, panelThrows, referenceRuns, runMethod } from '../scripts/accuracyLib'
import { POSITION_TOLERANCE } from './helpers'

const throws = panelThrows(4242, 400)
const refs = referenceRuns(throws)
const spec = (label: string) => METHOD_SPECS.find((s) => s.label === label)!
const accuracy = (label: string, hz: number) => measureAccuracy(runMethod(spec(label), hz, throws), refs)

describe('accuracy against the reference (400 throws)', () => {
  it('exact at 30 and 240 Hz: no throw differs, (δ, v) at the lip within 1e-9, final positions within 1e-6 px', () => {
    for (const hz of [30, 240]) {
      const a = accuracy('exact', hz)
      expect(a.sequenceDiffers).toBe(0)
      expect(a.lipPairs).toBeGreaterThan(300)
      expect(a.deltaErrMax).toBeLessThan(1e-9)
      expect(a.speedErrMax).toBeLessThan(1e-9)
      expect(a.posErrMax).toBeLessThan(POSITION_TOLERANCE)
    }
  })

  it('naive at 30 Hz differs on more than 5 % of throws, and 240 Hz × 16 sub-steps on fewer than a fifth as many', () => {
    const coarse = accuracy('naive', 30)
    const fine = accuracy('naive ×16', 240)
    expect(coarse.sequenceDiffers).toBeGreaterThan(0.05)
    expect(fine.sequenceDiffers).toBeLessThan(coarse.sequenceDiffers / 5)
    expect(fine.speedErrMean).toBeLessThan(coarse.speedErrMean / 5)
    expect(fine.posErrP95).toBeLessThan(coarse.posErrP95)
  })

  it('naive ×4 at 30 Hz is naive at 120 Hz: the same sub-step gives the same events and errors (to rounding of the sub-step times)', () => {
    const a = accuracy('naive ×4', 30)
    const b = accuracy('naive', 120)
    expect(a.sequenceDiffers).toBe(b.sequenceDiffers)
    expect(a.outcomeDiffers).toBe(b.outcomeDiffers)
    expect(a.lipPairs).toBe(b.lipPairs)
    for (const k of ['deltaErrMean', 'speedErrMean', 'posErrMean', 'posErrP95', 'posErrMax'] as const) {
      expect(Math.abs(a[k] - b[k]), k).toBeLessThan(1e-6 * (1 + b[k]))
    }
  })

  it('v1 (capture inside the lip below V_MAX, nothing else) differs on more than 30 % of throws at every rate', () => {
    for (const hz of [30, 240]) expect(accuracy('v1', hz).sequenceDiffers).toBeGreaterThan(0.3)
  })
})
