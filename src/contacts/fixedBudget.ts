// Fixed-tick contacts: the work meter (config.BALL_COLLISIONS = 'fixed'), and the budget a game may set on it
// (config.CONTACT_WORK_BUDGET; 0, the default, sets none). Each CONTACT_TICK span of the world's clock (the
// ticks k·tick, tick = CONTACT_TICK / 2^halvings, with the same ⌊k / 2^halvings⌋) may then spend
// CONTACT_WORK_BUDGET visits to every pair of its balls: CONTACT_WORK_BUDGET · n·(n − 1)/2 pair visits, n the
// balls on the panel (moving and resting) at the span's first tick, counted as at least MIN_WORK_BALLS. The
// meter counts what a tick's time goes on: each velocity sweep the pairs it starts over (fixedSolve.ts), the
// projection its pair visits (fixedProject.ts), each try its candidates and the pairs it keeps
// (systems/fixedContacts.ts). Once a span has spent its budget, the rest of it is lean: the tick that spent
// it ends its widening rounds and tries no finer spacing, and each later tick of the span takes one try, one
// velocity call of LEAN_ITERATIONS sweeps without widening rounds, and a projection of at most
// LEAN_PROJECTION_BUDGET × pairs visits (an overlap it leaves counts the tick as capped; later ticks take it
// out), followed by up to MAX_WIDEN_ROUNDS rounds that pair a ball it pushed into one the tick had not paired
// it with and project again, each as lean (without them a lean tick left such a ball 1.4 px deep in a crowd).
// Once the lean ticks too have spent LEAN_SHARE × the budget, the span's remaining ticks are skipped: no
// solve until the next span's first tick (a span of a tick halved 9 times has 512 ticks, and solved lean
// they cost a 146-ball crowd at 1e5 px/s 150 ms a frame of 1/60 s; tests/adversarial.test.ts). So a span
// costs at most (1 + LEAN_SHARE) × its budget, plus the full tick that crossed the budget and the lean tick
// that crossed the second mark. In the skipped part the balls follow their paths through one another (the
// walls and holes as ever), and the next span's first tick takes out the overlaps. Every impulse is still a
// two-body contact: momentum kept, kinetic energy never rising. What a lean tick gives up is the rounds that
// pair a ball the solve sped up beyond its reach, so a ball can pass another within the tick: a push along a
// row, which needs those rounds, is what a budget breaks first (docs/decisions.md §12). The meter is part of
// the world's state (snapshots keep it) and is read only at ticks, whose times do not depend on where steps
// end: the same ticks are lean, and the same skipped, at every frame rate.
import { LEAN_ITERATIONS, LEAN_SHARE, MIN_WORK_BALLS } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import type { FixedContactState } from '../world/fixedState.js'

/** slots of F.budget: the span metered, the work spent in it, its budget, the spans whose last ticks were skipped */
const SPAN = 0
const WORK = 1
const LIMIT = 2
const SKIPPED = 3

/** At a tick's solve: a new span starts a new count, its budget from the balls on the panel now. */
export function meterTick(w: BallWorld, F: FixedContactState): void {
  const span = Math.floor((F.nextTick - 1) / (1 << F.halvings))
  const B = F.budget
  if (span === B[SPAN]) return
  B[SPAN] = span
  B[WORK] = 0
  const n = Math.max(MIN_WORK_BALLS, w.moving.count + F.rest.restCount + F.rest.bigRestCount)
  const budget = w.config.CONTACT_WORK_BUDGET
  B[LIMIT] = budget === 0 ? -1 : (budget * n * (n - 1)) / 2
}

/** Counts `visits` pair visits (or candidates) to the span. */
export function spend(F: FixedContactState, visits: number): void {
  F.budget[WORK] += visits
}

/** Whether the span has spent its budget (there is one: −1 is none): the rest of it is solved lean. */
export function lean(F: FixedContactState): boolean {
  const limit = F.budget[LIMIT]!
  return limit >= 0 && F.budget[WORK]! > limit
}

/**
 * At a tick's solve, before anything else: once the span has spent its budget and LEAN_SHARE of it again on
 * lean ticks, its remaining ticks are skipped (no solve; the next is the next span's first tick), and true.
 */
export function skipRest(F: FixedContactState): boolean {
  const B = F.budget
  const limit = B[LIMIT]!
  if (!(limit >= 0 && B[WORK]! > (1 + LEAN_SHARE) * limit)) return false
  // a solve a command asked for within the skipped part finds the next tick already there
  const next = (B[SPAN]! + 1) * (1 << F.halvings)
  if (F.nextTick !== next) B[SKIPPED]!++
  F.nextTick = next
  return true
}

/** The velocity sweeps a call may take: LEAN_ITERATIONS once the span is lean. */
export function iterationsNow(w: BallWorld, F: FixedContactState): number {
  return lean(F) ? Math.min(LEAN_ITERATIONS, w.config.CONTACT_ITERATIONS) : w.config.CONTACT_ITERATIONS
}

