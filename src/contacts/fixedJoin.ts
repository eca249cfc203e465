// The fixed-tick method's projection (src/contacts/fixedProject.ts) moves balls along the tick's pairs,
// found at the tick's positions; a resting ball reaches only its radius (it does not move by itself), so a
// ball the projection pushes can end inside a resting ball it was not paired with (a rolling ball pressing a
// row of resting ones: the second is pushed into the third). After a projection that kept within its
// budget, each ball it moved more than half the slop is paired with the resting balls it now overlaps by
// more than PROJECTION_SLOP (those the tick did not gather join the packed candidates), and the projection
// runs again: at most MAX_WIDEN_ROUNDS times a tick (systems/fixedContacts.ts). Two balls that overlap by
// more than the slop after a projection that finished are never a pair of it, so no pair is listed twice.
import { BallMode } from '../../components/Ball.js'
import { PROJECTION_SLOP, TOUCH_GAP } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import { nextMark, pushCandidate, pushPair, reserveCandidates, sweepStores, type FixedContactState } from '../world/fixedState.js'
import { setRestingCandidate } from './fixedReach.js'
import { capsuleCellEstimate, capsuleCells, pointQuery } from './sweepGrid.js'

/** Pairs the balls the projection moved with the unpaired resting balls they overlap; true when it paired any. */
export function joinPushed(w: BallWorld, F: FixedContactState): boolean {
  const C = F.rest
  if (C.restCount === 0 && C.bigRestCount === 0) return false
  const B = w.Ball
  const n0 = F.n
  // how far the projection moved each candidate (the resting grid holds balls at the tick's positions)
  let shift = 0
  let movers = 0
  for (let k = 0; k < n0; k++) {
    if ((F.changed[k]! & 2) === 0) continue
    const e = F.id[k]!
    const dx = F.x[k]! - B.x[e]!
    const dy = F.y[k]! - B.y[e]!
    const d = Math.sqrt(dx * dx + dy * dy)
    if (d > shift) shift = d
    if (d > PROJECTION_SLOP / 2) movers++
  }
  // a new overlap deeper than the slop needs the two balls to have closed by more than it: one of them moved
  // more than half of it
  if (movers === 0) return false
  sweepStores(F)
  const st = nextMark(F)
  for (let k = 0; k < n0; k++) {
    F.packMark[F.id[k]!] = st
    F.packAt[F.id[k]!] = k
  }
  let paired = false
  for (let i = 0; i < n0; i++) {
    if ((F.changed[i]! & 2) === 0) continue
    const self = F.id[i]!
    const x = F.x[i]!
    const y = F.y[i]!
    const mx = x - B.x[self]!
    const my = y - B.y[self]!
    if (!(mx * mx + my * my > (PROJECTION_SLOP / 2) * (PROJECTION_SLOP / 2))) continue
    if (++C.seenStamp === 0xffffffff) {
      C.seen.fill(0)
      C.seenStamp = 1
    }
    for (let b = 0; b < C.bigRestCount; b++) if (pairIfPushed(w, F, i, C.bigRest[b]!, st)) paired = true
    if (C.restCount === 0) continue
    // centres within the two radii, the other's at most maxRadius, found at its tick position
    const reach = F.r[i]! + C.maxRadius + shift + TOUCH_GAP
    const mask = C.restHead.length - 1
    if (capsuleCellEstimate(C, pointQuery(x, y, reach)) > C.restHead.length) {
      for (let c = 0; c <= mask; c++) for (let e = C.restHead[c]!; e !== 0; e = C.restNext[e]!) if (pairIfPushed(w, F, i, e, st)) paired = true
    } else {
      const k = capsuleCells(C, pointQuery(x, y, reach), mask)
      for (let c = 0; c < k; c++) for (let e = C.restHead[C.cells[c]!]!; e !== 0; e = C.restNext[e]!) if (pairIfPushed(w, F, i, e, st)) paired = true
    }
  }
  return paired
}

/**
 * Pairs candidate i with resting ball e when they overlap by more than PROJECTION_SLOP (e at its position
 * in the packed candidates, if it is one; else it joins them); once per e for this i (the seen stamp).
 */
function pairIfPushed(w: BallWorld, F: FixedContactState, i: number, e: number, st: number): boolean {
  const B = w.Ball
  const C = F.rest
  if (C.seen[e] === C.seenStamp || e === F.id[i] || B.live[e] !== 1 || B.mode[e] !== BallMode.Resting) return false
  C.seen[e] = C.seenStamp
  let j = F.packMark[e] === st ? F.packAt[e]! : -1
  const dx = (j >= 0 ? F.x[j]! : B.x[e]!) - F.x[i]!
  const dy = (j >= 0 ? F.y[j]! : B.y[e]!) - F.y[i]!
  const s = F.r[i]! + B.radius[e]! - PROJECTION_SLOP
  if (!(s > 0) || dx * dx + dy * dy >= s * s) return false
  if (j < 0) {
    j = F.n
    pushCandidate(F, e)
    reserveCandidates(F, F.n)
    setRestingCandidate(w, F, j)
    F.packMark[e] = st
    F.packAt[e] = j
  }
  pushPair(F, i < j ? i : j, i < j ? j : i)
  return true
}
