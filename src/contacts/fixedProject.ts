// The fixed-tick method's position projection (config.BALL_COLLISIONS = 'fixed'), after the velocity solve
// of a contact tick (src/contacts/fixedSolve.ts): sweeps that move every overlapping pair apart along the
// normal, shared by inverse mass (each ball taking at least MIN_PROJECTION_SHARE), and keep balls inside the
// closed walls, until no overlap is deeper than PROJECTION_SLOP. Full sweeps while the overlaps are spread
// through the pairs, then sweeps over the pairs of the balls still moving (src/contacts/fixedPairs.ts); at
// most PROJECTION_BUDGET × pairs pair visits and PROJECTION_QUEUE_BUDGET × pairs pairs queued again a tick.
// Only positions change: no kinetic energy is added.
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
    F.capped++
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
  F.capped++
}

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
