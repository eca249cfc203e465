// The fixed-tick method's position projection (config.BALL_COLLISIONS = 'fixed'), after the velocity solve
// of a contact tick (src/contacts/fixedSolve.ts): sweeps that move every overlapping pair apart along the
// normal, shared by inverse mass (each ball taking at least MIN_PROJECTION_SHARE), and keep balls inside the
// closed walls, until no overlap is deeper than PROJECTION_SLOP. Full sweeps while the overlaps are spread
// through the pairs, then sweeps over the pairs of the balls still moving (src/contacts/fixedPairs.ts); at
// most PROJECTION_BUDGET × pairs pair visits and PROJECTION_QUEUE_BUDGET × pairs pairs queued again a tick.
// Sweeps that run out with overlaps left (a row or a pile pressed into a wall, a long row pressed within
// itself: each sweep carries a push a ball or two) are followed by one pass out from the walls and from the
// groups' anchors (src/contacts/fixedLayered.ts). Only positions change: no kinetic energy is added.
// The part of a push that a closed wall keeps a ball from taking goes to the other ball of the pair, so a
// heavy ball cannot drive a light one through the wall (src/contacts/fixedPush.ts).
import { LEAN_PROJECTION_BUDGET, MAX_LISTED_SWEEPS, PROJECTION_BUDGET, PROJECTION_QUEUE_BUDGET, PROJECTION_SLOP } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import { reserveSweeps, type FixedContactState } from '../world/fixedState.js'
import { activate, apart, buildAdjacency, nextDue, nextStamp, normal, nrm, startSweep } from './fixedPairs.js'
import { layered } from './fixedLayered.js'
import { lean, spend } from './fixedBudget.js'
import { movedA, movedB, pushApart } from './fixedPush.js'

export function solvePositions(w: BallWorld, F: FixedContactState): void {
  // the velocity sweeps met every pair at the tick's positions: no overlap among them, nothing to move
  if (!F.overlap) return
  // past the span's work budget, a lean projection (src/contacts/fixedBudget.ts)
  const sweeps = lean(F) ? LEAN_PROJECTION_BUDGET : PROJECTION_BUDGET
  const budget0 = sweeps * F.pairCount
  project(w, F, sweeps)
  spend(F, budget0 - left)
}

/** the projection's pair visits left of its budget when it returned */
let left = 0

function project(w: BallWorld, F: FixedContactState, sweeps: number): void {
  const pairs = F.pairCount
  reserveSweeps(F, F.n, pairs)
  let budget = sweeps * pairs
  left = budget
  // full sweeps, forward and back, while the overlaps are spread through the pairs
  let it = 0
  let moved = 0
  for (; it < sweeps; it++) {
    const stamp = nextStamp(F)
    const back = (it & 1) === 1
    let worst = 0
    moved = 0
    for (let k = 0; k < pairs; k++) {
      const p = back ? pairs - 1 - k : k
      if (apart(F, F.pairA[p]!, F.pairB[p]!)) continue
      normal(F, F.pairA[p]!, F.pairB[p]!)
      const gap = nrm.gap
      if (!(gap < 0)) continue
      pushApart(w, F, p)
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
    left = budget
    if (worst <= PROJECTION_SLOP) return
    if (moved === 0) break // held by the walls: no sweep can do more
    // a few balls still moving: on to sweeps over their pairs only
    if (moved * 8 < pairs) break
  }
  if (it === sweeps || budget <= 0 || moved === 0) {
    if (!settled(F) && !layered(w, F)) F.capped++
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
  // Gauss-Seidel sweeps over the pairs whose balls moved since the pair was last met: in pair order (the
  // keys due, as bits), a pair ahead of the sweep joins it when one of its balls moves, a pair behind joins the next
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
      const key = nextDue(F)
      size--
      const p = back ? pairs - 1 - key : key
      budget--
      left = budget
      const a = F.pairA[p]!
      const b = F.pairB[p]!
      if (apart(F, a, b)) continue
      normal(F, a, b)
      const gap = nrm.gap
      if (!(gap < 0)) continue
      pushApart(w, F, p)
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
  if (!settled(F) && !layered(w, F)) F.capped++
}

/**
 * Whether no pair is left deeper than PROJECTION_SLOP. Each sweep is judged by the overlaps it met before its
 * pushes, so the last sweep before the budget ran out can have left none: then nothing is capped and the
 * rows' pass has nothing to do. Counted as capped, the tick left a ball the sweeps had pushed into a resting
 * ball it was not paired with there until the next tick (systems/fixedContacts.ts pairs such balls only
 * after a projection that is not capped): a row of 55 balls pressed into a wall, 3.6e-3 px deep for a step.
 */
function settled(F: FixedContactState): boolean {
  for (let p = 0, pairs = F.pairCount; p < pairs; p++) {
    const a = F.pairA[p]!
    const b = F.pairB[p]!
    if (apart(F, a, b)) continue
    normal(F, a, b)
    if (nrm.gap < -PROJECTION_SLOP) return false
  }
  return true
}
