// The held grid (ball-ball contacts 'on' or 'fixed'): the balls waiting at their spots in the launcher's
// queue (mode 'held'), hashed by the cell of their spot, for the check of a ball put down
// (src/contacts/spot.ts, heldOn: a ball put down where one waits queues behind it). Built when a spot is
// first checked at a world time (O(held)); a ball held at that same time is linked in as it joins the queue,
// so putting down n balls at once costs O(n + held), not O(n · held) (a scan of the queue per ball took
// 2.3 s for 40,000 balls, half of them held at spots of their own). Held balls do not move; one that has
// left the queue since (launched, removed) stays linked until the next build and is passed over by mode.
// A ball linked twice in one build (a reused id) makes the next check rebuild, as in src/world/spotGrid.ts.
import { BallMode } from '../../components/Ball.js'
import type { CollisionState } from './contactState.js'
import type { BallWorld } from './createWorld.js'
import { bucketOf, restingState } from './restingGrid.js'

/** Builds the held grid from the launcher's queue at the world's time. */
export function buildHeldGrid(w: BallWorld, C: CollisionState): void {
  let size = C.heldHead.length
  while (size < 2 * w.held.count) size *= 2
  if (size !== C.heldHead.length) C.heldHead = new Uint32Array(size)
  else C.heldHead.fill(0)
  C.heldTime = w.time
  C.heldMaxR = 0
  C.heldBuilt = true
  C.heldGen++
  C.heldLinked = 0
  const q = w.held
  const B = w.Ball
  for (let i = 0; i < q.count; i++) {
    const eid = q.ids[i]!
    if (B.live[eid] !== 1 || B.mode[eid] !== BallMode.Held) continue
    if (C.heldIn[eid] === C.heldGen) continue // listed twice: linked once
    link(w, C, eid)
  }
}

function link(w: BallWorld, C: CollisionState, eid: number): void {
  const B = w.Ball
  const bucket = bucketOf(Math.floor(B.x[eid]! / C.cell), Math.floor(B.y[eid]! / C.cell), C.heldHead.length - 1)
  C.heldNext[eid] = C.heldHead[bucket]!
  C.heldHead[bucket] = eid
  C.heldIn[eid] = C.heldGen
  C.heldLinked++
  if (B.radius[eid]! > C.heldMaxR) C.heldMaxR = B.radius[eid]!
}

/** A ball that has just been held at its spot: linked into the held grid if the grid is of this time. */
export function heldJoin(w: BallWorld, eid: number): void {
  const C = restingState(w)
  if (C === null || !C.heldBuilt || C.heldTime !== w.time) return
  // a reused id, or a table that has grown too full: the next check rebuilds
  if (C.heldIn[eid] === C.heldGen || 2 * (C.heldLinked + 1) > C.heldHead.length) {
    C.heldBuilt = false
    return
  }
  link(w, C, eid)
}
