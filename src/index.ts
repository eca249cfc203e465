// Public entry point of the ball-physics module.
export { createBallPhysics, MAX_COORDINATE, MAX_MASS, MAX_RADIUS, MAX_SPEED, MAX_VALUE } from './api/createBallPhysics.js'
export type { BallPhysics, BallSpec, BallState, HoleSpec, HoleState, ThrowSpec, WallsSpec } from './api/createBallPhysics.js'
export { CAPTURE_WINDOW_SHAPES, COLLISION_MODES, CONFIG_CHOICES, CONFIG_RANGES, DEFAULT_CONFIG, METHODS, gravityFromSkip, resolveConfig, skipFromGravity } from './config/design.js'
export type { BallPhysicsConfig, CaptureWindowShape, CollisionMode, ConfigOverrides, SimulationMethod } from './config/design.js'
export { resolveContact } from './contacts/law.js'
export type { CollisionState } from './world/contactState.js'
export {
  acquireRim,
  addBallEntity,
  createBallWorld,
  ensureCapacity,
  forEachBall,
  isBall,
  releaseRim,
  removeBallEntity,
  rimSlot,
} from './world/createWorld.js'
export type { BallWorld, BallWorldData, BallWorldOptions, EntityIndex } from './world/createWorld.js'
export { DEFAULT_SCHEDULE, createSchedule, runSchedule } from './schedule.js'
export type { ScheduleEntry, System } from './schedule.js'
export { createFixedStepClock } from './clock.js'
export type { FixedStepClock, FixedStepClockOptions } from './clock.js'
export { EVENT_TYPE_NAMES } from './events.js'
export type { BallEvent, BallEventType, CaptureViaName } from './events.js'
export { DEFAULT_PANEL, addPanel } from './panel.js'
export { PHYSICAL_CONFIG } from './config/presets.js'
export type { PanelHole, PanelLayout } from './panel.js'
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
export { BALL_MODE_NAMES, BallMode, BallSchema } from '../components/Ball.js'
export type { BallModeName, BallStore } from '../components/Ball.js'
export { HoleSchema } from '../components/Hole.js'
export type { HoleStore } from '../components/Hole.js'
export { RIM_MODE_NAMES, RimContactSchema, RimMode } from '../components/RimContact.js'
export type { RimContactStore } from '../components/RimContact.js'
export { PathEvent, PathSchema } from '../components/Path.js'
export type { PathStore } from '../components/Path.js'
export { integrationSystem } from '../systems/integration.js'
export { skipOverSystem } from '../systems/skipOver.js'
export { captureSystem } from '../systems/capture.js'
export { cogGateSystem } from '../systems/cogGate.js'
export { bounceSystem } from '../systems/bounce.js'
export { rimRollSystem } from '../systems/rimRoll.js'
export { heroReferenceSystem, HERO_ROLL_TURN } from '../systems/heroReference.js'
export { wallsSystem } from '../systems/walls.js'
export { collisionsSystem } from '../systems/collisions.js'
export { WallEdge, WallsSchema } from '../components/Walls.js'
export type { WallsStore } from '../components/Walls.js'
