// The contact search: the first time two balls touch while approaching, by conservative advancement on
// their closed-form motions (no step can pass a contact, at any dt). Infinity is written 1 / 0 (as in
// src/geometry.ts: a cold global `Infinity` boxes the loop's doubles).
import { APPROACH_EPSILON, GAP_TOLERANCE, MAX_SEARCH_STEPS, MIN_ADVANCE, SETTLE_FLOOR, SINK_DEPTH } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import { BallMode } from '../../components/Ball.js'
import { HOT, H_T0, H_UX, H_UY, H_V0, H_X0, H_Y0 } from '../world/pathHot.js'
import { ACC, AT, AX, AY, E, EXACT, MT, NEXT, VX, VY, X, Y, evalBall, motionEnd, motionStart } from './evalMotion.js'

export const SearchResult = { None: 0, Contact: 1, Resume: 2 } as const
/**
 * The search's input, the first ball's span [FROM, TO] (s; the search takes its intersection with the second
 * ball's), and its result: RESULT (a SearchResult) and its TIME (s). A typed array: no allocation per write,
 * and no double passed as an argument (V8 boxes those for a function it does not inline, and a loop that
 * starts from a boxed one may box every step). PAIR_FROM, PAIR_TO: the pair's span, for searchStraight.
 */
export const search = new Float64Array(6)
export const RESULT = 0
export const TIME = 1
export const FROM = 2
export const TO = 3
const PAIR_FROM = 4
const PAIR_TO = 5

/**
 * MIN_ADVANCE as a double the optimiser can see. A module constant is a variable of the bundle to V8, of no
 * known type: merged into a loop's double (h in the searches) it made V8 box that double at every step of
 * every search (most of the exact method's allocation)
 */
const MIN_STEP = new Float64Array([MIN_ADVANCE])
/** SINK_DEPTH likewise */
const DEPTH = new Float64Array([SINK_DEPTH])

/**
 * First contact of balls a and b in [search[FROM], search[TO]] and b's own span (motionStart, motionEnd), on their
 * current motions: the earliest time at which their
 * gap is at most GAP_TOLERANCE while they approach. Sets search[RESULT]/search[TIME]: Contact at that time, None
 * if there is none before the span's end, or Resume with the time reached after MAX_SEARCH_STEPS (the search continues
 * from there when that time comes up in the heap).
 */
