// The fixed-tick method's pairs, packed and ordered (config.BALL_COLLISIONS = 'fixed'). The sweep
// (src/contacts/fixedSweep.ts) finds every pair of candidates within each other's reach; only the balls of
// those pairs, and those near a closed wall, are copied into the packed arrays the solve works on, moving
// balls by id, then resting ones by id (the candidates' order: a ball's index decides which ball of a pair
// is `a`). The solve is Gauss-Seidel, so its result depends on the order of the pairs: they are taken in
// the order of the dense broadphase's grid (src/contacts/fixedDense.ts), which the tick's candidates alone
// fix (cell twice the largest reach, at least the
// side that holds one candidate on average over their bounding box, at most 4n + 64 cells), row by row,
// by index within a cell, each pair from the ball met first; a pair with a "big" ball (reach over half a
// cell) after all the others, by the big ball's index, then the other ball's place. How the pairs were
// found has no part in it: both broadphases give the same pairs in the same order.
import { BallMode } from '../../components/Ball.js'
import type { BallWorld } from '../world/createWorld.js'
import { nextMark, pushListed, pushPair, reserveCandidates, reserveSort, type FixedContactState } from '../world/fixedState.js'
import { gridShape } from './fixedDense.js'
import { radixSort, sortByKeys, sortKeys, sweepPairs } from './fixedSweep.js'
import { renumberCapsules } from './fixedCapsule.js'
import { sortIdRange } from '../world/idLists.js'

/** Up to this many keys, a tick's pairs (and packed ids not sorted through a bitmap) are sorted by sortKeys, not by radix. */
const FEW_KEYS = 512

/** The largest K for which every joined key first·K + second (both below K) is an exact double. */
const MAX_JOINED = 94906265

/** Finds the tick's pairs (F.pairA, F.pairB, F.pairCount, in solve order) and packs their balls. */
export function findPairs(w: BallWorld, F: FixedContactState): void {
  sweepPairs(w, F)
  F.pairCount = 0
  if (F.peCount === 0) return
  gridShape(F, F.full)
  pack(w, F)
  orderPairs(F)
}

/** The ordering grid's column of x (clamped to the grid). */
export function orderCol(F: FixedContactState, x: number): number {
  const gx = Math.floor((x - F.minX) / F.gridCell)
  return gx >= F.cols ? F.cols - 1 : gx
}

/** The ordering grid's row of y (clamped to the grid). */
export function orderRow(F: FixedContactState, y: number): number {
  const gy = Math.floor((y - F.minY) / F.gridCell)
  return gy >= F.rows ? F.rows - 1 : gy
}

/**
 * Packs the balls of the sweep's pairs, those near a closed wall and the big ones (reach over half the
 * ordering cell, F.cell / 2): moving by id, then resting by id. Marks them (F.packMark, F.packAt).
 */
function pack(w: BallWorld, F: FixedContactState): void {
  const B = w.Ball
  const st = nextMark(F)
  // scratch lists: moving balls in F.found, resting in F.fresh (both free after the gather)
  F.foundCount = 0
  F.freshCount = 0
  for (let k = 0; k < F.peCount; k++) {
    take(B, F, st, F.pe1[k]!)
    take(B, F, st, F.pe2[k]!)
  }
  for (let k = 0; k < F.nearCount; k++) {
    take(B, F, st, F.near[k]!)
    F.nearMark[F.near[k]!] = st
  }
  const half = F.cell / 2
  if (F.reachMax > half) for (let k = 0; k < F.ordCount; k++) if (F.reachOf[F.ord[k]!]! > half) take(B, F, st, F.ord[k]!)
  const nm = F.foundCount
  const nr = F.freshCount
  F.foundCount = 0
  F.freshCount = 0
  sortIds(F, F.found, nm)
  sortIds(F, F.fresh, nr)
  const n = nm + nr
  reserveCandidates(F, n)
  F.n = n
  F.gathered = n
  F.restFrom = nm
  F.nearWallCount = 0
  F.bigCount = 0
  for (let i = 0; i < n; i++) {
    const e = i < nm ? F.found[i]! : F.fresh[i - nm]!
    F.id[i] = e
    F.x[i] = B.x[e]!
    F.y[i] = B.y[e]!
    F.r[i] = B.radius[e]!
    F.vx[i] = i < nm ? B.vx[e]! : 0
    F.vy[i] = i < nm ? B.vy[e]! : 0
    F.im[i] = 1 / F.mass[e]!
    const reach = F.reachOf[e]!
    F.reach[i] = reach
    F.changed[i] = 0
    F.grown[i] = 0
    F.packAt[e] = i
    if (F.nearMark[e] === st) F.nearWall[F.nearWallCount++] = i
    if (reach > half) F.big[F.bigCount++] = i
  }
}

/** Ball e is packed (once): to the moving list (F.found) or the resting one (F.fresh). */
function take(B: BallWorld['Ball'], F: FixedContactState, st: number, e: number): void {
  if (F.packMark[e] === st) return
  F.packMark[e] = st
  if (isMoving(B, e)) F.found = pushListed(F.found, F.foundCount++, e)
  else F.fresh = pushListed(F.fresh, F.freshCount++, e)
}

