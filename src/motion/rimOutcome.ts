// A lip crossing decided by the rigid-sphere reference (decideByReference: from the world's table, or by a
// live run) and what the ball does then: the outcome in rimOut (src/reference/rimTable.ts), applied with no
// jump. Shared by the tabulated rim model and the hero ball (systems/tabulatedRim.ts, systems/heroReference.ts).
//   dropped in clean (turned less than ROLL_TURN): 'capture' (via 'clean') at the crossing
//   rolled round the lip, captured or not: it rides the lip (mode rimRoll, a tabulated ride:
//     src/motion/rimRoll.ts) for the reference's time, turning the reference's angle, from the crossing to
//     the exit point (then 'lipOut' and 'nearMiss', leaving with the exit velocity) or to the contact circle
//     (then 'capture' via 'rimRoll'); 'rimRoll' at the crossing
//   bounced or skipped: it is carried straight across from the crossing to the exit point (a rolling path,
//     RimMode.Crossing, arriving after the reference's time; PathEvent.Landing ends it), then leaves with the
//     exit velocity; 'bounce' + 'nearMiss' or 'skip' at the crossing. A wall or a strike on the way ends it.
import { BallMode } from '../../components/Ball.js'
import { PathEvent } from '../../components/Path.js'
import { RIDE_DROPS, RIDE_LEAVES, RimMode } from '../../components/RimContact.js'
import { CaptureVia, EventType } from '../events.js'
import { cogRadius } from '../geometry.js'
import { RimKind, ROLL_TURN, TABLE_TOP_SPEED, captureSpeedAt, outcomeAt, referenceToOut, rimOut, type RimTable } from '../reference/rimTable.js'
import { simulateScaled } from '../reference/sphereLip.js'
import { LIVE_STEP_BUDGET } from '../reference/tolerances.js'
import { MIN_TABLE_RATIO } from '../config/limits.js'
import { lockAtLip } from '../world/rimSlots.js'
import { setBallMode } from '../world/ballMode.js'
import type { BallWorld } from '../world/createWorld.js'
import { captureBall, emitHoleEvent } from './ballFate.js'
import { leaveRim, planRimRoll, sampleRimRoll } from './rimRoll.js'
import { startAt, pathOffset, planRolling, startPath } from './rolling.js'
import { atan2, cos, hypot, sin } from '../math.js'
import { HOT, H_NEXT_T, H_UX, H_UY, H_V0 } from '../world/pathHot.js'

/** The world's table for this geometry, or null (then the live reference decides). */
function tableFor(w: BallWorld, ratio: number, inertia: number): RimTable | null {
  const tables = w.rimTables
  for (let i = 0; i < tables.length; i++) {
    const t = tables[i]!
    if (t.ratio === ratio && t.inertia === inertia) return t
  }
  return null
}

/**
 * Decides ball eid's lip crossing (marked Lip this pass) by the rigid-sphere reference and applies it:
 * from the world's table for the crossing's geometry when `tabulated` and one is there (and the speed is
 * within it), else by a live run. A ball not smaller than the hole, or a run a guard stopped, is left
 * marked for the six stages.
 */
export function decideByReference(w: BallWorld, eid: number, tabulated: boolean): void {
  const hole = w.Path.markHole[eid]!
  const R = w.Hole.radius[hole]!
  const r = w.Ball.radius[eid]!
  const cross = pathOffset(w, eid, hole)
  const delta = Math.abs(cross)
  const v = w.Path.speed[eid]!
  if (!(r < R) || !(delta < R) || !(v > 0)) return
  const j = w.config.BALL_INERTIA
  const ds = delta / r
  const vs = v / Math.sqrt(w.config.GRAVITY * r)
  // a ball within MIN_TABLE_RATIO of the hole's size, in a tabulated world: left to the stages (no table is
  // built for it, and the live reference's rolls round the lip run to its time limit there)
  if (tabulated && !(R >= MIN_TABLE_RATIO * r)) return
  const table = tabulated && vs <= TABLE_TOP_SPEED ? tableFor(w, R / r, j) : null
  // beyond the table's speeds (a fast ball, rare), a geometry with no table, or a hero ball: a live run
  if (table === null) referenceToOut(simulateScaled(R / r, ds, vs, j, null, LIVE_STEP_BUDGET), R / r, ds)
  else outcomeAt(table, ds, vs, vs <= captureSpeedAt(table, ds))
  if (rimOut.kind === RimKind.Guarded) return
  applyRimOutcome(w, eid, hole, cross)
}

