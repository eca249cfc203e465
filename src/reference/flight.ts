// Ballistic flight (phase 3) in scaled units (r = g = 1): the closed-form path with constant spin, the gap to
// the lip along it, and the search for the flight's end (lip contact, landing outside the hole, or dropping
// below lip level inside it); also the free-path clearance that releases a held roll.

import { brentRoot } from './brent.js'
import { lipToCartesian } from './contact.js'
import { G, V } from './state.js'
import {
  FLIGHT_MAX_SAMPLES,
  FLIGHT_MIN_TIME,
  FLIGHT_ROOT_TOL,
  FLIGHT_SAMPLE_DISTANCE,
  FLIGHT_SAMPLE_TIME,
  HOLD_PROBE_TIME,
  HOLD_RELEASE_TIME,
} from './tolerances.js'
import { hypot } from '../math.js'

export type FlightEnd = 'impact' | 'landed' | 'droppedInFlight' | 'noClearance' | 'sampleLimit'

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
export function freePathClearance(y: Float64Array, rs: number): number {
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
export function fly(rs: number): { end: FlightEnd; dt: number } {
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
  for (let samples = 0; ta < tStop; samples++) {
    const clearance = Number.isFinite(fa) ? fa / (Math.sqrt(d0 * d0 + fa) + d0) : 0 // distance − d0
    const tb = Math.min(tStop, ta + Math.max(dtFloor, clearance / vMax))
    // a guard: a step that rounds away (it can at the domain's edges) or a search that runs on; G and V untouched
    if (!(tb > ta) || samples >= FLIGHT_MAX_SAMPLES) return { end: 'sampleLimit', dt: 0 }
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
  if (end === 'droppedInFlight' && hypot(G[0]!, G[1]!) >= rs) end = 'landed' // cannot happen (see docs)
  return { end, dt: tEvent }
}
