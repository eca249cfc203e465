// Stage 1, capture (Penner's effective hole). Region 4 of the (δ, v) map, and the low-speed part of 2.
//   δ ≤ δ_eff(v) = R·√(1 − (v/V_MAX)²)   (CAPTURE_WINDOW 'quadratic': R·√(1 − v/V_MAX), docs/physical.md)
// At the exact lip crossing (not skipped), a ball inside the speed-shrinking window drops in clean.
// Also decides every stop: a ball whose speed runs out with its centre inside a lip circle falls in
// (via 'rest'); one that stops elsewhere rests on the panel, whatever its footprint covers (the v1
// "covering capture" failure is fixed by testing the centre, not the footprint).
// Reads Path.mark, RimContact (δ, v), Hole; writes Ball, RimContact, Path.mark; emits 'capture', 'rest'.
import { PathEvent } from '../components/Path.js'
import { CaptureVia } from '../src/events.js'
import { capturesClean } from '../src/geometry.js'
import { captureBall, restBall } from '../src/motion/ballFate.js'
import type { BallWorld } from '../src/world/createWorld.js'
import { hotNextT } from '../src/world/pathHot.js'
import { outsideStep } from '../src/world/system.js'

export function captureSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('captureSystem', w)
  const P = w.Path
  const RC = w.RimContact
  const vMax = w.config.V_MAX
  const shape = w.config.CAPTURE_WINDOW
  const list = w.marked
  for (let i = 0; i < list.count; i++) {
    const eid = list.ids[i]!
    const mark = P.mark[eid]
    const rim = w.Ball.rim[eid]!
    if (mark === PathEvent.Lip) {
      const hole = P.markHole[eid]!
      if (capturesClean(RC.delta[rim]!, RC.speed[rim]!, w.Hole.radius[hole]!, vMax, shape)) {
        P.mark[eid] = PathEvent.None
        captureBall(w, eid, hole, hotNextT(w, eid), CaptureVia.Clean)
      }
    } else if (mark === PathEvent.Stop) {
      P.mark[eid] = PathEvent.None
      const hole = RC.hole[rim]!
      if (hole !== 0) captureBall(w, eid, hole, hotNextT(w, eid), CaptureVia.Rest)
      else restBall(w, eid, hotNextT(w, eid))
    }
  }
}
