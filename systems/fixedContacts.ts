// Ball-ball contacts by the fixed-tick method (not a design stage; opt-in with config.BALL_COLLISIONS =
// 'fixed'). Contacts are solved at the times k·CONTACT_TICK of the world's clock, whatever the frame rate
// (the tick halved where the balls cover many of their spacings a tick: src/contacts/fixedHalve.ts):
// the step is split at those times, and at the first pass after each one this system pairs the balls that
// can touch within a tick (where the balls crowd, src/contacts/fixedDense.ts; where they are spread out, the
// sweep of src/contacts/fixedGrid.ts, fixedSweep.ts and fixedOrder.ts: the same pairs in the same order),
// solves their velocities (src/contacts/fixedSolve.ts)
// and separates overlaps (src/contacts/fixedProject.ts), pairing again the balls the solve sped up
// (src/contacts/fixedReach.ts; a tick whose rounds stop at their pair bounds with a ball that could still pass
// another, or that ends with a pair closing deep into itself that a finer tick would not, is solved again,
// halved: fixedRedo.ts, fixedDeep.ts) and those the projection pushed into balls they were not
// paired with (fixedJoin.ts); a tick whose projection took a row out from one of its balls
// (fixedLayered.ts) has its velocities solved again; each ball's contacts are counted on the clock, a light
// ball past MAX_TICK_CONTACTS in a contact tick of it meeting heavy ones without restitution (fixedCount.ts).
// With config.CONTACT_WORK_BUDGET set, each CONTACT_TICK span's work is metered, and past its budget the
// span's remaining ticks are solved lean: one try, a short velocity call, no widening rounds, a short
// projection; past as much again, they are skipped until the next span (fixedBudget.ts).
// Between ticks the balls follow their closed-form paths through the holes
// and walls exactly, as in every other mode. Cheaper than the exact method in dense scenes, at a cost in
// timing: a contact acts at the tick, up to one tick early (docs/decisions.md §12).
// Reads Ball, the walls, the fixed state; writes Ball, Path, RimContact; emits 'collision' and 'wall'.
import { gatherCandidates, wallsPending } from '../src/contacts/fixedGrid.js'
import { findPairs } from '../src/contacts/fixedOrder.js'
import { findPairsDense, gatherDense } from '../src/contacts/fixedDense.js'
import { lastSolveConverged, solveVelocities } from '../src/contacts/fixedSolve.js'
import { applyChanges } from '../src/contacts/fixedApply.js'
import { timeMeets } from '../src/contacts/fixedMeet.js'
import { countTickContacts } from '../src/contacts/fixedCount.js'
import { deepFiner } from '../src/contacts/fixedDeep.js'
import { solvePositions } from '../src/contacts/fixedProject.js'
import { anchoredCount } from '../src/contacts/fixedLayered.js'
import { joinPushed, markCandidatesSeen } from '../src/contacts/fixedJoin.js'
import { widenReach } from '../src/contacts/fixedReach.js'
import { coarsenTick, fewPairs, halveTick, recordGrowth } from '../src/contacts/fixedHalve.js'
import { beginTry, finerForRestitution, redoHalvings, restoreTick, saveTick } from '../src/contacts/fixedRedo.js'
import { beginWidening, withinCapsule } from '../src/contacts/fixedCapsule.js'
import { roundCandidates, roundList } from '../src/contacts/fixedRounds.js'
import { beginNear } from '../src/contacts/fixedNear.js'
import { lastCallChanges } from '../src/contacts/fixedCalls.js'
import { iterationsNow, lean, meterPairs, meterTick, skipRest, spend } from '../src/contacts/fixedBudget.js'
import { CHAIN_PAIRS_PER_BALL, CHAIN_ROUNDS_PER_CANDIDATE, DEEP_FRONTS, DEEP_ROW_FRONTS, MAX_CHAIN_ROUNDS, MAX_PASS_ROUNDS, MAX_WIDEN_ROUNDS, PASS_PAIRS_PER_BALL, PASS_PAIRS_PER_WIDENED, PROJECTION_SLOP, SMALL_TICK_BALLS } from '../src/config/tolerances.js'
import type { BallWorld } from '../src/world/createWorld.js'
import type { FixedContactState } from '../src/world/fixedState.js'
import { outsideStep } from '../src/world/system.js'
import { keepWallTurns } from '../src/contacts/fixedWallTurn.js'
import { guardPasses } from '../src/contacts/fixedGuard.js'
import { activeCount, activeLeastRadius, beginActive } from '../src/contacts/fixedActive.js'

