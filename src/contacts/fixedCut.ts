// Fixed-tick contacts: a capsule cut at the first ball it meets (src/contacts/fixedCapsule.ts,
// fixedReach.ts). A ball the solve sped up far beyond its size is widened along its path; paired with every
// ball along it, a row of n balls struck end on lists about n²/2 pairs in the tick (each ball of the row is
// sped up in turn, and each is paired with the rest of the row ahead of it), and the rounds' pair bounds
// stopped the push part way along a row of a few hundred tiny balls, whose far end then went through. A
// new capsule is cut instead where its path comes closest to the first ball it newly meets: a struck ball
// that stops there needs no more, and the push runs on through that ball, paired with the next one, about
// n pairs in all. A ball that goes on past the cut (heavier than the ball it struck, or it missed it) has
// its capsule lengthened to its whole path in the next round and is paired with every ball along it, as
// before (src/contacts/fixedCapsule.ts, extendAlong: src/contacts/fixedReach.ts, widenHits, looks each
// round at every ball the tick's solves have changed).
import type { BallWorld } from '../world/createWorld.js'
import type { FixedContactState } from '../world/fixedState.js'
import { box } from './fixedDense.js'
import { bounds, covers, cutAt, hasCapsule, pathLength, roundReach, segmentBounds, shareAlong } from './fixedCapsule.js'
import { probeAlong } from './fixedSeed.js'
import { joinedFree, joinedList } from './fixedNear.js'

/** The stretch of a path cutCapsule looks along at a time, in ordering grid cells, and at most so many stretches. */
const CUT_STRETCH = 2
const MAX_CUT_STRETCHES = 256

/** The nearest ball met so far, as a share of the path. */
let nearest = 1

/**
 * Cuts the new capsule of widened candidate g at the first ball without a capsule that it meets, by the
 * share of its path at that ball's centre (where the path comes closest to it, so the cut capsule still
 * meets it; a ball whose centre lies behind g's is met by its circle, and does not cut). The capsules of
 * other balls do not cut it (their pairs are found as before). Looked up where the pairing looks
 * (src/contacts/fixedReach.ts, pairNear: those gridPartners listed, F.pe2[peFrom..peTo), the big ones,
 * those the widening added before `upTo`; on dense ticks the ordering grid's cells stretch by stretch
 * along the path, up to the first ball met) and among the resting balls along its path.
 */
export function cutCapsule(w: BallWorld, F: FixedContactState, g: number, peFrom: number, peTo: number, upTo: number): void {
  const smallReach = roundReach[0]!
  nearest = 1
  for (let t = peFrom; t < peTo; t++) probe(F, g, F.packAt[F.pe2[t]!]!)
  for (let m = 0; m < F.bigCount; m++) probe(F, g, F.big[m]!)
  for (let k = 0, free = joinedFree(F, upTo), jl = joinedList(); k < free; k++) probe(F, g, jl[k]!)
  const step = Math.max((CUT_STRETCH * F.gridCell) / pathLength(g), 1 / MAX_CUT_STRETCHES)
  for (let a = 0; a < nearest; a += step) {
    const b = a + step < 1 ? a + step : 1
    if (F.dense === 1) {
      segmentBounds(F, g, a, b, smallReach)
      if (boundsBox(F)) {
        for (let gy = box[2]!; gy <= box[3]!; gy++) {
          for (let q = F.start[gy * F.cols + box[0]!]!, e = F.start[gy * F.cols + box[1]! + 1]!; q < e; q++) probe(F, g, F.si[q]!)
        }
      }
    }
    const resting = probeAlong(w, F, g, a, b)
    if (resting < nearest) nearest = resting
    if (b === 1) break
  }
  if (nearest < 1) cutAt(g, nearest)
}

/** Candidate j, without a capsule, if what g covers now meets it and did not before: the nearest yet? */
function probe(F: FixedContactState, g: number, j: number): void {
  if (j === g || hasCapsule(j)) return
  if (covers(F, g, false, j, false) || !covers(F, g, true, j, F.grown[j] === 1)) return
  const s = shareAlong(F, g, F.x[j]!, F.y[j]!)
  if (s > 0 && s < nearest) nearest = s
}

/** The ordering grid's cells of the box in bounds (columns box[0]..box[1], rows box[2]..box[3]); false if none. */
export function boundsBox(F: FixedContactState): boolean {
  if (F.cols === 0) return false
  const cell = F.gridCell
  box[0] = Math.max(0, Math.floor((bounds[0]! - F.minX) / cell))
  box[1] = Math.min(F.cols - 1, Math.floor((bounds[1]! - F.minX) / cell))
  box[2] = Math.max(0, Math.floor((bounds[2]! - F.minY) / cell))
  box[3] = Math.min(F.rows - 1, Math.floor((bounds[3]! - F.minY) / cell))
  return box[0]! <= box[1]! && box[2]! <= box[3]!
}
