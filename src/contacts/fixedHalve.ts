// Fixed-tick contacts: the tick's spacing, halved where the balls cover too much ground in a tick for their
// numbers (config.BALL_COLLISIONS = 'fixed'). A ball is paired with every ball it could reach within a tick
// in any direction (the swept test), so in a crowd of balls each moving many of their spacings a tick nearly
// every ball was paired with every other: 5,000 radius-0.5 balls at up to 3e4 px/s in a 1,000 px box had
// hundreds of pairs a candidate at 1/120 s, the solve's sweeps over them took 2.7 s for a step, and the
// visits bound on restitution (RESTITUTION_VISITS) drained an elastic gas of that kind. A tick whose pairs
// outnumber TICK_PAIRS_PER_CANDIDATE a candidate is halved h times, h the one that makes the least modelled
// work over the tick's span (work, below), up to MAX_TICK_HALVINGS; where the radii make the pairs (balls
// around a big one), halving leaves them and is not done. Where the last ticks' widening rounds kept
// multiplying the pairs they gathered (a crowd whose solve keeps speeding balls past their reach), the pairs
// are counted times that growth, here and for coarsening back (sustainedGrowth). The pairs of the finer tick
// are those of the tick whose reaches at the finer tick still meet (reaches only shrink: a subset, taken from
// the list in its order), every candidate takes its finer reach, and the ticks go on at that spacing. The
// spacing is coarsened back, one halving at a time, at a tick of the coarser spacing once the last tick's
// pairs were within a quarter of the bound, or a finer tick would not have thinned them; a try that is halved
// again at once doubles the ticks before the next. Ticks stay k·tick of the world's clock (tick =
// CONTACT_TICK / 2^halvings, so every tick of a coarser spacing is one of the finer), and every decision is
// taken from the world's state at a solve (its balls, the last solve's pairs, the back-off, the last ticks'
// growth), never from where a step ends: the ticks are the same at every frame rate and in both broadphases
// (which list the same pairs in the same order), and a snapshot keeps them. With restitution above 0, a tick
// is also halved where its balls close on their nearest partner by more than a share of their size a tick,
// and held from coarsening back while the coarser tick would have them do so (src/contacts/fixedTravel.ts).
import { BallMode } from '../../components/Ball.js'
import { GROWTH_TICKS, MAX_TICK_HALVINGS, TICK_PAIRS_PER_CANDIDATE, TICK_SNAP, TOUCH_GAP } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import type { FixedContactState } from '../world/fixedState.js'
import { countTravelHalving, holdsForTravel, travelApplies, travelHalvings } from './fixedTravel.js'
import { halvedActive, keepActive } from './fixedActive.js'
import { instantOut, tickInstant } from '../world/gridTime.js'

/** Per packed candidate: its speed, and its reach at each further halving (level h at [h·n + k]; scratch). */
let speed = new Float64Array(64)
let reachAt = new Float64Array(64)
/** Whether this solve's coarsenTick went to the coarser spacing (halveTick reads it in the same solve). */
let coarsened = false
/** Pairs kept at each further halving (scratch). */
const keptAt = new Float64Array(MAX_TICK_HALVINGS + 1)

/**
 * Before a tick's gather: back to the coarser spacing when the world is on one of its ticks and the last
 * tick's pairs were within a quarter of the bound (halving a tick about quarters the pairs of balls that
 * cover much ground, so the coarser tick should stay within it; if not, it is halved again), or recorded as
 * none (halveTick: a finer tick would not have thinned them), unless an earlier try is being waited out.
 */
export function coarsenTick(w: BallWorld, F: FixedContactState): void {
  coarsened = false
  if (F.halvings === 0) return
  // only at a tick's own solve, which runs at the end of the window that reaches it (not at a solve a command
  // asked for at a window's start, whose window ends at the tick of this spacing)
  const k = F.nextTick - 1
  if (w.time !== w.tickEnd || k % 2 !== 0) return
  tickInstant(w, F.halvings, k)
  if (w.time !== instantOut[0]) return
  sustainedGrowth(F)
  if (!fewPairs(F, true)) return
  if (F.coarsenWait > 0) {
    F.coarsenWait--
    return
  }
  coarsened = true
  F.halvings--
  setTick(w, F)
  F.nextTick = k / 2 + 1
}

