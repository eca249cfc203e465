// Stage 1, capture, decided at the tick: δ ≤ δ_eff(v) with v the speed at the overshot position; and a
// ball whose speed ran out in this sub-step falls in if its centre is inside a lip circle, else rests.
// Reads the naive marks, RimContact (δ, v); writes Ball, RimContact, Path.mark; emits 'capture', 'rest'.
import { PathEvent } from '../../../components/Path.js'
import { CaptureVia } from '../../../src/events.js'
import { capturesClean } from '../../../src/geometry.js'
import { captureBall, restBall } from '../../../src/motion/ballFate.js'
import type { BallWorld } from '../../../src/world/createWorld.js'
import { naiveState } from './state.js'
import { outsideStep } from '../../../src/world/system.js'

export function naiveCaptureSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('naiveCaptureSystem', w)
  const st = naiveState(w)
  const P = w.Path
  const RC = w.RimContact
  const vMax = w.config.V_MAX
  const list = st.marked
  for (let i = 0; i < list.count; i++) {
    const eid = list.ids[i]!
    const mark = P.mark[eid]
    const rim = w.Ball.rim[eid]!
    if (mark === PathEvent.Lip) {
      const hole = P.markHole[eid]!
      if (capturesClean(RC.delta[rim]!, RC.speed[rim]!, w.Hole.radius[hole]!, vMax, w.config.CAPTURE_WINDOW)) {
        P.mark[eid] = PathEvent.None
        captureBall(w, eid, hole, st.t, CaptureVia.Clean)
      }
    } else if (mark === PathEvent.Stop) {
      P.mark[eid] = PathEvent.None
      const hole = RC.hole[rim]!
      if (hole !== 0) captureBall(w, eid, hole, st.t, CaptureVia.Rest)
      else restBall(w, eid, st.t)
    }
  }
}
