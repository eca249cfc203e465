// A hash of balls by the cell of their centre at one world time, for the checks of a ball put down
// (src/contacts/spot.ts): the spot grid (the moving balls, src/world/spotGrid.ts) and the held grid (the
// balls waiting at their spots, src/world/heldGrid.ts). Built when a spot is first checked at a world time
// (O(balls)) and kept while balls are put down at that time, each ball that joins then linked in, so putting
// down n balls at once costs O(n + balls), not O(n · balls). A ball linked twice in one build (a reused id)
// makes the next check rebuild: a chain must not be linked into twice.
import type { BallWorld } from './createWorld.js'

/** Hash bucket of grid cell (ix, iy) in a table of mask + 1 buckets (this hash, the resting grid, the capsule hash). */
export function bucketOf(ix: number, iy: number, mask: number): number {
  return (Math.imul(ix, 73856093) ^ Math.imul(iy, 19349663)) & mask
}

export interface BallHash {
  /** bucket heads, by ball id (0: end of a chain); a power of two, at least twice the balls linked */
  head: Uint32Array
  /** the next ball in each ball's chain */
  next: Uint32Array
  /** the build each ball was last linked in */
  linkedIn: Uint32Array
  /** builds so far */
  gen: number
  /** balls linked since the build */
  linked: number
  /** the world time it was built at, and whether it is built */
  time: number
  built: boolean
  /** the largest radius among the balls linked */
  maxR: number
}

export function createBallHash(capacity: number, buckets: number): BallHash {
  return { head: new Uint32Array(buckets), next: new Uint32Array(capacity), linkedIn: new Uint32Array(capacity), gen: 0, linked: 0, time: 0, built: false, maxR: 0 }
}

/** Whether H is built, at the world's time. */
export function hashCurrent(w: BallWorld, H: BallHash): boolean {
  return H.built && H.time === w.time
}

/** Starts a build at the world's time, with room for `count` balls (then link each). */
export function beginBuild(w: BallWorld, H: BallHash, count: number): void {
  let size = H.head.length
  while (size < 2 * count) size *= 2
  if (size !== H.head.length) H.head = new Uint32Array(size)
  else H.head.fill(0)
  H.time = w.time
  H.maxR = 0
  H.built = true
  H.gen++
  H.linked = 0
}

/** Links ball eid by the cell (`cell` px wide) of its centre. */
export function linkBall(w: BallWorld, H: BallHash, cell: number, eid: number): void {
  const B = w.Ball
  const bucket = bucketOf(Math.floor(B.x[eid]! / cell), Math.floor(B.y[eid]! / cell), H.head.length - 1)
  H.next[eid] = H.head[bucket]!
  H.head[bucket] = eid
  H.linkedIn[eid] = H.gen
  H.linked++
  if (B.radius[eid]! > H.maxR) H.maxR = B.radius[eid]!
}

/** A ball that joins at the world's time: linked if H is of this time (a reused id, or a full table: rebuilt at the next check). */
export function joinBall(w: BallWorld, H: BallHash, cell: number, eid: number): void {
  if (!hashCurrent(w, H)) return
  if (H.linkedIn[eid] === H.gen || 2 * (H.linked + 1) > H.head.length) {
    H.built = false
    return
  }
  linkBall(w, H, cell, eid)
}
