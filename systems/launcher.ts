// Launcher (not a design stage; ball-ball contacts on only). A ball put down where another ball is waits
// there, held (mode 'held'), with the velocity it was given. At each launch instant (k·CONTACT_TICK of the
// world's clock with exact contacts; every tick, halved ones too, with the fixed tick) the held balls whose
// spots are clear are launched, in the order they came, from their spots with those velocities: the step
// ends a window on each instant while a ball is held and sets world.launchDue for the window that starts
// there (src/schedule.ts). An arcade launcher firing many balls from one point so lets them out one after
// another, each as the one before it clears the spot, instead of starting them inside one another. The rule
// adds no kinetic energy (a held ball keeps its velocity and is launched only where it overlaps nothing),
// and a released ball starts where it was put, at the instant: release times are the same at every frame
// rate (before, they were the steps' starts). A spot held only by resting balls is cleared: the launcher
// knocks them off it (kick, below; the one place it adds energy, as a throw does), each toward the nearest
// place off the spot that the closed walls leave it, so a ball that stops on a launcher's spot does not hold
// the balls behind it for good, whatever their masses or the walls beside it; a held ball that cannot fit
// between its closed walls kicks nothing. Kicks that do not clear a spot back off: a ball kicked k times in
// a row is kicked next no sooner than 2^(k − 1) launch ticks after the last (at most
// 2^(KICK_BACKOFF_DOUBLINGS − 1); backOff), so balls that the walls and one another jam on a spot for good
// are not kicked at every instant, for ever; the back-off is the kicked ball's, so such a spot delays no
// other, and the held balls queued on one spot share it.
// Bounded work: at most MAX_SPOT_CHECKS full checks per launch instant (each against the moving and resting
// balls near the spot, through grids); a held ball overlapping the held ball just before it in the queue
// waits without one. The rest wait for later instants.
// Reads the held queue, Ball, Walls, the moving set and the resting grid; writes Ball, Path, RimContact and
// the kicked balls' back-off (world.kickStreak, world.kickAfter).
import { BallMode } from '../components/Ball.js'
import { WallEdge } from '../components/Walls.js'
import { MAX_SPEED } from '../src/config/limits.js'
import { KICK_BACKOFF_DOUBLINGS, MAX_SPOT_CHECKS, TOUCH_GAP } from '../src/config/tolerances.js'
import { spotHeldByResting, spotTaken } from '../src/contacts/spot.js'
import { placeBall } from '../src/motion/ballFate.js'
import type { BallWorld } from '../src/world/createWorld.js'
import { createIdList } from '../src/world/idLists.js'
import { hypot } from '../src/math.js'
import { outsideStep } from '../src/world/system.js'

export function launcherSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('launcherSystem', w)
  if (w.pass !== 0 || w.held.count === 0 || !w.launchDue) return
  const q = w.held
  const B = w.Ball
  let kept = 0
  let checks = 0
  let last = 0
  for (let i = 0; i < q.count; i++) {
    const eid = q.ids[i]!
    if (B.live[eid] !== 1 || B.mode[eid] !== BallMode.Held) continue
    const x = B.x[eid]!
    const y = B.y[eid]!
    const r = B.radius[eid]!
    let wait: boolean
    let checked = false
    if (last !== 0 && overlaps(w, eid, last)) wait = true
    else if (checks >= MAX_SPOT_CHECKS) wait = true
    else {
      checks++
      checked = true
      wait = spotTaken(w, eid, x, y, r)
    }
    if (wait) {
      // a spot held only by resting balls: the launcher knocks them off it (else a ball that came to rest
      // on a launcher's spot would hold every ball behind it for good)
      if (checked && spotHeldByResting(w, eid, x, y, r, blockers)) kick(w, eid, x, y)
      q.ids[kept++] = eid
      last = eid
      continue
    }
    placeBall(w, eid, x, y, B.vx[eid]!, B.vy[eid]!)
  }
  q.count = kept
}

const blockers = createIdList(8)

