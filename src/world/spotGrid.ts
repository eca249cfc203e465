// The spot grid (ball-ball contacts 'on' or 'fixed'): the moving balls hashed by the cell of their centre at
// a world time (src/world/ballHash.ts), for the check of a ball put down (src/contacts/spot.ts). Built when a
// spot is first checked at a world time (O(moving)); every ball that starts moving at that same time is
// linked in as it joins the moving set (idLists.addMoving), so a ball put down, released by the launcher or
// given a velocity by a command is found by the next check.
import type { CollisionState } from './contactState.js'
import type { BallWorld } from './createWorld.js'
import { restingState } from './restingGrid.js'
import { beginBuild, joinBall, linkBall } from './ballHash.js'

/** Builds the spot grid from the moving set at the world's time. */
export function buildSpotGrid(w: BallWorld, C: CollisionState): void {
  const H = C.spot
  beginBuild(w, H, w.moving.count)
  const balls = w.moving.dense
  for (let i = 0, n = w.moving.count; i < n; i++) linkBall(w, H, C.cell, balls[i]!)
}

/** A ball that has just joined the moving set: linked into the spot grid if the grid is of this time. */
export function spotJoin(w: BallWorld, eid: number): void {
  const C = restingState(w)
  if (C !== null) joinBall(w, C.spot, C.cell, eid)
}
