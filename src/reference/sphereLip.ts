// Physical reference model: a rigid sphere rolling into a circular hole with a sharp lip
// (specification: shared/spec/reference-model.md). Headless, deterministic, no dependency.
//
// Frame: the hole is centred at the origin, the lip is the circle of radius R in the plane z = 0, the surface
// is z = 0 outside it, gravity is −g ẑ. The ball (radius r, inertia j·m·r²) rolls along +x at y = δ.
//
// Internally everything is in units r = g = 1 (lengths in r, times in √(r/g), speeds in √(g·r)), so the
// outcome depends only on R/r, δ/r, v/√(g·r) and j, and the tolerances below mean the same thing for a golf
// ball and for a game sprite.
//
// Phases (spec §Phases):
//  1. rolling on the surface up to the instant the centre crosses the lip circle: closed form (a straight
//     line at constant speed), so the model starts at that instant;
//  2. rolling on the lip without slip: state y = [ψ, θ, ψ̇, θ̇, ω_n] integrated by DOPRI5 with three events
//     (θ rises through 0: rolled out; θ falls through −π/2: dropped in; N falls through 0: lift-off);
//  3. ballistic flight with constant spin: closed form; the landing (centre descends to z = r outside the
//     hole) and the drop (centre descends to z = 0 inside) are roots of quadratics; the lip contact (distance
//     from the centre to the lip circle back to r while approaching) is bracketed by conservative advancement
//     on the closed form and refined with Brent's method;
//  4. perfectly plastic, no-slip impact with the lip (angular momentum about the contact point kept), then
//     back to 2 (or straight back to 3 if the lip cannot hold the ball: N < 0 after the impact).
// One addition to the spec, for a case it leaves open: a "held" roll when, at N ≤ 0, the free path would run
// straight back into the lip (see HELD_EVENTS).

import { brentRoot, createDopri5Workspace, dopri5, type OdeEvent, type OdeRhs } from './dopri5.js'

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
 * `integratorLimit`: a guard stopped the run before an outcome (then `captured` is false and no exit is given).
 */
export type ReferenceEnding =
  | 'rolledOut'
  | 'hoppedOut'
  | 'droppedFromLip'
  | 'droppedInFlight'
  | 'phaseLimit'
  | 'timeLimit'
  | 'integratorLimit'

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

// ---- guards and tolerances (scaled units: r = g = 1) ----
/** DOPRI5 relative tolerance on the lip: E/m drifts ~3e-13 per time unit (measured 3.4e-10 over 1000 units) */
export const LIP_RTOL = 1e-11
/** DOPRI5 absolute tolerance on the lip (state components are O(1) in units r = g = 1) */
export const LIP_ATOL = 1e-12
/** largest lip step (time units √(r/g)): the lift-off function N cannot dip below 0 and back unseen */
const LIP_MAX_STEP = 0.05
/** DOPRI5 step cap per lip phase (a 1000-unit roll takes ~10⁵ steps at the tolerances above) */
const LIP_MAX_STEPS = 2_000_000
/** smallest flight search step: at most this time (units √(r/g)) ... */
const FLIGHT_SAMPLE_TIME = 1 / 64
/** ... and at most this distance (units r) of travel; only a lip graze shorter than this can be missed */
const FLIGHT_SAMPLE_DISTANCE = 0.02
/** a landing closer to the flight's start than this (time units) is the start itself (the first crossing) */
const FLIGHT_MIN_TIME = 1e-9
/**
 * Shortest hop resolved (time units √(r/g); 1e-3 ≈ 47 µs for a golf ball): a flight whose gap to the lip is
 * not open at this time after take-off is treated as no flight (held roll, see HELD_EVENTS). Small enough to
 * leave every ordinary lift-off and bounce alone (their gap ≈ −N t² or c t³ is far above rounding here), large
 * enough that chattering hops cannot pile up without end.
 */
const HOLD_PROBE_TIME = 1e-3
/** a held ball is released into flight when its free path is open at this time (see freePathClearance) */
const HOLD_RELEASE_TIME = 2 * HOLD_PROBE_TIME
/** Brent tolerance on flight event times (time units): machine level for O(1) flight times */
const FLIGHT_ROOT_TOL = 1e-14
/** lip and flight phases before the run is stopped (a chain of impacts shortening without end) */
export const MAX_PHASES = 400
/** time (units √(r/g)) before the run is stopped (a steady roll round the lip that never decides) */
export const MAX_TIME = 2000

