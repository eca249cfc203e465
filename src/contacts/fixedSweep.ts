// The fixed-tick method's sweep (config.BALL_COLLISIONS = 'fixed', on ticks where the balls are spread out):
// the tick's candidates kept from tick to tick in the order of a uniform grid's cells, row by row (a key per
// ball: row·ROW + column), or column by column when the balls move more up and down than across (fewer of
// them then change places in the order). Between two ticks a ball moves a few px, so few change cell, and
// an insertion sort puts the order right again in about one comparison a ball (src/contacts/fixedGrid.ts,
// as it reads the balls). The pairs are then found in one pass over the keys: each ball against the rest of
// its cell and the next (the entries after it with a key at most one more), and against the three cells of
// the next row (a second pointer that only moves on), so the cost is a few comparisons a ball whatever the
// size of the field, with no per-cell work. Balls whose reach exceeds about half a cell ("big") look up the
// small balls in the cells within their reach by binary search, and are tested against each other
// directly. The sweep only finds the pairs: which balls the solve works on, and in which order it takes the
// pairs, is decided by src/contacts/fixedOrder.ts, so nothing here changes a result.
import type { BallWorld } from '../world/createWorld.js'
import { pushListed, reserveOrd, reserveSort, type FixedContactState } from '../world/fixedState.js'

/** key of a cell: row·ROW + column, rows and columns clamped to ±LIMIT (so the keys are exact doubles) */
const ROW = 67108864
const LIMIT = 16777216

function cellIndex(v: number, inv: number): number {
  const c = Math.floor(v * inv)
  return c < -LIMIT ? -LIMIT : c > LIMIT ? LIMIT : c
}

/**
 * A key for sweepKey's result and addFresh's argument: a slot, not a returned or passed double (V8 boxes
 * those for a call it does not inline, which made the gather allocate about a heap number a ball a tick
 * under the test runner).
 */
export const keyOut = new Float64Array(1)

/**
 * The key of the sweep cell of ball e (at X[e], Y[e]) into keyOut[0]: row·ROW + column, or column·ROW + row
 * when the cells go column by column (F.sweepCols 1); a big ball's key is this + 0.5.
 */
export function sweepKey(F: FixedContactState, X: Float64Array, Y: Float64Array, e: number): void {
  const inv = F.sweepInv
  let cx = Math.floor(X[e]! * inv)
  cx = cx < -LIMIT ? -LIMIT : cx > LIMIT ? LIMIT : cx
  let cy = Math.floor(Y[e]! * inv)
  cy = cy < -LIMIT ? -LIMIT : cy > LIMIT ? LIMIT : cy
  keyOut[0] = F.sweepCols === 1 ? cx * ROW + cy : cy * ROW + cx
}

/**
 * The widest reach of a small ball (a little under half the sweep cell: two small balls within reach are
 * less than a cell apart on each axis, so in neighbouring cells, even after the rounding of x / cell).
 */
export function smallReach(F: FixedContactState): number {
  return F.sweepCell * 0.499999
}

/** Adds ball eid (not in ord) with key keyOut[0] to the balls joining ord this tick. */
export function addFresh(F: FixedContactState, eid: number): void {
  const key = keyOut[0]!
  if (F.freshCount === F.freshKey.length) {
    const k = new Float64Array(2 * F.freshKey.length)
    k.set(F.freshKey)
    F.freshKey = k
  }
  F.fresh = pushListed(F.fresh, F.freshCount, eid)
  F.freshKey[F.freshCount++] = key
  F.inOrd[eid] = 1
}

/** Sorts the balls joining ord by key and merges them in (from the back, in place); every ball's place is set again. */
export function mergeFresh(F: FixedContactState): void {
  const m = F.freshCount
  if (m === 0) return
  F.freshCount = 0
  reserveSort(F, m)
  const perm = F.perm
  const keys = F.key1
  for (let i = 0; i < m; i++) {
    perm[i] = i
    keys[i] = F.freshKey[i]!
  }
  sortByKeys(F, m, false)
  const n = F.ordCount
  reserveOrd(F, n + m)
  const ord = F.ord
  const okey = F.okey
  let i = n - 1
  let j = m - 1
  for (let o = n + m - 1; j >= 0; o--) {
    const f = perm[j]!
    if (i >= 0 && okey[i]! > keys[f]!) {
      okey[o] = okey[i]!
      ord[o] = ord[i]!
      i--
    } else {
      okey[o] = keys[f]!
      ord[o] = F.fresh[f]!
      j--
    }
  }
  F.ordCount = n + m
  for (let p = 0; p < n + m; p++) F.posOf[ord[p]!] = p
}

