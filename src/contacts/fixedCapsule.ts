// Fixed-tick contacts: widening along a ball's path (src/contacts/fixedReach.ts). The velocity solve only
// acts on two balls that meet on straight lines within the tick (src/contacts/fixedSolve.ts), so a ball the
// solve sped up far beyond its size can only meet the balls along its line, the capsule of its radius swept
// by its velocity over the tick. Widened by its whole travel in every direction instead, a radius-0.5 ball
// at 1e5 px/s is paired with every ball within 833 px: in rows of tiny balls side by side, thousands of
// pairs a ball and a round, and the rounds' bounds stop the push halfway along a row. So a ball that would
// move more than CAPSULE_TRAVEL radii in the tick, with a circle wider than CAPSULE_CELLS of the tick's
// cells (among balls about as fast a capsule saves nothing), is widened to that capsule (once a tick; a
// second widening in a new direction widens its circle as before). A new capsule is cut at the first ball
// it meets (src/contacts/fixedCut.ts) and lengthened to the whole path in a later round if the ball goes
// on past the cut along it (extendAlong). What a candidate covers is then its
// reach circle and, this tick, its capsule; a pair is listed once, when the two covers first meet,
// whichever way round they are found: a widened ball with a capsule looks up the candidates where they
// can be (the grids' cells of its cover, the big ones, those the widening added, the list of balls with
// a capsule), a widened ball without one is tested against that list, and the other pairs are found as
// before, through the grids.
import { CAPSULE_CELLS, CAPSULE_TRAVEL, PROJECTION_SLOP, TOUCH_GAP } from '../config/tolerances.js'
import { grown } from '../world/contactState.js'
import type { FixedContactState } from '../world/fixedState.js'

/**
 * Per candidate: its path's sweep (velocity × tick) when its capsule was made, the share of it the capsule
 * covers now (cut at the first ball it can meet) and before the round that last lengthened it, the round
 * that made it and the round that last lengthened it; the tick's balls with one.
 */
let fullX = new Float64Array(64)
let fullY = new Float64Array(64)
let capS = new Float64Array(64)
let preS = new Float64Array(64)
let capAt = new Float64Array(64)
let extAt = new Float64Array(64)
let holders = new Int32Array(64)
let holderCount = 0
/** widening rounds counted over all ticks (so no stamp needs clearing); the tick's first */
let round = 0
let tickFrom = 1

/**
 * A circle given to meetsCircle (not a candidate: a ball not packed, a resting ball): centre and radius in
 * slots (V8 boxes a double passed to a call it does not inline).
 */
export const circle = new Float64Array(3)

/**
 * A widening round's reaches (src/contacts/fixedReach.ts): [0] a small ball's, the larger of half the cell
 * and [2]; [1] the round's widest new reach; [2] the widest reach any round of the try has widened a ball to
 * (a ball widened in an earlier round reaches that far: bounded by the round's own widest, a ball sped up
 * later missed a neighbour sped up before, 4.76 px away with reaches of 2.29 and 3.72 px, and the two passed
 * through each other before the next tick). Slots, not arguments or returned values: V8 boxes a double
 * passed to or returned from a call it does not inline (a heap number a round, and one a widened ball).
 */
export const roundReach = new Float64Array(3)

/** A new contact tick: no ball has a capsule. */
export function beginWidening(): void {
  roundReach[2] = 0
  tickFrom = round + 1
  holderCount = 0
  cutCount = 0
}

/** A new widening round (room for n candidates). */
export function nextRound(n: number): void {
  round++
  reserve(n)
}

/**
 * The packed candidates were renumbered (src/contacts/fixedOrder.ts, unpackedJoin): the first `old` moved
 * to moved[i] (in order), the rest of the `total` slots are balls joining, without a capsule.
 */
export function renumberCapsules(moved: Int32Array, old: number, total: number): void {
  if (holderCount === 0) return
  reserve(total)
  let next = total
  for (let i = old - 1; i >= 0; i--) {
    const o = moved[i]!
    for (let k = o + 1; k < next; k++) capAt[k] = 0
    fullX[o] = fullX[i]!
    fullY[o] = fullY[i]!
    capS[o] = capS[i]!
    preS[o] = preS[i]!
    capAt[o] = capAt[i]!
    extAt[o] = extAt[i]!
    next = o
  }
  for (let k = 0; k < next; k++) capAt[k] = 0
  for (let h = 0; h < holderCount; h++) holders[h] = moved[holders[h]!]!
}

