// The fixed-tick projection's pass out from the walls (config.BALL_COLLISIONS = 'fixed'), after sweeps that
// ran out with overlaps left (src/contacts/fixedProject.ts): shock propagation for positions. Balls touching a
// closed wall are taken first, then each row (ROW_MIN_BALLS or more along one line) no wall holds from one
// of its balls; each ball is moved out of those already taken, which stay where they are. Positions only: no
// kinetic energy is added.
import { PROJECTION_SLOP, ROW_LINE_COS, ROW_MIN_BALLS } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import type { FixedContactState } from '../world/fixedState.js'
import { walls } from './fixedGrid.js'
import { buildAdjacency, normal, nrm } from './fixedPairs.js'
import { keepInside, pushApart } from './fixedPush.js'
import { MOVED } from './fixedWallTurn.js'

/**
 * The sweeps ran out with overlaps left: a row or a pile pressed into a closed wall, or a row pressed
 * within itself, where each sweep moves a push only a ball or two along (a ball held by the wall hands its
 * whole share on, the next splits it with the one behind). Out from the walls instead, as shock propagation
 * does: the balls touching a closed wall first, then each ball that overlaps or touches one already taken,
 * nearest that ball's wall first (by where the balls were before this), each moved out of every ball already
 * taken that it overlaps (those are where they end), along the pair's normal before any moved (along). Then
 * each row no wall holds with an overlap deeper than the slop left in it, from one of its balls
 * (anchorOfGroup), or from the balls taken from a wall that the tick paired it with (seedFromTaken): every
 * ball the tick paired with one already taken, nearest that ball (or its wall) first.
 * Then one more full sweep. Positions only. True when no overlap deeper than PROJECTION_SLOP is left.
 */
export function layered(w: BallWorld, F: FixedContactState): boolean {
  const n = F.n
  const pairs = F.pairCount
  if (pairs === 0) return false
  if (heap.length < n) {
    heap = new Int32Array(2 * n)
    key = new Float64Array(2 * n)
    x0 = new Float64Array(2 * n)
    y0 = new Float64Array(2 * n)
    state = new Uint8Array(2 * n)
    face = new Uint8Array(2 * n)
    stack = new Int32Array(2 * n)
    group = new Int32Array(2 * n)
  }
  buildAdjacency(F)
  let size = 0
  for (let i = 0; i < n; i++) {
    x0[i] = F.x[i]!
    y0[i] = F.y[i]!
    state[i] = 0
    if (w.walls === 0) continue
    // touching a closed wall: taken first, from that wall
    nearestWall(F, i)
    const d = lay[L_GAP]!
    if (!(d <= PROJECTION_SLOP)) continue
    face[i] = wallFace
    key[i] = d
    state[i] = 1
    size = push(i, size)
  }
  let seeded = size > 0
  spread(w, F, size, false)
  // a row no wall holds (pressed within itself, or just off the walls) is taken from one of its balls,
  // which stays where it is, the others nearest it (or its wall) first; a pile is left to the sweeps
  for (let p = 0; p < pairs; p++) {
    const a = F.pairA[p]!
    const b = F.pairB[p]!
    if (state[a] !== 0 || state[b] !== 0) continue
    normal(F, a, b)
    if (!(nrm.gap < -PROJECTION_SLOP)) continue
    const v = anchorOfGroup(w, F, a)
    if (!groupIsRow) continue
    // a row paired with balls already taken from a wall goes on from those, as if it touched them; else
    // from its anchor
    let from = seedFromTaken(F)
    if (from === 0) from = seedAnchor(w, F, v)
    seeded = true
    anchoredRuns++
    spread(w, F, from, true)
  }
  if (!seeded) return false
  // one full sweep for what that leaves (a ball held by a wall, a push across the order)
  let worst = 0
  for (let p = 0; p < pairs; p++) {
    normal(F, F.pairA[p]!, F.pairB[p]!)
    const gap = nrm.gap
    if (!(gap < 0)) continue
    pushApart(w, F, p)
    if (-gap > worst) worst = -gap
  }
  return worst <= PROJECTION_SLOP
}

