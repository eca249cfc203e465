// The fixed-tick method's contact solve (config.BALL_COLLISIONS = 'fixed'), at one contact tick, over the
// pairs of src/contacts/fixedGrid.ts:
//   velocities: up to CONTACT_ITERATIONS sweeps over the pairs (then the closed walls) in a fixed order.
//     A pair that approaches and would touch within the tick takes the two-body impulse
//     j = (1 + e)·w / (1/m_a + 1/m_b) (e = BALL_RESTITUTION, or 0 below BALL_SETTLE_SPEED): every impulse is
//     a two-body contact, so momentum is kept and kinetic energy never rises, sweep by sweep; a pair takes
//     its restitution up to RESTITUTION_VISITS (4) times a tick, and closes inelastically when pushed
//     together again after that. "Would touch
//     within the tick" is the swept test on straight lines at the present velocities, and the impulse acts
//     along the normal at that first touch, so a glancing contact leaves as it would at its instant, up to
//     one tick early. A closed wall within reach reflects the normal velocity with the walls' restitution.
//     A ball at rest that an impulse would leave slower than BALL_SETTLE_SPEED holds like a wall. A pair
//     that drives its lighter ball (SQUEEZE_MASS_RATIO times or more) into a closed wall it can reach is
//     solved together with that wall (src/contacts/fixedWallPair.ts):
//     a light ball squeezed or wedged against a wall by a heavy one would otherwise take a little of the
//     push each sweep, and the sweeps run out with the pair still closing; one touching a second ball as
//     heavy that closes on its partner (or that its partner closes on, at rest), with that contact
//     (src/contacts/fixedSqueeze.ts).
//   positions: src/contacts/fixedProject.ts.
// Then every ball the solve changed starts a fresh path from its new state at the tick:
// src/contacts/fixedApply.ts.
import { spend } from './fixedBudget.js'
import type { BallWorld } from '../world/createWorld.js'
import { grownTo, type FixedContactState } from '../world/fixedState.js'
import { bouncesBetween, intoWalls } from './fixedGrid.js'
import { beginCall, beginSweep, lastCallN, listChange, nextPair } from './fixedCalls.js'
import { meetsWithinTick, nrm, touch, PAIR_VISIT_SHIFT as VISIT_SHIFT, reportPair, S_APPROACH, S_CLOCK, S_E, S_IMA, S_IMB, S_J, S_LIMIT, S_SEPARATE, S_SETTLE, S_T, solveSlots as S } from './fixedPairs.js'
import { jammed, settleJams } from './fixedJam.js'
import { heldBalls, holdRows } from './fixedShock.js'
import { capImpulse } from './law.js'
import { overSpeed } from '../motion/speedLimit.js'
import { RESTITUTION_VISITS, SQUEEZE_MASS_RATIO } from '../config/tolerances.js'
import { clockTick, spent } from './fixedCount.js'
import { noteClosedApart } from './fixedRedo.js'
import { aheadOf, pushed, wallAhead } from './fixedAhead.js'
import { SQ_APPROACH, SQ_BOUND, SQ_CHAIN, SQ_J, SQ_J1, SQ_J2, SQ_OTHER, pairWithBall, squeeze, squeezeChain } from './fixedSqueeze.js'
import { STRUCK, turnAtWalls, VELOCITY, WALL_DUE, WALL_TURNED } from './fixedWallTurn.js'
import { block, capBall, pairWithWall } from './fixedWallPair.js'
import { stillAtRest } from './fixedBlock.js'
import { changedAt, OTHER, PARTING, REFUSED, reserveStamps, testedAs, testedAt } from './fixedStamps.js'

/**
 * A sweep's impulses: pairs met past RESTITUTION_VISITS whose one ball is SQUEEZE_MASS_RATIO times lighter
 * than the other or more (by their own masses: a ball at rest held like a wall is not a heavier one, or a slow
 * push along a row at rest ended its calls half way and left the row 5e-3 px deep), with restitution 1 any
 * pair one of whose balls is pumped (the light ball of such a meeting earlier in the call, or a ball a
 * meeting of this kind turned: the pumping passes from ball to ball), and all others
 */
let remet = 0
let plain = 0
/** the call in which each packed ball was last the light ball of such a meeting (scratch, as testedAt) */
let pumpedIn = new Float64Array(256)

/** the stamps' clock (src/contacts/fixedStamps.ts) */
let clock = 0
/** the clock when the last call began (src/contacts/fixedCalls.ts: what one call keeps for the next) */
let callFrom = 0
/** the calls begun (src/contacts/fixedSqueeze.ts keeps a call's adjacency by it) */
let calls = 0

