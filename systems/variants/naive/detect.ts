// Naive event detection: after the move, look at where the tick landed. For each rolling ball,
//   centre inside a lip circle (|x − c| < R)        → a lip crossing, with v and δ taken *there*
//   entering ball inside the contact circle ρ_c     → a rim contact, normal taken there
//   centre back outside its locked hole             → the hole unlocks
//   footprint over a hole (R ≤ |x − c| < R + r)     → near miss, reported when the distance grows again
//   speed ran out                                   → a stop
// and for a ball on the rim, v < RIM_ROLL_DROP_SPEED or arc > RIM_ROLL_MAX_TURNS·2πR → the roll ends.
// δ is the offset of the current velocity line from the hole centre, which a straight path keeps; v is
// the speed at the overshot position, up to v·h past the lip.
// Reads Ball, Hole, RimContact, the naive store; writes RimContact, Path.mark/markHole, the naive marks;
// emits 'nearMiss'.
import { BallMode } from '../../../components/Ball.js'
import { PathEvent } from '../../../components/Path.js'
import { RimMode } from '../../../components/RimContact.js'
import { EventType, pushEvent } from '../../../src/events.js'
import { cogRadius, popArc } from '../../../src/geometry.js'
import { lockAtLip, releaseRim } from '../../../src/world/rimSlots.js'
import { pushId } from '../../../src/world/idLists.js'
import { type BallWorld } from '../../../src/world/createWorld.js'
import { naiveState } from './state.js'
import { hypot } from '../../../src/math.js'
import { outsideStep } from '../../../src/world/system.js'

export function naiveDetectSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('naiveDetectSystem', w)
  const st = naiveState(w)
  const t = st.t
  const S = st.store
  const B = w.Ball
  const P = w.Path
  const RC = w.RimContact
  const cfg = w.config
  const table = w.holes
  const xyr = table.xyr
  const ids = table.ids
  const balls = w.moving.dense
  for (let i = w.moving.count - 1; i >= 0; i--) {
    const eid = balls[i]!
    let rim = B.rim[eid]!
    if (B.mode[eid] === BallMode.RimRoll) {
      const hole = RC.hole[rim]!
      if (S.rollSpeed[eid]! < cfg.RIM_ROLL_DROP_SPEED || RC.arc[rim]! > popArc(cfg.RIM_ROLL_MAX_TURNS, w.Hole.radius[hole]!)) {
        P.mark[eid] = PathEvent.RollEnd
        P.markHole[eid] = hole
        pushId(st.marked, eid)
      }
      continue
    }
    const x = B.x[eid]!
    const y = B.y[eid]!
    const vx = B.vx[eid]!
    const vy = B.vy[eid]!
    const speed = hypot(vx, vy)
    const foot = B.radius[eid]!
    let mark: number = PathEvent.None
    let markHole = 0
    for (let j = 0, n = table.count; j < n; j++) {
      const hid = ids[j]!
      const dx = x - xyr[3 * j]!
      const dy = y - xyr[3 * j + 1]!
      const R = xyr[3 * j + 2]!
      const d2 = dx * dx + dy * dy
      if (hid === RC.hole[rim]) {
        if (d2 >= R * R) {
          releaseRim(w, eid)
          rim = 0
        } else if (RC.mode[rim] === RimMode.Entering) {
          const rc = cogRadius(R, foot)
          if (d2 < rc * rc) {
            mark = PathEvent.Contact
            markHole = hid
          }
        }
        continue
      }
      // a ball not smaller than the hole bridges it
      if (!(foot < R)) continue
      if (d2 < R * R) {
        if (RC.hole[rim] !== 0) continue // inside two lip circles cannot happen (they do not overlap)
        rim = lockAtLip(w, eid, hid, speed > 0 ? Math.abs(dx * vy - dy * vx) / speed : Math.sqrt(d2), speed, t, RimMode.Transit)
        mark = PathEvent.Lip
        markHole = hid
        if (S.nearHole[eid] === hid) S.nearHole[eid] = 0
        continue
      }
      const f = R + foot
      if (d2 < f * f) {
        if (hid === S.nearDone[eid] || hid === S.fromHole[eid]) continue
        const d = Math.sqrt(d2)
        if (S.nearHole[eid] !== hid) {
          if (dx * vx + dy * vy >= 0) continue // moving away: its closest approach is behind it
          S.nearHole[eid] = hid
          S.nearD[eid] = d
          S.nearV[eid] = speed
        } else if (d > S.nearD[eid]!) {
          // the distance grows again: the closest approach was the last sample
          pushEvent(w.events, EventType.NearMiss, eid, hid, t, true, S.nearD[eid]!, S.nearV[eid]!)
          S.nearHole[eid] = 0
          S.nearDone[eid] = hid
        } else {
          S.nearD[eid] = d
          S.nearV[eid] = speed
        }
      } else {
        if (hid === S.nearDone[eid]) S.nearDone[eid] = 0
        if (hid === S.nearHole[eid]) {
          // the footprint left the hole between two samples of a closing distance: report it now
          pushEvent(w.events, EventType.NearMiss, eid, hid, t, true, S.nearD[eid]!, S.nearV[eid]!)
          S.nearHole[eid] = 0
        }
      }
    }
    if (mark === PathEvent.None && S.stopped[eid] === 1) mark = PathEvent.Stop
    if (mark !== PathEvent.None) {
      P.mark[eid] = mark
      P.markHole[eid] = markHole
      pushId(st.marked, eid)
    }
  }
}
