// The touching cluster of a settling contact: the balls touching the pair, and those touching them.
import { BallMode } from '../../components/Ball.js'
import { APPROACH_EPSILON, MAX_CAPSULE_CELLS, MAX_CLUSTER, SETTLE_FLOOR, TOUCH_GAP } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import { nextSeenStamp, appendId } from '../world/contactState.js'
import { sortIdRange } from '../world/idLists.js'
import { AT, E, VX, VY, X, Y, evalBall, sampleForContact } from './evalMotion.js'
import { CR, X1, X2, Y1, Y2, capsuleCellsOver, capsuleCells, query, staleEntry } from './sweepGrid.js'

/**
 * The time a cluster is collected at (clusterAt[0], written by the caller before collectCluster), read by
 * consider and touches: a slot, since a double passed to a call V8 does not inline is boxed, a heap number a
 * ball looked at
 */
export const clusterAt = new Float64Array(1)

/**
 * Gathers into C.cluster the balls touching a or b (gap ≤ TOUCH_GAP at time t = clusterAt[0]), and those touching
 * them, breadth first, up to MAX_CLUSTER balls; a and b come first, and the balls each member adds follow
 * in id order, so the cluster (its members, their order, and where MAX_CLUSTER cuts it) depends on the
 * balls alone, never on the order the grids hold them in (which depends on when balls were predicted).
 * Members are sampled into Ball at t.
 */
export function collectCluster(w: BallWorld, a: number, b: number): void {
  const C = w.collide!
  const stamp = nextSeenStamp(C)
  C.cluster[0] = a
  C.cluster[1] = b
  C.seen[a] = stamp
  C.seen[b] = stamp
  let n = 2
  const B = w.Ball
  for (let head = 0; head < n && n < MAX_CLUSTER; head++) {
    const m = C.cluster[head]!
    const x = B.x[m]!
    const y = B.y[m]!
    const r = B.radius[m]!
    const first = n
    // a ball touches m within TOUCH_GAP: the lookups reach twice that past m, so that two balls touching
    // across a cell boundary (m's disc ending a rounding short of it, the other's starting on it) meet in a
    // cell; without it whether such a ball joined depended on how far its capsule in the hash reached, that
    // is on when it was last predicted (a cluster then differed with PREDICTION_HORIZON)
    const look = r + 2 * TOUCH_GAP
    // the lookups' circle written into the query's slots here (pointQuery took it as three doubles, boxed
    // where V8 did not inline it: a member's lookups in a pile)
    query[X1] = query[X2] = x
    query[Y1] = query[Y2] = y
    query[CR] = look
    // moving balls: through the hash (or all of them, for a member too wide for it), then the big ones
    if (capsuleCellsOver(C, query, MAX_CAPSULE_CELLS)) {
      const balls = w.moving.dense
      for (let i = 0, k = w.moving.count; i < k; i++) n = consider(w, n, balls[i]!, m, stamp)
    } else {
      const sMask = C.sweepHead.length - 1
      const k = capsuleCells(C, query, sMask)
      for (let i = 0; i < k; i++) {
        const bucket = C.cells[i]!
        if (C.sweepStamp[bucket] !== C.stamp) continue
        for (let e = C.sweepHead[bucket]!; e >= 0; e = C.entNext[e]!) {
          if (!staleEntry(C, e)) n = consider(w, n, C.entBall[e]!, m, stamp)
        }
      }
    }
    for (let i = 0; i < C.bigCount; i++) n = consider(w, n, C.big[i]!, m, stamp)
    // resting balls: through the grid (or every bucket, when that is cheaper), then those beside it
    if (C.restCount > 0) {
      const rMask = C.restHead.length - 1
      query[X1] = query[X2] = x
      query[Y1] = query[Y2] = y
      query[CR] = look + C.maxRadius
      if (capsuleCellsOver(C, query, C.restHead.length)) {
        for (let i = 0; i <= rMask; i++) {
          for (let c = C.restHead[i]!; c !== 0; c = C.restNext[c]!) n = consider(w, n, c, m, stamp)
        }
      } else {
        const k = capsuleCells(C, query, rMask)
        for (let i = 0; i < k; i++) {
          for (let c = C.restHead[C.cells[i]!]!; c !== 0; c = C.restNext[c]!) n = consider(w, n, c, m, stamp)
        }
      }
    }
    for (let i = 0; i < C.bigRestCount; i++) n = consider(w, n, C.bigRest[i]!, m, stamp)
    // this member's new neighbours in id order
    sortIdRange(C.cluster, first, n)
  }
  C.clusterCount = n < MAX_CLUSTER ? n : MAX_CLUSTER
}


/** Adds ball c to the cluster when it touches member m at clusterAt[0] (and is not in it yet); returns the new count. */
function consider(w: BallWorld, n: number, c: number, m: number, stamp: number): number {
  const C = w.collide!
  if (C.seen[c] === stamp || !touches(w, c, m)) return n
  C.seen[c] = stamp
  C.cluster = appendId(C.cluster, n, c)
  return n + 1
}

/**
 * True when ball c touches member m at time t = clusterAt[0] (gap ≤ TOUCH_GAP) without moving away from it; c is
 * then sampled into Ball at t. A ball separating from m (a striker rebounding off the cluster an instant
 * ago, still within the touch gap) is not part of the cluster: merging it would stop it dead.
 */
function touches(w: BallWorld, c: number, m: number): boolean {
  const t = clusterAt[0]!
  if (w.Ball.live[c] !== 1) return false
  const mode = w.Ball.mode[c]
  if (mode !== BallMode.Rolling && mode !== BallMode.RimRoll && mode !== BallMode.Resting) return false
  const B = w.Ball
  E[AT] = t
  evalBall(w, c)
  const dx = E[X] - B.x[m]!
  const dy = E[Y] - B.y[m]!
  const S = B.radius[m]! + B.radius[c]! + TOUCH_GAP
  const d2 = dx * dx + dy * dy
  if (d2 > S * S) return false
  const dvx = E[VX] - B.vx[m]!
  const dvy = E[VY] - B.vy[m]!
  const d = Math.sqrt(d2)
  if (d > 0) {
    const vn = (dx * dvx + dy * dvy) / d
    const floor = SETTLE_FLOOR * w.config.BALL_SETTLE_SPEED
    if (vn > floor + APPROACH_EPSILON * (1 + Math.sqrt(dvx * dvx + dvy * dvy))) return false
  }
  E[AT] = t
  sampleForContact(w, c)
  return true
}
