// The design's regime curves in the (δ, v) plane and the closed forms of a ball's motion, as pure
// functions. The systems, the demo overlay, the charts and the tests all call these: one formula, one place.
//
// Notation (docs/design.md §1): R hole radius, r ball radius, δ offset of the ball's straight
// path from the hole centre, v speed when the centre crosses the lip circle (radius R), g gravity.
// Infinity is written 1 / 0, a number literal: the global `Infinity` in a branch V8 has not seen run is a
// generic load, and the double it merges with is boxed at every call (docs/decisions.md §1).
import type { CaptureWindowShape } from './config/design.js'
import { ARG, RESULT, expSlot, expm1Slot, log, log1p, mathSlot } from './math.js'

/**
 * Stage 5 skip speed: v_skip(δ) = R·√(2g/r)·√(1 − δ²/R²). A ball faster than this at the lip flies over
 * the hole (its chord time is shorter than the time to fall by r). 0 for δ ≥ R.
 */
export function vSkip(delta: number, holeRadius: number, ballRadius: number, gravity: number): number {
  const k = 1 - (delta * delta) / (holeRadius * holeRadius)
  return k > 0 ? holeRadius * Math.sqrt((2 * gravity) / ballRadius) * Math.sqrt(k) : 0
}

/** The skip-over rule: a ball crossing the lip at offset delta and speed v flies over (v > v_skip). */
export function fliesOver(v: number, delta: number, holeRadius: number, ballRadius: number, gravity: number): boolean {
  return v > vSkip(delta, holeRadius, ballRadius, gravity)
}

/**
 * Stage 1 capture window (Penner's effective hole), the largest offset captured clean at speed v:
 *   'ellipse' (the design):      δ_eff(v) = R·√(1 − (v/V_MAX)²)
 *   'quadratic' (Penner's fit):  δ_eff(v) = R·√(1 − v/V_MAX), the inverse of v_c(δ) = V_MAX·(1 − δ²/R²)
 * 0 for v ≥ V_MAX (only a dead-centre ball at exactly V_MAX).
 */
export function captureWindow(speed: number, holeRadius: number, vMax: number, shape: CaptureWindowShape): number {
  const q = speed / vMax
  const k = shape === 'quadratic' ? 1 - q : 1 - q * q
  return k > 0 ? holeRadius * Math.sqrt(k) : 0
}

/**
 * The same window read the other way, for overlays and charts: v_c(δ), the largest speed captured clean
 * at offset δ; 'ellipse' V_MAX·√(1 − δ²/R²), 'quadratic' V_MAX·(1 − δ²/R²). 0 for δ ≥ R.
 */
export function captureSpeed(delta: number, holeRadius: number, vMax: number, shape: CaptureWindowShape): number {
  const k = 1 - (delta * delta) / (holeRadius * holeRadius)
  if (!(k > 0)) return 0
  return shape === 'quadratic' ? vMax * k : vMax * Math.sqrt(k)
}

/** Stage 1 test: δ ≤ δ_eff(v), and never above V_MAX. */
export function capturesClean(
  delta: number,
  speed: number,
  holeRadius: number,
  vMax: number,
  shape: CaptureWindowShape,
): boolean {
  return speed <= vMax && delta <= captureWindow(speed, holeRadius, vMax, shape)
}

/**
 * Stage 6 COG gate radius, R − r/2: a rim contact can roll only where more than half the ball is over the
 * hole. The engine also takes rim contacts on this circle (the contact circle, docs/decisions.md §2).
 */
export function cogRadius(holeRadius: number, ballRadius: number): number {
  return holeRadius - ballRadius / 2
}

/**
 * Offset above which a contact on the contact circle (radius ρ_c = R − r/2) is tangential enough to roll:
 * at that circle |v_t|/|v_n| = δ/√(ρ_c² − δ²), which exceeds `ratio` for δ > ρ_c·ratio/√(1 + ratio²).
 */
export function rollRatioDelta(holeRadius: number, ballRadius: number, ratio: number): number {
  return (cogRadius(holeRadius, ballRadius) * ratio) / Math.sqrt(1 + ratio * ratio)
}

/**
 * Region 2 of the lip-out paper, v ≈ √(2gr/(1+j)) / √(Rδ²/(R−r)³ − 1), j the ball's inertia factor
 * (config.BALL_INERTIA). No stage uses it; it is here for charts. Its radicand is negative for δ < (R − r)^{3/2}/√R: there it returns undefined.
 */
