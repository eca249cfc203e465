// The reference-tabulated rim model (RIM_MODEL 'tabulated', TABULATED_CONFIG): a lip crossing decided by the
// rigid-sphere reference's table at the crossing's geometry (src/reference/rimTable.ts) instead of the six
// closed-form stages. Runs after the hero ball's system and ahead of skipOver; a crossing it decides is
// unmarked, so the stages never see it.
//   capture  v ≤ v_c(δ), the reference's capture speed per δ row, linear between rows
//   outcome  the table's kind, exit point, direction and speed, time and turn on the lip (interpolated)
// What the ball does then:
//   rolled round the lip (turn ≥ ROLL_TURN), captured or not: it rides the lip (mode rimRoll, a tabulated
//     ride: src/motion/rimRoll.ts) for the reference's time, turning the reference's angle, from the crossing
//     to the exit point (then 'lipOut' and 'nearMiss', leaving with the exit velocity) or to the contact
//     circle (then 'capture' via 'rimRoll'); 'rimRoll' at the crossing
//   dropped in clean: 'capture' (via 'clean') at the crossing
//   bounced or skipped: it is carried straight across from the crossing to the exit point (a rolling path,
//     RimMode.Crossing, arriving after the reference's time), then leaves with the exit velocity; 'bounce' +
//     'nearMiss' or 'skip' at the crossing
// While it rides round the lip the ball is in mode rimRoll (the RimContact component marks it), as in a
// Stage 3 roll; while it is carried across, it is rolling (the hole locked).
// A ball faster than the table's top (2,000 px/s at the design's geometry), or of a size whose table was not
// given to the world (it has its config's; prepareRimTable adds others), is decided by the live reference; a
// ball not smaller than the hole, or a node where a guard stopped the reference, is left to the stages.
// Reads Path, Ball, Hole, RimContact, config; writes Ball, Path, RimContact; emits the events above.
import { BallMode } from '../components/Ball.js'
import { PathEvent } from '../components/Path.js'
import { RIDE_DROPS, RIDE_LEAVES, RimMode } from '../components/RimContact.js'
import { CaptureVia, EventType } from '../src/events.js'
import { captureBall, emitHoleEvent } from '../src/motion/ballFate.js'
import { planRimRoll, sampleRimRoll } from '../src/motion/rimRoll.js'
import { planRolling, startPath } from '../src/motion/rolling.js'
import { RimKind, ROLL_TURN, TABLE_TOP_SPEED, captureSpeedAt, crossingAngle, exitRelative, outcomeAt, rimOut, type RimTable } from '../src/reference/rimTable.js'
import { simulateScaled } from '../src/reference/sphereLip.js'
import { cogRadius } from '../src/geometry.js'
import { lockAtLip } from '../src/world/rimSlots.js'
import { setBallMode } from '../src/world/ballMode.js'
import { type BallWorld } from '../src/world/createWorld.js'

/** The world's table for this geometry, or null (then the live reference decides). */
function tableFor(w: BallWorld, ratio: number, inertia: number): RimTable | null {
  const tables = w.rimTables
  for (let i = 0; i < tables.length; i++) {
    const t = tables[i]!
    if (t.ratio === ratio && t.inertia === inertia) return t
  }
  return null
}

export function tabulatedRimSystem(w: BallWorld): void {
  if (w.config.RIM_MODEL !== 'tabulated') return
  const P = w.Path
  const B = w.Ball
  const RC = w.RimContact
  const list = w.marked
  for (let i = 0; i < list.count; i++) {
    const eid = list.ids[i]!
    const mark = P.mark[eid]
    if (mark === PathEvent.Lip) decideCrossing(w, eid)
    else if (mark === PathEvent.RollEnd && RC.ride[B.rim[eid]!] !== 0) endRide(w, eid)
    else if (mark === PathEvent.Landing) land(w, eid)
  }
}