export function fixedContactsSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('fixedContactsSystem', w)
  const F = w.fixed
  if (F === null || !F.due || w.pass !== 0) return
  F.due = false
  if (F.broadphase >= 0) F.denseNext = F.broadphase
  if (F.dense !== F.denseNext) {
    F.dense = F.denseNext
    // back to the sweep: its order is rebuilt
    if (F.dense === 0) F.sweepNext = F.sweepCell
  }
  coarsenTick(w, F)
  meterTick(w, F)
  // past its budget and as much again on lean ticks, the span's last ticks are skipped (src/contacts/fixedBudget.ts)
  if (skipRest(F)) return
  F.ticks++
  const eventsFrom = w.events.count
  // a try that stopped with a ball that may pass through another is dropped, and the tick solved again at a
  // finer spacing (src/contacts/fixedRedo.ts)
  saveTick(w, F)
  let tries = 0
  let atLeast = 0
  for (;;) {
    beginTry()
    const h = solveTick(w, F, atLeast)
    if (h === NO_PAIRS) {
      recordGrowth(F, false)
      return
    }
    // a try that leaves a pair closing deep into itself (or a ball moving into a wall) that a finer
    // spacing would not (src/contacts/fixedDeep.ts): solved again too, on a tick of few pairs a candidate;
    // on a tick of more, when it leaves at most DEEP_FRONTS of them (a push's front along a row, not a
    // crowd's many) and it had few pairs a candidate before its widening rounds (as a tick the spacing
    // coarsens back from: a crowd whose pairs are its radii would keep the finer spacing); DEEP_ROW_FRONTS of
    // them when it had at most one pair a candidate before those rounds (a push along a row at a fine tick
    // leaves three fronts: a crowd's tick that leaves as many has about four pairs a candidate)
    if (h === SOLVED) {
      // (more than CHAIN_PAIRS_PER_BALL · SMALL_TICK_BALLS pairs first: implied by the rest, and most ticks
      // then need no count of their balls, src/contacts/fixedActive.ts)
      const few = F.pairCount <= CHAIN_PAIRS_PER_BALL * SMALL_TICK_BALLS
      const taking = few ? 0 : activeCount(F)
      const dense = !few && taking > SMALL_TICK_BALLS && F.pairCount > CHAIN_PAIRS_PER_BALL * taking
      if (dense && !fewPairs(F)) break
      const fronts = F.tickPairs > 0 && F.tickPairs <= F.tickFull ? DEEP_ROW_FRONTS : DEEP_FRONTS
      // and a small tick of like masses that closed a pair apart at its start past its restitution visits
      // (src/contacts/fixedRedo.ts, finerForRestitution)
      if (!deepFiner(w, F, dense ? fronts : -1) && !finerForRestitution(F, tries)) break
    }
    // past the span's work budget, no finer try (src/contacts/fixedBudget.ts)
    if (lean(F)) break
    atLeast = redoHalvings(++tries, h === SOLVED ? tryHalvings : h)
    if (atLeast === 0) break
    restoreTick(w, F)
  }
  const capped = F.capped
  const anchored = anchoredCount()
  solvePositions(w, F)
  // a ball the projection pushed into a ball the tick did not pair it with: paired, projected again; past
  // MAX_WIDEN_ROUNDS only along a row (a push running along balls at rest that the tick did not gather, a
  // ball a round): while each round pairs one ball more and the tick has CHAIN_PAIRS_PER_BALL pairs a
  // candidate or fewer, up to MAX_PASS_ROUNDS. A lean tick takes the first MAX_WIDEN_ROUNDS only (each with a
  // lean projection): without them it left a ball the projection pushed 7 px, out of one ball into another
  // it had not paired, 1.4 px deep in it (src/contacts/fixedBudget.ts). Rounds that stop at a bound leave
  // what the last projection pushed into balls it has not paired until the next tick: the search pairs
  // them, and the tick counts as capped (a push through balls at rest, two balls joined in its fourth
  // round, left a ball 0.0032 px into another at rest, the tick not counted; tests/adversarial.test.ts)
  for (let round = 0; F.overlap && F.capped === capped; round++) {
    const pairs = F.pairCount
    if (!joinPushed(w, F)) break
    solvePositions(w, F)
    if (round + 1 < MAX_WIDEN_ROUNDS) continue
    // the rounds' bounds (a lean tick's at MAX_WIDEN_ROUNDS): a ball the last projection pushed into one the
    // tick has not paired stays in it until the next tick, and the tick counts as capped, as when the
    // projection's budget runs out (the search pairs what it finds; nothing solves those pairs in this tick)
    if (lean(F) || F.pairCount - pairs > 1 || F.pairCount > CHAIN_PAIRS_PER_BALL * activeCount(F) || round + 1 >= MAX_PASS_ROUNDS) {
      if (joinPushed(w, F)) F.capped++
      break
    }
  }
  // a row the projection took out from one of its balls (src/contacts/fixedLayered.ts) can have had a
  // push carried along it by more than the gaps between its balls: a ball moved up to one closing on it,
  // which the velocities solved at the old positions let through it within the tick; they are solved again
  // where the balls now are (without it, 4 of the 768 struck rows of npm run bench:rows let a ball pass).
  // That solve carries the push further than the rounds widened: a ball it leaves able to pass another is
  // widened and solved again, round by round, as in the tick (a mass-100 ball at 3,000 px/s into 200
  // radius-3 balls 1 px apart, e = 0: the front ball went from 640 to 946 px/s, through its neighbour at
  // rest, which was not a candidate)
  if (anchoredCount() !== anchored) {
    solveVelocities(w, F, iterationsNow(w, F))
    if (!lean(F) && mayPass(F)) {
      markCandidatesSeen(F)
      for (let round = 0; round < MAX_PASS_ROUNDS && F.pairCount <= PASS_PAIRS_PER_BALL * activeCount(F) && !lean(F) && mayPass(F); round++) {
        if (!widenReach(w, F)) break
        solveVelocities(w, F, iterationsNow(w, F))
      }
    }
  }
  if (lean(F)) F.lean++
  recordGrowth(F, true)
  // a candidate only a wall turned goes on to meet the wall at its instant (src/contacts/fixedWallTurn.ts)
  keepWallTurns(w, F)
  // a pair still closing deep, or a ball a wall would turn into a partner it then closes deep on: the last
  // guard (src/contacts/fixedGuard.ts); every pair where the last velocity sweeps did not converge or the
  // projection ran
  guardPasses(w, F, !lastSolveConverged() || F.overlap)
  countTickContacts(w, F)
  // a pair alone at the tick meets at its instant instead (src/contacts/fixedMeet.ts)
  timeMeets(w, F, eventsFrom)
  applyChanges(w, F)
}

