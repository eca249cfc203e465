// The fixed-tick method's broadphase for dense ticks (config.BALL_COLLISIONS = 'fixed'; src/contacts/
// fixedGrid.ts decides which a tick takes): when a good share of the candidates touch (a gas, a pile, a
// burst of balls thrown together), every candidate is copied, in id order, and the candidates are
// counting-sorted into a uniform grid over their bounding box, whose cell order is the pairs' solve order
// (src/contacts/fixedOrder.ts keeps to the same order when it packs only the balls that touch). The
// grid's cell is twice the largest reach, or four times the mean reach when the largest is more than
// four times the mean (then the wider or faster balls are "big": each scans the grid rows within its
// reach, and the big balls are paired with each other directly), at least the side that holds one
// candidate on average (at most 4n + 64 cells). Work per tick: O(ball ids in use (a scan of the mode
// bytes) + grid cells + pairs + big·(balls in reach, at most all) + big²).
import { BallMode } from '../../components/Ball.js'
import { TOUCH_GAP } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import { pushCandidate, pushPair, reserveCandidates, type FixedContactState } from '../world/fixedState.js'
import { markWall, readWalls } from './fixedGrid.js'
import { seedAround, seedOverlapping, seedTouched } from './fixedSeed.js'
import { sortIdRange } from '../world/idLists.js'
import { nextSeenStamp } from '../world/contactState.js'

/**
 * Gathers the candidates of a dense tick: the moving balls in id order, then the resting balls within reach of
 * one of them (or of a resting ball the last tick's projection moved), in id order, found through the
 * resting grid. Sets their reaches, the grid cell and the near-wall list.
 */
export function gatherDense(w: BallWorld, F: FixedContactState): void {
  const B = w.Ball
  const live = B.live
  const mode = B.mode
  const top = Math.min(live.length, w.entityIndex.maxId + 1)
  F.n = 0
  for (let eid = 1; eid < top; eid++) {
    if (live[eid] === 1 && (mode[eid] === BallMode.Rolling || mode[eid] === BallMode.RimRoll)) pushCandidate(F, eid)
  }
  F.restFrom = F.n
  gatherRestingDense(w, F)
  const n = F.n
  reserveCandidates(F, n)
  const tick = F.tick
  let sum = 0
  let max = 0
  let minX = Infinity
  let minY = Infinity
  let maxX = -Infinity
  let maxY = -Infinity
  for (let k = 0; k < n; k++) {
    const eid = F.id[k]!
    const r = B.radius[eid]!
    const resting = k >= F.restFrom
    const vx = resting ? 0 : B.vx[eid]!
    const vy = resting ? 0 : B.vy[eid]!
    const x = B.x[eid]!
    const y = B.y[eid]!
    F.x[k] = x
    F.y[k] = y
    F.r[k] = r
    F.vx[k] = vx
    F.vy[k] = vy
    F.im[k] = 1 / F.mass[eid]!
    const reach = r + Math.sqrt(vx * vx + vy * vy) * tick + TOUCH_GAP
    F.reach[k] = reach
    F.changed[k] = 0
    sum += reach
    if (reach > max) max = reach
    if (x < minX) minX = x
    if (x > maxX) maxX = x
    if (y < minY) minY = y
    if (y > maxY) maxY = y
  }
  F.full = n
  F.gathered = n
  F.cell = n === 0 ? 1 : max <= (4 * sum) / n ? 2 * max : (4 * sum) / n
  F.minX = minX
  F.minY = minY
  F.maxX = maxX
  F.maxY = maxY
  F.nearWallCount = 0
  readWalls(w)
  if (w.walls !== 0) for (let i = 0; i < n; i++) markWall(F, i)
}

/**
 * Appends the resting balls within reach of the seeds (moving candidates, touched resting balls), sorted by
 * id; or, when there are no more resting balls than moving ones, every resting ball.
 */
function gatherRestingDense(w: BallWorld, F: FixedContactState): void {
  const C = F.rest
  if (C.restCount === 0 && C.bigRestCount === 0) {
    F.touchedCount = 0
    return
  }
  const B = w.Ball
  nextSeenStamp(C)
  const moving = F.n
  if (4 * (C.restCount + C.bigRestCount) <= moving) {
    // few resting balls: all of them join, in id order (pairing them costs less than a lookup per moving ball)
    const live = B.live
    const mode = B.mode
    const top = Math.min(live.length, w.entityIndex.maxId + 1)
    for (let eid = 1; eid < top; eid++) {
      if (live[eid] === 1 && mode[eid] === BallMode.Resting) {
        C.seen[eid] = C.seenStamp
        pushCandidate(F, eid)
      }
    }
    F.touchedCount = 0
    return
  }
  for (let k = 0; k < moving; k++) seedAround(w, F, F.id[k]!)
  seedTouched(w, F)
  F.touchedCount = 0
  // and every resting ball that overlaps a resting candidate, transitively
  seedOverlapping(w, F, moving)
  // ids in ascending order, whatever order the grid gave them in (the same candidates in the same order
  // at every frame rate)
  sortIdRange(F.id, moving, F.n)
}

