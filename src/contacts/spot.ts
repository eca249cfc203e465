// Is a spot on the panel free? A ball put down (ball-ball contacts 'on' or 'fixed') where another ball is would start
// inside it; such a ball is held until its spot is clear (systems/launcher.ts). Checked, through grids,
// against the moving balls near the spot (their stored state is at the world's time between steps) and
// the resting balls near it.
import { BallMode } from '../../components/Ball.js'
import type { CollisionState } from '../world/contactState.js'
import { nextSeenStamp } from '../world/contactState.js'
import type { BallWorld } from '../world/createWorld.js'
import { isMoving, pushId, type IdList } from '../world/idLists.js'
import { restingState } from '../world/restingGrid.js'
import { buildSpotGrid } from '../world/spotGrid.js'
import { buildHeldGrid } from '../world/heldGrid.js'
import { hashCurrent } from '../world/ballHash.js'
import { capsuleCellsOver, capsuleCells, pointQuery } from './sweepGrid.js'

/** True when a ball of radius r at (x, y) would overlap a moving or resting ball other than `self`. */
export function spotTaken(w: BallWorld, self: number, x: number, y: number, r: number): boolean {
  const C = restingState(w)
  if (C === null) return false
  return movingAt(w, C, self, x, y, r) || restingAt(w, C, self, x, y, r, null)
}

/**
 * True when a ball held at its spot (waiting in the launcher's queue) overlaps a ball of radius r at (x, y),
 * `self` aside: a ball put down there queues behind it, held too. Without this, a ball put down while the
 * spot was clear for a moment (the ball launched last had just left it) was placed at once, ahead of every
 * ball waiting there: one thrown at the launch point 1.5 s into a 300-ball burst left 27th of 301, not last.
 * Through the held grid (src/world/heldGrid.ts); a lookup wider than the grid's table reads the queue.
 */
export function heldOn(w: BallWorld, self: number, x: number, y: number, r: number): boolean {
  const q = w.held
  if (q.count === 0) return false
  const C = restingState(w)
  if (C === null) return false
  const H = C.held
  if (!hashCurrent(w, H)) buildHeldGrid(w, C)
  const reach = r + H.maxR
  if (capsuleCellsOver(C, pointQuery(x, y, reach), q.count)) {
    for (let i = q.count - 1; i >= 0; i--) if (heldAt(w, q.ids[i]!, self, x, y, r)) return true
    return false
  }
  const k = capsuleCells(C, pointQuery(x, y, reach), H.head.length - 1)
  for (let i = 0; i < k; i++) {
    for (let b = H.head[C.cells[i]!]!; b !== 0; b = H.next[b]!) if (heldAt(w, b, self, x, y, r)) return true
  }
  return false
}

/** The place in the launcher's queue of the first held ball other than `self` overlapping the circle (x, y, r), or -1. */
export function firstHeldAt(w: BallWorld, self: number, x: number, y: number, r: number): number {
  const q = w.held
  for (let i = 0; i < q.count; i++) if (heldAt(w, q.ids[i]!, self, x, y, r)) return i
  return -1
}

/** A ball h other than `self`, live and held, overlapping the circle (x, y, r). */
export function heldAt(w: BallWorld, h: number, self: number, x: number, y: number, r: number): boolean {
  const B = w.Ball
  if (h === self || B.live[h] !== 1 || B.mode[h] !== BallMode.Held) return false
  const dx = B.x[h]! - x
  const dy = B.y[h]! - y
  const s = B.radius[h]! + r
  return dx * dx + dy * dy < s * s
}

/**
 * When the only balls on the spot (x, y, r) are resting ones, lists them in `out` (emptied first) and
 * returns true; false when a moving ball is on it, or nothing is.
 */
export function spotHeldByResting(w: BallWorld, self: number, x: number, y: number, r: number, out: IdList): boolean {
  out.count = 0
  const C = restingState(w)
  if (C === null || movingAt(w, C, self, x, y, r)) return false
  nextSeenStamp(C)
  restingAt(w, C, self, x, y, r, out)
  return out.count > 0
}

/** A resting ball on the circle: true at the first one found, or, with `out`, every one listed there. */
function restingAt(w: BallWorld, C: CollisionState, self: number, x: number, y: number, r: number, out: IdList | null): boolean {
  for (let i = 0; i < C.bigRestCount; i++) if (near(w, C.bigRest[i]!, self, x, y, r) && found(C, out, C.bigRest[i]!)) return true
  if (C.restCount === 0) return out !== null && out.count > 0
  const rMask = C.restHead.length - 1
  const reach = r + C.maxRadius
  if (capsuleCellsOver(C, pointQuery(x, y, reach), C.restHead.length)) {
    for (let i = 0; i <= rMask; i++) for (let b = C.restHead[i]!; b !== 0; b = C.restNext[b]!) if (near(w, b, self, x, y, r) && found(C, out, b)) return true
  } else {
    const k = capsuleCells(C, pointQuery(x, y, reach), rMask)
    for (let i = 0; i < k; i++) {
      for (let b = C.restHead[C.cells[i]!]!; b !== 0; b = C.restNext[b]!) if (near(w, b, self, x, y, r) && found(C, out, b)) return true
    }
  }
  return out !== null && out.count > 0
}

/** A resting ball on the spot: stop at it (no list), or list it once (the seen stamp) and go on. */
function found(C: CollisionState, out: IdList | null, b: number): boolean {
  if (out === null) return true
  if (C.seen[b] === C.seenStamp) return false
  C.seen[b] = C.seenStamp
  pushId(out, b)
  return false
}

/**
 * A moving ball (its stored state is at the world's time between steps) overlapping the circle, through the
 * spot grid (src/world/spotGrid.ts): built from the moving set the first time a spot is checked at this
 * world time (O(moving)), then kept, each ball that starts moving at this time linked in, so putting down n
 * balls at once costs O(n + moving), not O(n · moving). A lookup wider than the grid's table scans the
 * moving set.
 */
function movingAt(w: BallWorld, C: CollisionState, self: number, x: number, y: number, r: number): boolean {
  const H = C.spot
  if (!hashCurrent(w, H)) buildSpotGrid(w, C)
  const reach = r + H.maxR
  const mask = H.head.length - 1
  if (capsuleCellsOver(C, pointQuery(x, y, reach), w.moving.count)) {
    const balls = w.moving.dense
    for (let i = 0, n = w.moving.count; i < n; i++) if (overlapsMoving(w, balls[i]!, self, x, y, r)) return true
    return false
  }
  const k = capsuleCells(C, pointQuery(x, y, reach), mask)
  for (let i = 0; i < k; i++) {
    for (let b = H.head[C.cells[i]!]!; b !== 0; b = H.next[b]!) if (overlapsMoving(w, b, self, x, y, r)) return true
  }
  return false
}

function overlapsMoving(w: BallWorld, b: number, self: number, x: number, y: number, r: number): boolean {
  if (b === self || !isMoving(w, b)) return false
  const B = w.Ball
  const dx = B.x[b]! - x
  const dy = B.y[b]! - y
  const s = r + B.radius[b]!
  return dx * dx + dy * dy < s * s
}

/** A resting ball b other than `self` overlapping the circle (x, y, r). */
function near(w: BallWorld, b: number, self: number, x: number, y: number, r: number): boolean {
  const B = w.Ball
  if (b === self || B.mode[b] !== BallMode.Resting) return false
  const dx = B.x[b]! - x
  const dy = B.y[b]! - y
  const s = r + B.radius[b]!
  return dx * dx + dy * dy < s * s
}

