// Ball-ball contacts, opt-in (config.BALL_COLLISIONS = 'on'). A world without them never reads this file's
// state and pays nothing for it.
//
// Balls that can touch need one clock: in collision mode the integration system handles every event (a
// ball's own: lip, contact, stop, roll end, wall; or a pair's contact) in global time order from a binary
// heap, one event per pass, so that no ball is ever moved past an instant at which another could strike it.
// Heap entries carry the path versions of their balls; a ball whose motion changes gets a new version, so
// its old entries are dropped when they come up, and its contacts are predicted again.
//
// Contact times are found by conservative advancement on the balls' closed-form paths (straight rolls with
// constant deceleration, rim rolls, rest): with the gap g, its rate ġ and a bound A on the relative
// acceleration, the gap cannot close before h = (ġ + √(ġ² + 2Ag)) / A, so stepping by h never steps over a
// contact, at any dt (no tunnelling by construction). Near contact the step is Newton's, so it converges
// quadratically; it stops at a gap of GAP_TOLERANCE px with the balls approaching.
//
// Candidate pairs come from two spatial hashes over a uniform grid: one of the capsules swept by moving balls
// over the rest of the step (rebuilt every step, appended to when a path changes), one of resting balls (kept
// across steps, updated when a ball comes to rest or wakes), so resting balls cost nothing until struck.
//
// Allocation: all state is in typed arrays that grow by doubling; nothing is allocated per ball per tick.
import { BallMode } from '../../components/Ball.js'
import { RimMode } from '../../components/RimContact.js'
import { rimRollAt, rimRollState } from '../motion/rolling.js'
import type { BallWorld } from '../world/createWorld.js'

/** Contact is declared when the gap is at most this, px, and the balls approach. */
export const GAP_TOLERANCE = 1e-7
/**
 * Balls approach when the gap closes faster than this share of their relative speed plus SETTLE_FLOOR of
 * BALL_SETTLE_SPEED: rounding after a contact that left them sliding side by side is not a new contact,
 * and balls settled against each other (their speeds equal to within a thousandth of the settle speed)
 * stay settled instead of averaging their velocities ever more finely.
 */
export const APPROACH_EPSILON = 1e-9
export const SETTLE_FLOOR = 1e-3
/**
 * A contact within this time, s, of an earlier contact of either ball is elastic (the TC model of Luding and
 * McNamara): a push through a row of touching balls then passes along it in one sweep, as in Newton's
 * cradle, instead of dissipating in an endless run of ever-smaller contacts (inelastic collapse).
 */
export const CONTACT_DURATION = 1e-4
/** Gap, px, within which balls count as touching when a settling contact gathers its cluster. */
export const CLUSTER_TOUCH = 1e-6
/** Most balls one settling contact moves together. */
export const MAX_CLUSTER = 256
/** Least advance of the contact search while two balls touch without approaching, s. */
export const MIN_ADVANCE = 1e-6
/** Iterations of one contact search before it is put back in the heap to continue later. */
export const MAX_SEARCH_STEPS = 512

export const HeapKind = { Own: 0, Contact: 1, Resume: 2 } as const

export interface CollisionState {
  /** mass of each ball (by entity id), in units of a default ball */
  mass: Float64Array
  /** path version of each ball; heap entries made with an older version are stale */
  ver: Uint32Array
  /** the ball this one last touched (0: none), and when, s */
  partner: Uint32Array
  lastContact: Float64Array
  /** resting grid: bucket of a resting ball (−1: not in the grid) and its list links (0: none) */
  restBucket: Int32Array
  restNext: Uint32Array
  restPrev: Uint32Array
  restHead: Uint32Array
  restCount: number
  /** largest radius of any ball the grids have seen, px */
  maxRadius: number
  /** grid cell, px */
  cell: number
  /** swept-capsule hash: bucket heads (valid where stamp matches), entries as linked lists */
  sweepHead: Int32Array
  sweepStamp: Uint32Array
  stamp: number
  entNext: Int32Array
  entBall: Uint32Array
  entCount: number
  /** per-query stamp by entity id, so a candidate is tested once per query */
  seen: Uint32Array
  seenStamp: number
  /** bucket indices of the capsule being rasterised */
  cells: Int32Array
  /** members of the touching cluster being settled */
  cluster: Uint32Array
  clusterCount: number
  /** binary heap of events, keyed by (time, a, b, kind) */
  hT: Float64Array
  hA: Uint32Array
  hB: Uint32Array
  hVA: Uint32Array
  hVB: Uint32Array
  hKind: Uint8Array
  heapCount: number
  /** time of the last event handled, s */
  now: number
  /** contacts resolved since the world was made */
  contacts: number
}

