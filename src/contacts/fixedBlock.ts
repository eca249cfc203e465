// The fixed-tick squeeze block's arithmetic (src/contacts/fixedSqueeze.ts): the 2 × 2 system of its two
// contacts' impulses, and the tests it asks of the balls (touching, closing on each other, held at rest).
// Inputs and answers pass through slots, not arguments: a double passed to (or returned from) a call V8 does
// not take inline is boxed.
import { PROJECTION_SLOP } from '../config/tolerances.js'
import type { FixedContactState } from '../world/fixedState.js'
import { S_SETTLE, solveSlots } from './fixedPairs.js'

/**
 * The block's inputs to impulses() (the inverse masses of h, the light side and o, σ·c, the cross product,
 * the two contacts' wanted changes r₁, r₂) and a velocity for holds(): slots, since a double passed to a call
 * V8 does not inline is boxed, a heap number an argument a block
 */
export const blk = new Float64Array(9)
export const B_IMH = 0
export const B_IML = 1
export const B_IMO = 2
export const B_SIGMA_C = 3
export const B_CROSS = 4
export const B_R1 = 5
export const B_R2 = 6
export const B_VX = 7
export const B_VY = 8

/**
 * closesFaster's speed, and the speed it must beat (slots: a double returned from a call V8 does not inline,
 * or passed to one, is boxed)
 */
export const closing = new Float64Array(2)

/**
 * Whether candidates h and m close on each other along the line of their centres faster than closing[1]
 * (at least 0): the speed into closing[0].
 */
export function closesFaster(F: FixedContactState, h: number, m: number): boolean {
  const than = closing[1]!
  const dx = F.x[m]! - F.x[h]!
  const dy = F.y[m]! - F.y[h]!
  const d = Math.sqrt(dx * dx + dy * dy)
  const v = ((F.vx[h]! - F.vx[m]!) * dx + (F.vy[h]! - F.vy[m]!) * dy) / d
  closing[0] = v
  return v > than
}

/**
 * The block's impulses (its inputs in blk) into out[0], out[1] (the squeeze's SQ_J1, SQ_J2):
 * (imh + iml)·j₁ + σ·iml·c·j₂ = r₁ and σ·iml·c·j₁ + (iml + imo)·j₂ = r₂ (c = n₁·n₂, σc given). The
 * determinant is written out, 1 − c² as the cross product squared: A·D − B² cancels to the heavy balls'
 * inverse masses, a billionth of the light one's, and lost half the digits of the impulses. False when it
 * is not above 0, or an impulse is not.
 */
export function impulses(out: Float64Array): boolean {
  const imh = blk[B_IMH]!
  const iml = blk[B_IML]!
  const imo = blk[B_IMO]!
  const sigmaC = blk[B_SIGMA_C]!
  const cross = blk[B_CROSS]!
  const r1 = blk[B_R1]!
  const r2 = blk[B_R2]!
  const A = imh + iml
  const B = sigmaC * iml
  const D = iml + imo
  const det = imh * iml + imh * imo + iml * imo + iml * iml * cross * cross
  if (!(det > 0)) return false
  const j1 = (r1 * D - B * r2) / det
  const j2 = (A * r2 - B * r1) / det
  if (!(j1 > 0 && j2 > 0)) return false
  out[0] = j1
  out[1] = j2
  return true
}

/** Whether candidate i is a ball at rest that the velocity in blk[B_VX], blk[B_VY] would leave slower than BALL_SETTLE_SPEED. */
export function holds(F: FixedContactState, i: number): boolean {
  const vx = blk[B_VX]!
  const vy = blk[B_VY]!
  const settle = solveSlots[S_SETTLE]!
  return stillAtRest(F, i) && vx * vx + vy * vy < settle * settle
}

/**
 * Whether candidate i was gathered at rest and the tick has given it no velocity yet. Such a ball that a
 * contact would leave slower than BALL_SETTLE_SPEED stays at rest (src/contacts/fixedApply.ts), so the
 * solve, the wall pair and the guard hold it like a wall: the other ball takes the whole impulse.
 */
export function stillAtRest(F: FixedContactState, i: number): boolean {
  return i >= F.restFrom && F.vx[i] === 0 && F.vy[i] === 0
}

/** Whether candidates i and j touch, within PROJECTION_SLOP (a boolean, not the gap: a returned double is boxed). */
export function touching(F: FixedContactState, i: number, j: number): boolean {
  const dx = F.x[j]! - F.x[i]!
  const dy = F.y[j]! - F.y[i]!
  return Math.sqrt(dx * dx + dy * dy) - F.r[i]! - F.r[j]! <= PROJECTION_SLOP
}