function isMoving(B: BallWorld['Ball'], e: number): boolean {
  const m = B.mode[e]
  return m === BallMode.Rolling || m === BallMode.RimRoll
}

/**
 * Sorts the distinct ids[0..n) ascending: insertion for a few; through a bitmap of the ids when it has at
 * most 4n words (set each id's bit, read the words in order); else as numbers (sortKeys), or by radix
 * through F.perm for many.
 */
function sortIds(F: FixedContactState, ids: Uint32Array, n: number): void {
  if (n <= 16) {
    sortIdRange(ids, 0, n)
    return
  }
  let top = 0
  for (let i = 0; i < n; i++) if (ids[i]! > top) top = ids[i]!
  const words = (top >>> 5) + 1
  if (words <= 4 * n) {
    sortByBits(ids, n, words)
    return
  }
  reserveSort(F, n)
  if (n <= FEW_KEYS) {
    for (let i = 0; i < n; i++) F.key1[i] = ids[i]!
    sortKeys(F, n)
    for (let i = 0; i < n; i++) ids[i] = F.key1[i]!
    return
  }
  for (let i = 0; i < n; i++) {
    F.key1[i] = ids[i]!
    F.perm[i] = i
  }
  radixSort(F, n, top)
  for (let i = 0; i < n; i++) ids[i] = F.key1[F.perm[i]!]!
}

/** sortByBits' bitmap of ids (scratch: every word it sets is zero again when it returns). */
let idBits = new Int32Array(64)

/** Sorts the distinct ids[0..n), all below 32·words, through idBits. */
function sortByBits(ids: Uint32Array, n: number, words: number): void {
  if (idBits.length < words) idBits = new Int32Array(Math.max(words, 2 * idBits.length))
  const bits = idBits
  for (let i = 0; i < n; i++) {
    const e = ids[i]!
    bits[e >>> 5]! |= 1 << (e & 31)
  }
  let k = 0
  for (let wd = 0; wd < words; wd++) {
    let b = bits[wd]!
    if (b === 0) continue
    bits[wd] = 0
    while (b !== 0) {
      const low = b & -b
      ids[k++] = (wd << 5) | (31 - Math.clz32(low))
      b ^= low
    }
  }
}

/**
 * The sweep's pairs in solve order (see the top of this file): each small ball's place is (cell, index);
 * a pair of two small balls goes by the place of the one met first, then the other's; a pair with a big
 * ball after all those, by the big ball's index, then the other's place (small ones before big ones).
 */
function orderPairs(F: FixedContactState): void {
  const n = F.n
  const half = F.cell / 2
  const cells = F.cols * F.rows
  const place = F.next
  for (let i = 0; i < n; i++) place[i] = F.reach[i]! > half ? -1 : orderRow(F, F.y[i]!) * F.cols + orderCol(F, F.x[i]!)
  const count = F.peCount
  reserveSort(F, count)
  const k1 = F.key1
  const k2 = F.key2
  const bigBase = cells * n
  for (let t = 0; t < count; t++) {
    const a = F.packAt[F.pe1[t]!]!
    const b = F.packAt[F.pe2[t]!]!
    const pa = place[a]!
    const pb = place[b]!
    if (pa >= 0 && pb >= 0) {
      const ka = pa * n + a
      const kb = pb * n + b
      k1[t] = ka < kb ? ka : kb
      k2[t] = ka < kb ? kb : ka
    } else if (pa < 0 && pb < 0) {
      k1[t] = bigBase + (a < b ? a : b)
      k2[t] = bigBase + (a < b ? b : a)
    } else {
      const g = pa < 0 ? a : b
      const s = pa < 0 ? b : a
      k1[t] = bigBase + g
      k2[t] = place[s]! * n + s
    }
  }
  const K = bigBase + n
  if (count <= FEW_KEYS && K <= MAX_JOINED) {
    // few pairs: one key a pair, first·K + second (exact: below 2^53), sorted as numbers (a radix sort's
    // 256 buckets a pass cost more below some hundreds of keys); the keys are distinct, so the order is the
    // two keys' order whatever the sort, and each pair is read back from its key
    for (let t = 0; t < count; t++) k1[t] = k1[t]! * K + k2[t]!
    sortKeys(F, count)
    for (let k = 0; k < count; k++) {
      const c = k1[k]!
      let first = Math.floor(c / K)
      let second = c - first * K
      if (second < 0) {
        first--
        second += K
      } else if (second >= K) {
        first++
        second -= K
      }
      const a = first >= bigBase ? first - bigBase : indexOf(first, n)
      const b = second >= bigBase ? second - bigBase : indexOf(second, n)
      pushPair(F, a < b ? a : b, a < b ? b : a)
    }
    return
  }
  for (let t = 0; t < count; t++) F.perm[t] = t
  if (bigBase + n < 2147483648) {
    // by the first key (whole numbers), then runs of equal first keys by the second
    radixSort(F, count, bigBase + n)
    const perm = F.perm
    for (let i = 1; i < count; i++) {
      const v = perm[i]!
      let j = i - 1
      while (j >= 0 && k1[perm[j]!] === k1[v] && k2[perm[j]!]! > k2[v]!) {
        perm[j + 1] = perm[j]!
        j--
      }
      perm[j + 1] = v
    }
  } else sortByKeys(F, count, true)
  for (let k = 0; k < count; k++) {
    const t = F.perm[k]!
    const a = F.packAt[F.pe1[t]!]!
    const b = F.packAt[F.pe2[t]!]!
    pushPair(F, a < b ? a : b, a < b ? b : a)
  }
}