/**
 * The velocity sweeps over the tick's pairs; true when a sweep left every pair as it was (converged).
 * `fresh`: pairs below it were met by a call that converged, at the velocities the balls still have (a
 * widening round in between only adds pairs): they are passed by until a ball of theirs changes. `old`
 * (with fresh 0): the pairs below it are those of the call before, in the same tick, with the positions
 * and velocities it left (a widening round in between): their stamps are kept (src/contacts/fixedCalls.ts).
 */
export function solveVelocities(w: BallWorld, F: FixedContactState, iterations: number, fresh = 0, old = 0): boolean {
  converged = sweepVelocities(w, F, iterations, fresh, old)
  return converged
}

/** whether the last solveVelocities call converged */
let converged = true

/** Whether the last velocity solve converged (the tick's last guard looks at every pair when it did not: src/contacts/fixedGuard.ts). */
export function lastSolveConverged(): boolean {
  return converged
}

/** solveVelocities' sweeps (see there). */
function sweepVelocities(w: BallWorld, F: FixedContactState, iterations: number, fresh: number, old: number): boolean {
  S[S_T] = w.time
  S[S_E] = w.config.BALL_RESTITUTION
  S[S_SETTLE] = w.config.BALL_SETTLE_SPEED
  S[S_LIMIT] = w.config.CONTACT_SPEED_LIMIT
  S[S_CLOCK] = clockTick(w)
  reserveStamps(F)
  if (pumpedIn.length < F.n) pumpedIn = grownTo(pumpedIn, 2 * F.n)
  const fromN = lastCallN()
  if (beginCall(F, fresh, old)) {
    // the old pairs and candidates keep their stamps; the new pairs are tested in the first sweep, and the
    // candidates that joined have not changed
    testedAt.fill(-1, fresh > 0 ? fresh : old, F.pairCount)
    changedAt.fill(0, fromN, F.n)
  } else {
    // every pair is tested in the first sweep (the packed balls may have moved in the arrays since a last
    // call), but for those a converged call met at these velocities: tested at clock 0, before any change
    testedAt.fill(0, 0, fresh)
    testedAt.fill(-1, fresh, F.pairCount)
    changedAt.fill(0, 0, F.n)
    clock = 0
  }
  callFrom = clock
  calls++
  let moved = false
  const mid = iterations >> 1
  for (let it = 0; it < iterations; it++) {
    // half the sweeps done without converging: a long row left closing moves on as one body
    // (src/contacts/fixedJam.ts), a row pressed into a closed wall is held by the wall (fixedShock.ts),
    // and the other half take their new velocities to the balls around them
    if (it === mid && it > 0) settle(w, F)
    moved = false
    // the walls first and last in each sweep, the pairs forward and backward in turn (symmetric
    // Gauss-Seidel): a push runs through a row against a wall either way within a sweep
    const back = (it & 1) === 1
    // every pair, or only those that can be met again, in the same order (src/contacts/fixedCalls.ts)
    const listed = beginSweep(F, back, it === 0, fresh)
    spend(F, F.pairCount)
    let turned = wallVelocities(w, F)
    remet = 0
    plain = 0
    if (listed) {
      for (let p = nextPair(); p >= 0; p = nextPair()) if (impulse(w, F, p)) moved = true
    } else if (walkAll(w, F, back)) moved = true
    turned |= wallVelocities(w, F)
    const walled = (turned & 1) !== 0
    if (walled) moved = true
    // a sweep whose only changes were balls turned between two walls they both reach within the tick ends
    // the sweeps: the next would turn them back, and the one after that again, for ever (pumping light balls
    // among heavy ones: docs/known-failures.md). It ends unconverged (the next call tests every pair)
    if (!moved) return turned === 0
    // from half way on, a sweep whose only impulses met light balls again past their restitution with
    // heavier ones (or, with restitution 1, met a ball such a meeting turned earlier in the call) ends the
    // sweeps too: each turns a light ball between heavy ones it reaches within the tick, as between two
    // walls, and the next sweep would turn it back (pumped crowds: docs/decisions.md §12). Before half way,
    // such a sweep brings half way forward: the jam and wall rules, then a sweep that ends the call if it
    // too is one (the sweeps between would only have turned those balls to and fro). Not at restitution 0
    // when a closed wall turned a ball in the sweep: a light ball pushed along a wall by a heavy one is
    // turned by the pair and then loses its motion into the wall, a little less of the push left each
    // sweep, and nothing is pumped (ended early, the pair went on closing: up to 4.2 px deep before the
    // next tick, docs/known-failures.md)
    if (remet > 0 && plain === 0 && !(S[S_E] === 0 && walled)) {
      if (it >= mid) return false
      it = mid - 1
    }
  }
  return false
}

