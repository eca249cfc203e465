// A ball's straight path and its next event's time and distance, interleaved: one 64-byte row a ball id
// (world.pathHot): origin x0, y0, unit direction ux, uy, speed at the origin v0 (px/s), time at the origin
// t0 (s), then the next event's time nextT and distance nextS along the path. The integration system reads
// these for every moving ball in every step; as eight Path arrays they fell out of the caches with
// 100,000 balls, and an event read a dozen cache lines. The Path store (components/Path.ts) keeps the
// rest of the path's state. Read a field as world.pathHot[eid * HOT + H_X0], and so on.
import type { BallWorld } from './createWorld.js'

/** doubles a row */
export const HOT = 8
export const H_X0 = 0
export const H_Y0 = 1
export const H_UX = 2
export const H_UY = 3
export const H_V0 = 4
export const H_T0 = 5
export const H_NEXT_T = 6
export const H_NEXT_S = 7

/** Sets the time of a ball's next event. */
export function setNextT(w: BallWorld, eid: number, t: number): void {
  w.pathHot[eid * HOT + H_NEXT_T] = t
}

/** The time of a ball's next event. */
export function hotNextT(w: BallWorld, eid: number): number {
  return w.pathHot[eid * HOT + H_NEXT_T]!
}

/** Zeroes a ball's row (with the Ball and Path rows: clearBallRows in balls.ts). */
export function clearPathHot(w: BallWorld, eid: number): void {
  const H = w.pathHot
  const h = eid * HOT
  for (let k = 0; k < HOT; k++) H[h + k] = 0
}

/** A row for every id below `capacity`, the old rows kept. */
export function growPathHot(w: BallWorld, capacity: number): void {
  if (w.pathHot.length >= capacity * HOT) return
  const next = new Float64Array(capacity * HOT)
  next.set(w.pathHot)
  w.pathHot = next
}
