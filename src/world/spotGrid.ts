// The spot grid (ball-ball contacts 'on' or 'fixed'): the moving balls hashed by the cell of their centre at
// the world's time `spotTime`, for the check of a ball put down (src/contacts/spot.ts). Built when a spot is
// first checked at a world time (O(moving)); every ball that starts moving at that same time is linked in
// as it joins the moving set (idLists.addMoving), so a ball put down, released by the launcher or given a
// velocity by a command is found by the next check. A ball linked twice in one build (a reused id) makes the
// next check rebuild (a chain must not be linked into twice).
import type { CollisionState } from './contactState.js'
import type { BallWorld } from './createWorld.js'
import { bucketOf, restingState } from './restingGrid.js'

/** Builds the spot grid from the moving set at the world's time. */
export function buildSpotGrid(w: BallWorld, C: CollisionState): void {
  let size = C.spotHead.length
  while (size < 2 * w.moving.count) size *= 2
  if (size !== C.spotHead.length) C.spotHead = new Uint32Array(size)
  else C.spotHead.fill(0)
  C.spotTime = w.time
  C.spotMaxR = 0
  C.spotBuilt = true
  C.spotGen++
  const balls = w.moving.dense
  for (let i = 0, n = w.moving.count; i < n; i++) link(w, C, balls[i]!)
}

function link(w: BallWorld, C: CollisionState, eid: number): void {
  const B = w.Ball
  const bucket = bucketOf(Math.floor(B.x[eid]! / C.cell), Math.floor(B.y[eid]! / C.cell), C.spotHead.length - 1)
  C.spotNext[eid] = C.spotHead[bucket]!
  C.spotHead[bucket] = eid
  C.spotIn[eid] = C.spotGen
  if (B.radius[eid]! > C.spotMaxR) C.spotMaxR = B.radius[eid]!
}

/** A ball that has just joined the moving set: linked into the spot grid if the grid is of this time. */
export function spotJoin(w: BallWorld, eid: number): void {
  const C = restingState(w)
  if (C === null || !C.spotBuilt || C.spotTime !== w.time) return
  // a reused id, or a table that has grown too full: the next check rebuilds
  if (C.spotIn[eid] === C.spotGen || 2 * w.moving.count > C.spotHead.length) {
    C.spotBuilt = false
    return
  }
  link(w, C, eid)
}
