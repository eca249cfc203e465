// Fixed-tick contacts: a ball the velocity solve made faster than it was when the tick's pairs were found
// (a struck ball at rest, the last ball of a row) can now reach balls it was not paired with, and would
// move into them before the next tick. After each solve round, every such ball's reach is widened to its
// new speed and it is paired again: with the candidates in the tick's grid and the big ones, and with the
// resting balls now in its reach (they join the candidates). The solve then runs again over all pairs.
// At most MAX_WIDEN_ROUNDS rounds a tick (src/config/tolerances.ts): a chain longer than that is caught
// at the next tick, by the projection.
import { PROJECTION_SLOP, TOUCH_GAP } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import { pushPair, reserveCandidates, type FixedContactState } from '../world/fixedState.js'
import { markWall, seedResting } from './fixedGrid.js'

/** Widens the reach of the candidates the last round sped up and pairs them again; false when none did. */
export function widenReach(w: BallWorld, F: FixedContactState): boolean {
  const tick = F.tick
  F.widenedCount = 0
  let widest = 0
  for (let h = 0; h < F.hitCount; h++) {
    const i = F.hit[h]!
    const vx = F.vx[i]!
    const vy = F.vy[i]!
    const wide = F.r[i]! + Math.sqrt(vx * vx + vy * vy) * tick + TOUCH_GAP
    // wider by no more than the projection's slop: at worst it moves that far into a neighbour, which the
    // next tick's projection takes out
    if (!(wide > F.reach[i]! + PROJECTION_SLOP)) continue
    F.wide[i] = wide
    F.grown[i] = 1
    F.widened[F.widenedCount++] = i
    if (wide > widest) widest = wide
  }
  if (F.widenedCount === 0) return false
  const smallReach = Math.max(F.cell / 2, widest)
  const restFrom = F.n
  for (let k = 0; k < F.widenedCount; k++) {
    const g = F.widened[k]!
    pairInGrid(F, g, F.wide[g]! + smallReach)
    for (let m = 0; m < F.bigCount; m++) consider(F, g, F.big[m]!)
    // resting balls not yet candidates (the gather's seen stamps skip those that are)
    seedResting(w, F, F.x[g]!, F.y[g]!, F.wide[g]!)
  }
  addResting(w, F, restFrom)
  for (let k = 0; k < F.widenedCount; k++) {
    const g = F.widened[k]!
    F.reach[g] = F.wide[g]!
    F.grown[g] = 0
    markWall(F, g)
  }
  return true
}

/** Pairs widened candidate g with the small candidates of the grid cells within `range` of it. */
function pairInGrid(F: FixedContactState, g: number, range: number): void {
  if (F.cols === 0) return
  const cell = F.gridCell
  const x0 = Math.max(0, Math.floor((F.x[g]! - range - F.minX) / cell))
  const x1 = Math.min(F.cols - 1, Math.floor((F.x[g]! + range - F.minX) / cell))
  const y0 = Math.max(0, Math.floor((F.y[g]! - range - F.minY) / cell))
  const y1 = Math.min(F.rows - 1, Math.floor((F.y[g]! + range - F.minY) / cell))
  if (x1 < x0 || y1 < y0) return
  for (let gy = y0; gy <= y1; gy++) {
    for (let q = F.start[gy * F.cols + x0]!, e = F.start[gy * F.cols + x1 + 1]!; q < e; q++) consider(F, g, F.si[q]!)
  }
}

/**
 * Pairs g with j when they can touch within the tick at their new reaches but could not at the reaches
 * they were paired with (so no pair is listed twice); a pair of two widened candidates is listed from the
 * lower index.
 */
function consider(F: FixedContactState, g: number, j: number): void {
  if (j === g || (F.grown[j] === 1 && j < g)) return
  const dx = F.x[j]! - F.x[g]!
  const dy = F.y[j]! - F.y[g]!
  const d2 = dx * dx + dy * dy
  const now = F.wide[g]! + (F.grown[j] === 1 ? F.wide[j]! : F.reach[j]!)
  const before = F.reach[g]! + F.reach[j]!
  if (d2 >= now * now || d2 < before * before) return
  pushPair(F, g < j ? g : j, g < j ? j : g)
}

/** Gives the resting balls that joined (ids from index `from`) their candidate data and pairs them with the widened candidates. */
function addResting(w: BallWorld, F: FixedContactState, from: number): void {
  if (F.n === from) return
  reserveCandidates(F, F.n)
  const B = w.Ball
  for (let k = from; k < F.n; k++) {
    const eid = F.id[k]!
    F.x[k] = B.x[eid]!
    F.y[k] = B.y[eid]!
    F.r[k] = B.radius[eid]!
    F.vx[k] = 0
    F.vy[k] = 0
    F.im[k] = 1 / F.mass[eid]!
    F.reach[k] = B.radius[eid]! + TOUCH_GAP
    F.changed[k] = 0
    F.grown[k] = 0
    markWall(F, k)
    for (let m = 0; m < F.widenedCount; m++) {
      const g = F.widened[m]!
      const dx = F.x[k]! - F.x[g]!
      const dy = F.y[k]! - F.y[g]!
      const s = F.wide[g]! + F.reach[k]!
      if (dx * dx + dy * dy < s * s) pushPair(F, g < k ? g : k, g < k ? k : g)
    }
  }
}
