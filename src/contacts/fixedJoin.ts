// The fixed-tick method's projection (src/contacts/fixedProject.ts) moves balls along the tick's pairs,
// found at the tick's positions; a resting ball reaches only its radius (it does not move by itself), and a
// slow one little more, so a ball the projection pushes can end inside a ball it was not paired with (a
// rolling ball pressing a row of resting ones: the second is pushed into the third; a light ball pushed out
// of a heavy one into a ball lying still but still rolling). After a projection that kept within its budget,
// each ball it moved more than half the slop is paired with the balls it now overlaps by more than
// PROJECTION_SLOP: resting ones (those the tick did not gather join the packed candidates), then moving ones
// (found in the dense grid, or through the sweep order, and packed in their places if they were not), and
// the projection runs again: at most MAX_WIDEN_ROUNDS times a tick (systems/fixedContacts.ts). Two balls that
// overlap by more than the slop after a projection that finished are never a pair of it, so no pair is
// listed twice; the moving ones are listed in packed order, the same on both broadphases. A ball it moved
// that ends short of a packed ball it then closes deep on (src/contacts/fixedDeep.ts) is paired with it
// too, when the tick has at most DEEP_FRONTS such pairs and not that pair already, and the tick's last
// guard (fixedGuard.ts) closes the pair: it would go through itself before the next tick.
import { BallMode } from '../../components/Ball.js'
import { DEEP_FRONTS, PROJECTION_SLOP, TOUCH_GAP } from '../config/tolerances.js'
import { closesDeep } from './fixedDeep.js'
import type { BallWorld } from '../world/createWorld.js'
import { nextMark, pushCandidate, pushListed, pushPair, reserveCandidates, reserveSort, sweepStores, type FixedContactState } from '../world/fixedState.js'
import { setRestingCandidate } from './fixedReach.js'
import { sortIdRange } from '../world/idLists.js'
import { capsuleCellsOver, capsuleCells, pointQuery } from './sweepGrid.js'
import { box, boxRange, gridBox } from './fixedDense.js'
import { unpackedJoin } from './fixedOrder.js'
import { QR, QX, QY, queried, queryBox, sortByKeys } from './fixedSweep.js'
import { nextSeenStamp } from '../world/contactState.js'
import { MOVED } from './fixedWallTurn.js'

/** Pairs the balls the projection moved with the unpaired balls they overlap; true when it paired any. */
export function joinPushed(w: BallWorld, F: FixedContactState): boolean {
  const C = F.rest
  const B = w.Ball
  const n0 = F.n
  // how far the projection moved each candidate (the stores, the grids and the sweep order hold the balls at
  // the tick's positions)
  let shift = 0
  let movers = 0
  if (far.length < n0) far = new Int32Array(2 * n0)
  farCount = 0
  for (let k = 0; k < n0; k++) {
    if ((F.changed[k]! & MOVED) === 0) continue
    const e = F.id[k]!
    const dx = F.x[k]! - B.x[e]!
    const dy = F.y[k]! - B.y[e]!
    const d2 = dx * dx + dy * dy
    const d = Math.sqrt(d2)
    if (d > shift) shift = d
    if (d > PROJECTION_SLOP / 2) movers++
    if (d2 > (PROJECTION_SLOP / 2) * (PROJECTION_SLOP / 2)) far[farCount++] = k
  }
  // a new overlap deeper than the slop needs the two balls to have closed by more than it: one of them moved
  // more than half of it
  if (movers === 0) return false
  let paired = false
  const resting = C.restCount > 0 || C.bigRestCount > 0
  // the candidates by id, for the resting pairs and for the moving ones of a sweep tick (those pairIfPushed
  // packs are marked as it packs them)
  const st = resting || F.dense !== 1 ? markPacked(F, n0) : 0
  if (resting) {
    for (let f = 0; f < farCount; f++) {
      const i = far[f]!
      nextSeenStamp(C)
      const x = F.x[i]!
      const y = F.y[i]!
      pushedCount = 0
      for (let b = 0; b < C.bigRestCount; b++) listIfPushed(w, F, i, C.bigRest[b]!, st)
      if (C.restCount > 0) {
        // centres within the two radii, the other's at most maxRadius, found at its tick position
        const reach = F.r[i]! + C.maxRadius + shift + TOUCH_GAP
        const mask = C.restHead.length - 1
        if (capsuleCellsOver(C, pointQuery(x, y, reach), C.restHead.length)) {
          for (let c = 0; c <= mask; c++) for (let e = C.restHead[c]!; e !== 0; e = C.restNext[e]!) listIfPushed(w, F, i, e, st)
        } else {
          const k = capsuleCells(C, pointQuery(x, y, reach), mask)
          for (let c = 0; c < k; c++) for (let e = C.restHead[C.cells[c]!]!; e !== 0; e = C.restNext[e]!) listIfPushed(w, F, i, e, st)
        }
      }
      // paired by id, not in the resting grid's order (it depends on where a step split the tick: a 240 Hz
      // step splits it at its half, and two balls that stop in one tick enter the grid in another order)
      sortIdRange(pushed, 0, pushedCount)
      for (let p = 0; p < pushedCount; p++) pairPushed(w, F, i, pushed[p]!, st)
      if (pushedCount > 0) paired = true
    }
  }
  if (joinMoving(w, F, shift, st)) paired = true
  return paired
}

