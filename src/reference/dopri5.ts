// Dormand–Prince 5(4) with adaptive step size, dense output and event location. No external dependency: the
// Butcher tableau is in dopri5Tableau.ts, Brent's root finder in brent.ts.
//
// The method (Dormand & Prince 1980; Hairer, Nørsett & Wanner, "Solving ODEs I", §II.4–II.6):
// - seven stages, first-same-as-last (the last stage of a step is the first of the next), so six right-hand
//   side evaluations per accepted step;
// - the step is advanced with the 5th-order solution (local extrapolation); the embedded 4th-order solution
//   only serves to estimate the local error;
// - the error is measured in the weighted RMS norm ‖e_i / (atol + rtol·max(|y_i|, |y_new,i|))‖ and a step is
//   accepted when that norm is ≤ 1; the next step size comes from a PI controller (Gustafsson, as in Hairer's
//   DOPRI5 code) with a safety factor and clamped between a minimum and a maximum factor;
// - dense output: Hairer's 4th-order continuous extension (the same coefficients as SciPy's RK45), exact at
//   both ends of the step, so a sign change seen at the step ends is also a sign change of the interpolant.
//
// Event location: after each accepted step every event function is evaluated at the new point. A sign change
// in the requested direction between the two ends of the step is bracketed, and the crossing is found by
// Brent's method ON THE DENSE-OUTPUT INTERPOLANT (no re-integration). The interpolant's error is of the same
// order as the step's local error, so the event time is as accurate as the requested tolerance allows. The
// earliest crossing among all events wins; the state there is the interpolated state. A crossing that starts
// exactly at a zero of the event function (the usual case when a phase begins on the event surface) is not
// reported: a rising crossing needs g < 0 before and g ≥ 0 after, a falling one g > 0 before and g ≤ 0 after.
//
// Work arrays are preallocated in a workspace; a call to `dopri5` allocates only its small result object
// (and a closure when it has to locate an event).

import { brentRoot } from './brent.js'
import {
  A21,
  A31,
  A32,
  A41,
  A42,
  A43,
  A51,
  A52,
  A53,
  A54,
  A61,
  A62,
  A63,
  A64,
  A65,
  B1,
  B3,
  B4,
  B5,
  B6,
  C2,
  C3,
  C4,
  C5,
  E1,
  E3,
  E4,
  E5,
  E6,
  E7,
  P1,
  P3,
  P4,
  P5,
  P6,
  P7,
} from './dopri5Tableau.js'
import { exp, log, pow } from '../math.js'

/** Right-hand side: write dy/dt at (t, y) into `dydt`. Must not keep references to the arrays. */
export type OdeRhs = (t: number, y: Float64Array, dydt: Float64Array) => void

/** Event function g(t, y); an event happens where g crosses zero in the requested direction. */
export type EventFunction = (t: number, y: Float64Array) => number

export interface OdeEvent {
  readonly g: EventFunction
  /** +1: only rising crossings (g goes from < 0 to ≥ 0); −1: only falling ones; 0: both */
  readonly direction: -1 | 0 | 1
}

export interface Dopri5Options {
  /** relative tolerance of the local error */
  readonly rtol: number
  /** absolute tolerance of the local error (same for every component) */
  readonly atol: number
  /** largest step allowed; keeps event functions from changing sign twice unseen within one step */
  readonly hMax?: number
  /** first step; estimated from the problem (Hairer's heuristic) when omitted */
  readonly hInit?: number
  /** accepted plus rejected steps before giving up */
  readonly maxSteps?: number
}

export type Dopri5Status = 'reachedEnd' | 'event' | 'maxSteps' | 'stepUnderflow'

export interface Dopri5Result {
  readonly status: Dopri5Status
  /** time reached; the state there has been written back into `y` */
  readonly t: number
  /** index of the event that stopped the integration, −1 if none */
  readonly event: number
  readonly accepted: number
  readonly rejected: number
  /** right-hand side evaluations */
  readonly evaluations: number
}

export interface Dopri5Workspace {
  readonly n: number
  readonly maxEvents: number
  readonly k1: Float64Array
  readonly k2: Float64Array
  readonly k3: Float64Array
  readonly k4: Float64Array
  readonly k5: Float64Array
  readonly k6: Float64Array
  readonly k7: Float64Array
  /** 5th-order solution at the end of the step being tried */
  readonly yNew: Float64Array
  /** argument of the stage evaluations */
  readonly yStage: Float64Array
  /** interpolated state (dense output) */
  readonly yDense: Float64Array
  /** event function values at the start of the current step */
  readonly gPrev: Float64Array
  /** event function values at the end of the current step */
  readonly gNew: Float64Array
  /** state at the start of the last step of the latest `dopri5` call (for `dopri5DenseOutput`) */
  readonly yStart: Float64Array
  /** start time and size of that step (NaN before the first call) */
  lastStepStart: number
  lastStepSize: number
}

