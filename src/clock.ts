// A fixed-step clock for games that render at the display's rate: it accumulates frame time, runs whole
// physics steps, caps the catch-up after a long frame (a tab that slept) and gives the interpolation
// factor for drawing between the last two physics states. The physics itself is exact for any dt; the
// fixed step is for smooth, display-independent pacing.
import { describe, readSpec } from './check.js'

export interface FixedStepClock {
  /** physics step, s */
  readonly stepSeconds: number
  /** most steps run for one frame; time beyond them is dropped whole (and counted in `droppedSeconds`) */
  readonly maxStepsPerFrame: number
  /** steps run by the last `advance` */
  steps: number
  /** how far the display time is past the last physics step, in steps, [0, 1) */
  alpha: number
  /** total frame time dropped by the catch-up cap, s */
  droppedSeconds: number
  /** Adds a frame's duration and runs the due steps through `step`. */
  advance(frameSeconds: number, step: (dt: number) => void): void
}

export interface FixedStepClockOptions {
  /**
   * steps per second, [0.1, 10000]; default 120. A step longer than the world's MAX_STEP (0.25 s by default:
   * below 4 Hz) is cut to it by sim.step, and the simulation then runs slower than the frames' time.
   */
  hz?: number | undefined
  /** integer in [1, 1000]; default 8 */
  maxStepsPerFrame?: number | undefined
}

/** the slowest clock: a step of 10 s, the largest MAX_STEP (a subnormal hz once gave a step of 1/hz = Infinity) */
const MIN_HZ = 0.1
const MAX_HZ = 10000

export function createFixedStepClock(options: FixedStepClockOptions = {}): FixedStepClock {
  const o = readSpec('clock options', options, ['hz', 'maxStepsPerFrame'] as const, 'options')
  const hz = o.hz ?? 120
  const maxSteps = o.maxStepsPerFrame ?? 8
  if (typeof hz !== 'number') throw new TypeError(`hz must be a number in [${MIN_HZ}, ${MAX_HZ}], got ${describe(hz)}`)
  if (!Number.isFinite(hz) || hz < MIN_HZ || hz > MAX_HZ) throw new RangeError(`hz must be in [${MIN_HZ}, ${MAX_HZ}], got ${hz}`)
  if (typeof maxSteps !== 'number') throw new TypeError(`maxStepsPerFrame must be an integer in [1, 1000], got ${describe(maxSteps)}`)
  if (!Number.isInteger(maxSteps) || maxSteps < 1 || maxSteps > 1000) {
    throw new RangeError(`maxStepsPerFrame must be an integer in [1, 1000], got ${maxSteps}`)
  }
  const dt = 1 / hz
  let acc = 0
  const clock: FixedStepClock = {
    stepSeconds: dt,
    maxStepsPerFrame: maxSteps,
    steps: 0,
    alpha: 0,
    droppedSeconds: 0,
    advance(frameSeconds, step) {
      if (typeof frameSeconds !== 'number') throw new TypeError(`frameSeconds must be a finite number ≥ 0, got ${describe(frameSeconds)}`)
      if (!Number.isFinite(frameSeconds) || frameSeconds < 0) {
        throw new RangeError(`frameSeconds must be a finite number ≥ 0, got ${frameSeconds}`)
      }
      acc += frameSeconds
      let n = 0
      while (acc >= dt && n < maxSteps) {
        step(dt)
        acc -= dt
        n++
      }
      if (acc >= dt) {
        // the rest of a long frame is dropped whole, and the display restarts at the last step (alpha 0).
        // Kept, its fraction of a step (acc % dt) read a hair under one step when the rest was a whole number
        // of steps, as rounding makes it: the drawn frame stayed a step behind for good
        clock.droppedSeconds += acc
        acc = 0
      }
      clock.steps = n
      clock.alpha = acc / dt
    },
  }
  return clock
}
