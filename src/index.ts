// `positron-ball-physics`: the game API. A simulation behind createBallPhysics, the config and its presets,
// the built-in panel, a fixed-step clock, the events, and the regime curves for overlays and charts.
// Games that run their own loop or add their own systems use `positron-ball-physics/ecs`; the rigid-sphere
// reference is `positron-ball-physics/reference`.
export { createBallPhysics } from './api/createBallPhysics.js'
export type { BallPhysics } from './api/createBallPhysics.js'
export type { BallSpec, BallState, HoleState, ThrowSpec } from './commands/balls.js'
export type { HoleSpec } from './commands/holes.js'
export type { WallsSpec } from './commands/walls.js'
export type { BallWorldOptions } from './world/createWorld.js'
export { MAX_COORDINATE, MAX_MASS, MAX_RADIUS, MAX_SPEED, MAX_VALUE, MIN_MASS, MIN_OUTCOME_STEP, MIN_TABLE_RATIO } from './config/limits.js'
export {
  CAPTURE_WINDOW_SHAPES,
  RIM_MODELS,
  COLLISION_MODES,
  CONTACT_TIMINGS,
  CONFIG_CHOICES,
  CONFIG_RANGES,
  DEFAULT_CONFIG,
  METHODS,
  gravityFromSkip,
  resolveConfig,
  skipFromGravity,
} from './config/design.js'
export type { BallPhysicsConfig, CaptureWindowShape, CollisionMode, ConfigOverrides, ContactTiming, RimModel, SimulationMethod } from './config/design.js'
export { PHYSICAL_CONFIG, TABULATED_CONFIG } from './config/presets.js'
export { prepareRimTable, tabulatedCaptureSpeed } from './reference/rimTables.js'
export { DEFAULT_PANEL, addPanel } from './panel.js'
export type { PanelHole, PanelLayout } from './panel.js'
export { createFixedStepClock } from './clock.js'
export type { FixedStepClock, FixedStepClockOptions } from './clock.js'
export { SNAPSHOT_VERSION } from './commands/snapshot.js'
export { SnapshotError } from './commands/snapshotCodec.js'
export { REPLAY_VERSION, replayFromJSON, replayToJSON } from './commands/replay.js'
export type { Replay } from './commands/replay.js'
export type { ReplayInput } from './world/recorder.js'
export { createReplayPlayer } from './api/replayPlayer.js'
export { solveThrow } from './api/solveThrow.js'
export { mulberry32 } from './random.js'
export { mergeTallies, outcomeMap, sampleThrows, summarizeOutcomes } from './api/outcomes.js'
export type { OutcomeMapSpec, OutcomeScene, OutcomeSummary, OutcomeTally, ThrowDistribution } from './api/outcomes.js'
export type { ThrowFailure, ThrowOutcome, ThrowRequest, ThrowSolution } from './api/solveThrow.js'
export type { ReplayPlayer } from './api/replayPlayer.js'
export type { ScheduleEntry, System } from './schedule.js'
export { EVENT_TYPE_NAMES } from './events.js'
export type { BallEvent, BallEventType, BallOnlyEvent, CaptureEvent, CaptureViaName, CollisionEvent, EventView, HoleEvent } from './events.js'
export { BALL_MODE_NAMES } from '../components/Ball.js'
export type { BallModeName } from '../components/Ball.js'
export {
  captureSpeed,
  captureWindow,
  capturesClean,
  cogRadius,
  midRimDropSpeed,
  popArc,
  rimBounce,
  rollArc,
  rollDropTime,
  rollPopTime,
  rollRatioDelta,
  rollSpeed,
  speedAtDistance,
  stopDistance,
  stopTime,
  timeToDistance,
  vSkip,
} from './geometry.js'
