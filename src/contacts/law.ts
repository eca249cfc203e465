// The contact law of two smooth balls, and the rules a contact applies to the balls' state.
import { RimMode } from '../../components/RimContact.js'
import { MAX_SPEED } from '../config/limits.js'
import { capped, capVelocity, overSpeed, pumpedPast } from '../motion/speedLimit.js'
import type { BallWorld } from '../world/createWorld.js'

/** Result of resolveContact: new velocities, the impulse along the normal and the approach speed. */
export const contactOut = { vax: 0, vay: 0, vbx: 0, vby: 0, impulse: 0, approach: 0 }

/**
 * Velocities after a contact of balls a and b (masses ma, mb, centres a→b along (nx, ny), unit), with
 * restitution e: the normal impulse j = (1 + e)·w / (1/ma + 1/mb), w the approach speed, changes a by −j·n/ma
 * and b by +j·n/mb; tangential velocities are kept (smooth balls). Momentum is conserved exactly in exact
 * arithmetic and kinetic energy falls by (1 − e²)·w²/(2(1/ma + 1/mb)) ≥ 0. A contact that would leave a ball
 * with a velocity component beyond MAX_SPEED, or beyond `limit` (CONTACT_SPEED_LIMIT; MAX_SPEED when absent)
 * and faster than that component came in, takes less restitution (capImpulse). (A settling contact instead
 * gives the touching cluster its centre-of-mass velocity: systems/collisions.ts.)
 */
export function resolveContact(
  ma: number,
  mb: number,
  vax: number,
  vay: number,
  vbx: number,
  vby: number,
  nx: number,
  ny: number,
  e: number,
  limit = MAX_SPEED,
): void {
  const I = contactIn
  I[CI_MA] = ma
  I[CI_MB] = mb
  I[CI_VAX] = vax
  I[CI_VAY] = vay
  I[CI_VBX] = vbx
  I[CI_VBY] = vby
  I[CI_NX] = nx
  I[CI_NY] = ny
  I[CI_E] = e
  I[CI_LIMIT] = limit
  resolveContactIn()
}

/**
 * resolveContact's inputs, for callers in the step (slots: nine doubles passed to a call V8 does not inline
 * are nine heap numbers a contact): masses, velocities, normal, restitution, CONTACT_SPEED_LIMIT
 */
export const contactIn = new Float64Array(10)
export const CI_MA = 0
export const CI_MB = 1
export const CI_VAX = 2
export const CI_VAY = 3
export const CI_VBX = 4
export const CI_VBY = 5
export const CI_NX = 6
export const CI_NY = 7
export const CI_E = 8
export const CI_LIMIT = 9

/** resolveContact with its inputs in contactIn. */
export function resolveContactIn(): void {
  const I = contactIn
  const ma = I[CI_MA]!
  const mb = I[CI_MB]!
  const vax = I[CI_VAX]!
  const vay = I[CI_VAY]!
  const vbx = I[CI_VBX]!
  const vby = I[CI_VBY]!
  const nx = I[CI_NX]!
  const ny = I[CI_NY]!
  const e = I[CI_E]!
  const limit = I[CI_LIMIT]!
  const o = contactOut
  const rx = vbx - vax
  const ry = vby - vay
  const approach = -(rx * nx + ry * ny)
  o.approach = approach
  if (!(approach > 0)) {
    o.vax = vax
    o.vay = vay
    o.vbx = vbx
    o.vby = vby
    o.impulse = 0
    return
  }
  let j = ((1 + e) * approach) / (1 / ma + 1 / mb)
  let ax = vax - (j / ma) * nx
  let ay = vay - (j / ma) * ny
  let bx = vbx + (j / mb) * nx
  let by = vby + (j / mb) * ny
  if (overSpeed(ax, ay) || overSpeed(bx, by) || pumpedPast(vax, ax, limit) || pumpedPast(vay, ay, limit) || pumpedPast(vbx, bx, limit) || pumpedPast(vby, by, limit)) {
    // a light ball struck by a heavy one would leave faster than CONTACT_SPEED_LIMIT or MAX_SPEED: less
    // restitution (capImpulse)
    j = capImpulse(vax, vay, vbx, vby, nx, ny, 1 / ma, 1 / mb, approach, e, limit)
    ax = vax - (j / ma) * nx
    ay = vay - (j / ma) * ny
    bx = vbx + (j / mb) * nx
    by = vby + (j / mb) * ny
    capVelocity(ax, ay)
    ax = capped[0]!
    ay = capped[1]!
    capVelocity(bx, by)
    bx = capped[0]!
    by = capped[1]!
  }
  o.impulse = j
  o.vax = ax
  o.vay = ay
  o.vbx = bx
  o.vby = by
}

