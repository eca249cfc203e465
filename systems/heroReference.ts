// Hero ball: the physical reference decides its lip crossings ("model no more than a scene needs"; see
// docs/physical.md). Covers the whole (δ, v) plane, for the balls flagged Ball.hero only.
//   at the exact lip crossing (δ, v): referenceOutcome({ δ, v, R, r, g, j }) → captured, or the exit
//   (point, speed, direction, time) of a rigid sphere rolling on and flying over a sharp lip
// Runs ahead of skipOver; a hero crossing it decides is unmarked, so the six stages never see it. Other
// balls, a hero whose radius is not below the hole's (the reference needs r < R), and a run the
// reference's guards stop (a steady roll round the rim that never decides) are left to the six stages.
// Escape: the ball leaves from the reference's exit point with its exit velocity, at the exact exit time;
// between the crossing and the exit it moves on the straight segment that ends there (the roll on the lip
// is not animated). Events are stamped at the crossing: 'capture' (via 'rimRoll' after a turn of at
// least HERO_ROLL_TURN on the lip, preceded by 'rimRoll'; else 'clean'); escapes give 'skip' (flew over,
// no impact), 'rimRoll' + 'lipOut' (turned at least HERO_ROLL_TURN) or 'bounce', each with 'nearMiss'
// except the skip. Costs one reference run (~20 µs on average) per hero lip crossing; allocates only the
// reference's result object, once per crossing, never per tick.
// Reads Path, Ball, Hole, config; writes Ball, Path, RimContact (takes the ball's slot); emits the events above.
import { PathEvent } from '../components/Path.js'
import { RimMode } from '../components/RimContact.js'
import { CaptureVia, EventType } from '../src/events.js'
import { captureBall, emitHoleEvent } from '../src/motion/ballFate.js'
import { planRolling, startPath } from '../src/motion/rolling.js'
import { referenceOutcome, type ReferenceInput } from '../src/reference/index.js'
import { lockAtLip } from '../src/world/rimSlots.js'
import { type BallWorld } from '../src/world/createWorld.js'

/** Turn on the lip (rad) from which a hero's outcome counts as a rim roll (docs/reference-model.md: about 20°). */
export const HERO_ROLL_TURN = (20 * Math.PI) / 180

// one input object, reused: a crossing allocates nothing of its own
const input: ReferenceInput = { delta: 0, speed: 0, holeRadius: 1, ballRadius: 0.5, gravity: 1, inertia: 0.4 }

export function heroReferenceSystem(w: BallWorld): void {
  const P = w.Path
  const H = w.Hole
  const B = w.Ball
  const list = w.marked
  for (let i = 0; i < list.count; i++) {
    const eid = list.ids[i]!
    if (B.hero[eid] !== 1 || P.mark[eid] !== PathEvent.Lip) continue
    const hole = P.markHole[eid]!
    const R = H.radius[hole]!
    const r = B.radius[eid]!
    const ux = P.ux[eid]!
    const uy = P.uy[eid]!
    const hx = H.x[hole]! - P.x0[eid]!
    const hy = H.y[hole]! - P.y0[eid]!
    // signed offset of the path: the closest point of the path is at cross·(−uy, ux) from the hole centre
    const cross = hx * uy - hy * ux
    const delta = Math.abs(cross)
    const v = P.speed[eid]!
    if (!(r < R) || !(delta < R) || !(v > 0)) continue
    input.delta = delta
    input.speed = v
    input.holeRadius = R
    input.ballRadius = r
    input.gravity = w.config.GRAVITY
    input.inertia = w.config.BALL_INERTIA
    const out = referenceOutcome(input)
    if (out.ending === 'phaseLimit' || out.ending === 'timeLimit' || out.ending === 'integratorLimit') continue

    const t = P.nextT[eid]!
    lockAtLip(w, eid, hole, delta, v, t, RimMode.Transit)
    P.mark[eid] = PathEvent.None
    const rolled = out.turnAngle >= HERO_ROLL_TURN
    if (rolled) emitHoleEvent(w, EventType.RimRoll, eid, hole, t)
    if (out.captured) {
      captureBall(w, eid, hole, t, rolled ? CaptureVia.RimRoll : CaptureVia.Clean)
      continue
    }

    // the reference's frame: x along the path, y toward the side the path passes the hole on
    const side = cross >= 0 ? 1 : -1
    const ex = -uy * side
    const ey = ux * side
    const X = out.exitX!
    const Y = out.exitY!
    const ca = Math.cos(out.exitAngle!)
    const sa = Math.sin(out.exitAngle!)
    const dx = ca * ux + sa * ex
    const dy = ca * uy + sa * ey
    const vOut = out.exitSpeed!
    // a straight path that reaches the exit point at t + duration with the exit velocity
    const decel = w.config.ROLLING_DECEL
    const dur = out.duration
    const back = vOut * dur + 0.5 * decel * dur * dur
    const v0 = vOut + decel * dur
    const exitX = H.x[hole]! + X * ux + Y * ex
    const exitY = H.y[hole]! + X * uy + Y * ey
    startPath(w, eid, exitX - dx * back, exitY - dy * back, dx * v0, dy * v0, t)
    // events start at the exit point: the segment before it only carries the ball there
    P.s[eid] = back
    P.fromHole[eid] = hole
    planRolling(w, eid)
    if (rolled) emitHoleEvent(w, EventType.LipOut, eid, hole, t)
    else emitHoleEvent(w, out.impacts === 0 && out.ending === 'hoppedOut' ? EventType.Skip : EventType.Bounce, eid, hole, t)
    if (rolled || out.impacts > 0 || out.ending !== 'hoppedOut') emitHoleEvent(w, EventType.NearMiss, eid, hole, t)
  }
}
