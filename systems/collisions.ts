// Ball-ball contacts (not a design stage; opt-in with config.BALL_COLLISIONS = 'on'). The integration
// system finds the contact exactly and marks both balls; this system applies the contact law and restarts
// the balls on straight paths from the contact.
//   contact: normal impulse with restitution BALL_RESTITUTION and the balls' masses, tangential velocity
//     kept (resolveContact in src/contacts/law.ts); elastic when either ball touched another within
//     CONTACT_DURATION (a push runs along a row of touching balls as in Newton's cradle)
//   settling contact (approach slower than BALL_SETTLE_SPEED, or the same two balls touching again with
//     nothing between, or a ball past MAX_TICK_CONTACTS contacts in this contact tick: a light ball squeezed
//     between heavy ones): the touching cluster around them leaves with its centre-of-mass velocity, and off a
//     closed wall a member touches that it moves into as one body, at the balls' restitution times the wall's;
//     then nothing in it can touch again (inelastic collapse ends).
//     Two balls alone that approach that slowly while sliding past each other at GRAZE_SLIDE times
//     BALL_SETTLE_SPEED or more (a graze), with restitution above 0, take the normal impulse instead,
//     keeping their tangential motion
//   struck while rolling on a rim: it leaves the rim and is in transit through that hole (no new decision
//     there; it falls in if it stops inside the lip circle), as after a pop-off
//   struck while skipping over or entering a hole: likewise in transit (the lip decision no longer applies)
//   struck at rest: it wakes and rolls
// Reads Path.mark, Ball; writes Ball, Path, RimContact; emits 'collision' (one per contact, ball < other).
import { BallMode } from '../components/Ball.js'
import { PathEvent } from '../components/Path.js'
import { WallEdge } from '../components/Walls.js'
import { CONTACT_DURATION, GRAZE_SLIDE, MAX_TICK_CONTACTS, NEVER, TOUCH_GAP } from '../src/config/tolerances.js'
import { clusterAt, collectCluster } from '../src/contacts/cluster.js'
import { CI_E, CI_LIMIT, CI_MA, CI_MB, CI_NX, CI_NY, CI_VAX, CI_VAY, CI_VBX, CI_VBY, contactIn, contactOut, isRepeatContact, resolveContactIn, strikeLeavesRim } from '../src/contacts/law.js'
import { appendCollision, appendEvent, EventType } from '../src/events.js'
import { launchBall } from '../src/motion/ballFate.js'
import { PS_T, PS_VX, PS_VY, PS_X, PS_Y, pathStart, planRolling } from '../src/motion/rolling.js'
import { planRimRoll } from '../src/motion/rimRoll.js'
import { pushId } from '../src/world/idLists.js'
import { contactTickKey, countContacts } from '../src/world/contactState.js'
import { type BallWorld } from '../src/world/createWorld.js'
import { hypot } from '../src/math.js'
import { HOT, H_NEXT_T, setNextT } from '../src/world/pathHot.js'
import { outsideStep } from '../src/world/system.js'

