import { describe, expect, it } from 'vitest'
import {
  createDopri5Workspace,
  dopri5,
  dopri5DenseOutput,
  lipEnergy,
  referenceCaptureOffset,
  referenceCaptureSpeed,
  referenceOutcome,
  referenceTrace,
  rollOnLip,
  singleImpactDeadCentreLimit,
  type LipState,
  type OdeRhs,
  type PhaseRecord,
  type ReferenceInput,
} from '../src/reference/index'

// Golf (Holmes 1991): hole radius, ball radius (42.67 mm ball), solid-sphere inertia, gravity; SI units.
const R = 0.053975
const r = 0.021335
const J = 2 / 5
const GRAV = 9.81
const GOLF = { holeRadius: R, ballRadius: r, gravity: GRAV, inertia: J }

// ---- tolerances ----
/** DOPRI5 test tolerances: tight enough that the checks below test the method, not the tolerance */
const RTOL = 1e-10
const ATOL = 1e-12
/** global error allowed after 20 time units of oscillation (≈ 3 periods × per-step error ≤ RTOL) */
const OSCILLATOR_ERROR = 1e-8
/** relative error allowed for exponential decay over 5 time constants */
const DECAY_REL_ERROR = 1e-8
/** event time accuracy asked of the event location (brief: ~1e-9) */
const EVENT_TIME_ERROR = 1e-9
/** energy on the lip must be kept to this, relative (brief) */
const ENERGY_REL_DRIFT = 1e-8

describe('DOPRI5 integrator', () => {
  const oscillator: OdeRhs = (_t, y, dy) => {
    dy[0] = y[1]!
    dy[1] = -y[0]!
  }

  it('integrates a harmonic oscillator to 1e-8 over 20 time units and lands exactly on tEnd', () => {
    const ws = createDopri5Workspace(2, 0)
    const y = new Float64Array([1, 0])
    const res = dopri5(ws, oscillator, 0, y, 20, { rtol: RTOL, atol: ATOL })
    expect(res.status).toBe('reachedEnd')
    expect(res.t).toBe(20)
    expect(Math.abs(y[0]! - Math.cos(20))).toBeLessThan(OSCILLATOR_ERROR)
    expect(Math.abs(y[1]! + Math.sin(20))).toBeLessThan(OSCILLATOR_ERROR)
    expect(res.evaluations).toBeLessThan(20_000) // adaptive steps, not a crawl
  })

  it('integrates exponential decay to 1e-8 relative, with a stiffer rate forcing rejections early on', () => {
    const ws = createDopri5Workspace(1, 0)
    const lambda = 2
    const decay: OdeRhs = (_t, y, dy) => {
      dy[0] = -lambda * y[0]!
    }
    const y = new Float64Array([1])
    const res = dopri5(ws, decay, 0, y, 5, { rtol: RTOL, atol: 1e-20, hInit: 1 })
    expect(res.status).toBe('reachedEnd')
    expect(Math.abs(y[0]! / Math.exp(-lambda * 5) - 1)).toBeLessThan(DECAY_REL_ERROR)
    expect(res.rejected).toBeGreaterThan(0) // the oversized first step was rejected and shrunk
  })

  it('locates events to 1e-9: cos t falls through 0 at π/2 and rises through 0 at 3π/2', () => {
    const ws = createDopri5Workspace(2, 2)
    const falling = { g: (_t: number, y: Float64Array) => y[0]!, direction: -1 as const }
    const rising = { g: (_t: number, y: Float64Array) => y[0]!, direction: 1 as const }
    const y = new Float64Array([1, 0])
    const first = dopri5(ws, oscillator, 0, y, 10, { rtol: RTOL, atol: ATOL }, [rising, falling])
    expect(first.status).toBe('event')
    expect(first.event).toBe(1)
    expect(Math.abs(first.t - Math.PI / 2)).toBeLessThan(EVENT_TIME_ERROR)
    expect(Math.abs(y[1]! + 1)).toBeLessThan(EVENT_TIME_ERROR)
    // restarting on the root: the zero at the start is not reported again
    const second = dopri5(ws, oscillator, first.t, y, 10, { rtol: RTOL, atol: ATOL }, [rising, falling])
    expect(second.event).toBe(0)
    expect(Math.abs(second.t - (3 * Math.PI) / 2)).toBeLessThan(EVENT_TIME_ERROR)
  })

  it('dense output over the last step is exact at its end and accurate inside', () => {
    const ws = createDopri5Workspace(2, 0)
    const y = new Float64Array([1, 0])
    // one long step (h = 0.3, accepted at this loose tolerance): a real test of the interpolant
    dopri5(ws, oscillator, 0, y, 0.3, { rtol: 1e-4, atol: 1e-4, hInit: 0.3 })
    const out = new Float64Array(2)
    const t0 = ws.lastStepStart
    const h = ws.lastStepSize
    expect(h).toBe(0.3)
    dopri5DenseOutput(ws, 0.3, out)
    expect(out[0]).toBe(y[0]) // exact at the step end
    for (const x of [0.25, 0.5, 0.75]) {
      dopri5DenseOutput(ws, t0 + x * h, out)
      // 4th-order interpolant: error O(h⁵) ≈ 2e-3 · small constant
      expect(Math.abs(out[0]! - Math.cos(t0 + x * h))).toBeLessThan(1e-6)
    }
  })
})

