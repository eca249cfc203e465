// The demo's regime overlay draws the capture window the core decides with, under every preset: a ball
// just inside the drawn window is captured clean, one just outside is not (under PHYSICAL_CONFIG the
// window is quadratic; an overlay that fell back to the design's ellipse would fail here).
import { describe, expect, it } from 'vitest'
import { DEFAULT_CONFIG, PHYSICAL_CONFIG, TABULATED_CONFIG, resolveConfig, type ConfigOverrides } from '../src/index'
import { regimeCurves } from '../demo/regimeCurves'
import { settle, shoot } from './helpers'

function outcome(delta: number, speed: number, overrides: ConfigOverrides): string {
  const { sim, ball } = shoot(delta, speed, overrides)
  const events = settle(sim, 1 / 240, 5).filter((e) => e.ball === ball)
  const first = events.find((e) => e.type !== 'nearMiss')
  return first ? (first.via ? `${first.type}:${first.via}` : first.type) : 'none'
}

describe.each([
  ['DEFAULT_CONFIG', {} as ConfigOverrides],
  ['PHYSICAL_CONFIG', PHYSICAL_CONFIG],
])('regime overlay under %s', (_name, overrides) => {
  const config = resolveConfig(overrides)
  const curves = regimeCurves(config, 160, 700)

  it('uses the config it is given (the window reaches V_MAX of that config)', () => {
    expect(curves.window.at(-1)!.speed).toBe(Math.min(config.V_MAX, 700))
    expect(curves.window[0]!.delta).toBe(config.HOLE_RADIUS)
  })

  it("draws the capture window where the engine's capture decision changes", () => {
    let checked = 0
    // interior points of the curve, away from its ends (δ = R at v = 0, δ = 0 at V_MAX) and from the skip region
    for (const p of curves.window.slice(4, -4)) {
      const { delta, speed } = p
      if (delta < 1 || delta > config.HOLE_RADIUS - config.BALL_RADIUS / 2 - 1) continue
      expect(outcome(delta - 0.05, speed, overrides), `inside at (${delta}, ${speed})`).toBe('capture:clean')
      expect(outcome(delta + 0.05, speed, overrides), `outside at (${delta}, ${speed})`).not.toBe('capture:clean')
      checked++
    }
    expect(checked).toBeGreaterThan(10)
  })
})

describe('regime overlay under TABULATED_CONFIG', () => {
  const config = resolveConfig(TABULATED_CONFIG)
  const curves = regimeCurves(config, 60, 700)

  it("draws the table's capture speed where the engine's capture decision changes (clean or after a roll)", () => {
    const captured = (delta: number, speed: number) => {
      const { sim, ball } = shoot(delta, speed, TABULATED_CONFIG)
      return settle(sim, 1 / 240, 5).some((e) => e.ball === ball && e.type === 'capture')
    }
    let checked = 0
    for (const p of curves.window.slice(1, -1)) {
      if (p.speed >= 700 || p.delta > config.HOLE_RADIUS - 0.2) continue
      expect(captured(p.delta, p.speed * 0.99), `below at (${p.delta}, ${p.speed})`).toBe(true)
      expect(captured(p.delta, p.speed * 1.01), `above at (${p.delta}, ${p.speed})`).toBe(false)
      checked++
    }
    expect(checked).toBeGreaterThan(40)
  })
})

it('the two presets draw different windows (the overlay follows CAPTURE_WINDOW)', () => {
  const a = regimeCurves(DEFAULT_CONFIG, 40, 700).window
  const b = regimeCurves(resolveConfig(PHYSICAL_CONFIG), 40, 700).window
  expect(a.map((p) => p.delta)).not.toEqual(b.map((p) => p.delta))
})

it('the naive method decides with the active capture window too', () => {
  // a lip crossing inside the ellipse but outside the quadratic window (V_MAX 507): δ = 9.5, v = 400
  const R = 18
  const v = 400
  const delta = 9.5
  expect(delta).toBeLessThan(R * Math.sqrt(1 - (v / 507) ** 2))
  expect(delta).toBeGreaterThan(R * Math.sqrt(1 - v / 507))
  const naive = { METHOD: 'naive', SUBSTEPS: 16 } as const
  expect(outcome(delta, v, { ...PHYSICAL_CONFIG, ...naive })).not.toBe('capture:clean')
  expect(outcome(delta, v, { ...PHYSICAL_CONFIG, ...naive, CAPTURE_WINDOW: 'ellipse' })).toBe('capture:clean')
  expect(outcome(delta, v, PHYSICAL_CONFIG)).not.toBe('capture:clean')
})