export function createCollisionState(capacity: number, ballRadius: number): CollisionState {
  const restBucket = new Int32Array(capacity)
  restBucket.fill(-1)
  return {
    mass: new Float64Array(capacity),
    ver: new Uint32Array(capacity),
    partner: new Uint32Array(capacity),
    lastContact: new Float64Array(capacity).fill(-1e300),
    restBucket,
    restNext: new Uint32Array(capacity),
    restPrev: new Uint32Array(capacity),
    restHead: new Uint32Array(1 << 12),
    restCount: 0,
    maxRadius: ballRadius,
    cell: 4 * ballRadius,
    sweepHead: new Int32Array(1 << 10),
    sweepStamp: new Uint32Array(1 << 10),
    stamp: 0,
    entNext: new Int32Array(1 << 12),
    entBall: new Uint32Array(1 << 12),
    entCount: 0,
    seen: new Uint32Array(capacity),
    seenStamp: 0,
    cells: new Int32Array(256),
    cluster: new Uint32Array(MAX_CLUSTER),
    clusterCount: 0,
    hT: new Float64Array(1 << 10),
    hA: new Uint32Array(1 << 10),
    hB: new Uint32Array(1 << 10),
    hVA: new Uint32Array(1 << 10),
    hVB: new Uint32Array(1 << 10),
    hKind: new Uint8Array(1 << 10),
    heapCount: 0,
    now: 0,
    contacts: 0,
  }
}

function grown<T extends Float64Array | Uint32Array | Int32Array | Uint8Array>(a: T, n: number, fill = 0): T {
  const next = new (a.constructor as new (n: number) => T)(n)
  next.set(a)
  if (fill !== 0) next.fill(fill, a.length)
  return next
}

/** Grows the per-ball arrays to `capacity` entities. */
export function growCollisionState(C: CollisionState, capacity: number): void {
  if (C.mass.length >= capacity) return
  C.mass = grown(C.mass, capacity)
  C.ver = grown(C.ver, capacity)
  C.partner = grown(C.partner, capacity)
  C.lastContact = grown(C.lastContact, capacity, -1e300)
  C.restBucket = grown(C.restBucket, capacity, -1)
  C.restNext = grown(C.restNext, capacity)
  C.restPrev = grown(C.restPrev, capacity)
  C.seen = grown(C.seen, capacity)
}

// ---------------------------------------------------------------------------------------------------------
// The state of a ball at any time of its current motion, without writing to the stores

/**
 * The scratch state evalBall writes, in a Float64Array: V8 boxes every double written to a module-level
 * `let` (a fresh heap number per write), and a typed array never allocates.
 *   X, Y, VX, VY: state; AX, AY: exact acceleration (rolling); ACC: bound on |acceleration| from now on
 *   (rim roll), else |(AX, AY)|; EXACT: 1 when (AX, AY) is the exact, piecewise constant acceleration;
 *   NEXT: when the acceleration next changes (a rolling ball's stop), s
 */
const E = new Float64Array(10)
const X = 0
const Y = 1
const VX = 2
const VY = 3
const AX = 4
const AY = 5
const ACC = 6
const EXACT = 7
const NEXT = 8
/** input: the time evalBall evaluates at (passed here, not as an argument, which V8 would box) */
const AT = 9

/**
 * Evaluates ball `eid` at time E[AT] on its current motion into the module's scratch state. The formulas are
 * those of sampleRolling and sampleRimRoll, term for term, so a contact sees the very state the stores get.
 */
