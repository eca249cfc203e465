// Fixed-tick contacts: the contacts each ball takes within one contact tick of the world's clock,
// [k·CONTACT_TICK, (k + 1)·CONTACT_TICK), over all the (halved) ticks solved in it, as the exact method counts
// them (config.MAX_TICK_CONTACTS, src/config/tolerances.ts). A ball past that many takes its later contacts in
// that tick of the clock without restitution (src/contacts/fixedSolve.ts). Light balls among heavy ones in a
// closed elastic box are pumped by them toward MAX_SPEED, and a ball that crosses its box many times a tick
// meets a ball at nearly every one of its halved ticks: an elastic crowd of masses 8.6e-6 to 1e9 took
// thousands of ticks for 0.1 s. The counts live in the resting state's arrays (F.rest: a snapshot keeps them)
// and are added once a tick is solved, from each pair's impulses that tick, so a try solved again
// (src/contacts/fixedRedo.ts) counts once.
import { MAX_TICK_CONTACTS, PUMP_MASS_RATIO } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import type { FixedContactState } from '../world/fixedState.js'
import { contactTickKey, countContacts } from '../world/contactState.js'
import { S_CLOCK, solveSlots } from './fixedPairs.js'

/**
 * The key of the contact tick of the clock that the world's time falls in (k + 1: 0 is none). The time is
 * read here, not passed: a double passed to a call V8 does not inline is boxed.
 */
export function clockTick(w: BallWorld): number {
  return contactTickKey(w.time, w.config.CONTACT_TICK)
}

/**
 * Whether the pair (a, b) has a ball PUMP_MASS_RATIO times lighter than the other or more that has taken
 * MAX_TICK_CONTACTS contacts or more in the contact tick of the clock, whose key the solve keeps in
 * solveSlots[S_CLOCK] (read here, not passed: V8 boxed it at every impulse where it did not inline this).
 */
export function spent(F: FixedContactState, a: number, b: number): boolean {
  if (F.im[a]! >= PUMP_MASS_RATIO * F.im[b]!) return over(F, a)
  if (F.im[b]! >= PUMP_MASS_RATIO * F.im[a]!) return over(F, b)
  return false
}

function over(F: FixedContactState, i: number): boolean {
  const key = solveSlots[S_CLOCK]!
  const eid = F.id[i]!
  return F.rest.tickContactsAt[eid] === key && F.rest.tickContacts[eid]! >= MAX_TICK_CONTACTS
}

/** Adds the impulses of each pair at the tick (F.pairHit above its bit 0, up to RESTITUTION_VISITS) to its balls' counts. */
export function countTickContacts(w: BallWorld, F: FixedContactState): void {
  const key = clockTick(w)
  const C = F.rest
  for (let p = 0; p < F.pairCount; p++) {
    const v = F.pairHit[p]! >> 1
    if (v === 0) continue
    countContacts(C, F.id[F.pairA[p]!]!, key, v)
    countContacts(C, F.id[F.pairB[p]!]!, key, v)
  }
}
