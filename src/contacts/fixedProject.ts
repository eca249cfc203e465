// The fixed-tick method's position projection (config.BALL_COLLISIONS = 'fixed'), after the velocity solve
// of a contact tick (src/contacts/fixedSolve.ts): sweeps that move every overlapping pair apart along the
// normal, shared by inverse mass (each ball taking at least MIN_PROJECTION_SHARE), and keep balls inside the
// closed walls, until no overlap is deeper than PROJECTION_SLOP. Full sweeps while the overlaps are spread
// through the pairs, then sweeps over the pairs of the balls still moving (src/contacts/fixedPairs.ts); at
// most PROJECTION_BUDGET × pairs pair visits and PROJECTION_QUEUE_BUDGET × pairs pairs queued again a tick.
// Sweeps that run out with overlaps left (a row or a pile pressed into a wall: each sweep carries a push a
// ball or two) are followed by one pass out from the walls, each ball moved out of those nearer the wall
// (layered). Only positions change: no kinetic energy is added.
// The part of a push that a closed wall keeps a ball from taking goes to the other ball of the pair, so a
// heavy ball cannot drive a light one through the wall.
import { MAX_LISTED_SWEEPS, MIN_PROJECTION_SHARE, PROJECTION_BUDGET, PROJECTION_QUEUE_BUDGET, PROJECTION_SLOP } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import { reserveSweeps, type FixedContactState } from '../world/fixedState.js'
import { walls } from './fixedGrid.js'
import { activate, buildAdjacency, heapPop, nextStamp, normal, nrm, startSweep } from './fixedPairs.js'

export function solvePositions(w: BallWorld, F: FixedContactState): void {
  // the velocity sweeps met every pair at the tick's positions: no overlap among them, nothing to move
  if (!F.overlap) return
  const pairs = F.pairCount
  reserveSweeps(F, F.n, pairs)
  let budget = PROJECTION_BUDGET * pairs
  // full sweeps, forward and back, while the overlaps are spread through the pairs
  let it = 0
  let moved = 0
  for (; it < PROJECTION_BUDGET; it++) {
    const stamp = nextStamp(F)
    const back = (it & 1) === 1
    let worst = 0
    moved = 0
    for (let k = 0; k < pairs; k++) {
      const p = back ? pairs - 1 - k : k
      normal(F, F.pairA[p]!, F.pairB[p]!)
      const gap = nrm.gap
      if (!(gap < 0)) continue
      pushApart(w, F, p, gap)
      if (-gap > worst) worst = -gap
      if (F.ballStamp[F.pairA[p]!] !== stamp && movedA) {
        F.ballStamp[F.pairA[p]!] = stamp
        F.moved[moved++] = F.pairA[p]!
      }
      if (F.ballStamp[F.pairB[p]!] !== stamp && movedB) {
        F.ballStamp[F.pairB[p]!] = stamp
        F.moved[moved++] = F.pairB[p]!
      }
    }
    budget -= pairs
    if (worst <= PROJECTION_SLOP) return
    if (moved === 0) break // held by the walls: no sweep can do more
    // a few balls still moving: on to sweeps over their pairs only
    if (moved * 8 < pairs) break
  }
  if (it === PROJECTION_BUDGET || budget <= 0 || moved === 0) {
    if (!layered(w, F)) F.capped++
    return
  }
  buildAdjacency(F)
  // the first active sweep: the pairs of the balls the last full sweep moved
  const stamp0 = nextStamp(F)
  F.activeCount = 0
  for (let m = 0; m < moved; m++) {
    const i = F.moved[m]!
    for (let q = F.adjStart[i]!, e = F.adjStart[i + 1]!; q < e; q++) {
      const p = F.adjPairs[q]!
      if (F.nextStamp[p] === stamp0) continue
      F.nextStamp[p] = stamp0
      F.active[F.activeCount++] = p
    }
  }
  // Gauss-Seidel sweeps over the pairs whose balls moved since the pair was last met: in pair order (a
  // heap), a pair ahead of the sweep joins it when one of its balls moves, a pair behind joins the next
  // sweep; so each sweep does what a full sweep would, less the pairs whose gap cannot have changed
  // (a push queues again every pair of the balls it moved: in a crowd where each ball touches many, that
  // reading, not the visits, is the work, so it has a budget of its own)
  let queue = PROJECTION_QUEUE_BUDGET * pairs
  for (let sweep = it + 1; sweep < MAX_LISTED_SWEEPS && F.activeCount > 0 && budget > 0 && queue > 0; sweep++) {
    const back = (sweep & 1) === 1
    const stamp = nextStamp(F)
    let size = startSweep(F, back, stamp)
    let worst = 0
    while (size > 0 && budget > 0 && queue > 0) {
      const key = F.heap[0]!
      size = heapPop(F.heap, size)
      const p = back ? pairs - 1 - key : key
      budget--
      const a = F.pairA[p]!
      const b = F.pairB[p]!
      normal(F, a, b)
      const gap = nrm.gap
      if (!(gap < 0)) continue
      pushApart(w, F, p, gap)
      if (-gap > worst) worst = -gap
      // activate reads every pair of its ball, F.adjStart[i + 1] − F.adjStart[i] of them
      if (movedA) {
        queue -= F.adjStart[a + 1]! - F.adjStart[a]!
        size = activate(F, a, key, back, stamp, size)
      }
      if (movedB) {
        queue -= F.adjStart[b + 1]! - F.adjStart[b]!
        size = activate(F, b, key, back, stamp, size)
      }
    }
    // done when a whole sweep left no overlap over the slop (a sweep the budget cut short is not whole:
    // the pairs it did not reach may still overlap, and the tick counts as capped)
    if (size === 0 && worst <= PROJECTION_SLOP) return
  }
  if (!layered(w, F)) F.capped++
}

