// Stages 2 and 4, rim bounce, at the tick: the normal is taken at the overshot position,
//   n̂ = (ball − hole)/|ball − hole|,  v' = (1 − μ_t)·v_t − e·(v·n̂)·n̂
// with no guard for a centre on the hole centre (|ball − hole| = 0), as a direct port writes it.
// The hole stays locked until the centre is outside its lip circle.
// Reads the naive marks, Ball, Hole; writes Ball, RimContact.mode, the naive store; emits 'bounce', 'nearMiss'.
import { PathEvent } from '../../../components/Path.js'
import { RimMode } from '../../../components/RimContact.js'
import { EventType } from '../../../src/events.js'
import { emitHoleEvent } from '../../../src/motion/ballFate.js'
import { rimBounce } from '../../../src/geometry.js'
import type { BallWorld } from '../../../src/world/createWorld.js'
import { naiveState } from './state.js'
import { hypot } from '../../../src/math.js'
import { outsideStep } from '../../../src/world/system.js'

/** the bounced velocity, reused for every ball */
const out = new Float64Array(2)

export function naiveBounceSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('naiveBounceSystem', w)
  const st = naiveState(w)
  const P = w.Path
  const RC = w.RimContact
  const H = w.Hole
  const B = w.Ball
  const e = w.config.RIM_RESTITUTION
  const keep = 1 - w.config.RIM_FRICTION
  const list = st.marked
  for (let i = 0; i < list.count; i++) {
    const eid = list.ids[i]!
    if (P.mark[eid] !== PathEvent.Bounce) continue
    P.mark[eid] = PathEvent.None
    const hole = P.markHole[eid]!
    let nx = B.x[eid]! - H.x[hole]!
    let ny = B.y[eid]! - H.y[hole]!
    const len = hypot(nx, ny)
    nx /= len
    ny /= len
    const vx = B.vx[eid]!
    const vy = B.vy[eid]!
    rimBounce(vx, vy, nx, ny, e, keep, out)
    B.vx[eid] = out[0]!
    B.vy[eid] = out[1]!
    RC.mode[B.rim[eid]!] = RimMode.Transit
    st.store.fromHole[eid] = hole
    emitHoleEvent(w, EventType.Bounce, eid, hole, st.t)
    emitHoleEvent(w, EventType.NearMiss, eid, hole, st.t)
  }
}
