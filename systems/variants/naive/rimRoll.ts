// Stage 3, rim-around / lip-out, at the tick. A contact marked Roll snaps the centre onto the contact circle
// ρ_c = R − r/2 at the overshot position's angle and keeps the tangential speed there; naiveMove then decays it by
// v·(1 − μ_roll·h) per sub-step. When naiveDetect finds v < RIM_ROLL_DROP_SPEED the ball drops in; when
// it finds the arc past RIM_ROLL_MAX_TURNS·2πR it pops off along the tangent, hole locked until it is out.
// Reads the naive marks, Ball, Hole, RimContact; writes Ball, RimContact, the naive store;
// emits 'rimRoll', 'capture', 'lipOut', 'nearMiss'.
import { BallMode } from '../../../components/Ball.js'
import { PathEvent } from '../../../components/Path.js'
import { RimMode } from '../../../components/RimContact.js'
import { CaptureVia, EventType } from '../../../src/events.js'
import { captureBall, emitHoleEvent } from '../../../src/motion/ballFate.js'
import { startRimRoll } from '../../../src/motion/rimRoll.js'
import { cogRadius } from '../../../src/geometry.js'
import type { BallWorld } from '../../../src/world/createWorld.js'
import { naiveState } from './state.js'
import { setBallMode } from '../../../src/world/ballMode.js'
import { cos, sin } from '../../../src/math.js'
import { outsideStep } from '../../../src/world/system.js'

export function naiveRimRollSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('naiveRimRollSystem', w)
  const st = naiveState(w)
  const S = st.store
  const P = w.Path
  const RC = w.RimContact
  const H = w.Hole
  const B = w.Ball
  const list = st.marked
  for (let i = 0; i < list.count; i++) {
    const eid = list.ids[i]!
    const mark = P.mark[eid]
    const rim = B.rim[eid]!
    if (mark === PathEvent.Roll) {
      P.mark[eid] = PathEvent.None
      const hole = P.markHole[eid]!
      const phi = startRimRoll(w, eid, hole, st.t)
      const R = cogRadius(H.radius[hole]!, B.radius[eid]!)
      RC.angle[rim] = phi
      RC.arc[rim] = 0
      const v = RC.speed0[rim]!
      const dir = RC.direction[rim]!
      S.rollSpeed[eid] = v
      const c = cos(phi)
      const s = sin(phi)
      B.x[eid] = H.x[hole]! + R * c
      B.y[eid] = H.y[hole]! + R * s
      B.vx[eid] = -dir * s * v
      B.vy[eid] = dir * c * v
      emitHoleEvent(w, EventType.RimRoll, eid, hole, st.t)
    } else if (mark === PathEvent.RollEnd) {
      P.mark[eid] = PathEvent.None
      const hole = P.markHole[eid]!
      if (S.rollSpeed[eid]! < w.config.RIM_ROLL_DROP_SPEED) {
        captureBall(w, eid, hole, st.t, CaptureVia.RimRoll)
      } else {
        // leave along the tangent (the velocity naiveMove set), hole locked until the centre is out
        RC.mode[rim] = RimMode.Transit
        setBallMode(w, eid, BallMode.Rolling)
        S.fromHole[eid] = hole
        emitHoleEvent(w, EventType.LipOut, eid, hole, st.t)
        emitHoleEvent(w, EventType.NearMiss, eid, hole, st.t)
      }
    }
  }
}