/**
 * Whether the last tick's pairs (before its widening rounds; none when a finer tick would not have thinned
 * them) were within a quarter of the halving bound, at most TICK_PAIRS_PER_CANDIDATE / 4 a candidate: few
 * enough for the spacing to coarsen back. coarsenTick counts them times the last ticks' sustained growth
 * (`grown`: sustainedGrowth's, just taken), as halveTick does (else a tick halved for its growth coarsens
 * back at once, and the spacing swings).
 */
export function fewPairs(F: FixedContactState, grown = false): boolean {
  const growth = grown ? growthOut[0]! : 1
  return 4 * F.tickPairs * growth <= TICK_PAIRS_PER_CANDIDATE * F.tickFull
}

/**
 * After a tick's pairs are found: when they outnumber TICK_PAIRS_PER_CANDIDATE a candidate, the tick is
 * halved h times, h the one that makes the least work over this tick's span (see work); 0 when the pairs
 * hardly fall (the radii make them). Its pairs and every candidate's reach are then those of the finer tick,
 * and the next tick comes that much sooner. Records the tick's pairs for coarsenTick (none, on a halved tick
 * whose pairs a finer one would not thin), and backs coarsening off when the coarser tick it just tried is
 * halved again at once.
 */
export function halveTick(w: BallWorld, F: FixedContactState, atLeast = 0): number {
  const levels = MAX_TICK_HALVINGS - F.halvings
  let h = 0
  let saturated = false
  sustainedGrowth(F)
  const growth = growthOut[0]!
  // balls closing on their nearest partner by more than a share of their size a tick (src/contacts/fixedTravel.ts)
  const travelOn = travelApplies(w)
  const travel = travelOn ? travelHalvings(F, Math.min(levels, w.config.CONTACT_TRAVEL_HALVINGS - F.halvings)) : 0
  const byTravel = travel > atLeast
  if (byTravel) atLeast = travel
  if (F.pairCount * growth > TICK_PAIRS_PER_CANDIDATE * F.full || atLeast > 0) {
    h = levels > 0 ? bestHalvings(w, F, levels) : 0
    // a tick solved again at a finer spacing (src/contacts/fixedRedo.ts), or one whose balls close on their
    // nearest partner too far a tick: at least that many
    if (h < atLeast) h = Math.min(atLeast, levels)
    if (byTravel && h > 0) countTravelHalving()
    if (h > 0) {
      // the balls taking part are counted before the halving drops pairs (src/contacts/fixedActive.ts)
      keepActive(F)
      halve(w, F, h)
      halvedActive(F)
    }
    // a halved tick whose pairs a finer one would not thin (half of them or more kept: balls sped up beyond
    // any spacing, as light ones struck by heavy ones) gains nothing from its spacing: back to coarser
    // ticks, as when its pairs are few
    else saturated = F.halvings > 0 && (levels === 0 || 2 * keptAt[1]! >= F.pairCount)
  } else if (F.halvings > 0 && 4 * F.pairCount > TICK_PAIRS_PER_CANDIDATE * F.full) {
    // a halved tick of too many pairs to coarsen back but too few to halve: its pairs are the balls' radii
    // (a crowd squeezed together) when a finer tick would keep half of them or more; it gains nothing from
    // its spacing either
    if (levels > 0) countKept(w, F, 1)
    saturated = levels === 0 || 2 * keptAt[1]! >= F.pairCount
  }
  if (coarsened) {
    // a coarser tick that had to be halved again: try again only after twice as many ticks as last time
    F.coarsenBackoff = h > 0 ? Math.min(2 * F.coarsenBackoff, MAX_COARSEN_WAIT) : 1
    if (h > 0) F.coarsenWait = F.coarsenBackoff
    coarsened = false
  }
  F.tickPairs = saturated ? 0 : F.pairCount
  // too fast for the coarser tick: its next try at coarsening waits (src/contacts/fixedTravel.ts)
  if (travelOn && holdsForTravel(F, w.config.CONTACT_TRAVEL_HALVINGS)) F.coarsenWait = Math.max(F.coarsenWait, 1)
  F.tickFull = F.full
  gathered = F.pairCount
  return h
}

/**
 * At a tick's end (its pairs all found, the widening rounds' too): how much they grew from the pairs it had
 * at its spacing before those rounds (1 for a tick with none), kept for the last GROWTH_TICKS ticks.
 */
export function recordGrowth(F: FixedContactState, pairs: boolean): void {
  F.tickGrowth[F.ticks % GROWTH_TICKS] = pairs && gathered > 0 ? F.pairCount / gathered : 1
}
/** This tick's pairs at its spacing before its widening rounds (halveTick; recordGrowth reads it at the same tick's end). */
let gathered = 0

