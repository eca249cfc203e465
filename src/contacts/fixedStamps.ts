// The fixed-tick velocity sweeps' stamps (src/contacts/fixedSolve.ts), within one call (scratch: one solve at
// a time): when each pair was last tested, and when each packed ball's velocity last changed, on a clock
// that counts the changes, and what each pair's last test found. A pair neither of whose balls has changed
// since its last test would be found so again: a sweep passes it by, and the rules run half way through a
// call (src/contacts/fixedJam.ts, fixedShock.ts) take what it was found without the swept test. The jam
// rule, which runs first, stamps the pairs it tests and finds not closing (foundNow), so the row rule after
// it and the next sweep take them as found too.
import type { FixedContactState } from '../world/fixedState.js'
import { grownTo } from '../world/fixedState.js'

export let testedAt = new Float64Array(256)
export let changedAt = new Float64Array(256)
/** per pair: its last test found it REFUSED (not meeting within the tick), PARTING (touching now and not approaching along the line of centres), or OTHER */
export let testedAs = new Uint8Array(256)
export const OTHER = 0
export const REFUSED = 1
export const PARTING = 2

/** Room for the tick's pairs and candidates. */
export function reserveStamps(F: FixedContactState): void {
  if (testedAt.length < F.pairCount) {
    testedAt = grownTo(testedAt, 2 * F.pairCount)
    testedAs = grownTo(testedAs, 2 * F.pairCount)
  }
  if (changedAt.length < F.n) changedAt = grownTo(changedAt, 2 * F.n)
}

/**
 * What pair p would be found again, REFUSED or PARTING, when neither of its balls changed since its last
 * test in the call; else OTHER (to be tested).
 */
export function asBefore(F: FixedContactState, p: number): number {
  const at = testedAt[p]!
  if (!(changedAt[F.pairA[p]!]! <= at && changedAt[F.pairB[p]!]! <= at) || !foundBefore) return OTHER
  const as = testedAs[p]!
  if (as !== OTHER) takenAsFound++
  return as
}

/**
 * Pair p was just tested by a rule (src/contacts/fixedJam.ts) at the balls' present velocities and found `as`,
 * with no impulse due (refused, parting, or meeting without approaching): stamped as a sweep's test would
 * stamp it, so the rules after it and the next sweep take it as found instead of testing it again.
 */
export function foundNow(F: FixedContactState, p: number, as: number): void {
  if (!foundBefore) return
  const a = changedAt[F.pairA[p]!]!
  const b = changedAt[F.pairB[p]!]!
  testedAt[p] = a > b ? a : b
  testedAs[p] = as
}

/** For tests: whether the rules may take a pair as found before (off: they test every pair), and the pairs they did. */
let foundBefore = true
let takenAsFound = 0
export function takeAsFound(on: boolean): void {
  foundBefore = on
}
export function takenAsFoundCount(): number {
  return takenAsFound
}