function close(F: FixedContactState, i: number, j: number): boolean {
  const dx = F.x[j]! - F.x[i]!
  const dy = F.y[j]! - F.y[i]!
  const s = F.reach[i]! + F.reach[j]!
  return dx * dx + dy * dy < s * s
}

/**
 * The dense grid's shape for n candidates over their bounding box (F.minX … F.maxY): its cell, F.cell or
 * the side that holds one candidate on average if that is wider, grown until the grid has at most 4n + 64
 * cells (F.gridCell), and its columns and rows (F.cols, F.rows). Both broadphases take the pairs in this
 * grid's order (src/contacts/fixedOrder.ts), so both call this.
 */
export function gridShape(F: FixedContactState, n: number): void {
  const minX = F.minX
  const minY = F.minY
  const maxX = F.maxX
  const maxY = F.maxY
  let cell = F.cell
  let cols = 1
  let rows = 1
  if (n > 0) {
    // (a box that is not finite never fits: the loop below would not end. Commands keep positions and
    // masses finite, so this is a broken invariant, said rather than hung on)
    if (!(maxX - minX < Infinity && maxY - minY < Infinity)) {
      throw new Error(`fixed tick: the candidates' bounding box [${minX}, ${maxX}] × [${minY}, ${maxY}] is not finite`)
    }
    // about one ball a cell at least (more, emptier cells cost more in the sort than the tests they save)
    const even = Math.sqrt(((maxX - minX) * (maxY - minY)) / n)
    if (even > cell) cell = even
    const most = 4 * n + 64
    for (;;) {
      cols = Math.floor((maxX - minX) / cell) + 1
      rows = Math.floor((maxY - minY) / cell) + 1
      if (cols * rows <= most) break
      // a sparse scene: coarser cells (still at least twice every small reach); again while a long thin box
      // (one row or column) still has too many
      cell *= Math.sqrt((cols * rows) / most) * 1.001
    }
  }
  F.gridCell = cell
  F.cols = cols
  F.rows = rows
}

/**
 * Pairs every two candidates that can touch within the tick. The small candidates are counting-sorted
 * into a dense grid over their bounding box (at most 4n + 64 cells: the cell grows for a sparse scene),
 * each cell is paired with itself and four neighbours ahead of it, and the big candidates scan the cells
 * in their reach. Deterministic order: cells in row order, candidates by index within a cell.
 */
export function findPairsDense(F: FixedContactState): void {
  const n = F.n
  const half = F.cell / 2
  F.pairCount = 0
  F.bigCount = 0
  // the bounding box of every candidate (the big ones included: a box a little larger at most)
  const minX = F.minX
  const minY = F.minY
  gridShape(F, n)
  const cell = F.gridCell
  const cols = F.cols
  const rows = F.rows
  const cells = cols * rows
  const start = reserveCells(F, cells)
  start.fill(0, 0, cells + 1)
  let small = 0
  for (let i = 0; i < n; i++) {
    if (F.reach[i]! > half) {
      F.big[F.bigCount++] = i
      continue
    }
    small++
    const c = cellOf(F.x[i]! - minX, F.y[i]! - minY, cell, cols, rows)
    F.next[i] = c
    start[c + 1]!++
  }
  F.gridCell = cell
  F.cols = small > 0 ? cols : 0
  F.rows = small > 0 ? rows : 0
  for (let c = 0; c < cells; c++) start[c + 1]! += start[c]!
  // counting sort, stable: candidates by cell, by index within a cell; their data copied in that order
  const sx = F.sx
  const sy = F.sy
  const sr = F.sr
  const si = F.si
  for (let i = 0; i < n; i++) {
    if (F.reach[i]! > half) continue
    const k = F.fill[F.next[i]!]!++ + start[F.next[i]!]!
    sx[k] = F.x[i]!
    sy[k] = F.y[i]!
    sr[k] = F.reach[i]!
    si[k] = i
  }
  F.fill.fill(0, 0, cells)
  // each sorted entry against the rest of its cell and the next cell in its row (one run of entries),
  // then the three cells below (another); cells visited in row order, so no division per entry
  for (let gy = 0, c = 0; gy < rows; gy++) {
    const below = gy + 1 < rows
    for (let gx = 0; gx < cols; gx++, c++) {
      const from = start[c]!
      const to = start[c + 1]!
      if (from === to) continue
      const run = start[gx + 1 < cols ? c + 2 : c + 1]!
      const d = c + cols
      const lo = below ? start[gx > 0 ? d - 1 : d]! : 0
      const hi = below ? start[gx + 1 < cols ? d + 2 : d + 1]! : 0
      for (let p = from; p < to; p++) {
        scan(F, p, p + 1, run)
        if (below) scan(F, p, lo, hi)
      }
    }
  }
  for (let k = 0; k < F.bigCount; k++) {
    const i = F.big[k]!
    pairBig(F, i, small, minX, minY, cell, cols, rows)
    for (let m = k + 1; m < F.bigCount; m++) {
      const j = F.big[m]!
      if (close(F, i, j)) pushPair(F, i, j)
    }
  }
}