/** Decides a lip crossing from the table (or the live reference above its top speed). */
function decideCrossing(w: BallWorld, eid: number): void {
  const P = w.Path
  const H = w.Hole
  const B = w.Ball
  const hole = P.markHole[eid]!
  const R = H.radius[hole]!
  const r = B.radius[eid]!
  const ux = P.ux[eid]!
  const uy = P.uy[eid]!
  // signed offset of the path: its closest point is at cross·(−uy, ux) from the hole centre
  const cross = (H.x[hole]! - P.x0[eid]!) * uy - (H.y[hole]! - P.y0[eid]!) * ux
  const delta = Math.abs(cross)
  const v = P.speed[eid]!
  if (!(r < R) || !(delta < R) || !(v > 0)) return
  const g = w.config.GRAVITY
  const j = w.config.BALL_INERTIA
  const vScale = Math.sqrt(g * r)
  const ds = delta / r
  const vs = v / vScale
  const o = rimOut
  const table = vs > TABLE_TOP_SPEED ? null : tableFor(w, R / r, j)
  if (table === null) {
    // beyond the table's speeds (a fast ball, rare), or a geometry with no table built: the live reference
    const live = simulateScaled(R / r, ds, vs, j, null)
    if (live.ending === 'phaseLimit' || live.ending === 'timeLimit' || live.ending === 'integratorLimit') return
    o.turn = live.turnAngle
    o.time = live.duration
    if (live.captured) o.kind = RimKind.Captured
    else {
      o.kind = live.turnAngle >= ROLL_TURN ? RimKind.Rolled : live.impacts > 0 ? RimKind.Bounced : RimKind.Skipped
      let turn = crossingAngle(R / r, ds) - Math.atan2(live.exitY!, live.exitX!)
      turn -= 2 * Math.PI * Math.floor(turn / (2 * Math.PI))
      while (turn + Math.PI < live.turnAngle) turn += 2 * Math.PI
      o.exitTurn = turn
      o.exitRadius = Math.sqrt(live.exitX! * live.exitX! + live.exitY! * live.exitY!)
      const rel = exitRelative(live.exitAngle!, crossingAngle(R / r, ds), turn)
      o.exitCos = Math.cos(rel)
      o.exitSin = Math.sin(rel)
      o.exitSpeed = live.exitSpeed!
    }
  } else {
    outcomeAt(table, ds, vs, vs <= captureSpeedAt(table, ds))
    if (o.kind === RimKind.Guarded) return
  }

  const t = P.nextT[eid]!
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
    const cT = Math.cos(o.exitTurn)
    const sT = Math.sin(o.exitTurn)
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
        startPath(w, eid, B.x[eid]!, B.y[eid]!, (dx / L) * v0, (dy / L) * v0, t)
        RC.mode[slot] = RimMode.Crossing
        RC.rideTo[slot] = L
        RC.time0[slot] = t
        RC.speed0[slot] = P.v0[eid]!
      } else {
        RC.mode[slot] = RimMode.Transit
        startPath(w, eid, B.x[eid]!, B.y[eid]!, RC.exitVx[slot]!, RC.exitVy[slot]!, t)
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
  RC.rideFrom[slot] = Math.sqrt((B.x[eid]! - hx) ** 2 + (B.y[eid]! - hy) ** 2)
  RC.rideTo[slot] = escapes ? o.exitRadius * r : cogRadius(R, r)
  RC.angle0[slot] = Math.atan2(B.y[eid]! - hy, B.x[eid]! - hx)
  RC.direction[slot] = side > 0 ? -1 : 1
  RC.time0[slot] = t
  RC.speed0[slot] = v
  setBallMode(w, eid, BallMode.RimRoll)
  sampleRimRoll(w, eid, t)
  planRimRoll(w, eid)
  emitHoleEvent(w, EventType.RimRoll, eid, hole, t)
}

/** A tabulated crossing reaches the reference's exit point (its state there sampled): it leaves at the exit velocity. */
function land(w: BallWorld, eid: number): void {
  const P = w.Path
  const B = w.Ball
  const RC = w.RimContact
  const slot = B.rim[eid]!
  P.mark[eid] = PathEvent.None
  RC.mode[slot] = RimMode.Transit
  startPath(w, eid, B.x[eid]!, B.y[eid]!, RC.exitVx[slot]!, RC.exitVy[slot]!, P.nextT[eid]!)
  P.fromHole[eid] = P.markHole[eid]!
  planRolling(w, eid)
}

/** A tabulated ride's end (its state there already sampled): drop in, or leave with the exit velocity. */
function endRide(w: BallWorld, eid: number): void {
  const P = w.Path
  const B = w.Ball
  const RC = w.RimContact
  const slot = B.rim[eid]!
  const hole = P.markHole[eid]!
  const t = P.nextT[eid]!
  P.mark[eid] = PathEvent.None
  const ride = RC.ride[slot]
  RC.ride[slot] = 0
  if (ride === RIDE_DROPS) {
    captureBall(w, eid, hole, t, CaptureVia.RimRoll)
    return
  }
  RC.mode[slot] = RimMode.Transit
  setBallMode(w, eid, BallMode.Rolling)
  startPath(w, eid, B.x[eid]!, B.y[eid]!, RC.exitVx[slot]!, RC.exitVy[slot]!, t)
  P.fromHole[eid] = hole
  planRolling(w, eid)
  emitHoleEvent(w, EventType.LipOut, eid, hole, t)
  emitHoleEvent(w, EventType.NearMiss, eid, hole, t)
}
