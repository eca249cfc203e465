// Sampling a ball on its straight path (src/motion/rolling.ts): its state at a time, or at a distance along
// the path where an event was found, from the path's closed form.
import { speedAtDistance } from '../geometry.js'
import { type BallWorld } from '../world/createWorld.js'
import { HOT, H_T0, H_UX, H_UY, H_V0, H_X0, H_Y0 } from '../world/pathHot.js'

/** The time sampleRollingAt samples at, s, and the distance sampleAtDistance samples at, px (slots: a boxed double otherwise). */
export const sampleTime = new Float64Array(1)
export const sampleDistance = new Float64Array(1)

/** Ball state at time t on its straight path (clamped at its stop). */
export function sampleRolling(w: BallWorld, eid: number, t: number): void {
  sampleTime[0] = t
  sampleRollingAt(w, eid)
}

/** sampleRolling at sampleTime[0]. */
export function sampleRollingAt(w: BallWorld, eid: number): void {
  const t = sampleTime[0]!
  const P = w.Path
  const B = w.Ball
  const H = w.pathHot
  const h = eid * HOT
  const v0 = H[h + H_V0]!
  const decel = w.config.ROLLING_DECEL
  let tau = t - H[h + H_T0]!
  if (tau < 0) tau = 0
  if (decel > 0 && tau * decel > v0) tau = v0 / decel
  const d = v0 * tau - 0.5 * decel * tau * tau
  const v = v0 - decel * tau
  const ux = H[h + H_UX]!
  const uy = H[h + H_UY]!
  B.x[eid] = H[h + H_X0]! + ux * d
  B.y[eid] = H[h + H_Y0]! + uy * d
  B.vx[eid] = ux * v
  B.vy[eid] = uy * v
  P.speed[eid] = v
}

/** Ball state at distance sampleDistance[0] along its straight path: exact geometry for an event found there. */
export function sampleAtDistance(w: BallWorld, eid: number): void {
  const d = sampleDistance[0]!
  const P = w.Path
  const B = w.Ball
  const H = w.pathHot
  const h = eid * HOT
  const v = speedAtDistance(d, H[h + H_V0]!, w.config.ROLLING_DECEL)
  const ux = H[h + H_UX]!
  const uy = H[h + H_UY]!
  B.x[eid] = H[h + H_X0]! + ux * d
  B.y[eid] = H[h + H_Y0]! + uy * d
  B.vx[eid] = ux * v
  B.vy[eid] = uy * v
  P.speed[eid] = v
}