describe('sphere on a sharp lip: integrator checks', () => {
  it(`keeps E/m on the lip to ${ENERGY_REL_DRIFT} relative over a long roll (100 √(r/g), ~4.7 s for golf)`, () => {
    // a ball on the lip turning round it, tilted in, spinning about the normal
    const start: LipState = { psi: 1, theta: -0.4, psiDot: -4, thetaDot: 2, omegaN: 10 }
    const T = Math.sqrt(r / GRAV)
    const e0 = lipEnergy(start, R, r, GRAV, J)
    const { state, steps } = rollOnLip(start, 100 * T, R, r, GRAV, J)
    const e1 = lipEnergy(state, R, r, GRAV, J)
    expect(steps).toBeGreaterThan(1000) // a long integration, not a handful of steps
    expect(Math.abs(e1 / e0 - 1)).toBeLessThan(ENERGY_REL_DRIFT)
  })

  it(`keeps E/m to ${ENERGY_REL_DRIFT} on every lip phase of a 380° lip-out, and turns more than 180° (Hogan and Antali)`, () => {
    const tr = referenceTrace({ ...GOLF, delta: 0.77 * R, speed: 0.595 })
    expect(tr.outcome.captured).toBe(false)
    expect(tr.outcome.turnAngle).toBeGreaterThan(2 * Math.PI) // measured 6.66 rad (382°)
    for (const p of tr.phases) {
      if (p.kind !== 'lip') continue
      expect(Math.abs(p.energyEnd! / p.energyStart! - 1)).toBeLessThan(ENERGY_REL_DRIFT)
    }
    // rolling out at θ = 0 after a pure roll: the exit speed equals the entry speed (energy kept)
    expect(Math.abs(tr.outcome.exitSpeed! / 0.595 - 1)).toBeLessThan(ENERGY_REL_DRIFT)
  })
})

describe('sphere on a sharp lip: golf anchors (Holmes 1991)', () => {
  // idealised: no slip up to lift-off (needs high friction), no rolling resistance
  const DEAD_CENTRE_LIMIT = 1.626 // m/s, Holmes
  const DEAD_CENTRE_REL = 0.01 // brief: within 1 %

  it('dead-centre capture limit 1.626 m/s within 1 % (measured 1.6274 m/s)', () => {
    const vc = referenceCaptureSpeed(0, R, r, GRAV, J)
    expect(Math.abs(vc / DEAD_CENTRE_LIMIT - 1)).toBeLessThan(DEAD_CENTRE_REL)
  })

  it('the hole is about 25 % narrower at 0.65 m/s, within 3 points (measured 25.6 %)', () => {
    const dMax = referenceCaptureOffset(0.65, R, r, GRAV, J)!
    expect(Math.abs(1 - dMax / R - 0.25)).toBeLessThan(0.03)
  })

  it('about 4 % narrower at 0.23 m/s (Holmes); the model gives 2.97 %, pinned here to ±0.1 point', () => {
    const dMax = referenceCaptureOffset(0.23, R, r, GRAV, J)!
    const narrowing = 1 - dMax / R
    expect(narrowing).toBeGreaterThan(0) // narrower, as Holmes says
    expect(Math.abs(narrowing - 0.0297)).toBeLessThan(0.001) // regression pin of the measured value
  })

  it('the δ = 0 single-impact closed form agrees with the full model within 2 % (measured 1.43 % below)', () => {
    const full = referenceCaptureSpeed(0, R, r, GRAV, J)
    const single = singleImpactDeadCentreLimit(R, r, GRAV, J)
    expect(Math.abs(single / full - 1)).toBeLessThan(0.02)
    // the free-fall criterion (2R − r)·√(g/2r) ≈ 1.31 m/s (Penner) is well below both
    expect((2 * R - r) * Math.sqrt(GRAV / (2 * r))).toBeLessThan(single)
  })

  it('captures just below the dead-centre limit and lets the ball out just above it', () => {
    const vc = referenceCaptureSpeed(0, R, r, GRAV, J)
    expect(referenceOutcome({ ...GOLF, delta: 0, speed: vc * 0.999 }).captured).toBe(true)
    const above = referenceOutcome({ ...GOLF, delta: 0, speed: vc * 1.001 })
    expect(above.captured).toBe(false)
    expect(above.exitSpeed).toBeGreaterThan(0)
    expect(above.turnAngle).toBe(0) // dead centre: a planar motion, the contact never moves round
  })
})