/** Non-dimensional parameters of a run: hole radius in ball radii and the inertia factor. */
interface Params {
  rs: number
  j: number
}

const P: Params = { rs: 2, j: 0.4 }

/** Lip ODEs of the spec in units r = g = 1; y = [ψ, θ, ψ̇, θ̇, ω_n]. */
const lipRhs: OdeRhs = (_t, y, dy) => {
  const th = y[1]!
  const pd = y[2]!
  const td = y[3]!
  const wn = y[4]!
  const s = Math.sin(th)
  const c = Math.cos(th)
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
function normalForce(y: Float64Array, rs: number): number {
  const th = y[1]!
  const pd = y[2]!
  const td = y[3]!
  const s = Math.sin(th)
  return Math.cos(th) - td * td - (rs + s) * pd * pd * s
}

/** E/m on the lip in units g·r. */
function lipEnergyScaled(y: Float64Array, rs: number, j: number): number {
  const th = y[1]!
  const pd = y[2]!
  const td = y[3]!
  const wn = y[4]!
  const rho = rs + Math.sin(th)
  return 0.5 * (1 + j) * (rho * rho * pd * pd + td * td) + 0.5 * j * wn * wn + Math.cos(th)
}

const EVENT_ROLLED_OUT = 0
const EVENT_DROPPED = 1
/** lip events (the ball presses on the lip): roll out, drop in, lift off */
const LIP_EVENTS: readonly OdeEvent[] = [
  { g: (_t, y) => y[1]!, direction: 1 }, // θ rises through 0: centre back over the surface
  { g: (_t, y) => y[1]! + Math.PI / 2, direction: -1 }, // θ falls through −π/2: centre at lip level inside
  { g: (_t, y) => normalForce(y, P.rs), direction: -1 }, // N falls through 0: the lip lets go
]
const EVENT_CLEAR = 2
/**
 * Held-roll events. At N = 0 the no-slip friction force is generally not zero, and dropping it can bend the
 * free path INTO the lip (gap ∝ −t³): then neither rolling (N < 0) nor flight (it penetrates) is consistent,
 * the no-slip idealisation's breakdown (a real ball slides there). The model keeps such a ball rolling on the
 * lip ("held") until the free path from its current state would be clear of the lip at HOLD_RELEASE_TIME, or
 * until it presses on the lip again (N rises through 0). A hop shorter than HOLD_PROBE_TIME is thereby merged
 * into the roll; it is rare (about 3 lift-offs in 5000 over the golf (δ, v) plane).
 */
const HELD_EVENTS: readonly OdeEvent[] = [
  LIP_EVENTS[0]!,
  LIP_EVENTS[1]!,
  { g: (_t, y) => freePathClearance(y, P.rs), direction: 1 }, // the free path would now clear the lip
  { g: (_t, y) => normalForce(y, P.rs), direction: 1 }, // pressing on the lip again: roll normally
]

const LIP_OPTIONS = { rtol: LIP_RTOL, atol: LIP_ATOL, hMax: LIP_MAX_STEP, maxSteps: LIP_MAX_STEPS } as const

const ws = createDopri5Workspace(5, HELD_EVENTS.length)
const lip = new Float64Array(5)
// flight state: centre, velocity, spin (scaled)
const G = new Float64Array(3)
const V = new Float64Array(3)
const W = new Float64Array(3)

/** Writes the centre, velocity and spin of the ball rolling on the lip in state y into G, V, W. */
function lipToCartesian(y: Float64Array, rs: number): void {
  const psi = y[0]!
  const th = y[1]!
  const pd = y[2]!
  const td = y[3]!
  const wn = y[4]!
  const cp = Math.cos(psi)
  const sp = Math.sin(psi)
  const st = Math.sin(th)
  const ct = Math.cos(th)
  const rho = rs + st
  // n = sinθ e_ρ + cosθ e_z, t_θ = cosθ e_ρ − sinθ e_z, e_ρ = (cp, sp, 0), e_ψ = (−sp, cp, 0)
  const nx = st * cp
  const ny = st * sp
  const nz = ct
  G[0] = rho * cp
  G[1] = rho * sp
  G[2] = ct
  // V = ρ ψ̇ e_ψ + r θ̇ t_θ
  V[0] = -rho * pd * sp + td * ct * cp
  V[1] = rho * pd * cp + td * ct * sp
  V[2] = -td * st
  // ω = ω_n n + n × V / r
  W[0] = wn * nx + (ny * V[2]! - nz * V[1]!)
  W[1] = wn * ny + (nz * V[0]! - nx * V[2]!)
  W[2] = wn * nz + (nx * V[1]! - ny * V[0]!)
}

/**
 * Plastic no-slip impact at the lip point nearest to the centre G (|G − P| = r): keeps the angular momentum
 * about P, L = (G − P) × V + j r² ω; ω⁺ = (L·n) n / (j r²) + (L − (L·n) n) / ((1+j) r²), V⁺ = ω⁺ × (G − P).
 * Writes the lip state into y.
 */
function impact(y: Float64Array, rs: number, j: number): void {
  const gx = G[0]!
  const gy = G[1]!
  const gz = G[2]!
  const rhoG = Math.hypot(gx, gy)
  const psi = Math.atan2(gy, gx)
  const cp = gx / rhoG
  const sp = gy / rhoG
  // n = (G − P)/|G − P|, with P = R e_ρ (|G − P| = r up to the rounding of the contact search)
  const ex = gx - rs * cp
  const ey = gy - rs * sp
  const en = Math.sqrt(ex * ex + ey * ey + gz * gz)
  const nx = ex / en
  const ny = ey / en
  const nz = gz / en
  const vx = V[0]!
  const vy = V[1]!
  const vz = V[2]!
  // L/(m r²) = n × V + j ω (units r = 1)
  const lx = ny * vz - nz * vy + j * W[0]!
  const ly = nz * vx - nx * vz + j * W[1]!
  const lz = nx * vy - ny * vx + j * W[2]!
  const ln = lx * nx + ly * ny + lz * nz
  const wx = (ln * nx) / j + (lx - ln * nx) / (1 + j)
  const wy = (ln * ny) / j + (ly - ln * ny) / (1 + j)
  const wz = (ln * nz) / j + (lz - ln * nz) / (1 + j)
  const ux = wy * nz - wz * ny
  const uy = wz * nx - wx * nz
  const uz = wx * ny - wy * nx
  // tilt from n = sinθ e_ρ + cosθ e_z; θ̇ and ψ̇ from V⁺ = ρψ̇ e_ψ + r θ̇ t_θ
  const sinTh = nx * cp + ny * sp
  const th = Math.atan2(sinTh, nz)
  const st = Math.sin(th)
  const ct = Math.cos(th)
  const rho = rs + st
  y[0] = psi
  y[1] = th
  y[2] = (-ux * sp + uy * cp) / rho
  y[3] = (ux * cp + uy * sp) * ct - uz * st
  y[4] = ln / j
  W[0] = wx
  W[1] = wy
  W[2] = wz
  V[0] = ux
  V[1] = uy
  V[2] = uz
}

type FlightEnd = 'impact' | 'landed' | 'droppedInFlight' | 'noClearance'

/**
 * Gap function of a flight: D(G(t)) − D(G(0)), where D(G) = (ρ_G − R)² + z_G² is the squared distance from
 * the centre to the lip circle (scaled), G(t) = G + V t − ½ t² ẑ. A flight starts on the contact surface
 * D = r² (take-off or the first crossing), so the lip is touched again where this falls back to 0. Written as
 * differences from the start, with no "− r²" cancellation: near take-off it grows like −N t² (or like t³ at
 * N = 0) and must be resolved far below 1e-16 to tell a real lift-off from an immediate re-contact.
 */
function lipGap(t: number, rs: number): number {
  const x0 = G[0]!
  const y0 = G[1]!
  const vx = V[0]!
  const vy = V[1]!
  const rho0 = Math.sqrt(x0 * x0 + y0 * y0) // not Math.hypot: this is the hot path, and no overflow can occur
  const x = x0 + vx * t
  const y = y0 + vy * t
  const rho = Math.sqrt(x * x + y * y)
  // ρ² − ρ0² exactly as a polynomial in t, then Δρ = (ρ² − ρ0²)/(ρ + ρ0)
  const dRho = ((2 * (x0 * vx + y0 * vy) + (vx * vx + vy * vy) * t) * t) / (rho + rho0)
  const u0 = rho0 - rs
  const z0 = G[2]!
  const dz = (V[2]! - 0.5 * t) * t
  return dRho * (2 * u0 + dRho) + dz * (2 * z0 + dz)
}

/**
 * Gap (scaled, per HOLD_RELEASE_TIME²) of the free path from lip state y at HOLD_RELEASE_TIME; overwrites
 * G, V, W. Probing at twice the shortest resolved hop makes a released ball's flight pass `fly`'s test (its
 * halving points always include one in [HOLD_PROBE_TIME, HOLD_RELEASE_TIME], where the gap is then open).
 */
function freePathClearance(y: Float64Array, rs: number): number {
  lipToCartesian(y, rs)
  return lipGap(HOLD_RELEASE_TIME, rs) / (HOLD_RELEASE_TIME * HOLD_RELEASE_TIME)
}

/** Horizontal distance of the flying centre from the hole axis at time t (scaled). */
function axisDistance(t: number): number {
  const x = G[0]! + V[0]! * t
  const y = G[1]! + V[1]! * t
  return Math.sqrt(x * x + y * y)
}

/** Squared distance D = (ρ_G − R)² + z_G² from the flight's start to the lip circle (scaled; r² up to rounding). */
function flightD0(rs: number): number {
  const u = Math.sqrt(G[0]! * G[0]! + G[1]! * G[1]!) - rs
  return u * u + G[2]! * G[2]!
}

/**
 * Flight from (G, V) with constant spin: finds the first of lip contact (approaching), landing outside the
 * hole (centre descends to z = r with ρ ≥ R) and the centre descending below z = 0 inside the hole. Moves
 * G and V to that instant and returns which it was and its time.
 */
function fly(rs: number): { end: FlightEnd; dt: number } {
  const z0 = G[2]!
  const vz = V[2]!
  // descending root of z(t) = 0 (z0 ≥ 0 so it exists): the latest the flight can end
  const tFall = vz + Math.sqrt(vz * vz + 2 * Math.max(z0, 0))
  // descending root of z(t) = 1 (landing height), when the ball reaches it
  const discLand = vz * vz + 2 * (z0 - 1)
  let tStop = tFall
  let stopEnd: FlightEnd = 'droppedInFlight'
  if (discLand >= 0) {
    const tLand = vz + Math.sqrt(discLand)
    if (tLand > FLIGHT_MIN_TIME && axisDistance(tLand) >= rs) {
      tStop = tLand
      stopEnd = 'landed'
    }
  }
  // Conservative advancement: the distance to the lip circle changes no faster than the speed, so a step of
  // (distance − r)/vMax cannot cross the contact surface unseen. Near take-off, where the gap opens only like
  // t² or t³, steps are floored at FLIGHT_SAMPLE_DISTANCE of travel (a graze shorter than that is missed).
  const vMax = Math.sqrt(V[0]! * V[0]! + V[1]! * V[1]! + V[2]! * V[2]!) + tStop // speed bound (g = 1)
  const dtFloor = Math.min(FLIGHT_SAMPLE_TIME, FLIGHT_SAMPLE_DISTANCE / vMax)
  const d0 = Math.sqrt(flightD0(rs)) // distance to the lip circle at take-off (r = 1 up to rounding)
  let ta = 0
  let fa = Number.POSITIVE_INFINITY // the take-off point is on the surface (gap 0) and leaving it
  let tEvent = tStop
  let end: FlightEnd = stopEnd
  while (ta < tStop) {
    const clearance = Number.isFinite(fa) ? fa / (Math.sqrt(d0 * d0 + fa) + d0) : 0 // distance − d0
    const tb = Math.min(tStop, ta + Math.max(dtFloor, clearance / vMax))
    const fb = lipGap(tb, rs)
    if (fb <= 0) {
      let tClosed = tb
      let fClosed = fb
      if (!Number.isFinite(fa)) {
        // The first sample already touches again. Near take-off the gap grows only like t² (N < 0) or t³
        // (N = 0), so halve towards the take-off point, down to HOLD_PROBE_TIME, until the gap is open:
        // the crossing lies between that point and the previous (closed) one.
        for (let tt = 0.5 * tb; tt >= HOLD_PROBE_TIME && !Number.isFinite(fa); tt *= 0.5) {
          const ft = lipGap(tt, rs)
          if (ft > 0) {
            ta = tt
            fa = ft
          } else {
            tClosed = tt
            fClosed = ft
          }
        }
        if (!Number.isFinite(fa) && tb > HOLD_PROBE_TIME) {
          const ft = lipGap(HOLD_PROBE_TIME, rs)
          if (ft > 0) {
            ta = HOLD_PROBE_TIME
            fa = ft
          }
        }
        if (!Number.isFinite(fa)) return { end: 'noClearance', dt: 0 } // G and V untouched
      }
      tEvent = brentRoot((t) => lipGap(t, rs), ta, tClosed, fa, fClosed, FLIGHT_ROOT_TOL, -1)
      end = 'impact'
      break
    }
    ta = tb
    fa = fb
  }
  G[0] = G[0]! + V[0]! * tEvent
  G[1] = G[1]! + V[1]! * tEvent
  G[2] = G[2]! + V[2]! * tEvent - 0.5 * tEvent * tEvent
  V[2] = V[2]! - tEvent
  if (end === 'droppedInFlight' && Math.hypot(G[0]!, G[1]!) >= rs) end = 'landed' // cannot happen (see docs)
  return { end, dt: tEvent }
}

function checkFinite(name: string, value: number): void {
  if (typeof value !== 'number' || !Number.isFinite(value)) throw new RangeError(`${name} must be a finite number`)
}

/** Throws a RangeError naming the first field out of range. */
export function validateReferenceInput(input: ReferenceInput): void {
  const { delta, speed, holeRadius, ballRadius, gravity, inertia } = input
  checkFinite('holeRadius', holeRadius)
  if (!(holeRadius > 0)) throw new RangeError('holeRadius must be in (0, ∞)')
  checkFinite('ballRadius', ballRadius)
  if (!(ballRadius > 0 && ballRadius < holeRadius)) throw new RangeError('ballRadius must be in (0, holeRadius)')
  checkFinite('delta', delta)
  if (!(Math.abs(delta) < holeRadius)) throw new RangeError('delta must be in (−holeRadius, holeRadius)')
  checkFinite('speed', speed)
  if (!(speed > 0)) throw new RangeError('speed must be in (0, ∞)')
  checkFinite('gravity', gravity)
  if (!(gravity > 0)) throw new RangeError('gravity must be in (0, ∞)')
  checkFinite('inertia', inertia)
  // a spherically symmetric mass inside radius r has 0 < j ≤ 2/3 (the thin shell is the extreme)
  if (!(inertia > 0 && inertia <= 2 / 3)) throw new RangeError('inertia must be in (0, 2/3]')
}

/**
 * Runs the model in scaled units (r = g = 1): rs = R/r, ds = δ/r, vs = v/√(g r). `trace` (optional) receives
 * the phases in scaled units; the caller converts.
 */
function simulateScaled(rs: number, ds: number, vs: number, j: number, trace: PhaseRecord[] | null): ReferenceOutcome {
  P.rs = rs
  P.j = j
  const k = Math.sqrt(1 - (ds * ds) / (rs * rs))
  let t = 0
  let phases = 0
  let impacts = 0
  let turn = 0
  let mode: 'lip' | 'held' | 'flight'
  const y = lip
  // lip state at the crossing (also the state a held roll starts from if the flight below cannot clear)
  y[0] = Math.atan2(ds, -rs * k)
  y[1] = 0
  y[2] = (-vs * ds) / (rs * rs)
  y[3] = -vs * k
  y[4] = 0
  if (vs * vs * k * k > 1) {
    // too fast for the lip to hold it (N < 0 at θ = 0): flight from the crossing, rolling spin ω = ẑ × V / r
    G[0] = -rs * k
    G[1] = ds
    G[2] = 1
    V[0] = vs
    V[1] = 0
    V[2] = 0
    W[0] = 0
    W[1] = vs
    W[2] = 0
    mode = 'flight'
  } else {
    mode = 'lip'
  }
  const result = (ending: ReferenceEnding, captured: boolean, exit?: { vx: number; vy: number }): ReferenceOutcome => {
    const out: ReferenceOutcome = { captured, turnAngle: Math.abs(turn), ending, impacts, phases, duration: t }
    if (exit !== undefined) {
      out.exitSpeed = Math.hypot(exit.vx, exit.vy)
      out.exitAngle = Math.atan2(exit.vy, exit.vx)
      out.exitX = G[0]!
      out.exitY = G[1]!
    }
    return out
  }

  while (true) {
    if (phases >= MAX_PHASES) return result('phaseLimit', false)
    phases++
    if (mode === 'lip' || mode === 'held') {
      const held = mode === 'held'
      const psi0 = y[0]!
      const th0 = y[1]!
      const e0 = trace ? lipEnergyScaled(y, rs, j) : 0
      const t0 = t
      const res = dopri5(ws, lipRhs, t, y, MAX_TIME, LIP_OPTIONS, held ? HELD_EVENTS : LIP_EVENTS)
      t = res.t
      turn += y[0]! - psi0
      let end: PhaseEnd
      if (res.status === 'event') {
        if (res.event === EVENT_ROLLED_OUT) end = 'rolledOut'
        else if (res.event === EVENT_DROPPED) end = 'droppedFromLip'
        else if (!held) end = 'liftOff'
        else end = res.event === EVENT_CLEAR ? 'clear' : 'pressing'
      } else {
        end = res.status === 'reachedEnd' ? 'timeLimit' : 'integratorLimit'
      }
      if (trace) {
        const rec: PhaseRecord = {
          kind: 'lip',
          tStart: t0,
          tEnd: t,
          end,
          psiStart: psi0,
          psiEnd: y[0]!,
          thetaStart: th0,
          thetaEnd: y[1]!,
          energyStart: e0,
          energyEnd: lipEnergyScaled(y, rs, j),
          steps: res.accepted + res.rejected,
        }
        if (held) rec.held = true
        trace.push(rec)
      }
      if (end === 'rolledOut') {
        lipToCartesian(y, rs)
        return result('rolledOut', false, { vx: V[0]!, vy: V[1]! })
      }
      if (end === 'droppedFromLip') return result('droppedFromLip', true)
      if (end === 'timeLimit' || end === 'integratorLimit') return result(end, false)
      if (end === 'pressing') {
        mode = 'lip'
      } else {
        lipToCartesian(y, rs)
        mode = 'flight'
      }
    } else {
      const t0 = t
      const { end, dt } = fly(rs)
      t += dt
      if (trace) trace.push({ kind: 'flight', tStart: t0, tEnd: t, end })
      if (end === 'landed') return result('hoppedOut', false, { vx: V[0]!, vy: V[1]! })
      if (end === 'droppedInFlight') return result('droppedInFlight', true)
      if (end === 'noClearance') {
        // N ≤ 0 but the free path runs into the lip at once (see HELD_EVENTS): the lip keeps the ball
        // (y still holds the lip state the flight started from)
        mode = 'held'
        continue
      }
      if (t >= MAX_TIME) return result('timeLimit', false)
      impacts++
      impact(y, rs, j)
      // the lip holds the ball only if it presses on it; otherwise it flies off again at once
      mode = normalForce(y, rs) >= 0 ? 'lip' : 'flight'
    }
  }
}

function scaleOutcome(out: ReferenceOutcome, speedScale: number, timeScale: number, lengthScale: number): ReferenceOutcome {
  out.duration *= timeScale
  if (out.exitSpeed !== undefined) out.exitSpeed *= speedScale
  if (out.exitX !== undefined) out.exitX *= lengthScale
  if (out.exitY !== undefined) out.exitY *= lengthScale
  return out
}

/** Outcome of one ball (see ReferenceOutcome). Deterministic: the same input gives the same output. */
export function referenceOutcome(input: ReferenceInput): ReferenceOutcome {
  validateReferenceInput(input)
  const { delta, speed, holeRadius: R, ballRadius: r, gravity: g, inertia: j } = input
  const vScale = Math.sqrt(g * r)
  const out = simulateScaled(R / r, delta / r, speed / vScale, j, null)
  return scaleOutcome(out, vScale, Math.sqrt(r / g), r)
}

/** Outcome plus the phase sequence (times, tilts, contact angles, energies), in the input's units. */
export function referenceTrace(input: ReferenceInput): ReferenceTrace {
  validateReferenceInput(input)
  const { delta, speed, holeRadius: R, ballRadius: r, gravity: g, inertia: j } = input
  const vScale = Math.sqrt(g * r)
  const timeScale = Math.sqrt(r / g)
  const phases: PhaseRecord[] = []
  const outcome = scaleOutcome(simulateScaled(R / r, delta / r, speed / vScale, j, phases), vScale, timeScale, r)
  const eScale = g * r
  for (const p of phases) {
    p.tStart *= timeScale
    p.tEnd *= timeScale
    if (p.energyStart !== undefined) p.energyStart *= eScale
    if (p.energyEnd !== undefined) p.energyEnd *= eScale
  }
  return { outcome, phases }
}

/** Lip state in the input's units: contact angle ψ, tilt θ (θ < 0: centre over the hole), their rates, ω_n. */
export interface LipState {
  psi: number
  theta: number
  psiDot: number
  thetaDot: number
  omegaN: number
}

/** E/m of a ball rolling on the lip: ½(1+j)(ρ²ψ̇² + r²θ̇²) + ½ j r² ω_n² + g r cosθ, ρ = R + r sinθ. */
export function lipEnergy(s: LipState, holeRadius: number, ballRadius: number, gravity: number, inertia: number): number {
  const rho = holeRadius + ballRadius * Math.sin(s.theta)
  const r = ballRadius
  return (
    0.5 * (1 + inertia) * (rho * rho * s.psiDot * s.psiDot + r * r * s.thetaDot * s.thetaDot) +
    0.5 * inertia * r * r * s.omegaN * s.omegaN +
    gravity * r * Math.cos(s.theta)
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
  validateReferenceInput({ delta: 0, speed: 1, holeRadius, ballRadius, gravity, inertia })
  if (!(duration >= 0 && Number.isFinite(duration))) throw new RangeError('duration must be in [0, ∞)')
  const T = Math.sqrt(ballRadius / gravity)
  P.rs = holeRadius / ballRadius
  P.j = inertia
  const y = lip
  y[0] = start.psi
  y[1] = start.theta
  y[2] = start.psiDot * T
  y[3] = start.thetaDot * T
  y[4] = start.omegaN * T
  const res = dopri5(ws, lipRhs, 0, y, duration / T, {
    rtol: LIP_RTOL,
    atol: LIP_ATOL,
    hMax: LIP_MAX_STEP,
    maxSteps: LIP_MAX_STEPS,
  })
  if (res.status !== 'reachedEnd') throw new Error(`rollOnLip: integrator stopped (${res.status})`)
  return {
    state: { psi: y[0]!, theta: y[1]!, psiDot: y[2]! / T, thetaDot: y[3]! / T, omegaN: y[4]! / T },
    steps: res.accepted + res.rejected,
  }
}

// ---- searches ----
/** speed grid points scanned before bisecting the capture boundary (finds the largest captured cell) */
const CAPTURE_SPEED_GRID = 160
/** offset grid points scanned before bisecting the effective hole edge */
const CAPTURE_OFFSET_GRID = 160
/** bisection steps after the scan: 2⁻⁴⁰ of a grid cell is far below any physical meaning */
const BISECTION_STEPS = 40
/** the speed scan runs up to this multiple of the free-fall skip speed 2R·√(g/2r): well past any capture */
const SPEED_SCAN_TOP = 4

function capturedScaled(rs: number, ds: number, vs: number, j: number): boolean {
  return simulateScaled(rs, ds, vs, j, null).captured
}

/**
 * Capture speed v_c(δ): the largest speed that is captured at offset δ. Scans a speed grid up to
 * SPEED_SCAN_TOP times the free-fall skip speed, takes the highest captured grid point and bisects between
 * it and the next one (so a captured window narrower than a grid cell above it can be missed).
 */
export function referenceCaptureSpeed(
  delta: number,
  holeRadius: number,
  ballRadius: number,
  gravity: number,
  inertia: number,
): number {
  validateReferenceInput({ delta, speed: 1, holeRadius, ballRadius, gravity, inertia })
  const rs = holeRadius / ballRadius
  const ds = delta / ballRadius
  const vTop = SPEED_SCAN_TOP * 2 * rs * Math.sqrt(0.5)
  let lo = 0
  for (let i = CAPTURE_SPEED_GRID; i >= 1; i--) {
    const v = (vTop * i) / CAPTURE_SPEED_GRID
    if (capturedScaled(rs, ds, v, inertia)) {
      lo = v
      break
    }
  }
  if (lo === vTop) return Number.POSITIVE_INFINITY // captured at the top of the scan: no finite limit found
  let hi = lo + vTop / CAPTURE_SPEED_GRID
  if (lo === 0) lo = hi * 1e-6 // nothing captured on the grid: bisect the first cell
  for (let i = 0; i < BISECTION_STEPS; i++) {
    const mid = 0.5 * (lo + hi)
    if (capturedScaled(rs, ds, mid, inertia)) lo = mid
    else hi = mid
  }
  return lo * Math.sqrt(gravity * ballRadius)
}

/**
 * Effective hole at a speed: the largest offset δ captured at `speed` (scan of [0, R) and bisection, as
 * for the capture speed). Undefined when no offset on the grid is captured.
 */
export function referenceCaptureOffset(
  speed: number,
  holeRadius: number,
  ballRadius: number,
  gravity: number,
  inertia: number,
): number | undefined {
  validateReferenceInput({ delta: 0, speed, holeRadius, ballRadius, gravity, inertia })
  const rs = holeRadius / ballRadius
  const vs = speed / Math.sqrt(gravity * ballRadius)
  const cell = rs / CAPTURE_OFFSET_GRID
  let lo = -1
  for (let i = CAPTURE_OFFSET_GRID - 1; i >= 0; i--) {
    if (capturedScaled(rs, cell * i, vs, inertia)) {
      lo = cell * i
      break
    }
  }
  if (lo < 0) return undefined
  let hi = lo + cell
  for (let i = 0; i < BISECTION_STEPS; i++) {
    const mid = 0.5 * (lo + hi)
    if (mid >= rs) break
    if (capturedScaled(rs, mid, vs, inertia)) lo = mid
    else hi = mid
  }
  return lo * ballRadius
}

/** time grid for the first contact in the single-impact estimate (units √(r/g)) */
const SINGLE_IMPACT_TIME_STEP = 1 / 256

/**
 * The spec's δ = 0 single-impact estimate (units r = g = 1, ρ = R/r): a ball leaving the near lip at speed v
 * flies to the far lip; at first contact (2ρ − v t)² + (1 − t²/2)² = 1, with β = atan2(−(2ρ − v t), 1 − t²/2)
 * and L = v (cosβ + j) + t sinβ it escapes iff L > 0 and L²/(2(1+j)) ≥ 1 − cosβ. A ball whose centre falls
 * below lip level before touching counts as captured. Returns true for an escape.
 */
export function singleImpactEscapes(vs: number, rs: number, j: number): boolean {
  const h = (t: number): number => {
    const a = 2 * rs - vs * t
    const b = 1 - 0.5 * t * t
    return a * a + b * b - 1
  }
  const tFall = Math.SQRT2 // centre at lip level
  let ta = 0
  let fa = h(0)
  for (let tb = SINGLE_IMPACT_TIME_STEP; ta < tFall; tb += SINGLE_IMPACT_TIME_STEP) {
    const fb = h(tb)
    if (fb <= 0) {
      const t = brentRoot(h, ta, tb, fa, fb, FLIGHT_ROOT_TOL, -1)
      if (t >= tFall) return false
      const beta = Math.atan2(-(2 * rs - vs * t), 1 - 0.5 * t * t)
      const L = vs * (Math.cos(beta) + j) + t * Math.sin(beta)
      return L > 0 && (L * L) / (2 * (1 + j)) >= 1 - Math.cos(beta)
    }
    ta = tb
    fa = fb
  }
  return false
}

/**
 * Dead-centre capture limit from the single-impact estimate (largest captured speed), in the input's units.
 * Scans and bisects like referenceCaptureSpeed. Meaningful when the result exceeds √(g r) (the ball then
 * leaves the near lip at once, as the estimate assumes).
 */
export function singleImpactDeadCentreLimit(holeRadius: number, ballRadius: number, gravity: number, inertia: number): number {
  validateReferenceInput({ delta: 0, speed: 1, holeRadius, ballRadius, gravity, inertia })
  const rs = holeRadius / ballRadius
  const vTop = SPEED_SCAN_TOP * 2 * rs * Math.sqrt(0.5)
  let lo = 0
  for (let i = CAPTURE_SPEED_GRID; i >= 1; i--) {
    const v = (vTop * i) / CAPTURE_SPEED_GRID
    if (!singleImpactEscapes(v, rs, inertia)) {
      lo = v
      break
    }
  }
  let hi = lo + vTop / CAPTURE_SPEED_GRID
  for (let i = 0; i < BISECTION_STEPS; i++) {
    const mid = 0.5 * (lo + hi)
    if (!singleImpactEscapes(mid, rs, inertia)) lo = mid
    else hi = mid
  }
  return lo * Math.sqrt(gravity * ballRadius)
}
