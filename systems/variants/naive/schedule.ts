// Schedules of the tick-sampled methods. Each sub-step runs the clock, then the stage systems in the exact
// core's order; the step's schedule lists that group SUBSTEPS times (substeps are configuration).
//   'naive': clock, move, detect, skip-over, capture, COG gate, bounce, rim-roll
//   'v1':    clock, move, v1 capture
import type { ScheduleEntry } from '../../../src/world/system.js'
import { naiveBounceSystem } from './bounce.js'
import { naiveCaptureSystem } from './capture.js'
import { naiveClockSystem } from './clock.js'
import { naiveCogGateSystem } from './cogGate.js'
import { naiveDetectSystem } from './detect.js'
import { naiveMoveSystem } from './move.js'
import { naiveRimRollSystem } from './rimRoll.js'
import { naiveSkipOverSystem } from './skipOver.js'
import { v1CaptureSystem } from './v1Capture.js'

export const NAIVE_SUBSTEP: readonly ScheduleEntry[] = Object.freeze([
  Object.freeze({ name: 'naive.clock', run: naiveClockSystem }),
  Object.freeze({ name: 'naive.move', run: naiveMoveSystem }),
  Object.freeze({ name: 'naive.detect', run: naiveDetectSystem }),
  Object.freeze({ name: 'naive.skipOver', run: naiveSkipOverSystem }),
  Object.freeze({ name: 'naive.capture', run: naiveCaptureSystem }),
  Object.freeze({ name: 'naive.cogGate', run: naiveCogGateSystem }),
  Object.freeze({ name: 'naive.bounce', run: naiveBounceSystem }),
  Object.freeze({ name: 'naive.rimRoll', run: naiveRimRollSystem }),
])

export const V1_SUBSTEP: readonly ScheduleEntry[] = Object.freeze([
  Object.freeze({ name: 'v1.clock', run: naiveClockSystem }),
  Object.freeze({ name: 'v1.move', run: naiveMoveSystem }),
  Object.freeze({ name: 'v1.capture', run: v1CaptureSystem }),
])

/** The group of systems of one sub-step, repeated `substeps` times. */
export function repeatSubsteps(group: readonly ScheduleEntry[], substeps: number): ScheduleEntry[] {
  const out: ScheduleEntry[] = []
  for (let k = 0; k < substeps; k++) out.push(...group)
  return out
}