/**
 * Each resting ball on held ball h's spot (x, y) whose back-off is out (backOff) leaves it toward the
 * nearest place off the spot that the closed walls leave it (see wayOff: straight away from the spot's
 * centre unless a wall is in the way, else along that wall), at the speed a head-on strike by h at its
 * launch velocity would give it,
 * (1 + e)·m_h/(m_h + m_b)·|v_h|, or, if that is less, at the speed that rolls it there against
 * ROLLING_DECEL, √(2·a·s) for a way of length s (with no deceleration, BALL_SETTLE_SPEED); at most
 * MAX_SPEED. The launcher does the work, whatever the masses: kinetic energy is added, as by a throw, and h
 * stays held until its spot is clear. (Before, a ball the strike left slower than BALL_SETTLE_SPEED was not
 * kicked, nor any other on the spot, and one struck just faster rolled 0.003 px and stopped on the spot
 * again: a radius-25 ball lying on a launcher's spot held every smaller ball behind it for good. A ball
 * lying against a wall beyond the spot was kicked straight into the wall, came back or stayed, and held
 * the spot for good.) A held ball that cannot fit between its closed walls kicks nothing: its spot can
 * never be clear while a ball is in the box (one wider than its box once kicked the balls round it every
 * second or so for good), nor does a ball with no place off the spot between the walls move.
 */
function kick(w: BallWorld, h: number, x: number, y: number): void {
  const B = w.Ball
  if (w.walls !== 0 && !fits(w, B.radius[h]!)) return
  const mass = w.collide !== null ? w.collide.mass : w.fixed!.mass
  const vh = hypot(B.vx[h]!, B.vy[h]!)
  const e = w.config.BALL_RESTITUTION
  const decel = w.config.ROLLING_DECEL
  for (let i = 0; i < blockers.count; i++) {
    const b = blockers.ids[i]!
    if (w.time < w.kickAfter[b]!) continue
    let nx = B.x[b]! - x
    let ny = B.y[b]! - y
    const away = hypot(nx, ny)
    let d = away
    if (d === 0) {
      // on the spot's centre: along h's launch direction (or up the panel)
      nx = vh > 0 ? B.vx[h]! : 0
      ny = vh > 0 ? B.vy[h]! : -1
      d = vh > 0 ? vh : 1
    }
    // the length of its way off the spot: straight out, or (a wall in the way) to the nearest place left
    let way = B.radius[h]! + B.radius[b]! - away + TOUCH_GAP
    if (w.walls !== 0 && !wayOff(w, b, x, y, B.radius[h]! + B.radius[b]! + TOUCH_GAP, nx / d, ny / d, B.vx[h]!, B.vy[h]!)) {
      if (place[2]! < 0) continue
      nx = place[0]! - B.x[b]!
      ny = place[1]! - B.y[b]!
      d = hypot(nx, ny)
      if (!(d > 0)) continue
      way = d
    }
    const clear = decel > 0 ? Math.sqrt(2 * decel * way) : w.config.BALL_SETTLE_SPEED
    const speed = Math.min(MAX_SPEED, Math.max(kickSpeed(mass, h, b, vh, e), clear))
    placeBall(w, b, B.x[b]!, B.y[b]!, (speed * nx) / d, (speed * ny) / d)
    backOff(w, b)
    w.kicks++
  }
}

/**
 * Ball b was kicked now: it is kicked next no sooner than the launch instant 2^(k − 1) ticks on (half a
 * tick short of it, against rounding), k its kicks in a row (balls jammed on a spot by the walls and one
 * another stop again at once, every launch instant). A ball that stayed off the spots for the longest wait,
 * 2^(KICK_BACKOFF_DOUBLINGS − 1) ticks, past its due starts again from one. (Starting again after its own
 * wait let a crowd that overfills a closed box kick its churning balls about four times as often.)
 */
function backOff(w: BallWorld, b: number): void {
  const tick = w.config.CONTACT_TICK
  let streak = w.kickStreak[b]!
  if (streak > 0 && w.time - w.kickAfter[b]! >= tick * (1 << (KICK_BACKOFF_DOUBLINGS - 1))) streak = 0
  streak = Math.min(KICK_BACKOFF_DOUBLINGS, streak + 1)
  w.kickStreak[b] = streak
  w.kickAfter[b] = w.time + tick * ((1 << (streak - 1)) - 0.5)
}

/** wayOff's answer when a wall is in the way: the place (x, y), and 1, or −1 when there is none */
const place = new Float64Array(3)

