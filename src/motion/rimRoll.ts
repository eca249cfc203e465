// A ball rolling round a hole's lip (Stage 3): its closed-form state at any time, v_t = v_t0·e^(−μτ), the
// start of a roll and its end (drop or pop-off), exact for every dt.
import { BallMode } from '../../components/Ball.js'
import { PathEvent } from '../../components/Path.js'
import { RimMode } from '../../components/RimContact.js'
import { popArc, rollDropTime, rollPopTime } from '../geometry.js'
import { type BallWorld } from '../world/createWorld.js'
import { EventType } from '../events.js'
import { emitHoleEvent } from './ballFate.js'
import { sampleRollingAt, sampleTime, startAt, planRolling, startPath } from './rolling.js'
import { setBallMode } from '../world/ballMode.js'
import { setNextT } from '../world/pathHot.js'
import { ARG, COS, RESULT, SIN, atan2, expSlot, expm1Slot, hypot, mathSlot, sinCosSlot } from '../math.js'

/** Next event of a ball rolling on a rim: the earlier of its drop and its pop-off. */
export function planRimRoll(w: BallWorld, eid: number): void {
  const RC = w.RimContact
  const cfg = w.config
  const slot = w.Ball.rim[eid]!
  const hole = RC.hole[slot]!
  if (RC.ride[slot] !== 0) {
    // a tabulated ride ends when its time is up (systems/tabulatedRim.ts decides what then)
    const P = w.Path
    P.nextKind[eid] = PathEvent.RollEnd
    P.nextHole[eid] = hole
    setNextT(w, eid, RC.time0[slot]! + RC.rideTime[slot]!)
    return
  }
  const vt0 = RC.speed0[slot]!
  const tDrop = rollDropTime(vt0, cfg.RIM_ROLL_FRICTION, cfg.RIM_ROLL_DROP_SPEED)
  const tPop = rollPopTime(vt0, cfg.RIM_ROLL_FRICTION, popArc(cfg.RIM_ROLL_MAX_TURNS, w.Hole.radius[hole]!))
  const P = w.Path
  P.nextKind[eid] = PathEvent.RollEnd
  P.nextHole[eid] = hole
  setNextT(w, eid, RC.time0[slot]! + Math.min(tDrop, tPop))
}

/**
 * A ball on a rim leaves it at time t with velocity (vx, vy): in transit through the hole (locked until its
 * centre is out), rolling on a fresh path; 'lipOut' and 'nearMiss'. Shared by the Stage 3 pop-off and the
 * end of a tabulated ride.
 */
export function leaveRim(w: BallWorld, eid: number, hole: number, vx: number, vy: number, t: number): void {
  const B = w.Ball
  w.RimContact.mode[B.rim[eid]!] = RimMode.Transit
  setBallMode(w, eid, BallMode.Rolling)
  startAt(B.x[eid]!, B.y[eid]!, vx, vy, t)
  startPath(w, eid)
  w.Path.fromHole[eid] = hole
  planRolling(w, eid)
  emitHoleEvent(w, EventType.LipOut, eid, hole, t)
  emitHoleEvent(w, EventType.NearMiss, eid, hole, t)
}

/** True when a rim roll that started with speed vt0 pops off before it drops. */
export function rollPopsOff(w: BallWorld, eid: number): boolean {
  const RC = w.RimContact
  const cfg = w.config
  const slot = w.Ball.rim[eid]!
  const vt0 = RC.speed0[slot]!
  const tDrop = rollDropTime(vt0, cfg.RIM_ROLL_FRICTION, cfg.RIM_ROLL_DROP_SPEED)
  const tPop = rollPopTime(vt0, cfg.RIM_ROLL_FRICTION, popArc(cfg.RIM_ROLL_MAX_TURNS, w.Hole.radius[RC.hole[slot]!]!))
  return tPop < tDrop
}

/** A rim-rolling ball's state at a time, written by rimRollAt (module scratch: no allocation). */
export const rimRollState = { x: 0, y: 0, vx: 0, vy: 0, speed: 0, angle: 0, arc: 0, radius: 0 }

/**
 * Evaluates a rim-rolling ball at time sampleTime[0] (src/motion/rolling.ts: a slot, not an argument,
 * which V8 boxes where it does not inline the call) into rimRollState: v_t = v_t0·e^(−μτ), exact for every
 * dt. The centre rides the contact circle ρ_c = R − r/2, where the COG gate took the contact (so a roll
 * starts where the ball is, with no jump), and turns arc/ρ_c radians.
 */
