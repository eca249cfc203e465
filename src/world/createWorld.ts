// The simulation world: a bitECS world whose context carries this world's component stores, the resolved
// config, the clock and the event buffer. Stores are per world, so any number of worlds (one per test,
// one per game table) can live side by side without sharing entity ids or arrays.
//
// Holes and the walls are full bitECS entities, with their tags and components. Balls are lightweight
// entities: their ids come from the same entity index (so ids are shared and `entityExists` holds for a
// live ball), but they get no bitECS component bookkeeping, which costs a Set and a Map entry per entity
// plus query and mask entries per component: about 230 bytes of JS heap per ball. Their data lives in the
// stores below, indexed by ball id; Ball.live marks which ids are balls. Each store has its own length
// (src/store.ts): the per-ball ones grow with ball ids, Hole and Walls with their own entities' ids, and
// RimContact is pooled by slot (components/RimContact.ts).
import { createEntityIndex, createWorld, type World } from 'bitecs'
import { createBallStore, type BallStore } from '../../components/Ball.js'
import { createHoleStore, type HoleStore } from '../../components/Hole.js'
import { createPathStore, type PathStore } from '../../components/Path.js'
import { createRimContactStore, type RimContactStore } from '../../components/RimContact.js'
import { createWallsStore, type WallsStore } from '../../components/Walls.js'
import { resolveConfig, type BallPhysicsConfig, type ConfigOverrides } from '../config/design.js'
import { createEventBuffer, type EventBuffer } from '../events.js'
import { GRID_MIN_HOLES, createHoleGrid, type HoleGrid } from './holeGrid.js'
import { clearSlot, growStore } from '../../components/store.js'
import { bumpVersion, createCollisionState, growCollisionState, type CollisionState } from './contactState.js'
import { restingRemove } from './restingGrid.js'

/** A growable list of entity ids. */
export interface IdList {
  count: number
  ids: Uint32Array
}

export function createIdList(capacity = 256): IdList {
  return { count: 0, ids: new Uint32Array(capacity) }
}

export function pushId(list: IdList, eid: number): void {
  if (list.count === list.ids.length) {
    const next = new Uint32Array(list.ids.length * 2)
    next.set(list.ids)
    list.ids = next
  }
  list.ids[list.count++] = eid
}

/**
 * The balls that move (rolling or on a rim), as a sparse set: O(1) insert and remove with no allocation,
 * so a ball that stops or falls in costs nothing afterwards. (A bitECS tag did the same job at about a
 * quarter of the dense-scene step time, in add/remove bookkeeping and garbage.)
 */
export interface MovingSet {
  count: number
  dense: Uint32Array
  /** index in `dense` by entity id; valid only where dense[sparse[eid]] === eid */
  sparse: Uint32Array
}

export function isMoving(world: BallWorld, eid: number): boolean {
  const m = world.moving
  const i = m.sparse[eid]!
  return i < m.count && m.dense[i] === eid
}

export function addMoving(world: BallWorld, eid: number): void {
  if (isMoving(world, eid)) return
  const m = world.moving
  if (m.count === m.dense.length) {
    const next = new Uint32Array(m.dense.length * 2)
    next.set(m.dense)
    m.dense = next
  }
  m.sparse[eid] = m.count
  m.dense[m.count++] = eid
}

/** Removes by swapping the last element in; callers iterating `dense` go from the end to the start. */
export function removeMoving(world: BallWorld, eid: number): void {
  if (!isMoving(world, eid)) return
  const m = world.moving
  const i = m.sparse[eid]!
  const last = m.dense[--m.count]!
  m.dense[i] = last
  m.sparse[last] = i
}

/** bitECS's entity index, shared by balls, holes and walls. */
export type EntityIndex = ReturnType<typeof createEntityIndex>

/**
 * Takes an entity id from the index, recycling the most recently freed one first, as bitECS's own
 * addEntity does. (bitECS 0.4 keeps its addEntityId/removeEntityId internal, so these two mirror them on
 * the index object it returns; tests/world.test.ts checks that they interoperate with bitECS's addEntity,
 * removeEntity and entityExists.)
 */
function takeEntityId(index: EntityIndex): number {
  if (index.aliveCount < index.dense.length) {
    const id = index.dense[index.aliveCount]!
    index.sparse[id] = index.aliveCount++
    return id
  }
  const id = ++index.maxId
  index.dense.push(id)
  index.sparse[id] = index.aliveCount++
  return id
}

/** Returns a live id to the index (swapped behind the live ones, first in line for reuse). */
function freeEntityId(index: EntityIndex, id: number): void {
  const i = index.sparse[id]
  if (i === undefined || i >= index.aliveCount) return
  const last = index.aliveCount - 1
  const lastId = index.dense[last]!
  index.sparse[lastId] = i
  index.dense[i] = lastId
  index.sparse[id] = last
  index.dense[last] = id
  index.aliveCount--
}

