// Fixed-tick contacts: where a widening round (src/contacts/fixedReach.ts, pairNear and pairJoined;
// src/contacts/fixedCut.ts, cutCapsule) finds two kinds of candidate without walking them all each round.
// A push running along a row of thousands of balls makes a round a ball, and each round added a ball of
// each kind, so those walks made the push cost the square of the row:
//   - the resting balls the rounds added (candidates F.gathered up to F.n) that have no capsule: a list
//     kept in index order, from which those that got a capsule are dropped (a capsule is kept to the
//     tick's end);
//   - the candidates with a capsule (src/contacts/fixedCapsule.ts): entered at the end of each round that
//     widened them, by the box that holds what they cover (their capsule as cut, their reach), in the cells
//     of a hash of side NEAR_CELLS times the tick's ordering cell (a box over NEAR_MAX_CELLS cells: in a
//     list walked by every lookup); a lookup gives those entered in the cells of its box, those in that
//     list and those the round widened (their boxes may have changed), each once. Only a widening changes
//     a candidate's box within a tick (its reach, its capsule's cut or length), and positions do not
//     change until the projection after the rounds.
// Both are rebuilt when the candidates are renumbered (src/contacts/fixedOrder.ts, packings). What is found
// is tested as before, and the callers' results do not depend on the order they find it in (pairNear's
// partners are sorted by id; pairJoined keeps the index order; the cut takes the nearest).
import type { FixedContactState } from '../world/fixedState.js'
import { grownTo } from '../world/fixedState.js'
import { TOUCH_GAP } from '../config/tolerances.js'
import { bounds, hasCapsule, holderList, holdersNow, holderBox, nearBox } from './fixedCapsule.js'
import { packings } from './fixedOrder.js'

const NEAR_CELLS = 2
const NEAR_MAX_CELLS = 16
/** A lookup box over this many cells: the caller walks every candidate with a capsule instead. */
const NEAR_MAX_QUERY = 64

/** For tests: whether the lists and the hash are used (off: every round walks them all, as before). */
let using = true
export function useNearLists(on: boolean): void {
  using = on
}

let packing = -1
let joined = new Int32Array(64)
let joinedCount = 0
let joinedUpTo = 0

/** A new contact tick (after its gather): nothing listed yet. */
export function beginNear(F: FixedContactState): void {
  nearSize[0] = NEAR_CELLS * Math.max(F.gridCell, F.cell, TOUCH_GAP)
  clear(F)
}

/** Empties the list and the hash (numbered as the candidates are now). */
function clear(F: FixedContactState): void {
  packing = packings()
  joinedCount = 0
  joinedUpTo = F.gathered
  entryCount = 0
  longCount = 0
  bucketsFor++
  enteredHolders = 0
}

function renumbered(F: FixedContactState): void {
  if (packing === packings()) return
  clear(F)
  // the holders entered before, by their boxes now
  const list = holderList()
  for (let h = 0, n = holdersNow(); h < n; h++) enter(F, list[h]!)
}

/**
 * The resting balls the rounds added, below `upTo`, without a capsule, in index order, into joinedList()
 * (their count; with the lists off, every one of F.gathered to upTo).
 */
export function joinedFree(F: FixedContactState, upTo: number): number {
  if (!using) {
    let n = 0
    for (let j = F.gathered; j < upTo; j++) {
      if (n === joined.length) joined = grownTo(joined, 2 * n)
      joined[n++] = j
    }
    return n
  }
  renumbered(F)
  let n = 0
  for (let k = 0; k < joinedCount; k++) {
    const j = joined[k]!
    if (!hasCapsule(j)) joined[n++] = j
  }
  for (let j = Math.max(joinedUpTo, F.gathered); j < upTo; j++) {
    if (hasCapsule(j)) continue
    if (n === joined.length) joined = grownTo(joined, 2 * n)
    joined[n++] = j
  }
  if (upTo > joinedUpTo) joinedUpTo = upTo
  joinedCount = n
  // those at or past upTo (none while upTo only grows) are not the caller's
  let m = n
  while (m > 0 && joined[m - 1]! >= upTo) m--
  return m
}

export function joinedList(): Int32Array {
  return joined
}

// The hash of the candidates with a capsule: buckets by cell (bucketHead, stamped by tick with bucketAt),
// entries chained (entryNext) with their candidate; boxes too wide for it in `long`.
/** the hash's cell size (a slot: V8 boxes a double held in a module-level `let` at every write) */
const nearSize = new Float64Array([1])
let buckets = 1024
let bucketHead = new Int32Array(1024)
let bucketAt = new Float64Array(1024)
let bucketsFor = 1
let entryOf = new Int32Array(256)
let entryNext = new Int32Array(256)
let entryCount = 0
let long = new Int32Array(64)
let longCount = 0
/** the bucket stamp at which each candidate went into `long` */
let longAt = new Float64Array(256)
let enteredHolders = 0

/** Enters the candidates with a capsule the round widened (its end: their boxes as they are now), and those made since. */
export function enterWidened(F: FixedContactState): void {
  if (!using) return
  renumbered(F)
  for (let k = 0; k < F.widenedCount; k++) {
    const g = F.widened[k]!
    if (hasCapsule(g)) enter(F, g)
  }
  enteredHolders = holdersNow()
}

function enter(F: FixedContactState, j: number): void {
  if (2 * (entryCount + NEAR_MAX_CELLS) > buckets) rehash(F, entryCount + NEAR_MAX_CELLS)
  place(F, j)
}