export function rimRollAt(w: BallWorld, eid: number): void {
  const t = sampleTime[0]!
  const RC = w.RimContact
  const slot = w.Ball.rim[eid]!
  const hole = RC.hole[slot]!
  if (RC.ride[slot] !== 0) {
    rideAt(w, slot, hole)
    return
  }
  // cogRadius, rollArc and rollSpeed (src/geometry.ts) written out, term for term (a change to one is a
  // change to both): called, they took and returned doubles, which V8 boxes where it does not inline the
  // call (four heap numbers a rim-rolling ball a step)
  const R = w.Hole.radius[hole]! - w.Ball.radius[eid]! / 2
  const vt0 = RC.speed0[slot]!
  const mu = w.config.RIM_ROLL_FRICTION
  let tau = t - RC.time0[slot]!
  if (tau < 0) tau = 0
  let arc = vt0 * tau
  if (mu > 0) {
    mathSlot[ARG] = -mu * tau
    expm1Slot()
    arc = (vt0 * -mathSlot[RESULT]!) / mu
  }
  mathSlot[ARG] = -mu * tau
  expSlot()
  const v = vt0 * mathSlot[RESULT]!
  const dir = RC.direction[slot]!
  const phi = RC.angle0[slot]! + (dir * arc) / R
  mathSlot[ARG] = phi
  sinCosSlot()
  const c = mathSlot[COS]!
  const s = mathSlot[SIN]!
  const o = rimRollState
  o.x = w.Hole.x[hole]! + R * c
  o.y = w.Hole.y[hole]! + R * s
  o.vx = -dir * s * v
  o.vy = dir * c * v
  o.speed = v
  o.angle = phi
  o.arc = arc
  o.radius = R
}

/**
 * A tabulated ride at time sampleTime[0] into rimRollState: the centre turns at a steady rate while its
 * distance from the hole centre moves linearly from rideFrom to rideTo (an animation of the reference's
 * outcome, whose start and end are the reference's: the lip crossing and the exit point or the drop).
 */
function rideAt(w: BallWorld, slot: number, hole: number): void {
  const RC = w.RimContact
  const T = RC.rideTime[slot]!
  let tau = sampleTime[0]! - RC.time0[slot]!
  if (tau < 0) tau = 0
  else if (tau > T) tau = T
  const f = T > 0 ? tau / T : 1
  const turn = RC.rideTurn[slot]!
  const dir = RC.direction[slot]!
  const from = RC.rideFrom[slot]!
  const to = RC.rideTo[slot]!
  const phi = RC.angle0[slot]! + dir * turn * f
  const rho = from + (to - from) * f
  mathSlot[ARG] = phi
  sinCosSlot()
  const c = mathSlot[COS]!
  const s = mathSlot[SIN]!
  // d(phi)/dt and d(rho)/dt
  const wPhi = T > 0 ? (dir * turn) / T : 0
  const wRho = T > 0 ? (to - from) / T : 0
  const o = rimRollState
  o.x = w.Hole.x[hole]! + rho * c
  o.y = w.Hole.y[hole]! + rho * s
  o.vx = wRho * c - rho * s * wPhi
  o.vy = wRho * s + rho * c * wPhi
  o.speed = Math.sqrt(o.vx * o.vx + o.vy * o.vy)
  o.angle = phi
  o.arc = rho * turn * f
  o.radius = rho
}

/** Ball state at time t on the rim (rimRollAt), written into Ball, RimContact and Path. */
export function sampleRimRoll(w: BallWorld, eid: number, t: number): void {
  sampleTime[0] = t
  sampleRimRollAt(w, eid)
}

/** A moving ball (rolling or on a rim) sampled at sampleTime[0] into its stores. */
export function sampleMovingAt(w: BallWorld, eid: number): void {
  if (w.Ball.mode[eid] === BallMode.RimRoll) sampleRimRollAt(w, eid)
  else sampleRollingAt(w, eid)
}

/** sampleRimRoll at sampleTime[0] (the systems' form: they write the slot). */
export function sampleRimRollAt(w: BallWorld, eid: number): void {
  rimRollAt(w, eid)
  const o = rimRollState
  const B = w.Ball
  const slot = B.rim[eid]!
  B.x[eid] = o.x
  B.y[eid] = o.y
  B.vx[eid] = o.vx
  B.vy[eid] = o.vy
  w.RimContact.angle[slot] = o.angle
  w.RimContact.arc[slot] = o.arc
  w.Path.speed[eid] = o.speed
}

/**
 * Puts a ball on the rim of `hole` at time t (Stage 3's start), from its state in Ball: angle, tangential
 * speed |v_t| along the counter-clockwise tangent (−n_y, n_x), direction and start time into its RimContact
 * slot, mode RimRoll. Returns the angle. Shared by the exact and the naive rim-roll systems.
 */
export function startRimRoll(w: BallWorld, eid: number, hole: number, t: number): number {
  const B = w.Ball
  const RC = w.RimContact
  const rim = B.rim[eid]!
  const nx = B.x[eid]! - w.Hole.x[hole]!
  const ny = B.y[eid]! - w.Hole.y[hole]!
  const len = hypot(nx, ny)
  const vt = len > 0 ? (-B.vx[eid]! * ny + B.vy[eid]! * nx) / len : 0
  const phi = atan2(ny, nx)
  RC.mode[rim] = RimMode.Rolling
  RC.angle0[rim] = phi
  RC.speed0[rim] = Math.abs(vt)
  RC.direction[rim] = vt >= 0 ? 1 : -1
  RC.time0[rim] = t
  setBallMode(w, eid, BallMode.RimRoll)
  return phi
}
