// Stage 3, rim-around / lip-out. Region 3 of the (δ, v) map, and the mid-speed part of region 2.
//   on the contact circle (radius R − r/2): v_t(τ) = v_t0·e^(−μ_roll·τ),  arc s(τ) = v_t0·(1 − e^(−μ_roll·τ))/μ_roll
//   drop when v_t < RIM_ROLL_DROP_SPEED; pop off when s > RIM_ROLL_MAX_TURNS·2πR, whichever comes first
// A contact the COG gate marked Roll starts rolling: the normal component is spent, the tangential speed
// kept, and the centre rides the contact circle from where the gate took the contact (the design puts it on
// the lip circle, r/2 further out: docs/decisions.md §2). The decay is the exact exponential, so the end times are closed forms and every dt is stable.
// A drop is a capture (via 'rimRoll'); a pop-off leaves along the tangent with the hole locked until the
// centre is outside the lip circle.
// Reads Path.mark, Ball, Hole, RimContact; writes Ball, RimContact, Path; emits 'rimRoll', 'capture', 'lipOut', 'nearMiss'.
import { PathEvent } from '../components/Path.js'
import { CaptureVia, EventType } from '../src/events.js'
import { captureBall, emitHoleEvent } from '../src/motion/ballFate.js'
import { leaveRim, planRimRoll, rollPopsOff, sampleRimRoll, startRimRoll } from '../src/motion/rimRoll.js'
import type { BallWorld } from '../src/world/createWorld.js'
import { hotNextT } from '../src/world/pathHot.js'
import { outsideStep } from '../src/world/system.js'

export function rimRollSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('rimRollSystem', w)
  const P = w.Path
  const B = w.Ball
  const list = w.marked
  for (let i = 0; i < list.count; i++) {
    const eid = list.ids[i]!
    const mark = P.mark[eid]
    if (mark === PathEvent.Roll) {
      P.mark[eid] = PathEvent.None
      const hole = P.markHole[eid]!
      const t = hotNextT(w, eid)
      startRimRoll(w, eid, hole, t)
      sampleRimRoll(w, eid, t)
      planRimRoll(w, eid)
      emitHoleEvent(w, EventType.RimRoll, eid, hole, t)
    } else if (mark === PathEvent.RollEnd) {
      P.mark[eid] = PathEvent.None
      const hole = P.markHole[eid]!
      const t = hotNextT(w, eid)
      if (rollPopsOff(w, eid)) {
        // leave along the tangent; the state at t was set by the integration system
        leaveRim(w, eid, hole, B.vx[eid]!, B.vy[eid]!, t)
      } else {
        captureBall(w, eid, hole, t, CaptureVia.RimRoll)
      }
    }
  }
}
