// The fixed-tick method's pairs alone at their tick meet at their instant (config.BALL_COLLISIONS = 'fixed',
// CONTACT_TIMING 'instant', or 'auto' while the world has holes). A tick solves every contact at the tick, up to
// one tick before the two balls touch: the pair leaves from where the balls were at the tick, not from where
// they touch, and along a burst's paths that error (up to the approach speed times a tick) changes which hole a
// ball ends in. Where a pair is alone at its tick (each of its balls in no other contact of the tick, both
// moving (rolling, or on a rim: a ball struck there leaves it, as at a tick) or one rolling into one at rest,
// moved by no wall, no rest rule and no projection, the two touching within the tick on their own paths, neither
// path changed by an event of its own before that), the tick's impulse is dropped and the pair is given a Meet
// event on both paths at the instant the two touch on their paths (decelerations included). There the
// integration takes the two-body law with the velocities the balls have then, as the exact method does, at the
// restitution the tick's solve gave the pair (its rules can take some or all of it), and both balls start fresh
// paths from that instant (meetAt, src/contacts/fixedMeetAt.ts). A ball at rest has no events: it keeps its spot
// until the instant, where the rolling ball's Meet takes both, and it wakes there as at a tick, when it leaves
// at BALL_SETTLE_SPEED or more (a ball at rest moved or put elsewhere since is not struck). Nothing else can
// reach either ball before the instant: no event of its own that changes its path (a near miss, the exit from a
// locked hole or a skip-over before it are bookkeeping on the same path: the planner finds how far the path
// holds, src/motion/rolling.ts planTracked, and gives the meeting back as the next event after them; a ball
// reaching its meeting while its partner is still short of it, on such events of its own, waits for it in the
// next pass), the next tick is not before it, and no third ball within the tick. A ball may have been paired
// with others (within reach, in a burst most are), but each of those the solve left as it was, and on straight
// lines over the tick (the solve's swept test, by a margin for the paths' deceleration and a rim's turn) it
// touches none of them, neither on its way to the instant nor after it at the velocity the solve gave it
// (quiet): the third ball is then no nearer the pair than the tick's solve left it. The pair's collision event
// is given at the instant, not at the tick. Between the tick and the instant: walls or holes changed plan each
// path again from where it is, and the meeting stays its next event unless the new path has one of its own
// before it (keepMeet); a ball given a new path (a command's velocity, which also asks for a solve that pairs
// the balls again) gives up its meeting, and a ball whose partner gave it up goes on as it was: neither takes
// the impulse, and the next solve finds the pair again. So does a ball that a step out of passes holds back
// (src/motion/pause.ts).
import { BallMode } from '../../components/Ball.js'
import { PathEvent } from '../../components/Path.js'
import { EventType, moveEvent } from '../events.js'
import { changeAt, planRolling, planTracked } from '../motion/rolling.js'
import { planRimRoll } from '../motion/rimRoll.js'
import type { BallWorld } from '../world/createWorld.js'
import { instantOut, tickInstant } from '../world/gridTime.js'
import { grownTo, type FixedContactState } from '../world/fixedState.js'
import { HOT, H_NEXT_T } from '../world/pathHot.js'
import { meetNext } from '../world/meetState.js'
import { E, AT, VX, VY, X, Y, evalBall } from './evalMotion.js'
import { TOUCH_GAP } from '../config/tolerances.js'

/** Newton steps toward the instant of touch on the two paths, from the straight-line instant */
const TOUCH_STEPS = 8
/**
 * the gap at that instant within which the steps have found it: this share of the two radii, or, far from
 * the origin, this many times the positions' size (their rounding: a gap 1e9 px out is known to about 1e-7 px)
 */
const TOUCH_TOLERANCE = 1e-9
const ROUNDING = 1e-15

/**
 * each packed ball's pairs in the tick's last pair list, as a list through their entries (entry 2p: pair p's
 * first ball, 2p + 1: its second): a ball's first entry, −1 for none, and each entry's next (scratch)
 */
let first = new Int32Array(256)
let after = new Int32Array(512)
/** by ball id: the stamp of the tick that timed its pair (scratch for dropping the tick's collision events) */
let timedAt = new Uint32Array(256)
/** the stamp (a slot: a module-level number that may leave the small integers is boxed at every write) */
const STAMP = new Uint32Array(1)

/** scratch of a pair's state at the touch: a's position and velocity, b's, the instant (src/contacts/fixedMeetAt.ts uses it too) */
export const P0 = new Float64Array(11)
export const AXp = 0
export const AYp = 1
export const AVX = 2
export const AVY = 3
export const BXp = 4
export const BYp = 5
export const BVX = 6
export const BVY = 7
export const TT = 8
/** the next tick's instant: no pair is timed past it */
const UNTIL = 9
/** the restitution the tick's solve gave the pair */
const EFF = 10