describe('sphere on a sharp lip: inputs and invariances', () => {
  const good: ReferenceInput = { ...GOLF, delta: 0.3 * R, speed: 1 }
  const bad: Array<[keyof ReferenceInput, number, RegExp]> = [
    ['delta', Number.NaN, /delta/],
    ['delta', R, /delta must be in \(−holeRadius, holeRadius\)/],
    ['speed', 0, /speed must be in \(0, 1000000000000·√\(gravity·ballRadius\)\] = \(0, /],
    ['speed', Number.POSITIVE_INFINITY, /speed/],
    // the model's domain: v/√(g·r) at most 1e12 (here about 4.6e11 m/s), R/r at most 1e8
    ['speed', 1e12 * Math.sqrt(9.81 * r) * 1.000001, /speed must be in \(0, 1000000000000·√\(gravity·ballRadius\)\]/],
    ['holeRadius', -1, /holeRadius/],
    ['ballRadius', R, /ballRadius must be in \[holeRadius \/ 100000000, holeRadius\)/],
    ['ballRadius', 0, /ballRadius/],
    ['ballRadius', R / 1e8 / 1.000001, /ballRadius must be in \[holeRadius \/ 100000000, holeRadius\)/],
    ['gravity', 0, /gravity must be in \(0, ∞\)/],
    ['inertia', 0, /inertia must be in \(0, 2\/3\]/],
    ['inertia', 1, /inertia/],
  ]
  it('refuses input past the model\'s domain that used to hang it or answer wrongly (the flight search stalled on a step that rounded away)', () => {
    const px = { holeRadius: 18, ballRadius: 11, gravity: 6953, inertia: 0.4 }
    expect(() => referenceOutcome({ ...px, delta: 0, speed: 1e160 })).toThrow(/speed must be in \(0, 1000000000000·√\(gravity·ballRadius\)\]/)
    expect(() => referenceOutcome({ ...px, delta: 0, speed: 400, gravity: 5e-324 })).toThrow(/speed must be in/)
    expect(() => referenceCaptureSpeed(0, 1e14, 1, 1, 0.4)).toThrow(/ballRadius must be in \[holeRadius \/ 100000000, holeRadius\)/)
    expect(() => referenceCaptureOffset(1e308, 18, 11, 6953, 0.4)).toThrow(/speed must be in/)
    expect(() => referenceOutcome({ ...px, holeRadius: 1e20, ballRadius: 1, delta: 0, speed: 1000 })).toThrow(RangeError)
    // at the domain's edges it still answers, quickly: a ball 1e8 times smaller than the hole drops in
    const edge = referenceOutcome({ holeRadius: 1e8, ballRadius: 1, gravity: 6953, inertia: 0.4, delta: 1e8 - 3, speed: 1000 })
    expect(edge.captured).toBe(true)
    expect(edge.ending).toBe('droppedInFlight')
    expect(referenceOutcome({ ...px, delta: 3, speed: 0.999e12 * Math.sqrt(6953 * 11) }).ending).toBe('hoppedOut')
  })

  it.each(bad)('%s = %s throws a RangeError naming the field', (field, value, message) => {
    expect(() => referenceOutcome({ ...good, [field]: value })).toThrow(RangeError)
    expect(() => referenceOutcome({ ...good, [field]: value })).toThrow(message)
  })

  it('is deterministic: the same input gives identical output, whatever ran in between', () => {
    const inputs: ReferenceInput[] = [
      { ...GOLF, delta: 0, speed: 1.62 },
      { ...GOLF, delta: 0.24 * R, speed: 1.62 }, // an impact chain with a held roll
      { ...GOLF, delta: 0.77 * R, speed: 0.595 }, // a long lip-out
      { ...GOLF, delta: 0.5 * R, speed: 0.9 },
    ]
    const first = inputs.map((i) => referenceOutcome(i))
    referenceCaptureSpeed(0.4 * R, R, r, GRAV, J) // other work on the shared workspace
    const second = inputs.map((i) => referenceOutcome(i)).reverse().reverse()
    expect(second).toEqual(first)
    for (let k = 0; k < inputs.length; k++) {
      expect(Object.is(second[k]!.turnAngle, first[k]!.turnAngle)).toBe(true)
      expect(Object.is(second[k]!.duration, first[k]!.duration)).toBe(true)
    }
  })

  it('depends only on δ/R, v/√(g r), R/r and j (game units give the same outcome)', () => {
    // the game's hole: R = 18 px, r = 11 px, g = 6953 px/s²
    const px = { holeRadius: 18, ballRadius: 11, gravity: 6953, inertia: J }
    const si = { holeRadius: 0.18, ballRadius: 0.11, gravity: 9.81, inertia: J }
    const vScale = Math.sqrt((6953 * 11) / (9.81 * 0.11))
    for (const [f, vs] of [[0.2, 1.4], [0.6, 0.7], [0.85, 0.5]] as const) {
      const a = referenceOutcome({ ...px, delta: f * 18, speed: vs * Math.sqrt(6953 * 11) })
      const b = referenceOutcome({ ...si, delta: f * 0.18, speed: vs * Math.sqrt(9.81 * 0.11) })
      expect(a.captured).toBe(b.captured)
      expect(a.ending).toBe(b.ending)
      expect(a.turnAngle).toBeCloseTo(b.turnAngle, 9)
      if (a.exitSpeed !== undefined) expect(a.exitSpeed / vScale).toBeCloseTo(b.exitSpeed!, 9)
    }
  })

  it('mirrors: −δ gives the same outcome with the exit direction reflected', () => {
    for (const [f, v] of [[0.3, 1.5], [0.77, 0.595], [0.6, 1.2]] as const) {
      const a = referenceOutcome({ ...GOLF, delta: f * R, speed: v })
      const b = referenceOutcome({ ...GOLF, delta: -f * R, speed: v })
      expect(b.captured).toBe(a.captured)
      expect(b.turnAngle).toBeCloseTo(a.turnAngle, 9)
      if (a.exitAngle !== undefined) expect(b.exitAngle!).toBeCloseTo(-a.exitAngle, 9)
    }
  })

  it('never hits a guard over the golf (δ, v) plane, and every run ends in a physical outcome', () => {
    const endings = new Set<string>()
    for (let i = 0; i < 20; i++) {
      for (let k = 0; k < 20; k++) {
        const o = referenceOutcome({ ...GOLF, delta: (i / 20) * R, speed: 0.05 + k * 0.12 })
        endings.add(o.ending)
        expect(['rolledOut', 'hoppedOut', 'droppedFromLip', 'droppedInFlight']).toContain(o.ending)
        expect(o.captured).toBe(o.ending === 'droppedFromLip' || o.ending === 'droppedInFlight')
      }
    }
    expect(endings.size).toBe(4) // all four endings occur
  })
})

describe('sphere on a sharp lip: the engine\'s live step budget', () => {
  it('a steady roll that would run to MAX_TIME stops at LIVE_STEP_BUDGET lip steps (guarded); a run that decides is the same, bit for bit', async () => {
    const { simulateScaled } = await import('../src/reference/sphereLip')
    const { LIVE_STEP_BUDGET } = await import('../src/reference/tolerances')
    const { isGuarded } = await import('../src/reference/types')
    const lipSteps = (trace: PhaseRecord[]) => trace.reduce((s, p) => s + (p.kind === 'lip' ? p.steps! : 0), 0)
    // a ball nearly the hole's size, slow and near the centre line: it rolls round the lip to the time limit
    const steady = [22 / 21.5, 1.1 / 21.5, 90 / Math.sqrt(1000 * 21.5), 0.4] as const
    const full: PhaseRecord[] = []
    const whole = simulateScaled(...steady, full)
    expect(whole.ending).toBe('timeLimit')
    expect(lipSteps(full)).toBeGreaterThan(5 * LIVE_STEP_BUDGET)
    const cut: PhaseRecord[] = []
    const capped = simulateScaled(...steady, cut, LIVE_STEP_BUDGET)
    expect(capped.ending).toBe('integratorLimit')
    expect(isGuarded(capped.ending)).toBe(true)
    expect(lipSteps(cut)).toBe(LIVE_STEP_BUDGET)
    // runs that decide, over a grid of the design's geometry and of balls near the hole's size
    let decided = 0
    for (const rs of [2, 1.2, 1.02]) {
      for (let i = 0; i < 8; i++) {
        for (let k = 0; k < 8; k++) {
          const args = [rs, ((i + 0.5) / 8) * rs, 0.1 + 0.4 * k, 0.4] as const
          const a = simulateScaled(...args, null)
          if (isGuarded(a.ending)) continue
          decided++
          expect(simulateScaled(...args, null, LIVE_STEP_BUDGET)).toEqual(a)
        }
      }
    }
    expect(decided).toBeGreaterThan(150)
  })
})
