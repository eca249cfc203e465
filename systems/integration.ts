// Integration: moves every ball along its closed-form path to the end of the step, or to its next event
// if that comes first (docs/decisions.md §1).
//
// Covers no region by itself: it finds, exactly, the instants at which the other systems decide: the lip
// crossing (δ, v), the contact circle, the stop, the end of a rim roll. A ball stopped at such an event is
// marked for the decision systems; the schedule then runs another pass for the marked balls.
// Bookkeeping events are handled here and the ball goes on: leaving a hole's lip circle (the hole unlocks
// and the ball's RimContact slot is given back), the closest approach of a near miss (reported), and,
// without exact contacts, the end of a reference-decided ride round the lip or carry across (its outcome
// was decided at the crossing: src/motion/rimOutcome.ts).
//   rolling: s(τ) = v0·τ − a·τ²/2, v(τ) = v0 − a·τ        rim roll: see sampleRimRoll
// Reads Path, RimContact, Hole; writes Ball (x, y, vx, vy), Path (speed, s, mark), RimContact (angle, arc).
import { BallMode } from '../components/Ball.js'
import { PathEvent } from '../components/Path.js'
import { RIDE_DROPS } from '../components/RimContact.js'
import { EventType, appendEvent } from '../src/events.js'
import { pathOffset, planRolling, sampleAtDistance, sampleDistance, sampleTime } from '../src/motion/rolling.js'
import { capturesClean, fliesOver } from '../src/geometry.js'
import { sampleMovingAt, sampleRimRoll, sampleRimRollAt } from '../src/motion/rimRoll.js'
import { HeapKind, heapPop, heapPush, pushTime, heapTopA, heapTopB, heapTopKind, heapTopLive, heapTopT } from '../src/contacts/eventHeap.js'
import { beginWindow } from '../src/contacts/sweepGrid.js'
import { bumpVersion } from '../src/world/contactState.js'
import { predictBall, resumeSearch } from '../src/contacts/predict.js'
import { AT, E, MT, motionEnd, sampleForContact } from '../src/contacts/evalMotion.js'
import { FROM, search } from '../src/contacts/search.js'
import { pushId } from '../src/world/idLists.js'
import { HOT, H_NEXT_S, H_NEXT_T, H_UX, H_UY, H_X0, H_Y0 } from '../src/world/pathHot.js'
import { releaseRim } from '../src/world/rimSlots.js'
import { endRide, landCrossing } from '../src/motion/rimOutcome.js'
import { type BallWorld, type IdList } from '../src/world/createWorld.js'
import { MAX_INLINE_EVENTS } from '../src/config/tolerances.js'
import { outsideStep } from '../src/world/system.js'
import { meetAt } from '../src/contacts/fixedMeetAt.js'

