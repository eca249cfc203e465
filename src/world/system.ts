// What a system is: a function over the world, run once per event pass of a step, in schedule order.
import type { BallWorld } from './createWorld.js'

export type System = (world: BallWorld) => void

export interface ScheduleEntry {
  readonly name: string
  readonly run: System
}
