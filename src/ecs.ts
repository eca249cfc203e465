// `positron-ball-physics/ecs`: the bitECS world, its components, the commands that change it, the systems
// and the schedule, and what a game's own system needs. Balls, holes and the walls are bitECS entities: a
// game may put its own components on them, query them together with ours, and remove them with bitECS's
// removeEntity. createBallPhysics (the main entry) is a thin facade over the same functions.

// world
export { createBallWorld } from './commands/createBallWorld.js'
export type { BallWorld, BallWorldData, BallWorldOptions, EntityIndex, IdList } from './world/createWorld.js'
export { forEachBall, isBall } from './world/balls.js'
export { rimSlot } from './world/rimSlots.js'

// schedule
export { DEFAULT_SCHEDULE, createSchedule, runSchedule, v1Schedule } from './schedule.js'
export type { ScheduleEntry, System } from './schedule.js'

// commands
export {
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
  throwVelocity,
} from './commands/balls.js'
export type { BallSpec, BallState, HoleState, ThrowSpec } from './commands/balls.js'
export { addHole, addHoles, removeHole } from './commands/holes.js'
export type { HoleSpec } from './commands/holes.js'
export { clearWalls, setWalls } from './commands/walls.js'
export type { WallsSpec } from './commands/walls.js'
export { drainEvents, drainEventsWith } from './commands/events.js'
export { SNAPSHOT_VERSION, restoreWorld, snapshotWorld } from './commands/snapshot.js'
export { SnapshotError } from './commands/snapshotCodec.js'
export { REPLAY_VERSION, createReplayPlayer, playReplay, replayFromJSON, replayToJSON, startReplay, takeReplay } from './commands/replay.js'
export type { Replay, ReplayPlayer } from './commands/replay.js'
export type { ReplayInput } from './world/recorder.js'

// components
export { BALL_MODE_NAMES, BallMode, BallSchema } from '../components/Ball.js'
export type { BallModeCode, BallModeName, BallStore } from '../components/Ball.js'
export { HoleSchema } from '../components/Hole.js'
export type { HoleStore } from '../components/Hole.js'
export { RIM_MODE_NAMES, RimContactSchema, RimMode } from '../components/RimContact.js'
export type { RimContactStore, RimModeCode } from '../components/RimContact.js'
export { PathEvent, PathSchema } from '../components/Path.js'
export type { PathEventCode, PathStore } from '../components/Path.js'
/** a ball's path and next event's time and distance: world.pathHot[eid * HOT + H_X0], and so on */
export { HOT, H_NEXT_S, H_NEXT_T, H_T0, H_UX, H_UY, H_V0, H_X0, H_Y0 } from './world/pathHot.js'
export { WallEdge, WallsSchema } from '../components/Walls.js'
export type { WallsStore } from '../components/Walls.js'

// for a game's own systems: events, and the motion a decision restarts
export { CaptureVia, EventType } from './events.js'
export type { BallEvent, BallOnlyEvent, CaptureEvent, CaptureViaCode, CollisionEvent, EventTypeCode, EventView, HoleEvent } from './events.js'
// checked (src/commands/systemMotion.ts): a bad argument throws naming it, before anything changes
export {
  captureBall,
  emitHoleEvent,
  launchBall,
  lockAtLip,
  planRimRoll,
  planRolling,
  pushEvent,
  releaseRim,
  restBall,
  sampleAtDistance,
  sampleRimRoll,
  sampleRolling,
  startPath,
  startRimRoll,
} from './commands/systemMotion.js'

// systems, in the default schedule's order
export { launcherSystem } from '../systems/launcher.js'
export { fixedContactsSystem } from '../systems/fixedContacts.js'
export { integrationSystem } from '../systems/integration.js'
export { heroReferenceSystem } from '../systems/heroReference.js'
export { tabulatedRimSystem } from '../systems/tabulatedRim.js'
export { skipOverSystem } from '../systems/skipOver.js'
export { captureSystem } from '../systems/capture.js'
export { cogGateSystem } from '../systems/cogGate.js'
export { bounceSystem } from '../systems/bounce.js'
export { rimRollSystem } from '../systems/rimRoll.js'
export { wallsSystem } from '../systems/walls.js'
export { collisionsSystem } from '../systems/collisions.js'