/** the halvings the last try took (halveTick): the next try takes more */
let tryHalvings = 0

/** solveTick's answers besides the halvings of a try that stopped with a ball that may pass */
const NO_PAIRS = -2
const SOLVED = -1

/**
 * One try at the tick: gathers and pairs the candidates, halves the tick (at least `atLeast` times), solves
 * the velocities and widens the reach of the balls the solve sped up, round after round. Returns NO_PAIRS
 * when there is nothing to solve; the halvings this try took when the rounds stopped at a bound on their
 * pairs with a ball that could still pass through another (the tick is solved again); else SOLVED (the
 * rounds ended, or stopped at a bound on their number, which solving again along a row only makes dearer).
 */
function solveTick(w: BallWorld, F: FixedContactState, atLeast: number): number {
  if (F.dense === 1) gatherDense(w, F)
  else gatherCandidates(w, F)
  if (F.full < 2) {
    F.tickPairs = 0
    return NO_PAIRS
  }
  if (F.dense === 1) findPairsDense(F)
  else findPairs(w, F)
  beginActive(F)
  const h = halveTick(w, F, atLeast)
  meterPairs(w, F)
  spend(F, F.full + F.pairCount)
  tryHalvings = h
  chooseBroadphase(F)
  if (F.pairCount === 0) return NO_PAIRS
  const iterations = iterationsNow(w, F)
  F.hitCount = 0
  F.overlap = false
  let converged = solveVelocities(w, F, iterations)
  beginWidening()
  beginNear(F)
  // a push runs one ball further along a row with gaps each round; past MAX_WIDEN_ROUNDS only while a ball
  // could pass through another within the tick and the pairs keep within PASS_PAIRS_PER_BALL a candidate
  // (src/config/tolerances.ts), and past MAX_PASS_ROUNDS only while the tick has CHAIN_PAIRS_PER_BALL pairs a
  // candidate or fewer (a push along a row; past it with a ball that may still pass another, the tick is
  // solved again finer, as at the pair bounds), and past MAX_CHAIN_ROUNDS only while each call keeps its stamps (a
  // round then costs the balls it changes), up to CHAIN_ROUNDS_PER_CANDIDATE rounds a candidate; those rounds
  // start from the new pairs when the last round converged
  let added = 0
  let widened = 1
  let wallAgain = false
  for (let round = 0; ; round++) {
    // past the span's work budget: no more rounds (src/contacts/fixedBudget.ts)
    if (lean(F)) return SOLVED
    if (round >= MAX_CHAIN_ROUNDS && (lastCallChanges() < 0 || round >= CHAIN_ROUNDS_PER_CANDIDATE * activeCount(F))) return SOLVED
    const extra = round >= MAX_WIDEN_ROUNDS
    if (extra) {
      if (!mayPass(F) && !(added > 0 && F.pairCount <= CHAIN_PAIRS_PER_BALL * activeCount(F))) return SOLVED
      if (F.pairCount > PASS_PAIRS_PER_BALL * activeCount(F) || added > PASS_PAIRS_PER_WIDENED * widened) return h
    }
    if (round >= MAX_PASS_ROUNDS && F.pairCount > CHAIN_PAIRS_PER_BALL * activeCount(F)) return mayPass(F) ? h : SOLVED
    const pairs = F.pairCount
    const walled = F.nearWallCount
    if (!widenReach(w, F)) return SOLVED
    // a round that found no new pair but widened a ball into a closed wall it is moving into solves again,
    // once a tick, in a tick along rows: the wall sends it back at the tick (else it turns between ticks,
    // back through the balls behind it; a ball the wall cannot send back, one wider than its box, kept the
    // rounds going to their bound)
    if (extra && F.pairCount === pairs) {
      if (wallAgain || F.pairCount > CHAIN_PAIRS_PER_BALL * activeCount(F) || !wallsPending(F, walled)) return SOLVED
      wallAgain = true
    }
    added = F.pairCount - pairs
    widened = F.widenedCount > 0 ? F.widenedCount : 1
    converged = solveVelocities(w, F, iterations, extra && converged ? pairs : 0, pairs)
  }
}

