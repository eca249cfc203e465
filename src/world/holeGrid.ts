// Hole broadphase: a uniform grid over the hole centres, walked along a ball's straight path, so that
// planning a path costs the cells it crosses instead of every hole on the panel.
//
// Cells are at least as wide as the farthest a hole can matter to a path (R + r: a near miss), so every
// hole whose events a path can meet lies in the 3 × 3 block around a cell the path's centre line crosses;
// each cell lists the holes of its block (built once per change of the holes), so the walk reads one list
// a cell (reading the nine cells of each block measured 0.9× / 0.93× the step on the 1,000-ball panel
// without / with contacts, side by side).
// The walk goes cell by cell in order of distance; a hole not yet seen when the walk enters a cell at
// distance t has its closest approach beyond t, so none of its events comes before t − R_max, and the walk
// stops once t − R_max passes the best event found.
// A few holes far wider than the rest (at most BIG_HOLES, each over 4× the median radius) are kept out of
// the grid and visited by every walk: sized for them, the cells held every hole of a panel (one hole of
// radius 1e4 far off among 3,600 of 18 px made a step of 1,000 balls 25× slower: npm run bench:big-hole).
import { MAX_GRID_CELLS } from '../config/tolerances.js'
import type { HoleTable } from './createWorld.js'

export interface HoleGrid {
  /** the table changed since the grid was built */
  dirty: boolean
  /** holes in the table when built */
  built: number
  cell: number
  minX: number
  minY: number
  nx: number
  ny: number
  /**
   * CSR: the holes of the 3 × 3 block of cells around cell c are items[start[c] .. start[c + 1]) (indices
   * into the hole table; each hole is listed by the up to 9 cells around its own)
   */
  start: Int32Array
  items: Int32Array
  /** largest radius of the holes in the grid, px */
  maxRadius: number
  /** the holes kept out of the grid (table indices), visited by every walk: big[0 .. bigCount) */
  big: Int32Array
  bigCount: number
  /**
   * ball radius the cell size was chosen for (at most maxRadius); a ball wider than it and narrower than
   * maxRadius has the grid built again for it, one at least maxRadius wide meets no hole of the grid
   */
  ballRadius: number
  /** per table index: the query that last saw the hole (dedupe across overlapping 3 × 3 blocks) */
  seen: Uint32Array
  query: number
}

export function createHoleGrid(): HoleGrid {
  return {
    dirty: true,
    built: 0,
    cell: 1,
    minX: 0,
    minY: 0,
    nx: 0,
    ny: 0,
    start: new Int32Array(1),
    items: new Int32Array(0),
    maxRadius: 0,
    big: new Int32Array(0),
    bigCount: 0,
    ballRadius: 0,
    seen: new Uint32Array(0),
    query: 0,
  }
}


