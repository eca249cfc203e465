// An independent rigid-sphere-meets-sharp-lip model (docs/physical.md, "An independent model"), to check
// the project's reference (src/reference/) and the tabulated rim model against a second, separately written
// solution of the same idealisation: a rigid sphere that never slips on a sharp circular lip, plastic
// no-slip impacts, no rolling resistance. Nothing here is imported from src/reference/.
//
// How it differs from the reference:
// - formulation: Newton–Euler for the sphere in Cartesian vectors (independentSphere.ts), the lip contact a
//   constraint whose force is solved at every evaluation; no lip angles, no reduced equations;
// - units: the game's own (px, s), no scaling;
// - numerics: classical RK4 with a fixed step (INDEPENDENT_STEP), a projection back onto the lip after each
//   step on it, and events located by bisection on the length of a single RK4 step from the step's start;
//   dips of an event function inside one step (a graze) are found from its rate at the step's ends; the
//   flight is integrated like everything else (RK4 is exact on a parabola);
// - the roll that cannot let go (N < 0 while the free path would cut into the lip) is kept on the lip by
//   its own rule: the ball leaves only when its free path stays clear of the lip for LOOK_AHEAD.
import type { ReferenceInput } from '../reference/types.js'
import { STATE_SIZE, energy, flightDerivative, lipDerivative, lipGap, lipGapRate, projectOntoLip, type SphereLip } from './independentSphere.js'

/** RK4 step, in units of √(r/g) (1/200: halving it changes no cell of the game's map; docs/physical.md). */
export const INDEPENDENT_STEP = 1 / 200
/** A ball leaves the lip only if its free path stays clear of the lip this long, in √(r/g). */
export const LOOK_AHEAD = 1e-3
/** Runs that have not decided after this long stop and count as escapes, in √(r/g). */
export const MAX_TIME = 2000
/** Runs that have not decided after this many rolls and flights stop and count as escapes. */
export const MAX_PHASES = 2000

/** The same input as the reference's (only the type is shared: none of the reference's code). */
export type IndependentInput = ReferenceInput

export interface IndependentOptions {
  /** RK4 step in √(r/g) (default INDEPENDENT_STEP) */
  step?: number
  /** look-ahead of a lift-off in √(r/g) (default LOOK_AHEAD) */
  lookAhead?: number
  /** time guard in √(r/g) (default MAX_TIME) */
  maxTime?: number
  /** called at the crossing and after every change of phase and the decision, with the time (s) and the state */
  trace?: (what: IndependentEvent, time: number, state: Float64Array) => void
}

/** What a trace call reports: the run's start, a lift-off, a held roll, a re-touch, or the ending. */
export type IndependentEvent = 'start' | 'liftOff' | 'held' | 'released' | 'impact' | IndependentEnding

export type IndependentEnding = 'rolledOut' | 'hoppedOut' | 'droppedFromLip' | 'droppedInFlight' | 'timeLimit' | 'phaseLimit'

export interface IndependentOutcome {
  captured: boolean
  ending: IndependentEnding
  /** re-touches of the lip from flight */
  impacts: number
  /** times the ball left the lip into flight (including a start in flight) */
  liftOffs: number
  /** times N fell below 0 while the free path would have cut into the lip, so the ball stayed on */
  held: number
  /** whether any decision consulted the look-ahead (a run without one does not depend on LOOK_AHEAD) */
  lookedAhead: boolean
  /** time from the lip crossing to the decision, s */
  duration: number
  steps: number
  /** largest |E − E₀|/E₀ over the rolls on the lip, E₀ the energy at the roll's start */
  energyDrift: number
}

const LIP = 0
const FLIGHT = 1
/** event slots: 0 the centre sinks to lip level, 1 the lip (roll-out on the lip, contact in flight), 2 N or landing */
const EVENTS = 3
/** bisections that locate an event in a step: the step's length over 2⁶⁰, far below a double's resolution of t */
const BISECTIONS = 60

const P: SphereLip = { R: 0, r: 0, g: 0, j: 0 }
const y = new Float64Array(STATE_SIZE)
const yEnd = new Float64Array(STATE_SIZE)
const yTry = new Float64Array(STATE_SIZE)
const k1 = new Float64Array(STATE_SIZE)
const k2 = new Float64Array(STATE_SIZE)
const k3 = new Float64Array(STATE_SIZE)
const k4 = new Float64Array(STATE_SIZE)
const mid = new Float64Array(STATE_SIZE)
const scratch = new Float64Array(STATE_SIZE)
const v0 = new Float64Array(EVENTS)
const v1 = new Float64Array(EVENTS)
const s0 = new Float64Array(EVENTS)
const s1 = new Float64Array(EVENTS)
const vt = new Float64Array(EVENTS)
const st = new Float64Array(EVENTS)