/**
 * After a tick's solve, before its changes are applied: each pair alone at the tick is given a Meet event at
 * its instant instead of its impulse now (see above). `eventsFrom`: the events buffer's count when the tick
 * began (the tick's collision events of those pairs are dropped).
 */
export function timeMeets(w: BallWorld, F: FixedContactState, eventsFrom: number): void {
  const n = F.n
  const pairs = F.pairCount
  // CONTACT_TIMING 'auto': only where there are holes for the instants to decide between
  const timing = w.config.CONTACT_TIMING
  if (pairs === 0 || timing === 'tick' || (timing === 'auto' && w.holes.count === 0)) return
  if (first.length < n) first = grownTo(first, 2 * n)
  if (after.length < 2 * pairs) after = grownTo(after, 4 * pairs)
  first.fill(-1, 0, n)
  for (let p = 0; p < pairs; p++) {
    const a = F.pairA[p]!
    const b = F.pairB[p]!
    after[2 * p] = first[a]!
    first[a] = 2 * p
    after[2 * p + 1] = first[b]!
    first[b] = 2 * p + 1
  }
  tickInstant(w, F.halvings, F.nextTick)
  P0[UNTIL] = instantOut[0]!
  STAMP[0] = STAMP[0] === 0xffffffff ? 1 : STAMP[0]! + 1
  if (timedAt.length < w.capacity) timedAt = grownTo(timedAt, w.capacity)
  if (STAMP[0] === 1) timedAt.fill(0)
  let timed = 0
  for (let p = 0; p < pairs; p++) {
    const a = F.pairA[p]!
    const b = F.pairB[p]!
    if (!alone(w, F, a, b)) continue
    const ea = F.id[a]!
    const eb = F.id[b]!
    timedAt[ea] = STAMP[0]!
    timedAt[eb] = STAMP[0]!
    timed++
    // the tick's impulse dropped: the two keep their paths, up to the instant
    F.changed[a] = 0
    F.changed[b] = 0
    setMeet(w, ea, eb)
    setMeet(w, eb, ea)
  }
  if (timed === 0) return
  w.meet!.timed += timed
  dropTickCollisions(w, eventsFrom)
}

/**
 * Whether packed pair (a, b) is alone at the tick as above; if so the instant of touch and the balls' states
 * there are in P0.
 */