/**
 * The growth a tick's pairs are counted with (halveTick): the least over the last GROWTH_TICKS ticks. A crowd
 * whose solve keeps speeding balls past their reach (light balls pumped by heavy ones) ends each tick with
 * several times the pairs it gathered, and its sweeps do not converge there: counted as gathered, its pairs
 * were within the bound and its tick was never halved. A push along a row grows them a hundredfold, but at
 * a tick or two: the least is 1 there. Into growthOut[0] (V8 boxes a double returned from a call it does not
 * inline, and one passed to it).
 */
function sustainedGrowth(F: FixedContactState): void {
  const g = F.tickGrowth
  let least = g[0]!
  for (let i = 1; i < GROWTH_TICKS; i++) if (g[i]! < least) least = g[i]!
  growthOut[0] = least
}

/** sustainedGrowth's answer */
const growthOut = new Float64Array(1)

/** Halvings still open to a tick from the spacing it started at (saveSpacing). */
export function halvingsLeft(): number {
  return MAX_TICK_HALVINGS - spacing[0]!
}

/** The spacing's state at a tick's start, after coarsenTick: halvings, tick, next tick, the window's end, coarsening's counts and flag. */
const spacing = new Float64Array(9)

/** Keeps the spacing's state at a tick's start (after coarsenTick), for a tick solved again (restoreSpacing). */
export function saveSpacing(w: BallWorld, F: FixedContactState): void {
  spacing[0] = F.halvings
  spacing[1] = F.tick
  spacing[2] = F.nextTick
  spacing[3] = w.tickEnd
  spacing[4] = F.tickPairs
  spacing[5] = F.tickFull
  spacing[6] = F.coarsenWait
  spacing[7] = F.coarsenBackoff
  spacing[8] = coarsened ? 1 : 0
}

/** Puts back the spacing's state saveSpacing kept: the tick is gathered and halved again from there. */
export function restoreSpacing(w: BallWorld, F: FixedContactState): void {
  F.halvings = spacing[0]!
  F.tick = spacing[1]!
  F.nextTick = spacing[2]!
  w.tickEnd = spacing[3]!
  F.tickPairs = spacing[4]!
  F.tickFull = spacing[5]!
  F.coarsenWait = spacing[6]!
  F.coarsenBackoff = spacing[7]!
  coarsened = spacing[8] === 1
}

/** Most ticks coarsening waits after tries that were halved again at once (doubling from 2). */
const MAX_COARSEN_WAIT = 1024

/**
 * The halvings, up to `levels`, that make the least work (see halveTick), from the pairs each keeps, times
 * their growth (growthOut).
 */
function bestHalvings(w: BallWorld, F: FixedContactState, levels: number): number {
  const growth = growthOut[0]!
  countKept(w, F, levels)
  let best = 0
  let least = work(F.full, F.pairCount * growth, 0)
  for (let h = 1; h <= levels; h++) {
    const at = work(F.full, keptAt[h]! * growth, h)
    if (at < least) {
      least = at
      best = h
    }
  }
  return best
}

/**
 * The tick's pairs whose reaches still meet at each further halving up to `levels`, in keptAt[h], with each
 * candidate's reach at halving h in reachAt[h·n + k] (halve takes them from there).
 */
function countKept(w: BallWorld, F: FixedContactState, levels: number): void {
  const n = F.n
  if (speed.length < n) speed = new Float64Array(2 * n)
  if (reachAt.length < (levels + 1) * n) reachAt = new Float64Array(2 * (levels + 1) * n)
  for (let k = 0; k < n; k++) {
    const vx = F.vx[k]!
    const vy = F.vy[k]!
    speed[k] = Math.sqrt(vx * vx + vy * vy)
  }
  for (let h = 1; h <= levels; h++) {
    const tick = w.config.CONTACT_TICK / (1 << (F.halvings + h))
    const o = h * n
    for (let k = 0; k < n; k++) reachAt[o + k] = F.r[k]! + speed[k]! * tick + TOUCH_GAP
  }
  keptAt.fill(0)
  for (let p = 0; p < F.pairCount; p++) {
    const a = F.pairA[p]!
    const b = F.pairB[p]!
    let h = 1
    while (h <= levels && meetsAt(F, a, b, h * n)) keptAt[h++]!++
  }
}