/**
 * The broadphase for the next tick (both give the same pairs in the same order): the dense one where the
 * balls crowd, the sweep where they are spread out. Crowding is measured two ways: the balls per square of
 * side twice the largest reach over the candidates' bounding box (a gas at area fraction 0.2 has about
 * 0.5, a burst spread over the panel's tiles less than 0.15), and the pairs per candidate (a pile at rest
 * has several). The sweep's order is rebuilt after dense ticks.
 */
function chooseBroadphase(F: FixedContactState): void {
  if (F.broadphase >= 0) {
    F.denseNext = F.broadphase
    return
  }
  const area = (F.maxX - F.minX) * (F.maxY - F.minY)
  // Infinity written 1 / 0 (the global, in a branch V8 has not seen taken, is a generic load that boxes)
  const crowd = area > 0 ? (F.full * F.cell * F.cell) / area : 1 / 0
  const share = F.pairCount / F.full
  if (F.dense === 1 && crowd < 0.25 && share < 0.25) F.denseNext = 0
  else if (F.dense === 0 && (crowd > 0.3 || share > 0.3)) F.denseNext = 1
}

/**
 * Whether a ball the solve sped up beyond its reach (one the next widening round would pair again) moves
 * more in a tick than its radius and the smallest candidate's: the distance at which, unpaired, it could
 * pass through a ball instead of ending inside it.
 */
function mayPass(F: FixedContactState): boolean {
  // the smallest radius of the balls taking part (src/contacts/fixedActive.ts)
  const rMin = activeLeastRadius(F)
  // a candidate neither the last solve nor the last cut touched was looked at by the last round's widening
  // (src/contacts/fixedRounds.ts), and gives no to this
  const listed = roundCandidates(F, false)
  const list = listed < 0 ? F.hit : roundList()
  const count = listed < 0 ? F.hitCount : listed
  for (let h = 0; h < count; h++) {
    const i = list[h]!
    const vx = F.vx[i]!
    const vy = F.vy[i]!
    const travel = Math.sqrt(vx * vx + vy * vy) * F.tick
    if (travel > F.r[i]! + rMin && F.r[i]! + travel > F.reach[i]! + PROJECTION_SLOP && !withinCapsule(F, i)) return true
  }
  return false
}