function evalBall(w: BallWorld, eid: number): void {
  const t = E[AT]!
  const B = w.Ball
  const mode = B.mode[eid]
  if (mode === BallMode.RimRoll) {
    rimRollAt(w, eid, t)
    const o = rimRollState
    E[X] = o.x
    E[Y] = o.y
    E[VX] = o.vx
    E[VY] = o.vy
    E[AX] = 0
    E[AY] = 0
    // |acceleration| = √((v²/R)² + (μv)²) ≤ v²/R + μv, and v only falls from here
    E[ACC] = (o.speed * o.speed) / o.radius + w.config.RIM_ROLL_FRICTION * o.speed
    E[EXACT] = 0
    E[NEXT] = Infinity
    return
  }
  if (mode === BallMode.Resting) {
    E[X] = B.x[eid]!
    E[Y] = B.y[eid]!
    E[VX] = 0
    E[VY] = 0
    E[AX] = 0
    E[AY] = 0
    E[ACC] = 0
    E[EXACT] = 1
    E[NEXT] = Infinity
    return
  }
  const P = w.Path
  const v0 = P.v0[eid]!
  const decel = w.config.ROLLING_DECEL
  const t0 = P.t0[eid]!
  let tau = t - t0
  if (tau < 0) tau = 0
  let moving = v0 > 0
  if (decel > 0 && tau * decel > v0) {
    tau = v0 / decel
    moving = false
  }
  const d = v0 * tau - 0.5 * decel * tau * tau
  const v = v0 - decel * tau
  const ux = P.ux[eid]!
  const uy = P.uy[eid]!
  E[X] = P.x0[eid]! + ux * d
  E[Y] = P.y0[eid]! + uy * d
  E[VX] = ux * v
  E[VY] = uy * v
  E[EXACT] = 1
  if (moving && decel > 0) {
    E[AX] = -decel * ux
    E[AY] = -decel * uy
    E[ACC] = decel
    E[NEXT] = t0 + v0 / decel
  } else {
    E[AX] = 0
    E[AY] = 0
    E[ACC] = 0
    E[NEXT] = Infinity
  }
}

/** When the ball's current motion began (the search for its contacts starts there, whatever the ticks). */
function motionStart(w: BallWorld, eid: number): number {
  const mode = w.Ball.mode[eid]
  if (mode === BallMode.RimRoll) return w.RimContact.time0[w.Ball.rim[eid]!]!
  const P = w.Path
  if (mode === BallMode.Resting) {
    // a ball at rest has been so since its path stopped (or since it was put down)
    const decel = w.config.ROLLING_DECEL
    const v0 = P.v0[eid]!
    return v0 > 0 && decel > 0 ? P.t0[eid]! + v0 / decel : P.t0[eid]!
  }
  return P.t0[eid]!
}

/** End of the span over which a ball's current motion is known: its next own event, capped. */
function motionEnd(w: BallWorld, eid: number, cap: number): number {
  const mode = w.Ball.mode[eid]
  if (mode === BallMode.Resting) return cap
  const t = w.Path.nextT[eid]!
  return t < cap ? t : cap
}

// ---------------------------------------------------------------------------------------------------------
// Contact search

export const SearchResult = { None: 0, Contact: 1, Resume: 2 } as const
/** result of the last search (a SearchResult) and its time, s; a typed array: no allocation per write */
export const search = new Float64Array(2)
const RESULT = 0
const TIME = 1

/**
 * First contact of balls a and b in [from, to], on their current motions: the earliest time at which their
 * gap is at most GAP_TOLERANCE while they approach. Sets search[RESULT]/search[TIME]: Contact at that time, None
 * if there is none before `to`, or Resume with the time reached after MAX_SEARCH_STEPS (the search continues
 * from there when that time comes up in the heap).
 */
