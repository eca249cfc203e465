// Fixed-tick contacts: what a tick's velocity solve leaves for a finer tick. The sweeps
// (src/contacts/fixedSolve.ts) stop at CONTACT_ITERATIONS, and the widening rounds at their bounds, with some
// pairs still approaching; most close by a fraction of a px and the projection (fixedProject.ts) parts them
// at the next tick. But where balls cover many of their radii a tick (a row of radius-0.5 balls struck at
// 1e4 px/s, a push that runs the length of a row and back off a wall within one tick), a pair left closing
// goes through itself before the next tick, and the projection then parts it on the far side. A pair closes
// deep when, on straight lines at its present velocities, it closes within the tick by more than its gap
// (none when it overlaps) and its smaller radius: the smaller ball's centre would come inside the other
// ball. (Half the sum of the radii, the same for like balls, let a small ball bounced between a big one and a
// wall within the tick end it closing at 6,600 px/s, 5.2 px deep: a radius-2.3 ball wholly inside a
// radius-8.6 one, out through its far side before the next tick; tests/systems/fixedDeep.test.ts.) A ball
// of radius under DEEP_UNSEEN_DEPTH (a speck under a px across) closes deep only past that depth, or a
// quarter of the larger radius if less: no one sees a speck that far in, and the projection parts the two on
// the side they met (the larger ball's centre still three quarters of its radius away). A ball near a closed
// wall that still moves into it within the tick turns there between ticks, back into whatever is behind it.
// A try of a tick of at most CHAIN_PAIRS_PER_BALL pairs a candidate that leaves either, where the finest
// spacing (MAX_TICK_HALVINGS) would not, is solved again halved (systems/fixedContacts.ts, fixedRedo.ts): at
// a finer tick each push runs through fewer balls. A pair that would close by more than its smaller radius
// even at the finest spacing is left to the projection, a speck too: it is no push a finer tick shortens but
// a ball no solve holds (pumped to 1e5 px/s, or driven through balls 1e12 times lighter than itself). Judged
// by the speck's depth there as well, more ticks were solved again, not fewer: a speck of radius 0.0115
// closing at 3e4 px/s counted, and the crowd of specks pumping light balls in tests/systems/fixedHalve.test.ts
// took 673–1,208 ticks for 0.2 s against 595–767 before the speck's depth, and 546–732 with the rule as it is.
// Judged by the speck's radius alone, a radius-0.0015 ball of mass 865 running at 5e3 px/s into radius-11
// balls of mass 1e-9 crowded against a wall left tick after tick closing at 100–4,000 px/s (a solve stops it
// through balls 1e12 times lighter at no spacing), each solved again 8–10 times finer until it closed by less
// than 0.0015 px: 3,120 ticks for 0.2 s, a step of 10 s in 4.6 s; now 0.9 s (a named test in
// tests/adversarial.test.ts).
// A tick of more pairs a candidate is solved again only
// when it leaves at most DEEP_FRONTS of them (src/config/tolerances.ts: a push's front along a row struck
// fast, and the wall ahead); a crowd that leaves more is left to the projection: there every ball covers
// its neighbours' spacing, and each try costs the whole crowd (a crowd of 261 balls pumped to 5e7 px/s
// took 9 times as long).
import type { FixedContactState } from '../world/fixedState.js'
import { DEEP_UNSEEN_DEPTH, MAX_TICK_HALVINGS, TOUCH_GAP } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import { finestTick, intoWalls } from './fixedGrid.js'

/**
 * Whether pair (a, b) closes within the tick (`finest`: within finestTick[0]), on straight lines at the
 * present velocities, by more than its gap (none when overlapping) and its smaller radius, or, within the
 * tick and a speck (radius under DEEP_UNSEEN_DEPTH), by more than its gap and DEEP_UNSEEN_DEPTH or a quarter
 * of the larger radius, whichever is less (a boolean, not the amount, and no double passed: V8 boxes those
 * for a call it does not inline).
 */
