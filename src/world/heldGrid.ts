// The held grid (ball-ball contacts 'on' or 'fixed'): the balls waiting at their spots in the launcher's
// queue (mode 'held'), hashed by the cell of their spot (src/world/ballHash.ts), for the check of a ball put
// down (src/contacts/spot.ts, heldOn: a ball put down where one waits queues behind it). Built when a spot is
// first checked at a world time (O(held)); a ball held at that same time is linked in as it joins the queue,
// so putting down n balls at once costs O(n + held), not O(n · held) (a scan of the queue per ball took
// 2.3 s for 40,000 balls, half of them held at spots of their own). Held balls do not move; one that has
// left the queue since (launched, removed) stays linked until the next build and is passed over by mode.
import { BallMode } from '../../components/Ball.js'
import type { CollisionState } from './contactState.js'
import type { BallWorld } from './createWorld.js'
import { restingState } from './restingGrid.js'
import { beginBuild, joinBall, linkBall } from './ballHash.js'

/** Builds the held grid from the launcher's queue at the world's time. */
export function buildHeldGrid(w: BallWorld, C: CollisionState): void {
  const H = C.held
  beginBuild(w, H, w.held.count)
  const q = w.held
  const B = w.Ball
  for (let i = 0; i < q.count; i++) {
    const eid = q.ids[i]!
    if (B.live[eid] !== 1 || B.mode[eid] !== BallMode.Held) continue
    if (H.linkedIn[eid] === H.gen) continue // listed twice: linked once
    linkBall(w, H, C.cell, eid)
  }
}

/** A ball that has just been held at its spot: linked into the held grid if the grid is of this time. */
export function heldJoin(w: BallWorld, eid: number): void {
  const C = restingState(w)
  if (C !== null) joinBall(w, C.held, C.cell, eid)
}
