// The path's hot fields, interleaved: one 64-byte row a ball id (world.pathHot), a copy of what the
// integration system reads for every moving ball in every step (Path.x0, y0, ux, uy, v0, t0, nextT, and
// whether the ball rolls: Ball.mode). Its pass over the moving balls then reads one row a ball instead of
// eight arrays; with 100,000 balls the arrays fell out of the caches. The Path store stays the record
// (games and tests read it); every write of these fields goes through here, so the copy never differs.
// Not in a snapshot: restoreWorld rebuilds it from the Path store (rebuildPathHot).
import { BallMode } from '../../components/Ball.js'
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
/** 0 while the ball rolls (Ball.mode rolling), else 1 (on a rim, or not moving) */
export const H_RIM = 7

/** Sets a path's origin, direction, speed and start time, in the Path store and the row. */
export function setPathStart(w: BallWorld, eid: number, x: number, y: number, ux: number, uy: number, v0: number, t0: number): void {
  const P = w.Path
  P.x0[eid] = x
  P.y0[eid] = y
  P.t0[eid] = t0
  P.v0[eid] = v0
  P.ux[eid] = ux
  P.uy[eid] = uy
  const H = w.pathHot
  const h = eid * HOT
  H[h + H_X0] = x
  H[h + H_Y0] = y
  H[h + H_UX] = ux
  H[h + H_UY] = uy
  H[h + H_V0] = v0
  H[h + H_T0] = t0
}

/** Sets the time of a ball's next event. */
export function setNextT(w: BallWorld, eid: number, t: number): void {
  w.Path.nextT[eid] = t
  w.pathHot[eid * HOT + H_NEXT_T] = t
}

/** Sets a path's start time (a ball that waits out a step: src/motion/pause.ts). */
export function setPathT0(w: BallWorld, eid: number, t0: number): void {
  w.Path.t0[eid] = t0
  w.pathHot[eid * HOT + H_T0] = t0
}

/** Follows a change of Ball.mode (src/world/ballMode.ts). */
export function setHotMode(w: BallWorld, eid: number, mode: number): void {
  w.pathHot[eid * HOT + H_RIM] = mode === BallMode.Rolling ? 0 : 1
}

/** Zeroes a ball's row (with clearSlot of the Path store). */
export function clearPathHot(w: BallWorld, eid: number): void {
  w.pathHot.fill(0, eid * HOT, eid * HOT + HOT)
}

/** A row for every id below `capacity`, the old rows kept. */
export function growPathHot(w: BallWorld, capacity: number): void {
  if (w.pathHot.length >= capacity * HOT) return
  const next = new Float64Array(capacity * HOT)
  next.set(w.pathHot)
  w.pathHot = next
}

/** Writes every row from the Path store and Ball.mode (after a restore). */
export function rebuildPathHot(w: BallWorld): void {
  const P = w.Path
  const mode = w.Ball.mode
  const n = Math.min(P.x0.length, mode.length)
  if (w.pathHot.length < n * HOT) w.pathHot = new Float64Array(n * HOT)
  else w.pathHot.fill(0)
  const H = w.pathHot
  for (let eid = 0; eid < n; eid++) {
    const h = eid * HOT
    H[h + H_X0] = P.x0[eid]!
    H[h + H_Y0] = P.y0[eid]!
    H[h + H_UX] = P.ux[eid]!
    H[h + H_UY] = P.uy[eid]!
    H[h + H_V0] = P.v0[eid]!
    H[h + H_T0] = P.t0[eid]!
    H[h + H_NEXT_T] = P.nextT[eid]!
    H[h + H_RIM] = mode[eid] === BallMode.Rolling ? 0 : 1
  }
}
