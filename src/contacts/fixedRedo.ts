// Fixed-tick contacts: a tick solved again at a finer spacing. The widening rounds (src/contacts/fixedReach.ts)
// stop at bounds on their pairs (src/config/tolerances.ts: PASS_PAIRS_PER_BALL, PASS_PAIRS_PER_WIDENED);
// when they stop there with a ball the last round sped up that could still pass through another within
// the tick, or end with a pair closing deep into itself, or a ball moving into a wall, that a finer spacing
// would solve (on a tick of many pairs a candidate, only a push's front: src/contacts/fixedDeep.ts), the
// tick's solve so far is dropped and the tick is gathered, paired and solved
// again from the same state, halved at least once more (src/contacts/fixedHalve.ts). So is a tick of few pairs
// whose solve closed pairs inelastically past their restitution visits, every one of them a pair apart at
// the tick (elasticFiner): a heavier ball struck into a pile whose balls are apart sends each struck ball
// across its gap into the next, and back into the striker, within the tick; at a finer spacing those
// meetings fall in ticks of their own. Not when a touching pair closed so too: a touching pile's pairs meet
// as often within any tick, and at a finer spacing at more ticks. A heavy ball striking a
// row of light ones sends each ahead at up to twice its speed, and, frozen at the tick's start, every light
// ball reaches every other within a tick; at a finer spacing each reaches a few. The solve writes only the
// packed candidates until the projection, so dropping it is putting back what it wrote outside them: the
// events and contacts it recorded, the count of the balls the last tick touched (the gather empties the
// list; nothing in a try writes to it: applyChanges does, after the last try) and the spacing's state. At most MAX_TICK_REDOS times a tick (src/config/tolerances.ts), each halved 1, 3, 7, 15
// times more than the first try, and never past MAX_TICK_HALVINGS.
import { APART_SHARE, MAX_TICK_REDOS, SMALL_TICK_PAIRS } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import type { FixedContactState } from '../world/fixedState.js'
import { halvingsLeft, restoreSpacing, saveSpacing } from './fixedHalve.js'

let events = 0
let contacts = 0
let inelastic = 0
let touchedCount = 0
/** Ticks solved again, over the process's life (for tests and benchmarks). */
let redone = 0
/** the try's impulses closed inelastically past their visits: between balls apart at the tick, and touching */
let apart = 0
let touching = 0

/**
 * Counts an impulse of pair (a, b) closed inelastically though restitution is above 0 (F.inelastic), and, when
 * it was past the pair's restitution visits (`visited`), this try's. One closed for a light ball past
 * MAX_TICK_CONTACTS is not the try's: that count runs over the contact tick of the clock, which a finer
 * spacing does not shorten.
 */
export function closedPastVisits(F: FixedContactState, a: number, b: number, visited: boolean): void {
  F.inelastic++
  if (!visited) return
  const dx = F.x[b]! - F.x[a]!
  const dy = F.y[b]! - F.y[a]!
  const reach = (F.r[a]! + F.r[b]!) * (1 + APART_SHARE)
  if (dx * dx + dy * dy > reach * reach) apart++
  else touching++
}

/** Begins a try of the tick: none of its impulses closed past their visits yet. */
export function beginTry(): void {
  apart = 0
  touching = 0
}

/**
 * Whether the try, on a tick of at most SMALL_TICK_PAIRS pairs, closed pairs inelastically past their
 * restitution visits, all of them apart at the tick: a finer spacing would keep their restitution. Pairs,
 * not candidates: both broadphases find the same pairs, and the dense one packs more candidates.
 */
export function elasticFiner(F: FixedContactState): boolean {
  return apart > 0 && touching === 0 && F.pairCount <= SMALL_TICK_PAIRS
}

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