/**
 * Sorts F.perm[0..n) by F.key1 (and then F.key2 when `two`), stably: insertion for a few, else a bottom-up
 * merge through F.permTmp.
 */
export function sortByKeys(F: FixedContactState, n: number, two: boolean): void {
  const k1 = F.key1
  const k2 = F.key2
  let a = F.perm
  if (n <= 24) {
    for (let i = 1; i < n; i++) {
      const v = a[i]!
      let j = i - 1
      while (j >= 0 && after(k1, k2, two, a[j]!, v)) {
        a[j + 1] = a[j]!
        j--
      }
      a[j + 1] = v
    }
    return
  }
  let b = F.permTmp
  for (let width = 1; width < n; width *= 2) {
    for (let lo = 0; lo < n; lo += 2 * width) {
      const mid = Math.min(lo + width, n)
      const hi = Math.min(lo + 2 * width, n)
      let i = lo
      let j = mid
      for (let o = lo; o < hi; o++) {
        if (i < mid && (j >= hi || !after(k1, k2, two, a[i]!, a[j]!))) b[o] = a[i++]!
        else b[o] = a[j++]!
      }
    }
    const t = a
    a = b
    b = t
  }
  if (a !== F.perm) for (let i = 0; i < n; i++) F.perm[i] = a[i]!
}

/** Runs sorted by insertion before sortKeys merges them. */
const RUN = 8

/**
 * Sorts F.key1[0..n) ascending, in place (F.key2 the scratch): insertion within runs of RUN, then bottom-up
 * merges. For the tick's few keys (pairs, packed ids): a radix sort's 256 buckets a pass cost more than
 * this below some hundreds of keys.
 */
export function sortKeys(F: FixedContactState, n: number): void {
  let a = F.key1
  let b = F.key2
  for (let lo = 0; lo < n; lo += RUN) {
    const hi = lo + RUN < n ? lo + RUN : n
    for (let i = lo + 1; i < hi; i++) {
      const v = a[i]!
      let j = i - 1
      while (j >= lo && a[j]! > v) {
        a[j + 1] = a[j]!
        j--
      }
      a[j + 1] = v
    }
  }
  for (let width = RUN; width < n; width *= 2) {
    for (let lo = 0; lo < n; lo += 2 * width) {
      const mid = lo + width < n ? lo + width : n
      const hi = lo + 2 * width < n ? lo + 2 * width : n
      let i = lo
      let j = mid
      for (let o = lo; o < hi; o++) b[o] = i < mid && (j >= hi || a[i]! <= a[j]!) ? a[i++]! : a[j++]!
    }
    const t = a
    a = b
    b = t
  }
  if (a !== F.key1) for (let i = 0; i < n; i++) F.key1[i] = a[i]!
}

/** True when entry p sorts after entry q. */
function after(k1: Float64Array, k2: Float64Array, two: boolean, p: number, q: number): boolean {
  return k1[p]! > k1[q]! || (two && k1[p] === k1[q] && k2[p]! > k2[q]!)
}

/**
 * Every two balls of ord within each other's reach (centre distance below the sum of their reaches), into
 * F.pe1, F.pe2 as ids, reading ord's arrays in order. A big ball's key is not a whole number.
 */
export function sweepPairs(w: BallWorld, F: FixedContactState): void {
  const N = F.ordCount
  const key = F.okey
  const ord = F.ord
  const X = w.Ball.x
  const Y = w.Ball.y
  const reach = F.reachOf
  F.peCount = 0
  F.sweepBigCount = 0
  let b = 0
  for (let p = 0; p < N; p++) {
    const k = key[p]!
    if (k !== Math.floor(k)) {
      F.sweepBig = pushListed(F.sweepBig, F.sweepBigCount++, ord[p]!)
      continue
    }
    // the rest of its cell and the next cell in its row
    for (let q = p + 1; q < N && key[q]! <= k + 1; q++) {
      const kq = key[q]!
      if (kq === Math.floor(kq)) test(F, X, Y, reach, ord[p]!, ord[q]!)
    }
    // the three cells of the next row
    const lo = k + ROW - 1
    while (b < N && key[b]! < lo) b++
    for (let q = b; q < N && key[q]! <= lo + 2; q++) {
      const kq = key[q]!
      if (kq === Math.floor(kq)) test(F, X, Y, reach, ord[p]!, ord[q]!)
    }
  }
  // each big ball against the small ones in the cells within its reach, and against the other big ones
  const half = smallReach(F)
  for (let k = 0; k < F.sweepBigCount; k++) {
    const e = F.sweepBig[k]!
    queried[QX] = X[e]!
    queried[QY] = Y[e]!
    queried[QR] = reach[e]! + half
    queryBox(F)
    for (let m = 0; m < F.foundCount; m++) {
      const f = F.found[m]!
      if (reach[f]! <= half) test(F, X, Y, reach, e, f)
    }
    for (let m = k + 1; m < F.sweepBigCount; m++) test(F, X, Y, reach, e, F.sweepBig[m]!)
  }
}