/**
 * Marks every candidate seen under a new stamp of the resting state's (F.rest.seen): joinPushed takes the
 * stamps the gather left on the candidates, so a widening after it (systems/fixedContacts.ts) would add a
 * resting candidate a second time, at its stored position.
 */
export function markCandidatesSeen(F: FixedContactState): void {
  const C = F.rest
  const stamp = nextSeenStamp(C)
  for (let k = 0; k < F.n; k++) C.seen[F.id[k]!] = stamp
}

/** Marks the first n candidates packed, by id, with their indices (F.packMark, F.packAt); returns the mark. */
function markPacked(F: FixedContactState, n: number): number {
  sweepStores(F)
  const st = nextMark(F)
  for (let k = 0; k < n; k++) {
    F.packMark[F.id[k]!] = st
    F.packAt[F.id[k]!] = k
  }
  return st
}

/**
 * The candidates (of the first n0) the projection moved more than half the slop, listed by joinPushed for
 * both of its passes (scratch: one tick at a time).
 */
let far = new Int32Array(64)
let farCount = 0

/**
 * Pairs each candidate the projection pushed far (far, listed by joinPushed) with the moving candidates it now overlaps
 * by more than the slop: the big ones, and the small ones of the dense grid's cells (or of the sweep order's)
 * within its radius, the largest small radius and the largest push of it. Those the sweep did not pack are
 * packed first (on a sweep tick the packed are marked `st` by id); then the pairs, as packed indices, are
 * listed in order, each once.
 */