/** Makes a ball entity: an id from the entity index, the per-ball stores grown to it and its rows zeroed. */
export function addBallEntity(world: BallWorld): number {
  const eid = takeEntityId(world.entityIndex)
  ensureCapacity(world, eid)
  clearSlot(world.Ball, eid)
  clearSlot(world.Path, eid)
  world.Ball.live[eid] = 1
  return eid
}

/** Removes a ball entity: it stops moving, gives back its RimContact slot, its rows are zeroed, its id freed. */
export function removeBallEntity(world: BallWorld, eid: number): void {
  if (!isBall(world, eid)) return
  removeMoving(world, eid)
  releaseRim(world, eid)
  if (world.collide !== null) {
    restingRemove(world, eid)
    bumpVersion(world, eid)
  }
  clearSlot(world.Ball, eid)
  clearSlot(world.Path, eid)
  freeEntityId(world.entityIndex, eid)
}

/** True when `eid` is a live ball of this world. */
export function isBall(world: BallWorld, eid: number): boolean {
  return eid > 0 && eid < world.capacity && world.Ball.live[eid] === 1
}

/** Calls `fn` for every live ball, in ascending id order. */
export function forEachBall(world: BallWorld, fn: (eid: number) => void): void {
  const live = world.Ball.live
  for (let eid = 1, n = Math.min(live.length, world.entityIndex.maxId + 1); eid < n; eid++) if (live[eid] === 1) fn(eid)
}

/** The ball's RimContact slot: 0, the all-zero row (hole 0, mode None), when it holds no hole lock. */
export function rimSlot(world: BallWorld, eid: number): number {
  return world.Ball.rim[eid]!
}

/**
 * The ball's RimContact slot, taking one for it if it has none (a taken row is all zero). Call it where a
 * ball gets a hole lock, before writing its row; the store may grow, so fetch arrays after the call.
 */
export function acquireRim(world: BallWorld, eid: number): number {
  const held = world.Ball.rim[eid]!
  if (held !== 0) return held
  const pool = world.rimFree
  const slot = pool.count > 0 ? pool.ids[--pool.count]! : world.rimNext++
  if (slot >= world.RimContact.hole.length) growStore(world.RimContact, 2 * world.RimContact.hole.length)
  world.Ball.rim[eid] = slot
  return slot
}

/**
 * Takes a hole lock for a ball at its lip crossing: a RimContact slot recording the hole, (δ, v), the
 * crossing's time and the rim mode. Returns the slot.
 */
export function lockAtLip(world: BallWorld, eid: number, hole: number, delta: number, speed: number, t: number, mode: number): number {
  const rim = acquireRim(world, eid)
  const RC = world.RimContact
  RC.hole[rim] = hole
  RC.mode[rim] = mode
  RC.hasLip[rim] = 1
  RC.delta[rim] = delta
  RC.speed[rim] = speed
  RC.lipTime[rim] = t
  return rim
}

/** Gives back the ball's RimContact slot (zeroed) when its hole lock ends; a no-op when it has none. */
export function releaseRim(world: BallWorld, eid: number): void {
  const slot = world.Ball.rim[eid]!
  if (slot === 0) return
  // every field, written out: this runs at each lock's end (clearSlot's generic loop costs more)
  const RC = world.RimContact
  RC.hole[slot] = 0
  RC.mode[slot] = 0
  RC.hasLip[slot] = 0
  RC.delta[slot] = 0
  RC.speed[slot] = 0
  RC.lipTime[slot] = 0
  RC.angle[slot] = 0
  RC.arc[slot] = 0
  RC.angle0[slot] = 0
  RC.speed0[slot] = 0
  RC.direction[slot] = 0
  RC.time0[slot] = 0
  pushId(world.rimFree, slot)
  world.Ball.rim[eid] = 0
}

/** Holes packed for the planner's scan: x, y, R per hole, and the entity ids in the same order. */
export interface HoleTable {
  count: number
  xyr: Float64Array
  ids: Uint32Array
}

export interface BallWorldData {
  config: Readonly<BallPhysicsConfig>
  Ball: BallStore
  Hole: HoleStore
  /** pooled: indexed by a ball's slot (Ball.rim), not by its id */
  RimContact: RimContactStore
  Path: PathStore
  Walls: WallsStore
  /** the entity carrying this world's Walls, 0 when the panel has none */
  walls: number
  /** the balls the integration system iterates */
  moving: MovingSet
  /** the world's entity index (passed to createWorld): ids of balls, holes and walls */
  entityIndex: EntityIndex
  /** RimContact slots given back, for reuse */
  rimFree: IdList
  /** next RimContact slot never handed out (slot 0 is the empty row) */
  rimNext: number
  /**
   * @deprecated Balls carry no bitECS components (see the top of src/world.ts): this tag is on no entity.
   * Use isBall(world, eid) and forEachBall(world, fn), or BallPhysics.balls().
   */
  IsBall: Record<string, never>
  /** tag: the entity is a hole */
  IsHole: Record<string, never>
  /** capacity of the per-ball stores (Ball, Path, the moving set's index): they grow when a ball id reaches it */
  capacity: number
  /** simulation time at the end of the last step, s */
  time: number
  /** end of the step being run, s */
  tickEnd: number
  /** event pass within the step being run (0 = the pass over every moving ball) */
  pass: number
  holes: HoleTable
  /** broadphase over `holes`, rebuilt when they change */
  holeGrid: HoleGrid
  /** hole count from which the planner walks the grid (0: always; Infinity: never) */
  gridFrom: number
  /** balls stopped at an event in this pass, for the decision systems */
  marked: IdList
  /** the previous pass's marked balls, which the integration system continues */
  todo: IdList
  events: EventBuffer
  /** ball-ball contact state when config.BALL_COLLISIONS is 'on', else null */
  collide: CollisionState | null
}