/**
 * layered's pass from the balls in its heap (size of them): each ball taken moved out of every ball already
 * taken that it overlaps (those are where they end), along the pair's normal before any moved (along); then
 * the balls that overlap or touch it where it is now (anyPair: every ball paired with it) join the heap, by
 * their distance before the pass to its wall (or to its group's anchor). A ball left clear of those taken
 * does not move.
 */
function spread(w: BallWorld, F: FixedContactState, size: number, anyPair: boolean): void {
  while (size > 0) {
    const v = heap[0]!
    size = pop(size)
    for (let q = F.adjStart[v]!, e = F.adjStart[v + 1]!; q < e; q++) {
      const p = F.adjPairs[q]!
      const u = F.pairA[p] === v ? F.pairB[p]! : F.pairA[p]!
      if (state[u] !== 2) continue
      along(F, u, v)
      const gap = lay[L_GAP]!
      if (!(gap < 0)) continue
      F.x[v] = F.x[v]! - gap * lay[L_X]!
      F.y[v] = F.y[v]! - gap * lay[L_Y]!
      keepInside(w, F, v)
      F.changed[v]! |= MOVED
    }
    state[v] = 2
    for (let q = F.adjStart[v]!, e = F.adjStart[v + 1]!; q < e; q++) {
      const p = F.adjPairs[q]!
      const u = F.pairA[p] === v ? F.pairB[p]! : F.pairA[p]!
      if (state[u] !== 0) continue
      if (!anyPair) {
        along(F, v, u)
        if (!(lay[L_GAP]! < PROJECTION_SLOP)) continue
      }
      face[u] = face[v]!
      if (face[u] === FROM_BALL) {
        const dx = x0[u]! - x0[anchorBall]!
        const dy = y0[u]! - y0[anchorBall]!
        key[u] = Math.sqrt(dx * dx + dy * dy)
      } else {
        toFace(F, u, face[u]!, true)
        key[u] = lay[L_GAP]!
      }
      state[u] = 1
      size = push(u, size)
    }
  }
}

/** Candidate i's gap to its nearest closed wall (Infinity if none) into lay[L_GAP], that wall's face into wallFace. */
function nearestWall(F: FixedContactState, i: number): void {
  let d = Infinity
  let f = 0
  for (let k = 0; k < 4; k++) {
    toFace(F, i, k, false)
    if (lay[L_GAP]! < d) {
      d = lay[L_GAP]!
      f = k
    }
  }
  lay[L_GAP] = d
  wallFace = f
}

let wallFace = 0

/**
 * The ball a group no wall holds is taken from (the group of ball s: the balls not yet taken linked to it
 * through the tick's pairs): its ball nearest a closed wall when that one can reach the wall within the tick,
 * or is nearer it than the group's overlaps add up to (a push toward the wall would be held there:
 * anchorAtWall), else its heaviest (the one the sweeps move least), on a tie the one nearer a wall, then the
 * lower index. Sets groupIsRow: at least ROW_MIN_BALLS balls, the normal of every pair that touches or
 * overlaps (closer than PROJECTION_SLOP) within ROW_LINE_COS of the first one's; a group that is not a row
 * is marked taken (the sweeps' work, not this pass's). A row of 55 balls of radius 11 struck by a ball 1e4
 * times heavier and pressed within itself, clear of the walls, was taken out by the sweeps at about half
 * its depth a tick: 0.36 px deep, more than 1e-3 px for 0.2 s.
 */