/**
 * Applies the outcome in rimOut (not RimKind.Guarded) to ball eid at its lip crossing of `hole` (marked Lip
 * this pass): `cross` is the path's signed offset from the hole centre (pathOffset).
 */
function applyRimOutcome(w: BallWorld, eid: number, hole: number, cross: number): void {
  const delta = Math.abs(cross)
  const v = w.Path.speed[eid]!
  const P = w.Path
  const H = w.Hole
  const B = w.Ball
  const o = rimOut
  const R = H.radius[hole]!
  const r = B.radius[eid]!
  const ux = w.pathHot[eid * HOT + H_UX]!
  const uy = w.pathHot[eid * HOT + H_UY]!
  const vScale = Math.sqrt(w.config.GRAVITY * r)
  const t = w.pathHot[eid * HOT + H_NEXT_T]!
  const slot = lockAtLip(w, eid, hole, delta, v, t, RimMode.Transit)
  P.mark[eid] = PathEvent.None
  // a roll round the lip: an escape of that kind, or a capture after turning ROLL_TURN or more
  const rolled = o.kind === RimKind.Rolled || (o.kind === RimKind.Captured && o.turn >= ROLL_TURN)
  if (o.kind === RimKind.Captured && !rolled) {
    captureBall(w, eid, hole, t, CaptureVia.Clean)
    return
  }
  // the reference's frame: x along the path, y toward the side the path passes the hole on
  const side = cross >= 0 ? 1 : -1
  const ex = -uy * side
  const ey = ux * side
  const RC = w.RimContact
  const hx = H.x[hole]!
  const hy = H.y[hole]!
  const duration = (o.time * r) / vScale // √(r/g) = r/√(g·r)
  const escapes = o.kind !== RimKind.Captured
  if (escapes) {
    // the exit velocity: its direction in the reference's frame, then in the world's; the reference never
    // leaves faster than it came (no energy is put in), the interpolation could by a hair
    // The exit point lies at psi = psi0 − exitTurn about the hole; the crossing point (−√(R² − δ²), δ) gives
    // cos and sin of psi0 without a trigonometric call. The exit direction is exitRelative's angle from the
    // tangent at psi, which points at psi − π/2: (cos, sin) of it are (exitCos·sin psi + exitSin·cos psi,
    // exitSin·sin psi − exitCos·cos psi).
    const c0 = -Math.sqrt(R * R - delta * delta) / R
    const s0 = delta / R
    const cT = cos(o.exitTurn)
    const sT = sin(o.exitTurn)
    const cPsi = c0 * cT + s0 * sT
    const sPsi = s0 * cT - c0 * sT
    const ca = o.exitCos * sPsi + o.exitSin * cPsi
    const sa = o.exitSin * sPsi - o.exitCos * cPsi
    const vOut = Math.min(o.exitSpeed * vScale, v)
    RC.exitVx[slot] = (ca * ux + sa * ex) * vOut
    RC.exitVy[slot] = (ca * uy + sa * ey) * vOut
    if (!rolled) {
      // a bounce or a skip: carried straight from the crossing to the reference's exit point, arriving
      // after the reference's time (a rolling path: its own event ends it), then it leaves at the exit velocity
      const X = o.exitRadius * r * cPsi
      const Y = o.exitRadius * r * sPsi
      const dx = hx + X * ux + Y * ex - B.x[eid]!
      const dy = hy + X * uy + Y * ey - B.y[eid]!
      const L = Math.sqrt(dx * dx + dy * dy)
      if (o.kind === RimKind.Skipped) emitHoleEvent(w, EventType.Skip, eid, hole, t)
      else {
        emitHoleEvent(w, EventType.Bounce, eid, hole, t)
        emitHoleEvent(w, EventType.NearMiss, eid, hole, t)
      }
      if (L > 1e-9 && duration > 0) {
        // v0·T − a·T²/2 = L: there at time T (or sooner, at L, if the deceleration would stop it first)
        const v0 = L / duration + 0.5 * w.config.ROLLING_DECEL * duration
        startAt(B.x[eid]!, B.y[eid]!, (dx / L) * v0, (dy / L) * v0, t)
        startPath(w, eid)
        RC.mode[slot] = RimMode.Crossing
        RC.rideTo[slot] = L
        RC.time0[slot] = t
        RC.speed0[slot] = w.pathHot[eid * HOT + H_V0]!
      } else {
        RC.mode[slot] = RimMode.Transit
        startAt(B.x[eid]!, B.y[eid]!, RC.exitVx[slot]!, RC.exitVy[slot]!, t)
        startPath(w, eid)
      }
      P.fromHole[eid] = hole
      planRolling(w, eid)
      return
    }
  }
  // a roll round the lip: the ball rides it from where it is (its centre on the lip circle), turning the way
  // the path goes round the hole (in the reference's frame the angle falls; the world frame is mirrored
  // when side < 0), to the exit point or the contact circle, for the reference's time. No jump at either end.
  RC.mode[slot] = RimMode.Rolling
  RC.ride[slot] = escapes ? RIDE_LEAVES : RIDE_DROPS
  RC.rideTurn[slot] = escapes ? o.exitTurn : o.turn
  RC.rideTime[slot] = duration
  RC.rideFrom[slot] = hypot(B.x[eid]! - hx, B.y[eid]! - hy)
  RC.rideTo[slot] = escapes ? o.exitRadius * r : cogRadius(R, r)
  RC.angle0[slot] = atan2(B.y[eid]! - hy, B.x[eid]! - hx)
  RC.direction[slot] = side > 0 ? -1 : 1
  RC.time0[slot] = t
  RC.speed0[slot] = v
  setBallMode(w, eid, BallMode.RimRoll)
  // the ride is not sampled at its start without ball-ball contacts: nothing reads the ball's state before
  // the next pass's integration samples the ride again (at its end or the step's, or the pause when the
  // passes run out); a sine and a cosine fewer per ride. With contacts the launcher and the predictions may.
  if (w.collide !== null || w.fixed !== null) sampleRimRoll(w, eid, t)
  planRimRoll(w, eid)
  emitHoleEvent(w, EventType.RimRoll, eid, hole, t)
}

