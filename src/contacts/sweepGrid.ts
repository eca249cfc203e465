// The swept-capsule hash of a prediction window: each moving ball's capsule over the rest of the window,
// rasterised into a uniform grid of hash buckets, so a ball meets only the balls near its path.
import { BallMode } from '../../components/Ball.js'
import { grown, type CollisionState } from '../world/contactState.js'
import type { BallWorld } from '../world/createWorld.js'
import { cogRadius } from '../geometry.js'
import { bucketOf } from '../world/ballHash.js'
import { heapClear } from './eventHeap.js'
import { AT, E, MT, X, Y, evalBall, motionEnd } from './evalMotion.js'

/**
 * Fills C.cells with the buckets (of a table of mask + 1) of every grid cell that the capsule q may touch
 * (ends (q[X1], q[Y1]), (q[X2], q[Y2]), radius q[CR]): row by row, the segment's extent within the row's
 * band, widened by the radius. Returns the count. The capsule is read from an array, not passed as
 * arguments: V8 boxes each double passed to a function it does not inline.
 */
export function capsuleCells(C: CollisionState, q: Float64Array, mask: number): number {
  const x1 = q[X1]!
  const y1 = q[Y1]!
  const x2 = q[X2]!
  const y2 = q[Y2]!
  const rho = q[CR]!
  const c = C.cell
  const lo = Math.min(y1, y2) - rho
  const hi = Math.max(y1, y2) + rho
  const row0 = Math.floor(lo / c)
  const row1 = Math.floor(hi / c)
  const dy = y2 - y1
  let n = 0
  for (let row = row0; row <= row1; row++) {
    // the part of the segment whose y lies within rho of this row's band
    const bandLo = row * c - rho
    const bandHi = (row + 1) * c + rho
    let s0 = 0
    let s1 = 1
    if (dy !== 0) {
      let sa = (bandLo - y1) / dy
      let sb = (bandHi - y1) / dy
      if (sa > sb) {
        const tmp = sa
        sa = sb
        sb = tmp
      }
      if (sa > s0) s0 = sa
      if (sb < s1) s1 = sb
      if (s0 > s1) continue
    }
    const xa = x1 + (x2 - x1) * s0
    const xb = x1 + (x2 - x1) * s1
    const col0 = Math.floor((Math.min(xa, xb) - rho) / c)
    const col1 = Math.floor((Math.max(xa, xb) + rho) / c)
    for (let col = col0; col <= col1; col++) {
      if (n === C.cells.length) C.cells = grown(C.cells, n * 2)
      C.cells[n++] = bucketOf(col, row, mask)
    }
  }
  return n
}

/**
 * Starts a prediction window ending at `until`: empties the heap and the swept-capsule hash (sized for the
 * moving balls), and the list of changed paths (every moving ball is predicted now; resting ones are found
 * through the resting grid).
 */
export function beginWindow(w: BallWorld, until: number): void {
  const C = w.collide!
  C.until = until
  heapClear(C)
  C.entCount = 0
  C.entLive = 0
  C.bigCount = 0
  for (let i = 0; i < C.dirtyCount; i++) C.isDirty[C.dirty[i]!] = 0
  C.dirtyCount = 0
  let size = C.sweepHead.length
  while (size < 4 * w.moving.count) size *= 2
  if (size !== C.sweepHead.length) {
    C.sweepHead = new Int32Array(size)
    C.sweepStamp = new Uint32Array(size)
    C.stamp = 0
  }
  C.stamp++
  if (C.stamp === 0xffffffff) {
    C.sweepStamp.fill(0)
    C.entStep.fill(0)
    C.predicted.fill(0)
    C.stamp = 1
  }
}

/**
 * True when hash entry e belongs to an older capsule of its ball (skipped: the ball has a newer one), or to
 * a ball that has left the world since.
 */
export function staleEntry(C: CollisionState, e: number): boolean {
  const b = C.entBall[e]!
  return C.entStep[b] !== C.stamp || e < C.entStart[b]!
}

/**
 * Enters ball a's capsule (the n buckets in C.cells) into the hash as its latest; its older capsule's
 * entries become stale. When stale entries outnumber live ones (and a few thousand), the hash is
 * compacted: only the latest capsules are kept, in the same order, so walking a bucket costs what its
 * live entries cost, however many times the step's balls were predicted again.
 */
