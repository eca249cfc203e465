// State of the fixed-tick contact method (config.BALL_COLLISIONS = 'fixed'; null without it): each ball's mass, the
// contact clock, the sweep order kept from tick to tick (src/contacts/fixedSweep.ts), the work meter (fixedBudget.ts),
// and the per-tick working arrays of fixedGrid.ts, fixedDense.ts, fixedOrder.ts, fixedSolve.ts and fixedProject.ts, packed
// by candidate (the balls of a tick that can touch) and grown by doubling: a tick allocates nothing once they fit the scene.
import type { BallPhysicsConfig } from '../config/design.js'
import { appendId, createCollisionState, type CollisionState } from './contactState.js'
import { GROWTH_TICKS } from '../config/tolerances.js'

export interface FixedContactState {
  /** mass of each ball (by entity id), in units of a default ball */
  mass: Float64Array
  /** the resting grid (src/world/restingGrid.ts; its resting-grid fields): resting balls are candidates only when a moving ball can reach them */
  rest: CollisionState
  /** balls moved by the last tick's projection or come to rest since: next tick, they and the resting balls they touch are candidates */
  touched: Uint32Array
  touchedCount: number
  /** packed candidates from this index on rest (the resting ones the gather found, then those the widening added) */
  restFrom: number
  /** contact tick, s: CONTACT_TICK halved `halvings` times (src/contacts/fixedHalve.ts); solved at k·tick */
  tick: number
  /** k of the next contact tick; times CONTACT_TICK was halved */
  nextTick: number
  halvings: number
  /** fixedHalve.ts: the last tick's pairs and candidates; ticks to wait before coarsening, and the wait after a try that fails */
  tickPairs: number
  tickFull: number
  /** fixedHalve.ts: how much the pairs of each of the last GROWTH_TICKS ticks grew in its widening rounds */
  tickGrowth: Float64Array
  coarsenWait: number
  coarsenBackoff: number
  /** true while the window being run starts at a contact tick (the solve runs in its first pass) */
  due: boolean
  /** the tick's candidates (moving, and resting ones that can be touched), kept sorted by sweep cell tick to tick (fixedSweep.ts); those that can touch are packed below */
  ord: Uint32Array
  /** the keys of ord's balls, in its order (written by the gather at each ball's place of the last tick) */
  okey: Float64Array
  ordCount: number
  /** sweep cell, px (at least twice the reach of every ball but the "big" ones), and its inverse; the cell wanted from the next tick (0: keep) */
  sweepCell: number
  sweepInv: number
  sweepNext: number
  /** 1: the sweep's cells go column by column (keys column·ROW + row), for balls that move mostly up and down; the order wanted from the next tick */
  sweepCols: number
  sweepColsNext: number
  /** by ball id: 1 while in ord, and its place there; its reach at this tick's gather; stamps of the packed balls and of those near a closed wall; index in the packed arrays */
  inOrd: Uint8Array
  posOf: Int32Array
  reachOf: Float64Array
  packMark: Uint32Array
  nearMark: Uint32Array
  packAt: Int32Array
  markStamp: number
  /** candidates of the tick (moving, then resting) before packing, and the largest reach among them and those widened */
  full: number
  reachMax: number
  /** balls joining ord this tick and their keys; resting candidates found through the resting grid (scratch) */
  fresh: Uint32Array
  freshKey: Float64Array
  freshCount: number
  /** ids near a closed wall this tick; sweep cells' big balls; balls found by a box query */
  near: Uint32Array
  nearCount: number
  sweepBig: Uint32Array
  sweepBigCount: number
  found: Uint32Array
  foundCount: number
  /** pairs found by the sweep, as ids */
  pe1: Uint32Array
  pe2: Uint32Array
  peCount: number
  /** 1: this tick takes the dense broadphase (src/contacts/fixedDense.ts), 0: the sweep; the next tick's (the share of candidates in pairs decides) */
  dense: number
  denseNext: number
  /** −1: the broadphase is chosen tick by tick (the default); 0: always the sweep, 1: always the dense grid (tests compare the two) */
  broadphase: number
  /** dense broadphase: first sorted entry of each grid cell (cells + 1 entries), fill counters, and the candidates sorted by cell: position, reach and index */
  start: Int32Array
  fill: Int32Array
  sx: Float64Array
  sy: Float64Array
  sr: Float64Array
  si: Int32Array
  /** sort scratch: two keys and a permutation (and its merge buffer) */
  key1: Float64Array
  key2: Float64Array
  perm: Int32Array
  permTmp: Int32Array
  // the balls that can touch within the tick, packed (moving by id, then resting by id, then those the
  // widening added): the tick's pairs, walls and widening are solved over these
  n: number
  /** packed balls that were candidates at the gather (the rest were added by the widening) */
  gathered: number
  id: Uint32Array
  x: Float64Array
  y: Float64Array
  r: Float64Array
  vx: Float64Array
  vy: Float64Array
  /** inverse mass */
  im: Float64Array
  /** radius plus the distance the ball can cover in one tick, px (at the velocity it was paired with) */
  reach: Float64Array
  /** the reach at the velocity a solve round left it with; grown: 1 where that is wider (src/contacts/fixedReach.ts) */
  wide: Float64Array
  grown: Uint8Array
  /** some pair met by the velocity sweeps of this tick overlaps */
  overlap: boolean
  /** candidates whose velocity the solve changed, in the order it did */
  hit: Int32Array
  hitCount: number
  /** candidates widened in this round */
  widened: Int32Array
  widenedCount: number
  /** grid cell of a packed ball in the grid that orders the pairs (fixedOrder.ts); scratch for the solve after */
  next: Int32Array
  /** what the solve changed: 1 velocity, 2 position; the wall's bits (4, 8, 16) and a pair's (32): src/contacts/fixedWallTurn.ts */
  changed: Uint8Array
  /** packed balls too wide or too fast for the ordering grid (its "big" balls) */
  big: Int32Array
  bigCount: number
  /** candidates near a closed wall this tick */
  nearWall: Int32Array
  nearWallCount: number
  /** candidate pairs close enough to touch within the tick; normal a→b; whether an event was emitted */
  pairA: Int32Array
  pairB: Int32Array
  pairHit: Uint8Array
  pairCount: number
  /** grid cell of this tick, px, and the candidates' bounding box */
  cell: number
  minX: number
  minY: number
  maxX: number
  maxY: number
  /** the grid that orders the tick's pairs (fixedOrder.ts): its cell (px), columns and rows */
  gridCell: number
  cols: number
  rows: number
  /** the solve's pairs of each candidate (CSR: adjStart, n + 1 entries, into adjPairs), the pairs listed for the next sweep, the candidates moved in a sweep */
  adjStart: Int32Array
  adjPairs: Int32Array
  active: Int32Array
  activeCount: number
  moved: Int32Array
  /** a sweep over listed pairs: its keys due, as bits (key k: bit k & 31 of word k >> 5; fixedPairs.ts) */
  dueKeys: Int32Array
  /** stamps of the sweeps over listed pairs: a pair in the sweep, a pair in the next sweep, a candidate moved */
  pairStamp: Uint32Array
  nextStamp: Uint32Array
  ballStamp: Uint32Array
  stamp: number
  /** contacts reported (impulses with approach of at least BALL_SETTLE_SPEED), and ticks solved */
  contacts: number
  ticks: number
  /** impulses closed inelastically past RESTITUTION_VISITS or MAX_TICK_CONTACTS, or by the tick's last guard (src/contacts/fixedGuard.ts), though BALL_RESTITUTION > 0 (the world's life; docs/fixed-tick.md) */
  inelastic: number
  /** ticks whose projection stopped with an overlap deeper than PROJECTION_SLOP left (its budget spent, balls held by the walls, or its rounds that pair the balls it pushed into unpaired ones stopped at their bound) */
  capped: number
  /** the work meter (src/contacts/fixedBudget.ts): the CONTACT_TICK span it meters, the work spent in it, its budget (−1: none; −2: UNLIKE_MASS_BUDGET's, not yet set by the span's first pairing), the spans whose last ticks it skipped (over the world's life), the share of a try's work it counts; `lean`: ticks that ended past their budget (over the world's life) */
  budget: Float64Array
  lean: number
  /** pairs of a pushed ball and a moving ball listed after a projection (src/contacts/fixedJoin.ts), counted over the world's life */
  movingJoins: number
}

