// The fixed tick's resting candidates (systems/fixedContacts.ts): the resting balls a moving ball can reach
// within the tick, those touching a resting ball the last tick's projection moved, and every resting ball
// overlapping one of those, transitively (the projection sees a jammed cluster at once). Shared by both
// broadphases (src/contacts/fixedDense.ts, fixedGrid.ts) and the widening (fixedReach.ts); found through the
// resting grid (src/world/restingGrid.ts), once each (its seen stamp).
import { BallMode } from '../../components/Ball.js'
import { PROJECTION_SLOP, TOUCH_GAP } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import { pushCandidate, type FixedContactState } from '../world/fixedState.js'
import { CR, X1, X2, Y1, Y2, capsuleCellsOver, capsuleCells, query } from './sweepGrid.js'
import { bounds, circle, meetsCircle, readPath, readSweep, shareAlong } from './fixedCapsule.js'

/** Adds the resting balls moving ball eid can reach within the tick (its radius plus a tick's travel). */
export function seedAround(w: BallWorld, F: FixedContactState, eid: number): void {
  const B = w.Ball
  const vx = B.vx[eid]!
  const vy = B.vy[eid]!
  seed[0] = B.x[eid]!
  seed[1] = B.y[eid]!
  seed[2] = B.radius[eid]! + Math.sqrt(vx * vx + vy * vy) * F.tick + TOUCH_GAP
  seedResting(w, F)
}

/** Adds the resting balls touching a resting ball the last tick's projection moved (F.touched). */
export function seedTouched(w: BallWorld, F: FixedContactState): void {
  const B = w.Ball
  for (let k = 0; k < F.touchedCount; k++) {
    const eid = F.touched[k]!
    if (B.live[eid] !== 1 || B.mode[eid] !== BallMode.Resting) continue
    seed[0] = B.x[eid]!
    seed[1] = B.y[eid]!
    seed[2] = B.radius[eid]! + TOUCH_GAP
    seedResting(w, F)
  }
}

/**
 * Adds every resting ball overlapping a resting candidate from F.id[from] on, transitively: the projection
 * sees the whole overlapping cluster at once (a push crosses a jammed pile in one tick, not a ball a tick).
 */
export function seedOverlapping(w: BallWorld, F: FixedContactState, from: number): void {
  const B = w.Ball
  for (let k = from; k < F.n; k++) {
    const eid = F.id[k]!
    seed[0] = B.x[eid]!
    seed[1] = B.y[eid]!
    seed[2] = B.radius[eid]! - PROJECTION_SLOP
    seedResting(w, F)
  }
}

/**
 * seedResting's circle (x, y, reach), written by the caller just before the call: V8 boxes each double passed
 * to a function it does not inline, three heap numbers a moving ball a tick in seedAround.
 */
export const seed = new Float64Array(3)

/** Adds the resting balls the circle `seed` reaches, once each (the seen stamp), to F.id. */
export function seedResting(w: BallWorld, F: FixedContactState): void {
  const C = F.rest
  query[X1] = query[X2] = seed[0]!
  query[Y1] = query[Y2] = seed[1]!
  query[CR] = seed[2]! + C.maxRadius + 2 * TOUCH_GAP // addResting's reach + radius + gap, and a gap more
  walkResting(w, F, -1)
}

/**
 * The resting balls of the cells `query` touches (every one when it covers more cells than the table has,
 * the big ones always), each offered to addResting (g < 0: the circle `seed`) or to addCovered (what
 * widened candidate g covers).
 */
function walkResting(w: BallWorld, F: FixedContactState, g: number): void {
  const C = F.rest
  for (let i = 0; i < C.bigRestCount; i++) offer(w, F, g, C.bigRest[i]!)
  if (C.restCount === 0) return
  const mask = C.restHead.length - 1
  if (capsuleCellsOver(C, query, C.restHead.length)) {
    for (let b = 0; b <= mask; b++) for (let e = C.restHead[b]!; e !== 0; e = C.restNext[e]!) offer(w, F, g, e)
    return
  }
  const k = capsuleCells(C, query, mask)
  for (let i = 0; i < k; i++) for (let e = C.restHead[C.cells[i]!]!; e !== 0; e = C.restNext[e]!) offer(w, F, g, e)
}

function offer(w: BallWorld, F: FixedContactState, g: number, e: number): void {
  if (g < 0) addResting(w, F, e)
  else if (probing) probeCovered(w, F, g, e)
  else addCovered(w, F, g, e)
}

function addResting(w: BallWorld, F: FixedContactState, e: number): void {
  const C = F.rest
  if (C.seen[e] === C.seenStamp) return
  const B = w.Ball
  const dx = B.x[e]! - seed[0]!
  const dy = B.y[e]! - seed[1]!
  const s = seed[2]! + B.radius[e]! + TOUCH_GAP
  if (dx * dx + dy * dy >= s * s) return
  C.seen[e] = C.seenStamp
  pushCandidate(F, e)
}

/**
 * Adds the resting balls that what widened candidate g newly covers reaches (its circle and its capsule,
 * src/contacts/fixedCapsule.ts), once each, to F.id.
 */
export function seedAlong(w: BallWorld, F: FixedContactState, g: number): void {
  readSweep(g)
  stretchQuery(F, g, 0, 1)
  walkResting(w, F, g)
}

/**
 * The nearest resting ball not yet a candidate that what widened candidate g covers now meets, among those
 * whose centres lie ahead of g's and whose cells the stretch from share a to b of its path reaches: its
 * share of the path, by its centre (src/contacts/fixedCut.ts); 1 if none. Adds none.
 */
export function probeAlong(w: BallWorld, F: FixedContactState, g: number, a: number, b: number): number {
  readPath(g)
  stretchQuery(F, g, a, b)
  probing = true
  nearest = 1
  walkResting(w, F, g)
  probing = false
  return nearest
}

let probing = false
let nearest = 1

function probeCovered(w: BallWorld, F: FixedContactState, g: number, e: number): void {
  if (F.rest.seen[e] === F.rest.seenStamp) return
  const B = w.Ball
  circle[0] = B.x[e]!
  circle[1] = B.y[e]!
  circle[2] = B.radius[e]! + TOUCH_GAP
  if (!meetsCircle(F, g, true)) return
  const s = shareAlong(F, g, circle[0]!, circle[1]!)
  if (s > 0 && s < nearest) nearest = s
}

/**
 * The capsule query of shares a to b of the sweep in bounds[0], bounds[1] from g's centre, as wide as the
 * wider of g's circle and its capsule, and a resting ball.
 */
function stretchQuery(F: FixedContactState, g: number, a: number, b: number): void {
  const ux = bounds[0]!
  const uy = bounds[1]!
  query[X1] = F.x[g]! + ux * a
  query[Y1] = F.y[g]! + uy * a
  query[X2] = F.x[g]! + ux * b
  query[Y2] = F.y[g]! + uy * b
  query[CR] = Math.max(F.wide[g]!, F.r[g]! + TOUCH_GAP) + F.rest.maxRadius + 2 * TOUCH_GAP
}

function addCovered(w: BallWorld, F: FixedContactState, g: number, e: number): void {
  const C = F.rest
  if (C.seen[e] === C.seenStamp) return
  const B = w.Ball
  circle[0] = B.x[e]!
  circle[1] = B.y[e]!
  circle[2] = B.radius[e]! + TOUCH_GAP
  if (!meetsCircle(F, g, true)) return
  C.seen[e] = C.seenStamp
  pushCandidate(F, e)
}