function joinMoving(w: BallWorld, F: FixedContactState, shift: number, st: number): boolean {
  const half = F.cell / 2
  const dense = F.dense === 1
  let found = 0
  let joining = 0
  deepCount = 0
  for (let f = 0; f < farCount; f++) {
    const i = far[f]!
    for (let m = 0; m < F.bigCount; m++) {
      const j = F.big[m]!
      if (overlapsMoving(w, F, i, F.id[j]!, j)) found = record(F, found, i, dense ? j : F.id[j]!, dense)
      else noteDeep(F, i, j)
    }
    // and as far again as it travels in the tick, for the moving candidates it now closes deep on
    const vx = F.vx[i]!
    const vy = F.vy[i]!
    const range = F.r[i]! + half + shift + Math.sqrt(vx * vx + vy * vy) * F.tick
    if (dense) {
      boxRange[0] = range
      if (!gridBox(F, i)) continue
      for (let gy = box[2]!; gy <= box[3]!; gy++) {
        for (let q = F.start[gy * F.cols + box[0]!]!, end = F.start[gy * F.cols + box[1]! + 1]!; q < end; q++) {
          const j = F.si[q]!
          if (overlapsMoving(w, F, i, F.id[j]!, j)) found = record(F, found, i, j, true)
          else noteDeep(F, i, j)
        }
      }
      continue
    }
    queried[QX] = F.x[i]!
    queried[QY] = F.y[i]!
    queried[QR] = range
    queryBox(F)
    for (let q = 0; q < F.foundCount; q++) {
      const e = F.found[q]!
      if (F.reachOf[e]! > half) continue // a big one: in F.big
      const packed = F.packMark[e] === st && F.packAt[e]! >= 0
      if (!overlapsMoving(w, F, i, e, packed ? F.packAt[e]! : -1)) {
        if (packed) noteDeep(F, i, F.packAt[e]!)
        continue
      }
      found = record(F, found, i, e, false)
      if (F.packMark[e] !== st) {
        F.packMark[e] = st
        F.packAt[e] = -1
        F.fresh = pushListed(F.fresh, joining++, e)
      }
    }
  }
  const deep = joinDeep(F)
  if (found === 0) return deep
  if (joining > 0) unpackedJoin(w, F, F.fresh, joining)
  // as packed indices, lower first, in order; a pair both of whose balls were pushed far is found twice
  reserveSort(F, found)
  const n = F.n
  for (let t = 0; t < found; t++) {
    const a = dense ? F.pe1[t]! : F.packAt[F.pe1[t]!]!
    const b = dense ? F.pe2[t]! : F.packAt[F.pe2[t]!]!
    F.key1[t] = a < b ? a * n + b : b * n + a
    F.perm[t] = t
  }
  sortByKeys(F, found, false)
  let last = -1
  for (let t = 0; t < found; t++) {
    const key = F.key1[F.perm[t]!]!
    if (key === last) continue
    last = key
    const a = Math.floor(key / n)
    pushPair(F, a, key - a * n)
    F.movingJoins++
  }
  return true
}

/** Pairs joinDeep paired over the process's life (tests). */
let deepJoined = 0

/** Pairs joinDeep paired since the process started. */
export function deepJoinedCount(): number {
  return deepJoined
}

/**
 * The packed candidates a pushed one closes deep on without overlapping them (noteDeep; lower index first),
 * DEEP_FRONTS of them at most, or one more: then none is paired (scratch, one tick at a time).
 */
const deepA = new Int32Array(2 * DEEP_FRONTS + 2)
const deepB = new Int32Array(2 * DEEP_FRONTS + 2)
let deepCount = 0

/**
 * Notes candidates i and j (packed) when they close deep within the tick (src/contacts/fixedDeep.ts), each
 * pair once, up to one past DEEP_FRONTS: a ball the projection pushed out of one ball to within its travel of
 * another, closing on it, that the tick did not pair (a row pressed by a ball 1e6 times heavier against a
 * wall: its second-last ball laid out 0.23 px from the last, closing at 2,400 px/s on a 5.2e-4 s tick, went
 * through it before the next tick).
 */
function noteDeep(F: FixedContactState, i: number, j: number): void {
  if (deepCount > DEEP_FRONTS || i === j) return
  // closing deep needs the pair to close by more than its smaller radius within the tick (no square root)
  const ux = F.vx[j]! - F.vx[i]!
  const uy = F.vy[j]! - F.vy[i]!
  const r = F.r[i]! < F.r[j]! ? F.r[i]! : F.r[j]!
  if ((ux * ux + uy * uy) * F.tick * F.tick <= r * r || !closesDeep(F, i, j, false)) return
  const a = i < j ? i : j
  const b = i < j ? j : i
  for (let d = 0; d < deepCount; d++) if (deepA[d] === a && deepB[d] === b) return
  deepA[deepCount] = a
  deepB[deepCount] = b
  deepCount++
}

/**
 * Pairs what noteDeep found, when it found at most DEEP_FRONTS (past them the tick's last guard leaves the
 * tick alone: src/contacts/fixedGuard.ts), but not a pair the tick has already (one pass over its pairs).
 * Their velocities are left to that guard. Returns whether it paired any.
 */
