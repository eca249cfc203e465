// Fixed-tick contacts: widening along a ball's path (src/contacts/fixedReach.ts). The velocity solve only
// acts on two balls that meet on straight lines within the tick (src/contacts/fixedSolve.ts), so a ball the
// solve sped up far beyond its size can only meet the balls along its line, the capsule of its radius swept
// by its velocity over the tick. Widened by its whole travel in every direction instead, a radius-0.5 ball
// at 1e5 px/s is paired with every ball within 833 px: in rows of tiny balls side by side, thousands of
// pairs a ball and a round, and the rounds' bounds stop the push halfway along a row. So a ball that would
// move more than CAPSULE_TRAVEL radii in the tick, with a circle wider than CAPSULE_CELLS of the tick's
// cells (among balls about as fast a capsule saves nothing), is widened to that capsule (once a tick; a
// second widening in a new direction widens its circle as before). What a candidate covers is then its
// reach circle and, this tick, its capsule; a pair is listed once, when the two covers first meet,
// whichever way round they are found: a widened ball with a capsule looks up the candidates where they
// can be (the grids' cells of its cover, the big ones, those the widening added, the list of balls with
// a capsule), a widened ball without one is tested against that list, and the other pairs are found as
// before, through the grids.
import { CAPSULE_CELLS, CAPSULE_TRAVEL, PROJECTION_SLOP, TOUCH_GAP } from '../config/tolerances.js'
import { grown } from '../world/contactState.js'
import type { FixedContactState } from '../world/fixedState.js'

/** Per candidate: its capsule's sweep (velocity × tick) and the round that made it; the tick's balls with one. */
let capX = new Float64Array(64)
let capY = new Float64Array(64)
let capAt = new Float64Array(64)
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

/** A new contact tick: no ball has a capsule. */
export function beginWidening(): void {
  tickFrom = round + 1
  holderCount = 0
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
    capX[o] = capX[i]!
    capY[o] = capY[i]!
    capAt[o] = capAt[i]!
    next = o
  }
  for (let k = 0; k < next; k++) capAt[k] = 0
  for (let h = 0; h < holderCount; h++) holders[h] = moved[holders[h]!]!
}

function reserve(n: number): void {
  if (capAt.length < n) {
    let len = capAt.length
    while (len < n) len *= 2
    capX = grown(capX, len)
    capY = grown(capY, len)
    capAt = grown(capAt, len)
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

/**
 * Whether candidate i's sweep at its present velocity lies within its capsule (to the projection's slop),
 * if it has one: the same start and radius, so it does when the sweep's end does.
 */
export function withinCapsule(F: FixedContactState, i: number): boolean {
  if (!hasCapsule(i)) return false
  return axisFrom2(i, F.vx[i]! * F.tick, F.vy[i]! * F.tick) <= PROJECTION_SLOP * PROJECTION_SLOP
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
  capX[i] = vx * F.tick
  capY[i] = vy * F.tick
  capAt[i] = round
  holders[holderCount++] = i
  return true
}

/** Squared distance from (px, py) to the capsule axis of candidate i. */
function toAxis2(F: FixedContactState, i: number, px: number, py: number): number {
  return axisFrom2(i, px - F.x[i]!, py - F.y[i]!)
}

/** Squared distance from the point (dx, dy) from candidate i's centre to its capsule axis. */
function axisFrom2(i: number, dx: number, dy: number): number {
  const ux = capX[i]!
  const uy = capY[i]!
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
  return toAxis2(F, i, cx, cy) < c * c
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
  if (toAxis2(F, b, F.x[a]!, F.y[a]!) < c * c) return true
  if (!(aNew ? hasCapsule(a) : hadCapsule(a))) return false
  const s = F.r[a]! + F.r[b]! + 2 * TOUCH_GAP
  return axes2(F, a, b) < s * s
}

/** Squared distance between the capsule axes of candidates a and b (closest points of two segments). */
function axes2(F: FixedContactState, a: number, b: number): number {
  const ux = capX[a]!
  const uy = capY[a]!
  const vx = capX[b]!
  const vy = capY[b]!
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
  const ex = x + capX[i]!
  const ey = y + capY[i]!
  bounds[0] = Math.min(bounds[0]!, Math.min(x, ex) - c)
  bounds[1] = Math.max(bounds[1]!, Math.max(x, ex) + c)
  bounds[2] = Math.min(bounds[2]!, Math.min(y, ey) - c)
  bounds[3] = Math.max(bounds[3]!, Math.max(y, ey) + c)
}

/** Candidate i's capsule sweep (velocity × tick) into bounds[0], bounds[1] (none: zero). */
export function readSweep(i: number): void {
  const has = hasCapsule(i)
  bounds[0] = has ? capX[i]! : 0
  bounds[1] = has ? capY[i]! : 0
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

/** Whether the box of what candidate j (with a capsule) covers misses the target box: then so do the two covers. */
export function beyondBox(F: FixedContactState, j: number): boolean {
  const R = Math.max(F.grown[j] === 1 ? F.wide[j]! : F.reach[j]!, F.r[j]! + TOUCH_GAP)
  const x = F.x[j]!
  const y = F.y[j]!
  const ex = x + capX[j]!
  const ey = y + capY[j]!
  return Math.max(x, ex) + R < target[0]! || Math.min(x, ex) - R > target[1]! || Math.max(y, ey) + R < target[2]! || Math.min(y, ey) - R > target[3]!
}
