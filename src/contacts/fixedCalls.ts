// Fixed-tick contacts: what the velocity solve (src/contacts/fixedSolve.ts) keeps from one call to the next
// within a tick, so that a push running along a row of thousands of balls (a widening round and a call a
// ball, src/contacts/fixedReach.ts) costs each call its few balls, not the whole row:
//   - which calls keep the stamps of the one before: a widening round's call, with no candidate renumbered
//     since the call before (src/contacts/fixedOrder.ts, packings). After a call that converged, its old
//     pairs were all tested after their balls' last change, so only its new pairs and the balls it changes
//     are looked at; after one that did not (its sweeps ran out, or ended on a pumped crowd), its first sweep
//     walks every pair but tests only those with a ball changed since their last test, as a later sweep does
//     (a crowd of fast heavy balls pumping light ones between them tested every pair again at each of its
//     rounds: a third of its tests). The rounds (src/contacts/fixedRounds.ts, and the rounds' bound in
//     systems/fixedContacts.ts) take only a call after one that converged as keeping;
//   - the candidates a call changed (src/contacts/fixedRounds.ts) and each candidate's place in F.hit;
//   - in a call that keeps the stamps, sweeps that visit only the pairs that can be met again: those of the
//     balls changed since their last test, taken from a heap in the order a whole sweep visits them (by
//     index, forward or backward), so they take the same impulses in the same order as the whole sweep.
//     A sweep whose pairs to look at would be more than a sixteenth of the tick's walks them all instead.
import type { FixedContactState } from '../world/fixedState.js'
import { grownTo } from '../world/fixedState.js'
import { packings } from './fixedOrder.js'
import { VELOCITY } from './fixedWallTurn.js'

let callN = 0
let callPacking = -1
/** the call keeps the stamps of the one before (stamped), and that one converged (kept) */
let kept = false
let stamped = false
/** the candidates the last call changed, each once, in the order it did */
let callHits = new Int32Array(64)
let callHitCount = 0
/** each candidate's place in F.hit (the tick's changed candidates) */
let hitPos = new Int32Array(256)

/**
 * A solve call begins, with the pairs below `fresh` met by a call that converged, or (fresh 0) the pairs
 * below `old` those of the call before in the same tick: whether it keeps the stamps of the call before (the
 * caller then fills only the new pairs and candidates).
 */
export function beginCall(F: FixedContactState, fresh: number, old: number): boolean {
  if (hitPos.length < F.n) hitPos = grownTo(hitPos, 2 * F.n)
  const keep = keeping && (fresh > 0 || old > 0) && packings() === callPacking
  const afterConverged = fresh > 0
  if (keep && afterConverged) keptCalls++
  else if (keep) continuedCalls++
  if (!keep) {
    for (let k = 0; k < F.hitCount; k++) hitPos[F.hit[k]!] = k
    linked = 0
    linkedN = 0
    linksValid = false
  }
  kept = keep && afterConverged
  stamped = keep
  callN = F.n
  callPacking = packings()
  callHitCount = 0
  pendingCount = 0
  pendingPairs = 0
  overflow = false
  sweepNo++
  if (keep) linkPairs(F)
  return keep
}

/** For tests: the velocity sweeps begun since the process started. */
let sweepsBegun = 0
export function sweepsRun(): number {
  return sweepsBegun
}

/** For tests: whether a call may keep the stamps (off: every call fills them and walks every pair and hit), and the calls that did. */
let keeping = true
let keptCalls = 0
let continuedCalls = 0
export function keepAcrossCalls(on: boolean): void {
  keeping = on
}
export function callsKept(): number {
  return keptCalls
}
/** For tests: the calls that kept the stamps of a call that did not converge. */
export function callsContinued(): number {
  return continuedCalls
}

/** The candidates of the last call (those from this index joined since). */
export function lastCallN(): number {
  return callN
}

/** Candidate i's velocity changes (first: the first time in the call); listed in F.hit the first time in the tick. */
export function listChange(F: FixedContactState, i: number, first: boolean): void {
  if ((F.changed[i]! & VELOCITY) === 0) {
    hitPos[i] = F.hitCount
    F.hit[F.hitCount++] = i
  }
  if (first) {
    if (callHitCount === callHits.length) callHits = grownTo(callHits, 2 * callHitCount)
    callHits[callHitCount++] = i
  }
  if (!stamped) return
  // the pairs to look at again: this ball's, in the next sweep (until they are too many to list: the next
  // sweep walks every pair), and those still ahead in this one
  if (pendMark[i] !== sweepNo && !overflow) {
    pendMark[i] = sweepNo
    if (pendingCount === pending.length) pending = grownTo(pending, 2 * pendingCount)
    pending[pendingCount++] = i
    pendingPairs += degree[i]!
    if (LIST_SHARE * pendingPairs > F.pairCount) overflow = true
  }
  if (!listing) return
  for (let p = head[i]!; p >= 0; p = F.pairA[p] === i ? linkA[p]! : linkB[p]!) {
    const key = back ? pairTotal - 1 - p : p
    if (key > atKey) push(p, key)
  }
}

/** The candidates whose velocity the last call changed (in lastCallChanged(), their count), or -1 unless it kept the stamps of a call that converged. */
export function lastCallChanges(): number {
  return kept ? callHitCount : -1
}

export function lastCallChanged(): Int32Array {
  return callHits
}

/** Candidate i's place in F.hit (i listed there). */
export function hitPlace(i: number): number {
  return hitPos[i]!
}