/**
 * The normal impulse of a contact (unit normal (nx, ny) from a to b, inverse masses ima and imb, approach
 * speed `approach`, restitution e) lowered so that neither ball leaves with a velocity component beyond
 * MAX_SPEED, nor beyond `limit` (CONTACT_SPEED_LIMIT), or, for a component already beyond the limit, beyond
 * its size before: its restitution is the largest in [0, e] that keeps every component so. Momentum is kept, and kinetic energy
 * falls further. Heavy balls drive light ones to any speed (Fermi acceleration: a light ball between a heavy
 * one and a wall gains twice the heavy one's speed each round trip, up to the heavy balls' energy), every
 * px/s of which costs ticks or events, and a state the commands would refuse (ballState read, given back to
 * setBallVelocity) is no state to leave a ball in. When even an inelastic contact leaves a component beyond
 * them (the ball's motion across the normal, or the partner's speed), the inelastic impulse; capVelocity
 * (src/motion/speedLimit.ts) then slows a ball beyond MAX_SPEED.
 */
export function capImpulse(
  vax: number,
  vay: number,
  vbx: number,
  vby: number,
  nx: number,
  ny: number,
  ima: number,
  imb: number,
  approach: number,
  e: number,
  limit = MAX_SPEED,
): number {
  const unit = approach / (ima + imb)
  // each component is c + f·s, f = 1 + restitution; the largest f in [1, 1 + e] that keeps it within
  let f = 1 + e
  f = within(vax, -unit * ima * nx, f, limit)
  f = within(vay, -unit * ima * ny, f, limit)
  f = within(vbx, unit * imb * nx, f, limit)
  f = within(vby, unit * imb * ny, f, limit)
  return f > 1 ? f * unit : unit
}

/**
 * The largest f' ≤ f for which |c + f'·s| ≤ M (f itself when c + f·s is within it), M the larger of `limit`
 * and |c| (a component already beyond the limit may keep its size, not grow), at most MAX_SPEED.
 */
function within(c: number, s: number, f: number, limit: number): number {
  const size = c < 0 ? -c : c
  let M = limit > size ? limit : size
  if (M > MAX_SPEED) M = MAX_SPEED
  const at = c + f * s
  if (!(at > M || at < -M) || s === 0) return f
  const g = ((s > 0 ? M : -M) - c) / s
  return g < f ? g : f
}

/**
 * True when a and b touch again with nothing having happened to either since they last touched each other
 * (partner is set after a contact and cleared by every new path, in startPath). Two balls pressed together by their decelerations would
 * otherwise touch again and again, ever sooner (a Zeno sequence): such a contact is made perfectly
 * inelastic, after which they move as one and cannot touch again.
 */
export function isRepeatContact(w: BallWorld, a: number, b: number): boolean {
  const C = w.collide!
  return C.partner[a] === b && C.partner[b] === a
}

/** The rim mode a struck ball keeps: inside a lip circle it is in transit (its decision there is void). */
export function strikeLeavesRim(w: BallWorld, eid: number): void {
  const c = w.Ball.rim[eid]!
  if (c !== 0) {
    w.RimContact.mode[c] = RimMode.Transit
    w.RimContact.ride[c] = 0
  }
}
