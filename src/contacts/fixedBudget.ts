// Fixed-tick contacts: the work meter (config.BALL_COLLISIONS = 'fixed'), and the budget a game may set on it
// (config.CONTACT_WORK_BUDGET; 0, the default, sets none, and then config.UNLIKE_MASS_BUDGET applies: below).
// Each CONTACT_TICK span of the world's clock (the
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
// it with and project again, each as lean (without them a lean tick left such a ball 1.4 px deep in a crowd;
// one the last round's projection pushes into an unpaired ball counts the tick as capped too).
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
//
// With no CONTACT_WORK_BUDGET a span takes UNLIKE_MASS_BUDGET (16 by default), and the meter counts of each
// try's work only the share of its pairs whose masses are UNLIKE_MASS_RATIO apart or more. A light ball
// squeezed between two heavy ones closing takes about π·√(M/m) meetings to turn them (M/m up to 1e18 here), and
// the solve takes them all: 100 balls of mass 1 at 1e5 px/s among 100 of mass 1e-9 cost 30,686 sweeps in 0.1
// s. Such crowds spend this budget and go lean; scenes of like masses, and a row struck by a heavier ball (one
// unlike pair among many), spend none of it and are solved as with no budget, bit for bit. This budget is
// UNLIKE_MASS_BUDGET visits to each pair the span's first try pairs (counted as at least MIN_WORK_BALLS'
// n·(n − 1)/2 pairs), set at that pairing: a crowd has about ten pairs a ball within reach, not n/2. At 16
// visits to every pair of its balls, a pumped crowd of 370 balls could spend about 1.04 M visits a span
// before going lean, about 28 times its budget now (about 2,400 pairs), and seldom reached the mark past
// which a span's last ticks are skipped: the long adversarial run's two slowest such sequences stepped in
// 8.0–8.4 s, run alone, against 1.4–2.0 s now.
import { LEAN_ITERATIONS, LEAN_SHARE, MIN_WORK_BALLS, UNLIKE_MASS_RATIO } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import type { FixedContactState } from '../world/fixedState.js'

/**
 * slots of F.budget: the span metered, the work spent in it, its budget, the spans whose last ticks were
 * skipped, the share of a try's visits the meter counts
 */
const SPAN = 0
const WORK = 1
const LIMIT = 2
const SKIPPED = 3
const SHARE = 4
/** LIMIT of a span whose budget is UNLIKE_MASS_BUDGET until its first pairing sets it */
const UNSET = -2
/** the fewest pairs an UNLIKE_MASS_BUDGET span's budget counts */
const MIN_WORK_PAIRS = (MIN_WORK_BALLS * (MIN_WORK_BALLS - 1)) / 2

/** Whether the spans' budget is UNLIKE_MASS_BUDGET: the game set no CONTACT_WORK_BUDGET (the config is the world's for life). */
function unlikeBudget(w: BallWorld): boolean {
  return w.config.CONTACT_WORK_BUDGET === 0 && w.config.UNLIKE_MASS_BUDGET !== 0
}

/**
 * At a tick's solve: a new span starts a new count, its budget the game's CONTACT_WORK_BUDGET over the balls
 * on the panel now, or with none UNLIKE_MASS_BUDGET, which counts the work of unlike pairs only and is set
 * at the span's first pairing (meterPairs).
 */
export function meterTick(w: BallWorld, F: FixedContactState): void {
  const span = Math.floor((F.nextTick - 1) / (1 << F.halvings))
  const B = F.budget
  if (span === B[SPAN]) return
  B[SPAN] = span
  B[WORK] = 0
  const unlike = unlikeBudget(w)
  B[SHARE] = unlike ? 0 : 1
  if (unlike) {
    B[LIMIT] = UNSET
    return
  }
  const n = Math.max(MIN_WORK_BALLS, w.moving.count + F.rest.restCount + F.rest.bigRestCount)
  const budget = w.config.CONTACT_WORK_BUDGET
  B[LIMIT] = budget === 0 ? -1 : (budget * n * (n - 1)) / 2
}

/**
 * At a try's pairing, where the span's budget is UNLIKE_MASS_BUDGET: the share of the try's work the meter
 * counts is that of its pairs whose masses are UNLIKE_MASS_RATIO apart or more (by the balls' own masses).
 * A crowd of light balls pumped among heavy ones spends it; a row struck by a heavy ball, one unlike pair
 * among many like ones, or any scene of like masses, does not. The span's first pairing sets its budget:
 * UNLIKE_MASS_BUDGET visits to each of its pairs, at least MIN_WORK_PAIRS of them.
 */
export function meterPairs(w: BallWorld, F: FixedContactState): void {
  if (!unlikeBudget(w)) return
  const B = F.budget
  const pairs = F.pairCount
  const { pairA, pairB, id, mass } = F
  let unlike = 0
  for (let p = 0; p < pairs; p++) {
    const ma = mass[id[pairA[p]!]!]!
    const mb = mass[id[pairB[p]!]!]!
    if (ma >= UNLIKE_MASS_RATIO * mb || mb >= UNLIKE_MASS_RATIO * ma) unlike++
  }
  B[SHARE] = pairs === 0 ? 0 : unlike / pairs
  if (B[LIMIT] === UNSET) B[LIMIT] = w.config.UNLIKE_MASS_BUDGET * Math.max(pairs, MIN_WORK_PAIRS)
}

/** Counts `visits` pair visits (or candidates) to the span, at the share the meter counts. */
export function spend(F: FixedContactState, visits: number): void {
  F.budget[WORK] += visits * F.budget[SHARE]!
}

/** Whether the span has spent its budget (there is one: −1 is none, and UNSET none yet): the rest of it is solved lean. */
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