export function createFixedState(capacity: number, config: Readonly<BallPhysicsConfig>): FixedContactState {
  const n = 64
  return {
    mass: new Float64Array(capacity).fill(1),
    rest: createCollisionState(capacity, config.BALL_RADIUS),
    touched: new Uint32Array(16),
    touchedCount: 0,
    restFrom: 0,
    tick: config.CONTACT_TICK,
    nextTick: 1,
    halvings: 0,
    tickPairs: 0,
    tickFull: 0,
    tickGrowth: new Float64Array(GROWTH_TICKS).fill(1),
    coarsenWait: 0,
    coarsenBackoff: 1,
    due: false,
    n: 0,
    id: new Uint32Array(n),
    x: new Float64Array(n),
    y: new Float64Array(n),
    r: new Float64Array(n),
    vx: new Float64Array(n),
    vy: new Float64Array(n),
    im: new Float64Array(n),
    reach: new Float64Array(n),
    wide: new Float64Array(n),
    grown: new Uint8Array(n),
    widened: new Int32Array(n),
    hit: new Int32Array(n),
    hitCount: 0,
    overlap: false,
    widenedCount: 0,
    next: new Int32Array(n),
    changed: new Uint8Array(n),
    start: new Int32Array(4 * n),
    fill: new Int32Array(4 * n),
    sx: new Float64Array(n),
    sy: new Float64Array(n),
    sr: new Float64Array(n),
    si: new Int32Array(n),
    big: new Int32Array(n),
    bigCount: 0,
    nearWall: new Int32Array(n),
    nearWallCount: 0,
    pairA: new Int32Array(n),
    pairB: new Int32Array(n),
    pairHit: new Uint8Array(n),
    pairCount: 0,
    cell: 4 * config.BALL_RADIUS,
    minX: 0,
    minY: 0,
    maxX: 0,
    maxY: 0,
    gridCell: 1,
    cols: 0,
    rows: 0,
    adjStart: new Int32Array(n + 1),
    adjPairs: new Int32Array(2 * n),
    active: new Int32Array(n),
    activeCount: 0,
    moved: new Int32Array(n),
    dueKeys: new Int32Array((n >> 5) + 1),
    pairStamp: new Uint32Array(n),
    nextStamp: new Uint32Array(n),
    ballStamp: new Uint32Array(n),
    stamp: 0,
    contacts: 0,
    inelastic: 0,
    ticks: 0,
    capped: 0,
    budget: new Float64Array([-1, 0, -1, 0, 1]),
    lean: 0,
    movingJoins: 0,
    ord: new Uint32Array(n),
    okey: new Float64Array(n),
    ordCount: 0,
    sweepCell: 4 * config.BALL_RADIUS,
    sweepInv: 1 / (4 * config.BALL_RADIUS),
    sweepNext: 0,
    sweepCols: 0,
    sweepColsNext: 0,
    inOrd: new Uint8Array(0),
    posOf: new Int32Array(0),
    reachOf: new Float64Array(0),
    packMark: new Uint32Array(0),
    nearMark: new Uint32Array(0),
    packAt: new Int32Array(0),
    markStamp: 0,
    full: 0,
    reachMax: 0,
    fresh: new Uint32Array(n),
    freshKey: new Float64Array(n),
    freshCount: 0,
    near: new Uint32Array(n),
    nearCount: 0,
    sweepBig: new Uint32Array(n),
    sweepBigCount: 0,
    found: new Uint32Array(n),
    foundCount: 0,
    pe1: new Uint32Array(n),
    pe2: new Uint32Array(n),
    peCount: 0,
    dense: 1,
    denseNext: 1,
    broadphase: -1,
    key1: new Float64Array(n),
    key2: new Float64Array(n),
    perm: new Int32Array(n),
    permTmp: new Int32Array(n),
    gathered: 0,
  }
}

