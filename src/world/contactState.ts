// Ball-ball contact state (config.BALL_COLLISIONS = 'on'): masses, path versions, the resting grid's
// links, the swept-capsule hash, the event heap and scratch lists, all in typed arrays that grow by
// doubling, so nothing is allocated per ball per tick. A world with contacts off has none of it (null).
// The algorithms that use it are in src/contacts/.
import { createBallHash, type BallHash } from './ballHash.js'
import { MAX_CLUSTER } from '../config/tolerances.js'
import type { BallWorld } from './createWorld.js'

/** restBucket of a resting ball kept beside the grid (too wide for it) */
export const BESIDE_GRID = -2

/** Radius classes of the resting grid (a quarter octave each, from about 2⁻¹² to 2²⁰ px). */
export const RADIUS_CLASSES = 128

/** `until` of a state with no predictions (the next step builds them): before any step's end */
export const NO_WINDOW = -1

/** lastContact of a ball that has touched nothing yet: long before any simulated time */
export const NO_CONTACT = -1e300

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
  /** resting balls too wide for the grid (MAX_RESTING_CELLS), beside it; their restBucket is BESIDE_GRID */
  bigRest: Uint32Array
  bigRestCount: number
  /** moving balls too big or too fast for the swept-capsule hash in this window (MAX_CAPSULE_CELLS) */
  big: Uint32Array
  bigCount: number
  /**
   * Per ball: when its rolling path's closed form may change next, s (set by the planner: its next event,
   * or a later one when the events before it keep the path); a count of its path starts (startPath); and
   * at its last prediction, that count and the end of the span the prediction covered
   */
  formulaEnd: Float64Array
  gen: Uint32Array
  predGen: Uint32Array
  spanEnd: Float64Array
  /**
   * Per ball: the distance along its path at which the planner last found the closed form may change, and
   * the path's start count then. A plan of the same path that has not reached that distance (after a
   * skip-over, a near miss, a lip exit) reuses it and walks the holes only to its next event.
   */
  changeS: Float64Array
  changeGen: Uint32Array
  /** the sweep stamp at which each ball was last predicted (it has been predicted in this window when equal) */
  predicted: Uint32Array
  /**
   * End of the prediction window, s: the heap and the swept-capsule hash hold every contact before it of
   * the paths they were made with (docs/decisions.md §11); NO_WINDOW when they must be built again
   */
  until: number
  /** balls whose path changed since they were last predicted (set by pathChanged), each listed once */
  dirty: Uint32Array
  dirtyCount: number
  isDirty: Uint8Array
  /** resting balls per radius class (restingGrid.ts), each ball's class, and the highest class in use */
  restClassCount: Uint32Array
  restClass: Uint8Array
  restTopClass: number
  /**
   * An upper bound (within 19 %) on the radius of the resting balls now in the grid, px: resting balls are
   * looked up by centre cell, so a lookup widens by it. It shrinks when the largest resting balls leave.
   */
  maxRadius: number
  /** grid cell, px */
  cell: number
  /** swept-capsule hash: bucket heads (valid where stamp matches), entries as linked lists */
  sweepHead: Int32Array
  sweepStamp: Uint32Array
  stamp: number
  entNext: Int32Array
  entBall: Uint32Array
  /** the bucket of each entry (for compaction) */
  entBucket: Int32Array
  entCount: number
  /**
   * each ball's latest capsule in this step's hash: its first entry and entry count, valid where
   * entStep[ball] === stamp; an entry before its ball's first is stale (the ball has a newer capsule)
   */
  entStart: Int32Array
  entLen: Int32Array
  entStep: Uint32Array
  /** entries of the latest capsules (live); the hash is compacted when stale entries outnumber them */
  entLive: number
  /** per-query stamp by entity id, so a candidate is tested once per query */
  seen: Uint32Array
  seenStamp: number
  /** bucket indices of the capsule being rasterised */
  cells: Int32Array
  /** members of the touching cluster being settled */
  cluster: Uint32Array
  clusterCount: number
  /** the event heap (src/contacts/eventHeap.ts): each node's time and pool entry */
  hT: Float64Array
  hE: Uint32Array
  heapCount: number
  /** its entries' pool: balls, their path versions, kind; entries below eCount not in the heap are on eFree */
  eA: Uint32Array
  eB: Uint32Array
  eVA: Uint32Array
  eVB: Uint32Array
  eKind: Uint8Array
  eFree: Uint32Array
  eFreeCount: number
  eCount: number
  /** the moving balls by the cell of their centre at one world time (src/world/spotGrid.ts) */
  spot: BallHash
  /** the balls held at their spots, likewise (src/world/heldGrid.ts) */
  held: BallHash
  /**
   * contacts each ball took within one contact tick of the world's clock, [k·CONTACT_TICK, (k + 1)·CONTACT_TICK)
   * (valid where tickContactsAt[ball] === k + 1; 0: none yet)
   */
  tickContacts: Uint32Array
  tickContactsAt: Float64Array
  /** time of the last event handled, s */
  now: number
  /** contacts resolved since the world was made */
  contacts: number
  /** predictions of a moving ball's contacts since the world was made (a window's build predicts every moving ball) */
  predictions: number
  /** `predictions` and the moving balls when the current window was built (for the next window's length) */
  windowPredictions: number
  windowBalls: number
}