export function searchContact(w: BallWorld, a: number, b: number): void {
  search[RESULT] = SearchResult.None
  motionStart(w, b)
  const startB = E[MT]!
  motionEnd(w, b)
  const endB = E[MT]!
  const from = search[FROM]! > startB ? search[FROM]! : startB
  const to = search[TO]! < endB ? search[TO]! : endB
  const minAdvance = MIN_STEP[0]!
  if (!(from <= to)) return
  const mode = w.Ball.mode
  if (mode[a] !== BallMode.RimRoll && mode[b] !== BallMode.RimRoll) {
    search[PAIR_FROM] = from
    search[PAIR_TO] = to
    searchStraight(w, a, b)
    return
  }
  const S = w.Ball.radius[a]! + w.Ball.radius[b]!
  const floor = SETTLE_FLOOR * w.config.BALL_SETTLE_SPEED
  const deep = -DEPTH[0]!
  let t = from
  for (let iter = 0; iter < MAX_SEARCH_STEPS; iter++) {
    E[AT] = t
    evalBall(w, a)
    const xa = E[X]
    const ya = E[Y]
    const vxa = E[VX]
    const vya = E[VY]
    const axa = E[AX]
    const aya = E[AY]
    const acca = E[ACC]
    const exa = E[EXACT]
    const na = E[NEXT]
    E[AT] = t
    evalBall(w, b)
    const dx = E[X] - xa
    const dy = E[Y] - ya
    const dvx = E[VX] - vxa
    const dvy = E[VY] - vya
    const dist = Math.sqrt(dx * dx + dy * dy)
    const g = dist - S
    // rate of change of the gap (negative: approaching); coincident centres count as approaching
    const vrel = Math.sqrt(dvx * dvx + dvy * dvy)
    const vn = dist > 0 ? (dx * dvx + dy * dvy) / dist : -vrel
    if (g <= GAP_TOLERANCE ? vn < -(floor + APPROACH_EPSILON * (1 + vrel)) || (g <= deep && vn < -APPROACH_EPSILON * (1 + vrel)) : false) {
      search[RESULT] = SearchResult.Contact
      search[TIME] = t
      return
    }
    // bound on the relative acceleration until the next change of either ball's acceleration
    let A: number
    let pieceEnd: number
    if (exa === 1 && E[EXACT] === 1) {
      const rx = E[AX] - axa
      const ry = E[AY] - aya
      A = Math.sqrt(rx * rx + ry * ry)
      pieceEnd = na < E[NEXT] ? na : E[NEXT]
    } else {
      A = acca + E[ACC]
      pieceEnd = 1 / 0
    }
    // the gap closes no sooner than closeIn's bound
    const gg = g > 0 ? g : 0
    // (closeIn written out, and creep's numbers through slots: a double passed to or returned from a call
    // V8 does not inline is boxed, nine heap numbers a step of a touching pair's search)
    let h = vn < 0 ? (2 * gg) / (Math.sqrt(vn * vn + 2 * A * gg) - vn) : A > 0 ? (vn + Math.sqrt(vn * vn + 2 * A * gg)) / A : 1 / 0
    // touching (or nearly, and not closing): a step from the rates (creep), at least MIN_ADVANCE
    if (h < minAdvance && !(vn < 0 && g > 0)) {
      CR[CR_H] = h
      CR[CR_G] = g
      CR[CR_VN] = vn
      CR[CR_VREL] = vrel
      CR[CR_A] = A
      CR[CR_FLOOR] = floor
      CR[CR_DEEP] = deep
      CR[CR_MIN] = minAdvance
      creep()
      h = CR[CR_H]!
    }
    let next = t + h
    if (pieceEnd > t && next > pieceEnd) next = pieceEnd
    if (next > to) return
    if (!(next > t)) next = t + MIN_ADVANCE // h below the time resolution at t
    t = next
  }
  search[RESULT] = SearchResult.Resume
  search[TIME] = t
}

/** the constants of a ball on a straight path or at rest, read once per search: x0, y0, ux, uy, v0, t0 */
const K = new Float64Array(12)

function loadStraight(w: BallWorld, eid: number, o: number): void {
  if (w.Ball.mode[eid] === BallMode.Resting) {
    K[o] = w.Ball.x[eid]!
    K[o + 1] = w.Ball.y[eid]!
    K[o + 2] = NaN // marks a ball at rest
    return
  }
  const H = w.pathHot
  const h = eid * HOT
  K[o] = H[h + H_X0]!
  K[o + 1] = H[h + H_Y0]!
  K[o + 2] = H[h + H_UX]!
  K[o + 3] = H[h + H_UY]!
  K[o + 4] = H[h + H_V0]!
  K[o + 5] = H[h + H_T0]!
}

/**
 * searchContact for two balls neither of which is on a rim (the common case): the same steps, with each
 * ball's state computed in place from its path's constants, term for term as evalBall computes it.
 * Written out twice, for a and b, on purpose: one loop over a shared helper writing into a scratch array
 * (as evalBall does) measured 1.02x / 1.25x this version's contact overhead on the 1,000-ball gas / panel,
 * side by side; keep the three copies of the rolling formula (here and evalBall) in step.
 */
