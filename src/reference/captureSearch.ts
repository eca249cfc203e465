// Searches of the capture boundary with the full model: the capture speed at an offset and the effective hole
// (largest captured offset) at a speed, each a grid scan followed by bisection.

import { simulateScaled } from './sphereLip.js'
import { validateReferenceInput } from './types.js'

/** speed grid points scanned before bisecting the capture boundary (finds the largest captured cell) */
export const CAPTURE_SPEED_GRID = 160
/** offset grid points scanned before bisecting the effective hole edge */
const CAPTURE_OFFSET_GRID = 160
/** bisection steps after the scan: 2⁻⁴⁰ of a grid cell is far below any physical meaning */
export const BISECTION_STEPS = 40
/** the speed scan runs up to this multiple of the free-fall skip speed 2R·√(g/2r): well past any capture */
export const SPEED_SCAN_TOP = 4

function capturedScaled(rs: number, ds: number, vs: number, j: number): boolean {
  return simulateScaled(rs, ds, vs, j, null).captured
}

/**
 * Capture speed v_c(δ): the largest speed that is captured at offset δ. Scans a speed grid up to
 * SPEED_SCAN_TOP times the free-fall skip speed, takes the highest captured grid point and bisects between
 * it and the next one (so a captured window narrower than a grid cell above it can be missed).
 */
export function referenceCaptureSpeed(
  delta: number,
  holeRadius: number,
  ballRadius: number,
  gravity: number,
  inertia: number,
): number {
  validateReferenceInput({ delta, speed: 1, holeRadius, ballRadius, gravity, inertia })
  const rs = holeRadius / ballRadius
  const ds = delta / ballRadius
  const vTop = SPEED_SCAN_TOP * 2 * rs * Math.sqrt(0.5)
  let lo = 0
  for (let i = CAPTURE_SPEED_GRID; i >= 1; i--) {
    const v = (vTop * i) / CAPTURE_SPEED_GRID
    if (capturedScaled(rs, ds, v, inertia)) {
      lo = v
      break
    }
  }
  if (lo === vTop) return Number.POSITIVE_INFINITY // captured at the top of the scan: no finite limit found
  let hi = lo + vTop / CAPTURE_SPEED_GRID
  if (lo === 0) lo = hi * 1e-6 // nothing captured on the grid: bisect the first cell
  for (let i = 0; i < BISECTION_STEPS; i++) {
    const mid = 0.5 * (lo + hi)
    if (capturedScaled(rs, ds, mid, inertia)) lo = mid
    else hi = mid
  }
  return lo * Math.sqrt(gravity * ballRadius)
}

/**
 * Effective hole at a speed: the largest offset δ captured at `speed` (scan of [0, R) and bisection, as
 * for the capture speed). Undefined when no offset on the grid is captured.
 */
export function referenceCaptureOffset(
  speed: number,
  holeRadius: number,
  ballRadius: number,
  gravity: number,
  inertia: number,
): number | undefined {
  validateReferenceInput({ delta: 0, speed, holeRadius, ballRadius, gravity, inertia })
  const rs = holeRadius / ballRadius
  const vs = speed / Math.sqrt(gravity * ballRadius)
  const cell = rs / CAPTURE_OFFSET_GRID
  let lo = -1
  for (let i = CAPTURE_OFFSET_GRID - 1; i >= 0; i--) {
    if (capturedScaled(rs, cell * i, vs, inertia)) {
      lo = cell * i
      break
    }
  }
  if (lo < 0) return undefined
  let hi = lo + cell
  for (let i = 0; i < BISECTION_STEPS; i++) {
    const mid = 0.5 * (lo + hi)
    if (mid >= rs) break
    if (capturedScaled(rs, mid, vs, inertia)) lo = mid
    else hi = mid
  }
  return lo * ballRadius
}