export function integrationSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('integrationSystem', w)
  if (w.collide !== null) {
    orderedIntegration(w)
    return
  }
  const tEnd = w.tickEnd
  const mode = w.Ball.mode
  if (w.pass === 0) {
    w.marked.count = 0
    // from the end: a ball that stops or falls in is swapped out of the set behind the cursor. The path's
    // fields are read from its row in world.pathHot (src/world/pathHot.ts: one cache line a ball; the offsets are
    // written out as numbers, which V8 folds into the loads: x0, y0, ux, uy, v0, t0, nextT, nextS)
    const balls = w.moving.dense
    const B = w.Ball
    const { x, y, vx, vy } = B
    const H = w.pathHot
    const decel = w.config.ROLLING_DECEL
    let nd = 0
    if (decel === 0) {
      // without rolling deceleration a ball's velocity is its path's, ux·v0, written when the path began:
      // only the position moves (the same bits as the general form below: d = v0·τ, x = x0 + ux·d)
      for (let i = w.moving.count - 1; i >= 0; i--) {
        const eid = balls[i]!
        const h = eid << 3 // ids stay below 2^28: the rows would pass 2 GiB first
        if (H[h + 6]! > tEnd) {
          if (mode[eid] === BallMode.Rolling) {
            const d = H[h + 4]! * (tEnd - H[h + 5]!)
            x[eid] = H[h]! + H[h + 2]! * d
            y[eid] = H[h + 1]! + H[h + 3]! * d
          } else {
            sampleTime[0] = tEnd
            sampleRimRollAt(w, eid)
          }
          continue
        }
        if (nd === due.length) due = grown(due)
        due[nd++] = eid
      }
      advanceDue(w, nd, tEnd)
      return
    }
    for (let i = w.moving.count - 1; i >= 0; i--) {
      const eid = balls[i]!
      const h = eid << 3
      if (H[h + 6]! > tEnd) {
        if (mode[eid] === BallMode.Rolling) {
          // the common case, inlined: no event this step, evaluate the path at the step's end
          const v = H[h + 4]!
          let tau = tEnd - H[h + 5]!
          if (decel > 0 && tau * decel > v) tau = v / decel
          const d = v * tau - 0.5 * decel * tau * tau
          const vNow = v - decel * tau
          const dx = H[h + 2]!
          const dy = H[h + 3]!
          x[eid] = H[h]! + dx * d
          y[eid] = H[h + 1]! + dy * d
          vx[eid] = dx * vNow
          vy[eid] = dy * vNow
        } else {
          // the time in a slot (src/motion/rolling.ts): as an argument, a heap number a rim-rolling ball a step
          sampleTime[0] = tEnd
          sampleRimRollAt(w, eid)
        }
        continue
      }
      if (nd === due.length) due = grown(due)
      due[nd++] = eid
    }
    advanceDue(w, nd, tEnd)
  } else {
    // continue the balls the decision systems handled in the last pass
    const todo = takeMarked(w)
    advanceTo[0] = tEnd
    for (let i = 0, n = todo.count; i < n; i++) {
      const eid = todo.ids[i]!
      const m = mode[eid]
      if (m === BallMode.Rolling || m === BallMode.RimRoll) advanceThroughEvents(w, eid)
    }
  }
}

/**
 * With ball-ball contacts on: one event per pass (and the lip crossings keptOrTaken allows after it), in
 * global time order (src/contacts/eventHeap.ts). Predictions live
 * in a window that may outlast the step (C.until, config.PREDICTION_HORIZON ahead, or to the step's end): the first step past
 * a window's end starts another and predicts every moving ball; other passes predict again only the balls
 * the systems just moved and those whose paths changed since (pathChanged: commands, the launcher). Then
 * the earliest live event is taken: a ball's own event is advanced to exactly as without contacts
 * (bookkeeping handled inline, decisions marked); a contact samples both balls and marks them for the
 * collisions system. When no event is left before the step's end, every moving ball is sampled there; the
 * window's later events wait in the heap for the next steps.
 */