function reserve(n: number): void {
  if (capAt.length < n) {
    let len = capAt.length
    while (len < n) len *= 2
    fullX = grown(fullX, len)
    fullY = grown(fullY, len)
    capS = grown(capS, len)
    preS = grown(preS, len)
    capAt = grown(capAt, len)
    extAt = grown(extAt, len)
    holders = grown(holders, len)
  }
}

/** Whether candidate i has a capsule this tick. */
export function hasCapsule(i: number): boolean {
  return i < capAt.length && capAt[i]! >= tickFrom
}

/** Whether candidate i had a capsule before this round. */
function hadCapsule(i: number): boolean {
  return i < capAt.length && capAt[i]! >= tickFrom && capAt[i]! < round
}

export function holderList(): Int32Array {
  return holders
}

export function holdersNow(): number {
  return holderCount
}

/** The share of its path candidate i's capsule covers (now, or as it was before this round). */
function shareOf(i: number, now: boolean): number {
  return !now && extAt[i] === round ? preS[i]! : capS[i]!
}

/**
 * Whether candidate i's sweep at its present velocity lies within its capsule (to the projection's slop),
 * if it has one: the same start and radius, so it does when the sweep's end does.
 */
export function withinCapsule(F: FixedContactState, i: number): boolean {
  if (!hasCapsule(i)) return false
  return axisFrom2(i, capS[i]!, F.vx[i]! * F.tick, F.vy[i]! * F.tick) <= PROJECTION_SLOP * PROJECTION_SLOP
}

/**
 * Lengthens candidate i's capsule to its whole path if it was cut (src/contacts/fixedCut.ts) short of
 * where the ball goes now: its sweep's end beyond the capsule but on the path (to the projection's slop).
 */
export function extendAlong(F: FixedContactState, i: number): boolean {
  if (!hasCapsule(i) || !(capS[i]! < 1)) return false
  const sx = F.vx[i]! * F.tick
  const sy = F.vy[i]! * F.tick
  const slop2 = PROJECTION_SLOP * PROJECTION_SLOP
  if (axisFrom2(i, capS[i]!, sx, sy) <= slop2 || axisFrom2(i, 1, sx, sy) > slop2) return false
  preS[i] = capS[i]!
  capS[i] = 1
  extAt[i] = round
  return true
}

/** Whether candidate i's capsule was made this round (whole, until it is cut). */
export function madeNow(i: number): boolean {
  return hasCapsule(i) && capAt[i] === round
}

/**
 * Where along candidate i's path (a share of its sweep, 0 at its centre, 1 at the sweep's end) the point
 * (px, py) lies, projected on it (for the cut).
 */
export function shareAlong(F: FixedContactState, i: number, px: number, py: number): number {
  const ux = fullX[i]!
  const uy = fullY[i]!
  const uu = ux * ux + uy * uy
  return uu > 0 ? ((px - F.x[i]!) * ux + (py - F.y[i]!) * uy) / uu : 0
}

/** The length of candidate i's path (its sweep when the capsule was made). */
export function pathLength(i: number): number {
  return Math.sqrt(fullX[i]! * fullX[i]! + fullY[i]! * fullY[i]!)
}

/**
 * The box of shares a to b of candidate i's path with the capsule's radius, grown by `extra` on every
 * side, into bounds (as coverBounds).
 */
export function segmentBounds(F: FixedContactState, i: number, a: number, b: number, extra: number): void {
  const c = F.r[i]! + TOUCH_GAP + extra
  const x0 = F.x[i]! + fullX[i]! * a
  const y0 = F.y[i]! + fullY[i]! * a
  const x1 = F.x[i]! + fullX[i]! * b
  const y1 = F.y[i]! + fullY[i]! * b
  bounds[0] = Math.min(x0, x1) - c
  bounds[1] = Math.max(x0, x1) + c
  bounds[2] = Math.min(y0, y1) - c
  bounds[3] = Math.max(y0, y1) + c
}

/** Cuts candidate i's capsule at share s of its path (listed for the next round: src/contacts/fixedRounds.ts). */
export function cutAt(i: number, s: number): void {
  capS[i] = s
  if (cutCount === cuts.length) cuts = grown(cuts, 2 * cutCount)
  cuts[cutCount++] = i
}