export function collisionsSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('collisionsSystem', w)
  const C = w.collide
  if (C === null) return
  const P = w.Path
  const B = w.Ball
  const list = w.marked
  const n0 = list.count
  for (let i = 0; i < n0; i++) {
    const a = list.ids[i]!
    if (P.mark[a] !== PathEvent.Collide) continue
    const b = P.markOther[a]!
    if (P.mark[b] !== PathEvent.Collide || P.markOther[b] !== a) {
      // the other ball was removed this pass (by a game's system; its rows are cleared, an id bitECS gave
      // out again included): a goes on as if it had never been there
      if (P.mark[b] === PathEvent.None) {
        dropContact(w, a)
        continue
      }
      throw new Error(`ball ${a}: contact with ball ${b} was marked on one ball only`)
    }
    P.mark[a] = PathEvent.None
    P.mark[b] = PathEvent.None
    const t = w.pathHot[a * HOT + H_NEXT_T]!
    let nx = B.x[b]! - B.x[a]!
    let ny = B.y[b]! - B.y[a]!
    const d = Math.sqrt(nx * nx + ny * ny)
    if (d > 0) {
      nx /= d
      ny /= d
    } else {
      // coincident centres: push apart along the relative velocity
      const rx = B.vx[a]! - B.vx[b]!
      const ry = B.vy[a]! - B.vy[b]!
      const s = Math.sqrt(rx * rx + ry * ry)
      nx = s > 0 ? rx / s : 1
      ny = s > 0 ? ry / s : 0
    }
    const approach = -((B.vx[b]! - B.vx[a]!) * nx + (B.vy[b]! - B.vy[a]!) * ny)
    // a glancing contact at relative speed v approaches slower than s in a share of about s²/(2v²) of
    // contacts: 1 in 180,000 at s = 1 px/s (the default BALL_SETTLE_SPEED), v = 300 px/s
    const slow = approach < w.config.BALL_SETTLE_SPEED
    const repeat = isRepeatContact(w, a, b)
    // the contact tick of the world's clock the contact falls in (its count is the same at every frame rate)
    const tick = contactTickKey(t, w.config.CONTACT_TICK)
    const settle = slow || repeat || countContacts(C, a, tick, 1) > MAX_TICK_CONTACTS || countContacts(C, b, tick, 1) > MAX_TICK_CONTACTS
    C.contacts++
    let graze = false
    if (settle) {
      // the time through a slot, for the cluster and the settle (a double passed to a call V8 does not inline is boxed)
      clusterAt[0] = t
      collectCluster(w, a, b)
      // two balls alone that barely approach but slide past each other fast (a graze; restitution above 0)
      // take the normal impulse and keep their motion along the tangent; merged, both stopped dead (a graze
      // at 300 px/s each way left two balls at rest). Only a first touch, counted with the tick's contacts
      // (the count was skipped for a slow one): pressed together, the two touch again and settle then (a
      // graze each time, they once made a thousand contacts a second and a step that hung on the pass cap)
      graze =
        slow && !repeat && w.config.BALL_RESTITUTION > 0 && C.clusterCount === 2 && slides(B, a, b, nx, ny) >= GRAZE_SLIDE * w.config.BALL_SETTLE_SPEED &&
        countContacts(C, a, tick, 1) <= MAX_TICK_CONTACTS && countContacts(C, b, tick, 1) <= MAX_TICK_CONTACTS
      if (!graze) {
        settleCluster(w, a, b)
        const k = appendCollision(w.events, a < b ? a : b, a < b ? b : a)
        w.events.time[k] = t
        w.events.speed[k] = approach
        w.events.impulse[k] = contactOut.impulse
        continue
      }
    }
    const rapid = t - C.lastContact[a]! < CONTACT_DURATION || t - C.lastContact[b]! < CONTACT_DURATION
    const e = rapid && !graze ? 1 : w.config.BALL_RESTITUTION
    const I = contactIn
    I[CI_MA] = C.mass[a]!
    I[CI_MB] = C.mass[b]!
    I[CI_VAX] = B.vx[a]!
    I[CI_VAY] = B.vy[a]!
    I[CI_VBX] = B.vx[b]!
    I[CI_VBY] = B.vy[b]!
    I[CI_NX] = nx
    I[CI_NY] = ny
    I[CI_E] = e
    I[CI_LIMIT] = w.config.CONTACT_SPEED_LIMIT
    resolveContactIn()
    const o = contactOut
    C.lastContact[a] = t
    C.lastContact[b] = t
    const k = appendCollision(w.events, a < b ? a : b, a < b ? b : a)
    w.events.time[k] = t
    w.events.speed[k] = o.approach
    w.events.impulse[k] = o.impulse
    // the new starts written here, not through startAt (five doubles a call where V8 does not inline it)
    pathStart[PS_X] = B.x[a]!
    pathStart[PS_Y] = B.y[a]!
    pathStart[PS_VX] = o.vax
    pathStart[PS_VY] = o.vay
    pathStart[PS_T] = t
    restart(w, a)
    pathStart[PS_X] = B.x[b]!
    pathStart[PS_Y] = B.y[b]!
    pathStart[PS_VX] = o.vbx
    pathStart[PS_VY] = o.vby
    pathStart[PS_T] = t
    restart(w, b)
    // set after the restart (a new path clears it): any later change of either path clears it again
    C.partner[a] = b
    C.partner[b] = a
  }
}

/**
 * Ball a's contact whose other ball is gone: its mark is cleared and its own next event, which the contact
 * took the place of, planned again from the same path (the same event: nothing it is planned from changed).
 */
function dropContact(w: BallWorld, a: number): void {
  w.Path.mark[a] = PathEvent.None
  const mode = w.Ball.mode[a]
  if (mode === BallMode.Rolling) planRolling(w, a)
  else if (mode === BallMode.RimRoll) planRimRoll(w, a)
  else setNextT(w, a, NEVER)
}

/** The speed at which balls a and b slide past each other: their relative velocity across the normal (nx, ny). */
function slides(B: BallWorld['Ball'], a: number, b: number, nx: number, ny: number): number {
  const rx = B.vx[b]! - B.vx[a]!
  const ry = B.vy[b]! - B.vy[a]!
  return Math.abs(rx * ny - ry * nx)
}

/**
 * The cluster touching a and b (collectCluster, just run, at clusterAt[0]) leaves with its centre-of-mass
 * velocity; off a closed wall it touches and moves into, as one body at the balls' restitution times the
 * wall's (stopped on that axis where that is slower than BALL_SETTLE_SPEED or it touches the opposite wall).
 */