export function midRimDropSpeed(
  delta: number,
  holeRadius: number,
  ballRadius: number,
  gravity: number,
  inertia: number,
): number | undefined {
  const gap = holeRadius - ballRadius
  const radicand = (holeRadius * delta * delta) / (gap * gap * gap) - 1
  if (!(gap > 0) || !(radicand > 0)) return undefined
  return Math.sqrt((2 * gravity * ballRadius) / (1 + inertia)) / Math.sqrt(radicand)
}

// ---- straight rolling with constant deceleration a: s(τ) = v0·τ − a·τ²/2 until v0/a ----

/** Distance rolled before stopping (Infinity when a = 0 and the ball moves). */
export function stopDistance(v0: number, decel: number): number {
  if (v0 <= 0) return 0
  return decel > 0 ? (v0 * v0) / (2 * decel) : 1 / 0
}

/** Time to stop (Infinity when a = 0 and the ball moves). */
export function stopTime(v0: number, decel: number): number {
  if (v0 <= 0) return 0
  return decel > 0 ? v0 / decel : 1 / 0
}

/**
 * Earliest τ ≥ 0 at which the ball has rolled distance d, or Infinity if it stops first. Written as
 * 2d/(v0 + √(v0² − 2ad)) so that it stays accurate when a·d ≪ v0² (no cancellation).
 */
export function timeToDistance(d: number, v0: number, decel: number): number {
  if (d <= 0) return 0
  const disc = v0 * v0 - 2 * decel * d
  if (disc < 0) return 1 / 0
  const denom = v0 + Math.sqrt(disc)
  return denom > 0 ? (2 * d) / denom : 1 / 0
}

/** Speed after rolling distance d (0 past the stop). */
export function speedAtDistance(d: number, v0: number, decel: number): number {
  const disc = v0 * v0 - 2 * decel * d
  return disc > 0 ? Math.sqrt(disc) : 0
}

// ---- rim roll: v_t(τ) = v_t0·e^(−μτ), arc s(τ) = v_t0·(1 − e^(−μτ))/μ (exact for every dt) ----

/** Arc length rolled on the rim after τ seconds. */
export function rollArc(tau: number, vt0: number, friction: number): number {
  if (!(friction > 0)) return vt0 * tau
  // expm1 through its slot (src/motion/rimRoll.ts's rimRollAt writes this and rollSpeed out, term for term,
  // for the sample at every step's end: keep the two the same)
  mathSlot[ARG] = -friction * tau
  expm1Slot()
  return (vt0 * -mathSlot[RESULT]!) / friction
}

/** Rim-roll speed after τ seconds. */
export function rollSpeed(tau: number, vt0: number, friction: number): number {
  mathSlot[ARG] = -friction * tau
  expSlot()
  return vt0 * mathSlot[RESULT]!
}

/** Time for the rim-roll speed to fall to the drop speed (0 if it starts below; Infinity if μ = 0). */
export function rollDropTime(vt0: number, friction: number, dropSpeed: number): number {
  if (vt0 <= dropSpeed) return 0
  return friction > 0 ? log(vt0 / dropSpeed) / friction : 1 / 0
}

/** Time to roll an arc of length `arc`, or Infinity if the decaying speed never covers it. */
export function rollPopTime(vt0: number, friction: number, arc: number): number {
  if (vt0 <= 0) return 1 / 0
  if (!(friction > 0)) return arc / vt0
  const q = (friction * arc) / vt0
  return q < 1 ? -log1p(-q) / friction : 1 / 0
}

/**
 * Arc length of the pop-off threshold: RIM_ROLL_MAX_TURNS turns of the lip circle (radius R). The arc is the
 * distance the ball rolls; its centre rides the smaller contact circle, so it turns through more angle.
 */
export function popArc(maxTurns: number, holeRadius: number): number {
  return maxTurns * 2 * Math.PI * holeRadius
}

// ---- rim bounce (Stages 2 and 4) ----

/**
 * The rim bounce law for a unit normal n̂ (from the hole centre to the ball): v_n = v·n̂, v_t = v − v_n·n̂,
 * v' = keep·v_t − e·v_n·n̂ with keep = 1 − μ_t. Writes v' into out[0], out[1] (no allocation).
 */
export function rimBounce(vx: number, vy: number, nx: number, ny: number, e: number, keep: number, out: Float64Array): void {
  const vn = vx * nx + vy * ny
  const tx = vx - vn * nx
  const ty = vy - vn * ny
  out[0] = keep * tx - e * vn * nx
  out[1] = keep * ty - e * vn * ny
}
