// The simulation world: a bitECS world whose context carries this world's component stores, the resolved
// config, the clock and the event buffer. Stores are per world, so any number of worlds (one per test,
// one per game table) can live side by side without sharing entity ids or arrays.
//
// Balls, holes and the walls are bitECS entities. A ball carries the Ball and Path components, and
// RimContact while a hole holds it; a hole carries Hole (and the IsHole tag); the walls carry Walls. A game
// may put its own components on any of them and query them together with these. Component data lives in
// struct-of-arrays stores (components/store.ts): Ball and Path indexed by entity id, Hole and Walls by
// entity id but grown only by their own entities, RimContact pooled by slot (Ball.rim).
//
// This file makes the data; src/commands/createBallWorld.ts makes a world ready to simulate (it adds the
// observers that keep the simulation in step with bitECS's addComponent/removeComponent/removeEntity).
import { createEntityIndex, createWorld, type World } from 'bitecs'
import { createBallStore, type BallStore } from '../../components/Ball.js'
import { createHoleStore, type HoleStore } from '../../components/Hole.js'
import { createPathStore, type PathStore } from '../../components/Path.js'
import { createRimContactStore, type RimContactStore } from '../../components/RimContact.js'
import { growStore } from '../../components/store.js'
import { createWallsStore, type WallsStore } from '../../components/Walls.js'
import type { BallPhysicsConfig } from '../config/design.js'
import { createEventBuffer, type EventBuffer } from '../events.js'
import { createCollisionState, growCollisionState, type CollisionState } from './contactState.js'
import { createFixedState, growFixedMass, grownTo, type FixedContactState } from './fixedState.js'
import { createMeetState, growMeetState, type MeetState } from './meetState.js'
import { GRID_MIN_HOLES } from '../config/tolerances.js'
import { createHoleGrid, type HoleGrid } from './holeGrid.js'
import { createHoleTable, type HoleCells, type HoleTable } from './holeTable.js'
import { HOT, growPathHot } from './pathHot.js'
import { createIdList, type IdList, type MovingSet } from './idLists.js'
import type { RimTable } from '../reference/rimTable.js'
import type { Recorder } from './recorder.js'

export type { HoleTable } from './holeTable.js'
export type { IdList, MovingSet } from './idLists.js'

/** bitECS's entity index, shared by balls, holes and walls. */
export type EntityIndex = ReturnType<typeof createEntityIndex>

export interface BallWorldData {
  config: Readonly<BallPhysicsConfig>
  Ball: BallStore
  Hole: HoleStore
  /** pooled: indexed by a ball's slot (Ball.rim), not by its id */
  RimContact: RimContactStore
  Path: PathStore
  /** each ball's path and next event's time and distance, one interleaved row an id (src/world/pathHot.ts) */
  pathHot: Float64Array
  Walls: WallsStore
  /** the entity carrying this world's Walls, 0 when the panel has none */
  walls: number
  /** the balls the integration system iterates */
  moving: MovingSet
  /** the world's entity index (passed to createWorld): ids of balls, holes and walls */
  entityIndex: EntityIndex
  /** RimContact slots given back, for reuse */
  rimFree: IdList
  /** the tabulated rim model's tables this world may use (its config's, and those prepareRimTable added) */
  rimTables: RimTable[]
  /** next RimContact slot never handed out (slot 0 is the empty row) */
  rimNext: number
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
  /** the holes by cell, for overlap checks (derived from `holes` when first needed; not in snapshots) */
  holeCells: HoleCells | null
  /** live balls (forEachBall walks no ids when there are none: a panel of holes is built in linear time) */
  ballCount: number
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
  /** fixed-tick contact state when config.BALL_COLLISIONS is 'fixed', else null */
  fixed: FixedContactState | null
  /** the fixed tick's pairs alone at their tick that meet at their instant (src/contacts/fixedMeet.ts); null without it */
  meet: MeetState | null
  /** true while runSchedule runs (a nested step is refused) */
  stepping: boolean
  /**
   * Per-ball stores kept outside the core (indexed by ball id, made with components/store.ts), such as the
   * tick-sampled methods' state: their rows are zeroed when an id becomes a ball, so a reused id inherits
   * nothing. Register a store by pushing it here.
   */
  ballStores: object[]
  /** balls held at their spawn spot until it is clear (ball-ball contacts on), in the order they came */
  held: IdList
  /**
   * held balls removed between steps and still in `held`: they leave it in one pass when the queue is next
   * read (dropGoneHeld, src/world/idLists.ts), so that removing n held balls costs O(n + queue), not O(n · queue)
   */
  heldGone: number
  /**
   * true during a window that starts on a launch instant (k·CONTACT_TICK of the world's clock; with the
   * fixed tick, any of its ticks) while balls are held: the launcher acts only then (set by the step,
   * src/schedule.ts)
   */
  launchDue: boolean
  /** balls the launcher has knocked off its spots since the world was made (systems/launcher.ts) */
  kicks: number
  /**
   * by ball id, for a ball the launcher has knocked off a spot: its kicks in a row, and the world time
   * before which it is kicked no more (systems/launcher.ts: a ball jammed on a spot is kicked less and less
   * often; the kicked ball's own, so such a spot delays no other); zeroed when an id becomes a ball
   */
  kickStreak: Uint8Array
  kickAfter: Float64Array
  /** the inputs recorded for a replay while the world records (src/commands/replay.ts), else null */
  recorder: Recorder | null
  /**
   * Why the world stopped: set when a step was ended part-done by an error (a system threw), else null.
   * Such a world refuses every later step and every command that would change it (src/check.ts).
   */
  failed: string | null
}