function deriv(mode: number, x: Float64Array, out: Float64Array): void {
  if (mode === LIP) lipDerivative(P, x, out)
  else flightDerivative(P, x, out)
}

/** One classical RK4 step of length h from `from` into `to` (no projection). */
function rk4(mode: number, from: Float64Array, h: number, to: Float64Array): void {
  deriv(mode, from, k1)
  for (let i = 0; i < STATE_SIZE; i++) mid[i] = from[i]! + 0.5 * h * k1[i]!
  deriv(mode, mid, k2)
  for (let i = 0; i < STATE_SIZE; i++) mid[i] = from[i]! + 0.5 * h * k2[i]!
  deriv(mode, mid, k3)
  for (let i = 0; i < STATE_SIZE; i++) mid[i] = from[i]! + h * k3[i]!
  deriv(mode, mid, k4)
  for (let i = 0; i < STATE_SIZE; i++) to[i] = from[i]! + (h / 6) * (k1[i]! + 2 * k2[i]! + 2 * k3[i]! + k4[i]!)
}

/**
 * Event values (an event fires when its value falls from > 0 to ≤ 0) and their rates (NaN: no graze check).
 * On the lip: 0 z (dropped), 1 R − ρ (rolled out), 2 N/m (lift-off), or −N/m while held (N back above 0).
 * In flight: 0 z (dropped inside the hole), 1 the lip gap (re-touch), 2 z − r outside the hole (landed).
 */
function eventValues(mode: number, held: boolean, x: Float64Array, val: Float64Array, rate: Float64Array): void {
  const rho = Math.sqrt(x[0]! * x[0]! + x[1]! * x[1]!)
  const rhoDot = (x[0]! * x[3]! + x[1]! * x[4]!) / rho
  val[0] = x[2]!
  rate[0] = x[5]!
  if (mode === LIP) {
    val[1] = P.R - rho
    rate[1] = -rhoDot
    const n = lipDerivative(P, x, scratch)
    val[2] = held ? -n : n
    rate[2] = Number.NaN
  } else {
    val[1] = lipGap(P, x[0]!, x[1]!, x[2]!)
    rate[1] = lipGapRate(P, x)
    // outside the hole the flat is there; inside, the lip is met first (its gap is < 0 at ρ = R, z < r)
    val[2] = rho >= P.R ? x[2]! - P.r : 1
    rate[2] = Number.NaN
  }
}

/** The free path from x stays clear of the lip over `ahead` seconds (8 samples; the gap opens like t² or t³). */
function freePathClear(x: Float64Array, ahead: number): boolean {
  for (let s = 1; s <= 8; s++) {
    const t = (s / 8) * ahead
    if (lipGap(P, x[0]! + x[3]! * t, x[1]! + x[4]! * t, x[2]! + x[5]! * t - 0.5 * P.g * t * t) <= 0) return false
  }
  return true
}

/** Step length in (lo, hi] at which event e first fires from y, located by bisection; hi fires, lo does not. */
function locate(mode: number, held: boolean, e: number, lo: number, hi: number): number {
  for (let n = 0; n < BISECTIONS && hi - lo > 0; n++) {
    const m = 0.5 * (lo + hi)
    if (m <= lo || m >= hi) break
    rk4(mode, y, m, yTry)
    eventValues(mode, held, yTry, vt, st)
    if (vt[e]! <= 0) hi = m
    else lo = m
  }
  return hi
}

/** Where event e's value is smallest inside (0, h), its rate going from < 0 to > 0; returns the step length. */
function lowest(mode: number, held: boolean, e: number, h: number): number {
  let lo = 0
  let hi = h
  for (let n = 0; n < BISECTIONS; n++) {
    const m = 0.5 * (lo + hi)
    if (m <= lo || m >= hi) break
    rk4(mode, y, m, yTry)
    eventValues(mode, held, yTry, vt, st)
    if (st[e]! < 0) lo = m
    else hi = m
  }
  rk4(mode, y, hi, yTry)
  eventValues(mode, held, yTry, vt, st)
  return hi
}

/**
 * Capture or escape of a ball whose centre crosses the lip circle at offset δ from the hole's centre and
 * speed v, rolling straight (without slip) on the flat. Not reentrant: one module-level workspace.
 */
