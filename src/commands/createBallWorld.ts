// A world ready to simulate: the config resolved and validated, the stores made, and the observers that
// keep the simulation in step with bitECS (src/world/balls.ts): a ball's or a hole's or the walls' entity
// removed by removeEntity, ours or the game's, is forgotten by the simulation at once.
import { observe, onAdd, onRemove } from 'bitecs'
import { resolveConfig, type ConfigOverrides } from '../config/design.js'
import { adoptBall, forgetBall } from '../world/balls.js'
import { createWorldData, gridThreshold, type BallWorld, type BallWorldOptions } from '../world/createWorld.js'
import { forgetHole } from './holes.js'
import { rimTableFor } from '../reference/rimTables.js'
import { fillCaptureRows } from '../reference/rimTable.js'
import { describe, readSpec } from './validate.js'
import { forgetWalls } from './walls.js'

/** Largest `options.capacity`. */
export const MAX_CAPACITY = 1 << 26

/**
 * Creates an empty world with the design's constants changed by `overrides` (validated). Games that run
 * their own loop start here and drive it with the commands and runSchedule; createBallPhysics wraps the
 * same world.
 */
export function createBallWorld(overrides: ConfigOverrides = {}, options: BallWorldOptions = {}): BallWorld {
  const config = resolveConfig(overrides)
  const o = readSpec('options', options, ['capacity', 'broadphase'] as const)
  const capacity = o.capacity === undefined ? 1024 : o.capacity
  const broadphase = o.broadphase === undefined ? 'auto' : o.broadphase
  if (broadphase !== 'auto' && broadphase !== 'grid' && broadphase !== 'scan') {
    throw new RangeError(`options.broadphase must be 'auto', 'grid' or 'scan', got ${describe(broadphase)}`)
  }
  if (typeof capacity !== 'number' || !Number.isInteger(capacity) || capacity < 1 || capacity > MAX_CAPACITY) {
    throw new RangeError(`options.capacity must be an integer in [1, ${MAX_CAPACITY}], got ${describe(capacity)}`)
  }
  const world = createWorldData(config, capacity, gridThreshold(broadphase))
  // the tabulated rim model's table for the config's ball and hole, built now with every capture row (once
  // per process: shipped for the design's geometry; 0.4-0.5 s for balls of radius 5-9 in an 18-px hole,
  // seconds near the hole's size) rather than row by row inside the steps whose crossings need them (a step
  // with 128 first crossings at radius 16.66 took 11 s); other sizes: prepareRimTable
  if (config.RIM_MODEL === 'tabulated' && config.BALL_RADIUS < config.HOLE_RADIUS) {
    const table = rimTableFor(config.HOLE_RADIUS / config.BALL_RADIUS, config.BALL_INERTIA)
    fillCaptureRows(table)
    world.rimTables.push(table)
  }
  observe(world, onAdd(world.Ball), (eid: number) => adoptBall(world, eid))
  observe(world, onRemove(world.Ball), (eid: number) => forgetBall(world, eid))
  observe(world, onRemove(world.Hole), (eid: number) => forgetHole(world, eid))
  observe(world, onRemove(world.Walls), (eid: number) => forgetWalls(world, eid))
  return world
}
