// The demo's throw controls (demo/input.ts) without a browser: a tap of an arrow key turns the aim by one
// fine step at any frame rate, and a held key sweeps at AIM_RATE once held past AIM_HOLD.
import { describe, expect, it } from 'vitest'
import { AIM_HOLD, AIM_NUDGE, AIM_RATE, ThrowInput } from '../demo/input'

/** Presses `code` at time 0, holds it `seconds` with frames of `fps`, releases it; returns the aim. */
function press(code: string, seconds: number, fps: number): number {
  const input = new ThrowInput(() => {})
  const dt = 1 / fps
  input.key(code, true, false, 0)
  let t = 0
  while (t + dt <= seconds) {
    t += dt
    input.update(t, dt)
  }
  input.update(seconds, seconds - t)
  input.key(code, false, false, seconds)
  return input.angle
}

describe('demo throw controls', () => {
  it('a tap of ← or → is one fine step at 15, 28, 60 and 144 fps (the sweep once began at the press: 3–4 steps a tap)', () => {
    for (const fps of [15, 28, 60, 144]) {
      expect(press('ArrowRight', 0.12, fps), `${fps} fps`).toBe(AIM_NUDGE)
      expect(press('ArrowLeft', 0.2, fps), `${fps} fps`).toBe(-AIM_NUDGE)
    }
  })

  it('a key held past AIM_HOLD sweeps at AIM_RATE, the same at every frame rate', () => {
    const want = AIM_NUDGE + AIM_RATE * (1 - AIM_HOLD)
    for (const fps of [15, 28, 60, 144]) expect(press('ArrowRight', 1, fps), `${fps} fps`).toBeCloseTo(want, 9)
  })
})