export function independentOutcome(input: IndependentInput, options: IndependentOptions = {}): IndependentOutcome {
  const { delta, speed, holeRadius: R, ballRadius: r, gravity: g, inertia: j } = input
  if (!(R > 0 && r > 0 && r < R && g > 0 && j > 0 && j <= 2 / 3 && delta >= 0 && delta < R && speed > 0)) {
    throw new RangeError('independentOutcome: need 0 < ballRadius < holeRadius, gravity > 0, inertia in (0, 2/3], 0 ≤ delta < holeRadius, speed > 0')
  }
  P.R = R
  P.r = r
  P.g = g
  P.j = j
  const unit = Math.sqrt(r / g)
  const h = (options.step ?? INDEPENDENT_STEP) * unit
  const ahead = (options.lookAhead ?? LOOK_AHEAD) * unit
  const maxTime = (options.maxTime ?? MAX_TIME) * unit
  const out: IndependentOutcome = {
    captured: false,
    ending: 'timeLimit',
    impacts: 0,
    liftOffs: 0,
    held: 0,
    lookedAhead: false,
    duration: 0,
    steps: 0,
    energyDrift: 0,
  }

  // at the crossing: centre over the lip, rolling along +x (ω = ẑ × V / r); both contacts at the lip point
  y.fill(0)
  y[0] = -Math.sqrt(R * R - delta * delta)
  y[1] = delta
  y[2] = r
  y[3] = speed
  y[7] = speed / r
  let t = 0
  let mode = LIP
  let held = false
  let phases = 1
  let e0 = energy(P, y)
  /** the next step's length (shorter once, at the start of a flight: the look-ahead already checked) */
  let next = h
  const note = (what: IndependentEvent): void => options.trace?.(what, t, y)
  note('start')

  /** Leaves the lip at the current state, or holds it there: the look-ahead decides. */
  const leaveOrHold = (): void => {
    out.lookedAhead = true
    if (freePathClear(y, ahead)) {
      mode = FLIGHT
      held = false
      out.liftOffs++
      phases++
      next = ahead
      note('liftOff')
    } else {
      if (!held || mode !== LIP) out.held++
      mode = LIP
      held = true
      note('held')
    }
  }
  if (lipDerivative(P, y, scratch) < 0) leaveOrHold()

  eventValues(mode, held, y, v0, s0)
  for (;;) {
    if (t > maxTime) {
      out.ending = 'timeLimit'
      break
    }
    if (phases > MAX_PHASES) {
      out.ending = 'phaseLimit'
      break
    }
    const step = next
    next = h
    rk4(mode, y, step, yEnd)
    eventValues(mode, held, yEnd, v1, s1)
    out.steps++
    // the earliest event in the step, crossing or graze
    let first = -1
    let at = Infinity
    for (let e = 0; e < EVENTS; e++) {
      if (!(v0[e]! > 0)) continue
      let tau = Infinity
      if (v1[e]! <= 0) tau = locate(mode, held, e, 0, step)
      else if (s0[e]! < 0 && s1[e]! > 0) {
        const m = lowest(mode, held, e, step)
        if (vt[e]! <= 0) tau = locate(mode, held, e, 0, m)
      }
      if (tau < at) {
        at = tau
        first = e
      }
    }
    if (first < 0) {
      // a held ball leaves as soon as its free path clears the lip: bisect the step for that moment
      let length = step
      const leave = mode === LIP && held && freePathClear(yEnd, ahead)
      if (leave) {
        let lo = 0
        for (let n = 0; n < BISECTIONS; n++) {
          const m = 0.5 * (lo + length)
          if (m <= lo || m >= length) break
          rk4(LIP, y, m, yTry)
          if (freePathClear(yTry, ahead)) length = m
          else lo = m
        }
        if (length < step) rk4(LIP, y, length, yEnd)
      }
      y.set(yEnd)
      t += length
      if (mode === LIP) {
        projectOntoLip(P, y)
        const drift = Math.abs(energy(P, y) - e0) / e0
        if (drift > out.energyDrift) out.energyDrift = drift
        if (leave) leaveOrHold()
      }
      eventValues(mode, held, y, v0, s0)
      continue
    }
    // to the event, on its far side
    rk4(mode, y, at, yEnd)
    y.set(yEnd)
    t += at
    if (mode === LIP) {
      projectOntoLip(P, y)
      if (first === 0) {
        out.captured = true
        out.ending = 'droppedFromLip'
        break
      }
      if (first === 1) {
        out.ending = 'rolledOut'
        break
      }
      if (held) {
        held = false
        note('released')
      } else leaveOrHold()
    } else {
      if (first === 0) {
        out.captured = true
        out.ending = 'droppedInFlight'
        break
      }
      if (first === 2) {
        out.ending = 'hoppedOut'
        break
      }
      // re-touch: plastic, no-slip impact; then roll if the lip pushes, else leave again (or hold)
      out.impacts++
      projectOntoLip(P, y)
      mode = LIP
      held = false
      phases++
      e0 = energy(P, y)
      note('impact')
      if (lipDerivative(P, y, scratch) < 0) leaveOrHold()
    }
    eventValues(mode, held, y, v0, s0)
  }
  out.duration = t
  note(out.ending)
  return out
}
