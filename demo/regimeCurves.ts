// The regime map's curves in the (δ, v) plane for a config, as plain points: what the demo's overlay draws.
// They come from the same functions, with the same config, that the systems decide with (a test checks the
// capture curve against the engine itself).
import { captureWindow, cogRadius, rollRatioDelta, tabulatedCaptureSpeed, vSkip, type BallPhysicsConfig } from '../src/index'

export interface RegimePoint {
  /** δ, px */
  delta: number
  /** v, px/s */
  speed: number
}

export interface RegimeCurves {
  /** v_skip(δ) for δ from 0 to R */
  skip: RegimePoint[]
  /**
   * the capture window δ_eff(v) for v from 0 to min(V_MAX, vTop); under RIM_MODEL 'tabulated', the table's
   * capture speed v_c(δ) for δ from R down to 0 (capped at vTop)
   */
  window: RegimePoint[]
  /** the COG gate's offset R − r/2 */
  cog: number
  /** the offset above which a contact is tangential enough to roll */
  roll: number
}

/** The curves for `config`, each sampled at n + 1 points; v above vTop is not drawn. */
export function regimeCurves(c: Readonly<BallPhysicsConfig>, n: number, vTop: number): RegimeCurves {
  const R = c.HOLE_RADIUS
  const r = c.BALL_RADIUS
  const skip: RegimePoint[] = []
  const window: RegimePoint[] = []
  const tabulated = c.RIM_MODEL === 'tabulated' && r < R
  for (let i = 0; i <= n; i++) {
    const d = (i / n) * R
    skip.push({ delta: d, speed: vSkip(d, R, r, c.GRAVITY) })
    if (tabulated) {
      // the reference's capture speed per offset, as the table decides (every capture, clean or after a roll)
      const dd = ((n - i) / n) * R * (1 - 1e-9)
      window.push({ delta: dd, speed: Math.min(vTop, tabulatedCaptureSpeed(dd, R, r, c.GRAVITY, c.BALL_INERTIA)) })
      continue
    }
    const v = Math.min(c.V_MAX, vTop) * (i / n)
    window.push({ delta: Math.min(R, captureWindow(v, R, c.V_MAX, c.CAPTURE_WINDOW)), speed: v })
  }
  return { skip, window, cog: cogRadius(R, r), roll: rollRatioDelta(R, r, c.RIM_ROLL_RATIO) }
}
