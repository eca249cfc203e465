// Rolling on the lip (phase 2): the lip equations of motion, the normal force and the energy, the events that
// end a roll (rolled out, dropped in, lift-off; and those of a held roll), the integrator settings and
// workspace, and the public lipEnergy and rollOnLip. Scaled units (r = g = 1) except in the public functions.

import { createDopri5Workspace, dopri5, type OdeEvent, type OdeRhs } from './dopri5.js'
import { freePathClearance } from './flight.js'
import { P, lip } from './state.js'
import { LIP_ATOL, LIP_MAX_STEP, LIP_MAX_STEPS, LIP_RTOL } from './tolerances.js'
import { readLipState, validateLipGeometry, type LipState } from './types.js'
import { cos, sin } from '../math.js'
import { describe } from '../check.js'

/** Lip ODEs (docs/reference-model.md, phase 2) in units r = g = 1; y = [ψ, θ, ψ̇, θ̇, ω_n]. */
export const lipRhs: OdeRhs = (_t, y, dy) => {
  const th = y[1]!
  const pd = y[2]!
  const td = y[3]!
  const wn = y[4]!
  const s = sin(th)
  const c = cos(th)
  const j = P.j
  const rho = P.rs + s
  dy[0] = pd
  dy[1] = td
  // (1+j)(ρ ψ̈ + 2 r cosθ θ̇ ψ̇) = j r ω_n θ̇
  dy[2] = ((j / (1 + j)) * wn * td - 2 * c * td * pd) / rho
  // (1+j)(r θ̈ − ρ ψ̇² cosθ) = g sinθ − j r ω_n ψ̇ sinθ
  dy[3] = rho * pd * pd * c + (s - j * wn * pd * s) / (1 + j)
  // ω̇_n = −(R/r) ψ̇ θ̇
  dy[4] = -P.rs * pd * td
}

/** Normal force per mass on the lip, units g: N/m = g cosθ − r θ̇² − ρ ψ̇² sinθ. */
export function normalForce(y: Float64Array, rs: number): number {
  const th = y[1]!
  const pd = y[2]!
  const td = y[3]!
  const s = sin(th)
  return cos(th) - td * td - (rs + s) * pd * pd * s
}

/** E/m on the lip in units g·r. */
export function lipEnergyScaled(y: Float64Array, rs: number, j: number): number {
  const th = y[1]!
  const pd = y[2]!
  const td = y[3]!
  const wn = y[4]!
  const rho = rs + sin(th)
  return 0.5 * (1 + j) * (rho * rho * pd * pd + td * td) + 0.5 * j * wn * wn + cos(th)
}

export const EVENT_ROLLED_OUT = 0
export const EVENT_DROPPED = 1
/** lip events (the ball presses on the lip): roll out, drop in, lift off */
export const LIP_EVENTS: readonly OdeEvent[] = [
  { g: (_t, y) => y[1]!, direction: 1 }, // θ rises through 0: centre back over the surface
  { g: (_t, y) => y[1]! + Math.PI / 2, direction: -1 }, // θ falls through −π/2: centre at lip level inside
  { g: (_t, y) => normalForce(y, P.rs), direction: -1 }, // N falls through 0: the lip lets go
]
export const EVENT_CLEAR = 2
/**
 * Held-roll events. At N = 0 the no-slip friction force is generally not zero, and dropping it can bend the
 * free path INTO the lip (gap ∝ −t³): then neither rolling (N < 0) nor flight (it penetrates) is consistent,
 * the no-slip idealisation's breakdown (a real ball slides there). The model keeps such a ball rolling on the
 * lip ("held") until the free path from its current state would be clear of the lip at HOLD_RELEASE_TIME, or
 * until it presses on the lip again (N rises through 0). A hop shorter than HOLD_PROBE_TIME is thereby merged
 * into the roll; it is rare (about 3 lift-offs in 5000 over the golf (δ, v) plane).
 */
export const HELD_EVENTS: readonly OdeEvent[] = [
  LIP_EVENTS[0]!,
  LIP_EVENTS[1]!,
  { g: (_t, y) => freePathClearance(y, P.rs), direction: 1 }, // the free path would now clear the lip
  { g: (_t, y) => normalForce(y, P.rs), direction: 1 }, // pressing on the lip again: roll normally
]

export const LIP_OPTIONS = { rtol: LIP_RTOL, atol: LIP_ATOL, hMax: LIP_MAX_STEP, maxSteps: LIP_MAX_STEPS } as const
export const ws = createDopri5Workspace(5, HELD_EVENTS.length)

/** E/m of a ball rolling on the lip: ½(1+j)(ρ²ψ̇² + r²θ̇²) + ½ j r² ω_n² + g r cosθ, ρ = R + r sinθ. */
export function lipEnergy(state: LipState, holeRadius: number, ballRadius: number, gravity: number, inertia: number): number {
  const s = readLipState(state)
  validateLipGeometry(holeRadius, ballRadius, gravity, inertia)
  const rho = holeRadius + ballRadius * sin(s.theta)
  const r = ballRadius
  return (
    0.5 * (1 + inertia) * (rho * rho * s.psiDot * s.psiDot + r * r * s.thetaDot * s.thetaDot) +
    0.5 * inertia * r * r * s.omegaN * s.omegaN +
    gravity * r * cos(s.theta)
  )
}

/**
 * Integrates the lip equations alone (no events: the lip is assumed to hold the ball whatever N) for
 * `duration` from `start`, in the input's units. For checking the integrator (energy) and for charts.
 */
export function rollOnLip(
  start: LipState,
  duration: number,
  holeRadius: number,
  ballRadius: number,
  gravity: number,
  inertia: number,
): { state: LipState; steps: number } {
  const s = readLipState(start)
  validateLipGeometry(holeRadius, ballRadius, gravity, inertia)
  if (typeof duration !== 'number') throw new TypeError(`duration must be a number in [0, ∞), got ${describe(duration)}`)
  if (!(duration >= 0 && Number.isFinite(duration))) throw new RangeError(`duration must be in [0, ∞), got ${duration}`)
  const T = Math.sqrt(ballRadius / gravity)
  P.rs = holeRadius / ballRadius
  P.j = inertia
  const y = lip
  y[0] = s.psi
  y[1] = s.theta
  y[2] = s.psiDot * T
  y[3] = s.thetaDot * T
  y[4] = s.omegaN * T
  const res = dopri5(ws, lipRhs, 0, y, duration / T, {
    rtol: LIP_RTOL,
    atol: LIP_ATOL,
    hMax: LIP_MAX_STEP,
    maxSteps: LIP_MAX_STEPS,
  })
  // a duration the integrator's steps cannot cover (LIP_MAX_STEPS at most LIP_MAX_STEP each, scaled)
  if (res.status !== 'reachedEnd') throw new RangeError(`rollOnLip: duration ${duration} is too long: the integrator stopped (${res.status}) at ${res.t * T}`)
  return {
    state: { psi: y[0]!, theta: y[1]!, psiDot: y[2]! / T, thetaDot: y[3]! / T, omegaN: y[4]! / T },
    steps: res.accepted + res.rejected,
  }
}
