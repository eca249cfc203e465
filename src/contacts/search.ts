// The contact search: the first time two balls touch while approaching, by conservative advancement on
// their closed-form motions (no step can pass a contact, at any dt).
import { APPROACH_EPSILON, GAP_TOLERANCE, MAX_SEARCH_STEPS, MIN_ADVANCE, SETTLE_FLOOR } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import { ACC, AT, AX, AY, E, EXACT, NEXT, VX, VY, X, Y, evalBall } from './evalMotion.js'

export const SearchResult = { None: 0, Contact: 1, Resume: 2 } as const
/** result of the last search (a SearchResult) and its time, s; a typed array: no allocation per write */
export const search = new Float64Array(2)
export const RESULT = 0
export const TIME = 1

/**
 * First contact of balls a and b in [from, to], on their current motions: the earliest time at which their
 * gap is at most GAP_TOLERANCE while they approach. Sets search[RESULT]/search[TIME]: Contact at that time, None
 * if there is none before `to`, or Resume with the time reached after MAX_SEARCH_STEPS (the search continues
 * from there when that time comes up in the heap).
 */
export function searchContact(w: BallWorld, a: number, b: number, from: number, to: number): void {
  search[RESULT] = SearchResult.None
  if (!(from <= to)) return
  const S = w.Ball.radius[a]! + w.Ball.radius[b]!
  const floor = SETTLE_FLOOR * w.config.BALL_SETTLE_SPEED
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
    if (g <= GAP_TOLERANCE && vn < -(floor + APPROACH_EPSILON * (1 + vrel))) {
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
      pieceEnd = Infinity
    }
    const gg = g > 0 ? g : 0
    let h: number
    if (vn < 0) {
      // the gap closes no sooner than the positive root of gg + vn·h − A·h²/2 (written without cancellation)
      h = (2 * gg) / (Math.sqrt(vn * vn + 2 * A * gg) - vn)
    } else {
      h = A > 0 ? (vn + Math.sqrt(vn * vn + 2 * A * gg)) / A : Infinity
      // touching without approaching: creep on; the balls can close by at most A·MIN_ADVANCE²/2 meanwhile
      if (h < MIN_ADVANCE) h = MIN_ADVANCE
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