/** The candidates whose capsules were cut since the list was last taken (takeCuts), in the order they were. */
let cuts = new Int32Array(64)
let cutCount = 0

/** The cut list and its count; the list is emptied (its contents stay readable until the next cut). */
export function takeCuts(): number {
  const n = cutCount
  cutCount = 0
  return n
}

export function cutList(): Int32Array {
  return cuts
}

/** The number of cuts listed and not yet taken. */
export function cutsNow(): number {
  return cutCount
}

/**
 * Widens candidate i, which outgrows its reach, along its path if it would move more than CAPSULE_TRAVEL
 * radii in the tick and has no capsule yet (true; its reach circle stays); false when its circle is to be
 * widened instead.
 */
export function widenAlong(F: FixedContactState, i: number): boolean {
  if (hasCapsule(i)) return false
  const vx = F.vx[i]!
  const vy = F.vy[i]!
  const travel = Math.sqrt(vx * vx + vy * vy) * F.tick
  if (!(travel > CAPSULE_TRAVEL * (F.r[i]! + TOUCH_GAP)) || !(F.r[i]! + travel > CAPSULE_CELLS * F.cell)) return false
  fullX[i] = vx * F.tick
  fullY[i] = vy * F.tick
  capS[i] = 1
  preS[i] = 0
  capAt[i] = round
  extAt[i] = 0
  holders[holderCount++] = i
  return true
}

/** Squared distance from (px, py) to the capsule axis of candidate i (now, or before this round). */
function toAxis2(F: FixedContactState, i: number, now: boolean, px: number, py: number): number {
  return axisFrom2(i, shareOf(i, now), px - F.x[i]!, py - F.y[i]!)
}

/** Squared distance from the point (dx, dy) from candidate i's centre to the share s of its path. */
function axisFrom2(i: number, s0: number, dx: number, dy: number): number {
  const ux = fullX[i]! * s0
  const uy = fullY[i]! * s0
  const uu = ux * ux + uy * uy
  const s = clamp01(uu > 0 ? (dx * ux + dy * uy) / uu : 0)
  const ex = dx - s * ux
  const ey = dy - s * uy
  return ex * ex + ey * ey
}

/**
 * Whether what candidate i covers (its circle of radius wide, if newly, else reach; its capsule, counted
 * if `isNew` or made before this round) meets the circle in `circle`.
 */
export function meetsCircle(F: FixedContactState, i: number, isNew: boolean): boolean {
  const cx = circle[0]!
  const cy = circle[1]!
  const R = circle[2]!
  const dx = cx - F.x[i]!
  const dy = cy - F.y[i]!
  const s = (isNew ? F.wide[i]! : F.reach[i]!) + R
  if (dx * dx + dy * dy < s * s) return true
  if (!(isNew ? hasCapsule(i) : hadCapsule(i))) return false
  const c = F.r[i]! + TOUCH_GAP + R
  return toAxis2(F, i, isNew, cx, cy) < c * c
}

/** Whether what candidates a and b cover meets (each new or as before this round, as meetsCircle). */
export function covers(F: FixedContactState, a: number, aNew: boolean, b: number, bNew: boolean): boolean {
  circle[0] = F.x[b]!
  circle[1] = F.y[b]!
  circle[2] = bNew ? F.wide[b]! : F.reach[b]!
  if (meetsCircle(F, a, aNew)) return true
  if (!(bNew ? hasCapsule(b) : hadCapsule(b))) return false
  // b's capsule against a's circle, then against a's capsule
  const ra = aNew ? F.wide[a]! : F.reach[a]!
  const c = F.r[b]! + TOUCH_GAP + ra
  if (toAxis2(F, b, bNew, F.x[a]!, F.y[a]!) < c * c) return true
  if (!(aNew ? hasCapsule(a) : hadCapsule(a))) return false
  const s = F.r[a]! + F.r[b]! + 2 * TOUCH_GAP
  return axes2(F, a, shareOf(a, aNew), b, shareOf(b, bNew)) < s * s
}