/**
 * The solve's account of the velocities settleJams and holdRows changed. Each rule's list is read after it
 * ran: a rule grows its scratch arrays (the list among them) when the tick has more candidates than they
 * hold, and the list read before was the old array (the balls changed then went unstamped, and others were
 * stamped in their place).
 */
function settle(w: BallWorld, F: FixedContactState): void {
  const jams = settleJams(F)
  struckAll(F, jammed(), jams)
  const holds = holdRows(w, F, S[S_E]!, S[S_SETTLE]!, wallVelocity)
  struckAll(F, heldBalls(), holds)
}

/** The first `count` candidates of `list` were struck by a rule: each change noted and stamped. */
function struckAll(F: FixedContactState, list: Int32Array, count: number): void {
  for (let k = 0; k < count; k++) {
    const i = list[k]!
    noteChange(F, i)
    changedAt[i] = ++clock
    F.changed[i]! |= STRUCK
  }
}

/** Candidate i's velocity changes now (before its stamp): listed (src/contacts/fixedCalls.ts). */
function noteChange(F: FixedContactState, i: number): void {
  listChange(F, i, changedAt[i]! <= callFrom)
}

/**
 * Pair p takes the two-body impulse if it approaches and its balls would touch within the tick; returns
 * whether it did.
 */
function impulse(w: BallWorld, F: FixedContactState, p: number): boolean {
  const at = testedAt[p]!
  if (changedAt[F.pairA[p]!]! <= at && changedAt[F.pairB[p]!]! <= at) return false
  return impulseNow(w, F, p)
}

/** A sweep over every pair, forward or backward (impulse on each): whether any took an impulse. */
function walkAll(w: BallWorld, F: FixedContactState, back: boolean): boolean {
  const n = F.pairCount
  const A = F.pairA
  const B = F.pairB
  const T = testedAt
  const C = changedAt
  let moved = false
  for (let k = 0; k < n; k++) {
    const p = back ? n - 1 - k : k
    const at = T[p]!
    if (C[A[p]!]! <= at && C[B[p]!]! <= at) continue
    if (impulseNow(w, F, p)) moved = true
  }
  return moved
}

/** impulse without its stamp check: pair p is tested now (its stamp set), and takes the impulse if it meets. */
function impulseNow(w: BallWorld, F: FixedContactState, p: number): boolean {
  const a = F.pairA[p]!
  const b = F.pairB[p]!
  testedAt[p] = clock
  if (!meetsWithinTick(F, a, b)) {
    testedAs[p] = REFUSED
    return false
  }
  const approach = -((F.vx[b]! - F.vx[a]!) * nrm.x + (F.vy[b]! - F.vy[a]!) * nrm.y)
  // touching now, the normal is the line of centres (src/contacts/fixedPairs.ts, normal)
  if (!(approach > 0)) {
    testedAs[p] = touch.c <= 0 ? PARTING : OTHER
    return false
  }
  testedAs[p] = OTHER
  S[S_APPROACH] = approach
  return applyImpulse(w, F, p)
}

