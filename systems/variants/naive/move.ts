// Naive motion, as a tick-sampled port would write it: explicit Euler with the rolling deceleration,
//   x ← x + v·h,  |v| ← |v| − a·h  (stopped at 0)
// and on the rim, the exponential decay replaced by its first-order step,
//   arc ← arc + v·h,  φ ← φ ± v·h/ρ_c,  v ← v·(1 − μ_roll·h)    (negative for h > 1/μ_roll; ρ_c = R − r/2)
// No event is found in time: whatever happened inside the sub-step is seen at its end (naiveDetect).
// Reads Ball, RimContact, Hole, the naive store; writes Ball, RimContact (angle, arc), the naive store.
import { BallMode } from '../../../components/Ball.js'
import { cogRadius } from '../../../src/geometry.js'
import type { BallWorld } from '../../../src/world/createWorld.js'
import { naiveState } from './state.js'
import { cos, hypot, sin } from '../../../src/math.js'
import { outsideStep } from '../../../src/world/system.js'

/** One first-order step of the rim-roll decay: v·(1 − μ·h). Exported for the stability tests. */
export function naiveRollDecay(v: number, friction: number, h: number): number {
  return v * (1 - friction * h)
}

export function naiveMoveSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('naiveMoveSystem', w)
  const st = naiveState(w)
  const h = st.h
  const S = st.store
  const B = w.Ball
  const RC = w.RimContact
  const H = w.Hole
  const decel = w.config.ROLLING_DECEL
  const mu = w.config.RIM_ROLL_FRICTION
  const balls = w.moving.dense
  for (let i = w.moving.count - 1; i >= 0; i--) {
    const eid = balls[i]!
    const vx = B.vx[eid]!
    const vy = B.vy[eid]!
    if (B.mode[eid] === BallMode.RimRoll) {
      const rim = B.rim[eid]!
      const hole = RC.hole[rim]!
      const R = cogRadius(H.radius[hole]!, B.radius[eid]!)
      const v = S.rollSpeed[eid]!
      const dir = RC.direction[rim]!
      RC.arc[rim] = RC.arc[rim]! + v * h
      const phi = RC.angle[rim]! + (dir * v * h) / R
      RC.angle[rim] = phi
      const vNew = naiveRollDecay(v, mu, h)
      S.rollSpeed[eid] = vNew
      const c = cos(phi)
      const s = sin(phi)
      B.x[eid] = H.x[hole]! + R * c
      B.y[eid] = H.y[hole]! + R * s
      B.vx[eid] = -dir * s * vNew
      B.vy[eid] = dir * c * vNew
      continue
    }
    B.x[eid] = B.x[eid]! + vx * h
    B.y[eid] = B.y[eid]! + vy * h
    const speed = hypot(vx, vy)
    const next = speed - decel * h
    if (next > 0) {
      const k = next / speed
      B.vx[eid] = vx * k
      B.vy[eid] = vy * k
      S.stopped[eid] = 0
    } else {
      B.vx[eid] = 0
      B.vy[eid] = 0
      S.stopped[eid] = 1
    }
  }
}
