// Stages 2 and 4, rim bounce. The bounce region: contacts that failed capture and the rim-roll gate.
//   n̂ = (ball − hole)/|ball − hole|,  v_n = v·n̂,  v_t = v − v_n·n̂,  v' = (1 − μ_t)·v_t − e·v_n·n̂
// With e = 0.30 a head-on hit loses 1 − e² = 91 % of its normal kinetic energy (Stage 4). The ball leaves
// on a new straight path; the hole stays locked until its centre is back outside the lip circle.
// Reads Path.mark, Ball, Hole; writes Ball, Path, RimContact.mode; emits 'bounce' and 'nearMiss'.
import { PathEvent } from '../components/Path.js'
import { RimMode } from '../components/RimContact.js'
import { EventType } from '../src/events.js'
import { emitHoleEvent } from '../src/motion/ballFate.js'
import { startAt, planRolling, startPath } from '../src/motion/rolling.js'
import { rimBounce } from '../src/geometry.js'
import type { BallWorld } from '../src/world/createWorld.js'
import { hotNextT } from '../src/world/pathHot.js'
import { hypot } from '../src/math.js'
import { outsideStep } from '../src/world/system.js'

/** the bounced velocity, reused for every ball */
const out = new Float64Array(2)

export function bounceSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('bounceSystem', w)
  const P = w.Path
  const RC = w.RimContact
  const H = w.Hole
  const B = w.Ball
  const e = w.config.RIM_RESTITUTION
  const keep = 1 - w.config.RIM_FRICTION
  const list = w.marked
  for (let i = 0; i < list.count; i++) {
    const eid = list.ids[i]!
    if (P.mark[eid] !== PathEvent.Bounce) continue
    P.mark[eid] = PathEvent.None
    const hole = P.markHole[eid]!
    const t = hotNextT(w, eid)
    const x = B.x[eid]!
    const y = B.y[eid]!
    const vx = B.vx[eid]!
    const vy = B.vy[eid]!
    let nx = x - H.x[hole]!
    let ny = y - H.y[hole]!
    const len = hypot(nx, ny)
    if (len > 0) {
      nx /= len
      ny /= len
    } else {
      // centre exactly on the hole centre: no radial direction; take the contact as head-on
      const sp = hypot(vx, vy)
      nx = sp > 0 ? -vx / sp : 1
      ny = sp > 0 ? -vy / sp : 0
    }
    rimBounce(vx, vy, nx, ny, e, keep, out)
    RC.mode[B.rim[eid]!] = RimMode.Transit
    startAt(x, y, out[0]!, out[1]!, t)
    startPath(w, eid)
    P.fromHole[eid] = hole
    planRolling(w, eid)
    emitHoleEvent(w, EventType.Bounce, eid, hole, t)
    emitHoleEvent(w, EventType.NearMiss, eid, hole, t)
  }
}
