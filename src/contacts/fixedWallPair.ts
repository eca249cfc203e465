// Fixed-tick contacts: a pair solved together with the closed wall that it drives its lighter ball into
// (src/contacts/fixedSolve.ts, applyImpulse): one visit ends a squeeze or a wedge against the wall, where
// the sweeps would bounce the light ball between the wall and its partner, a little of the push each sweep.
// A block that would pump a ball past CONTACT_SPEED_LIMIT takes less of the pair's restitution, down to none
// (docs/decisions.md §8).
import { EventType, appendEvent } from '../events.js'
import type { BallWorld } from '../world/createWorld.js'
import type { FixedContactState } from '../world/fixedState.js'
import { capped, capVelocity, largestShare, overSpeed, pastLimit, share, shareRows } from '../motion/speedLimit.js'
import { face } from './fixedAhead.js'
import { walls } from './fixedGrid.js'
import { nrm, S_APPROACH, S_IMA, S_IMB, S_LIMIT, S_SEPARATE, S_SETTLE, S_T, solveSlots as S } from './fixedPairs.js'
import { WALL_REPORTED, wedgedOn } from './fixedWallTurn.js'

/** Candidate i's velocity with no component beyond MAX_SPEED (capVelocity, src/motion/speedLimit.ts). */
export function capBall(F: FixedContactState, i: number): void {
  if (!overSpeed(F.vx[i]!, F.vy[i]!)) return
  capVelocity(F.vx[i]!, F.vy[i]!)
  F.vx[i] = capped[0]!
  F.vy[i] = capped[1]!
}

/** the impulses of the last pairWithWall: the pair's, the wall's */
export const block = { j: 0, k: 0 }

/**
 * Pair (a, b), approaching at S[S_APPROACH] along nrm (inverse masses S[S_IMA], S[S_IMB]), solved together
 * with the wall `face` that candidate q (a or b) is pushed into: pair impulse j ≥ 0 and wall impulse k ≥ 0
 * on q such that the pair leaves at S[S_SEPARATE] (its restitution's share) times the walls' restitution
 * (the push goes through q into the wall: a dead wall takes it all, as a light ball's many bounces between
 * the two would) and q leaves the wall at the walls' restitution times its own speed into it before, each
 * zero when the other alone does it. Applied when both are positive and kinetic energy does not rise;
 * returns false, changing nothing, otherwise. Where the pair's restitution would pump a ball past
 * CONTACT_SPEED_LIMIT, the pair takes the largest share of it that does not, down to none (largestShare).
 */