/**
 * The modelled work over a tick's span halved h times: 2^h ticks of n candidates and `pairs` pairs each, a
 * pair costing more the more pairs each ball has (each impulse tests again every pair of the balls it
 * changes, and a tick of many pairs a ball has many impulses): 1 + pairs a candidate / PAIR_DEGREE. Fitted
 * to measured ticks: 400 balls in a 100 px box, 199 pairs a candidate, 2 µs a pair; 12 pairs a candidate,
 * 0.3 µs a pair or candidate.
 */
function work(n: number, pairs: number, h: number): number {
  return (1 << h) * (n + pairs * (1 + pairs / (PAIR_DEGREE * n)))
}
const PAIR_DEGREE = 32

/** Halves the tick h times: the pairs and reaches of the finer tick, the clock's next tick at its spacing. */
function halve(w: BallWorld, F: FixedContactState, h: number): void {
  const n = F.n
  const o = h * n
  let kept = 0
  for (let p = 0, count = F.pairCount; p < count; p++) {
    const a = F.pairA[p]!
    const b = F.pairB[p]!
    if (!meetsAt(F, a, b, o)) continue
    F.pairA[kept] = a
    F.pairB[kept] = b
    F.pairHit[kept] = 0
    kept++
  }
  F.pairCount = kept
  for (let k = 0; k < n; k++) F.reach[k] = reachAt[o + k]!
  F.halvings += h
  setTick(w, F)
  if (F.dense === 0) sweepReaches(w, F)
  // the next tick of the finer spacing after now: the one after this tick, or after now when the solve runs
  // between ticks (one a command asked for)
  let next = (1 << h) * (F.nextTick - 1) + 1
  for (;;) {
    tickInstant(w, F.halvings, next)
    if (instantOut[0]! > w.time) break
    next++
  }
  F.nextTick = next
  // a solve at a window's start: the window ends at that tick at the latest, or on it when the window would
  // end a few ulps short of it (TICK_SNAP, as a step does at a tick); src/schedule.ts solves a window that
  // ends on the next tick
  const at = instantOut[0]!
  if (at <= w.tickEnd || nearTick(at, w.tickEnd, w.tickEnd - w.time)) w.tickEnd = at
}

/**
 * Whether a window ending at `end` ends on the tick at `tick` but for rounding: within TICK_SNAP of it
 * (relative), and never by half the window's `span` or more (at a clock of months, 8ε of it passes a step
 * of 1e-9 s).
 */
export function nearTick(tick: number, end: number, span: number): boolean {
  const gap = Math.abs(tick - end)
  return gap <= TICK_SNAP * tick && gap < 0.5 * span
}

/**
 * On a sweep tick, the finer reach of the candidates the sweep gathered and did not pack too (F.reachOf: the
 * widening rounds look them up there, and pack those they reach with it), as the dense broadphase has for
 * every candidate; the big ones keep theirs, so the two places that tell them apart (reachOf over half the
 * ordering cell: they were paired through F.big) still do (the packed ones, every big one among them, have
 * their finer reach in F.reach).
 */
function sweepReaches(w: BallWorld, F: FixedContactState): void {
  const B = w.Ball
  const half = F.cell / 2
  const tick = F.tick
  for (let p = 0; p < F.ordCount; p++) {
    const e = F.ord[p]!
    const m = B.mode[e]
    if (m !== BallMode.Rolling && m !== BallMode.RimRoll) continue
    if (F.reachOf[e]! > half) continue
    const vx = B.vx[e]!
    const vy = B.vy[e]!
    F.reachOf[e] = B.radius[e]! + Math.sqrt(vx * vx + vy * vy) * tick + TOUCH_GAP
  }
}

/** Whether packed candidates a and b are within each other's reach at the halving whose reaches start at o (the broadphases' test). */
function meetsAt(F: FixedContactState, a: number, b: number, o: number): boolean {
  const dx = F.x[b]! - F.x[a]!
  const dy = F.y[b]! - F.y[a]!
  const s = reachAt[o + a]! + reachAt[o + b]!
  return dx * dx + dy * dy < s * s
}

/**
 * F.tick: CONTACT_TICK halved F.halvings times (exact: a power of two), written here, not returned (V8 boxes
 * a returned double).
 */
function setTick(w: BallWorld, F: FixedContactState): void {
  F.tick = w.config.CONTACT_TICK / (1 << F.halvings)
}
