// v1, the rule the design replaced (docs/design.md §2): at each tick, a ball whose centre is
// inside a lip circle with speed below V1_SPEED_LIMIT = V_MAX (the speed at which the Stage 1 window closes,
// the design's own "low enough") is captured. Nothing else: no skip, no rim contact, no bounce or roll, no
// near miss. A ball whose speed ran out rests (or falls in, by the same rule, if its centre is inside).
// Reads Ball, Hole, the naive store; writes Ball, RimContact (δ, v of the capture); emits 'capture', 'rest'.
import { BallMode } from '../../../components/Ball.js'
import { RimMode } from '../../../components/RimContact.js'
import { CaptureVia } from '../../../src/events.js'
import { captureBall, restBall } from '../../../src/motion/ballFate.js'
import { lockAtLip } from '../../../src/world/rimSlots.js'
import { type BallWorld } from '../../../src/world/createWorld.js'
import { naiveState } from './state.js'
import { hypot } from '../../../src/math.js'
import { outsideStep } from '../../../src/world/system.js'

export function v1CaptureSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('v1CaptureSystem', w)
  const st = naiveState(w)
  const S = st.store
  const B = w.Ball
  const limit = w.config.V_MAX
  const table = w.holes
  const xyr = table.xyr
  const balls = w.moving.dense
  for (let i = w.moving.count - 1; i >= 0; i--) {
    const eid = balls[i]!
    if (B.mode[eid] !== BallMode.Rolling) continue
    const x = B.x[eid]!
    const y = B.y[eid]!
    const vx = B.vx[eid]!
    const vy = B.vy[eid]!
    const speed = hypot(vx, vy)
    let captured = false
    if (speed < limit) {
      for (let j = 0, n = table.count; j < n; j++) {
        const dx = x - xyr[3 * j]!
        const dy = y - xyr[3 * j + 1]!
        const R = xyr[3 * j + 2]!
        const d2 = dx * dx + dy * dy
        // a ball not smaller than the hole bridges it
        if (d2 >= R * R || !(B.radius[eid]! < R)) continue
        const hole = table.ids[j]!
        lockAtLip(w, eid, hole, speed > 0 ? Math.abs(dx * vy - dy * vx) / speed : Math.sqrt(d2), speed, st.t, RimMode.None)
        captureBall(w, eid, hole, st.t, speed > 0 ? CaptureVia.Clean : CaptureVia.Rest)
        captured = true
        break
      }
    }
    if (!captured && S.stopped[eid] === 1) restBall(w, eid, st.t)
  }
}
