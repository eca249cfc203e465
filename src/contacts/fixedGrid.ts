// The fixed-tick method's gather on a sweep tick (config.BALL_COLLISIONS = 'fixed'; systems/fixedContacts.ts
// takes the dense broadphase of src/contacts/fixedDense.ts instead where the balls crowd): at a contact
// tick, the balls on the panel (rolling, on a rim or resting; not held, captured or out) that can take part:
// every moving ball, and the resting balls within reach of one (or overlapping one, or moved or come to rest
// since the last tick), found through the resting grid, or every resting ball when there are few. A reach is
// the radius plus the distance the ball covers in a tick; two balls are paired when their centres are closer
// than the sum of their reaches, so no pair can pass through each other between two ticks (the swept test),
// whatever the speed.
// The candidates are kept from tick to tick in the sweep order of src/contacts/fixedSweep.ts: a pass over the
// moving set writes each moving ball's record (key, position, reach) at its place of the last tick, a pass
// over the order drops the balls that left and sorts it by insertion, and the balls that joined are merged
// in. No scan of the ids in use (a ball that starts moving is found in the world's moving set, one that comes
// to rest among the balls touched since the last tick), no copy of a ball that touches nothing. Work per
// tick: O(candidates + places changed), plus the resting-grid lookups when resting balls outnumber a quarter
// of the moving ones (src/contacts/fixedSeed.ts). Also here: the walls of the tick, which both broadphases use.
import { BallMode } from '../../components/Ball.js'
import { WallEdge } from '../../components/Walls.js'
import { TOUCH_GAP } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import { pushListed, reserveCandidates, sweepStores, type FixedContactState } from '../world/fixedState.js'
import { addFresh, keyOut, mergeFresh, smallReach, sweepKey } from './fixedSweep.js'
import { seedAround, seedOverlapping, seedTouched } from './fixedSeed.js'
import { nextSeenStamp } from '../world/contactState.js'

/** The tick's reductions over the candidates: sum and largest reach, bounding box, balls big for the sweep cell. */
const acc = { sum: 0, max: 0, minX: Infinity, minY: Infinity, maxX: -Infinity, maxY: -Infinity, big: 0, vx: 0, vy: 0, half: 0.5 }

/**
 * Gathers the candidates of a tick into F.ord (F.full of them) with their reaches (F.reachOf), the balls near
 * a closed wall (F.near), and the tick's cell for the pairs' order (F.cell, fixedOrder.ts).
 */
export function gatherCandidates(w: BallWorld, F: FixedContactState): void {
  sweepStores(F)
  const C = F.rest
  readWalls(w)
  const moving = w.moving.count
  const restTotal = C.restCount + C.bigRestCount
  // few resting balls: all of them are candidates (pairing them costs less than a lookup per moving ball)
  const allRest = restTotal > 0 && 4 * restTotal <= moving
  const lookup = restTotal > 0 && !allRest
  if (restTotal > 0) nextSeenStamp(C)
  if (F.sweepNext !== 0) {
    // a new sweep cell or cell order: every key changes, the order is sorted again from scratch
    F.sweepCell = F.sweepNext
    F.sweepInv = 1 / F.sweepNext
    F.sweepCols = F.sweepColsNext
    F.sweepNext = 0
    for (let p = 0; p < F.ordCount; p++) F.inOrd[F.ord[p]!] = 0
    F.ordCount = 0
  }
  // the widest reach of a small ball for this tick's sweep cell (read per ball below)
  acc.half = smallReach(F)
  acc.sum = 0
  acc.max = 0
  acc.minX = Infinity
  acc.minY = Infinity
  acc.maxX = -Infinity
  acc.maxY = -Infinity
  acc.big = 0
  F.nearCount = 0
  F.freshCount = 0
  const nMov = readMoving(w, F)
  F.n = 0
  if (lookup) seedAll(w, F)
  let kept = sortOrd(w, F, allRest, lookup)
  if (counts.moving !== nMov - F.freshCount) {
    // a ball of ord moving but not in the moving set (whose key was not written): every key again
    for (let p = 0; p < F.ordCount; p++) F.inOrd[F.ord[p]!] = 0
    F.ordCount = 0
    F.freshCount = 0
    F.nearCount = 0
    readMoving(w, F)
    kept = sortOrd(w, F, allRest, lookup)
  }
  const nRest = kept + joinResting(w, F, allRest, lookup, restTotal - kept)
  F.touchedCount = 0
  mergeFresh(F)
  const n = nMov + nRest
  F.full = n
  F.n = 0
  F.reachMax = acc.max
  F.minX = acc.minX
  F.minY = acc.minY
  F.maxX = acc.maxX
  F.maxY = acc.maxY
  F.cell = n === 0 ? 1 : orderCell(w, F, n)
  // the sweep cell for the next ticks: twice the reach that the order's cell allows, a little more so
  // that a tick's speed-ups do not make it change at once; coarser cells (the balls slowed down) or many
  // big balls (sped up) ask for a new one
  const want = 1.1 * F.cell
  if (n > 0 && (F.sweepCell > 1.15 * want || acc.big > 8 + n / 16)) F.sweepNext = want
  // a ball that changes row passes the balls of a row (as many as the field's width holds), one that
  // changes column those of a column: the order that moves fewer, when it moves half as many
  const rows = acc.vy * (acc.maxX - acc.minX)
  const cols = acc.vx * (acc.maxY - acc.minY)
  const better = F.sweepCols === 1 ? rows < cols / 2 : cols < rows / 2
  if (n > 0 && better) {
    F.sweepColsNext = 1 - F.sweepCols
    if (F.sweepNext === 0) F.sweepNext = F.sweepCell
  } else F.sweepColsNext = F.sweepCols
}

