// Contact prediction: a ball's contacts with every ball near its path over the prediction window, and its
// own next event, pushed into the event heap.
import { BallMode } from '../../components/Ball.js'
import { GAP_TOLERANCE, MAX_CAPSULE_CELLS } from '../config/tolerances.js'
import { nextSeenStamp, appendId } from '../world/contactState.js'
import type { BallWorld } from '../world/createWorld.js'
import { HeapKind, heapPush, pushTime } from './eventHeap.js'
import { AT, E, MT, VX, VY, X, Y, evalBall, motionEnd, motionStart } from './evalMotion.js'
import { FROM, RESULT, SearchResult, TIME, TO, search, searchContact } from './search.js'
import { CR, X1, X2, Y1, Y2, cap, capsuleCellsOver, capsuleCells, enterCapsule, query, staleEntry, sweptCapsule } from './sweepGrid.js'
import { HOT, H_NEXT_T } from '../world/pathHot.js'

/**
 * Predicts ball `a`'s contacts with every ball near its path over [C.now, C.until] (the prediction window)
 * and pushes them, and its own next event, into the heap; then enters its capsule into the hash. A window's
 * first build calls this once per moving ball, so each pair is tried once (by the later of the two); later
 * calls try every neighbour.
 */
export function predictBall(w: BallWorld, a: number): void {
  const C = w.collide!
  C.isDirty[a] = 0
  const mode = w.Ball.mode[a]
  if (mode !== BallMode.Rolling && mode !== BallMode.RimRoll && mode !== BallMode.Resting) return
  const tEnd = C.until
  if (mode !== BallMode.Resting) {
    const own = w.pathHot[a * HOT + H_NEXT_T]!
    if (own <= tEnd) {
      pushTime[0] = own
      heapPush(C, HeapKind.Own, a, 0)
    }
  }
  sweptCapsule(w, a)
  // a's span, for every pair searched (search.ts): in slots, which nothing else writes during a prediction
  // (V8 boxes each double passed to a function it does not inline, a heap number a pair tried); its capsule
  // is `cap` (sweptCapsule)
  motionStart(w, a)
  search[FROM] = E[MT]
  motionEnd(w, a)
  const endA = E[MT]
  search[TO] = endA
  const stamp = nextSeenStamp(C)
  C.seen[a] = stamp

  if (mode !== BallMode.Resting) {
    C.predicted[a] = C.stamp
    C.predictions++
    C.predGen[a] = C.gen[a]!
    C.spanEnd[a] = endA
  }

  // moving balls' capsules: through the hash, or, for a ball too big or fast for it, directly. A contact is
  // taken within GAP_TOLERANCE: the cells reach twice that past the capsule, so two capsules that come that
  // close across a cell boundary share a cell, whatever their lengths (which depend on when each ball was
  // predicted); the capsule is entered in the same cells
  const look = cap[CR]! + 2 * GAP_TOLERANCE
  query[X1] = cap[X1]!
  query[Y1] = cap[Y1]!
  query[X2] = cap[X2]!
  query[Y2] = cap[Y2]!
  query[CR] = look
  const big = capsuleCellsOver(C, query, MAX_CAPSULE_CELLS)
  const sMask = C.sweepHead.length - 1
  let n = big ? 0 : capsuleCells(C, query, sMask)
  for (let k = 0; k < n; k++) {
    const bucket = C.cells[k]!
    if (C.sweepStamp[bucket] !== C.stamp) continue
    for (let e = C.sweepHead[bucket]!; e >= 0; e = C.entNext[e]!) {
      const b = C.entBall[e]!
      if (C.seen[b] === stamp || staleEntry(C, e)) continue
      // stale entries of balls that have since stopped: those are found through the resting grid
      const mb = w.Ball.mode[b]
      if (mb !== BallMode.Rolling && mb !== BallMode.RimRoll) continue
      C.seen[b] = stamp
      tryPair(w, a, b)
    }
  }
  if (big) {
    // every moving ball predicted before it in this window that can reach its capsule (the others pair with
    // it when they are predicted, through the big list)
    const balls = w.moving.dense
    for (let i = 0, m = w.moving.count; i < m; i++) {
      const b = balls[i]!
      if (C.seen[b] === stamp || C.predicted[b] !== C.stamp) continue
      C.seen[b] = stamp
      if (!mayReach(w, b)) continue
      tryPair(w, a, b)
    }
    if (mode !== BallMode.Resting) C.big = appendId(C.big, C.bigCount++, a)
  } else {
    for (let i = 0; i < C.bigCount; i++) {
      const b = C.big[i]!
      if (C.seen[b] === stamp || w.Ball.live[b] !== 1) continue
      const mb = w.Ball.mode[b]
      if (mb !== BallMode.Rolling && mb !== BallMode.RimRoll) continue
      C.seen[b] = stamp
      tryPair(w, a, b)
    }
  }
  // enter a's capsule, in the same cells (resting balls are found through the resting grid); its older
  // capsule's entries go stale
  if (mode !== BallMode.Resting) enterCapsule(C, a, n)
  if (mode === BallMode.Resting) return
  // resting balls, by centre cell (widened by the largest radius in the grid); all of them when that is
  // cheaper than the cells; then those too wide for the grid
  if (C.restCount > 0) {
    const rMask = C.restHead.length - 1
    query[CR] = look + C.maxRadius
    if (capsuleCellsOver(C, query, C.restHead.length)) {
      for (let k = 0; k <= rMask; k++) {
        for (let b = C.restHead[k]!; b !== 0; b = C.restNext[b]!) restingCandidate(w, a, b, stamp)
      }
    } else {
      n = capsuleCells(C, query, rMask)
      for (let k = 0; k < n; k++) {
        for (let b = C.restHead[C.cells[k]!]!; b !== 0; b = C.restNext[b]!) restingCandidate(w, a, b, stamp)
      }
    }
  }
  for (let i = 0; i < C.bigRestCount; i++) restingCandidate(w, a, C.bigRest[i]!, stamp)
}