export function searchContact(w: BallWorld, a: number, b: number, from: number, to: number): void {
  search[RESULT] = SearchResult.None
  if (!(from <= to)) return
  const S = w.Ball.radius[a]! + w.Ball.radius[b]!
  const floor = SETTLE_FLOOR * w.config.BALL_SETTLE_SPEED
  let t = from
  for (let iter = 0; iter < MAX_SEARCH_STEPS; iter++) {
    E[AT] = t
    evalBall(w, a)
    const xa = E[X]
    const ya = E[Y]
    const vxa = E[VX]
    const vya = E[VY]
    const axa = E[AX]
    const aya = E[AY]
    const acca = E[ACC]
    const exa = E[EXACT]
    const na = E[NEXT]
    E[AT] = t
    evalBall(w, b)
    const dx = E[X] - xa
    const dy = E[Y] - ya
    const dvx = E[VX] - vxa
    const dvy = E[VY] - vya
    const dist = Math.sqrt(dx * dx + dy * dy)
    const g = dist - S
    // rate of change of the gap (negative: approaching); coincident centres count as approaching
    const vrel = Math.sqrt(dvx * dvx + dvy * dvy)
    const vn = dist > 0 ? (dx * dvx + dy * dvy) / dist : -vrel
    if (g <= GAP_TOLERANCE && vn < -(floor + APPROACH_EPSILON * (1 + vrel))) {
      search[RESULT] = SearchResult.Contact
      search[TIME] = t
      return
    }
    // bound on the relative acceleration until the next change of either ball's acceleration
    let A: number
    let pieceEnd: number
    if (exa === 1 && E[EXACT] === 1) {
      const rx = E[AX] - axa
      const ry = E[AY] - aya
      A = Math.sqrt(rx * rx + ry * ry)
      pieceEnd = na < E[NEXT] ? na : E[NEXT]
    } else {
      A = acca + E[ACC]
      pieceEnd = Infinity
    }
    const gg = g > 0 ? g : 0
    let h: number
    if (vn < 0) {
      // the gap closes no sooner than the positive root of gg + vn·h − A·h²/2 (written without cancellation)
      h = (2 * gg) / (Math.sqrt(vn * vn + 2 * A * gg) - vn)
    } else {
      h = A > 0 ? (vn + Math.sqrt(vn * vn + 2 * A * gg)) / A : Infinity
      // touching without approaching: creep on; the balls can close by at most A·MIN_ADVANCE²/2 meanwhile
      if (h < MIN_ADVANCE) h = MIN_ADVANCE
    }
    let next = t + h
    if (pieceEnd > t && next > pieceEnd) next = pieceEnd
    if (next > to) return
    if (!(next > t)) next = t + MIN_ADVANCE // h below the time resolution at t
    t = next
  }
  search[RESULT] = SearchResult.Resume
  search[TIME] = t
}

// ---------------------------------------------------------------------------------------------------------
// The event heap

function heapLess(C: CollisionState, i: number, j: number): boolean {
  const ti = C.hT[i]!
  const tj = C.hT[j]!
  if (ti !== tj) return ti < tj
  if (C.hA[i] !== C.hA[j]) return C.hA[i]! < C.hA[j]!
  if (C.hB[i] !== C.hB[j]) return C.hB[i]! < C.hB[j]!
  return C.hKind[i]! < C.hKind[j]!
}

function heapSwap(C: CollisionState, i: number, j: number): void {
  const f = C.hT[i]!
  C.hT[i] = C.hT[j]!
  C.hT[j] = f
  let u = C.hA[i]!
  C.hA[i] = C.hA[j]!
  C.hA[j] = u
  u = C.hB[i]!
  C.hB[i] = C.hB[j]!
  C.hB[j] = u
  u = C.hVA[i]!
  C.hVA[i] = C.hVA[j]!
  C.hVA[j] = u
  u = C.hVB[i]!
  C.hVB[i] = C.hVB[j]!
  C.hVB[j] = u
  u = C.hKind[i]!
  C.hKind[i] = C.hKind[j]!
  C.hKind[j] = u
}

export function heapPush(C: CollisionState, t: number, kind: number, a: number, b: number): void {
  if (C.heapCount === C.hT.length) {
    const n = C.hT.length * 2
    C.hT = grown(C.hT, n)
    C.hA = grown(C.hA, n)
    C.hB = grown(C.hB, n)
    C.hVA = grown(C.hVA, n)
    C.hVB = grown(C.hVB, n)
    C.hKind = grown(C.hKind, n)
  }
  let i = C.heapCount++
  C.hT[i] = t
  C.hA[i] = a
  C.hB[i] = b
  C.hVA[i] = C.ver[a]!
  C.hVB[i] = b === 0 ? 0 : C.ver[b]!
  C.hKind[i] = kind
  while (i > 0) {
    const p = (i - 1) >> 1
    if (!heapLess(C, i, p)) break
    heapSwap(C, i, p)
    i = p
  }
}

/** Removes the top entry (read it from index 0 first). */
export function heapPop(C: CollisionState): void {
  const n = --C.heapCount
  if (n === 0) return
  heapSwap(C, 0, n)
  let i = 0
  for (;;) {
    const l = 2 * i + 1
    if (l >= n) break
    const r = l + 1
    const m = r < n && heapLess(C, r, l) ? r : l
    if (!heapLess(C, m, i)) break
    heapSwap(C, i, m)
    i = m
  }
}

