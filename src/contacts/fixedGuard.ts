// Fixed-tick contacts: the tick's last guard against a ball passing through another before the next tick.
// Between ticks every ball follows its own path (turned by the walls at their instants), so a pair the tick
// leaves closing by more than its gap and its smaller radius within the tick (closing deep,
// src/contacts/fixedDeep.ts) is through itself at the next one, where the projection parts it on the far
// side. A try that leaves such a pair is solved again finer (systems/fixedContacts.ts), but that is judged
// before the projection, and three things come after it: the projection moves balls (a ball pushed out of
// its neighbour up to its wall, still moving into it), the velocities are solved again where a row was laid
// out from an anchor, and neither is tried again; and the solve's walls turn only the balls listed near a
// wall, so a ball struck toward a wall after its sweeps converged turns there between ticks, back through the
// ball that struck it. A ball 1e3–1e9 times heavier than a row of radius-0.5 balls driving it into a closed
// wall at restitution 1 let a ball through its neighbour in 140 of 1,000 random rows (npm run bench:piston-rows).
// So, where the tick's last velocity sweeps stopped at a bound, or the projection ran, or a ball the tick
// changed still moves into a closed wall, the pairs are looked at once more: each pair that closes deep is
// closed inelastically (the two-body impulse that leaves it no approach: momentum kept, kinetic energy not
// raised), and a paired ball that a closed wall would turn within the tick into a partner it then closes deep
// on is turned at the tick (as the solve turns a ball within reach of its wall), round after round up to
// GUARD_ROUNDS. Only on a tick that leaves at most DEEP_FRONTS fronts (a push's front along a row and the
// wall ahead, as for solving a tick again): a crowd whose light balls heavy ones pump leaves many, by design
// (docs/fixed-tick.md), and closed inelastically at every tick the pumped crowds of
// tests/systems/fixedHalve.test.ts kept 0.85 of their energy instead of 0.97. A front is a group of balls
// joined by such pairs and turns, however many pairs it has: a heavy ball turned at its wall is paired with
// the fifteen light balls its travel reaches (counted by pair, the guard left 91 of the rows passing, not
// 62), and a ball a solve sends back into a row closes deep on three of its balls at once (counted with a
// turned ball once but by pair otherwise, 58 of the rows passed, with the projection's deep join of
// src/contacts/fixedJoin.ts; by group, 45, 33 of them in rows with lean ticks past the work budget, which
// the guard leaves alone). On a tick of at most SMALL_TICK_BALLS balls it acts however many fronts there are,
// as such a tick is solved again finer however many pairs it has (a walk over its pairs costs little): a
// velocity solve after the projection left three pairs of neighbours closing through each other, apart
// from one another, in 4 of the 43 rows still passing (39 then; 60 small elastic crowds in closed boxes,
// radius 0.5–2 at 2e3–1e5 px/s, some with a ball 1e4–1e6 times heavier, step to the same bits). And on a
// lean tick of at most SMALL_TICK_BALLS balls too: of the 37 rows still passing then, 34 had lean ticks
// (they spend no widening rounds), and 26 pass with it (the pumped crowds of the tests keep what they kept
// but one: a box of 12 balls of mass 1e9 pumping 12 of mass 1e-8 pumps them to 4.4e6 px/s in 1 s, not
// 4.8e6; tests/systems/speedCap.test.ts).
// A tick whose solve converged with no ball struck into a wall is left as it was, to the bit: the gas and the
// panel of the contacts benchmark step to the same bits.
import { EventType, appendEvent } from '../events.js'
import { DEEP_FRONTS, GUARD_ROUNDS, SMALL_TICK_BALLS } from '../config/tolerances.js'
import { activeCount } from './fixedActive.js'
import { lean, spend } from './fixedBudget.js'
import type { BallWorld } from '../world/createWorld.js'
import type { FixedContactState } from '../world/fixedState.js'
import { closesDeep } from './fixedDeep.js'
import { unite } from './fixedUnion.js'
import { intoWalls } from './fixedGrid.js'
import { turnAtWalls, VELOCITY, WALL_REPORTED, WALL_TURNED } from './fixedWallTurn.js'
import { stillAtRest } from './fixedBlock.js'

