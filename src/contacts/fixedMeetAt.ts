// A fixed tick's pair alone at its tick meets at its instant (src/contacts/fixedMeet.ts gives the pair its
// Meet events): the integration takes the two-body law there and starts both balls' paths afresh.
import { BallMode } from '../../components/Ball.js'
import { PathEvent } from '../../components/Path.js'
import { appendCollision } from '../events.js'
import { launchBall } from '../motion/ballFate.js'
import { pathStart, PS_T, PS_VX, PS_VY, PS_X, PS_Y } from '../motion/rolling.js'
import type { BallWorld } from '../world/createWorld.js'
import { pushId } from '../world/idLists.js'
import { HOT, H_NEXT_T } from '../world/pathHot.js'
import { CI_E, CI_LIMIT, CI_MA, CI_MB, CI_NX, CI_NY, CI_VAX, CI_VAY, CI_VBX, CI_VBY, contactIn, contactOut, resolveContactIn, strikeLeavesRim } from './law.js'
import { AVX, AVY, AXp, AYp, BVX, BVY, BXp, BYp, P0, planAgain, statesAt, TT } from './fixedMeet.js'

/**
 * Ball eid's Meet event, at time t (the integration): with its partner's Meet still at t, the two-body law
 * with both balls' states at t, and a fresh path from t for both (the partner's Meet is then replaced by its
 * new path's own next event: whether the integration advances it before or after this ball in the pass, it
 * goes on from t); with the partner's path changed since, this ball goes on as it was. With the partner
 * still short of the instant, on its way through bookkeeping events of its own, this ball waits at its Meet
 * for the next pass (returns true; the integration hands it over), so the partner meets it there.
 */
export function meetAt(w: BallWorld, eid: number): boolean {
  const F = w.fixed!
  const M = w.meet!
  const H = w.pathHot
  const t = H[eid * HOT + H_NEXT_T]!
  const other = w.Path.nextHole[eid]!
  const rolling = w.Ball.mode[other] === BallMode.Rolling
  const moving = rolling || w.Ball.mode[other] === BallMode.RimRoll
  if (M.with[eid] === other && M.t[eid] === t && M.with[other] === eid && M.t[other] === t && w.Ball.live[other] === 1 && rolling && H[other * HOT + H_NEXT_T]! < t) return true
  M.with[eid] = 0
  // the partner's Meet at t too, or the partner at rest with this meeting (it has no events)
  const kept = moving ? w.Path.nextKind[other] === PathEvent.Meet && H[other * HOT + H_NEXT_T] === t : w.Ball.mode[other] === BallMode.Resting
  if (M.t[eid] !== t || w.Ball.live[other] !== 1 || M.with[other] !== eid || M.t[other] !== t || !kept) {
    // the partner's path changed: this one is planned again as it was
    planAgain(w, eid)
    return false
  }
  M.with[other] = 0
  P0[TT] = t
  statesAt(w, eid, other)
  const gx = P0[BXp]! - P0[AXp]!
  const gy = P0[BYp]! - P0[AYp]!
  const dist = Math.sqrt(gx * gx + gy * gy)
  if (!moving) {
    // a ball at rest put elsewhere since (its id taken again): this one goes on as it was
    const S = w.Ball.radius[eid]! + w.Ball.radius[other]!
    if (!(dist - S <= 1e-6 * S && dist - S >= -1e-6 * S)) {
      planAgain(w, eid)
      return false
    }
  }
  // the two-body law (src/contacts/law.ts), at the restitution the tick's solve gave the pair alone
  const I = contactIn
  I[CI_MA] = F.mass[eid]!
  I[CI_MB] = F.mass[other]!
  I[CI_VAX] = P0[AVX]!
  I[CI_VAY] = P0[AVY]!
  I[CI_VBX] = P0[BVX]!
  I[CI_VBY] = P0[BVY]!
  I[CI_NX] = gx / dist
  I[CI_NY] = gy / dist
  I[CI_E] = M.e[eid]!
  I[CI_LIMIT] = w.config.CONTACT_SPEED_LIMIT
  resolveContactIn()
  const o = contactOut
  if (o.approach >= w.config.BALL_SETTLE_SPEED) {
    const ev = w.events
    const i = appendCollision(ev, eid < other ? eid : other, eid < other ? other : eid)
    ev.time[i] = t
    ev.speed[i] = o.approach
    ev.impulse[i] = o.impulse
  }
  if (moving) restart(w, other, BXp, true)
  else if (Math.sqrt(o.vbx * o.vbx + o.vby * o.vby) >= w.config.BALL_SETTLE_SPEED) {
    // a ball at rest wakes as at a tick (src/contacts/fixedApply.ts) and goes on from t in the next pass
    restart(w, other, BXp, true)
    pushId(w.marked, other)
  }
  restart(w, eid, AXp, false)
  return false
}

/**
 * A fresh path for ball eid from the instant P0[TT], at its position there (P0 from slot `at`) and its
 * velocity after the contact (contactOut: the second ball's when `second`).
 */
function restart(w: BallWorld, eid: number, at: number, second: boolean): void {
  const o = contactOut
  pathStart[PS_X] = P0[at]!
  pathStart[PS_Y] = P0[at + 1]!
  pathStart[PS_VX] = second ? o.vbx : o.vax
  pathStart[PS_VY] = second ? o.vby : o.vay
  pathStart[PS_T] = P0[TT]!
  w.Ball.x[eid] = pathStart[PS_X]!
  w.Ball.y[eid] = pathStart[PS_Y]!
  strikeLeavesRim(w, eid)
  launchBall(w, eid)
}
