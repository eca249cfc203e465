// The resting grid (ball-ball contacts 'on' or 'fixed'): resting balls hashed by the grid cell of their centre, kept
// across steps and updated when a ball comes to rest or wakes, so resting balls cost nothing until struck.
import { bucketOf } from './ballHash.js'
import { MAX_RESTING_CELLS } from '../config/tolerances.js'
import { BESIDE_GRID, RADIUS_CLASSES, appendId, type CollisionState } from './contactState.js'
import type { BallWorld } from './createWorld.js'
import { pow } from '../math.js'

/** Radius classes: class k holds radii up to 2^((k − CLASS_OFFSET)/4) px. */
const CLASS_OFFSET = 48

/** The largest radius each class holds, px (portable pow: the same classes on every engine). */
const CLASS_BOUNDS = Float64Array.from({ length: RADIUS_CLASSES }, (_, k) => pow(2, (k - CLASS_OFFSET) / 4))

function classBound(k: number): number {
  return CLASS_BOUNDS[k]!
}

/**
 * The class of radius r: the smallest whose bound is at least r (the last class for any larger), by a binary
 * search of the bounds. Comparisons only: a logarithm here (a call V8 does not inline, its double boxed)
 * allocated each time a ball came to rest, about 60 bytes a ball-step in a pile pressed by a stream.
 */
function radiusClass(r: number): number {
  let lo = 0
  let hi = RADIUS_CLASSES - 1
  while (lo < hi) {
    const mid = (lo + hi) >> 1
    if (CLASS_BOUNDS[mid]! >= r) hi = mid
    else lo = mid + 1
  }
  return lo
}

function countIn(C: CollisionState, eid: number, r: number): void {
  const k = radiusClass(r)
  C.restClass[eid] = k
  C.restClassCount[k]!++
  if (k > C.restTopClass) {
    C.restTopClass = k
    C.maxRadius = classBound(k)
  }
}

function countOut(C: CollisionState, eid: number): void {
  const k = C.restClass[eid]!
  C.restClassCount[k]!--
  if (k !== C.restTopClass || C.restClassCount[k] !== 0) return
  let top = k - 1
  while (top >= 0 && C.restClassCount[top] === 0) top--
  C.restTopClass = top
  C.maxRadius = top >= 0 ? classBound(top) : 0
}


/** The world's resting grid: the exact method's, or the fixed-tick method's; null with contacts off. */
export function restingState(w: BallWorld): CollisionState | null {
  return w.collide ?? (w.fixed === null ? null : w.fixed.rest)
}

/** Puts a resting ball into the resting grid (no-op if it is there). */
export function restingInsert(w: BallWorld, eid: number): void {
  const C = restingState(w)
  if (C === null || C.restBucket[eid] !== -1) return
  if (w.Ball.radius[eid]! > MAX_RESTING_CELLS * C.cell) {
    // too wide for the grid: it would widen every lookup; kept beside it and paired with directly
    C.bigRest = appendId(C.bigRest, C.bigRestCount++, eid)
    C.restBucket[eid] = BESIDE_GRID
    return
  }
  if (C.restCount + 1 > 2 * C.restHead.length) rehashResting(w, C.restHead.length * 4)
  countIn(C, eid, w.Ball.radius[eid]!)
  const mask = C.restHead.length - 1
  const bucket = bucketOf(Math.floor(w.Ball.x[eid]! / C.cell), Math.floor(w.Ball.y[eid]! / C.cell), mask)
  const head = C.restHead[bucket]!
  C.restBucket[eid] = bucket
  C.restPrev[eid] = 0
  C.restNext[eid] = head
  if (head !== 0) C.restPrev[head] = eid
  C.restHead[bucket] = eid
  C.restCount++
}

/** Takes a ball out of the resting grid (no-op if it is not there). */
export function restingRemove(w: BallWorld, eid: number): void {
  const C = restingState(w)
  if (C === null) return
  const bucket = C.restBucket[eid]!
  if (bucket === BESIDE_GRID) {
    let n = 0
    for (let i = 0; i < C.bigRestCount; i++) if (C.bigRest[i] !== eid) C.bigRest[n++] = C.bigRest[i]!
    C.bigRestCount = n
    C.restBucket[eid] = -1
    return
  }
  if (bucket < 0) return
  const prev = C.restPrev[eid]!
  const next = C.restNext[eid]!
  if (prev !== 0) C.restNext[prev] = next
  else C.restHead[bucket] = next
  if (next !== 0) C.restPrev[next] = prev
  countOut(C, eid)
  C.restBucket[eid] = -1
  C.restNext[eid] = 0
  C.restPrev[eid] = 0
  C.restCount--
}

function rehashResting(w: BallWorld, buckets: number): void {
  const C = restingState(w)!
  const old = C.restHead
  C.restHead = new Uint32Array(buckets)
  const count = C.restCount
  C.restCount = 0
  // collect the chains first (they are relinked as they are walked)
  const ids = new Uint32Array(count)
  let k = 0
  for (let b = 0; b < old.length; b++) {
    for (let e = old[b]!; e !== 0; e = C.restNext[e]!) ids[k++] = e
  }
  for (let i = 0; i < k; i++) C.restBucket[ids[i]!] = -1
  // the same balls go back in: their radius classes are counted again
  C.restClassCount.fill(0)
  C.restTopClass = -1
  C.maxRadius = 0
  for (let i = 0; i < k; i++) restingInsert(w, ids[i]!)
}
