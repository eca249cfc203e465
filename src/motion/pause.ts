// The rule for a step that runs out of event passes (config.MAX_EVENT_PASSES): the balls still behind the
// step's end wait where they are and resume at the step's end, their motion shifted in time (each keeps its
// path, its speed and its next event, later by the wait). So no ball is ever left behind the world's clock:
// every event lies in the step that reported it, events never go back in time across drains, and a command
// after the step re-plans balls that are where the clock says. Only a scene with more events in one step
// than the passes allow (a 1e5 px/s ball in a 60 px box) waits, and only for the part of the step it had left.
import { BallMode } from '../../components/Ball.js'
import type { BallWorld } from '../world/createWorld.js'
import { dropPredictions } from '../world/contactState.js'
import { sampleMovingAt } from './rimRoll.js'
import { sampleTime } from './rolling.js'
import { timeToDistance } from '../geometry.js'
import { HOT, H_NEXT_T, H_T0, H_V0 } from '../world/pathHot.js'

/** Shifts a moving ball's current motion `delta` seconds later (its path, its rim roll, its next event). */
export function delayMotion(w: BallWorld, eid: number, delta: number): void {
  const mode = w.Ball.mode[eid]
  if (mode === BallMode.RimRoll) {
    w.RimContact.time0[w.Ball.rim[eid]!]! += delta
  } else if (mode === BallMode.Rolling) {
    w.pathHot[eid * HOT + H_T0]! += delta
  } else return
  w.pathHot[eid * HOT + H_NEXT_T]! += delta
  // a fixed tick's pair that was to meet (src/contacts/fixedMeet.ts): this ball no longer meets the other then
  if (w.meet !== null && w.meet.with[eid] !== 0) w.meet.t[eid]! += delta
}

/** The time a moving ball's stored state is at: its last event on the current path (or rim roll). */
function ownTime(w: BallWorld, eid: number): number {
  const P = w.Path
  if (w.Ball.mode[eid] === BallMode.RimRoll) return w.RimContact.time0[w.Ball.rim[eid]!]!
  const h = eid * HOT
  return w.pathHot[h + H_T0]! + timeToDistance(P.s[eid]!, w.pathHot[h + H_V0]!, w.config.ROLLING_DECEL)
}

/**
 * After the last pass of a step that ran out of passes: every ball the decision systems handled in it
 * waits until the step's end. With ball-ball contacts on, the whole world waits from the last event handled
 * (every ball is there, in one consistent state), so no ball moves through another while others wait.
 */
export function waitOutStep(w: BallWorld): void {
  const tEnd = w.tickEnd
  const C = w.collide
  if (C !== null) {
    const delta = tEnd - C.now
    const balls = w.moving.dense
    for (let i = 0, n = w.moving.count; i < n; i++) {
      const eid = balls[i]!
      delayMotion(w, eid, delta)
      sampleTime[0] = tEnd
      sampleMovingAt(w, eid)
    }
    C.now = tEnd
    w.marked.count = 0
    // every path moved in time: the next step predicts them all again
    dropPredictions(w)
    return
  }
  const list = w.marked
  for (let i = 0; i < list.count; i++) {
    const eid = list.ids[i]!
    const mode = w.Ball.mode[eid]
    if (mode !== BallMode.Rolling && mode !== BallMode.RimRoll) continue
    delayMotion(w, eid, tEnd - ownTime(w, eid))
    sampleTime[0] = tEnd
    sampleMovingAt(w, eid)
  }
  list.count = 0
}