/** Per packed candidate: intoWalls' bits this round, 0 once the guard turned it (scratch, grown by doubling). */
let into = new Uint8Array(64)

/** Pairs closed and balls turned by the guard over the process's life (tests and benchmarks). */
let guarded = 0

/** Pairs closed and balls turned by guardPasses since the process started. */
export function guardedCount(): number {
  return guarded
}

/**
 * Closes inelastically every pair of the tick that closes deep, and turns at the tick a ball that a closed
 * wall would turn into a partner it then closes deep on, round after round until none is left or
 * GUARD_ROUNDS, on a tick that leaves at most DEEP_FRONTS groups of them or has at most SMALL_TICK_BALLS
 * balls (see above). `full`: the last velocity sweeps stopped at a bound or the projection ran; else only a
 * ball the tick changed that still moves into a closed wall sets it looking. Not on a lean tick
 * (src/contacts/fixedBudget.ts) of more than SMALL_TICK_BALLS balls; each round is metered.
 * Returns the pairs and balls it changed.
 */
export function guardPasses(w: BallWorld, F: FixedContactState, full: boolean): number {
  if (F.pairCount === 0 || (lean(F) && activeCount(F) > SMALL_TICK_BALLS) || !(full || struckIntoWall(F))) return 0
  if (into.length < F.n) into = new Uint8Array(2 * F.n)
  let changed = 0
  for (let round = 0; round < GUARD_ROUNDS; round++) {
    // every candidate, not only those listed near a wall at the gather: the solve speeds balls up and the
    // projection moves them
    let walled = false
    for (let i = 0; i < F.n; i++) {
      const bits = intoWalls(F, i)
      into[i] = bits
      if (bits !== 0) walled = true
    }
    // (a small tick is guarded however many fronts it leaves: not counted there)
    if (round === 0 && activeCount(F) > SMALL_TICK_BALLS && countFronts(w, F, walled, DEEP_FRONTS) > DEEP_FRONTS) return 0
    spend(F, F.n + 2 * F.pairCount)
    let acted = 0
    for (let p = 0; p < F.pairCount; p++) acted += fronts(w, F, F.pairA[p]!, F.pairB[p]!, walled, true)
    changed += acted
    if (acted === 0) break
  }
  guarded += changed
  return changed
}

/** Per packed candidate: its group of fronts (union-find, src/contacts/fixedUnion.ts; scratch). */
let parent = new Int32Array(64)

/**
 * The fronts guardPasses would act on at its first round, counted up to most + 1: the groups of balls joined
 * by a pair closing deep, or by a ball a wall would turn into a partner it then closes deep on (a push's
 * front is one group however many of its balls close deep on each other); nothing is changed.
 */
function countFronts(w: BallWorld, F: FixedContactState, walled: boolean, most: number): number {
  if (parent.length < F.n) parent = new Int32Array(2 * F.n)
  for (let i = 0; i < F.n; i++) parent[i] = -1
  let count = 0
  for (let p = 0; p < F.pairCount && count <= most; p++) {
    const a = F.pairA[p]!
    const b = F.pairB[p]!
    if (fronts(w, F, a, b, walled, false) !== 0) count += joinFront(a, b)
  }
  return count
}

/**
 * Pair (a, b)'s tests of a round: a ball of it that a closed wall would turn into the other, which it then
 * closes deep on (`walled`: some candidate moves into a closed wall this round), and the pair closing deep.
 * `act`: each turns the ball or closes the pair as it finds it (guardPasses); else nothing is changed
 * (countFronts). Returns how many it found (acting: how many changed something).
 */
function fronts(w: BallWorld, F: FixedContactState, a: number, b: number, walled: boolean, act: boolean): number {
  let found = 0
  if (walled) {
    if (into[a]! !== 0 && turnsInto(w, F, a, b, act)) found++
    if (into[b]! !== 0 && turnsInto(w, F, b, a, act)) found++
  }
  if (fastEnough(F, a, b) && closesDeep(F, a, b, false) && (!act || closeInelastic(w, F, a, b))) found++
  return found
}

/** Joins candidates a and b into one group of fronts: the change in the number of groups. */
function joinFront(a: number, b: number): number {
  let change = 0
  if (parent[a] === -1) {
    parent[a] = a
    change++
  }
  if (parent[b] === -1) {
    parent[b] = b
    change++
  }
  return unite(parent, a, b) ? change - 1 : change
}