/**
 * Every moving ball's reach and key, in the moving set's order (the order the integration just walked the
 * per-ball arrays in), the key written at its place in ord; a ball not in ord yet joins it. Returns how
 * many.
 */
function readMoving(w: BallWorld, F: FixedContactState): number {
  const B = w.Ball
  const live = B.live
  const mode = B.mode
  const X = B.x
  const Y = B.y
  const VX = B.vx
  const VY = B.vy
  const rad = B.radius
  const reachOf = F.reachOf
  const inOrd = F.inOrd
  const posOf = F.posOf
  const okey = F.okey
  const tick = F.tick
  const half = acc.half
  const near = w.walls !== 0
  const wx0 = walls.minX
  const wx1 = walls.maxX
  const wy0 = walls.minY
  const wy1 = walls.maxY
  const dense = w.moving.dense
  const count = w.moving.count
  let sum = 0
  let max = 0
  let minX = Infinity
  let minY = Infinity
  let maxX = -Infinity
  let maxY = -Infinity
  let big = 0
  let n = 0
  let svx = 0
  let svy = 0
  for (let i = 0; i < count; i++) {
    const e = dense[i]!
    const m = mode[e]!
    if (live[e] !== 1 || (m !== BallMode.Rolling && m !== BallMode.RimRoll)) continue
    const x = X[e]!
    const y = Y[e]!
    const vx = VX[e]!
    const vy = VY[e]!
    const reach = rad[e]! + Math.sqrt(vx * vx + vy * vy) * tick + TOUCH_GAP
    n++
    svx += Math.abs(vx)
    svy += Math.abs(vy)
    reachOf[e] = reach
    sum += reach
    if (reach > max) max = reach
    if (x < minX) minX = x
    if (x > maxX) maxX = x
    if (y < minY) minY = y
    if (y > maxY) maxY = y
    if (near && !(x - reach > wx0 && x + reach < wx1 && y - reach > wy0 && y + reach < wy1)) F.near = pushListed(F.near, F.nearCount++, e)
    // a ball too wide or fast for the sweep cell has a key half a cell on (fixedSweep.ts)
    sweepKey(F, X, Y, e)
    let key = keyOut[0]!
    if (reach > half) {
      key += 0.5
      big++
    }
    if (inOrd[e] !== 1) {
      keyOut[0] = key
      addFresh(F, e)
      continue
    }
    okey[posOf[e]!] = key
  }
  acc.sum = sum
  acc.max = max
  acc.minX = minX
  acc.minY = minY
  acc.maxX = maxX
  acc.maxY = maxY
  acc.big = big
  acc.vx = svx
  acc.vy = svy
  return n
}

/** The balls of ord kept by sortOrd: moving, resting. */
const counts = { moving: 0, resting: 0 }

/**
 * Puts ord back in key order by insertion (the order of the last tick is nearly right), dropping the balls
 * that are no longer candidates; the resting candidates' keys are found here. Returns how many rest.
 */
function sortOrd(w: BallWorld, F: FixedContactState, allRest: boolean, lookup: boolean): number {
  const B = w.Ball
  const live = B.live
  const mode = B.mode
  const seen = F.rest.seen
  const seenStamp = F.rest.seenStamp
  const okey = F.okey
  const ord = F.ord
  const posOf = F.posOf
  const N = F.ordCount
  let nMov = 0
  let nRest = 0
  let out = 0
  for (let p = 0; p < N; p++) {
    const e = ord[p]!
    const m = mode[e]!
    let k = okey[p]!
    if (live[e] === 1 && (m === BallMode.Rolling || m === BallMode.RimRoll)) nMov++
    else if (live[e] === 1 && m === BallMode.Resting && (allRest || (lookup && seen[e] === seenStamp))) {
      if (allRest) seen[e] = seenStamp
      restingKey(w, F, e)
      k = keyOut[0]!
      nRest++
    } else {
      F.inOrd[e] = 0
      continue
    }
    let j = out
    while (j > 0 && okey[j - 1]! > k) {
      const f = ord[j - 1]!
      okey[j] = okey[j - 1]!
      ord[j] = f
      posOf[f] = j
      j--
    }
    okey[j] = k
    ord[j] = e
    posOf[e] = j
    out++
  }
  F.ordCount = out
  counts.moving = nMov
  counts.resting = nRest
  return nRest
}

