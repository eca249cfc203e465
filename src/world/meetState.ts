// The fixed tick's pairs that meet at their instant (src/contacts/fixedMeet.ts): per ball id, part of the
// world's state (snapshots keep it).
import { BallMode } from '../../components/Ball.js'
import { PathEvent } from '../../components/Path.js'
import type { BallWorld } from './createWorld.js'
import { grownTo } from './fixedState.js'
import { HOT, H_NEXT_S, H_NEXT_T, H_T0, H_V0 } from './pathHot.js'

export interface MeetState {
  /** the other ball of the ball's meeting (0: none; a new path clears it), and the meeting's instant, s */
  with: Uint32Array
  t: Float64Array
  /** the restitution the meeting takes: what the tick's solve gave the pair */
  e: Float64Array
  /** pairs given their instant instead of the tick, over the world's life */
  timed: number
}

export function createMeetState(capacity: number): MeetState {
  return { with: new Uint32Array(capacity), t: new Float64Array(capacity), e: new Float64Array(capacity), timed: 0 }
}

/** Rows for every ball id below `cap`, the old ones kept. */
export function growMeetState(M: MeetState, cap: number): void {
  if (M.with.length >= cap) return
  M.with = grownTo(M.with, cap)
  M.t = grownTo(M.t, cap)
  M.e = grownTo(M.e, cap)
}

/**
 * Ball e's next event: its meeting (M.with, M.t), on its present path or rim roll (src/contacts/fixedMeet.ts
 * gives it; src/motion/rolling.ts gives it back after a plan of the same path).
 */
export function meetNext(w: BallWorld, e: number): void {
  const M = w.meet!
  const H = w.pathHot
  const h = e * HOT
  const t = M.t[e]!
  const tau = t - H[h + H_T0]!
  H[h + H_NEXT_T] = t
  // (the distance along a straight path; a ball on a rim has none)
  H[h + H_NEXT_S] = w.Ball.mode[e] === BallMode.Rolling ? H[h + H_V0]! * tau - 0.5 * w.config.ROLLING_DECEL * tau * tau : 0
  w.Path.nextKind[e] = PathEvent.Meet
  w.Path.nextHole[e] = M.with[e]!
  w.Path.nextEdge[e] = 0
}
