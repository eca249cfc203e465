// Public data of the physical reference model (docs/reference-model.md): the input and its validation, the
// outcome, the phase trace and the lip state. No behaviour beyond checking an input.
import { describe, readSpec } from '../check.js'
import { MAX_RATIO, MAX_SCALED_SPEED } from './tolerances.js'

export interface ReferenceInput {
  /** offset of the straight path from the hole centre (its closest approach); |delta| < holeRadius */
  delta: number
  /** speed when the centre crosses the lip circle */
  speed: number
  holeRadius: number
  ballRadius: number
  gravity: number
  /** j in I = j·m·r²: 2/5 solid sphere, 2/3 thin shell */
  inertia: number
}

/**
 * How a run ended. `rolledOut`: θ back to 0, the ball rolls away on the surface; `hoppedOut`: landed on the
 * surface outside the hole after a flight; `droppedFromLip`: θ reached −π/2 while rolling on the lip;
 * `droppedInFlight`: the centre went below lip level inside the hole in flight; `phaseLimit`, `timeLimit`,
 * `integratorLimit`, `flightLimit`: a guard stopped the run before an outcome (the phases, the time, the lip
 * integrator's steps or the flight search's samples ran out), and `outOfDomain`: the scaled input lies outside
 * the model's domain (R/r above MAX_RATIO, 1e8, or v/√(g·r) above MAX_SCALED_SPEED, 1e12; only the engine's internal runs
 * can meet it, the public functions refuse such input); then `captured` is false and no exit is given.
 */
export type ReferenceEnding =
  | 'rolledOut'
  | 'hoppedOut'
  | 'droppedFromLip'
  | 'droppedInFlight'
  | 'phaseLimit'
  | 'timeLimit'
  | 'integratorLimit'
  | 'flightLimit'
  | 'outOfDomain'

/** Whether a run ended on a guard (or outside the domain) rather than an outcome: no capture, no exit. */
export function isGuarded(ending: ReferenceEnding): boolean {
  return ending === 'phaseLimit' || ending === 'timeLimit' || ending === 'integratorLimit' || ending === 'flightLimit' || ending === 'outOfDomain'
}

export interface ReferenceOutcome {
  captured: boolean
  /** radians the contact point travelled round the lip: |Σ Δψ| over the rolling phases (flights excluded) */
  turnAngle: number
  /** escaped only: speed when leaving (rolled out: at θ = 0; hopped out: horizontal speed at landing) */
  exitSpeed?: number
  /** escaped only: direction of the exit velocity in the plane, radians, relative to the incoming +x */
  exitAngle?: number
  /**
   * escaped only: where the centre left, in the plane (hole centre at the origin, the ball came along +x at
   * y = δ): on the lip circle when rolled out, the landing point when hopped out
   */
  exitX?: number
  exitY?: number
  ending: ReferenceEnding
  /** number of impacts with the lip */
  impacts: number
  /** number of lip and flight phases */
  phases: number
  /** time from the lip crossing to the end, in the input's time unit */
  duration: number
}

export type PhaseEnd =
  | 'liftOff'
  | 'rolledOut'
  | 'droppedFromLip'
  | 'impact'
  | 'landed'
  | 'droppedInFlight'
  | 'timeLimit'
  | 'integratorLimit'
  | 'noClearance'
  | 'sampleLimit'
  | 'clear'
  | 'pressing'

/** One phase of a run, in the input's units. Lip phases carry θ, ψ and E/m at both ends. */
export interface PhaseRecord {
  kind: 'lip' | 'flight'
  tStart: number
  tEnd: number
  end: PhaseEnd
  /** lip phases: contact angle and tilt at the start and the end */
  psiStart?: number
  psiEnd?: number
  thetaStart?: number
  thetaEnd?: number
  /** lip phases: energy per mass E/m = ½(1+j)(ρ²ψ̇² + r²θ̇²) + ½ j r² ω_n² + g r cosθ at both ends */
  energyStart?: number
  energyEnd?: number
  /** lip phases: DOPRI5 accepted and rejected steps */
  steps?: number
  /** lip phases: a held roll (N ≤ 0 but the free path would run into the lip; see the docs) */
  held?: boolean
}

