// Stage 6, COG gate (with Stage 3's entry test). Region 3's boundary against the bounce region.
//   the path reaches the contact circle ρ_c = R − r/2  ⇔  δ < R − r/2      (COG gate)
//   at that circle, roll iff |v_t| / |v_n| > RIM_ROLL_RATIO                 (Stage 3 entry)
// A ball that crossed the lip and was neither skipped nor captured touches the rim. A tangential brush
// (δ ≥ R − r/2: most of the ball stays outside) is bounced at the lip crossing and deflects out. Otherwise
// the ball goes on to the contact circle, where the contact is taken (docs/decisions.md §2: there the ball is
// substantially over the hole, so both the gate and the roll test can hold), and the velocity split at
// that point decides: roll on the rim, or bounce.
// Reads Path, RimContact, Hole, Ball; writes RimContact.mode, Path.mark (Bounce or Roll for the next systems).
import { PathEvent } from '../components/Path.js'
import { RimMode } from '../components/RimContact.js'
import { cogRadius } from '../src/geometry.js'
import { planRolling } from '../src/motion/rolling.js'
import type { BallWorld } from '../src/world/createWorld.js'
import { outsideStep } from '../src/world/system.js'

export function cogGateSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('cogGateSystem', w)
  const P = w.Path
  const RC = w.RimContact
  const H = w.Hole
  const B = w.Ball
  const ratio = w.config.RIM_ROLL_RATIO
  const list = w.marked
  for (let i = 0; i < list.count; i++) {
    const eid = list.ids[i]!
    const mark = P.mark[eid]
    if (mark === PathEvent.Lip) {
      const hole = P.markHole[eid]!
      const rim = B.rim[eid]!
      if (RC.delta[rim]! < cogRadius(H.radius[hole]!, B.radius[eid]!)) {
        RC.mode[rim] = RimMode.Entering
        P.mark[eid] = PathEvent.None
        planRolling(w, eid)
      } else {
        P.mark[eid] = PathEvent.Bounce
      }
    } else if (mark === PathEvent.Contact) {
      const hole = P.markHole[eid]!
      const nx = B.x[eid]! - H.x[hole]!
      const ny = B.y[eid]! - H.y[hole]!
      const vx = B.vx[eid]!
      const vy = B.vy[eid]!
      // |v_t| / |v_n| > ratio, written without dividing: |v × n| > ratio·|v · n|
      const vn = vx * nx + vy * ny
      const vt = vx * ny - vy * nx
      P.mark[eid] = Math.abs(vt) > ratio * Math.abs(vn) ? PathEvent.Roll : PathEvent.Bounce
    }
  }
}
