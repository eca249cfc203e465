// The holes packed for the planner's scan: x, y, R per hole and the entity ids, in the order they were
// added (events at equal distances are ordered by hole id, so the order here never decides an outcome).
import type { BallWorld } from './createWorld.js'
import { GRID_MIN_HOLES } from '../config/tolerances.js'
import { bigFrom, buildHoleGrid } from './holeGrid.js'

/** Holes packed for the planner's scan: x, y, R per hole, and the entity ids in the same order. */
export interface HoleTable {
  count: number
  xyr: Float64Array
  ids: Uint32Array
}

/**
 * The holes by cell (entity ids in a hash of cells `cell` px wide), for the overlap check of a hole being
 * added: derived from the table when first needed (not part of a snapshot), then kept up to date.
 */
export interface HoleCells {
  cell: number
  byCell: Map<number, number[]>
  /** the largest lip radius among the holes in the cells (a lookup widens by it), px */
  maxR: number
  /**
   * holes wider than a cell, kept out of the cells and tested by every lookup (sized for one of radius 1e4,
   * the cells held every hole, and each addHole scanned them all); past WIDE_HOLES the cells are built again
   */
  wide: number[]
}

/** Most holes kept out of the cells before they are built again for the holes as they are. */
const WIDE_HOLES = 16

export function createHoleTable(): HoleTable {
  return { count: 0, xyr: new Float64Array(3 * 16), ids: new Uint32Array(16) }
}

function cellsOf(world: BallWorld): HoleCells {
  if (world.holeCells !== null) return world.holeCells
  const t = world.holes
  // cells 4× the widest hole but the few far wider than the rest (src/world/holeGrid.ts: bigRadius), and no
  // narrower than 4 × HOLE_RADIUS (cells sized for specks made each lookup for a hole of the usual size span
  // more cells than there are holes, and scan them all)
  const limit = bigFrom(t)
  let base = 0
  for (let i = 0; i < t.count; i++) {
    const R = t.xyr[3 * i + 2]!
    if (R <= limit && R > base) base = R
  }
  const cells: HoleCells = { cell: 4 * Math.max(base, world.config.HOLE_RADIUS), byCell: new Map(), maxR: 0, wide: [] }
  world.holeCells = cells
  for (let i = 0; i < t.count; i++) putInCell(world, cells, t.ids[i]!, t.xyr[3 * i]!, t.xyr[3 * i + 1]!, t.xyr[3 * i + 2]!)
  return cells
}

function putInCell(world: BallWorld, cells: HoleCells, eid: number, x: number, y: number, R: number): void {
  if (R > cells.cell) {
    cells.wide.push(eid)
    // (more than a few: built again, for the holes as they are, when next needed)
    if (cells.wide.length > WIDE_HOLES && world.holeCells === cells) world.holeCells = null
    return
  }
  const key = cellKey(Math.floor(x / cells.cell), Math.floor(y / cells.cell))
  const bucket = cells.byCell.get(key)
  if (bucket === undefined) cells.byCell.set(key, [eid])
  else bucket.push(eid)
  if (R > cells.maxR) cells.maxR = R
}

/** The hash key of cell (cx, cy); cells far apart may share one (a lookup checks distances). */
export function cellKey(cx: number, cy: number): number {
  return Math.imul(cx | 0, 73856093) ^ Math.imul(cy | 0, 19349663)
}

/** Appends a hole to the planner's table. */
export function addHoleToTable(world: BallWorld, eid: number): void {
  const t = world.holes
  if (t.count === t.ids.length) {
    const xyr = new Float64Array(t.xyr.length * 2)
    xyr.set(t.xyr)
    const ids = new Uint32Array(t.ids.length * 2)
    ids.set(t.ids)
    t.xyr = xyr
    t.ids = ids
  }
  const i = t.count++
  t.xyr[3 * i] = world.Hole.x[eid]!
  t.xyr[3 * i + 1] = world.Hole.y[eid]!
  t.xyr[3 * i + 2] = world.Hole.radius[eid]!
  t.ids[i] = eid
  if (world.holeCells !== null) putInCell(world, world.holeCells, eid, world.Hole.x[eid]!, world.Hole.y[eid]!, world.Hole.radius[eid]!)
  world.holeGrid.dirty = true
}

/**
 * True when `eid` is a hole of the simulation: one addHole (or a restore) put in the table, whose row holds its
 * radius (> 0) until it is removed. A Hole component a game adds by hand makes no such row, and no hole.
 */
export function isLiveHole(world: BallWorld, eid: number): boolean {
  const r = world.Hole.radius
  return eid > 0 && eid < r.length && r[eid]! > 0
}