/** Builds the grid for the holes in `table`, sized for balls up to `ballRadius` (and so for any ball, from the widest hole's radius on). */
export function buildHoleGrid(grid: HoleGrid, table: HoleTable, ballRadius: number): void {
  const n = table.count
  const xyr = table.xyr
  const limit = bigFrom(table)
  if (grid.big.length < n) grid.big = new Int32Array(n)
  grid.bigCount = 0
  let minX = Infinity
  let minY = Infinity
  let maxX = -Infinity
  let maxY = -Infinity
  let maxR = 0
  for (let i = 0; i < n; i++) {
    if (xyr[3 * i + 2]! > limit) {
      grid.big[grid.bigCount++] = i
      continue
    }
    const x = xyr[3 * i]!
    const y = xyr[3 * i + 1]!
    if (x < minX) minX = x
    if (x > maxX) maxX = x
    if (y < minY) minY = y
    if (y > maxY) maxY = y
    if (xyr[3 * i + 2]! > maxR) maxR = xyr[3 * i + 2]!
  }
  // a ball no smaller than a hole bridges it (no event: src/motion/rolling.ts), so a hole of the grid matters
  // only to balls narrower than it, and cells of maxR + min(ballRadius, maxR) serve balls of any radius: one
  // very wide ball does not make every cell hold the whole field, for as long as the world lives
  const forBalls = Math.min(ballRadius, maxR)
  let cell = maxR + forBalls
  // one cell of padding on every side, so a path point within R + r of a hole is inside the grid
  let nx = Math.floor((maxX - minX) / cell) + 3
  let ny = Math.floor((maxY - minY) / cell) + 3
  while (nx * ny > MAX_GRID_CELLS) {
    cell *= 2
    nx = Math.floor((maxX - minX) / cell) + 3
    ny = Math.floor((maxY - minY) / cell) + 3
  }
  grid.cell = cell
  grid.minX = minX - cell
  grid.minY = minY - cell
  grid.nx = nx
  grid.ny = ny
  grid.maxRadius = maxR
  grid.ballRadius = forBalls
  const start = new Int32Array(nx * ny + 1)
  const cellOf = new Int32Array(n).fill(-1)
  for (let i = 0; i < n; i++) {
    if (xyr[3 * i + 2]! > limit) continue
    const cx = Math.floor((xyr[3 * i]! - grid.minX) / cell)
    const cy = Math.floor((xyr[3 * i + 1]! - grid.minY) / cell)
    const c = cy * nx + cx
    cellOf[i] = c
    start[c + 1]!++
  }
  for (let c = 0; c < nx * ny; c++) start[c + 1]! += start[c]!
  const fill = start.slice(0, nx * ny)
  const own = new Int32Array(n)
  for (let i = 0; i < n; i++) if (cellOf[i]! >= 0) own[fill[cellOf[i]!]!++] = i
  // each cell lists the holes of the 3 × 3 block around it, block row by block row, each cell's in table
  // order: the walk then reads one list a cell it crosses, and meets the same holes in the same order
  // (each hole is listed by at most 9 cells)
  const block = new Int32Array(nx * ny + 1)
  const items = new Int32Array(9 * n)
  for (let cy = 0, o = 0; cy < ny; cy++) {
    for (let cx = 0; cx < nx; cx++) {
      for (let by = Math.max(0, cy - 1); by <= Math.min(ny - 1, cy + 1); by++) {
        for (let bx = Math.max(0, cx - 1); bx <= Math.min(nx - 1, cx + 1); bx++) {
          for (let k = start[by * nx + bx]!, e = start[by * nx + bx + 1]!; k < e; k++) items[o++] = own[k]!
        }
      }
      block[cy * nx + cx + 1] = o
    }
  }
  grid.start = block
  grid.items = items
  // stamps from before the rebuild must not read as seen: start them afresh
  if (grid.seen.length < n) grid.seen = new Uint32Array(Math.max(n, 2 * grid.seen.length))
  else grid.seen.fill(0)
  grid.query = 0
  grid.built = n
  grid.dirty = false
}

/** Most holes kept out of the grid as far wider than the rest. */
const BIG_HOLES = 16

/** bigRadius of the table's holes */
export function bigFrom(table: HoleTable): number {
  const n = table.count
  const r = new Float64Array(n)
  for (let i = 0; i < n; i++) r[i] = table.xyr[3 * i + 2]!
  return bigRadius(r)
}

/**
 * The radius above which a hole is far wider than the rest (kept out of a grid's cells): more than 4× the
 * median radius and more than all but the BIG_HOLES widest (Infinity when there are no more holes than
 * that). Sorts `radii` in place.
 */
export function bigRadius(radii: Float64Array): number {
  const n = radii.length
  if (n <= BIG_HOLES) return Infinity
  radii.sort()
  return Math.max(4 * radii[n >> 1]!, radii[n - 1 - BIG_HOLES]!)
}

/** Visits a table index and writes the best event distance found so far into walk[W_BOUND]. */
export type HoleVisitor = (index: number) => void

/**
 * The walk's numbers, in and out: the ray from (x, y) along the unit direction (ux, uy), the distance it
 * starts at, and the stopping bound (the best event distance known before the walk, then lowered by the
 * visitor as it finds earlier events). Slots of a typed array, not arguments and a return value: a double
 * passed to or returned from a call V8 does not inline is boxed, a heap number for every path planned and
 * every hole visited.
 */