// ---- step-size control (Hairer's DOPRI5 defaults) ----
/** fraction of the "optimal" step actually taken, so that the next step is likely accepted */
export const DOPRI5_SAFETY = 0.9
/** the step never shrinks by more than this factor at once (avoids collapsing on a single bad estimate) */
export const DOPRI5_MIN_FACTOR = 0.2
/** the step never grows by more than this factor at once (the error estimate is only asymptotic) */
export const DOPRI5_MAX_FACTOR = 10
/** PI-controller weight of the previous error (Gustafsson); 0.04 is Hairer's value for DOPRI5 */
export const DOPRI5_PI_BETA = 0.04
/** floor on the remembered previous error, so one tiny error cannot make the PI term explode */
const PREVIOUS_ERROR_FLOOR = 1e-4
/** default cap on accepted plus rejected steps */
export const DOPRI5_DEFAULT_MAX_STEPS = 100_000
/** a step below this many ulps of t cannot advance time: give up rather than loop */
const STEP_UNDERFLOW_ULPS = 16
/** when the remaining interval is within this factor of the step, take it exactly (no sliver step) */
const LAST_STEP_STRETCH = 1.01
/** Brent tolerance on the event's position within a step, as a fraction of the step (machine level) */
const EVENT_STEP_FRACTION_TOL = 1e-15

/** Work arrays for a system of dimension `n` with up to `maxEvents` event functions. */
export function createDopri5Workspace(n: number, maxEvents = 4): Dopri5Workspace {
  if (!Number.isInteger(n) || n < 1) throw new RangeError('n must be an integer ≥ 1')
  if (!Number.isInteger(maxEvents) || maxEvents < 0) throw new RangeError('maxEvents must be an integer ≥ 0')
  const a = () => new Float64Array(n)
  return {
    n,
    maxEvents,
    k1: a(),
    k2: a(),
    k3: a(),
    k4: a(),
    k5: a(),
    k6: a(),
    k7: a(),
    yNew: a(),
    yStage: a(),
    yDense: a(),
    gPrev: new Float64Array(maxEvents),
    gNew: new Float64Array(maxEvents),
    yStart: a(),
    lastStepStart: Number.NaN,
    lastStepSize: Number.NaN,
  }
}

function polyAt(p: readonly [number, number, number, number], x: number): number {
  return x * (p[0] + x * (p[1] + x * (p[2] + x * p[3])))
}

/**
 * Dense output of the step just computed in `ws` (from (t, y) with step h): writes y(t + x·h), x ∈ [0, 1],
 * into `out`. Exact (to rounding) at x = 0 and x = 1.
 */
export function dopri5Interpolate(ws: Dopri5Workspace, y: Float64Array, h: number, x: number, out: Float64Array): void {
  const b1 = polyAt(P1, x)
  const b3 = polyAt(P3, x)
  const b4 = polyAt(P4, x)
  const b5 = polyAt(P5, x)
  const b6 = polyAt(P6, x)
  const b7 = polyAt(P7, x)
  const { k1, k3, k4, k5, k6, k7 } = ws
  for (let i = 0; i < ws.n; i++) {
    out[i] = y[i]! + h * (b1 * k1[i]! + b3 * k3[i]! + b4 * k4[i]! + b5 * k5[i]! + b6 * k6[i]! + b7 * k7[i]!)
  }
}

/**
 * Dense output over the last step of the latest `dopri5` call on `ws` (the step that reached tEnd or held the
 * event): writes y(t) into `out` for t in [ws.lastStepStart, ws.lastStepStart + ws.lastStepSize].
 */
export function dopri5DenseOutput(ws: Dopri5Workspace, t: number, out: Float64Array): void {
  const h = ws.lastStepSize
  if (!(h > 0)) throw new RangeError('no step to interpolate: run dopri5 first')
  const x = (t - ws.lastStepStart) / h
  if (!(x >= 0 && x <= 1)) throw new RangeError('t is outside the last step')
  dopri5Interpolate(ws, ws.yStart, h, x, out)
}

/** Weighted RMS norm of `v` with weights atol + rtol·max(|a_i|, |b_i|). */
function weightedNorm(v: Float64Array, a: Float64Array, b: Float64Array, n: number, rtol: number, atol: number): number {
  let s = 0
  for (let i = 0; i < n; i++) {
    const w = atol + rtol * Math.max(Math.abs(a[i]!), Math.abs(b[i]!))
    const q = v[i]! / w
    s += q * q
  }
  return Math.sqrt(s / n)
}

