// Far from the origin: a scene moved by up to 9.9e8 px (positions are allowed to ±1e9) gives the same
// events (kind, ball, hole or other ball) as at the origin, and the design's stages the same times to a
// stated tolerance. Every path is written relative to its own start and every hole test relative to the
// hole, so rounding grows with the coordinates' ulp (2.2e-7 px at 9.9e8) and no further.
import { describe, expect, it } from 'vitest'
import { DEFAULT_PANEL, PHYSICAL_CONFIG, TABULATED_CONFIG, createBallPhysics, type BallEvent, type ConfigOverrides } from '../src/index'

const OFFSETS = [1e4, 1e8, 9.9e8]

/**
 * The default panel moved by (o, −o), walls with an open bottom; `n` throws from seeded random spots on
 * the launch row (or, for a burst, all from the launch point), stepped 8 s at 60 Hz.
 */
function panelRun(o: number, config: ConfigOverrides, n: number, burst: boolean): BallEvent[] {
  const sim = createBallPhysics(config)
  for (const h of DEFAULT_PANEL.holes) sim.addHole({ x: h.x + o, y: h.y - o, value: h.value })
  sim.setWalls({ minX: o, minY: -o, maxX: 420 + o, maxY: 480 - o, restitution: 0.5, open: { bottom: true } })
  let s = 1
  const rnd = (): number => { s = (s * 16807) % 2147483647; return s / 2147483647 }
  for (let i = 0; i < n; i++) {
    const x = burst ? DEFAULT_PANEL.launch.x : 30 + 360 * rnd()
    sim.throwBall({ x: x + o, y: DEFAULT_PANEL.launch.y - o, power: burst ? 0.3 + 0.7 * rnd() : rnd(), angle: -0.4 + 0.8 * rnd() })
  }
  const events: BallEvent[] = []
  for (let f = 0; f < 60 * 8; f++) { sim.step(1 / 60); events.push(...sim.drainEvents()) }
  return events
}

/** An event as kind:ball:hole-or-other. */
const label = (e: BallEvent): string => `${e.type}:${e.ball}:${'hole' in e ? e.hole : 'other' in e ? e.other : ''}`
/** Each event's label, sorted (events at one instant may tie in another order). */
const outline = (ev: BallEvent[]): string[] => ev.map(label).sort()

const SCENES: [string, ConfigOverrides, number, boolean][] = [
  ['the design, 200 throws', {}, 200, false],
  ['PHYSICAL_CONFIG, 200 throws', PHYSICAL_CONFIG, 200, false],
  ['TABULATED_CONFIG, 200 throws', TABULATED_CONFIG, 200, false],
  ["contacts 'on', 30 throws", { BALL_COLLISIONS: 'on' }, 30, false],
  ["contacts 'on', a 12-ball burst from the launch point", { BALL_COLLISIONS: 'on' }, 12, true],
  ["contacts 'fixed', 30 throws", { BALL_COLLISIONS: 'fixed' }, 30, false],
  ["contacts 'fixed', a 12-ball burst from the launch point", { BALL_COLLISIONS: 'fixed' }, 12, true],
]

describe('far from the origin', () => {
  for (const [name, config, n, burst] of SCENES) {
    it(`${name}: the same events moved by 1e4, 1e8 and 9.9e8 px`, () => {
      const home = panelRun(0, config, n, burst)
      expect(home.filter((e) => e.type === 'capture').length).toBeGreaterThan(burst ? 3 : n / 5)
      if (config.BALL_COLLISIONS !== undefined) expect(home.filter((e) => e.type === 'collision').length).toBeGreaterThan(5)
      const expected = outline(home)
      for (const o of OFFSETS) expect(outline(panelRun(o, config, n, burst)), `moved by ${o} px`).toEqual(expected)
    })
  }

  it('the design: every event time within 1e-7 s, every lip offset δ within 1e-5 px, at 9.9e8 px (measured 7.9e-9 s, 1.2e-6 px)', () => {
    const byKey = (ev: BallEvent[]): BallEvent[] => [...ev].sort((a, b) => (label(a) < label(b) ? -1 : label(a) > label(b) ? 1 : a.time - b.time))
    const home = byKey(panelRun(0, {}, 200, false))
    const far = byKey(panelRun(9.9e8, {}, 200, false))
    expect(far.length).toBe(home.length)
    let dt = 0
    let dd = 0
    let lips = 0
    for (let i = 0; i < home.length; i++) {
      const a = home[i]!, b = far[i]!
      expect(label(b)).toBe(label(a))
      dt = Math.max(dt, Math.abs(a.time - b.time))
      if ('delta' in a && a.delta !== undefined && 'delta' in b && b.delta !== undefined) { dd = Math.max(dd, Math.abs(a.delta - b.delta)); lips++ }
    }
    expect(lips).toBeGreaterThan(100)
    expect(dt).toBeLessThan(1e-7)
    expect(dd).toBeLessThan(1e-5)
  })
})