function orderedIntegration(w: BallWorld): void {
  const C = w.collide!
  const tEnd = w.tickEnd
  const P = w.Path
  if (w.pass === 0) {
    w.marked.count = 0
    if (tEnd > C.until) {
      // a window whose balls were predicted again more than CHURN times each on average (a pile, whose
      // paths change many times a step) gains nothing from its length and pays for longer capsules: the
      // next one ends with the step
      const churn = C.predictions - C.windowPredictions > CHURN * (C.windowBalls + 1)
      const ahead = C.now + (churn ? 0 : w.config.PREDICTION_HORIZON)
      beginWindow(w, ahead > tEnd ? ahead : tEnd)
      C.windowPredictions = C.predictions
      C.windowBalls = w.moving.count
      const balls = w.moving.dense
      for (let i = 0, n = w.moving.count; i < n; i++) predictBall(w, balls[i]!)
    }
  } else {
    const todo = takeMarked(w)
    for (let i = 0, n = todo.count; i < n; i++) predictAfterEvent(w, todo.ids[i]!)
  }
  if (C.dirtyCount > 0) predictChanged(w)
  const held = w.marked
  // the end of what is known of the balls whose crossings this pass holds: the span of each one's last
  // prediction (its path kept through the crossing); its events after the crossing are not in the heap
  heldSpan[0] = 1 / 0
  while (C.heapCount > 0) {
    const t = heapTopT(C)
    if (t > tEnd) break
    const live = heapTopLive(C)
    const kind = heapTopKind(C)
    const a = heapTopA(C)
    const b = heapTopB(C)
    // an event of a ball whose lip crossing this pass has yet to decide waits for the decision, and so does
    // every event from the end of a held ball's span on (its path may change there, a wall say, and meet a
    // ball sooner than the events after it: taking those first let the two pass through each other)
    if (held.count > 0 && live && (t >= heldSpan[0]! || P.mark[a] !== PathEvent.None || (b !== 0 && P.mark[b] !== PathEvent.None))) return
    heapPop(C)
    if (!live) continue
    if (t > C.now) C.now = t
    if (kind === HeapKind.Own) {
      advanceTo[0] = t
      advanceThroughEvents(w, a)
      if (P.mark[a] !== PathEvent.None) {
        // a lip crossing the default stages will skip over or capture clean: the decision keeps the path or
        // takes the ball out, and can change nothing another ball meets; the pass takes later events too
        const fate = lipBatching ? keptOrTaken(w, a) : Fate.Decided
        if (fate === Fate.Taken) continue
        if (fate === Fate.Kept) {
          // its contacts are in the heap up to its span's end only if that prediction was of this path
          const known = C.predGen[a] === C.gen[a] ? C.spanEnd[a]! : t
          if (known < heldSpan[0]!) heldSpan[0] = known
          continue
        }
        return
      }
      // bookkeeping only (a lip exit, a near miss)
      predictAfterEvent(w, a)
    } else if (kind === HeapKind.Resume) {
      search[FROM] = t
      resumeSearch(w, a, b)
    } else {
      markContact(w, a, b)
      markContact(w, b, a)
      return
    }
  }
  // the crossings taken in this pass are decided first
  if (held.count > 0) return
  // nothing left before the step's end
  const balls = w.moving.dense
  // the time in a slot (src/motion/rolling.ts): where V8 did not inline sampleRolling here, its time argument
  // was boxed for every moving ball, about 20 bytes a ball-step in a pile pressed by a stream
  sampleTime[0] = tEnd
  for (let i = 0, n = w.moving.count; i < n; i++) sampleMovingAt(w, balls[i]!)
  C.now = tEnd
}

/** orderedIntegration's bound on the events a pass takes past held crossings, s (a slot: not a boxed double) */
const heldSpan = new Float64Array(1)

/**
 * Set by the schedule runner for a window whose systems are the default schedule's and whose rim model is
 * the design's: only then does a lip crossing's decision follow from keptOrTaken's rules.
 */
let lipBatching = false

export function setLipBatching(on: boolean): void {
  lipBatching = on
}

/** What the default stages will do with a marked lip crossing, as far as the pass needs to know. */
const Fate = {
  /** by the stages in their pass (the pass ends at the crossing) */
  Decided: 0,
  /** skipped over: the path is kept through the crossing */
  Kept: 1,
  /** captured clean at the crossing: the ball meets nothing after it */
  Taken: 2,
} as const

/**
 * Whether ball a's marked lip crossing is one the default stages skip over (systems/skipOver.ts: Kept) or
 * capture clean (systems/capture.ts: Taken), from the same quantities those systems decide with; not a hero
 * ball's (Decided).
 */
