// Fixed-tick contacts: which candidates a widening round looks at (src/contacts/fixedReach.ts, widenHits;
// systems/fixedContacts.ts, mayPass). Whether a candidate is widened depends on its velocity, its reach
// and its capsule. Between two rounds only the solve changes a velocity and only the cut
// (src/contacts/fixedCut.ts) a capsule; a reach changes only when its candidate is widened. So a candidate
// touched by neither gives the answer it gave the round before, which looked at it. After a solve call that
// kept its stamps (src/contacts/fixedCalls.ts: no renumbering since the call before, which converged) a
// round looks only at the candidates that call changed and those whose capsules were cut, in the order of
// F.hit, the order every round walks; otherwise, or when they are many, at every candidate in F.hit. A push
// running along a row of thousands of balls then costs each round its few balls, not the whole row.
import type { FixedContactState } from '../world/fixedState.js'
import { cutList, cutsNow, takeCuts } from './fixedCapsule.js'
import { hitPlace, lastCallChanged, lastCallChanges } from './fixedCalls.js'

/** More than this many to look at: every candidate in F.hit is walked instead (a sort would cost more). */
const LISTED_MAX = 64

let listed = new Int32Array(2 * LISTED_MAX)

/**
 * The candidates this round looks at, into roundList() (their count), in the order of F.hit; -1 when
 * every candidate in F.hit is to be looked at. `take`: the cuts listed are taken (the round's widening
 * looks at them; mayPass, before it, only reads them).
 */
export function roundCandidates(F: FixedContactState, take: boolean): number {
  const changed = lastCallChanges()
  const cutCount = take ? takeCuts() : cutsNow()
  if (changed < 0 || changed + cutCount > LISTED_MAX || changed + cutCount >= F.hitCount) return -1
  const a = lastCallChanged()
  const c = cutList()
  let n = 0
  for (let k = 0; k < changed; k++) n = insert(a[k]!, n)
  for (let k = 0; k < cutCount; k++) n = insert(c[k]!, n)
  return n
}

/** Inserts candidate i by its place in F.hit into the n listed (no twice); the new count. */
function insert(i: number, n: number): number {
  const at = hitPlace(i)
  let b = n - 1
  while (b >= 0 && hitPlace(listed[b]!) > at) b--
  if (b >= 0 && listed[b] === i) return n
  for (let k = n; k > b + 1; k--) listed[k] = listed[k - 1]!
  listed[b + 1] = i
  return n + 1
}

export function roundList(): Int32Array {
  return listed
}