/** Candidate j by its box now: in the cells it spans, or in `long` (once a tick) if they are too many. */
function place(F: FixedContactState, j: number): void {
  holderBox(F, j)
  const size = nearSize[0]!
  const x0 = Math.floor(nearBox[0]! / size)
  const x1 = Math.floor(nearBox[1]! / size)
  const y0 = Math.floor(nearBox[2]! / size)
  const y1 = Math.floor(nearBox[3]! / size)
  if ((x1 - x0 + 1) * (y1 - y0 + 1) <= NEAR_MAX_CELLS) {
    for (let cy = y0; cy <= y1; cy++) for (let cx = x0; cx <= x1; cx++) link(j, bucketOf(cx, cy))
    return
  }
  if (longAt.length < F.n) longAt = grownTo(longAt, 2 * F.n)
  if (longAt[j] === bucketsFor) return
  longAt[j] = bucketsFor
  if (longCount === long.length) long = grownTo(long, 2 * longCount)
  long[longCount++] = j
}

function link(j: number, b: number): void {
  if (entryCount === entryOf.length) {
    entryOf = grownTo(entryOf, 2 * entryCount)
    entryNext = grownTo(entryNext, 2 * entryCount)
  }
  const e = entryCount++
  entryOf[e] = j
  if (bucketAt[b] !== bucketsFor) {
    bucketAt[b] = bucketsFor
    bucketHead[b] = -1
  }
  entryNext[e] = bucketHead[b]!
  bucketHead[b] = e
}

/** More buckets (at least four times `entries`), every candidate with a capsule entered again by its box now. */
function rehash(F: FixedContactState, entries: number): void {
  while (buckets < 4 * entries) buckets *= 2
  bucketHead = new Int32Array(buckets)
  bucketAt = new Float64Array(buckets)
  bucketsFor++
  entryCount = 0
  longCount = 0
  const list = holderList()
  for (let h = 0, n = holdersNow(); h < n; h++) place(F, list[h]!)
}

function bucketOf(cx: number, cy: number): number {
  // cells as 32-bit integers (a box past ±2^31 cells: the same bucket as some other, looked at and tested)
  return (Math.imul(cx | 0, 73856093) ^ Math.imul(cy | 0, 19349663)) & (buckets - 1)
}

let found = new Int32Array(64)
let seenAt = new Float64Array(256)
let seenFor = 0

/**
 * The candidates with a capsule that may meet the box in bounds (src/contacts/fixedCapsule.ts, set by the
 * caller: what a widened candidate covers; read there, not passed, as V8 boxes a double passed to a call it
 * does not inline), each once, into foundList(); their count, or -1 when the box spans too many cells
 * (walk every one).
 */
export function holdersIn(F: FixedContactState): number {
  if (!using) return -1
  const size = nearSize[0]!
  const cx0 = Math.floor(bounds[0]! / size)
  const cx1 = Math.floor(bounds[1]! / size)
  const cy0 = Math.floor(bounds[2]! / size)
  const cy1 = Math.floor(bounds[3]! / size)
  if (!((cx1 - cx0 + 1) * (cy1 - cy0 + 1) <= NEAR_MAX_QUERY)) return -1
  if (seenAt.length < F.n) seenAt = grownTo(seenAt, 2 * F.n)
  seenFor++
  let n = 0
  for (let cy = cy0; cy <= cy1; cy++) {
    for (let cx = cx0; cx <= cx1; cx++) {
      const b = bucketOf(cx, cy)
      if (bucketAt[b] !== bucketsFor) continue
      for (let e = bucketHead[b]!; e >= 0; e = entryNext[e]!) n = add(entryOf[e]!, n)
    }
  }
  for (let k = 0; k < longCount; k++) n = add(long[k]!, n)
  // those made or changed since the last round's end
  const list = holderList()
  for (let h = enteredHolders, count = holdersNow(); h < count; h++) n = add(list[h]!, n)
  for (let k = 0; k < F.widenedCount; k++) {
    const g = F.widened[k]!
    if (hasCapsule(g)) n = add(g, n)
  }
  return n
}

function add(j: number, n: number): number {
  if (seenAt[j] === seenFor) return n
  seenAt[j] = seenFor
  if (n === found.length) found = grownTo(found, 2 * n)
  found[n] = j
  return n + 1
}

export function foundList(): Int32Array {
  return found
}

/**
 * Whether widened candidate g and candidate j, within each other's reach before this widening, were paired
 * then (src/contacts/fixedReach.ts pairs only those its new reach meets and its old one did not). Not when
 * both are at rest, never widened, and one of them joined in a round: addResting pairs a joining ball with
 * the balls widened that round only (two balls at rest cannot meet until one is struck). A ball struck in a
 * row of touching balls that joined one by one was then not paired with the next ball, and the push went
 * on to the one after, through it.
 */
export function pairedBefore(F: FixedContactState, g: number, j: number): boolean {
  return !(restingReach(F, g) && restingReach(F, j) && (g >= F.gathered || j >= F.gathered))
}

/**
 * pairedBefore for widened candidate g and a ball of the sweep's order not packed as a candidate (gathered,
 * with reach `reach` and radius `radius`): it touched nothing at the gather, so only a g that joined in a
 * round, at rest, can have had it within reach unpaired.
 */
export function pairedBeforeUnpacked(F: FixedContactState, g: number, reach: number, radius: number): boolean {
  return !(restingReach(F, g) && g >= F.gathered && reach === radius + TOUCH_GAP)
}

/** Whether candidate i has the reach of a ball at rest (never widened this tick). */
export function restingReach(F: FixedContactState, i: number): boolean {
  return F.reach[i] === F.r[i]! + TOUCH_GAP
}
