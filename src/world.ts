// The simulation world: a bitECS world whose context carries this world's component stores, the resolved
// config, the clock and the event buffer. Stores are per world, so any number of worlds (one per test,
// one per game table) can live side by side without sharing entity ids or arrays.
import { createWorld, type World } from 'bitecs'
import { createBallStore, type BallStore } from '../components/Ball'
import { createHoleStore, type HoleStore } from '../components/Hole'
import { createPathStore, type PathStore } from '../components/Path'
import { createRimContactStore, type RimContactStore } from '../components/RimContact'
import { createWallsStore, type WallsStore } from '../components/Walls'
import { resolveConfig, type BallPhysicsConfig, type ConfigOverrides } from './config'
import { createEventBuffer, type EventBuffer } from './events'
import { GRID_MIN_HOLES, createHoleGrid, type HoleGrid } from './broadphase'
import { growStore } from './store'
import { createCollisionState, growCollisionState, type CollisionState } from './collide'

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
  RimContact: RimContactStore
  Path: PathStore
  Walls: WallsStore
  /** the entity carrying this world's Walls, 0 when the panel has none */
  walls: number
  /** the balls the integration system iterates */
  moving: MovingSet
  /** tag: the entity is a ball (balls and holes share the entity index) */
  IsBall: Record<string, never>
  /** tag: the entity is a hole */
  IsHole: Record<string, never>
  /** entity capacity of the stores; they grow when an id reaches it */
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
  /** entities preallocated in every store (the stores grow past it) */
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
  const data: BallWorldData = {
    config,
    Ball: createBallStore(capacity),
    Hole: createHoleStore(capacity),
    RimContact: createRimContactStore(capacity),
    Path: createPathStore(capacity),
    Walls: createWallsStore(capacity),
    walls: 0,
    moving: { count: 0, dense: new Uint32Array(256), sparse: new Uint32Array(capacity) },
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
  return createWorld(data)
}

/** Grows every store so that `eid` fits. */
export function ensureCapacity(world: BallWorld, eid: number): void {
  if (eid < world.capacity) return
  let cap = world.capacity
  while (cap <= eid) cap *= 2
  growStore(world.Ball, cap)
  growStore(world.Hole, cap)
  growStore(world.RimContact, cap)
  growStore(world.Path, cap)
  growStore(world.Walls, cap)
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