export function enterCapsule(C: CollisionState, a: number, n: number): void {
  if (C.entStep[a] === C.stamp) C.entLive -= C.entLen[a]!
  if (C.entCount + n > 2 * (C.entLive + n) + 4096) compact(C)
  if (C.entCount + n > C.entNext.length) {
    let len = C.entNext.length
    while (len < C.entCount + n) len *= 2
    C.entNext = grown(C.entNext, len)
    C.entBall = grown(C.entBall, len)
    C.entBucket = grown(C.entBucket, len)
  }
  C.entStep[a] = C.stamp
  C.entStart[a] = C.entCount
  C.entLen[a] = n
  C.entLive += n
  for (let k = 0; k < n; k++) link(C, C.entCount++, a, C.cells[k]!)
}

function link(C: CollisionState, e: number, ball: number, bucket: number): void {
  C.entBall[e] = ball
  C.entBucket[e] = bucket
  if (C.sweepStamp[bucket] !== C.stamp) {
    C.sweepStamp[bucket] = C.stamp
    C.entNext[e] = -1
  } else C.entNext[e] = C.sweepHead[bucket]!
  C.sweepHead[bucket] = e
}

/** Keeps only the latest capsules' entries, relinked in their order (a bucket walks as before, less the stale). */
function compact(C: CollisionState): void {
  const count = C.entCount
  // empty every bucket the entries use; then relink the live entries in ascending order
  for (let e = 0; e < count; e++) C.sweepStamp[C.entBucket[e]!] = C.stamp - 1
  let k = 0
  for (let e = 0; e < count; e++) {
    const b = C.entBall[e]!
    if (C.entStep[b] !== C.stamp || e < C.entStart[b]!) continue
    if (e === C.entStart[b]) C.entStart[b] = k
    link(C, k++, b, C.entBucket[e]!)
  }
  C.entCount = k
}

/** the capsule sweptCapsule writes: ends (X1, Y1), (X2, Y2) and radius CR */
export const cap = new Float64Array(5)
export const X1 = 0
export const Y1 = 1
export const X2 = 2
export const Y2 = 3
export const CR = 4
/** Into cap: the capsule a ball may sweep over the prediction window, from C.now to the end of its known motion (capped at C.until). */
export function sweptCapsule(w: BallWorld, eid: number): void {
  const r = w.Ball.radius[eid]!
  if (w.Ball.mode[eid] === BallMode.RimRoll) {
    // anywhere on the contact circle of its hole
    const slot = w.Ball.rim[eid]!
    const hole = w.RimContact.hole[slot]!
    cap[X1] = cap[X2] = w.Hole.x[hole]!
    cap[Y1] = cap[Y2] = w.Hole.y[hole]!
    // a tabulated ride reaches as far out as the farther of its two ends
    const RC = w.RimContact
    const far = RC.ride[slot] !== 0 ? Math.max(RC.rideFrom[slot]!, RC.rideTo[slot]!) : cogRadius(w.Hole.radius[hole]!, r)
    cap[CR] = far + r
    return
  }
  const C = w.collide!
  E[AT] = C.now
  evalBall(w, eid)
  cap[X1] = E[X]
  cap[Y1] = E[Y]
  motionEnd(w, eid)
  E[AT] = E[MT]
  evalBall(w, eid)
  cap[X2] = E[X]
  cap[Y2] = E[Y]
  cap[CR] = r
}

/**
 * Whether the capsule q (as capsuleCells reads it) covers more than `limit` grid cells, by an upper
 * estimate. A yes or no, not the estimate: a double returned by a call V8 does not inline is boxed.
 */
export function capsuleCellsOver(C: CollisionState, q: Float64Array, limit: number): boolean {
  const c = C.cell
  const dx = q[X2]! - q[X1]!
  const dy = q[Y2]! - q[Y1]!
  const across = (2 * q[CR]!) / c + 2
  return (Math.sqrt(dx * dx + dy * dy) / c + across) * across > limit
}

/** A capsule to look up (capsuleCells, capsuleCellsOver) that is not a ball's swept one: a point's disc. */
export const query = new Float64Array(5)

/** Sets query to the disc of radius rho about (x, y). */
export function pointQuery(x: number, y: number, rho: number): Float64Array {
  query[X1] = query[X2] = x
  query[Y1] = query[Y2] = y
  query[CR] = rho
  return query
}
