// Stage 6, COG gate (with Stage 3's entry test), decided at the tick. A lip crossing with δ ≥ R − r/2 is a
// brush and bounces; otherwise the ball heads for the contact circle ρ_c = R − r/2, and the first tick
// that finds it inside (this one, if it already is) takes the contact with the normal at that position:
//   roll iff |v_t| / |v_n| > RIM_ROLL_RATIO.
// Reads the naive marks, Ball, Hole, RimContact; writes RimContact.mode, Path.mark (Bounce or Roll).
import { PathEvent } from '../../../components/Path.js'
import { RimMode } from '../../../components/RimContact.js'
import { cogRadius } from '../../../src/geometry.js'
import type { BallWorld } from '../../../src/world/createWorld.js'
import { naiveState } from './state.js'
import { outsideStep } from '../../../src/world/system.js'

export function naiveCogGateSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('naiveCogGateSystem', w)
  const st = naiveState(w)
  const P = w.Path
  const RC = w.RimContact
  const H = w.Hole
  const B = w.Ball
  const ratio = w.config.RIM_ROLL_RATIO
  const list = st.marked
  for (let i = 0; i < list.count; i++) {
    const eid = list.ids[i]!
    let mark = P.mark[eid]
    const hole = P.markHole[eid]!
    const rim = B.rim[eid]!
    const nx = B.x[eid]! - H.x[hole]!
    const ny = B.y[eid]! - H.y[hole]!
    if (mark === PathEvent.Lip) {
      const rc = cogRadius(H.radius[hole]!, B.radius[eid]!)
      if (RC.delta[rim]! >= rc) {
        P.mark[eid] = PathEvent.Bounce
        continue
      }
      RC.mode[rim] = RimMode.Entering
      P.mark[eid] = PathEvent.None
      if (nx * nx + ny * ny >= rc * rc) continue
      mark = PathEvent.Contact
    }
    if (mark === PathEvent.Contact) {
      const vx = B.vx[eid]!
      const vy = B.vy[eid]!
      const vn = vx * nx + vy * ny
      const vt = vx * ny - vy * nx
      P.mark[eid] = Math.abs(vt) > ratio * Math.abs(vn) ? PathEvent.Roll : PathEvent.Bounce
    }
  }
}