/** A tabulated crossing reaches the reference's exit point (its state there sampled): it leaves at the exit velocity. */
export function landCrossing(w: BallWorld, eid: number): void {
  const P = w.Path
  const B = w.Ball
  const RC = w.RimContact
  const slot = B.rim[eid]!
  P.mark[eid] = PathEvent.None
  RC.mode[slot] = RimMode.Transit
  startAt(B.x[eid]!, B.y[eid]!, RC.exitVx[slot]!, RC.exitVy[slot]!, w.pathHot[eid * HOT + H_NEXT_T]!)
  startPath(w, eid)
  P.fromHole[eid] = P.markHole[eid]!
  planRolling(w, eid)
}

/** A tabulated ride's end (its state there already sampled): drop in, or leave with the exit velocity. */
export function endRide(w: BallWorld, eid: number): void {
  const P = w.Path
  const B = w.Ball
  const RC = w.RimContact
  const slot = B.rim[eid]!
  const hole = P.markHole[eid]!
  const t = w.pathHot[eid * HOT + H_NEXT_T]!
  P.mark[eid] = PathEvent.None
  const ride = RC.ride[slot]
  RC.ride[slot] = 0
  if (ride === RIDE_DROPS) {
    captureBall(w, eid, hole, t, CaptureVia.RimRoll)
    return
  }
  leaveRim(w, eid, hole, RC.exitVx[slot]!, RC.exitVy[slot]!, t)
}