/** True when the top entry was made with its balls' current versions. */
export function heapTopLive(C: CollisionState): boolean {
  const a = C.hA[0]!
  const b = C.hB[0]!
  return C.ver[a] === C.hVA[0] && (b === 0 || C.ver[b] === C.hVB[0])
}

// ---------------------------------------------------------------------------------------------------------
// Grids

function bucketOf(ix: number, iy: number, mask: number): number {
  return (Math.imul(ix, 73856093) ^ Math.imul(iy, 19349663)) & mask
}

/**
 * Fills C.cells with the buckets (of a table of mask + 1) of every grid cell that the capsule from
 * (x1, y1) to (x2, y2) with radius rho may touch: row by row, the segment's extent within the row's band,
 * widened by rho. Returns the count.
 */
function capsuleCells(C: CollisionState, x1: number, y1: number, x2: number, y2: number, rho: number, mask: number): number {
  const c = C.cell
  const lo = Math.min(y1, y2) - rho
  const hi = Math.max(y1, y2) + rho
  const row0 = Math.floor(lo / c)
  const row1 = Math.floor(hi / c)
  const dy = y2 - y1
  let n = 0
  for (let row = row0; row <= row1; row++) {
    // the part of the segment whose y lies within rho of this row's band
    const bandLo = row * c - rho
    const bandHi = (row + 1) * c + rho
    let s0 = 0
    let s1 = 1
    if (dy !== 0) {
      let sa = (bandLo - y1) / dy
      let sb = (bandHi - y1) / dy
      if (sa > sb) {
        const tmp = sa
        sa = sb
        sb = tmp
      }
      if (sa > s0) s0 = sa
      if (sb < s1) s1 = sb
      if (s0 > s1) continue
    }
    const xa = x1 + (x2 - x1) * s0
    const xb = x1 + (x2 - x1) * s1
    const col0 = Math.floor((Math.min(xa, xb) - rho) / c)
    const col1 = Math.floor((Math.max(xa, xb) + rho) / c)
    for (let col = col0; col <= col1; col++) {
      if (n === C.cells.length) C.cells = grown(C.cells, n * 2)
      C.cells[n++] = bucketOf(col, row, mask)
    }
  }
  return n
}

/** Puts a resting ball into the resting grid (no-op if it is there). */
export function restingInsert(w: BallWorld, eid: number): void {
  const C = w.collide
  if (C === null || C.restBucket[eid]! >= 0) return
  if (C.restCount + 1 > 2 * C.restHead.length) rehashResting(w, C.restHead.length * 4)
  const r = w.Ball.radius[eid]!
  if (r > C.maxRadius) C.maxRadius = r
  const mask = C.restHead.length - 1
  const bucket = bucketOf(Math.floor(w.Ball.x[eid]! / C.cell), Math.floor(w.Ball.y[eid]! / C.cell), mask)
  const head = C.restHead[bucket]!
  C.restBucket[eid] = bucket
  C.restPrev[eid] = 0
  C.restNext[eid] = head
  if (head !== 0) C.restPrev[head] = eid
  C.restHead[bucket] = eid
  C.restCount++
}

/** Takes a ball out of the resting grid (no-op if it is not there). */
export function restingRemove(w: BallWorld, eid: number): void {
  const C = w.collide
  if (C === null) return
  const bucket = C.restBucket[eid]!
  if (bucket < 0) return
  const prev = C.restPrev[eid]!
  const next = C.restNext[eid]!
  if (prev !== 0) C.restNext[prev] = next
  else C.restHead[bucket] = next
  if (next !== 0) C.restPrev[next] = prev
  C.restBucket[eid] = -1
  C.restNext[eid] = 0
  C.restPrev[eid] = 0
  C.restCount--
}

function rehashResting(w: BallWorld, buckets: number): void {
  const C = w.collide!
  const old = C.restHead
  C.restHead = new Uint32Array(buckets)
  const count = C.restCount
  C.restCount = 0
  // collect the chains first (they are relinked as they are walked)
  const ids = new Uint32Array(count)
  let k = 0
  for (let b = 0; b < old.length; b++) {
    for (let e = old[b]!; e !== 0; e = C.restNext[e]!) ids[k++] = e
  }
  for (let i = 0; i < k; i++) C.restBucket[ids[i]!] = -1
  for (let i = 0; i < k; i++) restingInsert(w, ids[i]!)
}

