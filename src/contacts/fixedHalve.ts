// Fixed-tick contacts: the tick's spacing, halved where the balls cover too much ground in a tick for their
// numbers (config.BALL_COLLISIONS = 'fixed'). A ball is paired with every ball it could reach within a tick
// in any direction (the swept test), so in a crowd of balls each moving many of their spacings a tick nearly
// every ball was paired with every other: 5,000 radius-0.5 balls at up to 3e4 px/s in a 1,000 px box had
// hundreds of pairs a candidate at 1/120 s, the solve's sweeps over them took 2.7 s for a step, and the
// visits bound on restitution (RESTITUTION_VISITS) drained an elastic gas of that kind. A tick whose pairs
// outnumber TICK_PAIRS_PER_CANDIDATE a candidate is halved h times, h the one that makes the least work over
// the tick's span, 2^h ticks of (candidates + pairs at that spacing) each, up to MAX_TICK_HALVINGS; where the
// radii make the pairs (balls around a big one), halving leaves them and is not done. The pairs of the finer
// tick are those of the tick whose reaches at the finer tick still meet (reaches only shrink: a subset, taken
// from the list in its order), and the ticks go on at that spacing. The spacing is coarsened back, one
// halving at a time, at a tick of the coarser spacing once the last tick's pairs were within a quarter of
// the bound. Ticks stay k·tick of the world's clock (tick = CONTACT_TICK / 2^halvings, so every tick of a
// coarser spacing is one of the finer), and the decisions are taken from the tick's balls alone: the ticks
// are the same at every frame rate and in both broadphases (which give the same pairs in the same order),
// and a snapshot keeps them.
import { MAX_TICK_HALVINGS, TICK_PAIRS_PER_CANDIDATE, TOUCH_GAP } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import type { FixedContactState } from '../world/fixedState.js'

/** Per packed candidate: its speed, and its reach at each further halving (level h at [h·n + k]; scratch). */
let speed = new Float64Array(64)
let reachAt = new Float64Array(64)
/** Pairs kept at each further halving (scratch). */
const keptAt = new Float64Array(MAX_TICK_HALVINGS + 1)

/**
 * Before a tick's gather: back to the coarser spacing when the world is on one of its ticks and the last
 * tick's pairs were within a quarter of the bound (halving a tick about quarters the pairs of balls that
 * cover much ground, so the coarser tick should stay within it; if not, it is halved again).
 */
export function coarsenTick(w: BallWorld, F: FixedContactState): void {
  if (F.halvings === 0) return
  // only at a tick's own solve, which runs at the end of the window that reaches it (not at a solve a command
  // asked for at a window's start, whose window ends at the tick of this spacing)
  const k = F.nextTick - 1
  if (w.time !== w.tickEnd || k % 2 !== 0 || w.time !== k * F.tick) return
  if (4 * F.tickPairs > TICK_PAIRS_PER_CANDIDATE * F.tickFull) return
  F.halvings--
  F.tick = tickOf(w, F.halvings)
  F.nextTick = k / 2 + 1
}

/**
 * After a tick's pairs are found: when they outnumber TICK_PAIRS_PER_CANDIDATE a candidate, the tick is
 * halved h times, h the one that makes the least work of this tick's span, 2^h ticks of (candidates + pairs
 * at that spacing) each; 0 when the pairs hardly fall (the radii make them). Its reaches and pairs are then
 * those of the finer tick, and the next tick comes that much sooner. Records the tick's pairs for
 * coarsenTick.
 */
export function halveTick(w: BallWorld, F: FixedContactState): void {
  const levels = MAX_TICK_HALVINGS - F.halvings
  if (levels > 0 && F.pairCount > TICK_PAIRS_PER_CANDIDATE * F.full) {
    const h = bestHalvings(w, F, levels)
    if (h > 0) halve(w, F, h)
  }
  F.tickPairs = F.pairCount
  F.tickFull = F.full
}

/** The halvings, up to `levels`, that make the least work (see halveTick), from the pairs each keeps. */
function bestHalvings(w: BallWorld, F: FixedContactState, levels: number): number {
  const n = F.n
  if (speed.length < n) speed = new Float64Array(2 * n)
  if (reachAt.length < (levels + 1) * n) reachAt = new Float64Array(2 * (levels + 1) * n)
  for (let k = 0; k < n; k++) {
    const vx = F.vx[k]!
    const vy = F.vy[k]!
    speed[k] = Math.sqrt(vx * vx + vy * vy)
  }
  for (let h = 1; h <= levels; h++) {
    const tick = tickOf(w, F.halvings + h)
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
  let best = 0
  let least = F.full + F.pairCount
  for (let h = 1; h <= levels; h++) {
    const work = (1 << h) * (F.full + keptAt[h]!)
    if (work < least) {
      least = work
      best = h
    }
  }
  return best
}

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
  F.tick = tickOf(w, F.halvings)
  // the next tick of the finer spacing after now: the one after this tick, or after now when the solve runs
  // between ticks (one a command asked for)
  let next = (1 << h) * (F.nextTick - 1) + 1
  while (next * F.tick <= w.time) next++
  F.nextTick = next
  // a solve at a window's start: the window ends at that tick (src/schedule.ts solves it there)
  if (next * F.tick < w.tickEnd) w.tickEnd = next * F.tick
}

/** Whether packed candidates a and b are within each other's reach at the halving whose reaches start at o (the broadphases' test). */
function meetsAt(F: FixedContactState, a: number, b: number, o: number): boolean {
  const dx = F.x[b]! - F.x[a]!
  const dy = F.y[b]! - F.y[a]!
  const s = reachAt[o + a]! + reachAt[o + b]!
  return dx * dx + dy * dy < s * s
}

/** CONTACT_TICK halved h times (exact: a power of two). */
function tickOf(w: BallWorld, h: number): number {
  return w.config.CONTACT_TICK / (1 << h)
}
