// The fixed-tick method's velocity solve (src/contacts/fixedSolve.ts): whether an impulse drives the lighter
// ball of a pair into a closed wall, so that the pair and the wall are solved together
// (src/contacts/fixedWallPair.ts).
import { PROJECTION_SLOP } from '../config/tolerances.js'
import type { FixedContactState } from '../world/fixedState.js'
import { walls } from './fixedGrid.js'
import { nrm } from './fixedPairs.js'

/** wallAhead's other speed for the ball it looks at (px/s): what an impulse gives it if it stands still, else 0 (a slot: not a boxed double) */
export const pushed = new Float64Array(1)

/** the pair wallAhead looks at */
let pairAt = 0

/** wallAhead looks at pair p next. */
export function aheadOf(p: number): void {
  pairAt = p
}

/** the closed wall found by wallAhead: its inward normal */
export const face = { x: 0, y: 0 }

/**
 * True when a push on candidate i (of the pair set by aheadOf) along sign·nrm drives it into a closed wall: a
 * ball standing still that the push sends (at pushed[0]) to the wall's face within the tick, or a moving one
 * that reaches the face within the tick at its own speed and whose partner closes the room between it and
 * the face (their gap and its gap to the face) within the tick, at the partner's own speed toward the face.
 * That wall's inward normal is left in `face` (of two, the one the push meets more squarely).
 */
export function wallAhead(F: FixedContactState, i: number, sign: number): boolean {
  const dx = sign * nrm.x
  const dy = sign * nrm.y
  const x = F.x[i]!
  const y = F.y[i]!
  const r = F.r[i]!
  const reach = F.reach[i]! - r
  const after = pushed[0]! * F.tick
  const travel = after > reach ? after : reach
  // on each axis, −|d| when the push drives the ball into a face within `travel`, else 0
  const lowX = x - r - walls.minX
  const highX = walls.maxX - x - r
  const cx = dx < 0 ? (lowX <= travel ? dx : 0) : dx > 0 ? (highX <= travel ? -dx : 0) : 0
  const lowY = y - r - walls.minY
  const highY = walls.maxY - y - r
  const cy = dy < 0 ? (lowY <= travel ? dy : 0) : dy > 0 ? (highY <= travel ? -dy : 0) : 0
  if (cx === 0 && cy === 0) return false
  if (cx <= cy) {
    face.x = dx < 0 ? 1 : -1
    face.y = 0
  } else {
    face.x = 0
    face.y = dy < 0 ? 1 : -1
  }
  if (pushed[0]! > 0) return true
  // a moving ball is squeezed only where its partner closes the room between it and the wall within the tick;
  // else it is one that crosses that room, met by its partner and sent into the wall, and is bounced
  // between the two by the plain impulses (solved with the wall, past its visits, it stopped a ball a
  // million times heavier dead 250 px from the wall: docs/known-failures.md)
  const o = F.pairA[pairAt]! === i ? F.pairB[pairAt]! : F.pairA[pairAt]!
  const room = Math.sqrt((F.x[o]! - x) * (F.x[o]! - x) + (F.y[o]! - y) * (F.y[o]! - y)) - r - F.r[o]! + (face.x > 0 ? lowX : face.x < 0 ? highX : face.y > 0 ? lowY : highY)
  return room <= -(F.vx[o]! * face.x + F.vy[o]! * face.y) * F.tick + PROJECTION_SLOP
}