/**
 * Hairer's initial step heuristic (HNW I, §II.4): make the first explicit Euler step's change, and its
 * estimated second-derivative term, of the order of the tolerance. Uses one extra evaluation (counted by
 * the caller) and `ws.yStage`/`ws.k2` as scratch.
 */
function initialStep(ws: Dopri5Workspace, rhs: OdeRhs, t: number, y: Float64Array, opts: Dopri5Options, hMax: number): number {
  const { n, k1, k2, yStage } = ws
  const d0 = weightedNorm(y, y, y, n, opts.rtol, opts.atol)
  const d1 = weightedNorm(k1, y, y, n, opts.rtol, opts.atol)
  // 1e-5 and 1e-6: Hairer's guards for a state or slope that is (relatively) zero
  let h0 = d0 < 1e-5 || d1 < 1e-5 ? 1e-6 : (0.01 * d0) / d1
  h0 = Math.min(h0, hMax)
  for (let i = 0; i < n; i++) yStage[i] = y[i]! + h0 * k1[i]!
  rhs(t + h0, yStage, k2)
  for (let i = 0; i < n; i++) k2[i] = k2[i]! - k1[i]!
  const d2 = weightedNorm(k2, y, y, n, opts.rtol, opts.atol) / h0
  const dm = Math.max(d1, d2)
  const h1 = dm <= 1e-15 ? Math.max(1e-6, h0 * 1e-3) : pow(0.01 / dm, 1 / 5)
  return Math.min(100 * h0, h1, hMax)
}

function crosses(direction: -1 | 0 | 1, g0: number, g1: number): boolean {
  const rising = g0 < 0 && g1 >= 0
  const falling = g0 > 0 && g1 <= 0
  return direction > 0 ? rising : direction < 0 ? falling : rising || falling
}

/**
 * Integrates y' = rhs(t, y) from t0 to tEnd (tEnd ≥ t0) with the state in `y` (overwritten with the final
 * state), stopping early at the first event crossing. Returns the status and the time reached.
 */