export type BallWorld = World<BallWorldData>

export interface BallWorldOptions {
  /**
   * ids preallocated in the per-ball stores (they grow past it). Hole, Walls and RimContact start small
   * and grow with their own use.
   */
  capacity?: number | undefined
  /**
   * How a ball's path is tested against the holes: 'scan' tests every hole, 'grid' walks a uniform grid,
   * 'auto' (default) scans below GRID_MIN_HOLES holes and walks the grid above. Outcomes are the same.
   */
  broadphase?: 'auto' | 'grid' | 'scan' | undefined
}

/** Initial length of the stores that do not grow with balls (Hole, Walls, RimContact). */
const SMALL_STORE = 64

/**
 * The world's data for a resolved config and validated options: empty stores, no entities. Use
 * createBallWorld (src/commands/createBallWorld.ts), which validates and wires the world up.
 */
export function createWorldData(config: Readonly<BallPhysicsConfig>, capacity: number, gridFrom: number): BallWorld {
  const entityIndex = createEntityIndex()
  const data: BallWorldData = {
    config,
    Ball: createBallStore(capacity),
    Hole: createHoleStore(SMALL_STORE),
    RimContact: createRimContactStore(SMALL_STORE),
    Path: createPathStore(capacity),
    pathHot: new Float64Array(capacity * HOT),
    Walls: createWallsStore(SMALL_STORE),
    walls: 0,
    moving: { count: 0, dense: new Uint32Array(256), sparse: new Uint32Array(capacity), churn: 0, spare: new Uint32Array(256) },
    entityIndex,
    rimFree: createIdList(SMALL_STORE),
    rimTables: [],
    rimNext: 1,
    IsHole: {},
    capacity,
    time: 0,
    tickEnd: 0,
    pass: 0,
    holes: createHoleTable(),
    holeCells: null,
    ballCount: 0,
    holeGrid: createHoleGrid(),
    gridFrom,
    marked: createIdList(),
    todo: createIdList(),
    events: createEventBuffer(),
    collide: config.BALL_COLLISIONS === 'on' ? createCollisionState(capacity, config.BALL_RADIUS) : null,
    fixed: config.BALL_COLLISIONS === 'fixed' ? createFixedState(capacity, config) : null,
    meet: config.BALL_COLLISIONS === 'fixed' ? createMeetState(capacity) : null,
    stepping: false,
    ballStores: [],
    held: createIdList(16),
    heldGone: 0,
    launchDue: false,
    kicks: 0,
    kickStreak: new Uint8Array(capacity),
    kickAfter: new Float64Array(capacity),
    recorder: null,
    failed: null,
  }
  const w = createWorld<BallWorldData>(data, entityIndex)
  bufferWorlds.set(w.events, w)
  return w
}

/**
 * Each world's event buffer, to its world: the ecs entry's pushEvent is given the buffer alone, and checks
 * the ball, the hole and the time against the world's (the buffer is the world's for its life: growing it
 * and restoring a snapshot write into it).
 */
const bufferWorlds = new WeakMap<EventBuffer, BallWorld>()

/** The world whose event buffer `buf` is, if any. */
export function worldOfEvents(buf: EventBuffer): BallWorld | undefined {
  return bufferWorlds.get(buf)
}

/** The hole count from which the planner walks the grid, for a broadphase option. */
export function gridThreshold(broadphase: 'auto' | 'grid' | 'scan'): number {
  return broadphase === 'grid' ? 0 : broadphase === 'scan' ? Infinity : GRID_MIN_HOLES
}

/** Grows the per-ball stores (Ball, Path, the moving set's index) so that ball id `eid` fits. */
export function ensureCapacity(world: BallWorld, eid: number): void {
  if (eid < world.capacity) return
  let cap = world.capacity
  while (cap <= eid) cap *= 2
  growStore(world.Ball, cap)
  growStore(world.Path, cap)
  growPathHot(world, cap)
  const sparse = new Uint32Array(cap)
  sparse.set(world.moving.sparse)
  world.moving.sparse = sparse
  world.kickStreak = grownTo(world.kickStreak, cap)
  world.kickAfter = grownTo(world.kickAfter, cap)
  if (world.collide !== null) growCollisionState(world.collide, cap)
  if (world.fixed !== null) {
    growFixedMass(world.fixed, cap)
    growMeetState(world.meet!, cap)
    growCollisionState(world.fixed.rest, cap)
  }
  world.capacity = cap
}