/** A resting candidate's reach and its part of the reductions; its key into keyOut[0] (a returned double is boxed: 14 bytes a ball a tick in sortOrd) */
function restingKey(w: BallWorld, F: FixedContactState, e: number): void {
  const x = w.Ball.x[e]!
  const y = w.Ball.y[e]!
  const reach = w.Ball.radius[e]! + TOUCH_GAP
  F.reachOf[e] = reach
  acc.sum += reach
  if (reach > acc.max) acc.max = reach
  if (x < acc.minX) acc.minX = x
  if (x > acc.maxX) acc.maxX = x
  if (y < acc.minY) acc.minY = y
  if (y > acc.maxY) acc.maxY = y
  if (w.walls !== 0 && !(x - reach > walls.minX && x + reach < walls.maxX && y - reach > walls.minY && y + reach < walls.maxY)) F.near = pushListed(F.near, F.nearCount++, e)
  sweepKey(F, w.Ball.x, w.Ball.y, e)
  if (reach > acc.half) {
    keyOut[0] += 0.5
    acc.big++
  }
}

/** Resting ball e joins ord this tick. */
function join(w: BallWorld, F: FixedContactState, e: number): void {
  restingKey(w, F, e)
  addFresh(F, e)
}

/**
 * Resting candidates not yet in ord join it: with every resting ball a candidate, those come to rest since
 * the last tick (they are among the touched balls; any other, when `missing` are not found so, by a scan
 * of the ids); else those the lookups found (F.id[0..F.n)). Returns how many.
 */
function joinResting(w: BallWorld, F: FixedContactState, allRest: boolean, lookup: boolean, missing: number): number {
  const B = w.Ball
  const C = F.rest
  let added = 0
  if (allRest) {
    for (let k = 0; k < F.touchedCount; k++) {
      const e = F.touched[k]!
      if (B.live[e] === 1 && B.mode[e] === BallMode.Resting && F.inOrd[e] !== 1) {
        C.seen[e] = C.seenStamp
        join(w, F, e)
        added++
      }
    }
    if (added === missing) return added
    const top = Math.min(B.live.length, w.entityIndex.maxId + 1)
    for (let e = 1; e < top; e++) {
      if (B.live[e] === 1 && B.mode[e] === BallMode.Resting && F.inOrd[e] !== 1) {
        C.seen[e] = C.seenStamp
        join(w, F, e)
        added++
      }
    }
  } else if (lookup) {
    for (let k = 0; k < F.n; k++) {
      const e = F.id[k]!
      if (F.inOrd[e] !== 1) {
        join(w, F, e)
        added++
      }
    }
  }
  return added
}

/**
 * The grid cell that orders the tick's pairs (fixedOrder.ts): twice the largest reach, or four times the
 * mean reach when the largest is more than four times the mean (then the wider or faster balls are "big").
 * The mean is that of the reaches summed in candidate order (moving by id, then resting by id); the sum in
 * ord's order gives the same choice unless the two are within rounding of each other, and then the sum is
 * taken again in that order.
 */
function orderCell(w: BallWorld, F: FixedContactState, n: number): number {
  const max = acc.max
  if (max <= ((4 * acc.sum) / n) * (1 - (n + 4) * 4.5e-16)) return 2 * max
  const B = w.Ball
  const top = Math.min(B.live.length, w.entityIndex.maxId + 1)
  let sum = 0
  for (let eid = 1; eid < top; eid++) {
    const m = B.mode[eid]
    if (F.inOrd[eid] === 1 && (m === BallMode.Rolling || m === BallMode.RimRoll)) sum += F.reachOf[eid]!
  }
  for (let eid = 1; eid < top; eid++) if (F.inOrd[eid] === 1 && B.mode[eid] === BallMode.Resting) sum += F.reachOf[eid]!
  return max <= (4 * sum) / n ? 2 * max : (4 * sum) / n
}

/**
 * The resting balls within reach of a moving ball (or of a resting ball the last tick's projection moved),
 * and every resting ball that overlaps one of those, transitively, into F.id (F.n of them; marked seen).
 */