/** Starts a step: empties the heap and the swept-capsule hash (sized for the moving balls). */
export function beginCollisionStep(w: BallWorld): void {
  const C = w.collide!
  C.heapCount = 0
  C.entCount = 0
  let size = C.sweepHead.length
  while (size < 4 * w.moving.count) size *= 2
  if (size !== C.sweepHead.length) {
    C.sweepHead = new Int32Array(size)
    C.sweepStamp = new Uint32Array(size)
    C.stamp = 0
  }
  C.stamp++
  if (C.stamp === 0xffffffff) {
    C.sweepStamp.fill(0)
    C.stamp = 1
  }
}

/** The capsule a ball may sweep from `from` to the end of its known motion (capped at `to`). */
/** the capsule sweptCapsule writes: ends (X1, Y1), (X2, Y2) and radius CR */
const cap = new Float64Array(5)
const X1 = 0
const Y1 = 1
const X2 = 2
const Y2 = 3
const CR = 4
function sweptCapsule(w: BallWorld, eid: number, from: number, to: number): void {
  const r = w.Ball.radius[eid]!
  if (w.Ball.mode[eid] === BallMode.RimRoll) {
    // anywhere on the rim circle of its hole
    const hole = w.RimContact.hole[w.Ball.rim[eid]!]!
    cap[X1] = cap[X2] = w.Hole.x[hole]!
    cap[Y1] = cap[Y2] = w.Hole.y[hole]!
    cap[CR] = w.Hole.radius[hole]! + r
    return
  }
  E[AT] = from
  evalBall(w, eid)
  cap[X1] = E[X]
  cap[Y1] = E[Y]
  E[AT] = motionEnd(w, eid, to)
  evalBall(w, eid)
  cap[X2] = E[X]
  cap[Y2] = E[Y]
  cap[CR] = r
}

/**
 * Predicts ball `a`'s contacts with every ball near its path over [C.now, tickEnd] and pushes them, and its
 * own next event, into the heap; then enters its capsule into the hash. A step's first build calls this once
 * per moving ball, so each pair is tried once (by the later of the two); later calls try every neighbour.
 */
export function predictBall(w: BallWorld, a: number): void {
  const C = w.collide!
  const mode = w.Ball.mode[a]
  if (mode !== BallMode.Rolling && mode !== BallMode.RimRoll && mode !== BallMode.Resting) return
  const tEnd = w.tickEnd
  if (mode !== BallMode.Resting) {
    const own = w.Path.nextT[a]!
    if (own <= tEnd) heapPush(C, own, HeapKind.Own, a, 0)
  }
  const now = C.now
  sweptCapsule(w, a, now, tEnd)
  const x1 = cap[X1]
  const y1 = cap[Y1]
  const x2 = cap[X2]
  const y2 = cap[Y2]
  const rho = cap[CR]
  const startA = motionStart(w, a)
  const endA = motionEnd(w, a, tEnd)
  if (++C.seenStamp === 0xffffffff) {
    C.seen.fill(0)
    C.seenStamp = 1
  }
  const stamp = C.seenStamp
  C.seen[a] = stamp

  // moving balls' capsules
  const sMask = C.sweepHead.length - 1
  let n = capsuleCells(C, x1, y1, x2, y2, rho, sMask)
  for (let k = 0; k < n; k++) {
    const bucket = C.cells[k]!
    if (C.sweepStamp[bucket] !== C.stamp) continue
    for (let e = C.sweepHead[bucket]!; e >= 0; e = C.entNext[e]!) {
      const b = C.entBall[e]!
      if (C.seen[b] === stamp) continue
      // stale entries of balls that have since stopped: those are found through the resting grid
      const mb = w.Ball.mode[b]
      if (mb !== BallMode.Rolling && mb !== BallMode.RimRoll) continue
      C.seen[b] = stamp
      tryPair(w, a, b, startA, endA, tEnd)
    }
  }
  // enter a's capsule, in the same cells (resting balls are found through the resting grid)
  if (mode !== BallMode.Resting) {
    for (let k = 0; k < n; k++) {
      const bucket = C.cells[k]!
      if (C.entCount === C.entNext.length) {
        C.entNext = grown(C.entNext, C.entCount * 2)
        C.entBall = grown(C.entBall, C.entCount * 2)
      }
      const e = C.entCount++
      C.entBall[e] = a
      if (C.sweepStamp[bucket] !== C.stamp) {
        C.sweepStamp[bucket] = C.stamp
        C.entNext[e] = -1
      } else C.entNext[e] = C.sweepHead[bucket]!
      C.sweepHead[bucket] = e
    }
  }
  // resting balls, by centre cell: widen by the largest radius
  if (mode !== BallMode.Resting && C.restCount > 0) {
    const rMask = C.restHead.length - 1
    n = capsuleCells(C, x1, y1, x2, y2, rho + C.maxRadius, rMask)
    for (let k = 0; k < n; k++) {
      for (let b = C.restHead[C.cells[k]!]!; b !== 0; b = C.restNext[b]!) {
        if (C.seen[b] === stamp) continue
        C.seen[b] = stamp
        // the bucket also holds balls of far cells that hash alike: test the distance to a's capsule first
        if (segmentDistance2(w.Ball.x[b]!, w.Ball.y[b]!, x1, y1, x2, y2) > (rho + w.Ball.radius[b]! + 2 * GAP_TOLERANCE) ** 2) continue
        tryPair(w, a, b, startA, endA, tEnd)
      }
    }
  }
}