function alone(w: BallWorld, F: FixedContactState, a: number, b: number): boolean {
  // the solve changed their velocities only, by a pair's impulse (no wall's bit, no projection's)
  const ca = F.changed[a]!
  const cb = F.changed[b]!
  if ((ca & 1) === 0 || (cb & 1) === 0 || ((ca | cb) & ~(1 | 32)) !== 0) return false
  const B = w.Ball
  const ea = F.id[a]!
  const eb = F.id[b]!
  // both moving (rolling, or on a rim other than a tabulated ride's), or one rolling into one at rest (which
  // keeps its spot until the instant)
  const ma = B.mode[ea]
  const mb = B.mode[eb]
  const movingA = ma === BallMode.Rolling || (ma === BallMode.RimRoll && w.RimContact.ride[B.rim[ea]!] === 0)
  const movingB = mb === BallMode.Rolling || (mb === BallMode.RimRoll && w.RimContact.ride[B.rim[eb]!] === 0)
  if (!((movingA && movingB) || (ma === BallMode.Rolling && mb === BallMode.Resting) || (ma === BallMode.Resting && mb === BallMode.Rolling))) return false
  // momentum passed between the two alone (a ball at rest held like a wall takes none); the velocities
  // before the solve are the stores', the rest the tick's packed arrays
  const vax = B.vx[ea]!
  const vay = B.vy[ea]!
  const vbx = B.vx[eb]!
  const vby = B.vy[eb]!
  const ima = F.im[a]!
  const imb = F.im[b]!
  const dax = F.vx[a]! - vax
  const day = F.vy[a]! - vay
  const dbx = F.vx[b]! - vbx
  const dby = F.vy[b]! - vby
  // (absolute values written out: Math.abs, where V8 calls it as a function, boxes its argument)
  const px = dax * imb + dbx * ima
  const py = day * imb + dby * ima
  const scale = imb * ((dax < 0 ? -dax : dax) + (day < 0 ? -day : day))
  if (!(scale > 0) || (px < 0 ? -px : px) + (py < 0 ? -py : py) > 1e-9 * scale) return false
  // the straight-line touch (exact without rolling deceleration), else Newton's steps on the gap along the
  // two paths from there
  const S = F.r[a]! + F.r[b]!
  const xa = F.x[a]!
  const ya = F.y[a]!
  const dx = F.x[b]! - xa
  const dy = F.y[b]! - ya
  const ux = vbx - vax
  const uy = vby - vay
  const c = dx * dx + dy * dy - S * S
  const half = dx * ux + dy * uy
  if (!(c > 0) || !(half < 0)) return false
  const disc = half * half - (ux * ux + uy * uy) * c
  if (!(disc >= 0)) return false
  const now = w.time
  const until = P0[UNTIL]!
  const tau = c / (-half + Math.sqrt(disc))
  // the restitution the tick's solve gave the pair (its rules take some or all of it: a pair met past its
  // visits, a pumped light ball, the speed limit, a closing slower than BALL_SETTLE_SPEED), along the normal
  // at the straight-line touch, as the solve's: the meeting takes the same, so the balls leave as fast as the
  // tick's widening rounds paired them for (a light ball the solve sent on inelastically, met at its instant
  // at the full restitution, went through a ball it was not paired with)
  const mx = dx + ux * tau
  const my = dy + uy * tau
  const m = Math.sqrt(mx * mx + my * my)
  const nx = mx / m
  const ny = my / m
  const approach = -(ux * nx + uy * ny)
  const across = dax * ny - day * nx
  const along = dax * nx + day * ny
  if (!(approach > 0) || !(along < 0) || (across < 0 ? -across : across) > 1e-9 * -along) return false
  let e = ((dbx - dax) * nx + (dby - day) * ny) / approach - 1
  if (!(e > 0)) e = 0
  if (e > w.config.BALL_RESTITUTION) e = w.config.BALL_RESTITUTION
  P0[EFF] = e
  let t = now + tau
  let found = w.config.ROLLING_DECEL === 0
  const tol = TOUCH_TOLERANCE * S + ROUNDING * ((xa < 0 ? -xa : xa) + (ya < 0 ? -ya : ya))
  for (let k = 0; !found && k < TOUCH_STEPS && t > now && t <= until; k++) {
    P0[TT] = t
    statesAt(w, ea, eb)
    const gx = P0[BXp]! - P0[AXp]!
    const gy = P0[BYp]! - P0[AYp]!
    const dist = Math.sqrt(gx * gx + gy * gy)
    const gap = dist - S
    const rate = (gx * (P0[BVX]! - P0[AVX]!) + gy * (P0[BVY]! - P0[AVY]!)) / dist
    if (!(rate < 0)) return false
    if (gap <= tol && gap >= -tol) found = true
    else t -= gap / rate
  }
  if (!found || !(t > now && t <= until)) return false
  // each other pair of either ball untouched by the solve, and clear of the meeting within the tick (the
  // instant stays in P0[TT] for the caller)
  P0[TT] = t
  if (!(quiet(w, F, a, b) && quiet(w, F, b, a))) return false
  return clearTo(w, ea) && clearTo(w, eb)
}

/**
 * Whether ball e's path holds up to the instant P0[TT]: its own next event is later, or every event before
 * it is bookkeeping on the same path (a near miss, the exit from a locked hole, a skip-over: each plans the
 * path again, and the meeting is its next event again after them, src/motion/rolling.ts). A meeting of an
 * earlier tick's, for the same pair, is given up first (a command between the two asked for this solve).
 */
function clearTo(w: BallWorld, e: number): boolean {
  const t = P0[TT]!
  const mode = w.Ball.mode[e]
  if (w.meet!.with[e] !== 0) {
    w.meet!.with[e] = 0
    if (mode !== BallMode.Resting && w.Path.nextKind[e] === PathEvent.Meet) planAgain(w, e)
  }
  // (a ball at rest has no events of its own; a ball on a rim has its roll's end)
  if (mode === BallMode.Resting) return true
  if (w.pathHot[e * HOT + H_NEXT_T]! > t) return true
  if (mode !== BallMode.Rolling) return false
  planTracked(w, e)
  return changeAt[0]! > t
}

/**
 * Whether packed ball a, meeting b at the instant P0[TT], keeps clear of each other ball it was paired with
 * in the tick: that ball untouched by the solve, and the two not touching within the tick on straight lines,
 * a at its velocity before the tick up to the instant and at the one the solve gave it after (the solve's
 * swept test, written out: a double passed to a call V8 does not inline is boxed), by a margin for the
 * paths' deceleration over the tick, and for how far a ball on a rim turns from a straight line.
 */
