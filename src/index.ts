// Public entry point of the ball-physics module.
export { createBallPhysics, MAX_COORDINATE, MAX_MASS, MAX_RADIUS, MAX_SPEED, MAX_VALUE } from './api'
export type { BallPhysics, BallSpec, BallState, HoleSpec, HoleState, ThrowSpec, WallsSpec } from './api'
export { CAPTURE_WINDOW_SHAPES, COLLISION_MODES, CONFIG_CHOICES, CONFIG_RANGES, DEFAULT_CONFIG, METHODS, gravityFromSkip, resolveConfig, skipFromGravity } from './config'
export type { BallPhysicsConfig, CaptureWindowShape, CollisionMode, ConfigOverrides, SimulationMethod } from './config'
export {
  APPROACH_EPSILON,
  CONTACT_DURATION,
  GAP_TOLERANCE,
  MIN_ADVANCE,
  SETTLE_FLOOR,
  contactOut,
  resolveContact,
  restingInsert,
  restingRemove,
} from './collide'
export type { CollisionState } from './collide'
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
} from './world'
export type { BallWorld, BallWorldData, BallWorldOptions, EntityIndex } from './world'
export { DEFAULT_SCHEDULE, createSchedule, runSchedule } from './schedule'
export type { ScheduleEntry, System } from './schedule'
export { createFixedStepClock } from './clock'
export type { FixedStepClock, FixedStepClockOptions } from './clock'
export { EVENT_TYPE_NAMES } from './events'
export type { BallEvent, BallEventType, CaptureViaName } from './events'
export { DEFAULT_PANEL, addPanel } from './panel'
export { PHYSICAL_CONFIG } from './physical/preset'
export type { PanelHole, PanelLayout } from './panel'
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
} from './geometry'
export { LIP_EPSILON } from './motion'
export { BALL_MODE_NAMES, BallMode, BallSchema } from '../components/Ball'
export type { BallModeName, BallStore } from '../components/Ball'
export { HoleSchema } from '../components/Hole'
export type { HoleStore } from '../components/Hole'
export { RIM_MODE_NAMES, RimContactSchema, RimMode } from '../components/RimContact'
export type { RimContactStore } from '../components/RimContact'
export { PathEvent, PathSchema } from '../components/Path'
export type { PathStore } from '../components/Path'
export { integrationSystem } from '../systems/integration'
export { skipOverSystem } from '../systems/skipOver'
export { captureSystem } from '../systems/capture'
export { cogGateSystem } from '../systems/cogGate'
export { bounceSystem } from '../systems/bounce'
export { rimRollSystem } from '../systems/rimRoll'
export { heroReferenceSystem, HERO_ROLL_TURN } from '../systems/heroReference'
export { wallsSystem } from '../systems/walls'
export { collisionsSystem } from '../systems/collisions'
export { WallEdge, WallsSchema } from '../components/Walls'
export type { WallsStore } from '../components/Walls'
