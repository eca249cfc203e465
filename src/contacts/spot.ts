// Is a spot on the panel free? A ball put down (ball-ball contacts 'on' or 'fixed') where another ball is would start
// inside it; such a ball is held until its spot is clear (systems/launcher.ts). Checked against every
// moving ball (their stored state is at the world's time between steps) and, through the resting grid,
// against the resting balls near the spot.
import { BallMode } from '../../components/Ball.js'
import type { BallWorld } from '../world/createWorld.js'
import { restingState } from '../world/restingGrid.js'
import { capsuleCellEstimate, capsuleCells } from './sweepGrid.js'

/** True when a ball of radius r at (x, y) would overlap a moving or resting ball other than `self`. */
export function spotTaken(w: BallWorld, self: number, x: number, y: number, r: number): boolean {
  const C = restingState(w)
  if (C === null) return false
  const B = w.Ball
  const balls = w.moving.dense
  for (let i = 0, n = w.moving.count; i < n; i++) {
    const b = balls[i]!
    if (b === self) continue
    const dx = B.x[b]! - x
    const dy = B.y[b]! - y
    const s = r + B.radius[b]!
    if (dx * dx + dy * dy < s * s) return true
  }
  for (let i = 0; i < C.bigRestCount; i++) if (near(w, C.bigRest[i]!, self, x, y, r)) return true
  if (C.restCount === 0) return false
  const rMask = C.restHead.length - 1
  const reach = r + C.maxRadius
  if (capsuleCellEstimate(C, x, y, x, y, reach) > C.restHead.length) {
    for (let i = 0; i <= rMask; i++) for (let b = C.restHead[i]!; b !== 0; b = C.restNext[b]!) if (near(w, b, self, x, y, r)) return true
    return false
  }
  const k = capsuleCells(C, x, y, x, y, reach, rMask)
  for (let i = 0; i < k; i++) {
    for (let b = C.restHead[C.cells[i]!]!; b !== 0; b = C.restNext[b]!) if (near(w, b, self, x, y, r)) return true
  }
  return false
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