/** Squared distance from (px, py) to the segment (x1, y1)–(x2, y2). */
function segmentDistance2(px: number, py: number, x1: number, y1: number, x2: number, y2: number): number {
  const dx = x2 - x1
  const dy = y2 - y1
  const len2 = dx * dx + dy * dy
  let s = len2 > 0 ? ((px - x1) * dx + (py - y1) * dy) / len2 : 0
  if (s < 0) s = 0
  else if (s > 1) s = 1
  const ex = x1 + s * dx - px
  const ey = y1 + s * dy - py
  return ex * ex + ey * ey
}

function tryPair(w: BallWorld, a: number, b: number, startA: number, endA: number, tEnd: number): void {
  const startB = motionStart(w, b)
  const endB = motionEnd(w, b, tEnd)
  searchAndPush(w, a, b, startA > startB ? startA : startB, endA < endB ? endA : endB)
}

/** Continues a search that ran out of steps, from where it stopped. */
export function resumeSearch(w: BallWorld, a: number, b: number, from: number): void {
  const endA = motionEnd(w, a, w.tickEnd)
  const endB = motionEnd(w, b, w.tickEnd)
  searchAndPush(w, a, b, from, endA < endB ? endA : endB)
}

/** Searches a and b over [from, to] and pushes what it finds: their contact, or where to resume. */
function searchAndPush(w: BallWorld, a: number, b: number, from: number, to: number): void {
  searchContact(w, a, b, from, to)
  if (search[RESULT] === SearchResult.None) return
  const C = w.collide!
  // a contact found behind the clock (balls put down overlapping) is handled now
  const t = search[TIME] > C.now ? search[TIME] : C.now
  const kind = search[RESULT] === SearchResult.Contact ? HeapKind.Contact : HeapKind.Resume
  heapPush(C, t, kind, a < b ? a : b, a < b ? b : a)
}

/**
 * Gathers into C.cluster the balls touching a or b (gap ≤ CLUSTER_TOUCH at time t), and those touching
 * them, breadth first, up to MAX_CLUSTER balls; a and b come first. Members are sampled into Ball at t.
 */
export function collectCluster(w: BallWorld, a: number, b: number, t: number): void {
  const C = w.collide!
  if (++C.seenStamp === 0xffffffff) {
    C.seen.fill(0)
    C.seenStamp = 1
  }
  const stamp = C.seenStamp
  const list = C.cluster
  list[0] = a
  list[1] = b
  C.seen[a] = stamp
  C.seen[b] = stamp
  let n = 2
  const B = w.Ball
  for (let head = 0; head < n && n < MAX_CLUSTER; head++) {
    const m = list[head]!
    const x = B.x[m]!
    const y = B.y[m]!
    const r = B.radius[m]!
    const sMask = C.sweepHead.length - 1
    let k = capsuleCells(C, x, y, x, y, r, sMask)
    for (let i = 0; i < k && n < MAX_CLUSTER; i++) {
      const bucket = C.cells[i]!
      if (C.sweepStamp[bucket] !== C.stamp) continue
      for (let e = C.sweepHead[bucket]!; e >= 0 && n < MAX_CLUSTER; e = C.entNext[e]!) {
        const c = C.entBall[e]!
        if (C.seen[c] === stamp) continue
        if (touches(w, c, x, y, r, t)) {
          C.seen[c] = stamp
          list[n++] = c
        }
      }
    }
    if (C.restCount === 0) continue
    const rMask = C.restHead.length - 1
    k = capsuleCells(C, x, y, x, y, r + C.maxRadius, rMask)
    for (let i = 0; i < k && n < MAX_CLUSTER; i++) {
      for (let c = C.restHead[C.cells[i]!]!; c !== 0 && n < MAX_CLUSTER; c = C.restNext[c]!) {
        if (C.seen[c] === stamp) continue
        if (touches(w, c, x, y, r, t)) {
          C.seen[c] = stamp
          list[n++] = c
        }
      }
    }
  }
  C.clusterCount = n
}

