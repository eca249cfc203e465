// The v1 rule, as a system, for measuring it on the same engine as the design (docs/physical.md):
//   capture iff the centre crosses the lip and v < V_MAX; otherwise the hole is not there.
// Put it ahead of skipOver and it handles every lip crossing, so the six stages never see one. It exists
// to chart the v1 model's fidelity and cost; no game should use it.
// Reads Path, Hole; writes RimContact, Path.mark; emits 'capture'.
import { PathEvent } from '../../components/Path.js'
import { RimMode } from '../../components/RimContact.js'
import { CaptureVia } from '../../src/events.js'
import { captureBall } from '../../src/motion/ballFate.js'
import { planRolling } from '../../src/motion/rolling.js'
import { lockAtLip } from '../../src/world/rimSlots.js'
import { type BallWorld } from '../../src/world/createWorld.js'
import { HOT, H_NEXT_T, H_UX, H_UY, H_X0, H_Y0 } from '../../src/world/pathHot.js'
import { outsideStep } from '../../src/world/system.js'

export function v1RuleSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('v1RuleSystem', w)
  const P = w.Path
  const RC = w.RimContact
  const H = w.Hole
  const vMax = w.config.V_MAX
  const list = w.marked
  for (let i = 0; i < list.count; i++) {
    const eid = list.ids[i]!
    if (P.mark[eid] !== PathEvent.Lip) continue
    const hole = P.markHole[eid]!
    const t = w.pathHot[eid * HOT + H_NEXT_T]!
    const delta = Math.abs((H.x[hole]! - w.pathHot[eid * HOT + H_X0]!) * w.pathHot[eid * HOT + H_UY]! - (H.y[hole]! - w.pathHot[eid * HOT + H_Y0]!) * w.pathHot[eid * HOT + H_UX]!)
    const rim = lockAtLip(w, eid, hole, delta, P.speed[eid]!, t, RimMode.None)
    P.mark[eid] = PathEvent.None
    if (P.speed[eid]! < vMax) {
      captureBall(w, eid, hole, t, CaptureVia.Clean)
    } else {
      RC.mode[rim] = RimMode.Transit
      planRolling(w, eid)
    }
  }
}
