// Fixed-tick contacts: the tick's spacing, halved where balls close on their nearest partner by more than a
// share of their size in a tick (config.BALL_COLLISIONS = 'fixed', restitution above 0). A pair that closes
// by its own size in a tick meets again within the tick, each of its balls with its other partners too;
// past RESTITUTION_VISITS visits of one pair in a call, or MAX_TICK_CONTACTS contacts of a ball in a tick,
// the solve closes it inelastically (src/contacts/fixedSolve.ts), so an elastic crowd whose balls cover their
// size a tick loses its energy: 200 radius-11 balls at 3,000 px/s in an elastic 420 × 480 box keep 0.10 of
// it after 1/3 s at 1/120 s, 0.34-0.39 at 1/240 s. A tick is halved (src/contacts/fixedHalve.ts) until at
// most TRAVEL_SHARE of the candidates with a pair have their nearest partner (the least |d|² − S²) closing
// more than TRAVEL_PER_TICK · S a tick, S the two radii; at most config.CONTACT_TRAVEL_HALVINGS from
// CONTACT_TICK (0 by default: off; at 4 a gas at 1e5 px/s costs 16 times the ticks at most on this
// account). Off by default for what it costs where it works: an elastic crowd that keeps its energy stays
// fast, and the long adversarial run's crowds of balls at 1e5 px/s cost up to twice the time a run with it
// (docs/known-failures.md). The spacing's next try at coarsening back waits while the coarser tick would
// have more than half that share. Read from the tick's packed candidates and pairs at its solve, as the other
// halving rules are: the same at every frame rate. With restitution 0 every contact closes inelastically
// anyway, and the rule is off.
import { MAX_TICK_HALVINGS, TRAVEL_PER_TICK, TRAVEL_SHARE } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import type { FixedContactState } from '../world/fixedState.js'

/** Per packed candidate: the least |d|² − S² over its pairs, and the halvings that pair needs (scratch). */
let nearest = new Float64Array(64)
let needs = new Float64Array(64)
/** Candidates with a pair whose nearest partner needs h halvings, at [h] (scratch). */
const needAt = new Float64Array(MAX_TICK_HALVINGS + 2)
/** Ticks halved with the travel rule asking for it, over the process's life (for tests and benchmarks). */
let halvedForTravel = 0

/** Whether the travel rule applies to this world: fixed-tick contacts with restitution above 0, and halvings allowed it. */
export function travelApplies(w: BallWorld): boolean {
  return w.config.BALL_RESTITUTION > 0 && w.config.CONTACT_TRAVEL_HALVINGS > 0
}

/**
 * The halvings (at most `levels`) after which at most TRAVEL_SHARE of the candidates with a pair have a
 * nearest partner closing more than TRAVEL_PER_TICK of the two radii a tick at F.tick halved that often.
 */
export function travelHalvings(F: FixedContactState, levels: number): number {
  if (levels <= 0 || !anyFast(F)) return 0
  const paired = countNeeds(F, 1, levels)
  if (paired === 0) return 0
  let over = paired
  for (let h = 0; h < levels; h++) {
    over -= needAt[h]!
    if (over <= TRAVEL_SHARE * paired) return h
  }
  return levels
}

/**
 * Whether some packed candidate covers more than 0.99 · TRAVEL_PER_TICK of its radius a tick. A pair closes
 * at most the sum of its balls' speeds, so with none such no pair closes more than TRAVEL_PER_TICK of the two
 * radii a tick, and the tick needs no halving for them (a gas of slow balls: one pass over the candidates
 * instead of one over the pairs).
 */
function anyFast(F: FixedContactState): boolean {
  const t2 = F.tick * F.tick
  const f = 0.99 * TRAVEL_PER_TICK
  for (let k = 0; k < F.n; k++) {
    const vx = F.vx[k]!
    const vy = F.vy[k]!
    const reach = f * F.r[k]!
    if ((vx * vx + vy * vy) * t2 > reach * reach) return true
  }
  return false
}

/** Counts a tick halved with the travel rule asking for it (more halvings than a tick solved again asked). */
export function countTravelHalving(): void {
  halvedForTravel++
}

/** Ticks halved with the travel rule asking for it since the process started. */
export function ticksHalvedForTravel(): number {
  return halvedForTravel
}

/**
 * Whether the tick at twice F.tick, the coarser spacing, would have more than half TRAVEL_SHARE of the
 * candidates with a pair closing more than TRAVEL_PER_TICK of the two radii on their nearest partner: the
 * spacing then stays (only while it is within `most` halvings of CONTACT_TICK).
 */
export function holdsForTravel(F: FixedContactState, most: number): boolean {
  if (F.halvings === 0 || F.halvings > most) return false
  const paired = countNeeds(F, 2, 0)
  return paired > 0 && needAt[1]! > 0.5 * TRAVEL_SHARE * paired
}

/**
 * Per packed candidate with a pair: the halvings (up to levels + 1) its nearest partner needs for the pair to
 * close at most TRAVEL_PER_TICK · S in a tick at `times` F.tick (1, or 2: the coarser spacing) halved that
 * often, counted into needAt. Returns the candidates with a pair. (A whole number crosses the call, not the
 * tick: V8 boxes a double passed to a call it does not inline.)
 */
function countNeeds(F: FixedContactState, times: number, levels: number): number {
  const tick = times * F.tick
  const n = F.n
  if (nearest.length < n) {
    nearest = new Float64Array(2 * n)
    needs = new Float64Array(2 * n)
  }
  nearest.fill(Infinity, 0, n)
  for (let p = 0; p < F.pairCount; p++) {
    const a = F.pairA[p]!
    const b = F.pairB[p]!
    const dx = F.x[b]! - F.x[a]!
    const dy = F.y[b]! - F.y[a]!
    const S = F.r[a]! + F.r[b]!
    const c = dx * dx + dy * dy - S * S
    if (c >= nearest[a]! && c >= nearest[b]!) continue
    const ux = F.vx[b]! - F.vx[a]!
    const uy = F.vy[b]! - F.vy[a]!
    const limit = S * TRAVEL_PER_TICK
    // the pair's relative travel in a tick, squared, quartered at each halving (exact: powers of two)
    let travel = tick * tick * (ux * ux + uy * uy)
    const limit2 = limit * limit
    let h = 0
    while (travel > limit2 && h <= levels) {
      travel *= 0.25
      h++
    }
    if (c < nearest[a]!) {
      nearest[a] = c
      needs[a] = h
    }
    if (c < nearest[b]!) {
      nearest[b] = c
      needs[b] = h
    }
  }
  needAt.fill(0)
  let paired = 0
  for (let k = 0; k < n; k++) {
    if (nearest[k] === Infinity) continue
    paired++
    needAt[needs[k]!]!++
  }
  return paired
}
