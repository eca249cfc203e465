// The fixed tick's pairs that meet at their instant (src/contacts/fixedMeet.ts): per ball id, part of the
// world's state (snapshots keep it).
import { grownTo } from './fixedState.js'

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
