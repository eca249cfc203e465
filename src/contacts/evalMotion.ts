// The state of a ball at any time of its current motion (straight roll, rim roll, rest), without writing to
// the stores: what the contact search, the capsules and the cluster gatherer evaluate.
import { BallMode } from '../../components/Ball.js'
import type { BallWorld } from '../world/createWorld.js'
import { rimRollAt, rimRollState } from '../motion/rimRoll.js'
import { sampleTime } from '../motion/rolling.js'
import { HOT, H_NEXT_T, H_T0, H_UX, H_UY, H_V0, H_X0, H_Y0 } from '../world/pathHot.js'

/**
 * The scratch state evalBall writes, in a Float64Array: V8 boxes every double written to a module-level
 * `let` (a fresh heap number per write), and a typed array never allocates.
 *   X, Y, VX, VY: state; AX, AY: exact acceleration (rolling); ACC: bound on |acceleration| from now on
 *   (rim roll), else |(AX, AY)|; EXACT: 1 when (AX, AY) is the exact, piecewise constant acceleration;
 *   NEXT: when the acceleration next changes (a rolling ball's stop), s
 */
export const E = new Float64Array(11)
export const X = 0
export const Y = 1
export const VX = 2
export const VY = 3
export const AX = 4
export const AY = 5
export const ACC = 6
export const EXACT = 7
export const NEXT = 8
/** input: the time evalBall evaluates at (passed here, not as an argument, which V8 would box) */
export const AT = 9
/** output of motionStart and motionEnd (a time, s): written, not returned, for the same reason */
export const MT = 10

/**
 * Evaluates ball `eid` at time E[AT] on its current motion into the module's scratch state. The formulas are
 * those of sampleRolling and sampleRimRoll, term for term, so a contact sees the very state the stores get.
 */
export function evalBall(w: BallWorld, eid: number): void {
  const t = E[AT]!
  const B = w.Ball
  const mode = B.mode[eid]
  if (mode === BallMode.RimRoll) {
    sampleTime[0] = t
    rimRollAt(w, eid)
    const o = rimRollState
    E[X] = o.x
    E[Y] = o.y
    E[VX] = o.vx
    E[VY] = o.vy
    E[AX] = 0
    E[AY] = 0
    // |acceleration| = √((v²/R)² + (μv)²) ≤ v²/R + μv, and v only falls from here
    E[ACC] = (o.speed * o.speed) / o.radius + w.config.RIM_ROLL_FRICTION * o.speed
    E[EXACT] = 0
    E[NEXT] = Infinity
    return
  }
  if (mode === BallMode.Resting) {
    E[X] = B.x[eid]!
    E[Y] = B.y[eid]!
    E[VX] = 0
    E[VY] = 0
    E[AX] = 0
    E[AY] = 0
    E[ACC] = 0
    E[EXACT] = 1
    E[NEXT] = Infinity
    return
  }
  const v0 = w.pathHot[eid * HOT + H_V0]!
  const decel = w.config.ROLLING_DECEL
  const t0 = w.pathHot[eid * HOT + H_T0]!
  let tau = t - t0
  if (tau < 0) tau = 0
  let moving = v0 > 0
  if (decel > 0 && tau * decel > v0) {
    tau = v0 / decel
    moving = false
  }
  const d = v0 * tau - 0.5 * decel * tau * tau
  const v = v0 - decel * tau
  const ux = w.pathHot[eid * HOT + H_UX]!
  const uy = w.pathHot[eid * HOT + H_UY]!
  E[X] = w.pathHot[eid * HOT + H_X0]! + ux * d
  E[Y] = w.pathHot[eid * HOT + H_Y0]! + uy * d
  E[VX] = ux * v
  E[VY] = uy * v
  E[EXACT] = 1
  if (moving && decel > 0) {
    E[AX] = -decel * ux
    E[AY] = -decel * uy
    E[ACC] = decel
    E[NEXT] = t0 + v0 / decel
  } else {
    E[AX] = 0
    E[AY] = 0
    E[ACC] = 0
    E[NEXT] = Infinity
  }
}

/**
 * When the ball's current motion began (the search for its contacts starts there, whatever the ticks), into
 * E[MT]. Written into a slot, not returned: a double returned by a call V8 does not inline is boxed, and
 * which calls it inlines changes with the caller (the contact search, the prediction, the integration) and
 * from one process to the next.
 */
export function motionStart(w: BallWorld, eid: number): void {
  const mode = w.Ball.mode[eid]
  if (mode === BallMode.RimRoll) {
    E[MT] = w.RimContact.time0[w.Ball.rim[eid]!]!
    return
  }
  const t0 = w.pathHot[eid * HOT + H_T0]!
  if (mode !== BallMode.Resting) {
    E[MT] = t0
    return
  }
  // a ball at rest has been so since its path stopped (or since it was put down)
  const decel = w.config.ROLLING_DECEL
  const v0 = w.pathHot[eid * HOT + H_V0]!
  E[MT] = v0 > 0 && decel > 0 ? t0 + v0 / decel : t0
}

/**
 * End of the span over which a ball's current motion is known, capped at the prediction window's end
 * (CollisionState.until), into E[MT] (as motionStart): its next own event, or for a rolling ball the later
 * event up to which the planner found its path kept (CollisionState.formulaEnd).
 */
export function motionEnd(w: BallWorld, eid: number): void {
  const C = w.collide!
  const cap = C.until
  const mode = w.Ball.mode[eid]
  let t = mode === BallMode.Resting ? cap : w.pathHot[eid * HOT + H_NEXT_T]!
  if (mode === BallMode.Rolling) {
    const f = C.formulaEnd[eid]!
    if (f > t) t = f
  }
  E[MT] = t < cap ? t : cap
}

/** Writes ball `eid`'s state at time E[AT] (on its current motion) into Ball. */
export function sampleForContact(w: BallWorld, eid: number): void {
  evalBall(w, eid)
  const B = w.Ball
  B.x[eid] = E[X]
  B.y[eid] = E[Y]
  B.vx[eid] = E[VX]
  B.vy[eid] = E[VY]
}
