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
// knocks them off it (kick, below; the one place it adds energy, as a throw does), so a ball that stops on
// a launcher's spot does not hold the balls behind it for good, whatever their masses; a held ball that
// cannot fit between its closed walls kicks nothing. Kicks that do not clear the spot back off: after the k-th with no ball
// launched since (nor the queue emptied), the next waits 2^(k − 1) launch ticks (at most
// 2^(KICK_BACKOFF_DOUBLINGS − 1)), so a spot that balls jammed by the walls and one another cover for good
// is not kicked at every instant, for ever.
// Bounded work: at most MAX_SPOT_CHECKS full checks per launch instant (each against the moving and resting
// balls near the spot, through grids); a held ball overlapping the held ball just before it in the queue
// waits without one. The rest wait for later instants.
// Reads the held queue, Ball, the moving set and the resting grid; writes Ball, Path, RimContact and the
// world's kick back-off (kickStreak, kickAfter).
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
  if (!w.stepping) outsideStep('launcherSystem')
  // no ball held (all launched or removed): the next held ball's kicks start without a wait
  if (w.held.count === 0 && w.kickStreak !== 0) endKickStreak(w)
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
      if (checked && w.time >= w.kickAfter && spotHeldByResting(w, eid, x, y, r, blockers) && kick(w, eid, x, y)) {
        // kicks that do not clear the spot (balls jammed on it by walls and one another stop again at once,
        // every launch instant) come less and less often, so such a world can come to rest: the next no
        // sooner than the launch instant 2^(streak − 1) ticks on (half a tick short of it, against rounding)
        if (w.kickStreak < KICK_BACKOFF_DOUBLINGS) w.kickStreak++
        w.kickAfter = w.time + w.config.CONTACT_TICK * ((1 << (w.kickStreak - 1)) - 0.5)
      }
      q.ids[kept++] = eid
      last = eid
      continue
    }
    placeBall(w, eid, x, y, B.vx[eid]!, B.vy[eid]!)
    endKickStreak(w)
  }
  q.count = kept
}

const blockers = createIdList(8)

/** A ball launched, or none left held: the next kick comes without a wait. */
function endKickStreak(w: BallWorld): void {
  w.kickStreak = 0
  w.kickAfter = 0
}

/**
 * Each resting ball on held ball h's spot (x, y) leaves it, away from the spot's centre, at the speed a
 * head-on strike by h at its launch velocity would give it, (1 + e)·m_h/(m_h + m_b)·|v_h|, or, if that is
 * less, at the speed that rolls it off the spot against ROLLING_DECEL, √(2·a·(r_h + r_b − d)) (with no
 * deceleration, BALL_SETTLE_SPEED); at most MAX_SPEED. The launcher does the work, whatever the masses:
 * kinetic energy is added, as by a throw, and h stays held until its spot is clear. (Before, a ball the
 * strike left slower than BALL_SETTLE_SPEED was not kicked, nor any other on the spot, and one struck just
 * faster rolled 0.003 px and stopped on the spot again: a radius-25 ball lying on a launcher's spot held
 * every smaller ball behind it for good.) A held ball that cannot fit between its closed walls kicks
 * nothing: its spot can never be cleared while a ball is in the box (one wider than its box once kicked the
 * balls round it every second or so for good). Returns whether it kicked.
 */
function kick(w: BallWorld, h: number, x: number, y: number): boolean {
  const B = w.Ball
  if (w.walls !== 0 && !fits(w, B.radius[h]!)) return false
  const mass = w.collide !== null ? w.collide.mass : w.fixed!.mass
  const vh = hypot(B.vx[h]!, B.vy[h]!)
  const e = w.config.BALL_RESTITUTION
  const decel = w.config.ROLLING_DECEL
  for (let i = 0; i < blockers.count; i++) {
    const b = blockers.ids[i]!
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
    const clear = decel > 0 ? Math.sqrt(2 * decel * (B.radius[h]! + B.radius[b]! - away + TOUCH_GAP)) : w.config.BALL_SETTLE_SPEED
    const speed = Math.min(MAX_SPEED, Math.max(kickSpeed(mass, h, b, vh, e), clear))
    placeBall(w, b, B.x[b]!, B.y[b]!, (speed * nx) / d, (speed * ny) / d)
    w.kicks++
  }
  return true
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