export function closesDeep(F: FixedContactState, a: number, b: number, finest: boolean): boolean {
  const tick = finest ? finestTick[0]! : F.tick
  const unseen = !finest
  const dx = F.x[b]! - F.x[a]!
  const dy = F.y[b]! - F.y[a]!
  const ux = F.vx[b]! - F.vx[a]!
  const uy = F.vy[b]! - F.vy[a]!
  const half = dx * ux + dy * uy
  if (!(half < 0)) return false
  // the closest approach within the tick
  let tau = -half / (ux * ux + uy * uy)
  if (tau > tick) tau = tick
  const mx = dx + ux * tau
  const my = dy + uy * tau
  const d = Math.sqrt(dx * dx + dy * dy)
  const ra = F.r[a]!
  const rb = F.r[b]!
  const s = ra + rb
  let depth = ra < rb ? ra : rb
  if (unseen && depth < DEEP_UNSEEN_DEPTH) {
    const quarter = (ra < rb ? rb : ra) * 0.25
    const far = quarter < DEEP_UNSEEN_DEPTH ? quarter : DEEP_UNSEEN_DEPTH
    if (far > depth) depth = far
  }
  return d - Math.sqrt(mx * mx + my * my) > (d > s ? d - s : 0) + depth
}

/** Per packed candidate: 1 when the tick paired it with another (deepFiner; scratch). */
let paired = new Uint8Array(64)

/**
 * Whether the tick leaves a ball near a wall moving into it, or a pair closing deep, that would not do so
 * within a tick as short as the finest spacing's, CONTACT_TICK / 2^MAX_TICK_HALVINGS (a finer spacing can
 * solve it: not a ball that covers its neighbours' spacing even then, as one pumped to 1e7 px/s, nor one
 * wider than its box, nor a pair that would close by more than its smaller radius even then, a speck's too),
 * and no more than `most` of them (counted together; -1: no bound). Nothing but indices and the world crosses
 * the call: a double passed to a call V8 does not inline is boxed. A ball near a wall counts only when the
 * tick paired it: one with no pair reaches no other ball within the tick wherever a wall turns it (its reach
 * is a disc of its speed times the tick about where it starts, and every ball whose reach meets it is
 * paired), so a finer tick changes nothing for it. Counting those too halved the whole world's tick for tiny
 * balls rattling between the walls of a 5-px channel at 1e5 px/s, far from every other ball: 70 ticks solved
 * again every 5 ms. Nor does every pair count: on straight lines turned at closed walls (the path between
 * ticks, as the solve sees it) a ball keeps within its speed on each axis times the tick of where it starts
 * (a wall turns that axis's motion back, at the same speed or slower), so a pair whose two such boxes do not
 * meet cannot meet within the tick however the walls turn either (a hole that turns a ball within the
 * tick is left out here, as it is for a ball no wall turns). Counting every pair, balls at 1e5 px/s
 * rattling across a 5-px channel, each on its own line 3 px from the next, kept the tick halved 9 times
 * (tests/systems/fixedDeep.test.ts).
 */
export function deepFiner(w: BallWorld, F: FixedContactState, most: number): boolean {
  finestTick[0] = w.config.CONTACT_TICK / (1 << MAX_TICK_HALVINGS)
  let count = 0
  let marked = false
  for (let k = 0; k < F.nearWallCount; k++) {
    const i = F.nearWall[k]!
    if (intoWalls(F, i) === 0 || intoWalls(F, i, true) !== 0) continue
    if (!marked) {
      markPaired(F)
      marked = true
    }
    if (paired[i] === 1 && ++count > most && most >= 0) return false
  }
  for (let p = 0; p < F.pairCount; p++) {
    const a = F.pairA[p]!
    const b = F.pairB[p]!
    if (closesDeep(F, a, b, false) && !closesDeep(F, a, b, true) && ++count > most && most >= 0) return false
  }
  return count > 0
}

/**
 * Marks in `paired` the packed candidates that are in one of the tick's pairs whose boxes over the tick meet
 * (each ball within its speed on each axis times the tick of where it starts, plus the radii: see deepFiner).
 */
function markPaired(F: FixedContactState): void {
  if (paired.length < F.n) paired = new Uint8Array(2 * F.n)
  paired.fill(0, 0, F.n)
  const tick = F.tick
  for (let p = 0; p < F.pairCount; p++) {
    const a = F.pairA[p]!
    const b = F.pairB[p]!
    // the boxes each ball keeps within over the tick, on straight lines turned at walls
    const s = F.r[a]! + F.r[b]! + TOUCH_GAP
    if (Math.abs(F.x[b]! - F.x[a]!) > s + (Math.abs(F.vx[a]!) + Math.abs(F.vx[b]!)) * tick) continue
    if (Math.abs(F.y[b]! - F.y[a]!) > s + (Math.abs(F.vy[a]!) + Math.abs(F.vy[b]!)) * tick) continue
    paired[a] = 1
    paired[b] = 1
  }
}
