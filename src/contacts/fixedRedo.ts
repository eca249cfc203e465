// Fixed-tick contacts: a tick solved again at a finer spacing. The widening rounds (src/contacts/fixedReach.ts)
// stop at bounds on their pairs (src/config/tolerances.ts: PASS_PAIRS_PER_BALL, PASS_PAIRS_PER_WIDENED);
// when they stop there with a ball the last round sped up that could still pass through another within
// the tick, or end with a pair closing deep into itself, or a ball moving into a wall, that a finer spacing
// would solve (on a tick of many pairs a candidate, only a push's front: src/contacts/fixedDeep.ts), the
// tick's solve so far is dropped and the tick is gathered, paired and solved
// again from the same state, halved at least once more (src/contacts/fixedHalve.ts): a heavy ball striking a
// row of light ones sends each ahead at up to twice its speed, and, frozen at the tick's start, every light
// ball reaches every other within a tick; at a finer spacing each reaches a few. The solve writes only the
// packed candidates until the projection, so dropping it is putting back what it wrote outside them: the
// events and contacts it recorded, the count of the balls the last tick touched (the gather empties the
// list; nothing in a try writes to it: applyChanges does, after the last try) and the spacing's state. At most MAX_TICK_REDOS times a tick (src/config/tolerances.ts), each halved 1, 3, 7, 15
// times more than the first try, and never past MAX_TICK_HALVINGS.
import { MAX_TICK_REDOS } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import type { FixedContactState } from '../world/fixedState.js'
import { halvingsLeft, restoreSpacing, saveSpacing } from './fixedHalve.js'

let events = 0
let contacts = 0
let inelastic = 0
let touchedCount = 0
/** Ticks solved again, over the process's life (for tests and benchmarks). */
let redone = 0

/** Keeps what a tick's solve writes outside its packed candidates, after coarsenTick and before the gather. */
export function saveTick(w: BallWorld, F: FixedContactState): void {
  events = w.events.count
  contacts = F.contacts
  inelastic = F.inelastic
  touchedCount = F.touchedCount
  saveSpacing(w, F)
}

/**
 * The halvings the next try of this tick asks for, more than the spacing it started at, when the last try,
 * which took `last` of them, stopped with a ball that may pass (tries: the tries so far); 0 when none is left.
 */
export function redoHalvings(tries: number, last: number): number {
  if (tries > MAX_TICK_REDOS) return 0
  const left = halvingsLeft()
  if (last >= left) return 0
  return Math.min(left, last + (1 << (tries - 1)))
}

/** Drops a tick's try: puts back what saveTick kept. */
export function restoreTick(w: BallWorld, F: FixedContactState): void {
  w.events.count = events
  F.contacts = contacts
  F.inelastic = inelastic
  F.touchedCount = touchedCount
  restoreSpacing(w, F)
  redone++
}

/** Ticks solved again since the process started. */
export function ticksRedone(): number {
  return redone
}
