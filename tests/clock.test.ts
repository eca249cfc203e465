// The fixed-step clock (src/clock.ts): the steps it runs for a frame, the catch-up cap and what it drops, and
// the interpolation factor.
import { describe, expect, it } from 'vitest'
import { createFixedStepClock } from '../src/index'

/** Advances the clock by each frame, returning the steps run for each and alpha after it. */
function run(hz: number, maxSteps: number, frames: readonly number[]): { steps: number[]; alphas: number[]; dropped: number } {
  const clock = createFixedStepClock({ hz, maxStepsPerFrame: maxSteps })
  const steps: number[] = []
  const alphas: number[] = []
  for (const f of frames) {
    let n = 0
    clock.advance(f, (dt) => {
      expect(dt).toBe(1 / hz)
      n++
    })
    expect(clock.steps).toBe(n)
    steps.push(n)
    alphas.push(clock.alpha)
  }
  return { steps, alphas, dropped: clock.droppedSeconds }
}

describe('createFixedStepClock', () => {
  it('runs the whole steps a frame brings, and alpha is the rest of a step in [0, 1)', () => {
    const { steps, alphas, dropped } = run(120, 8, Array<number>(600).fill(1 / 144))
    // 600 frames of 1/144 s are 500 steps of 1/120 s, less at most one still accumulating
    const total = steps.reduce((a, b) => a + b, 0)
    expect(total).toBeGreaterThanOrEqual(499)
    expect(total).toBeLessThanOrEqual(500)
    expect(Math.max(...steps)).toBe(1)
    for (const a of alphas) {
      expect(a).toBeGreaterThanOrEqual(0)
      expect(a).toBeLessThan(1)
    }
    expect(dropped).toBe(0)
  })

  it('drops the rest of a long frame whole: the steps lost are counted and the display restarts at the last step', () => {
    // a hitch of 0.5 s at 120 Hz with 8 steps a frame: 8 steps run, 0.5 − 8/120 s dropped. Dropped as
    // acc − (acc % dt), rounding left 0.425 s counted and alpha 0.99999999999998 (a step behind for good)
    for (const [hz, maxSteps, hitch] of [
      [120, 8, 0.5],
      [60, 4, 1],
      [144, 3, 0.25],
    ] as const) {
      const { steps, alphas, dropped } = run(hz, maxSteps, [hitch, 1 / hz, 2 / hz])
      expect(steps).toEqual([maxSteps, 1, 2])
      expect(dropped).toBeCloseTo(hitch - maxSteps / hz, 12)
      expect(alphas[0]).toBe(0)
      expect(alphas[1]).toBeLessThan(1e-9)
      expect(alphas[2]).toBeLessThan(1e-9)
    }
  })

  it('a frame of zero length runs nothing and changes nothing', () => {
    const { steps, alphas, dropped } = run(120, 8, [0.5 / 120, 0, 0])
    expect(steps).toEqual([0, 0, 0])
    expect(alphas).toEqual([0.5, 0.5, 0.5])
    expect(dropped).toBe(0)
  })
})