export function createCollisionState(capacity: number, ballRadius: number): CollisionState {
  const restBucket = new Int32Array(capacity)
  restBucket.fill(-1)
  return {
    mass: new Float64Array(capacity),
    ver: new Uint32Array(capacity),
    partner: new Uint32Array(capacity),
    lastContact: new Float64Array(capacity).fill(NO_CONTACT),
    restBucket,
    restNext: new Uint32Array(capacity),
    restPrev: new Uint32Array(capacity),
    restHead: new Uint32Array(1 << 12),
    restCount: 0,
    bigRest: new Uint32Array(16),
    bigRestCount: 0,
    big: new Uint32Array(16),
    bigCount: 0,
    formulaEnd: new Float64Array(capacity),
    gen: new Uint32Array(capacity),
    predGen: new Uint32Array(capacity),
    spanEnd: new Float64Array(capacity),
    changeS: new Float64Array(capacity),
    changeGen: new Uint32Array(capacity),
    predicted: new Uint32Array(capacity),
    until: NO_WINDOW,
    dirty: new Uint32Array(16),
    dirtyCount: 0,
    isDirty: new Uint8Array(capacity),
    restClassCount: new Uint32Array(RADIUS_CLASSES),
    restClass: new Uint8Array(capacity),
    restTopClass: -1,
    maxRadius: 0,
    cell: 4 * ballRadius,
    sweepHead: new Int32Array(1 << 10),
    sweepStamp: new Uint32Array(1 << 10),
    stamp: 0,
    entNext: new Int32Array(1 << 12),
    entBall: new Uint32Array(1 << 12),
    entBucket: new Int32Array(1 << 12),
    entCount: 0,
    entStart: new Int32Array(capacity),
    entLen: new Int32Array(capacity),
    entStep: new Uint32Array(capacity),
    entLive: 0,
    seen: new Uint32Array(capacity),
    seenStamp: 0,
    cells: new Int32Array(256),
    cluster: new Uint32Array(MAX_CLUSTER),
    clusterCount: 0,
    hT: new Float64Array(1 << 10),
    hE: new Uint32Array(1 << 10),
    heapCount: 0,
    eA: new Uint32Array(1 << 10),
    eB: new Uint32Array(1 << 10),
    eVA: new Uint32Array(1 << 10),
    eVB: new Uint32Array(1 << 10),
    eKind: new Uint8Array(1 << 10),
    eFree: new Uint32Array(1 << 10),
    eFreeCount: 0,
    eCount: 0,
    tickContacts: new Uint32Array(capacity),
    tickContactsAt: new Float64Array(capacity),
    spot: createBallHash(capacity, 1 << 8),
    held: createBallHash(capacity, 1 << 4),
    now: 0,
    contacts: 0,
    predictions: 0,
    windowPredictions: 0,
    windowBalls: 0,
  }
}

/** A copy of `a`, `n` long, the new tail filled with `fill`. */
export function grown<T extends Float64Array | Uint32Array | Int32Array | Uint8Array>(a: T, n: number, fill = 0): T {
  const next = new (a.constructor as new (n: number) => T)(n)
  next.set(a)
  if (fill !== 0) next.fill(fill, a.length)
  return next
}