/**
 * Whether resting ball b, on a spot centred at (x, y), can leave it straight away from the centre (along the
 * unit (ux, uy)) to the circle of radius R about it, where it touches the held ball no more: true when that
 * place lies between the closed walls (b's centre at least its radius from each). Otherwise the nearest
 * place on that circle between them is an end of the circle's arc there, on a line a radius from a closed
 * wall: it is written to `place` (the one nearest the straight way out; of two as near, the one ahead along
 * the held ball's velocity (vx, vy), or else the first of up, left, down, right), or place[2] = −1 when no
 * part of the circle lies between the walls.
 */
function wayOff(w: BallWorld, b: number, x: number, y: number, R: number, ux: number, uy: number, vx: number, vy: number): boolean {
  const W = w.Walls
  const k = w.walls
  const open = W.open[k]!
  const rb = w.Ball.radius[b]!
  const x0 = (open & WallEdge.Left) === 0 ? W.minX[k]! + rb : -Infinity
  const x1 = (open & WallEdge.Right) === 0 ? W.maxX[k]! - rb : Infinity
  const y0 = (open & WallEdge.Top) === 0 ? W.minY[k]! + rb : -Infinity
  const y1 = (open & WallEdge.Bottom) === 0 ? W.maxY[k]! - rb : Infinity
  const qx = x + R * ux
  const qy = y + R * uy
  if (qx >= x0 && qx <= x1 && qy >= y0 && qy <= y1) return true
  best = -Infinity
  ahead = -Infinity
  place[2] = -1
  // the circle's ends on each closed wall's line: y = y0 and x = x0 first (up, left), then y = y1, x = x1
  arcEnd(x, y, R, ux, uy, vx, vy, y0, x0, x1, true)
  arcEnd(x, y, R, ux, uy, vx, vy, x0, y0, y1, false)
  arcEnd(x, y, R, ux, uy, vx, vy, y1, x0, x1, true)
  arcEnd(x, y, R, ux, uy, vx, vy, x1, y0, y1, false)
  return false
}
let best = -Infinity
let ahead = -Infinity

/**
 * The points where the circle (x, y, R) meets the line at `at` (y = at when `across`, else x = at), within
 * [lo, hi] along it: each kept in `place` if nearer the straight way out (ux, uy) than the best so far (its
 * cosine to it larger), or as near and further along (vx, vy).
 */
function arcEnd(x: number, y: number, R: number, ux: number, uy: number, vx: number, vy: number, at: number, lo: number, hi: number, across: boolean): void {
  if (!Number.isFinite(at)) return
  const off = across ? at - y : at - x
  const h2 = R * R - off * off
  if (!(h2 >= 0)) return
  const half = Math.sqrt(h2)
  for (let s = -1; s <= 1; s += 2) {
    const along = s * half
    const px = across ? x + along : at
    const py = across ? at : y + along
    if ((across ? px : py) < lo || (across ? px : py) > hi) continue
    const cos = (px - x) * ux + (py - y) * uy
    const fore = (px - x) * vx + (py - y) * vy
    if (cos > best || (cos === best && fore > ahead)) {
      best = cos
      ahead = fore
      place[0] = px
      place[1] = py
      place[2] = 1
    }
  }
}

/** Whether a ball of radius r fits between the world's walls on each axis closed at both ends. */
function fits(w: BallWorld, r: number): boolean {
  const W = w.Walls
  const k = w.walls
  const open = W.open[k]!
  if ((open & (WallEdge.Left | WallEdge.Right)) === 0 && 2 * r > W.maxX[k]! - W.minX[k]!) return false
  return (open & (WallEdge.Top | WallEdge.Bottom)) !== 0 || 2 * r <= W.maxY[k]! - W.minY[k]!
}

/** The speed a head-on strike by held ball h at speed vh gives resting ball b (at most MAX_SPEED). */
function kickSpeed(mass: Float64Array, h: number, b: number, vh: number, e: number): number {
  return Math.min(MAX_SPEED, ((1 + e) * mass[h]! * vh) / (mass[h]! + mass[b]!))
}

function overlaps(w: BallWorld, a: number, b: number): boolean {
  const B = w.Ball
  const dx = B.x[a]! - B.x[b]!
  const dy = B.y[a]! - B.y[b]!
  const s = B.radius[a]! + B.radius[b]!
  return dx * dx + dy * dy < s * s
}