/** Takes a hole out of the planner's table, keeping the others in order; a no-op if it is not there. */
export function removeHoleFromTable(world: BallWorld, eid: number): void {
  const t = world.holes
  let i = 0
  while (i < t.count && t.ids[i] !== eid) i++
  if (i === t.count) return
  const cells = world.holeCells
  const w = cells === null ? -1 : cells.wide.indexOf(eid)
  if (cells !== null && w >= 0) cells.wide.splice(w, 1)
  else if (cells !== null) {
    const key = cellKey(Math.floor(t.xyr[3 * i]! / cells.cell), Math.floor(t.xyr[3 * i + 1]! / cells.cell))
    const bucket = cells.byCell.get(key)!
    bucket.splice(bucket.indexOf(eid), 1)
    if (bucket.length === 0) cells.byCell.delete(key)
  }
  t.ids.copyWithin(i, i + 1, t.count)
  t.xyr.copyWithin(3 * i, 3 * (i + 1), 3 * t.count)
  t.count--
  world.holeGrid.dirty = true
}

/**
 * The hole whose lip circle contains (x, y) (strictly inside), or 0. Lip circles never overlap, so there is
 * at most one. From the hole count at which the planner walks the hole grid, the holes kept out of the grid
 * and those of the 3 × 3 cells around the point (one list of the grid: a cell is at least as wide as the
 * largest lip radius in it); below it, every hole. Only a hole wider than `radius` (a ball's: one not
 * smaller than the hole bridges it).
 */
export function holeAt(world: BallWorld, x: number, y: number, radius = 0): number {
  const t = world.holes
  if (t.count > 0 && t.count >= world.gridFrom) {
    const g = world.holeGrid
    if (g.dirty) buildHoleGrid(g, t, Math.max(g.ballRadius, world.config.BALL_RADIUS))
    // the few holes kept out of the grid (src/world/holeGrid.ts)
    for (let k = 0; k < g.bigCount; k++) {
      const i = g.big[k]!
      const dx = x - t.xyr[3 * i]!
      const dy = y - t.xyr[3 * i + 1]!
      const R = t.xyr[3 * i + 2]!
      if (dx * dx + dy * dy < R * R) return R > radius ? t.ids[i]! : 0
    }
    const cx = Math.floor((x - g.minX) / g.cell)
    const cy = Math.floor((y - g.minY) / g.cell)
    // outside the grid's padded box: farther than a cell from every hole
    if (!(cx >= 0 && cx < g.nx && cy >= 0 && cy < g.ny)) return 0
    const c = cy * g.nx + cx
    for (let k = g.start[c]!; k < g.start[c + 1]!; k++) {
      const i = g.items[k]!
      const dx = x - t.xyr[3 * i]!
      const dy = y - t.xyr[3 * i + 1]!
      const R = t.xyr[3 * i + 2]!
      if (dx * dx + dy * dy < R * R) return R > radius ? t.ids[i]! : 0
    }
    return 0
  }
  for (let i = 0; i < t.count; i++) {
    const dx = x - t.xyr[3 * i]!
    const dy = y - t.xyr[3 * i + 1]!
    const R = t.xyr[3 * i + 2]!
    if (dx * dx + dy * dy < R * R) return R > radius ? t.ids[i]! : 0
  }
  return 0
}

/**
 * A hole whose lip circle overlaps the circle (x, y, radius) (entity id), or 0: from the holes kept out of
 * the cells and the cells within radius + the largest lip radius in them of the point, or, when those cells
 * are more than the holes, every hole.
 */
export function overlappingHole(world: BallWorld, x: number, y: number, radius: number): number {
  const t = world.holes
  const cells = t.count < GRID_MIN_HOLES ? null : cellsOf(world)
  if (cells !== null) {
    const H = world.Hole
    for (let k = 0; k < cells.wide.length; k++) {
      const h = cells.wide[k]!
      const dx = x - H.x[h]!
      const dy = y - H.y[h]!
      const min = radius + H.radius[h]!
      if (dx * dx + dy * dy < min * min) return h
    }
  }
  const reach = cells === null ? 0 : radius + cells.maxR
  const c = cells === null ? 1 : cells.cell
  const cx0 = Math.floor((x - reach) / c)
  const cx1 = Math.floor((x + reach) / c)
  const cy0 = Math.floor((y - reach) / c)
  const cy1 = Math.floor((y + reach) / c)
  if (cells === null || (cx1 - cx0 + 1) * (cy1 - cy0 + 1) > t.count) {
    for (let i = 0; i < t.count; i++) {
      const dx = x - t.xyr[3 * i]!
      const dy = y - t.xyr[3 * i + 1]!
      const min = radius + t.xyr[3 * i + 2]!
      if (dx * dx + dy * dy < min * min) return t.ids[i]!
    }
    return 0
  }
  const H = world.Hole
  for (let cy = cy0; cy <= cy1; cy++) {
    for (let cx = cx0; cx <= cx1; cx++) {
      const bucket = cells.byCell.get(cellKey(cx, cy))
      if (bucket === undefined) continue
      for (let k = 0; k < bucket.length; k++) {
        const h = bucket[k]!
        const dx = x - H.x[h]!
        const dy = y - H.y[h]!
        const min = radius + H.radius[h]!
        if (dx * dx + dy * dy < min * min) return h
      }
    }
  }
  return 0
}
