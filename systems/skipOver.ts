// Stage 5, skip-over. Region 1 of the (δ, v) map.
//   v > v_skip(δ) = R·√(2g/r)·√(1 − δ²/R²)      (chord time shorter than the time to fall by r)
// At the exact lip crossing, a ball faster than v_skip flies over: the hole is locked for this transit
// (no capture, no rim contact, no near miss) until the centre leaves its lip circle.
// Reads Path (mark, origin, direction, speed), Hole, Ball.radius; writes RimContact (takes the ball's slot),
// Path.mark; emits 'skip'.
import { PathEvent } from '../components/Path.js'
import { RimMode } from '../components/RimContact.js'
import { EventType } from '../src/events.js'
import { fliesOver } from '../src/geometry.js'
import { emitHoleEvent } from '../src/motion/ballFate.js'
import { pathOffset, planRolling } from '../src/motion/rolling.js'
import { lockAtLip } from '../src/world/rimSlots.js'
import { type BallWorld } from '../src/world/createWorld.js'
import { hotNextT } from '../src/world/pathHot.js'
import { outsideStep } from '../src/world/system.js'

export function skipOverSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('skipOverSystem', w)
  const P = w.Path
  const RC = w.RimContact
  const H = w.Hole
  const g = w.config.GRAVITY
  const list = w.marked
  for (let i = 0; i < list.count; i++) {
    const eid = list.ids[i]!
    if (P.mark[eid] !== PathEvent.Lip) continue
    const hole = P.markHole[eid]!
    // (δ, v) at the crossing: δ from the path's geometry, v from its closed form at that distance
    const delta = Math.abs(pathOffset(w, eid, hole))
    const v = P.speed[eid]!
    const t = hotNextT(w, eid)
    const rim = lockAtLip(w, eid, hole, delta, v, t, RimMode.Transit)
    if (fliesOver(v, delta, H.radius[hole]!, w.Ball.radius[eid]!, g)) {
      RC.mode[rim] = RimMode.Skipping
      P.mark[eid] = PathEvent.None
      emitHoleEvent(w, EventType.Skip, eid, hole, t)
      planRolling(w, eid)
    }
  }
}