/** A new stamp for C.seen (a ball is seen when its entry holds the stamp); the entries are cleared when the stamps wrap. */
export function nextSeenStamp(C: CollisionState): number {
  if (++C.seenStamp === 0xffffffff) {
    C.seen.fill(0)
    C.seenStamp = 1
  }
  return C.seenStamp
}

/** The key of the contact tick of the world's clock that time t falls in, [k·tick, (k + 1)·tick): k + 1 (0 is none). */
export function contactTickKey(t: number, contactTick: number): number {
  return Math.floor(t / contactTick) + 1
}

/** Adds n contacts of ball eid in the contact tick `key` (contactTickKey); returns its contacts in that tick so far. */
export function countContacts(C: CollisionState, eid: number, key: number, n: number): number {
  if (C.tickContactsAt[eid] !== key) {
    C.tickContactsAt[eid] = key
    C.tickContacts[eid] = 0
  }
  return (C.tickContacts[eid] = C.tickContacts[eid]! + n)
}

/** Grows the per-ball arrays to `capacity` entities. */
export function growCollisionState(C: CollisionState, capacity: number): void {
  if (C.mass.length >= capacity) return
  C.mass = grown(C.mass, capacity)
  C.ver = grown(C.ver, capacity)
  C.partner = grown(C.partner, capacity)
  C.lastContact = grown(C.lastContact, capacity, NO_CONTACT)
  C.restBucket = grown(C.restBucket, capacity, -1)
  C.restNext = grown(C.restNext, capacity)
  C.restPrev = grown(C.restPrev, capacity)
  C.restClass = grown(C.restClass, capacity)
  C.predicted = grown(C.predicted, capacity)
  C.formulaEnd = grown(C.formulaEnd, capacity)
  C.gen = grown(C.gen, capacity)
  C.predGen = grown(C.predGen, capacity)
  C.spanEnd = grown(C.spanEnd, capacity)
  C.changeS = grown(C.changeS, capacity)
  C.changeGen = grown(C.changeGen, capacity)
  C.isDirty = grown(C.isDirty, capacity)
  C.seen = grown(C.seen, capacity)
  C.spot.next = grown(C.spot.next, capacity)
  C.spot.linkedIn = grown(C.spot.linkedIn, capacity)
  C.held.next = grown(C.held.next, capacity)
  C.held.linkedIn = grown(C.held.linkedIn, capacity)
  C.entStart = grown(C.entStart, capacity)
  C.entLen = grown(C.entLen, capacity)
  C.entStep = grown(C.entStep, capacity)
  C.tickContacts = grown(C.tickContacts, capacity)
  C.tickContactsAt = grown(C.tickContactsAt, capacity)
}

/** Marks a ball's motion as changed: its heap entries become stale. */
export function bumpVersion(w: BallWorld, eid: number): void {
  const C = w.collide!
  C.ver[eid] = (C.ver[eid]! + 1) >>> 0
}

/**
 * A ball's path changed (planned again, stopped, put down): its contacts are predicted again at the next
 * pass of the integration system. Called by the path planner itself, so a command, a system or a game's
 * own code that moves a ball through the motion functions cannot leave a stale prediction behind.
 */
export function pathChanged(w: BallWorld, eid: number): void {
  const C = w.collide
  if (C === null || C.isDirty[eid] === 1) return
  C.isDirty[eid] = 1
  C.dirty = appendId(C.dirty, C.dirtyCount++, eid)
}

/** A ball leaves the world: its heap entries, its capsule in the hash and its listing as changed go stale. */
export function forgetPredictions(w: BallWorld, eid: number): void {
  const C = w.collide
  if (C === null) return
  bumpVersion(w, eid)
  C.isDirty[eid] = 0
  if (C.entStep[eid] === C.stamp) C.entLive -= C.entLen[eid]!
  C.entStep[eid] = 0
}

/** Drops every prediction: the next step predicts every moving ball again (after a change to all paths). */
export function dropPredictions(w: BallWorld): void {
  const C = w.collide
  if (C !== null) C.until = NO_WINDOW
}

/** Appends an id to one of the state's id arrays (grown by doubling); returns the array (it may be new). */
export function appendId(list: Uint32Array, count: number, eid: number): Uint32Array {
  const out = count === list.length ? grown(list, count * 2) : list
  out[count] = eid
  return out
}
