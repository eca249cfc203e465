// Union-find over a tick's packed candidates, for the rules that move or hold rows of balls together
// (src/contacts/fixedJam.ts, fixedShock.ts). A join hangs the higher root under the lower, so a group's
// root is its lowest candidate whatever the order of the joins; lookups halve the path as they go. And the
// test both rules make of a group being a row: its pairs' normals on one line.
import { ROW_LINE_COS } from '../config/tolerances.js'

/** The root of candidate i's group. */
export function rootOf(parent: Int32Array, i: number): number {
  while (parent[i] !== i) {
    const g = parent[parent[i]!]!
    parent[i] = g
    i = g
  }
  return i
}

/** Joins the groups of candidates a and b; whether they were apart. */
export function unite(parent: Int32Array, a: number, b: number): boolean {
  const ra = rootOf(parent, a)
  const rb = rootOf(parent, b)
  if (ra === rb) return false
  join(parent, ra, rb)
  return true
}

/** Joins the groups of roots ra ≠ rb, the higher root under the lower; the joined group's root. */
function join(parent: Int32Array, ra: number, rb: number): number {
  const r = ra < rb ? ra : rb
  parent[ra < rb ? rb : ra] = r
  return r
}

/**
 * unite, keeping each root's group size in `size` (1 for a candidate alone): the joined group's size, or 0
 * when a and b were in one group already.
 */
export function uniteSized(parent: Int32Array, size: Int32Array, a: number, b: number): number {
  const ra = rootOf(parent, a)
  const rb = rootOf(parent, b)
  if (ra === rb) return 0
  const joined = size[ra]! + size[rb]!
  size[join(parent, ra, rb)] = joined
  return joined
}

/**
 * Whether pair p's normal (normalX/normalY[p]) keeps to the line of the group rooted at r, to within
 * ROW_LINE_COS; the group's first pair sets its line (lineX/lineY[r], 0 and 0 until then). Indices in: no
 * double crosses the call.
 */
export function keepsLine(lineX: Float64Array, lineY: Float64Array, r: number, normalX: Float64Array, normalY: Float64Array, p: number): boolean {
  if (lineX[r] === 0 && lineY[r] === 0) {
    lineX[r] = normalX[p]!
    lineY[r] = normalY[p]!
    return true
  }
  return Math.abs(lineX[r]! * normalX[p]! + lineY[r]! * normalY[p]!) >= ROW_LINE_COS
}
