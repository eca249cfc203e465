// What a system is: a function over the world, run once per event pass of a step, in schedule order.
import type { BallWorld } from './createWorld.js'

export type System = (world: BallWorld) => void

export interface ScheduleEntry {
  readonly name: string
  readonly run: System
}

/**
 * Refuses a system called outside a step. A system acts on the step's window (the balls due before its end,
 * the pass's marked balls), which only runSchedule opens: called between steps it would find nothing to do
 * and return, the world unchanged, so a game that ran the systems in its own pipeline instead of through
 * runSchedule saw no ball move and no error.
 */
export function outsideStep(system: string, world: unknown): never {
  // (what was passed may not be a world at all: a bitECS world of the game's own has no `stepping` either)
  const w = world as Record<string, unknown> | null
  if (w === null || typeof w !== 'object' || !('Ball' in w) || !('holes' in w) || !('config' in w)) {
    throw new TypeError(`${system}: world must be a world made by createBallWorld, got ${w === null ? 'null' : Array.isArray(w) ? 'an array' : typeof w === 'object' ? 'an object that is not one' : typeof w}`)
  }
  throw new Error(
    `${system}: a system runs inside a step, which runSchedule(world, schedule, dt) (or sim.step) opens: put it in a schedule (createSchedule(world.config), with systems of your own spliced in) and run that; called between steps it would do nothing`,
  )
}