export type BallWorld = World<BallWorldData>

export interface BallWorldOptions {
  /**
   * ids preallocated in the per-ball stores (they grow past it). Hole, Walls and RimContact start small
   * and grow with their own use.
   */
  capacity?: number
  /**
   * How a ball's path is tested against the holes: 'scan' tests every hole, 'grid' walks a uniform grid,
   * 'auto' (default) scans below GRID_MIN_HOLES holes and walks the grid above. Outcomes are the same.
   */
  broadphase?: 'auto' | 'grid' | 'scan'
}

/**
 * Creates an empty world. Games that run their own schedule start here; `createBallPhysics` wraps it
 * with the public API.
 */
export function createBallWorld(overrides: ConfigOverrides = {}, options: BallWorldOptions = {}): BallWorld {
  const config = resolveConfig(overrides)
  const capacity = options.capacity ?? 1024
  const broadphase = options.broadphase ?? 'auto'
  if (broadphase !== 'auto' && broadphase !== 'grid' && broadphase !== 'scan') {
    throw new RangeError(`options.broadphase must be 'auto', 'grid' or 'scan', got ${String(broadphase)}`)
  }
  if (!Number.isInteger(capacity) || capacity < 1 || capacity > 1 << 26) {
    throw new RangeError(`options.capacity must be an integer in [1, ${1 << 26}], got ${capacity}`)
  }
  const entityIndex = createEntityIndex()
  if (entityIndex.versioning) throw new Error('createBallWorld: the entity index must not version its ids')
  const data: BallWorldData = {
    config,
    Ball: createBallStore(capacity),
    Hole: createHoleStore(SMALL_STORE),
    RimContact: createRimContactStore(SMALL_STORE),
    Path: createPathStore(capacity),
    Walls: createWallsStore(SMALL_STORE),
    walls: 0,
    moving: { count: 0, dense: new Uint32Array(256), sparse: new Uint32Array(capacity) },
    entityIndex,
    rimFree: createIdList(SMALL_STORE),
    rimNext: 1,
    IsBall: {},
    IsHole: {},
    capacity,
    time: 0,
    tickEnd: 0,
    pass: 0,
    holes: { count: 0, xyr: new Float64Array(3 * 16), ids: new Uint32Array(16) },
    holeGrid: createHoleGrid(),
    gridFrom: broadphase === 'grid' ? 0 : broadphase === 'scan' ? Infinity : GRID_MIN_HOLES,
    marked: createIdList(),
    todo: createIdList(),
    events: createEventBuffer(),
    collide: config.BALL_COLLISIONS === 'on' ? createCollisionState(capacity, config.BALL_RADIUS) : null,
  }
  return createWorld<BallWorldData>(data, entityIndex)
}

/** Initial length of the stores that do not grow with balls (Hole, Walls, RimContact). */
const SMALL_STORE = 64

/** Grows the per-ball stores (Ball, Path, the moving set's index) so that ball id `eid` fits. */
export function ensureCapacity(world: BallWorld, eid: number): void {
  if (eid < world.capacity) return
  let cap = world.capacity
  while (cap <= eid) cap *= 2
  growStore(world.Ball, cap)
  growStore(world.Path, cap)
  const sparse = new Uint32Array(cap)
  sparse.set(world.moving.sparse)
  world.moving.sparse = sparse
  if (world.collide !== null) growCollisionState(world.collide, cap)
  world.capacity = cap
}

/** Appends a hole to the planner's table. */
export function addHoleToTable(world: BallWorld, eid: number): void {
  const t = world.holes
  if (t.count === t.ids.length) {
    const xyr = new Float64Array(t.xyr.length * 2)
    xyr.set(t.xyr)
    const ids = new Uint32Array(t.ids.length * 2)
    ids.set(t.ids)
    t.xyr = xyr
    t.ids = ids
  }
  const i = t.count++
  t.xyr[3 * i] = world.Hole.x[eid]!
  t.xyr[3 * i + 1] = world.Hole.y[eid]!
  t.xyr[3 * i + 2] = world.Hole.radius[eid]!
  t.ids[i] = eid
  world.holeGrid.dirty = true
}