/** Makes room in the arrays of the sweeps over listed pairs for n candidates and `pairs` pairs (contents not kept). */
export function reserveSweeps(F: FixedContactState, n: number, pairs: number): void {
  if (F.adjStart.length < n + 1) {
    F.adjStart = new Int32Array(2 * n + 1)
    F.moved = new Int32Array(2 * n)
    F.ballStamp = new Uint32Array(2 * n)
    F.stamp = 0
  }
  if (F.active.length < pairs) {
    F.adjPairs = new Int32Array(4 * pairs)
    F.active = new Int32Array(2 * pairs)
    F.dueKeys = new Int32Array(((2 * pairs) >> 5) + 1)
    F.pairStamp = new Uint32Array(2 * pairs)
    F.nextStamp = new Uint32Array(2 * pairs)
    F.stamp = 0
  }
  if (F.stamp !== 0) return
  F.pairStamp.fill(0)
  F.nextStamp.fill(0)
  F.ballStamp.fill(0)
}

/** Grows the per-ball stores (mass, and the sweep's marks by id) so that ball id cap − 1 fits. */
export function growFixedMass(F: FixedContactState, cap: number): void {
  if (F.mass.length >= cap) return
  const m = new Float64Array(cap).fill(1)
  m.set(F.mass)
  F.mass = m
  if (F.inOrd.length > 0) sweepStores(F)
}