function keptOrTaken(w: BallWorld, a: number): number {
  if (w.Path.mark[a] !== PathEvent.Lip || w.Ball.hero[a] === 1) return Fate.Decided
  const hole = w.Path.markHole[a]!
  const delta = Math.abs(pathOffset(w, a, hole))
  const v = w.Path.speed[a]!
  const R = w.Hole.radius[hole]!
  const cfg = w.config
  if (fliesOver(v, delta, R, w.Ball.radius[a]!, cfg.GRAVITY)) return Fate.Kept
  return capturesClean(delta, v, R, cfg.V_MAX, cfg.CAPTURE_WINDOW) ? Fate.Taken : Fate.Decided
}

/** the balls with an event in the step, listed by the pass over the moving balls (in its order) */
let due: Uint32Array = new Uint32Array(256)
const sink = { v: 0 }

function grown(a: Uint32Array): Uint32Array {
  const next = new Uint32Array(a.length * 2)
  next.set(a)
  return next
}

/**
 * Advances the listed balls through their events, in the pass's order. Their rows of the Path and Ball
 * arrays the events read are loaded first, all at once: the loads of one ball do not wait for another's, so
 * their cache misses overlap (with 100,000 balls each row is a miss), where the event code met them one by
 * one.
 */
function advanceDue(w: BallWorld, n: number, tEnd: number): void {
  const P = w.Path
  const B = w.Ball
  const { nextKind, nextHole, s, sHole, speed, fromHole, nextEdge, mark } = P
  const { radius, rim } = B
  let acc = 0
  for (let k = 0; k < n; k++) {
    const e = due[k]!
    acc += nextKind[e]! + nextHole[e]! + s[e]! + sHole[e]! + speed[e]! + fromHole[e]! + nextEdge[e]! + mark[e]! + radius[e]! + rim[e]!
  }
  sink.v = acc
  advanceTo[0] = tEnd
  for (let k = 0; k < n; k++) advanceThroughEvents(w, due[k]!)
}

/**
 * After ball a's own event (its entry in the heap taken): predicts it again, unless the event kept its
 * path (a near miss, a lip exit, a skip-over: the same closed form since its last prediction) and that
 * prediction already covers the path up to where it may change next. Then only its next event goes into
 * the heap: its contacts found then still hold, and nothing new can be found before that span's end.
 */
function predictAfterEvent(w: BallWorld, a: number): void {
  const C = w.collide!
  if (w.Ball.mode[a] === BallMode.Rolling && C.predGen[a] === C.gen[a] && C.predicted[a] === C.stamp && spanKept(w, a)) {
    C.isDirty[a] = 0
    const own = w.pathHot[a * HOT + H_NEXT_T]!
    if (own <= C.until) {
      pushTime[0] = own
      heapPush(C, HeapKind.Own, a, 0)
    }
    return
  }
  bumpVersion(w, a)
  predictBall(w, a)
}

/** Whether the span of a's last prediction still reaches as far as its motion is known. */
function spanKept(w: BallWorld, a: number): boolean {
  motionEnd(w, a)
  return E[MT] <= w.collide!.spanEnd[a]!
}

/** Predictions per moving ball in a window above which the next window ends with its step. */
const CHURN = 4

/** Predicts again the balls whose paths changed since they were last predicted (their old entries go stale). */
function predictChanged(w: BallWorld): void {
  const C = w.collide!
  for (let i = 0; i < C.dirtyCount; i++) {
    const eid = C.dirty[i]!
    if (C.isDirty[eid] === 0) continue
    bumpVersion(w, eid)
    predictBall(w, eid)
  }
  C.dirtyCount = 0
}

/** The balls marked in the last pass, handed over for this one; `marked` starts empty. */
function takeMarked(w: BallWorld): IdList {
  const todo = w.marked
  w.marked = w.todo
  w.todo = todo
  w.marked.count = 0
  return todo
}