function anchorOfGroup(w: BallWorld, F: FixedContactState, s: number): number {
  let near = s
  let nearGap = Infinity
  let heavy = s
  let heavyGap = Infinity
  // the overlaps of the group's pairs, each met from both its balls: twice the push the row needs
  let depth2 = 0
  let lineX = 0
  let lineY = 0
  let row = true
  let top = 0
  stack[top++] = s
  state[s] = 3
  let count = 0
  while (top > 0) {
    const v = stack[--top]!
    group[count++] = v
    // not a row: the rest of the walk only gathers the group
    if (!row) {
      for (let q = F.adjStart[v]!, e = F.adjStart[v + 1]!; q < e; q++) {
        const p = F.adjPairs[q]!
        const u = F.pairA[p] === v ? F.pairB[p]! : F.pairA[p]!
        if (state[u] !== 0) continue
        state[u] = 3
        stack[top++] = u
      }
      continue
    }
    let d = Infinity
    if (w.walls !== 0) {
      nearestWall(F, v)
      d = lay[L_GAP]!
    }
    if (d < nearGap || (d === nearGap && v < near)) {
      near = v
      nearGap = d
    }
    if (F.im[v]! < F.im[heavy]! || (F.im[v] === F.im[heavy] && (d < heavyGap || (d === heavyGap && v < heavy)))) {
      heavy = v
      heavyGap = d
    }
    for (let q = F.adjStart[v]!, e = F.adjStart[v + 1]!; q < e; q++) {
      const p = F.adjPairs[q]!
      const u = F.pairA[p] === v ? F.pairB[p]! : F.pairA[p]!
      if (state[u] === 2) continue
      // a row: every pair that touches or overlaps along one line (a row pressed within itself that the
      // tick paired with a pile apart from it is still a row)
      normal(F, v, u)
      if (nrm.gap < PROJECTION_SLOP) {
        if (lineX === 0 && lineY === 0) {
          lineX = nrm.x
          lineY = nrm.y
        } else if (Math.abs(lineX * nrm.x + lineY * nrm.y) < ROW_LINE_COS) row = false
      }
      if (nrm.gap < 0) depth2 -= nrm.gap
      if (state[u] !== 0) continue
      state[u] = 3
      stack[top++] = u
    }
  }
  // a row is taken next; any other group is left where it is, as taken
  groupIsRow = row && count >= ROW_MIN_BALLS
  const mark = groupIsRow ? 0 : 2
  for (let k = 0; k < count; k++) {
    state[group[k]!] = mark
    face[group[k]!] = NO_FACE
  }
  groupCount = count
  // from the wall when the ball nearest it can reach it within the tick, or when a push out from elsewhere
  // would press that ball into it: the row's overlaps add up to more than its gap
  anchorAtWall = nearGap <= F.reach[near]! - F.r[near]! + PROJECTION_SLOP || nearGap <= depth2 / 2
  return anchorAtWall ? near : heavy
}

/** whether the last anchorOfGroup took the group from its wall; whether that group was a row */
let anchorAtWall = false
let groupIsRow = false
let groupCount = 0

/**
 * Puts into the heap each ball of the row anchorOfGroup gathered that the tick paired with a ball taken from
 * a wall, by its distance before the pass to that wall; returns how many.
 */
function seedFromTaken(F: FixedContactState): number {
  let size = 0
  for (let k = 0; k < groupCount; k++) {
    const i = group[k]!
    for (let q = F.adjStart[i]!, e = F.adjStart[i + 1]!; q < e && state[i] === 0; q++) {
      const p = F.adjPairs[q]!
      const u = F.pairA[p] === i ? F.pairB[p]! : F.pairA[p]!
      if (state[u] !== 2 || face[u]! >= FROM_BALL) continue
      face[i] = face[u]!
      toFace(F, i, face[i]!, true)
      key[i] = lay[L_GAP]!
      state[i] = 1
      size = push(i, size)
    }
  }
  return size
}