/** Squared distance between the capsule axes of candidates a and b, shares sa and sb of their paths (closest points of two segments). */
function axes2(F: FixedContactState, a: number, sa: number, b: number, sb: number): number {
  const ux = fullX[a]! * sa
  const uy = fullY[a]! * sa
  const vx = fullX[b]! * sb
  const vy = fullY[b]! * sb
  const rx = F.x[a]! - F.x[b]!
  const ry = F.y[a]! - F.y[b]!
  const A = ux * ux + uy * uy
  const E = vx * vx + vy * vy
  const f = vx * rx + vy * ry
  let s = 0
  let t = 0
  if (A <= 0 && E <= 0) {
    s = 0
    t = 0
  } else if (A <= 0) {
    t = clamp01(f / E)
  } else {
    const c = ux * rx + uy * ry
    if (E <= 0) s = clamp01(-c / A)
    else {
      const b2 = ux * vx + uy * vy
      const denom = A * E - b2 * b2
      s = denom > 0 ? clamp01((b2 * f - c * E) / denom) : 0
      t = (b2 * s + f) / E
      if (t < 0) {
        t = 0
        s = clamp01(-c / A)
      } else if (t > 1) {
        t = 1
        s = clamp01((b2 - c) / A)
      }
    }
  }
  const dx = rx + ux * s - vx * t
  const dy = ry + uy * s - vy * t
  return dx * dx + dy * dy
}

function clamp01(v: number): number {
  return v < 0 ? 0 : v > 1 ? 1 : v
}

/**
 * The box of what candidate i covers newly (circle and capsule), grown by `extra` on every side, into
 * bounds: minX, maxX, minY, maxY.
 */
export const bounds = new Float64Array(4)
export function coverBounds(F: FixedContactState, i: number, extra: number): void {
  const x = F.x[i]!
  const y = F.y[i]!
  const R = F.wide[i]! + extra
  bounds[0] = x - R
  bounds[1] = x + R
  bounds[2] = y - R
  bounds[3] = y + R
  if (!hasCapsule(i)) return
  const c = F.r[i]! + TOUCH_GAP + extra
  const ex = x + fullX[i]! * capS[i]!
  const ey = y + fullY[i]! * capS[i]!
  bounds[0] = Math.min(bounds[0]!, Math.min(x, ex) - c)
  bounds[1] = Math.max(bounds[1]!, Math.max(x, ex) + c)
  bounds[2] = Math.min(bounds[2]!, Math.min(y, ey) - c)
  bounds[3] = Math.max(bounds[3]!, Math.max(y, ey) + c)
}

/** Candidate i's whole path (its sweep when the capsule was made) into bounds[0], bounds[1]. */
export function readPath(i: number): void {
  bounds[0] = fullX[i]!
  bounds[1] = fullY[i]!
}

/** Candidate i's capsule sweep (velocity × tick) into bounds[0], bounds[1] (none: zero). */
export function readSweep(i: number): void {
  const has = hasCapsule(i)
  bounds[0] = has ? fullX[i]! * capS[i]! : 0
  bounds[1] = has ? fullY[i]! * capS[i]! : 0
}

/** The round now (for a cache kept within one). */
export function roundNow(): number {
  return round
}

/** The box of a widened candidate's cover (coverBounds without growth), for beyondBox. */
const target = new Float64Array(4)
export function setTarget(F: FixedContactState, g: number): void {
  coverBounds(F, g, 0)
  target.set(bounds)
}

/** The box beyondBox tests for candidate j (with a capsule) into nearBox: minX, maxX, minY, maxY (src/contacts/fixedNear.ts). */
export const nearBox = new Float64Array(4)
export function holderBox(F: FixedContactState, j: number): void {
  const R = Math.max(F.grown[j] === 1 ? F.wide[j]! : F.reach[j]!, F.r[j]! + TOUCH_GAP)
  const x = F.x[j]!
  const y = F.y[j]!
  const ex = x + fullX[j]! * capS[j]!
  const ey = y + fullY[j]! * capS[j]!
  nearBox[0] = Math.min(x, ex) - R
  nearBox[1] = Math.max(x, ex) + R
  nearBox[2] = Math.min(y, ey) - R
  nearBox[3] = Math.max(y, ey) + R
}

/** Whether the box of what candidate j (with a capsule) covers misses the target box: then so do the two covers. */
export function beyondBox(F: FixedContactState, j: number): boolean {
  holderBox(F, j)
  return nearBox[1]! < target[0]! || nearBox[0]! > target[1]! || nearBox[3]! < target[2]! || nearBox[2]! > target[3]!
}