export function pairWithWall(w: BallWorld, F: FixedContactState, a: number, b: number, q: number): boolean {
  const ima = S[S_IMA]!
  const imb = S[S_IMB]!
  const separate = S[S_SEPARATE]!
  const approach = S[S_APPROACH]!
  const nx = nrm.x
  const ny = nrm.y
  const imq = q === a ? ima : imb
  // q is pushed along d = ∓n; c = d·w < 0 (into the wall)
  const s = q === a ? -1 : 1
  const c = s * (nx * face.x + ny * face.y)
  const u2 = F.vx[q]! * face.x + F.vy[q]! * face.y
  const den = ima + imb - imq * c * c
  if (!(den > 0)) return false
  const m2a = ima > 0 ? 1 / ima : 0
  const m2b = imb > 0 ? 1 / imb : 0
  const before = m2a * (F.vx[a]! * F.vx[a]! + F.vy[a]! * F.vy[a]!) + m2b * (F.vx[b]! * F.vx[b]! + F.vy[b]! * F.vy[b]!)
  // the wall's restitution acts in series with the pair's: the push reaches the wall through q, and q's own
  // motion into the wall comes back at the wall's restitution (u2 < 0 is into the wall)
  // (none for a ball wider than the box across that wall: wedgedOn)
  const ew = wedgedOn(F, q, face.x !== 0 ? 1 : 2) ? 0 : walls.e
  const back = u2 < 0 ? -ew * u2 : 0
  const ax = F.vx[a]!
  const ay = F.vy[a]!
  const bx = F.vx[b]!
  const by = F.vy[b]!
  let sep = separate
  let j = 0
  let k = 0
  let vax = 0
  let vay = 0
  let vbx = 0
  let vby = 0
  // the block at the pair's restitution; where that would pump a ball past CONTACT_SPEED_LIMIT, again with
  // none and then with the largest share of it that keeps every component within (below)
  for (let pass = 0; ; pass++) {
    j = (sep * ew + approach + c * (u2 - back)) / den
    k = (back - u2) / imq - j * c
    if (!(j > 0 && k > 0)) return false
    vax = ax - j * ima * nx + (q === a ? k * ima * face.x : 0)
    vay = ay - j * ima * ny + (q === a ? k * ima * face.y : 0)
    vbx = bx + j * imb * nx + (q === b ? k * imb * face.x : 0)
    vby = by + j * imb * ny + (q === b ? k * imb * face.y : 0)
    const after = m2a * (vax * vax + vay * vay) + m2b * (vbx * vbx + vby * vby)
    // both restitutions at once can raise the energy (the two impulses are not independent): then the plain
    // impulse and the sweeps take the pair (a fully inelastic fallback here drained elastic scenes). Rounding
    // aside: an elastic striker off a pinned ball keeps its energy exactly, in exact arithmetic
    if (after > before + 8 * Number.EPSILON * before) return false
    // a squeeze near head on sends q along the wall at about its partner's speed over the sine of the angle
    // from head on, without bound as that angle closes. A tick cannot follow a ball across its box (its swept
    // tests are straight, and a wall turns it within the tick): a light ball squirted at 1e6 px/s and more
    // crossed a 420 px box many times a tick, every ball there paired with it, each sweep turned it and tested
    // those pairs again (seconds a step: docs/known-failures.md). So a squeeze that would send q along the wall
    // further than the wall's length in a tick is left to the plain impulse and the sweeps, as above
    const along = face.x !== 0 ? (q === a ? vay : vby) : q === a ? vax : vbx
    const span = face.x !== 0 ? walls.maxY - walls.minY : walls.maxX - walls.minX
    if (Math.abs(along) * F.tick > span) return false
    if (pass === 2) break
    if (pass === 1) {
      // the largest share of the pair's restitution that keeps each component within (largestShare)
      for (let r = 0; r < 4; r++) shareRows[3 * r + 2] = r === 0 ? vax : r === 1 ? vay : r === 2 ? vbx : vby
      largestShare(4)
      if (share[0] === 0) break
      sep = separate * share[0]!
      continue
    }
    // nor past CONTACT_SPEED_LIMIT: a velocity component beyond it and beyond its size before (pastLimit)
    // takes less of the pair's restitution, down to none, as the plain impulse does (capImpulse)
    if (!(sep > 0)) break
    for (let r = 0; r < 4; r++) {
      shareRows[3 * r] = r === 0 ? ax : r === 1 ? ay : r === 2 ? bx : by
      shareRows[3 * r + 1] = r === 0 ? vax : r === 1 ? vay : r === 2 ? vbx : vby
    }
    share[1] = S[S_LIMIT]!
    if (!pastLimit(4)) break
    sep = 0
  }
  F.vx[a] = vax
  F.vy[a] = vay
  F.vx[b] = vbx
  F.vy[b] = vby
  // no component beyond MAX_SPEED (src/motion/speedLimit.ts): the wall's push slows q, so only rounding or a
  // pumped ball's motion along the wall can take one there
  capBall(F, a)
  capBall(F, b)
  block.j = j
  block.k = k
  if ((F.changed[q]! & WALL_REPORTED) === 0 && k * imq >= S[S_SETTLE]!) {
    const ev = appendEvent(w.events, EventType.Wall, F.id[q]!, 0, false)
    w.events.time[ev] = S[S_T]!
    F.changed[q]! |= WALL_REPORTED
  }
  return true
}