function joinDeep(F: FixedContactState): boolean {
  if (deepCount === 0 || deepCount > DEEP_FRONTS) return false
  for (let p = 0; p < F.pairCount && deepCount > 0; p++) {
    const a = F.pairA[p]!
    const b = F.pairB[p]!
    for (let d = 0; d < deepCount; d++) {
      if (deepA[d] !== a || deepB[d] !== b) continue
      deepA[d] = deepA[deepCount - 1]!
      deepB[d] = deepB[deepCount - 1]!
      deepCount--
      break
    }
  }
  for (let d = 0; d < deepCount; d++) pushPair(F, deepA[d]!, deepB[d]!)
  deepJoined += deepCount
  const paired = deepCount > 0
  deepCount = 0
  return paired
}

/**
 * Whether ball e, a moving ball other than candidate i's, overlaps i by more than the slop: at its packed
 * position (candidate j), or at its tick position if it is not packed (j < 0).
 */
function overlapsMoving(w: BallWorld, F: FixedContactState, i: number, e: number, j: number): boolean {
  const B = w.Ball
  const m = B.mode[e]
  if (e === F.id[i] || B.live[e] !== 1 || (m !== BallMode.Rolling && m !== BallMode.RimRoll)) return false
  const dx = (j >= 0 ? F.x[j]! : B.x[e]!) - F.x[i]!
  const dy = (j >= 0 ? F.y[j]! : B.y[e]!) - F.y[i]!
  const s = F.r[i]! + B.radius[e]! - PROJECTION_SLOP
  return s > 0 && dx * dx + dy * dy < s * s
}

/**
 * Lists candidate i with its partner b in F.pe1, F.pe2 at index `found` (packed indices on a dense tick, ids
 * on a sweep tick: packing renumbers); returns the new count.
 */
function record(F: FixedContactState, found: number, i: number, b: number, dense: boolean): number {
  F.pe1 = pushListed(F.pe1, found, dense ? i : F.id[i]!)
  F.pe2 = pushListed(F.pe2, found, b)
  return found + 1
}

/** The resting balls listIfPushed found for one pushed candidate (scratch, one candidate at a time). */
let pushed: Uint32Array = new Uint32Array(64)
let pushedCount = 0

/**
 * Lists resting ball e (in `pushed`) when it overlaps candidate i by more than PROJECTION_SLOP (e at its
 * position in the packed candidates, if it is one); once per e for this i (the seen stamp).
 */
function listIfPushed(w: BallWorld, F: FixedContactState, i: number, e: number, st: number): void {
  const B = w.Ball
  const C = F.rest
  if (C.seen[e] === C.seenStamp || e === F.id[i] || B.live[e] !== 1 || B.mode[e] !== BallMode.Resting) return
  C.seen[e] = C.seenStamp
  const j = F.packMark[e] === st ? F.packAt[e]! : -1
  const dx = (j >= 0 ? F.x[j]! : B.x[e]!) - F.x[i]!
  const dy = (j >= 0 ? F.y[j]! : B.y[e]!) - F.y[i]!
  const s = F.r[i]! + B.radius[e]! - PROJECTION_SLOP
  if (!(s > 0) || dx * dx + dy * dy >= s * s) return
  pushed = pushListed(pushed, pushedCount++, e)
}

/** Pairs candidate i with resting ball e, listed by listIfPushed (if e is not a candidate, it joins them). */
function pairPushed(w: BallWorld, F: FixedContactState, i: number, e: number, st: number): void {
  let j = F.packMark[e] === st ? F.packAt[e]! : -1
  if (j < 0) {
    j = F.n
    pushCandidate(F, e)
    reserveCandidates(F, F.n)
    setRestingCandidate(w, F, j)
    F.packMark[e] = st
    F.packAt[e] = j
  }
  pushPair(F, i < j ? i : j, i < j ? j : i)
}