export const walk = new Float64Array(6)
export const W_X = 0
export const W_Y = 1
export const W_UX = 2
export const W_UY = 3
export const W_FROM = 4
export const W_BOUND = 5

/**
 * Calls `visit` once for every hole that may have an event on the ray in `walk` beyond its start distance,
 * nearest cells first. The walk stops when no unseen hole can beat the bound (walk[W_BOUND]).
 */
export function walkHoleGrid(grid: HoleGrid, visit: HoleVisitor): void {
  const x = walk[W_X]!
  const y = walk[W_Y]!
  const ux = walk[W_UX]!
  const uy = walk[W_UY]!
  const from = walk[W_FROM]!
  let best = walk[W_BOUND]!
  if (++grid.query === 0xffffffff) {
    grid.seen.fill(0)
    grid.query = 1
  }
  const q = grid.query
  // the holes kept out of the grid, first (the order of visits decides nothing: events at equal distances
  // go by hole id)
  for (let k = 0; k < grid.bigCount; k++) {
    const i = grid.big[k]!
    grid.seen[i] = q
    visit(i)
    best = walk[W_BOUND]!
  }
  const cell = grid.cell
  const nx = grid.nx
  const ny = grid.ny
  // clip the ray to the grid's box
  const x0 = grid.minX
  const y0 = grid.minY
  const x1 = x0 + nx * cell
  const y1 = y0 + ny * cell
  let tMin = from
  let tMax = Infinity
  if (ux !== 0) {
    const ta = (x0 - x) / ux
    const tb = (x1 - x) / ux
    tMin = Math.max(tMin, Math.min(ta, tb))
    tMax = Math.min(tMax, Math.max(ta, tb))
  } else if (x < x0 || x >= x1) return
  if (uy !== 0) {
    const ta = (y0 - y) / uy
    const tb = (y1 - y) / uy
    tMin = Math.max(tMin, Math.min(ta, tb))
    tMax = Math.min(tMax, Math.max(ta, tb))
  } else if (y < y0 || y >= y1) return
  if (tMin > tMax || tMin - grid.maxRadius > best) return
  const px = x + ux * tMin
  const py = y + uy * tMin
  let cx = Math.min(nx - 1, Math.max(0, Math.floor((px - x0) / cell)))
  let cy = Math.min(ny - 1, Math.max(0, Math.floor((py - y0) / cell)))
  const stepX = ux > 0 ? 1 : -1
  const stepY = uy > 0 ? 1 : -1
  // (1 / 0 for Infinity: the global, in a branch V8 has not seen run, boxes the walk's doubles)
  let tNextX = ux !== 0 ? tMin + (x0 + (cx + (ux > 0 ? 1 : 0)) * cell - px) / ux : 1 / 0
  let tNextY = uy !== 0 ? tMin + (y0 + (cy + (uy > 0 ? 1 : 0)) * cell - py) / uy : 1 / 0
  const dX = ux !== 0 ? cell / Math.abs(ux) : 1 / 0
  const dY = uy !== 0 ? cell / Math.abs(uy) : 1 / 0
  const start = grid.start
  const items = grid.items
  const seen = grid.seen
  const reach = grid.maxRadius
  let tEnter = tMin
  for (;;) {
    // the holes of the 3 × 3 block around the cell (listed with it)
    const c = cy * nx + cx
    for (let k = start[c]!, e = start[c + 1]!; k < e; k++) {
      const i = items[k]!
      if (seen[i] === q) continue
      seen[i] = q
      visit(i)
      best = walk[W_BOUND]!
    }
    if (tNextX < tNextY) {
      tEnter = tNextX
      cx += stepX
      tNextX += dX
      if (cx < 0 || cx >= nx) return
    } else {
      tEnter = tNextY
      cy += stepY
      tNextY += dY
      if (cy < 0 || cy >= ny) return
    }
    if (tEnter > tMax || tEnter - reach > best) return
  }
}