function quiet(w: BallWorld, F: FixedContactState, a: number, b: number): boolean {
  // (its one pair: the pair's own)
  if (after[first[a]!] === -1) return true
  const ea = F.id[a]!
  const now = w.time
  const tau = P0[TT]! - now
  const span = P0[UNTIL]! - now
  const margin = w.config.ROLLING_DECEL * span * span + TOUCH_GAP + rimBend(w, ea, span)
  for (let k = first[a]!; k !== -1; k = after[k]!) {
    const c = (k & 1) === 0 ? F.pairB[k >> 1]! : F.pairA[k >> 1]!
    if (c === b) continue
    if (F.changed[c] !== 0 || timedAt[F.id[c]!] === STAMP[0]) return false
    const S = F.r[a]! + F.r[c]! + margin + rimBend(w, F.id[c]!, span)
    let dx = F.x[c]! - F.x[a]!
    let dy = F.y[c]! - F.y[a]!
    let ux = F.vx[c]! - w.Ball.vx[ea]!
    let uy = F.vy[c]! - w.Ball.vy[ea]!
    let length = tau
    for (let part = 0; part < 2; part++) {
      if (part === 1) {
        dx += ux * tau
        dy += uy * tau
        ux = F.vx[c]! - F.vx[a]!
        uy = F.vy[c]! - F.vy[a]!
        length = span - tau
      }
      const gap = dx * dx + dy * dy - S * S
      if (!(gap > 0)) return false
      const half = dx * ux + dy * uy
      if (half < 0) {
        const disc = half * half - (ux * ux + uy * uy) * gap
        if (disc >= 0 && gap / (-half + Math.sqrt(disc)) <= length) return false
      }
    }
  }
  return true
}

/**
 * Twice how far ball e, if on a rim, turns from its tangent over `span` seconds: v²·span² / R, R the radius
 * its centre turns on (the hole's less half the ball's, as src/motion/rimRoll.ts); 0 for any other ball.
 */
function rimBend(w: BallWorld, e: number, span: number): number {
  if (w.Ball.mode[e] !== BallMode.RimRoll) return 0
  const B = w.Ball
  const R = w.Hole.radius[w.RimContact.hole[B.rim[e]!]!]! - B.radius[e]! / 2
  const vx = B.vx[e]!
  const vy = B.vy[e]!
  return ((vx * vx + vy * vy) * span * span) / R
}

/** A ball's own next event again, from its path or its rim roll (a meeting given up). */
export function planAgain(w: BallWorld, e: number): void {
  if (w.Ball.mode[e] === BallMode.RimRoll) planRimRoll(w, e)
  else planRolling(w, e)
}

/** Both balls' states at time P0[TT] on their paths (rolling, on a rim or at rest), into P0: what the stores get there. */
export function statesAt(w: BallWorld, ea: number, eb: number): void {
  stateAt(w, ea, AXp)
  stateAt(w, eb, BXp)
}

/** Ball e's position and velocity at time P0[TT] (src/contacts/evalMotion.ts), into P0 from slot k on. */
function stateAt(w: BallWorld, e: number, k: number): void {
  E[AT] = P0[TT]!
  evalBall(w, e)
  P0[k] = E[X]!
  P0[k + 1] = E[Y]!
  P0[k + 2] = E[VX]!
  P0[k + 3] = E[VY]!
}

/**
 * Ball e's path meets ball other at P0's instant: its next event, or, with bookkeeping of its own before it,
 * the next event after those (planRolling sets it then).
 */
function setMeet(w: BallWorld, e: number, other: number): void {
  const M = w.meet!
  M.with[e] = other
  M.t[e] = P0[TT]!
  M.e[e] = P0[EFF]!
  if (w.Ball.mode[e] !== BallMode.Resting && w.pathHot[e * HOT + H_NEXT_T]! > M.t[e]!) meetNext(w, e)
}

/**
 * Ball b's path was planned again from where it is, at the same velocity (src/commands/replan.ts: the walls
 * or the holes changed), its meeting with `other` cleared by the new path: the meeting is its next event
 * again when the new path's own next event is later.
 */
export function keepMeet(w: BallWorld, b: number, other: number): void {
  const M = w.meet!
  if (!(w.pathHot[b * HOT + H_NEXT_T]! > M.t[b]!)) return
  M.with[b] = other
  meetNext(w, b)
}

/** Drops the collision events the tick gave the pairs it timed (each pair's event comes at its instant). */
function dropTickCollisions(w: BallWorld, from: number): void {
  const ev = w.events
  let out = from
  for (let i = from; i < ev.count; i++) {
    if (ev.type[i] === EventType.Collision && timedAt[ev.ball[i]!] === STAMP[0] && w.meet!.with[ev.ball[i]!] === ev.other[i]) continue
    if (out !== i) moveEvent(ev, out, i)
    out++
  }
  ev.count = out
}