function searchStraight(w: BallWorld, a: number, b: number): void {
  const from = search[PAIR_FROM]!
  const minAdvance = MIN_STEP[0]!
  const to = search[PAIR_TO]!
  const S = w.Ball.radius[a]! + w.Ball.radius[b]!
  const floor = SETTLE_FLOOR * w.config.BALL_SETTLE_SPEED
  const deep = -DEPTH[0]!
  const decel = w.config.ROLLING_DECEL
  loadStraight(w, a, 0)
  loadStraight(w, b, 6)
  const restA = K[2] !== K[2]
  const restB = K[8] !== K[8]
  let t = from
  for (let iter = 0; iter < MAX_SEARCH_STEPS; iter++) {
    let xa: number, ya: number, vxa: number, vya: number, axa: number, aya: number, na: number
    if (restA) {
      xa = K[0]!
      ya = K[1]!
      vxa = vya = axa = aya = 0
      na = 1 / 0
    } else {
      const v0 = K[4]!
      const t0 = K[5]!
      let tau = t - t0
      if (tau < 0) tau = 0
      let moving = v0 > 0
      if (decel > 0 && tau * decel > v0) {
        tau = v0 / decel
        moving = false
      }
      const d = v0 * tau - 0.5 * decel * tau * tau
      const v = v0 - decel * tau
      const ux = K[2]!
      const uy = K[3]!
      xa = K[0]! + ux * d
      ya = K[1]! + uy * d
      vxa = ux * v
      vya = uy * v
      if (moving && decel > 0) {
        axa = -decel * ux
        aya = -decel * uy
        na = t0 + v0 / decel
      } else {
        axa = aya = 0
        na = 1 / 0
      }
    }
    let xb: number, yb: number, vxb: number, vyb: number, axb: number, ayb: number, nb: number
    if (restB) {
      xb = K[6]!
      yb = K[7]!
      vxb = vyb = axb = ayb = 0
      nb = 1 / 0
    } else {
      const v0 = K[10]!
      const t0 = K[11]!
      let tau = t - t0
      if (tau < 0) tau = 0
      let moving = v0 > 0
      if (decel > 0 && tau * decel > v0) {
        tau = v0 / decel
        moving = false
      }
      const d = v0 * tau - 0.5 * decel * tau * tau
      const v = v0 - decel * tau
      const ux = K[8]!
      const uy = K[9]!
      xb = K[6]! + ux * d
      yb = K[7]! + uy * d
      vxb = ux * v
      vyb = uy * v
      if (moving && decel > 0) {
        axb = -decel * ux
        ayb = -decel * uy
        nb = t0 + v0 / decel
      } else {
        axb = ayb = 0
        nb = 1 / 0
      }
    }
    const dx = xb - xa
    const dy = yb - ya
    const dvx = vxb - vxa
    const dvy = vyb - vya
    const dist = Math.sqrt(dx * dx + dy * dy)
    const g = dist - S
    const vrel = Math.sqrt(dvx * dvx + dvy * dvy)
    const vn = dist > 0 ? (dx * dvx + dy * dvy) / dist : -vrel
    if (g <= GAP_TOLERANCE ? vn < -(floor + APPROACH_EPSILON * (1 + vrel)) || (g <= deep && vn < -APPROACH_EPSILON * (1 + vrel)) : false) {
      search[RESULT] = SearchResult.Contact
      search[TIME] = t
      return
    }
    // both accelerations exact and piecewise constant (as in searchContact)
    const rx = axb - axa
    const ry = ayb - aya
    const A = Math.sqrt(rx * rx + ry * ry)
    const pieceEnd = na < nb ? na : nb
    // the gap closes no sooner than closeIn's bound
    const gg = g > 0 ? g : 0
    // (closeIn written out, and creep's numbers through slots: a double passed to or returned from a call
    // V8 does not inline is boxed, nine heap numbers a step of a touching pair's search)
    let h = vn < 0 ? (2 * gg) / (Math.sqrt(vn * vn + 2 * A * gg) - vn) : A > 0 ? (vn + Math.sqrt(vn * vn + 2 * A * gg)) / A : 1 / 0
    // touching (or nearly, and not closing): a step from the rates (creep), at least MIN_ADVANCE
    if (h < minAdvance && !(vn < 0 && g > 0)) {
      CR[CR_H] = h
      CR[CR_G] = g
      CR[CR_VN] = vn
      CR[CR_VREL] = vrel
      CR[CR_A] = A
      CR[CR_FLOOR] = floor
      CR[CR_DEEP] = deep
      CR[CR_MIN] = minAdvance
      creep()
      h = CR[CR_H]!
    }
    let next = t + h
    if (pieceEnd > t && next > pieceEnd) next = pieceEnd
    if (next > to) return
    if (!(next > t)) next = t + MIN_ADVANCE
    t = next
  }
  search[RESULT] = SearchResult.Resume
  search[TIME] = t
}