/** Pair p, approaching at S[S_APPROACH] along nrm, takes its impulse (see impulse); false if neither ball can move. */
function applyImpulse(w: BallWorld, F: FixedContactState, p: number): boolean {
  const approach = S[S_APPROACH]!
  const e = S[S_E]!
  const settle = S[S_SETTLE]!
  const a = F.pairA[p]!
  const b = F.pairB[p]!
  const nx = nrm.x
  const ny = nrm.y
  let ima = F.im[a]!
  let imb = F.im[b]!
  // restitution up to RESTITUTION_VISITS times a tick per pair (met again in a later sweep: a third ball or
  // a wall sent them together), then inelastic, so a light ball between heavy ones cannot be bounced to
  // and fro without end within one tick
  const hit = F.pairHit[p]!
  const visits = hit >> VISIT_SHIFT
  const bound = approach >= settle && (visits >= RESTITUTION_VISITS || spent(F, a, b))
  const k = (1 + (approach < settle || bound ? 0 : e)) * approach
  let j = k / (ima + imb)
  // a ball at rest that this impulse would leave slower than BALL_SETTLE_SPEED stays at rest (applyChanges),
  // so it holds like a wall: the other ball takes the whole impulse (else it would go on into a ball that
  // does not move, and overlap it until the next tick)
  const pinA = j * ima < settle && stillAtRest(F, a)
  const pinB = j * imb < settle && stillAtRest(F, b)
  if (pinA || pinB) {
    if (pinA) ima = 0
    if (pinB) imb = 0
    if (ima + imb === 0) return false
    j = k / (ima + imb)
  }
  if (visits < RESTITUTION_VISITS) F.pairHit[p] = hit + (1 << VISIT_SHIFT)
  if (bound && e > 0) {
    F.inelastic++
    // a pair apart at the tick's start: a finer tick may part its meetings (src/contacts/fixedRedo.ts)
    noteClosedApart(F, a, b)
  }
  // a pumped ball's other meetings go on only while the heavy ones turn it (docs/decisions.md §12), with
  // restitution 1: below it, piles of light balls a heavy one pressed into a corner kept velocities they
  // could not move at (2 and 4 balls at e = 0 and 0.5)
  if (visits >= RESTITUTION_VISITS && (F.im[a]! >= SQUEEZE_MASS_RATIO * F.im[b]! || F.im[b]! >= SQUEEZE_MASS_RATIO * F.im[a]!)) {
    remet++
    pumpedIn[F.im[a]! > F.im[b]! ? a : b] = calls
  } else if (e === 1 && (pumpedIn[a] === calls || pumpedIn[b] === calls)) {
    // and the other ball is pumped from now on in the call: a pumped ball knocks the balls around it into
    // one another, and those meetings kept the sweeps going (docs/decisions.md §12)
    remet++
    pumpedIn[a] = calls
    pumpedIn[b] = calls
  }
  else plain++
  // a ball SQUEEZE_MASS_RATIO times lighter than its partner (or more) that the impulse drives into a closed
  // wall it can reach within the tick (at its speed; a ball standing still, at the speed the impulse gives
  // it): the pair and that wall solved together (below), so a squeeze or a wedge ends in one visit, not a
  // little of the push each sweep (a ball lying by a wall, struck, was bounced between the wall and its
  // striker until the pair and the wall were solved together on a later visit, inelastic by then, so a heavy
  // striker stopped dead; a moving ball keeps its own reach: pinned at the wall, it would lose the part of
  // its motion the wall sends back, and an elastic gas its energy)
  let q = -1
  aheadOf(p)
  if (ima >= SQUEEZE_MASS_RATIO * imb) {
    pushed[0] = F.vx[a] === 0 && F.vy[a] === 0 ? j * ima : 0
    if (wallAhead(F, a, -1)) q = a
  }
  if (q < 0 && imb >= SQUEEZE_MASS_RATIO * ima) {
    pushed[0] = F.vx[b] === 0 && F.vy[b] === 0 ? j * imb : 0
    if (wallAhead(F, b, 1)) q = b
  }
  let walled = false
  if (q >= 0) {
    S[S_IMA] = ima
    S[S_IMB] = imb
    S[S_SEPARATE] = k - approach
    walled = pairWithWall(w, F, a, b, q)
  }
  // else a light ball touching a second heavy ball that closes on its partner, the impulse driving it there:
  // the two contacts together (src/contacts/fixedSqueeze.ts), by the balls' own masses: a heavy ball at rest
  // takes part, held like a wall only where the block too would leave it slower than BALL_SETTLE_SPEED
  let second = -1
  if (!walled && q < 0) {
    const ra = F.im[a]!
    const rb = F.im[b]!
    const l = ra >= SQUEEZE_MASS_RATIO * rb ? a : rb >= SQUEEZE_MASS_RATIO * ra ? b : -1
    if (l >= 0 && !(l === a ? pinA : pinB)) {
      S[S_SEPARATE] = k - approach
      squeeze[SQ_J] = j
      second = pairWithBall(F, p, l, calls)
    }
  }
  if (walled) {
    j = block.j
  } else if (second >= 0) {
    j = squeeze[SQ_J1]!
    const o = squeeze[SQ_OTHER]!
    capBall(F, a)
    capBall(F, b)
    capBall(F, o)
    noteChange(F, o)
    changedAt[o] = ++clock
    F.changed[o]! |= STRUCK
    // the light balls in a row after the pair's own (src/contacts/fixedSqueeze.ts)
    for (let k = 1, n = squeeze[SQ_CHAIN]!; k < n; k++) {
      const c = squeezeChain[k]!
      capBall(F, c)
      noteChange(F, c)
      changedAt[c] = ++clock
      F.changed[c]! |= STRUCK
    }
    // the second pair as the sweeps take a pair they meet: a visit, an inelastic meeting counted, reported
    const hit2 = F.pairHit[second]!
    if (hit2 >> VISIT_SHIFT < RESTITUTION_VISITS) F.pairHit[second] = hit2 + (1 << VISIT_SHIFT)
    if (squeeze[SQ_BOUND] === 1 && e > 0) F.inelastic++
    S[S_APPROACH] = squeeze[SQ_APPROACH]!
    S[S_J] = squeeze[SQ_J2]!
    reportPair(w, F, second, F.pairA[second]!, F.pairB[second]!)
  } else {
    const vax = F.vx[a]!
    const vay = F.vy[a]!
    const vbx = F.vx[b]!
    const vby = F.vy[b]!
    F.vx[a] = vax - j * ima * nx
    F.vy[a] = vay - j * ima * ny
    F.vx[b] = vbx + j * imb * nx
    F.vy[b] = vby + j * imb * ny
    // a light ball would leave faster than CONTACT_SPEED_LIMIT (and faster than it came) or MAX_SPEED: less
    // restitution (src/contacts/law.ts)
    const limit = S[S_LIMIT]!
    const ax = F.vx[a]!
    const ay = F.vy[a]!
    const bx = F.vx[b]!
    const by = F.vy[b]!
    // (pumpedPast, src/motion/speedLimit.ts, written out: here V8 does not take it inline, and its three
    // doubles a call were boxed, 20–46 bytes a ball-step in the crowd of unlike masses of the allocation test)
    const grows =
      ((ax > limit || ax < -limit) && ax * ax > vax * vax) ||
      ((ay > limit || ay < -limit) && ay * ay > vay * vay) ||
      ((bx > limit || bx < -limit) && bx * bx > vbx * vbx) ||
      ((by > limit || by < -limit) && by * by > vby * vby)
    if (overSpeed(ax, ay) || overSpeed(bx, by) || grows) {
      j = capImpulse(vax, vay, vbx, vby, nx, ny, ima, imb, approach, k / approach - 1, limit)
      F.vx[a] = vax - j * ima * nx
      F.vy[a] = vay - j * ima * ny
      F.vx[b] = vbx + j * imb * nx
      F.vy[b] = vby + j * imb * ny
      capBall(F, a)
      capBall(F, b)
    }
  }
  noteChange(F, a)
  noteChange(F, b)
  changedAt[a] = ++clock
  changedAt[b] = clock
  F.changed[a]! |= STRUCK
  F.changed[b]! |= STRUCK
  S[S_APPROACH] = approach
  S[S_J] = j
  reportPair(w, F, p, a, b)
  return true
}