/** The packed index in a small ball's key, place·n + index (key % n, which V8 computes as a call on doubles). */
function indexOf(key: number, n: number): number {
  const i = key - Math.floor(key / n) * n
  return i < 0 ? i + n : i >= n ? i - n : i
}

/**
 * Adds candidates of the gather that were not packed (ids in list[0..count), packMark set, packAt < 0) to
 * the packed arrays, in their places (moving by id, then resting by id, before those the widening added),
 * and renumbers every list of packed indices.
 */
export function unpackedJoin(w: BallWorld, F: FixedContactState, list: Uint32Array, count: number): void {
  const B = w.Ball
  packingCount++
  const old = F.n
  const total = old + count
  reserveCandidates(F, total)
  reserveSort(F, total)
  // the joining balls in packed order: moving by id, then resting by id
  for (let i = 0; i < count; i++) {
    F.key1[i] = keyOf(B, list[i]!)
    F.perm[i] = i
  }
  sortByKeys(F, count, false)
  const order = F.permTmp // free after the sort: the joining balls' ids, in order
  for (let i = 0; i < count; i++) order[i] = list[F.perm[i]!]!
  const moved = F.perm // index before → after
  let s = count - 1
  let o = total - 1
  for (let i = old - 1; i >= 0 || s >= 0; o--) {
    // those the widening added stay last
    if (s >= 0 && (i < 0 || (i < F.gathered && keyOf(B, order[s]!) > (i < F.restFrom ? 0 : RESTING) + F.id[i]!))) {
      place(w, F, order[s]!, o)
      s--
    } else {
      moveEntry(F, i, o)
      moved[i] = o
      i--
    }
  }
  let joinedMoving = 0
  for (let i = 0; i < count; i++) if (isMoving(B, order[i]!)) joinedMoving++
  F.restFrom += joinedMoving
  F.gathered += count
  F.n = total
  for (let i = 0; i < total; i++) F.packAt[F.id[i]!] = i
  for (let p = 0; p < F.pairCount; p++) {
    F.pairA[p] = moved[F.pairA[p]!]!
    F.pairB[p] = moved[F.pairB[p]!]!
  }
  for (let k = 0; k < F.hitCount; k++) F.hit[k] = moved[F.hit[k]!]!
  for (let k = 0; k < F.nearWallCount; k++) F.nearWall[k] = moved[F.nearWall[k]!]!
  for (let k = 0; k < F.widenedCount; k++) F.widened[k] = moved[F.widened[k]!]!
  for (let k = 0; k < F.bigCount; k++) F.big[k] = moved[F.big[k]!]!
  renumberCapsules(moved, old, total)
}

/** Renumberings of the candidates (unpackedJoin) over all ticks: the solve keeps its stamps only between two calls without one. */
let packingCount = 0
export function packings(): number {
  return packingCount
}

/** A packed ball's place in the order: moving by id, then resting by id. */
const RESTING = 4294967296

function keyOf(B: BallWorld['Ball'], e: number): number {
  return (isMoving(B, e) ? 0 : RESTING) + e
}

/** Packed entry i moves to index o. */
function moveEntry(F: FixedContactState, i: number, o: number): void {
  if (i === o) return
  F.id[o] = F.id[i]!
  F.x[o] = F.x[i]!
  F.y[o] = F.y[i]!
  F.r[o] = F.r[i]!
  F.vx[o] = F.vx[i]!
  F.vy[o] = F.vy[i]!
  F.im[o] = F.im[i]!
  F.reach[o] = F.reach[i]!
  F.wide[o] = F.wide[i]!
  F.grown[o] = F.grown[i]!
  F.changed[o] = F.changed[i]!
}

/** Candidate e of the gather, packed at index o with its state at the gather. */
function place(w: BallWorld, F: FixedContactState, e: number, o: number): void {
  const B = w.Ball
  const moving = isMoving(B, e)
  F.id[o] = e
  F.x[o] = B.x[e]!
  F.y[o] = B.y[e]!
  F.r[o] = B.radius[e]!
  F.vx[o] = moving ? B.vx[e]! : 0
  F.vy[o] = moving ? B.vy[e]! : 0
  F.im[o] = 1 / F.mass[e]!
  F.reach[o] = F.reachOf[e]!
  F.wide[o] = 0
  F.grown[o] = 0
  F.changed[o] = 0
}