/**
 * How far a search may advance (into CR[CR_H]; its inputs in CR) from a state where the gap's own bound h1 is under MIN_ADVANCE (touching, or
 * nearly and not closing), without passing the first time its contact test holds. g is the gap (px), vn its
 * rate (negative: closing), vrel the balls' relative speed, A a bound on their relative acceleration until
 * the state's piece ends. The test holds either at a gap of at most 0 (GAP_TOLERANCE) closing faster than
 * the floor (route 1), or deeper than SINK_DEPTH closing at all (route 2). The gap's rate falls no faster
 * than A (the gap's second derivative is at least −A: (|dv|² − vn²) / distance ≥ 0, plus the relative
 * acceleration along the normal), so each route holds no sooner than both the time its gap needs to close
 * (the positive root of x + vn·h − A·h²/2, written without cancellation) and half the time its rate needs to
 * fall to its threshold (the half a margin for the threshold's share of vrel, which grows by at most A·h,
 * and for rounding). Everywhere else the gap's bound is the step, as it always was. A pair that closes
 * slower than the floor no longer creeps while it sinks into itself (which cost one pair 23 ms a step 9 s
 * after it met, and more every step): the search passes over to the depth of route 2, where it is a contact.
 */
function creep(): void {
  const h1 = CR[CR_H]!
  const g = CR[CR_G]!
  const vn = CR[CR_VN]!
  const vrel = CR[CR_VREL]!
  const A = CR[CR_A]!
  const floor = CR[CR_FLOOR]!
  const deep = CR[CR_DEEP]!
  const minAdvance = CR[CR_MIN]!
  // route 1 waits for its rate, route 2 for its depth and a rate of closing at all
  const eps = APPROACH_EPSILON * (1 + vrel)
  const rate1 = fallIn(vn + floor + eps, A)
  let h = rate1 > h1 ? rate1 : h1
  // route 2 is never sooner than route 1's gap time: looked at only where route 1 waits for its rate
  if (rate1 > h1) {
    const x = g - deep
    const close2 = closeIn(x > 0 ? x : 0, vn, A)
    const rate2 = fallIn(vn + eps, A)
    const h2 = close2 > rate2 ? close2 : rate2
    if (h2 < h) h = h2
  }
  // touching without approaching: creep on; the balls can close by at most A·MIN_ADVANCE²/2 meanwhile
  CR[CR_H] = h < minAdvance ? minAdvance : h
}

/** creep's inputs (its gap's own bound h1 in CR_H, and the state's g, vn, vrel, A, floor, depth and least step) and its answer (CR_H) */
const CR = new Float64Array(8)
const CR_H = 0
const CR_G = 1
const CR_VN = 2
const CR_VREL = 3
const CR_A = 4
const CR_FLOOR = 5
const CR_DEEP = 6
const CR_MIN = 7

/**
 * The least time in which a gap x ≥ 0 closing at rate vn, its rate falling no faster than A, can close: the
 * positive root of x + vn·h − A·h²/2, written without cancellation (infinite when it never closes).
 */
function closeIn(x: number, vn: number, A: number): number {
  if (vn < 0) return (2 * x) / (Math.sqrt(vn * vn + 2 * A * x) - vn)
  return A > 0 ? (vn + Math.sqrt(vn * vn + 2 * A * x)) / A : 1 / 0
}

/** Half the least time in which a rate above its threshold by `above` can fall to it, falling no faster than A. */
function fallIn(above: number, A: number): number {
  if (!(above > 0)) return 0
  return A > 0 ? (0.5 * above) / A : 1 / 0
}