function seedAll(w: BallWorld, F: FixedContactState): void {
  const from = F.n
  const dense = w.moving.dense
  for (let i = 0; i < w.moving.count; i++) seedAround(w, F, dense[i]!)
  seedTouched(w, F)
  seedOverlapping(w, F, from)
}

/**
 * The closed walls of this tick: their inner faces (an open edge, or no walls, at ±Infinity, where no ball
 * ever reaches) and restitution; read once a tick, by the gather, for the pairing and the solve.
 */
export const walls = { minX: -Infinity, maxX: Infinity, minY: -Infinity, maxY: Infinity, e: 0 }

export function readWalls(w: BallWorld): void {
  const W = w.Walls
  const e = w.walls
  const open = e === 0 ? 15 : W.open[e]!
  // ±Infinity written ±1 / 0: the global, read in a branch V8 has not seen taken (a closed box), is a generic
  // load, and the face it merges with was boxed
  walls.minX = (open & WallEdge.Left) === 0 ? W.minX[e]! : -1 / 0
  walls.maxX = (open & WallEdge.Right) === 0 ? W.maxX[e]! : 1 / 0
  walls.minY = (open & WallEdge.Top) === 0 ? W.minY[e]! : -1 / 0
  walls.maxY = (open & WallEdge.Bottom) === 0 ? W.maxY[e]! : 1 / 0
  walls.e = e === 0 ? 0 : W.restitution[e]!
}

/** Lists packed candidate i among those near a closed wall when its reach meets one within the tick. */
export function markWall(F: FixedContactState, i: number): void {
  const x = F.x[i]!
  const y = F.y[i]!
  const reach = F.reach[i]!
  // far from every wall: the common case
  if (x - reach > walls.minX && x + reach < walls.maxX && y - reach > walls.minY && y + reach < walls.maxY) return
  listNearWall(F, i)
}

/**
 * Lists candidate i near a wall. The widening rounds list a ball again each time it is widened, so the
 * list can outgrow the candidates: then every candidate array doubles (together, as reserveCandidates
 * keeps them).
 */
export function listNearWall(F: FixedContactState, i: number): void {
  if (F.nearWallCount === F.nearWall.length) reserveCandidates(F, 2 * F.nearWall.length)
  F.nearWall[F.nearWallCount++] = i
}

/**
 * The finest spacing's tick, CONTACT_TICK / 2^MAX_TICK_HALVINGS, for intoWalls (deepFiner sets it): a slot,
 * not an argument
 */
export const finestTick = new Float64Array(1)

/**
 * Which closed walls candidate i moves into within the tick (or, `finest`, within finestTick[0]) at its
 * present velocity: bit 1 on x, bit 2 on y (an open edge's face is at ±Infinity: never within a tick).
 * Indices in, an integer out: no double crosses the call.
 */
export function intoWalls(F: FixedContactState, i: number, finest = false): number {
  const tick = finest ? finestTick[0]! : F.tick
  const x = F.x[i]!
  const y = F.y[i]!
  const r = F.r[i]!
  const vx = F.vx[i]!
  const vy = F.vy[i]!
  const onX = (vx < 0 && x - r - walls.minX <= -vx * tick) || (vx > 0 && walls.maxX - x - r <= vx * tick)
  const onY = (vy < 0 && y - r - walls.minY <= -vy * tick) || (vy > 0 && walls.maxY - y - r <= vy * tick)
  return (onX ? 1 : 0) | (onY ? 2 : 0)
}

/**
 * Whether candidate i could reach both walls of each axis of `into` (intoWalls' bits) within the tick,
 * whichever way it moves (in a box wider than it): turned by one wall, the other turns it back.
 */
export function bouncesBetween(F: FixedContactState, i: number, into: number): boolean {
  const r = F.r[i]!
  const sx = Math.abs(F.vx[i]!) * F.tick
  const sy = Math.abs(F.vy[i]!) * F.tick
  const loX = F.x[i]! - r - walls.minX
  const hiX = walls.maxX - F.x[i]! - r
  const loY = F.y[i]! - r - walls.minY
  const hiY = walls.maxY - F.y[i]! - r
  if ((into & 1) !== 0 && !(loX <= sx && hiX <= sx && loX + hiX > 0)) return false
  return (into & 2) === 0 || (loY <= sy && hiY <= sy && loY + hiY > 0)
}

/** Whether a candidate listed near a wall from F.nearWall[from] on moves into a closed wall within the tick. */
export function wallsPending(F: FixedContactState, from: number): boolean {
  for (let k = from; k < F.nearWallCount; k++) if (intoWalls(F, F.nearWall[k]!) !== 0) return true
  return false
}
