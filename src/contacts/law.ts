// The contact law of two smooth balls, and the rules a contact applies to the balls' state.
import { RimMode } from '../../components/RimContact.js'
import type { BallWorld } from '../world/createWorld.js'

/** Result of resolveContact: new velocities, the impulse along the normal and the approach speed. */
export const contactOut = { vax: 0, vay: 0, vbx: 0, vby: 0, impulse: 0, approach: 0 }

/**
 * Velocities after a contact of balls a and b (masses ma, mb, centres a→b along (nx, ny), unit), with
 * restitution e: the normal impulse j = (1 + e)·w / (1/ma + 1/mb), w the approach speed, changes a by −j·n/ma
 * and b by +j·n/mb; tangential velocities are kept (smooth balls). Momentum is conserved exactly in exact
 * arithmetic and kinetic energy falls by (1 − e²)·w²/(2(1/ma + 1/mb)) ≥ 0. (A settling contact instead
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
): void {
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
  const j = ((1 + e) * approach) / (1 / ma + 1 / mb)
  o.impulse = j
  o.vax = vax - (j / ma) * nx
  o.vay = vay - (j / ma) * ny
  o.vbx = vbx + (j / mb) * nx
  o.vby = vby + (j / mb) * ny
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