function cellOf(dx: number, dy: number, cell: number, cols: number, rows: number): number {
  let gx = Math.floor(dx / cell)
  let gy = Math.floor(dy / cell)
  if (gx >= cols) gx = cols - 1
  if (gy >= rows) gy = rows - 1
  return gy * cols + gx
}

/** Pairs sorted entry p with those of the sorted entries [from, to) within reach. */
function scan(F: FixedContactState, p: number, from: number, to: number): void {
  const sx = F.sx
  const sy = F.sy
  const sr = F.sr
  const x = sx[p]!
  const y = sy[p]!
  const r = sr[p]!
  for (let q = from; q < to; q++) {
    const dx = sx[q]! - x
    const dy = sy[q]! - y
    const s = r + sr[q]!
    if (dx * dx + dy * dy >= s * s) continue
    const i = F.si[p]!
    const j = F.si[q]!
    pushPair(F, i < j ? i : j, i < j ? j : i)
  }
}

/**
 * The dense grid's cells within boxRange[0] of candidate i: columns box[0]..box[1], rows box[2]..box[3].
 * (The range in a slot, not an argument: a double passed to a call V8 does not inline is boxed.)
 */
export const box = new Int32Array(4)
export const boxRange = new Float64Array(1)
export function gridBox(F: FixedContactState, i: number): boolean {
  if (F.cols === 0) return false
  const range = boxRange[0]!
  const cell = F.gridCell
  box[0] = Math.max(0, Math.floor((F.x[i]! - range - F.minX) / cell))
  box[1] = Math.min(F.cols - 1, Math.floor((F.x[i]! + range - F.minX) / cell))
  box[2] = Math.max(0, Math.floor((F.y[i]! - range - F.minY) / cell))
  box[3] = Math.min(F.rows - 1, Math.floor((F.y[i]! + range - F.minY) / cell))
  return box[0]! <= box[1]! && box[2]! <= box[3]!
}

/** Pairs big candidate i with the small candidates within its reach. */
function pairBig(F: FixedContactState, i: number, small: number, minX: number, minY: number, cell: number, cols: number, rows: number): void {
  if (small === 0) return
  const R = F.reach[i]! + F.cell / 2
  const x0 = Math.max(0, Math.floor((F.x[i]! - R - minX) / cell))
  const x1 = Math.min(cols - 1, Math.floor((F.x[i]! + R - minX) / cell))
  const y0 = Math.max(0, Math.floor((F.y[i]! - R - minY) / cell))
  const y1 = Math.min(rows - 1, Math.floor((F.y[i]! + R - minY) / cell))
  if (x1 < x0 || y1 < y0) return
  const start = F.start
  for (let gy = y0; gy <= y1; gy++) {
    for (let q = start[gy * cols + x0]!, e = start[gy * cols + x1 + 1]!; q < e; q++) {
      const j = F.si[q]!
      if (close(F, i, j)) pushPair(F, i < j ? i : j, i < j ? j : i)
    }
  }
}

/** The cell-start array for `cells` cells (and the per-cell fill counters). */
function reserveCells(F: FixedContactState, cells: number): Int32Array {
  if (F.start.length < cells + 2) {
    let len = F.start.length
    while (len < cells + 2) len *= 2
    F.start = new Int32Array(len)
    F.fill = new Int32Array(len)
  }
  return F.start
}