export interface ReferenceTrace {
  outcome: ReferenceOutcome
  phases: PhaseRecord[]
}

/** Lip state in the input's units: contact angle ψ, tilt θ (θ < 0: centre over the hole), their rates, ω_n. */
export interface LipState {
  psi: number
  theta: number
  psiDot: number
  thetaDot: number
  omegaN: number
}

const INPUT_KEYS = ['delta', 'speed', 'holeRadius', 'ballRadius', 'gravity', 'inertia'] as const

/** A number that is finite: a TypeError for another type, a RangeError for NaN or ±Infinity, naming it. */
export function checkFinite(name: string, value: unknown): void {
  if (typeof value !== 'number') throw new TypeError(`${name} must be a finite number, got ${describe(value)}`)
  if (!Number.isFinite(value)) throw new RangeError(`${name} must be a finite number, got ${value}`)
}

/** Throws a TypeError (not an object, a field not a number) or a RangeError naming the first field out of range, and what it got. */
export function validateReferenceInput(input: ReferenceInput): void {
  const { delta, speed, holeRadius, ballRadius, gravity, inertia } = readSpec('reference input', input, INPUT_KEYS, 'input') as unknown as ReferenceInput
  // the model's domain (src/reference/tolerances.ts) bounds the ratio R/r (in validateLipGeometry) and the scaled speed v/√(g·r)
  validateLipGeometry(holeRadius, ballRadius, gravity, inertia)
  checkFinite('delta', delta)
  if (!(Math.abs(delta) < holeRadius)) throw new RangeError(`delta must be in (−holeRadius, holeRadius) = (${-holeRadius}, ${holeRadius}), got ${delta}`)
  checkFinite('speed', speed)
  const vMax = MAX_SCALED_SPEED * Math.sqrt(gravity * ballRadius)
  if (!(speed > 0 && speed <= vMax)) throw new RangeError(`speed must be in (0, ${MAX_SCALED_SPEED}·√(gravity·ballRadius)] = (0, ${vMax}], got ${speed}`)
}

/** A lip's geometry and the ball's (R, r, g, j; validateReferenceInput's first checks, and lipEnergy's and rollOnLip's). */
export function validateLipGeometry(holeRadius: number, ballRadius: number, gravity: number, inertia: number): void {
  checkFinite('holeRadius', holeRadius)
  if (!(holeRadius > 0)) throw new RangeError(`holeRadius must be in (0, ∞), got ${holeRadius}`)
  checkFinite('ballRadius', ballRadius)
  if (!(ballRadius > 0 && ballRadius < holeRadius && holeRadius <= MAX_RATIO * ballRadius)) {
    throw new RangeError(`ballRadius must be in [holeRadius / ${MAX_RATIO}, holeRadius) = [${holeRadius / MAX_RATIO}, ${holeRadius}), got ${ballRadius}`)
  }
  checkFinite('gravity', gravity)
  if (!(gravity > 0)) throw new RangeError(`gravity must be in (0, ∞), got ${gravity}`)
  checkFinite('inertia', inertia)
  // a spherically symmetric mass inside radius r has 0 < j ≤ 2/3 (the thin shell is the extreme)
  if (!(inertia > 0 && inertia <= 2 / 3)) throw new RangeError(`inertia must be in (0, 2/3], got ${inertia}`)
}

const LIP_STATE_KEYS = ['psi', 'theta', 'psiDot', 'thetaDot', 'omegaN'] as const

/** A lip state's fields, each a finite number (TypeError or RangeError naming the field otherwise). */
export function readLipState(start: unknown): LipState {
  const s = readSpec('start', start, LIP_STATE_KEYS)
  for (const key of LIP_STATE_KEYS) checkFinite(`start.${key}`, s[key] as number)
  return s as unknown as LipState
}
