// The game API: a world, its schedule and clock behind a small typed surface. Every method is one of the
// commands (src/commands/) applied to this world; step runs the schedule with dt capped at MAX_STEP.
import type { BallPhysicsConfig, ConfigOverrides } from '../config/design.js'
import type { BallEvent, EventView } from '../events.js'
import {
  addBall,
  ballState,
  heldAhead,
  heldCount,
  holeState,
  isHeroBall,
  listBalls,
  listHoles,
  removeBall,
  setBallMass,
  setBallVelocity,
  setHeroBall,
  throwBall,
  type BallSpec,
  type BallState,
  type HoleState,
  type ThrowSpec,
} from '../commands/balls.js'
import { createBallWorld } from '../commands/createBallWorld.js'
import { drainEvents, drainEventsWith } from '../commands/events.js'
import { addHole, removeHole, type HoleSpec } from '../commands/holes.js'
import { clearWalls, setWalls, type WallsSpec } from '../commands/walls.js'
import { describe } from '../check.js'
import { createSchedule, runSchedule, type ScheduleEntry } from '../schedule.js'
import type { BallWorld, BallWorldOptions } from '../world/createWorld.js'
import { restoreWorld, snapshotWorld } from '../commands/snapshot.js'
import { startReplay, takeReplay, type Replay } from '../commands/replay.js'

export interface BallPhysics {
  readonly world: BallWorld
  readonly config: Readonly<BallPhysicsConfig>
  /** the pipeline, in order; editable (see src/schedule.ts) */
  readonly schedule: ScheduleEntry[]
  /** simulation time, s */
  readonly time: number
  addHole(spec: HoleSpec): number
  /** Removes a hole: balls on its rim leave on the tangent, balls in transit roll on, captured balls stay. */
  removeHole(hole: number): void
  addBall(spec: BallSpec): number
  throwBall(spec: ThrowSpec): number
  /** Advances by dt seconds (any finite dt > 0; more than MAX_STEP is cut to MAX_STEP). Returns the dt simulated. */
  step(dt: number): number
  /** Events since the last drain, in time order, as new objects. */
  drainEvents(): BallEvent[]
  /**
   * Events since the last drain, in the same order, passed to `visit` one at a time through one reused view
   * (copy what you keep); returns how many it passed. Allocates nothing: for games with many balls. `visit`
   * may command or step the world; what that records waits for the next drain. A ball or hole it removes is
   * named by none of the events the drain goes on to pass (its id may already be a new ball's). If `visit`
   * throws, the drain ends there and the events not yet given to it are dropped.
   */
  drainEventsWith(visit: (e: EventView) => void): number
  ballState(ball: number): BallState
  /** For a held ball, the held balls waiting ahead of it on its spot (they leave first); -1 for a ball not held. */
  heldAhead(ball: number): number
  /** How many balls wait held at their spots (contacts on: put down on another ball); 0 with contacts off. */
  heldCount(): number
  holeState(hole: number): HoleState
  /** Removes a ball (as bitECS removeEntity does): the simulation forgets it; its buffered events are dropped. */
  removeBall(ball: number): void
  /**
   * Sets a ball's velocity now: wakes a resting ball, re-aims a rolling one, and knocks a ball off a rim
   * (it leaves on a straight path, the hole locked until it is out). Captured and out balls cannot move.
   */
  setBallVelocity(ball: number, vx: number, vy: number): void
  /**
   * Makes a ball a hero (or not): from its next lip crossing on, the physical reference decides it instead
   * of the six stages (systems/heroReference.ts). Costs one reference run per hero lip crossing.
   */
  setHeroBall(ball: number, hero?: boolean): void
  /**
   * Sets a ball's mass for ball-ball contacts (units of a default ball, in [MIN_MASS, MAX_MASS]), from its
   * next contact on; with contacts off it is not kept (as addBall's).
   */
  setBallMass(ball: number, mass: number): void
  /** True for a hero ball. */
  isHeroBall(ball: number): boolean
  /** Puts walls round the panel (or replaces them); rolling balls are re-planned from where they are. */
  setWalls(spec: WallsSpec): void
  /** Removes the walls. */
  clearWalls(): void
  /** ids of the live balls, ascending (a new array) */
  balls(): number[]
  /** ids of the holes (a new array) */
  holes(): number[]
  /**
   * The whole simulation state as bytes (compact, versioned; src/commands/snapshot.ts). A game's own
   * components are not included. Not during a step.
   */
  snapshot(): Uint8Array
  /**
   * Gives this simulation — made with the same config, with no balls, holes or walls added yet — the
   * state in `bytes` (from snapshot()); stepping on gives the same bits as the original would. Bad,
   * truncated or mismatched bytes throw an error that says which, and change nothing.
   */
  restore(bytes: Uint8Array): void
  /**
   * Starts recording a replay: every command and step from now on (src/commands/replay.ts). A world that
   * already has balls or holes puts a snapshot of itself at the replay's start. Throws while a recording is
   * under way (stopRecording first: it returns that replay).
   */
  startRecording(): void
  /** Stops recording and returns the replay (plain data; replayToJSON for text). Throws when not recording. */
  stopRecording(): Replay
}