function settleCluster(w: BallWorld, a: number, b: number): void {
  const t = clusterAt[0]!
  const C = w.collide!
  const B = w.Ball
  const n = C.clusterCount
  let m = 0
  let px = 0
  let py = 0
  for (let k = 0; k < n; k++) {
    const eid = C.cluster[k]!
    const mass = C.mass[eid]!
    m += mass
    px += mass * B.vx[eid]!
    py += mass * B.vy[eid]!
  }
  let vx = px / m
  let vy = py / m
  // the impulse reported is the one on a
  contactOut.impulse = C.mass[a]! * hypot(vx - B.vx[a]!, vy - B.vy[a]!)
  // the closed walls it is sent back from (WallEdge bits)
  let bounced = 0
  if (w.walls !== 0) {
    const W = w.Walls
    const e = w.walls
    // the closed walls a member touches
    let touched = 0
    for (let k = 0; k < n; k++) touched |= wallsTouched(w, C.cluster[k]!)
    // a cluster moving into a wall it touches leaves it as one body at the balls' restitution times the
    // wall's (a squeeze of many contacts ends as the two-body law's limit would: a default ball pressing a
    // tiny one against an elastic wall rebounds), or stops on that axis when that is slower than
    // BALL_SETTLE_SPEED or the cluster touches the wall opposite too
    const keep = w.config.BALL_RESTITUTION * W.restitution[e]!
    const floor = w.config.BALL_SETTLE_SPEED
    const ux = vx
    const uy = vy
    if (vx < 0 && (touched & WallEdge.Left) !== 0) vx = (touched & WallEdge.Right) === 0 && -keep * vx >= floor ? -keep * vx : 0
    else if (vx > 0 && (touched & WallEdge.Right) !== 0) vx = (touched & WallEdge.Left) === 0 && keep * vx >= floor ? -keep * vx : 0
    if (vy < 0 && (touched & WallEdge.Top) !== 0) vy = (touched & WallEdge.Bottom) === 0 && -keep * vy >= floor ? -keep * vy : 0
    else if (vy > 0 && (touched & WallEdge.Bottom) !== 0) vy = (touched & WallEdge.Top) === 0 && keep * vy >= floor ? -keep * vy : 0
    if (vx !== 0 && vx !== ux) bounced |= ux < 0 ? WallEdge.Left : WallEdge.Right
    if (vy !== 0 && vy !== uy) bounced |= uy < 0 ? WallEdge.Top : WallEdge.Bottom
  }
  if (bounced !== 0) settleWallEvents(w, t, bounced)
  for (let k = 0; k < n; k++) {
    const eid = C.cluster[k]!
    C.lastContact[eid] = t
    // the start written here, not through startAt: where V8 does not inline it, its five doubles were boxed
    // for every member of every cluster settled (a pile's clusters run to hundreds)
    pathStart[PS_X] = B.x[eid]!
    pathStart[PS_Y] = B.y[eid]!
    pathStart[PS_VX] = vx
    pathStart[PS_VY] = vy
    pathStart[PS_T] = t
    restart(w, eid)
    // the others are predicted again next pass with a and b
    if (k >= 2) pushId(w.marked, eid)
  }
}

/** The closed walls (WallEdge bits) ball eid touches: within TOUCH_GAP of their lines. */
function wallsTouched(w: BallWorld, eid: number): number {
  const W = w.Walls
  const e = w.walls
  const B = w.Ball
  const open = W.open[e]!
  const x = B.x[eid]!
  const y = B.y[eid]!
  const r = B.radius[eid]!
  let touched = 0
  if ((open & WallEdge.Left) === 0 && x - r - W.minX[e]! <= TOUCH_GAP) touched |= WallEdge.Left
  if ((open & WallEdge.Right) === 0 && W.maxX[e]! - x - r <= TOUCH_GAP) touched |= WallEdge.Right
  if ((open & WallEdge.Top) === 0 && y - r - W.minY[e]! <= TOUCH_GAP) touched |= WallEdge.Top
  if ((open & WallEdge.Bottom) === 0 && W.maxY[e]! - y - r <= TOUCH_GAP) touched |= WallEdge.Bottom
  return touched
}

/**
 * A 'wall' event at time t for each member of the cluster being settled (its velocities not yet changed)
 * that touches one of the walls `bounced` (WallEdge bits) the cluster is sent back from and is not moving
 * away from it (a ball that bounced off it at this instant has its own).
 */
function settleWallEvents(w: BallWorld, t: number, bounced: number): void {
  const C = w.collide!
  const B = w.Ball
  for (let k = 0, n = C.clusterCount; k < n; k++) {
    const eid = C.cluster[k]!
    const walls = wallsTouched(w, eid) & bounced
    if (walls === 0) continue
    const vx = B.vx[eid]!
    const vy = B.vy[eid]!
    const away =
      ((walls & WallEdge.Left) === 0 || vx > 0) && ((walls & WallEdge.Right) === 0 || vx < 0) && ((walls & WallEdge.Top) === 0 || vy > 0) && ((walls & WallEdge.Bottom) === 0 || vy < 0)
    if (away) continue
    const ev = appendEvent(w.events, EventType.Wall, eid, 0, false)
    w.events.time[ev] = t
  }
}

/** Ball eid leaves the contact on a fresh path from pathStart (its position, new velocity, the contact's time). */
function restart(w: BallWorld, eid: number): void {
  strikeLeavesRim(w, eid)
  launchBall(w, eid)
}