/** The sweep's stores by ball id, made (or grown) to the mass store's size: a world whose ticks all take the dense broadphase never has them. */
export function sweepStores(F: FixedContactState): void {
  const cap = F.mass.length
  if (F.inOrd.length >= cap) return
  F.inOrd = grownTo(F.inOrd, cap)
  F.posOf = grownTo(F.posOf, cap)
  F.reachOf = grownTo(F.reachOf, cap)
  F.packMark = grownTo(F.packMark, cap)
  F.nearMark = grownTo(F.nearMark, cap)
  F.packAt = grownTo(F.packAt, cap)
}

/** A fresh stamp for packMark and nearMark (cleared when the stamps wrap). */
export function nextMark(F: FixedContactState): number {
  if (F.markStamp === 0xffffffff) {
    F.packMark.fill(0)
    F.nearMark.fill(0)
    F.markStamp = 0
  }
  return ++F.markStamp
}

/** List `list` with eid at index `count`: the same array, or a copy twice as long when it is full. */
export function pushListed(list: Uint32Array, count: number, eid: number): Uint32Array {
  const out = count === list.length ? grownTo(list, 2 * count) : list
  out[count] = eid
  return out
}

/** Makes room in the ordered sweep arrays for n balls (keeping their contents). */
export function reserveOrd(F: FixedContactState, n: number): void {
  if (F.ord.length >= n) return
  const len = doubled(F.ord.length, n)
  F.ord = grownTo(F.ord, len)
  F.okey = grownTo(F.okey, len)
}

/** Makes room in the sort scratch for n keys (contents not kept). */
export function reserveSort(F: FixedContactState, n: number): void {
  if (F.perm.length >= n) return
  const len = doubled(F.perm.length, n)
  F.key1 = new Float64Array(len)
  F.key2 = new Float64Array(len)
  F.perm = new Int32Array(len)
  F.permTmp = new Int32Array(len)
}

/** Appends ball eid to the candidate ids (F.n counts them); the other candidate arrays follow in reserveCandidates. */
export function pushCandidate(F: FixedContactState, eid: number): void {
  if (F.n === F.id.length) F.id = grownTo(F.id, 2 * F.id.length)
  F.id[F.n++] = eid
}

/** Makes room in every per-candidate array (keeping their contents) for n candidates. */
export function reserveCandidates(F: FixedContactState, n: number): void {
  if (F.id.length < n) F.id = grownTo(F.id, doubled(F.id.length, n))
  if (F.x.length >= n) return
  const len = doubled(F.x.length, n)
  F.x = grownTo(F.x, len)
  F.y = grownTo(F.y, len)
  F.r = grownTo(F.r, len)
  F.vx = grownTo(F.vx, len)
  F.vy = grownTo(F.vy, len)
  F.im = grownTo(F.im, len)
  F.reach = grownTo(F.reach, len)
  F.wide = grownTo(F.wide, len)
  F.grown = grownTo(F.grown, len)
  F.next = grownTo(F.next, len)
  F.changed = grownTo(F.changed, len)
  F.sx = grownTo(F.sx, len)
  F.sy = grownTo(F.sy, len)
  F.sr = grownTo(F.sr, len)
  F.si = grownTo(F.si, len)
  F.big = grownTo(F.big, len)
  F.nearWall = grownTo(F.nearWall, len)
  F.widened = grownTo(F.widened, len)
  F.hit = grownTo(F.hit, len)
}

/** len doubled until it is at least n. */
const doubled = (len: number, n: number): number => (len >= n ? len : doubled(2 * len, n))

export function grownTo<T extends Float64Array | Int32Array | Uint8Array | Uint32Array>(a: T, n: number): T {
  const next = new (a.constructor as new (n: number) => T)(n)
  next.set(a)
  return next
}

/** Appends the pair (a, b) of candidate indices. */
export function pushPair(F: FixedContactState, a: number, b: number): void {
  if (F.pairCount === F.pairA.length) {
    // pairs are also added during the solve (fixedReach.ts): what the earlier ones took this tick is kept
    const len = 2 * F.pairA.length
    F.pairA = grownTo(F.pairA, len)
    F.pairB = grownTo(F.pairB, len)
    F.pairHit = grownTo(F.pairHit, len)
  }
  F.pairA[F.pairCount] = a
  F.pairB[F.pairCount] = b
  F.pairHit[F.pairCount] = 0
  F.pairCount++
}

/**
 * Ball eid is a candidate next tick, with the resting balls it touches, even if it rests by then: a ball
 * the projection moved, or one that came to rest (it may have stopped inside another).
 */
export function touchBall(F: FixedContactState, eid: number): void {
  F.touched = appendId(F.touched, F.touchedCount++, eid)
}