// Each candidate's pairs, linked through the pair arrays (linkA: the next pair of the pair's ball a, linkB
// of its ball b), for the pairs below `linked`; the candidates below linkedN have heads.
let head = new Int32Array(256)
let degree = new Int32Array(256)
let linkA = new Int32Array(256)
let linkB = new Int32Array(256)
let linked = 0
let linkedN = 0
let linksValid = false

/** Links the pairs listed since (all of them, after a call that did not keep the stamps). */
function linkPairs(F: FixedContactState): void {
  if (head.length < F.n) {
    head = grownTo(head, 2 * F.n)
    degree = grownTo(degree, 2 * F.n)
    pendMark = grownTo(pendMark, 2 * F.n)
  }
  if (linkA.length < F.pairCount) {
    linkA = grownTo(linkA, 2 * F.pairCount)
    linkB = grownTo(linkB, 2 * F.pairCount)
    heapMark = grownTo(heapMark, 2 * F.pairCount)
  }
  if (!linksValid) {
    linksValid = true
    linkedN = 0
    linked = 0
  }
  head.fill(-1, linkedN, F.n)
  degree.fill(0, linkedN, F.n)
  linkedN = F.n
  for (let p = linked; p < F.pairCount; p++) {
    const a = F.pairA[p]!
    const b = F.pairB[p]!
    linkA[p] = head[a]!
    head[a] = p
    linkB[p] = head[b]!
    head[b] = p
    degree[a]!++
    degree[b]!++
  }
  linked = F.pairCount
}

// The sweep's heap of pairs to visit, keyed by their place in the sweep (index forward, pairTotal − 1 −
// index backward); heapMark: the sweep a pair was last put in it; pending: the candidates changed this
// sweep (their pairs are looked at in the next), pendMark the sweep each was last listed in.
let heap = new Int32Array(256)
let heapKey = new Int32Array(256)
let heapCount = 0
let heapMark = new Float64Array(256)
let pending = new Int32Array(64)
let pendingCount = 0
let pendingPairs = 0
let pendMark = new Float64Array(256)
/** the pairs listed for the next sweep passed 1/LIST_SHARE of the tick's (a heap costs more than a walk then) */
let overflow = false
const LIST_SHARE = 16
/** a listing sweep that outgrew its list, walking every pair from where it was */
let walking = false
let sweepNo = 0
let listing = false
let back = false
let atKey = -1
let pairTotal = 0

/**
 * A sweep begins (backward if `backward`): true when it is to visit only the pairs listed (the call keeps the
 * stamps and they are few), which nextPair() then gives in order; false when every pair is to be walked.
 * `fresh`: in the call's first sweep, the pairs from there on are new and are visited.
 */
export function beginSweep(F: FixedContactState, backward: boolean, first: boolean, fresh: number): boolean {
  sweepsBegun++
  const from = pending
  const fromCount = pendingCount
  const fromPairs = pendingPairs
  const over = overflow
  overflow = false
  // this sweep's changes are listed anew
  pending = spare
  spare = from
  pendingCount = 0
  pendingPairs = 0
  sweepNo++
  listing = false
  walking = false
  if (!stamped) return false
  const todo = first ? F.pairCount - fresh : fromPairs
  if (over || LIST_SHARE * todo > F.pairCount) return false
  listing = true
  back = backward
  pairTotal = F.pairCount
  atKey = -1
  heapCount = 0
  if (first) for (let p = fresh; p < F.pairCount; p++) push(p, back ? pairTotal - 1 - p : p)
  else {
    for (let k = 0; k < fromCount; k++) {
      const i = from[k]!
      for (let p = head[i]!; p >= 0; p = F.pairA[p] === i ? linkA[p]! : linkB[p]!) push(p, back ? pairTotal - 1 - p : p)
    }
  }
  return true
}
let spare = new Int32Array(64)

/** The next pair of a listing sweep, in the sweep's order; -1 at its end (the walls after it push nothing). */
export function nextPair(): number {
  // too many listed: the rest of the sweep walks every pair (those listed are among them, in the same order)
  if (walking || heapCount > pairTotal / LIST_SHARE) {
    walking = true
    listing = false
    heapCount = 0
    if (atKey + 1 >= pairTotal) {
      atKey = pairTotal
      return -1
    }
    atKey++
    return back ? pairTotal - 1 - atKey : atKey
  }
  if (heapCount === 0) {
    atKey = pairTotal
    return -1
  }
  const p = heap[0]!
  atKey = heapKey[0]!
  heapCount--
  if (heapCount > 0) {
    const lp = heap[heapCount]!
    const lk = heapKey[heapCount]!
    let i = 0
    for (;;) {
      const l = 2 * i + 1
      if (l >= heapCount) break
      const r = l + 1
      const c = r < heapCount && heapKey[r]! < heapKey[l]! ? r : l
      if (heapKey[c]! >= lk) break
      heap[i] = heap[c]!
      heapKey[i] = heapKey[c]!
      i = c
    }
    heap[i] = lp
    heapKey[i] = lk
  }
  return p
}

function push(p: number, key: number): void {
  if (heapMark[p] === sweepNo) return
  heapMark[p] = sweepNo
  if (heapCount === heap.length) {
    heap = grownTo(heap, 2 * heapCount)
    heapKey = grownTo(heapKey, 2 * heapCount)
  }
  let i = heapCount++
  while (i > 0) {
    const up = (i - 1) >> 1
    if (heapKey[up]! <= key) break
    heap[i] = heap[up]!
    heapKey[i] = heapKey[up]!
    i = up
  }
  heap[i] = p
  heapKey[i] = key
}