/** Creates a simulation with the design's constants, changed by `overrides` (validated). */
export function createBallPhysics(overrides: ConfigOverrides = {}, options: BallWorldOptions = {}): BallPhysics {
  return physicsFor(createBallWorld(overrides, options))
}

/** The game API over an existing world (with its config's schedule). */
export function physicsFor(w: BallWorld): BallPhysics {
  const cfg = w.config
  const schedule = createSchedule(cfg)
  return {
    world: w,
    config: cfg,
    schedule,
    get time() {
      return w.time
    },
    addHole: (spec) => addHole(w, spec),
    removeHole: (hole) => removeHole(w, hole),
    addBall: (spec) => addBall(w, spec),
    throwBall: (spec) => throwBall(w, spec),
    step(dt) {
      if (typeof dt !== 'number') throw new TypeError(`dt must be a number of seconds > 0, got ${describe(dt)}`)
      if (!Number.isFinite(dt) || dt <= 0) throw new RangeError(`dt must be a finite number of seconds > 0, got ${dt}`)
      // a long frame (a tab that slept) is not caught up: at most MAX_STEP of simulated time per call
      const h = dt > cfg.MAX_STEP ? cfg.MAX_STEP : dt
      runSchedule(w, schedule, h)
      return h
    },
    drainEvents: () => drainEvents(w),
    drainEventsWith: (visit) => drainEventsWith(w, visit),
    ballState: (ball) => ballState(w, ball),
    heldAhead: (ball) => heldAhead(w, ball),
    heldCount: () => heldCount(w),
    holeState: (hole) => holeState(w, hole),
    removeBall: (ball) => removeBall(w, ball),
    setBallVelocity: (ball, vx, vy) => setBallVelocity(w, ball, vx, vy),
    setHeroBall: (ball, hero = true) => setHeroBall(w, ball, hero),
    setBallMass: (ball, mass) => setBallMass(w, ball, mass),
    isHeroBall: (ball) => isHeroBall(w, ball),
    setWalls: (spec) => setWalls(w, spec),
    clearWalls: () => clearWalls(w),
    balls: () => listBalls(w),
    holes: () => listHoles(w),
    snapshot: () => snapshotWorld(w),
    restore: (bytes) => restoreWorld(w, bytes),
    startRecording() {
      if (w.recorder !== null) throw new Error('startRecording: the simulation is already recording; call stopRecording first (it returns the replay so far)')
      startReplay(w)
    },
    stopRecording() {
      if (w.recorder === null) throw new Error('stopRecording: the simulation is not recording; call startRecording first')
      return takeReplay(w)
    },
  }
}
