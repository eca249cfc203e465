// The holes packed for the planner's scan: x, y, R per hole and the entity ids, in the order they were
// added (events at equal distances are ordered by hole id, so the order here never decides an outcome).
import type { BallWorld } from './createWorld.js'
import { buildHoleGrid } from './holeGrid.js'

/** Holes packed for the planner's scan: x, y, R per hole, and the entity ids in the same order. */
export interface HoleTable {
  count: number
  xyr: Float64Array
  ids: Uint32Array
}

export function createHoleTable(): HoleTable {
  return { count: 0, xyr: new Float64Array(3 * 16), ids: new Uint32Array(16) }
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
  world.holeGrid.dirty = true
}

/** Takes a hole out of the planner's table, keeping the others in order; a no-op if it is not there. */
export function removeHoleFromTable(world: BallWorld, eid: number): void {
  const t = world.holes
  let i = 0
  while (i < t.count && t.ids[i] !== eid) i++
  if (i === t.count) return
  t.ids.copyWithin(i, i + 1, t.count)
  t.xyr.copyWithin(3 * i, 3 * (i + 1), 3 * t.count)
  t.count--
  world.holeGrid.dirty = true
}

/**
 * The hole whose lip circle contains (x, y) (strictly inside), or 0. Lip circles never overlap, so there is
 * at most one. From the hole count at which the planner walks the hole grid, the 3 × 3 cells around the
 * point (a cell is at least as wide as the largest lip radius); below it, every hole.
 */
export function holeAt(world: BallWorld, x: number, y: number): number {
  const t = world.holes
  if (t.count > 0 && t.count >= world.gridFrom) {
    const g = world.holeGrid
    if (g.dirty) buildHoleGrid(g, t, Math.max(g.ballRadius, world.config.BALL_RADIUS))
    const cx = Math.floor((x - g.minX) / g.cell)
    const cy = Math.floor((y - g.minY) / g.cell)
    for (let gy = Math.max(0, cy - 1); gy <= Math.min(g.ny - 1, cy + 1); gy++) {
      for (let gx = Math.max(0, cx - 1); gx <= Math.min(g.nx - 1, cx + 1); gx++) {
        const c = gy * g.nx + gx
        for (let k = g.start[c]!; k < g.start[c + 1]!; k++) {
          const i = g.items[k]!
          const dx = x - t.xyr[3 * i]!
          const dy = y - t.xyr[3 * i + 1]!
          const R = t.xyr[3 * i + 2]!
          if (dx * dx + dy * dy < R * R) return t.ids[i]!
        }
      }
    }
    return 0
  }
  for (let i = 0; i < t.count; i++) {
    const dx = x - t.xyr[3 * i]!
    const dy = y - t.xyr[3 * i + 1]!
    const R = t.xyr[3 * i + 2]!
    if (dx * dx + dy * dy < R * R) return t.ids[i]!
  }
  return 0
}

/** Index in the table of the first hole whose lip circle overlaps the circle (x, y, radius), or −1. */
export function overlappingHole(world: BallWorld, x: number, y: number, radius: number): number {
  const t = world.holes
  for (let i = 0; i < t.count; i++) {
    const dx = x - t.xyr[3 * i]!
    const dy = y - t.xyr[3 * i + 1]!
    const min = radius + t.xyr[3 * i + 2]!
    if (dx * dx + dy * dy < min * min) return i
  }
  return -1
}
