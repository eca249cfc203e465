// The fixed-tick projection's pass out from the walls (config.BALL_COLLISIONS = 'fixed'), after sweeps that
// ran out with overlaps left (src/contacts/fixedProject.ts): shock propagation for positions. Balls touching a
// closed wall are taken first; each ball is moved out of those already taken, which stay where they are.
// Positions only: no kinetic energy is added.
import { PROJECTION_SLOP } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import type { FixedContactState } from '../world/fixedState.js'
import { walls } from './fixedGrid.js'
import { buildAdjacency, normal, nrm } from './fixedPairs.js'
import { keepInside, pushApart } from './fixedPush.js'

/**
 * The sweeps ran out with overlaps left: a row or a pile pressed into a closed wall, where each sweep moves
 * a push only a ball or two along (a ball held by the wall hands its whole share on, the next splits it
 * with the one behind). Out from the walls instead, as shock propagation does: the balls touching a closed
 * wall first, then each ball that overlaps or touches one already taken, nearest that ball's wall first
 * (by where the balls were before this), each moved out of every ball already taken that it overlaps
 * (those are where they end), along the pair's normal before any moved (along); then one more full sweep.
 * Positions only. True when no overlap deeper than PROJECTION_SLOP is left.
 */
export function layered(w: BallWorld, F: FixedContactState): boolean {
  const n = F.n
  const pairs = F.pairCount
  if (w.walls === 0 || pairs === 0) return false
  if (heap.length < n) {
    heap = new Int32Array(2 * n)
    key = new Float64Array(2 * n)
    x0 = new Float64Array(2 * n)
    y0 = new Float64Array(2 * n)
    state = new Uint8Array(2 * n)
    face = new Uint8Array(2 * n)
  }
  buildAdjacency(F)
  let size = 0
  for (let i = 0; i < n; i++) {
    x0[i] = F.x[i]!
    y0[i] = F.y[i]!
    state[i] = 0
    // touching a closed wall: taken first, from that wall
    let f = 0
    let d = Infinity
    for (let k = 0; k < 4; k++) {
      toFace(F, i, k, false)
      if (lay[L_GAP]! < d) {
        d = lay[L_GAP]!
        f = k
      }
    }
    if (!(d <= PROJECTION_SLOP)) continue
    face[i] = f
    key[i] = d
    state[i] = 1
    size = push(i, size)
  }
  if (size === 0) return false
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
      F.changed[v]! |= 2
    }
    state[v] = 2
    // the balls it overlaps or touches where it is now, by their distance to its wall
    for (let q = F.adjStart[v]!, e = F.adjStart[v + 1]!; q < e; q++) {
      const p = F.adjPairs[q]!
      const u = F.pairA[p] === v ? F.pairB[p]! : F.pairA[p]!
      if (state[u] !== 0) continue
      along(F, v, u)
      if (!(lay[L_GAP]! < PROJECTION_SLOP)) continue
      face[u] = face[v]!
      toFace(F, u, face[u]!, true)
      key[u] = lay[L_GAP]!
      state[u] = 1
      size = push(u, size)
    }
  }
  // one full sweep for what that leaves (a ball held by a wall, a push across the order)
  let worst = 0
  for (let p = 0; p < pairs; p++) {
    normal(F, F.pairA[p]!, F.pairB[p]!)
    const gap = nrm.gap
    if (!(gap < 0)) continue
    pushApart(w, F, p, gap)
    if (-gap > worst) worst = -gap
  }
  return worst <= PROJECTION_SLOP
}

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

/** Whether heap entry a comes before b: nearer its wall, then lower index (one order whatever happens to tie). */
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

/** layered's scratch: a heap of candidates, each one's distance to its wall, positions before, state (0 not reached, 1 in the heap, 2 taken), its wall */
let heap = new Int32Array(64)
let key = new Float64Array(64)
let x0 = new Float64Array(64)
let y0 = new Float64Array(64)
let state = new Uint8Array(64)
let face = new Uint8Array(64)