/** Ball eid meets `other` now (C.now): its state there, marked for the collisions system. */
function markContact(w: BallWorld, eid: number, other: number): void {
  const P = w.Path
  const t = w.collide!.now
  E[AT] = t
  sampleForContact(w, eid)
  P.mark[eid] = PathEvent.Collide
  P.markOther[eid] = other
  w.pathHot[eid * HOT + H_NEXT_T] = t
  pushId(w.marked, eid)
}

/** the time advanceThroughEvents goes to, written by its callers (a double passed as an argument is boxed wherever V8 does not inline the call); nothing it calls writes it */
const advanceTo = new Float64Array(1)

function advanceThroughEvents(w: BallWorld, eid: number): void {
  const tEnd = advanceTo[0]!
  const P = w.Path
  const H = w.pathHot
  for (let guard = 0; guard < MAX_INLINE_EVENTS; guard++) {
    const t = H[eid * HOT + H_NEXT_T]!
    if (t > tEnd) {
      sampleTime[0] = tEnd
      sampleMovingAt(w, eid)
      return
    }
    const kind = P.nextKind[eid]!
    if (kind === PathEvent.Meet) {
      // a pair alone at a fixed contact tick meets here (src/contacts/fixedMeetAt.ts), or this ball waits for
      // its partner in the next pass
      if (meetAt(w, eid)) {
        pushId(w.marked, eid)
        return
      }
      continue
    }
    const hole = P.nextHole[eid]!
    if (kind === PathEvent.RollEnd) {
      // (a tabulated ride that drops in is not sampled at its end: the capture puts the ball at the hole's
      // centre, at rest, and gives its RimContact row back before anything reads them)
      if (w.RimContact.ride[w.Ball.rim[eid]!] !== RIDE_DROPS) sampleRimRoll(w, eid, t)
    } else {
      const s = H[eid * HOT + H_NEXT_S]!
      sampleDistance[0] = s
      sampleAtDistance(w, eid)
      P.s[eid] = s
      P.sHole[eid] = hole
    }
    if (kind === PathEvent.Exit) {
      releaseRim(w, eid)
      planRolling(w, eid)
      continue
    }
    if (w.collide === null && (kind === PathEvent.Landing || (kind === PathEvent.RollEnd && w.RimContact.ride[w.Ball.rim[eid]!] !== 0))) {
      // the end of a reference-decided ride round the lip or carry across: what happens there was decided
      // at the crossing (src/motion/rimOutcome.ts), so it is bookkeeping too, and the ball goes on in this
      // pass (or is captured). With exact contacts it is marked instead, so that the contact predictions
      // follow the new path: systems/tabulatedRim.ts ends it then.
      P.markHole[eid] = hole
      if (kind === PathEvent.Landing) landCrossing(w, eid)
      else {
        endRide(w, eid)
        if (w.Ball.mode[eid] !== BallMode.Rolling) return
      }
      continue
    }
    if (kind === PathEvent.Near) {
      const h = eid * HOT
      const c = (w.Hole.x[hole]! - H[h + H_X0]!) * H[h + H_UY]! - (w.Hole.y[hole]! - H[h + H_Y0]!) * H[h + H_UX]!
      const k = appendEvent(w.events, EventType.NearMiss, eid, hole, true)
      w.events.time[k] = t
      w.events.delta[k] = Math.abs(c)
      w.events.speed[k] = P.speed[eid]!
      planRolling(w, eid)
      continue
    }
    if (P.mark[eid] !== PathEvent.None) {
      throw new Error(
        `ball ${eid}: its event (kind ${P.mark[eid]}) was not handled by any system in the schedule; ` +
          'keep skipOver, capture, cogGate, bounce, rimRoll, walls and collisions in it',
      )
    }
    P.mark[eid] = kind
    P.markHole[eid] = hole
    P.markEdge[eid] = P.nextEdge[eid]!
    pushId(w.marked, eid)
    return
  }
  // unreachable with finite holes; leave the ball where it is and go on next pass
  pushId(w.marked, eid)
}
