// The transitions that end or restart a ball's motion: capture, rest, launch, and the hole events they emit.
import { BallMode } from '../../components/Ball.js'
import { PathEvent } from '../../components/Path.js'
import { RimMode } from '../../components/RimContact.js'
import { holeAt } from '../world/holeTable.js'
import { CaptureVia, EventType, appendEvent, type CaptureViaCode } from '../events.js'
import { addMoving, removeMoving } from '../world/idLists.js'
import { acquireRim, releaseRim } from '../world/rimSlots.js'
import { type BallWorld } from '../world/createWorld.js'
import { restingInsert, restingRemove } from '../world/restingGrid.js'
import { NEVER } from '../config/tolerances.js'
import { pathStart, PS_T, PS_VX, PS_VY, PS_X, PS_Y, planRolling, startAt, startPath } from './rolling.js'
import { setBallMode } from '../world/ballMode.js'
import { setNextT } from '../world/pathHot.js'
import { touchBall } from '../world/fixedState.js'
import { pathChanged } from '../world/contactState.js'

/** Emits a hole event carrying the lip crossing's (δ, v) when the ball has one for this hole. */
export function emitHoleEvent(
  w: BallWorld,
  type: (typeof EventType)[keyof typeof EventType],
  eid: number,
  hole: number,
  t: number,
  via: CaptureViaCode = CaptureVia.None,
): void {
  const RC = w.RimContact
  const slot = w.Ball.rim[eid]!
  const hasLip = RC.hole[slot] === hole && RC.hasLip[slot] === 1
  const buf = w.events
  const i = appendEvent(buf, type, eid, hole, hasLip, via)
  buf.time[i] = t
  if (hasLip) {
    buf.delta[i] = RC.delta[slot]!
    buf.speed[i] = RC.speed[slot]!
  }
}

/**
 * The ball falls into `hole` at time t: it sits at the hole centre, at rest, and stops being simulated.
 * Its hole lock ends with the capture event, so its RimContact slot is given back.
 */
export function captureBall(w: BallWorld, eid: number, hole: number, t: number, via: CaptureViaCode): void {
  emitHoleEvent(w, EventType.Capture, eid, hole, t, via)
  const B = w.Ball
  setBallMode(w, eid, BallMode.Captured)
  B.x[eid] = w.Hole.x[hole]!
  B.y[eid] = w.Hole.y[hole]!
  B.vx[eid] = 0
  B.vy[eid] = 0
  w.Path.speed[eid] = 0
  setNextT(w, eid, NEVER)
  w.Path.nextKind[eid] = PathEvent.None
  releaseRim(w, eid)
  removeMoving(w, eid)
  restingRemove(w, eid)
}

/** The ball stops on the panel, outside every hole, at time t. */
export function restBall(w: BallWorld, eid: number, t: number): void {
  const ev = appendEvent(w.events, EventType.Rest, eid, 0, false)
  w.events.time[ev] = t
  const B = w.Ball
  setBallMode(w, eid, BallMode.Resting)
  B.vx[eid] = 0
  B.vy[eid] = 0
  w.Path.speed[eid] = 0
  setNextT(w, eid, NEVER)
  w.Path.nextKind[eid] = PathEvent.None
  removeMoving(w, eid)
  // with ball-ball contacts on, a resting ball is found by moving ones through the resting grid, and looks
  // for the moving ones already predicted to pass its spot
  restingInsert(w, eid)
  pathChanged(w, eid)
  // fixed-tick contacts: it may have stopped inside another (between ticks); the next tick looks
  if (w.fixed !== null) touchBall(w.fixed, eid)
}

/** Puts a ball back into motion (rolling) on a fresh straight path from pathStart (src/motion/rolling.ts). */
export function launchBall(w: BallWorld, eid: number): void {
  // read before the mode changes (a component observer may start another path)
  const x = pathStart[PS_X]!
  const y = pathStart[PS_Y]!
  const vx = pathStart[PS_VX]!
  const vy = pathStart[PS_VY]!
  const t = pathStart[PS_T]!
  restingRemove(w, eid)
  setBallMode(w, eid, BallMode.Rolling)
  // written back here, not through startAt: where V8 inlines launchBall but not startAt into it, a call
  // with five doubles boxed them at every launch
  pathStart[PS_X] = x
  pathStart[PS_Y] = y
  pathStart[PS_VX] = vx
  pathStart[PS_VY] = vy
  pathStart[PS_T] = t
  startPath(w, eid)
  planRolling(w, eid)
  addMoving(w, eid)
}

/** launchBall with the start as arguments: what `./ecs` exports as launchBall, for a game's own systems. */
export function launchBallAt(w: BallWorld, eid: number, x: number, y: number, vx: number, vy: number, t: number): void {
  startAt(x, y, vx, vy, t)
  launchBall(w, eid)
}

/**
 * Puts a ball on the panel at (x, y), moving, at time t (default now). A ball put down inside a lip circle
 * is in transit through that hole: no decision is made for it there, and if it stops before leaving, it falls in.
 */
export function placeBall(w: BallWorld, eid: number, x: number, y: number, vx: number, vy: number, t = w.time): void {
  const inside = holeAt(w, x, y, w.Ball.radius[eid]!)
  if (inside !== 0) {
    const slot = acquireRim(w, eid)
    w.RimContact.hole[slot] = inside
    w.RimContact.mode[slot] = RimMode.Transit
  }
  startAt(x, y, vx, vy, t)
  launchBall(w, eid)
  // fixed-tick contacts: the new ball's path up to the next tick is checked now (a solve at this instant)
  if (w.fixed !== null) w.fixed.due = true
}