/**
 * The sweeps ran out with overlaps left: a row or a pile pressed into a closed wall, where each sweep moves
 * a push only a ball or two along (a ball held by the wall hands its whole share on, the next splits it
 * with the one behind). Out from the walls instead, as shock propagation does: the balls touching a closed
 * wall first, then each ball that overlaps or touches one already taken, nearest that ball's wall first
 * (by where the balls were before this), each moved out of every ball already taken that it overlaps
 * (those are where they end), along the pair's normal before any moved (along); then one more full sweep.
 * Positions only. True when no overlap deeper than PROJECTION_SLOP is left.
 */
function layered(w: BallWorld, F: FixedContactState): boolean {
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

/** whether the last pushApart() moved ball a, ball b of its pair */
let movedA = false
let movedB = false

/** Moves the balls of pair p, overlapping by −gap along nrm (normal() just set it), apart; sets movedA, movedB. */
function pushApart(w: BallWorld, F: FixedContactState, p: number, gap: number): void {
  const a = F.pairA[p]!
  const b = F.pairB[p]!
  const nx = nrm.x
  const ny = nrm.y
  // shared by inverse mass, each ball taking at least MIN_PROJECTION_SHARE (a light ball squeezed between
  // heavy ones would otherwise take every push and pass it to and fro); what a wall keeps one ball from
  // taking, the other takes (a ball against a wall is held by it)
  const want = -gap
  const share = Math.min(1 - MIN_PROJECTION_SHARE, Math.max(MIN_PROJECTION_SHARE, F.im[a]! / (F.im[a]! + F.im[b]!)))
  const ax = F.x[a]!
  const ay = F.y[a]!
  F.x[a] = ax - want * share * nx
  F.y[a] = ay - want * share * ny
  keepInside(w, F, a)
  const took = (ax - F.x[a]!) * nx + (ay - F.y[a]!) * ny
  const bx = F.x[b]!
  const by = F.y[b]!
  F.x[b] = bx + (want - took) * nx
  F.y[b] = by + (want - took) * ny
  keepInside(w, F, b)
  // and what a wall keeps b from taking goes back to a
  const left = want - took - ((F.x[b]! - bx) * nx + (F.y[b]! - by) * ny)
  if (left > 0) {
    F.x[a] = F.x[a]! - left * nx
    F.y[a] = F.y[a]! - left * ny
    keepInside(w, F, a)
  }
  F.changed[a]! |= 2
  F.changed[b]! |= 2
  movedA = F.x[a] !== ax || F.y[a] !== ay
  movedB = F.x[b] !== bx || F.y[b] !== by
}

/**
 * Keeps a moved candidate from being pushed through a closed wall: never further past a wall's inner face
 * than it was when the tick began (a ball outside the box stays outside; an open edge's face is at
 * ±Infinity, so it never holds).
 */
function keepInside(w: BallWorld, F: FixedContactState, i: number): void {
  const eid = F.id[i]!
  const r = F.r[i]!
  const x0 = w.Ball.x[eid]!
  const y0 = w.Ball.y[eid]!
  F.x[i] = Math.min(Math.max(F.x[i]!, Math.min(x0, walls.minX + r)), Math.max(x0, walls.maxX - r))
  F.y[i] = Math.min(Math.max(F.y[i]!, Math.min(y0, walls.minY + r)), Math.max(y0, walls.maxY - r))
}
