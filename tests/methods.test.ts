// METHOD and SUBSTEPS: one config option selects the schedule; validation names the key and the values.
import { describe, expect, it } from 'vitest'
import { DEFAULT_SCHEDULE, createSchedule } from '../src/ecs'
import { CONFIG_CHOICES, addPanel, createBallPhysics, resolveConfig } from '../src/index'
import { settle } from './helpers'

describe('METHOD and SUBSTEPS', () => {
  it("default is METHOD 'exact', SUBSTEPS 1, and its schedule is exactly DEFAULT_SCHEDULE", () => {
    const sim = createBallPhysics()
    expect(sim.config.METHOD).toBe('exact')
    expect(sim.config.SUBSTEPS).toBe(1)
    expect(sim.schedule).toEqual([...DEFAULT_SCHEDULE])
    expect(createSchedule()).toEqual([...DEFAULT_SCHEDULE])
  })

  it('every system of DEFAULT_SCHEDULE is exported from the ecs entry, so a game can build its own schedule from them', async () => {
    const ecs = (await import('../src/ecs')) as Record<string, unknown>
    const exported = new Set(Object.values(ecs))
    const missing = DEFAULT_SCHEDULE.filter((e) => !exported.has(e.run)).map((e) => e.name)
    expect(missing).toEqual([])
  })

  it('a bad METHOD, other choice key or SUBSTEPS throws a RangeError naming the key and the allowed values (a TypeError for a choice that is not a string)', () => {
    expect(() => resolveConfig({ METHOD: 'rk4' as never })).toThrow(RangeError)
    expect(() => resolveConfig({ METHOD: 'rk4' as never })).toThrow(/config\.METHOD must be one of 'exact', 'naive', 'v1', got 'rk4'/)
    expect(() => resolveConfig({ METHOD: 3 as never })).toThrow(/config\.METHOD must be one of/)
    // every choice key: a value of the wrong type (not a string) is a TypeError, a string not among the choices a RangeError
    for (const key of Object.keys(CONFIG_CHOICES) as Array<keyof typeof CONFIG_CHOICES>) {
      for (const bad of [true, 3, null, {}]) {
        expect(() => resolveConfig({ [key]: bad as never }), `${key} ${String(bad)}`).toThrow(TypeError)
        expect(() => resolveConfig({ [key]: bad as never })).toThrow(new RegExp(`config\\.${key} must be one of '`))
      }
      expect(() => resolveConfig({ [key]: 'none of them' as never }), key).toThrow(RangeError)
      expect(() => resolveConfig({ [key]: 'none of them' as never })).toThrow(new RegExp(`config\\.${key} must be one of .*, got 'none of them'`))
    }
    expect(() => resolveConfig({ SUBSTEPS: 0 })).toThrow(/config\.SUBSTEPS must be in \[1, 64\] \(an integer\), got 0/)
    expect(() => resolveConfig({ SUBSTEPS: 65 })).toThrow(RangeError)
    expect(() => resolveConfig({ SUBSTEPS: 2.5 })).toThrow(/config\.SUBSTEPS/)
    expect(resolveConfig({ METHOD: 'naive', SUBSTEPS: 64 })).toMatchObject({ METHOD: 'naive', SUBSTEPS: 64 })
  })

  it('naive with SUBSTEPS = 4 lists its 8 sub-step systems 4 times; v1 lists 3 systems', () => {
    const naive = createBallPhysics({ METHOD: 'naive', SUBSTEPS: 4 }).schedule.map((e) => e.name)
    expect(naive).toHaveLength(32)
    expect(naive.slice(0, 8)).toEqual([
      'naive.clock', 'naive.move', 'naive.detect', 'naive.skipOver', 'naive.capture', 'naive.cogGate', 'naive.bounce', 'naive.rimRoll',
    ])
    expect(createBallPhysics({ METHOD: 'v1' }).schedule.map((e) => e.name)).toEqual(['v1.clock', 'v1.move', 'v1.capture'])
  })

  it('every method runs 200 throws at the panel to rest with the same public API; v1 emits only capture and rest', () => {
    for (const METHOD of ['exact', 'naive', 'v1'] as const) {
      const sim = createBallPhysics({ METHOD })
      addPanel(sim)
      for (let i = 0; i < 200; i++) sim.throwBall({ x: 210, y: 450, power: i / 199, angle: ((i % 21) - 10) * 0.06 })
      const events = settle(sim, 1 / 60)
      const ends = events.filter((e) => e.type === 'capture' || e.type === 'rest')
      expect(ends, METHOD).toHaveLength(200)
      const kinds = new Set(events.map((e) => e.type))
      if (METHOD === 'v1') expect([...kinds].sort()).toEqual(['capture', 'rest'])
      else for (const k of ['skip', 'capture', 'bounce', 'nearMiss', 'rest']) expect(kinds.has(k as never), `${METHOD} ${k}`).toBe(true)
    }
  })

  it('naive sub-steps split the step: a ball at 600 px/s with no deceleration moves 10 px per 1/60 s step for any SUBSTEPS', () => {
    for (const SUBSTEPS of [1, 3, 16]) {
      const sim = createBallPhysics({ METHOD: 'naive', SUBSTEPS, ROLLING_DECEL: 0 })
      const b = sim.addBall({ x: 0, y: 0, vx: 600, vy: 0 })
      sim.step(1 / 60)
      sim.step(1 / 60)
      expect(sim.ballState(b).x).toBeCloseTo(20, 9)
    }
  })
})

describe('a derived key out of range says where it came from', () => {
  it('GRAVITY derived from V_SKIP_MAX and the radii (HOLE_RADIUS 1e-9 gives 2.25e24) names the keys to change', () => {
    expect(() => createBallPhysics({ HOLE_RADIUS: 1e-9 })).toThrow(RangeError)
    expect(() => createBallPhysics({ HOLE_RADIUS: 1e-9 })).toThrow(/config\.GRAVITY must be in \(0, 1000000000\], got .* \(derived from config\.V_SKIP_MAX, HOLE_RADIUS and BALL_RADIUS/)
    expect(() => createBallPhysics({ GRAVITY: 1e9, HOLE_RADIUS: 1e4, BALL_RADIUS: 1e-3 })).toThrow(/config\.V_SKIP_MAX .* \(derived from config\.GRAVITY/)
  })
})
