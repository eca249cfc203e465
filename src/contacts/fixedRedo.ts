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
// A small tick of like masses is solved again so too when its solve closed a pair that was apart at the
// tick's start inelastically past its restitution visits (finerForRestitution, below).
import { MAX_TICK_REDOS, PUMP_MASS_RATIO, RESTITUTION_REDO_GAP, RESTITUTION_REDO_TRIES, SMALL_TICK_BALLS } from '../config/tolerances.js'
import { activeCount } from './fixedActive.js'
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

/** a pair of this try closed inelastically past its restitution visits though apart at the tick's start */
let apartClosed = false
/** tries sent to be solved again for it, over the process's life (for tests and benchmarks; one at the finest spacing is not solved again) */
let restitutionRedone = 0

/** A try begins: no pair of it closed so yet. */
export function beginTry(): void {
  apartClosed = false
}

/**
 * The solve closed pair (a, b) inelastically past its restitution visits (src/contacts/fixedSolve.ts): noted
 * when the two were more than RESTITUTION_REDO_GAP apart at the tick's start (the solve writes velocities
 * only, so the packed positions are still the tick's start).
 */
export function noteClosedApart(F: FixedContactState, a: number, b: number): void {
  if (apartClosed) return
  const dx = F.x[b]! - F.x[a]!
  const dy = F.y[b]! - F.y[a]!
  const r = F.r[a]! + F.r[b]! + RESTITUTION_REDO_GAP
  if (dx * dx + dy * dy > r * r) apartClosed = true
}

/**
 * Whether a try (tries: the tries before it) is solved again at a finer spacing for its restitution: it closed
 * a pair that was apart inelastically, and it is a small tick whose pairs' masses are within PUMP_MASS_RATIO
 * (src/config/tolerances.ts, RESTITUTION_REDO_GAP). The pairs are the same in both broadphases, and so are
 * their balls' masses and the count of the balls taking part.
 */
export function finerForRestitution(F: FixedContactState, tries: number): boolean {
  if (!apartClosed || tries >= RESTITUTION_REDO_TRIES || activeCount(F) > SMALL_TICK_BALLS) return false
  let lo = 1 / 0
  let hi = 0
  for (let p = 0; p < F.pairCount; p++) {
    const a = F.im[F.pairA[p]!]!
    const b = F.im[F.pairB[p]!]!
    lo = Math.min(lo, a, b)
    hi = Math.max(hi, a, b)
  }
  if (!(hi < PUMP_MASS_RATIO * lo)) return false
  restitutionRedone++
  return true
}

/** Tries sent to be solved again for their restitution (finerForRestitution), since the process started. */
export function ticksRedoneForRestitution(): number {
  return restitutionRedone
}