/** Lists the pair (e, f) if their centres are closer than the sum of their reaches. */
function test(F: FixedContactState, X: Float64Array, Y: Float64Array, reach: Float64Array, e: number, f: number): void {
  const dx = X[f]! - X[e]!
  const dy = Y[f]! - Y[e]!
  const s = reach[e]! + reach[f]!
  if (dx * dx + dy * dy < s * s) pushPair(F, e, f)
}

function pushPair(F: FixedContactState, e: number, f: number): void {
  F.pe1 = pushListed(F.pe1, F.peCount, e)
  F.pe2 = pushListed(F.pe2, F.peCount, f)
  F.peCount++
}

/** counts of one radix pass */
const counts = new Int32Array(257)

/**
 * Sorts F.perm[0..n) stably by F.key1, whole numbers in [0, maxKey] (maxKey < 2³¹): least significant
 * byte first, through F.permTmp.
 */
export function radixSort(F: FixedContactState, n: number, maxKey: number): void {
  const k1 = F.key1
  let a = F.perm
  let b = F.permTmp
  for (let shift = 0, span = 1; span <= maxKey && shift < 32; shift += 8, span *= 256) {
    counts.fill(0)
    for (let i = 0; i < n; i++) counts[((k1[a[i]!]! >>> shift) & 255) + 1]!++
    for (let d = 0; d < 256; d++) counts[d + 1]! += counts[d]!
    for (let i = 0; i < n; i++) {
      const v = a[i]!
      b[counts[(k1[v]! >>> shift) & 255]!++] = v
    }
    const t = a
    a = b
    b = t
  }
  if (a !== F.perm) for (let i = 0; i < n; i++) F.perm[i] = a[i]!
}

/**
 * The box queryBox looks up: centre x, y and half-side R, in slots (QX, QY, QR): a double passed to a call
 * V8 does not inline is boxed.
 */
export const queried = new Float64Array(3)
export const QX = 0
export const QY = 1
export const QR = 2

/** The balls of ord whose sweep cell meets the box [x − R, x + R] × [y − R, y + R] (queried), into F.found (F.foundCount). */
export function queryBox(F: FixedContactState): void {
  const x = queried[QX]!
  const y = queried[QY]!
  const R = queried[QR]!
  const inv = F.sweepInv
  // in key terms: rows y0..y1, columns x0..x1 (the other way round when the cells go column by column)
  const u = F.sweepCols === 1 ? y : x
  const v = F.sweepCols === 1 ? x : y
  const x0 = cellIndex(u - R, inv)
  const x1 = cellIndex(u + R, inv)
  const y0 = cellIndex(v - R, inv)
  const y1 = cellIndex(v + R, inv)
  const N = F.ordCount
  const okey = F.okey
  F.foundCount = 0
  if ((y1 - y0 + 1) * 32 > N) {
    // a box as tall as the field: one pass over every ball
    for (let q = 0; q < N; q++) {
      const k = okey[q]!
      const gy = Math.floor(k / ROW + 0.5)
      const gx = Math.floor(k - gy * ROW)
      if (gy >= y0 && gy <= y1 && gx >= x0 && gx <= x1) F.found = pushListed(F.found, F.foundCount++, F.ord[q]!)
    }
    return
  }
  for (let gy = y0; gy <= y1; gy++) {
    const from = gy * ROW + x0
    const to = gy * ROW + x1 + 0.5 // a big ball's key is half a cell on
    // first entry with key ≥ from
    let lo = 0
    let hi = N
    while (lo < hi) {
      const mid = (lo + hi) >> 1
      if (okey[mid]! < from) lo = mid + 1
      else hi = mid
    }
    for (let q = lo; q < N && okey[q]! <= to; q++) F.found = pushListed(F.found, F.foundCount++, F.ord[q]!)
  }
}