function touches(w: BallWorld, c: number, x: number, y: number, r: number, t: number): boolean {
  const mode = w.Ball.mode[c]
  if (mode !== BallMode.Rolling && mode !== BallMode.RimRoll && mode !== BallMode.Resting) return false
  E[AT] = t
  evalBall(w, c)
  const dx = E[X] - x
  const dy = E[Y] - y
  const S = r + w.Ball.radius[c]! + CLUSTER_TOUCH
  if (dx * dx + dy * dy > S * S) return false
  sampleForContact(w, c, t)
  return true
}

/** Writes ball `eid`'s state at time t (on its current motion) into Ball. */
export function sampleForContact(w: BallWorld, eid: number, t: number): void {
  E[AT] = t
  evalBall(w, eid)
  const B = w.Ball
  B.x[eid] = E[X]
  B.y[eid] = E[Y]
  B.vx[eid] = E[VX]
  B.vy[eid] = E[VY]
}

/** Marks a ball's motion as changed: its heap entries become stale. */
export function bumpVersion(w: BallWorld, eid: number): void {
  const C = w.collide!
  C.ver[eid] = (C.ver[eid]! + 1) >>> 0
}

// ---------------------------------------------------------------------------------------------------------
// The contact law

/** Result of resolveContact: new velocities, the impulse along the normal and the approach speed. */
export const contactOut = { vax: 0, vay: 0, vbx: 0, vby: 0, impulse: 0, approach: 0 }

/**
 * Velocities after a contact of balls a and b (masses ma, mb, centres a→b along (nx, ny), unit), with
 * restitution e: the normal impulse j = (1 + e)·w / (1/ma + 1/mb), w the approach speed, changes a by −j·n/ma
 * and b by +j·n/mb; tangential velocities are kept (smooth balls). Momentum is conserved exactly in exact
 * arithmetic and kinetic energy falls by (1 − e²)·w²/(2(1/ma + 1/mb)) ≥ 0. (A settling contact instead
 * gives the touching cluster its centre-of-mass velocity: systems/collisions.ts.)
 */
export function resolveContact(
  ma: number,
  mb: number,
  vax: number,
  vay: number,
  vbx: number,
  vby: number,
  nx: number,
  ny: number,
  e: number,
): void {
  const o = contactOut
  const rx = vbx - vax
  const ry = vby - vay
  const approach = -(rx * nx + ry * ny)
  o.approach = approach
  if (!(approach > 0)) {
    o.vax = vax
    o.vay = vay
    o.vbx = vbx
    o.vby = vby
    o.impulse = 0
    return
  }
  const j = ((1 + e) * approach) / (1 / ma + 1 / mb)
  o.impulse = j
  o.vax = vax - (j / ma) * nx
  o.vay = vay - (j / ma) * ny
  o.vbx = vbx + (j / mb) * nx
  o.vby = vby + (j / mb) * ny
}

/**
 * True when a and b touch again with nothing having happened to either since they last touched each other
 * (partner is set after a contact and cleared by every new path, in startPath). Two balls pressed together by their decelerations would
 * otherwise touch again and again, ever sooner (a Zeno sequence): such a contact is made perfectly
 * inelastic, after which they move as one and cannot touch again.
 */
export function isRepeatContact(w: BallWorld, a: number, b: number): boolean {
  const C = w.collide!
  return C.partner[a] === b && C.partner[b] === a
}

/** The rim mode a struck ball keeps: inside a lip circle it is in transit (its decision there is void). */
export function strikeLeavesRim(w: BallWorld, eid: number): void {
  const c = w.Ball.rim[eid]!
  if (c !== 0) w.RimContact.mode[c] = RimMode.Transit
}