/**
 * A closed wall reflects the normal velocity of a candidate near one that would reach it within the tick:
 * wallVelocity's answers over the candidates, or'ed (bit 1: a ball turned, bit 2: one turned between two walls).
 */
function wallVelocities(w: BallWorld, F: FixedContactState): number {
  let turned = 0
  for (let k = 0; k < F.nearWallCount; k++) turned |= wallVelocity(w, F, F.nearWall[k]!)
  return turned
}

/**
 * Candidate i's velocity reflected by the closed walls it would reach within the tick: 0 when it was not,
 * 2 when it reaches both walls of each axis it was turned on (the other wall would turn it back), else 1.
 */
function wallVelocity(w: BallWorld, F: FixedContactState, i: number): number {
  const into = intoWalls(F, i)
  if (into === 0) return 0
  const vx = F.vx[i]!
  const vy = F.vy[i]!
  // a ball wider than its box on an axis is wedged there (wedgedOn): turned back, it would meet the far face
  // at once, and every sweep would turn it again
  turnAtWalls(F, i, into, true)
  // its 'wall' event is written once the tick is solved, if it keeps the turn (src/contacts/fixedWallTurn.ts)
  if (Math.max(Math.abs(F.vx[i]! - vx), Math.abs(F.vy[i]! - vy)) >= S[S_SETTLE]!) F.changed[i]! |= WALL_DUE
  noteChange(F, i)
  changedAt[i] = ++clock
  F.changed[i]! |= VELOCITY | WALL_TURNED
  return bouncesBetween(F, i, into) ? 2 : 1
}
