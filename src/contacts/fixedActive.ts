// The fixed-tick method's count of the balls that take part in a tick, and their smallest radius, the same
// whichever broadphase found the pairs (config.BALL_COLLISIONS = 'fixed'). The tick's bounds that scale
// with its balls (pairs a ball, rounds a ball, the small-tick redo: systems/fixedContacts.ts) read them.
// The sweep (src/contacts/fixedOrder.ts) packs only the balls of its pairs, those near a closed wall and the
// big ones, and those the rounds join, so there they are the packed candidates (F.n). The dense broadphase
// (src/contacts/fixedDense.ts) packs every candidate, those that touch nothing too, so there the same balls
// are marked: those of the pairs found (before the halving drops some, as the sweep has packed them by
// then), near a closed wall or big, then, as the rounds go, those of every pair added. Counting the dense
// broadphase's candidates instead parted the two broadphases (4 of 40 scenes of a struck pile with balls
// moving alone elsewhere): a bound on pairs a ball or the smallest radius read other balls.
// Work: O(pairs) per try of a dense tick that asks or is halved, once per pair; on a sweep tick, each packed
// candidate's radius read once when the smallest is asked; nothing otherwise.
import type { FixedContactState } from '../world/fixedState.js'
import { packings } from './fixedOrder.js'

/** By dense candidate index: the try's stamp when it takes part */
let mark = new Uint32Array(256)
let stamp = 0
let count = 0
/** pairs marked so far; whether the near-wall and big lists are marked (both lazily, when first asked) */
let upTo = 0
let based = false
/** smallest radius of the balls marked (dense) or read (sweep), in a slot (a module-level double would box at each write) */
const least = new Float64Array(1)
/** sweep ticks: packed candidates read so far, numbered as at renumbering leastPacking */
let leastUpTo = 0
let leastPacking = -1

function take(F: FixedContactState, i: number): void {
  if (mark[i] === stamp) return
  mark[i] = stamp
  count++
  if (F.r[i]! < least[0]!) least[0] = F.r[i]!
}

/**
 * A try's pairs are found. A dense try's balls in pairs, near a closed wall and big are marked when first
 * asked (most ticks never ask), or before the halving drops pairs (keepActive): the sweep has packed them
 * all by then.
 */
export function beginActive(F: FixedContactState): void {
  least[0] = 1 / 0
  leastUpTo = 0
  if (F.dense !== 1) return
  if (++stamp === 0xffffffff) {
    mark.fill(0)
    stamp = 1
  }
  count = 0
  upTo = 0
  based = false
}

/** The halving is about to drop pairs: a dense try's balls are marked first. */
export function keepActive(F: FixedContactState): void {
  if (F.dense === 1) sync(F)
}

/** The halving is done: the pairs it kept are marked; those added later are new. */
export function halvedActive(F: FixedContactState): void {
  if (F.dense === 1) upTo = F.pairCount
}

/** Marks the balls of the lists and of the pairs added since the last call (dense ticks). */
function sync(F: FixedContactState): void {
  if (mark.length < F.n) {
    const next = new Uint32Array(2 * F.n)
    next.set(mark)
    mark = next
  }
  if (!based) {
    // the lists only grow by balls the rounds widened, which are in pairs
    for (let k = 0; k < F.nearWallCount; k++) take(F, F.nearWall[k]!)
    for (let k = 0; k < F.bigCount; k++) take(F, F.big[k]!)
    based = true
  }
  for (let p = upTo; p < F.pairCount; p++) {
    take(F, F.pairA[p]!)
    take(F, F.pairB[p]!)
  }
  upTo = F.pairCount
}

/** The balls that take part in the tick so far: the same count in both broadphases. */
export function activeCount(F: FixedContactState): number {
  if (F.dense !== 1) return F.n
  sync(F)
  return count
}

/** The smallest radius among the balls that take part so far. */
export function activeLeastRadius(F: FixedContactState): number {
  if (F.dense === 1) {
    sync(F)
    return least[0]!
  }
  // a sweep tick's are its packed candidates, which only join within a tick, last unless renumbered
  if (leastPacking !== packings()) {
    leastPacking = packings()
    leastUpTo = 0
  }
  for (; leastUpTo < F.n; leastUpTo++) if (F.r[leastUpTo]! < least[0]!) least[0] = F.r[leastUpTo]!
  return least[0]!
}