export function dopri5(
  ws: Dopri5Workspace,
  rhs: OdeRhs,
  t0: number,
  y: Float64Array,
  tEnd: number,
  opts: Dopri5Options,
  events: readonly OdeEvent[] = [],
): Dopri5Result {
  const { n, k1, k2, k3, k4, k5, k6, k7, yNew, yStage, yDense, gPrev, gNew } = ws
  if (y.length < n) throw new RangeError('y is shorter than the workspace dimension')
  if (events.length > ws.maxEvents) throw new RangeError('more events than the workspace holds')
  if (!(opts.rtol > 0) || !(opts.atol > 0)) throw new RangeError('rtol and atol must be > 0')
  if (!(tEnd >= t0)) throw new RangeError('tEnd must be ≥ t0 (forward integration only)')
  const hMax = opts.hMax ?? tEnd - t0
  const maxSteps = opts.maxSteps ?? DOPRI5_DEFAULT_MAX_STEPS
  let t = t0
  let accepted = 0
  let rejected = 0
  let evaluations = 0
  const done = (status: Dopri5Status, event = -1): Dopri5Result => ({ status, t, event, accepted, rejected, evaluations })
  if (tEnd === t0) return done('reachedEnd')

  for (let e = 0; e < events.length; e++) gPrev[e] = events[e]!.g(t, y)
  rhs(t, y, k1)
  evaluations++
  let h: number
  if (opts.hInit !== undefined) {
    h = Math.min(opts.hInit, hMax)
  } else {
    h = initialStep(ws, rhs, t, y, opts, hMax)
    evaluations++
  }
  let errOld = PREVIOUS_ERROR_FLOOR
  let logErrOld = log(errOld)
  let lastRejected = false
  const expo = 0.2 - DOPRI5_PI_BETA * 0.75 // Hairer: 1/5 minus 0.75·β for the current-error exponent

  while (true) {
    if (accepted + rejected >= maxSteps) return done('maxSteps')
    if (h < STEP_UNDERFLOW_ULPS * Number.EPSILON * Math.max(1, Math.abs(t))) return done('stepUnderflow')
    let last = false
    if (t + LAST_STEP_STRETCH * h >= tEnd) {
      h = tEnd - t
      last = true
    }

    for (let i = 0; i < n; i++) yStage[i] = y[i]! + h * A21 * k1[i]!
    rhs(t + C2 * h, yStage, k2)
    for (let i = 0; i < n; i++) yStage[i] = y[i]! + h * (A31 * k1[i]! + A32 * k2[i]!)
    rhs(t + C3 * h, yStage, k3)
    for (let i = 0; i < n; i++) yStage[i] = y[i]! + h * (A41 * k1[i]! + A42 * k2[i]! + A43 * k3[i]!)
    rhs(t + C4 * h, yStage, k4)
    for (let i = 0; i < n; i++) {
      yStage[i] = y[i]! + h * (A51 * k1[i]! + A52 * k2[i]! + A53 * k3[i]! + A54 * k4[i]!)
    }
    rhs(t + C5 * h, yStage, k5)
    for (let i = 0; i < n; i++) {
      yStage[i] = y[i]! + h * (A61 * k1[i]! + A62 * k2[i]! + A63 * k3[i]! + A64 * k4[i]! + A65 * k5[i]!)
    }
    const tNew = last ? tEnd : t + h
    rhs(tNew, yStage, k6)
    for (let i = 0; i < n; i++) {
      yNew[i] = y[i]! + h * (B1 * k1[i]! + B3 * k3[i]! + B4 * k4[i]! + B5 * k5[i]! + B6 * k6[i]!)
    }
    rhs(tNew, yNew, k7)
    evaluations += 6
    // local error estimate, kept in yStage (no longer needed this step)
    for (let i = 0; i < n; i++) {
      yStage[i] = h * (E1 * k1[i]! + E3 * k3[i]! + E4 * k4[i]! + E5 * k5[i]! + E6 * k6[i]! + E7 * k7[i]!)
    }
    const err = weightedNorm(yStage, y, yNew, n, opts.rtol, opts.atol)

    // PI controller; a zero error would give an infinite factor, the clamp below handles it
    // err^expo / errOld^β as one exp of logarithms (log errOld kept from the step that set it): two
    // portable pows cost twice as much, and the factor needs no more digits than this gives
    const logErr = log(err)
    let fac = exp(expo * logErr - DOPRI5_PI_BETA * logErrOld) / DOPRI5_SAFETY // 1/fac = growth factor
    fac = Math.max(1 / DOPRI5_MAX_FACTOR, Math.min(1 / DOPRI5_MIN_FACTOR, fac))

    if (err <= 1) {
      accepted++
      errOld = Math.max(err, PREVIOUS_ERROR_FLOOR)
      logErrOld = log(errOld)
      // event location on the dense output of this step
      let hit = -1
      let hitX = 2
      for (let e = 0; e < events.length; e++) gNew[e] = events[e]!.g(tNew, yNew)
      for (let e = 0; e < events.length; e++) {
        const ev = events[e]!
        if (!crosses(ev.direction, gPrev[e]!, gNew[e]!)) continue
        const after: 1 | -1 = gNew[e]! > gPrev[e]! ? 1 : -1
        const hStep = h
        const tStep = t
        const phi = (x: number): number => {
          dopri5Interpolate(ws, y, hStep, x, yDense)
          return ev.g(tStep + x * hStep, yDense)
        }
        const x = brentRoot(phi, 0, 1, gPrev[e]!, gNew[e]!, EVENT_STEP_FRACTION_TOL, after)
        if (x < hitX) {
          hitX = x
          hit = e
        }
      }
      if (hit >= 0 || last) {
        // keep the final step for dopri5DenseOutput (k1..k7 are still this step's stages)
        ws.yStart.set(y.subarray(0, n))
        ws.lastStepStart = t
        ws.lastStepSize = h
      }
      if (hit >= 0) {
        const tHit = hitX >= 1 ? tNew : t + hitX * h
        dopri5Interpolate(ws, y, h, hitX, yDense)
        for (let i = 0; i < n; i++) y[i] = hitX >= 1 ? yNew[i]! : yDense[i]!
        t = tHit
        return done('event', hit)
      }
      for (let i = 0; i < n; i++) y[i] = yNew[i]!
      t = tNew
      if (last) return done('reachedEnd') // k1 left alone: the step stays available for dense output
      for (let i = 0; i < n; i++) k1[i] = k7[i]! // first same as last
      for (let e = 0; e < events.length; e++) gPrev[e] = gNew[e]!
      let hNew = h / fac
      if (lastRejected) hNew = Math.min(hNew, h) // no growth right after a rejection
      h = Math.min(hNew, hMax)
      lastRejected = false
    } else {
      rejected++
      h = h / Math.min(1 / DOPRI5_MIN_FACTOR, exp(expo * logErr) / DOPRI5_SAFETY)
      lastRejected = true
    }
  }
}