/**
 * Whether a candidate whose velocity the tick changed (F.hit) still moves into a closed wall within the tick:
 * the solve's walls turn only the candidates listed near a wall at the gather and in the widening rounds, and
 * a ball struck there after its sweeps converged goes on into the wall, to turn between ticks.
 */
function struckIntoWall(F: FixedContactState): boolean {
  for (let k = 0; k < F.hitCount; k++) {
    const i = F.hit[k]!
    if ((F.changed[i]! & VELOCITY) !== 0 && intoWalls(F, i) !== 0) return true
  }
  return false
}

/**
 * Whether pair (a, b) closes by more than its smaller radius within the tick at its relative speed: what
 * closing deep needs (closesDeep's depth is at least that radius), without a square root.
 */
function fastEnough(F: FixedContactState, a: number, b: number): boolean {
  const ux = F.vx[b]! - F.vx[a]!
  const uy = F.vy[b]! - F.vy[a]!
  const r = F.r[a]! < F.r[b]! ? F.r[a]! : F.r[b]!
  const t = F.tick
  return (ux * ux + uy * uy) * t * t > r * r
}

/**
 * Whether candidate i, turned at its closed walls now (their restitution; no speed along an axis it is wedged
 * on), closes deep on its partner o; `apply`: then it keeps that turn (its 'wall' event written at the tick),
 * else it is left as it was.
 */
function turnsInto(w: BallWorld, F: FixedContactState, i: number, o: number, apply: boolean): boolean {
  const vx = F.vx[i]!
  const vy = F.vy[i]!
  turnAtWalls(F, i, into[i]! & 3, false)
  const deep = fastEnough(F, i, o) && closesDeep(F, i, o, false)
  if (!apply || !deep) {
    F.vx[i] = vx
    F.vy[i] = vy
    return deep
  }
  into[i] = 0
  const c = F.changed[i]!
  F.changed[i] = c | VELOCITY | WALL_TURNED
  if ((c & WALL_REPORTED) === 0 && Math.max(Math.abs(F.vx[i]! - vx), Math.abs(F.vy[i]! - vy)) >= w.config.BALL_SETTLE_SPEED) {
    const ev = appendEvent(w.events, EventType.Wall, F.id[i]!, 0, false)
    w.events.time[ev] = w.time
    F.changed[i] = F.changed[i]! | WALL_REPORTED
  }
  return true
}

/**
 * The two-body impulse along the line of centres that leaves pair (a, b) no approach; a ball gathered at rest
 * that it would leave slower than BALL_SETTLE_SPEED holds like a wall (it stays at rest: src/contacts/fixedApply.ts),
 * as in the solve. Returns whether it changed a velocity.
 */
function closeInelastic(w: BallWorld, F: FixedContactState, a: number, b: number): boolean {
  const dx = F.x[b]! - F.x[a]!
  const dy = F.y[b]! - F.y[a]!
  const d = Math.sqrt(dx * dx + dy * dy)
  if (!(d > 0)) return false
  const nx = dx / d
  const ny = dy / d
  const approach = -((F.vx[b]! - F.vx[a]!) * nx + (F.vy[b]! - F.vy[a]!) * ny)
  if (!(approach > 0)) return false
  const settle = w.config.BALL_SETTLE_SPEED
  let ima = F.im[a]!
  let imb = F.im[b]!
  let j = approach / (ima + imb)
  if (j * ima < settle && stillAtRest(F, a)) ima = 0
  if (j * imb < settle && stillAtRest(F, b)) imb = 0
  if (ima + imb === 0) return false
  j = approach / (ima + imb)
  F.vx[a] = F.vx[a]! - j * ima * nx
  F.vy[a] = F.vy[a]! - j * ima * ny
  F.vx[b] = F.vx[b]! + j * imb * nx
  F.vy[b] = F.vy[b]! + j * imb * ny
  F.changed[a] = F.changed[a]! | VELOCITY
  F.changed[b] = F.changed[b]! | VELOCITY
  if (w.config.BALL_RESTITUTION > 0) F.inelastic++
  return true
}