/** Puts the row's anchor v into the heap, from its wall (anchorAtWall) or as its own anchor; returns 1. */
function seedAnchor(w: BallWorld, F: FixedContactState, v: number): number {
  if (anchorAtWall) {
    nearestWall(F, v)
    key[v] = lay[L_GAP]!
    face[v] = wallFace
  } else {
    face[v] = FROM_BALL
    anchorBall = v
    key[v] = 0
  }
  state[v] = 1
  return push(v, 0)
}

/** layered's mark of a ball taken from a group's anchor, not from a wall (faces 0–3); of one left where it is */
const FROM_BALL = 4
const NO_FACE = 5

/** the ball the group spread is taking from its anchor (FROM_BALL) started from: one group a spread */
let anchorBall = 0

/**
 * Candidate i's gap to closed wall face k (0 left, 1 right, 2 top, 3 bottom; an open one is infinitely far),
 * where it is or (`before`) where it was when layered began, into lay[L_GAP] (a returned double is boxed).
 */
function toFace(F: FixedContactState, i: number, k: number, before: boolean): void {
  const r = F.r[i]!
  const x = before ? x0[i]! : F.x[i]!
  const y = before ? y0[i]! : F.y[i]!
  lay[L_GAP] = k === 0 ? x - r - walls.minX : k === 1 ? walls.maxX - x - r : k === 2 ? y - r - walls.minY : walls.maxY - y - r
}

/**
 * The gap of pair (u, v) where they are now along the normal u→v where they were when layered began, and that
 * normal, into lay (L_GAP, L_X, L_Y): a push carried along a row grows from ball to ball, and by the present
 * centres a ball pushed past the next one's centre would push it the wrong way, or seem clear of it.
 */
function along(F: FixedContactState, u: number, v: number): void {
  let nx = x0[v]! - x0[u]!
  let ny = y0[v]! - y0[u]!
  const d = Math.sqrt(nx * nx + ny * ny)
  if (d > 0) {
    nx /= d
    ny /= d
  } else {
    // coincident then: the present normal
    normal(F, u, v)
    nx = nrm.x
    ny = nrm.y
  }
  lay[L_X] = nx
  lay[L_Y] = ny
  lay[L_GAP] = (F.x[v]! - F.x[u]!) * nx + (F.y[v]! - F.y[u]!) * ny - F.r[u]! - F.r[v]!
}

/** along's and toFace's results */
const lay = new Float64Array(3)
const L_GAP = 0
const L_X = 1
const L_Y = 2

/** Whether heap entry a comes before b: nearer its wall or anchor, then lower index (one order whatever happens to tie). */
function before(a: number, b: number): boolean {
  return key[a]! < key[b]! || (key[a] === key[b] && a < b)
}

function push(i: number, size: number): number {
  let c = size
  while (c > 0) {
    const up = (c - 1) >> 1
    if (!before(i, heap[up]!)) break
    heap[c] = heap[up]!
    c = up
  }
  heap[c] = i
  return size + 1
}

function pop(size: number): number {
  const n = size - 1
  const last = heap[n]!
  let i = 0
  for (;;) {
    let c = 2 * i + 1
    if (c >= n) break
    if (c + 1 < n && before(heap[c + 1]!, heap[c]!)) c++
    if (!before(heap[c]!, last)) break
    heap[i] = heap[c]!
    i = c
  }
  heap[i] = last
  return n
}

/**
 * layered's scratch: a heap of candidates, each one's distance to its wall or anchor, positions before,
 * state (0 not reached, 1 in the heap, 2 taken, 3 gathered by anchorOfGroup), its wall (or FROM_BALL);
 * anchorOfGroup's stack and group
 */
let heap = new Int32Array(64)
let key = new Float64Array(64)
let x0 = new Float64Array(64)
let y0 = new Float64Array(64)
let state = new Uint8Array(64)
let face = new Uint8Array(64)
let stack = new Int32Array(64)
let group = new Int32Array(64)

/** groups layered took from an anchor, over all ticks (the tick's velocities are solved again after one) */
let anchoredRuns = 0
export function anchoredCount(): number {
  return anchoredRuns
}
