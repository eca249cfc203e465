// The δ = 0 single-impact estimate (docs/reference-model.md): a closed-form escape test for a ball that flies
// from the near lip to the far lip and meets it once, and the dead-centre capture limit it implies.

import { brentRoot } from './brent.js'
import { BISECTION_STEPS, CAPTURE_SPEED_GRID, SPEED_SCAN_TOP } from './captureSearch.js'
import { FLIGHT_ROOT_TOL } from './tolerances.js'
import { validateReferenceInput } from './types.js'
import { atan2, cos, sin } from '../math.js'

/** time grid for the first contact in the single-impact estimate (units √(r/g)) */
const SINGLE_IMPACT_TIME_STEP = 1 / 256

/**
 * The δ = 0 single-impact estimate (units r = g = 1, ρ = R/r): a ball leaving the near lip at speed v
 * flies to the far lip; at first contact (2ρ − v t)² + (1 − t²/2)² = 1, with β = atan2(−(2ρ − v t), 1 − t²/2)
 * and L = v (cosβ + j) + t sinβ it escapes iff L > 0 and L²/(2(1+j)) ≥ 1 − cosβ. A ball whose centre falls
 * below lip level before touching counts as captured. Returns true for an escape.
 */
export function singleImpactEscapes(vs: number, rs: number, j: number): boolean {
  const h = (t: number): number => {
    const a = 2 * rs - vs * t
    const b = 1 - 0.5 * t * t
    return a * a + b * b - 1
  }
  const tFall = Math.SQRT2 // centre at lip level
  let ta = 0
  let fa = h(0)
  for (let tb = SINGLE_IMPACT_TIME_STEP; ta < tFall; tb += SINGLE_IMPACT_TIME_STEP) {
    const fb = h(tb)
    if (fb <= 0) {
      const t = brentRoot(h, ta, tb, fa, fb, FLIGHT_ROOT_TOL, -1)
      if (t >= tFall) return false
      const beta = atan2(-(2 * rs - vs * t), 1 - 0.5 * t * t)
      const L = vs * (cos(beta) + j) + t * sin(beta)
      return L > 0 && (L * L) / (2 * (1 + j)) >= 1 - cos(beta)
    }
    ta = tb
    fa = fb
  }
  return false
}

/**
 * Dead-centre capture limit from the single-impact estimate (largest captured speed), in the input's units.
 * Scans and bisects like referenceCaptureSpeed. Meaningful when the result exceeds √(g r) (the ball then
 * leaves the near lip at once, as the estimate assumes).
 */
export function singleImpactDeadCentreLimit(holeRadius: number, ballRadius: number, gravity: number, inertia: number): number {
  validateReferenceInput({ delta: 0, speed: 1, holeRadius, ballRadius, gravity, inertia })
  const rs = holeRadius / ballRadius
  const vTop = SPEED_SCAN_TOP * 2 * rs * Math.sqrt(0.5)
  let lo = 0
  for (let i = CAPTURE_SPEED_GRID; i >= 1; i--) {
    const v = (vTop * i) / CAPTURE_SPEED_GRID
    if (!singleImpactEscapes(v, rs, inertia)) {
      lo = v
      break
    }
  }
  let hi = lo + vTop / CAPTURE_SPEED_GRID
  for (let i = 0; i < BISECTION_STEPS; i++) {
    const mid = 0.5 * (lo + hi)
    if (!singleImpactEscapes(mid, rs, inertia)) lo = mid
    else hi = mid
  }
  return lo * Math.sqrt(gravity * ballRadius)
}