/** A resting ball b near a's capsule: tried once per prediction, after a distance test. */
function restingCandidate(w: BallWorld, a: number, b: number, stamp: number): void {
  const C = w.collide!
  if (C.seen[b] === stamp) return
  C.seen[b] = stamp
  // the bucket also holds balls of far cells that hash alike: test the distance to a's capsule first
  seg[PX] = w.Ball.x[b]!
  seg[PY] = w.Ball.y[b]!
  segmentDistance2()
  const reach = cap[CR]! + w.Ball.radius[b]! + 2 * GAP_TOLERANCE
  if (seg[D2]! > reach * reach) return
  tryPair(w, a, b)
}

/**
 * Whether moving ball b can come within reach of a's capsule within the window: it moves no farther than
 * its present speed times the window's span (its speed never grows).
 */
function mayReach(w: BallWorld, b: number): boolean {
  const C = w.collide!
  E[AT] = C.now
  evalBall(w, b)
  const travel = Math.sqrt(E[VX] * E[VX] + E[VY] * E[VY]) * (C.until - C.now)
  const r = cap[CR]! + w.Ball.radius[b]! + travel + 2 * GAP_TOLERANCE
  seg[PX] = E[X]
  seg[PY] = E[Y]
  segmentDistance2()
  return seg[D2]! <= r * r
}

/**
 * segmentDistance2's point (PX, PY) and result (D2), in slots: doubles passed to and returned from a call V8
 * does not inline are boxed (where restingCandidate was inlined into predictBall and this was not, five
 * heap numbers a resting ball looked at).
 */
const seg = new Float64Array(3)
const PX = 0
const PY = 1
const D2 = 2

/** Squared distance from (seg[PX], seg[PY]) to the segment of a's capsule, cap (X1, Y1)–(X2, Y2), into seg[D2]. */
function segmentDistance2(): void {
  const px = seg[PX]!
  const py = seg[PY]!
  const x1 = cap[X1]!
  const y1 = cap[Y1]!
  const dx = cap[X2]! - x1
  const dy = cap[Y2]! - y1
  const len2 = dx * dx + dy * dy
  let s = len2 > 0 ? ((px - x1) * dx + (py - y1) * dy) / len2 : 0
  if (s < 0) s = 0
  else if (s > 1) s = 1
  const ex = x1 + s * dx - px
  const ey = y1 + s * dy - py
  seg[D2] = ex * ex + ey * ey
}

/** Searches a (the ball being predicted, its span in search[FROM]/search[TO]) and b over their common span. */
function tryPair(w: BallWorld, a: number, b: number): void {
  searchAndPush(w, a, b)
}

/** Continues a search that ran out of steps, from search[FROM] (where it stopped, past b's start). */
export function resumeSearch(w: BallWorld, a: number, b: number): void {
  motionEnd(w, a)
  search[TO] = E[MT]
  searchAndPush(w, a, b)
}

/** Searches a and b (searchContact) and pushes what it finds: their contact, or where to resume. */
function searchAndPush(w: BallWorld, a: number, b: number): void {
  searchContact(w, a, b)
  if (search[RESULT] === SearchResult.None) return
  const C = w.collide!
  const kind = search[RESULT] === SearchResult.Contact ? HeapKind.Contact : HeapKind.Resume
  // a contact found behind the clock (balls put down overlapping) is handled now; a search to resume goes
  // on from where it stopped, wherever the clock is (resuming from the clock made a creeping re-contact's
  // time depend on where the step began)
  pushTime[0] = kind === HeapKind.Resume || search[TIME] > C.now ? search[TIME] : C.now
  heapPush(C, kind, a < b ? a : b, a < b ? b : a)
}
