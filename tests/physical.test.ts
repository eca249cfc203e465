// Physical accuracy (docs/physical.md): the game model against the rigid-sphere reference on a coarse
// (δ, v) grid, the physical preset, and the hero ball. The fine grid and the costs are in `npm run physical`.
import { describe, expect, it } from 'vitest'
import { DEFAULT_CONFIG, PHYSICAL_CONFIG, captureSpeed, captureWindow, capturesClean, createBallPhysics, resolveConfig } from '../src/index'
import { agreement, createShotRig, engineMap, gameGrid, gridDelta, gridSpeed, referenceMap } from '../src/physical/agreement'
import { v1Schedule } from '../src/schedule'
import { referenceOutcome } from '../src/reference/index'
import { rng, sequence, settle, shoot } from './helpers'

// Floors under what was measured on this grid (36 × 40 cells: v1 66.9 %, design 82.7 %, preset 91.8 %;
// `npm run physical` on 180 × 200 gives 66.8, 82.5 and 92.0 %), so that a change of model trips them.
const V1_FLOOR = 0.65
const DESIGN_FLOOR = 0.81
const PRESET_FLOOR = 0.9
/** the preset must beat the design by at least this share of the grid (measured: 9.1 points) */
const PRESET_MARGIN = 0.08

const GRID = gameGrid(36, 40)
const cfg = DEFAULT_CONFIG
const ref = referenceMap(GRID, cfg.BALL_RADIUS, cfg.GRAVITY, cfg.BALL_INERTIA)

describe('the game model against the rigid-sphere reference', () => {
  const design = engineMap(GRID)
  const preset = engineMap(GRID, PHYSICAL_CONFIG)
  const v1 = engineMap(GRID, {}, v1Schedule())

  it('the reference map has both outcomes, and captures at every δ at low speed', () => {
    const share = ref.map.reduce((a, b) => a + b, 0) / ref.map.length
    expect(share).toBeGreaterThan(0.2)
    expect(share).toBeLessThan(0.8)
    for (let i = 0; i < GRID.nDelta; i++) expect(ref.map[i * GRID.nSpeed]).toBe(1)
  })

  it(`the design's six stages agree on ≥ ${DESIGN_FLOOR * 100} % of the grid, v1 on ≥ ${V1_FLOOR * 100} % and less`, () => {
    const a = agreement(design, ref.map)
    const b = agreement(v1, ref.map)
    expect(a).toBeGreaterThanOrEqual(DESIGN_FLOOR)
    expect(b).toBeGreaterThanOrEqual(V1_FLOOR)
    expect(b).toBeLessThan(a)
  })

  it(`the physical preset agrees on ≥ ${PRESET_FLOOR * 100} %, at least ${PRESET_MARGIN * 100} points more than the design`, () => {
    const p = agreement(preset, ref.map)
    expect(p).toBeGreaterThanOrEqual(PRESET_FLOOR)
    expect(p - agreement(design, ref.map)).toBeGreaterThanOrEqual(PRESET_MARGIN)
  })

  it('the reused one-hole rig classifies as a fresh engine per shot (tests/helpers shoot)', () => {
    const rig = createShotRig(PHYSICAL_CONFIG)
    const r = rng(11)
    for (let n = 0; n < 40; n++) {
      const i = Math.floor(r() * GRID.nDelta)
      const k = Math.floor(r() * GRID.nSpeed)
      const s = shoot(gridDelta(GRID, i), gridSpeed(GRID, k), PHYSICAL_CONFIG)
      settle(s.sim, 1 / 60)
      expect(rig.shot(gridDelta(GRID, i), gridSpeed(GRID, k))).toBe(s.sim.ballState(s.ball).mode === 'captured')
      expect(preset[i * GRID.nSpeed + k]).toBe(s.sim.ballState(s.ball).mode === 'captured' ? 1 : 0)
    }
  })

  it('maps are deterministic', () => {
    expect(Array.from(engineMap(GRID, PHYSICAL_CONFIG))).toEqual(Array.from(preset))
    expect(Array.from(referenceMap(GRID, cfg.BALL_RADIUS, cfg.GRAVITY, cfg.BALL_INERTIA).map)).toEqual(Array.from(ref.map))
  })
})

describe('the physical preset', () => {
  it('is selected by config: a quadratic window captures where the ellipse does not, and the other way round', () => {
    // the quadratic window v_c = V_MAX·(1 − δ²/R²) lies below the ellipse V_MAX·√(1 − δ²/R²) at every 0 < δ < R
    const R = cfg.HOLE_RADIUS
    const delta = 12
    const vQuad = captureSpeed(delta, R, 600, 'quadratic')
    const vEll = captureSpeed(delta, R, 600, 'ellipse')
    expect(vQuad).toBeLessThan(vEll)
    const v = (vQuad + vEll) / 2
    expect(capturesClean(delta, v, R, 600, 'ellipse')).toBe(true)
    expect(capturesClean(delta, v, R, 600, 'quadratic')).toBe(false)
    const ell = shoot(delta, v, { V_MAX: 600 })
    const quad = shoot(delta, v, { V_MAX: 600, CAPTURE_WINDOW: 'quadratic' })
    expect(sequence(settle(ell.sim), ell.ball)[0]).toBe('capture:clean')
    expect(sequence(settle(quad.sim), quad.ball)).not.toContain('capture:clean')
  })

  it('the window and its inverse are one curve for each shape', () => {
    const R = cfg.HOLE_RADIUS
    for (const shape of ['ellipse', 'quadratic'] as const) {
      for (const d of [0, 3, 9, 15, 17.5]) {
        const v = captureSpeed(d, R, 507, shape)
        expect(captureWindow(v, R, 507, shape)).toBeCloseTo(d, 9)
      }
    }
  })

  it('the design stays the default; the preset is a Partial config that resolves', () => {
    expect(createBallPhysics().config.CAPTURE_WINDOW).toBe('ellipse')
    expect(createBallPhysics().config.V_MAX).toBe(600)
    const c = resolveConfig(PHYSICAL_CONFIG)
    expect(c.CAPTURE_WINDOW).toBe('quadratic')
    expect(c.GRAVITY).toBe(cfg.GRAVITY) // the preset keeps the physics' g
  })

  it('a bad value throws a RangeError naming the key and the allowed values', () => {
    expect(() => createBallPhysics({ CAPTURE_WINDOW: 'cubic' as never })).toThrow(RangeError)
    expect(() => createBallPhysics({ CAPTURE_WINDOW: 'cubic' as never })).toThrow(/CAPTURE_WINDOW must be one of 'ellipse', 'quadratic', got 'cubic'/)
    expect(() => createBallPhysics({ CAPTURE_WINDOW: 2 as never })).toThrow(/CAPTURE_WINDOW/)
    expect(() => createBallPhysics({ BALL_INERTIA: 0.9 })).toThrow(/BALL_INERTIA must be in \(0, 0\.66/)
    expect(() => createBallPhysics({ BALL_INERTIA: 0 })).toThrow(RangeError)
  })
})

describe('the hero ball', () => {
  // (δ, v) where the design and the reference disagree, both ways, and where they agree
  const CASES: Array<[number, number]> = [
    [2, 630], // reference captures, design bounces
    [9, 400], // design captures clean, reference escapes
    [11, 480], // design rolls on the rim
    [15, 100], // both capture
    [5, 750], // both escape
  ]

  it('follows the reference outcome at each (δ, v); the same shot without the flag follows the six stages', () => {
    let differ = 0
    for (const [d, v] of CASES) {
      const refOut = referenceOutcome({ delta: d, speed: v, holeRadius: cfg.HOLE_RADIUS, ballRadius: cfg.BALL_RADIUS, gravity: cfg.GRAVITY, inertia: cfg.BALL_INERTIA })
      const rig = createShotRig()
      expect(rig.shot(d, v, true)).toBe(refOut.captured)
      const plain = shoot(d, v)
      settle(plain.sim)
      const stages = plain.sim.ballState(plain.ball).mode === 'captured'
      expect(rig.shot(d, v, false)).toBe(stages)
      if (stages !== refOut.captured) differ++
    }
    expect(differ).toBeGreaterThanOrEqual(2) // the cases test something: the flag changes the outcome
  })

  it('leaves from the reference exit point with its exit velocity, at the exit time', () => {
    const d = 6
    const v = 700
    const out = referenceOutcome({ delta: d, speed: v, holeRadius: cfg.HOLE_RADIUS, ballRadius: cfg.BALL_RADIUS, gravity: cfg.GRAVITY, inertia: cfg.BALL_INERTIA })
    expect(out.captured).toBe(false)
    const sim = createBallPhysics({ ROLLING_DECEL: 0 })
    sim.addHole({ x: 0, y: 0 })
    const lipX = -Math.sqrt(18 * 18 - d * d)
    const ball = sim.addBall({ x: lipX - v * 0.05, y: d, vx: v, vy: 0, hero: true })
    // the crossing is at t = 0.05 s (to the rounding of the lip-circle solve, an ulp either way); step to
    // just past the exit, 1e-10 s: 4.4e-8 px on, well inside the 5e-7 px compared
    sim.step(0.05 + out.duration + 1e-10)
    const s = sim.ballState(ball)
    expect(s.mode).toBe('rolling')
    expect(s.x).toBeCloseTo(out.exitX!, 6)
    expect(s.y).toBeCloseTo(out.exitY!, 6)
    expect(Math.hypot(s.vx, s.vy)).toBeCloseTo(out.exitSpeed!, 6)
    expect(Math.atan2(s.vy, s.vx)).toBeCloseTo(out.exitAngle!, 9)
  })

  it('rides the lip for the reference time when it rolls round it (no jump to the exit), and leaves from the reference exit point', () => {
    const d = 10
    const v = 300
    const out = referenceOutcome({ delta: d, speed: v, holeRadius: cfg.HOLE_RADIUS, ballRadius: cfg.BALL_RADIUS, gravity: cfg.GRAVITY, inertia: cfg.BALL_INERTIA })
    expect(out.ending).toBe('rolledOut')
    const sim = createBallPhysics({ ROLLING_DECEL: 0 })
    sim.addHole({ x: 0, y: 0 })
    const lipX = -Math.sqrt(18 * 18 - d * d)
    const ball = sim.addBall({ x: lipX - v * 0.05, y: d, vx: v, vy: 0, hero: true })
    sim.step(0.05 + out.duration / 2)
    const mid = sim.ballState(ball)
    expect(mid.mode).toBe('rimRoll')
    expect(Math.hypot(mid.x, mid.y)).toBeCloseTo(18, 9)
    const events = sim.drainEvents()
    expect(events.map((e) => e.type)).toEqual(['rimRoll'])
    // (a hair past the exit: the ride's end is the crossing time plus the duration, in other roundings)
    sim.step(out.duration / 2 + 1e-7)
    const end = sim.drainEvents()
    expect(end.map((e) => e.type)).toEqual(['lipOut', 'nearMiss'])
    expect(end[0]!.time).toBeCloseTo(0.05 + out.duration, 9)
    const s = sim.ballState(ball)
    expect(s.x).toBeCloseTo(out.exitX!, 4)
    expect(s.y).toBeCloseTo(out.exitY!, 4)
  })

  it('mirrors: a path passing the hole on the other side leaves mirrored', () => {
    const run = (side: 1 | -1) => {
      const sim = createBallPhysics({ ROLLING_DECEL: 0 })
      sim.addHole({ x: 0, y: 0 })
      const ball = sim.addBall({ x: -60, y: 11 * side, vx: 450, vy: 0, hero: true })
      sim.step(0.25)
      return sim.ballState(ball)
    }
    const a = run(1)
    const b = run(-1)
    expect(b.x).toBeCloseTo(a.x, 9)
    expect(b.y).toBeCloseTo(-a.y, 9)
    expect(b.vy).toBeCloseTo(-a.vy, 9)
  })

  it('one hero among many: the other balls give exactly the events of a scene without a hero', () => {
    const scene = (hero: boolean) => {
      const sim = createBallPhysics()
      for (let i = 0; i < 4; i++) sim.addHole({ x: 80 * i, y: 0 })
      const r = rng(5)
      const ids: number[] = []
      for (let n = 0; n < 30; n++) {
        ids.push(sim.addBall({ x: 80 * Math.floor(r() * 4) - 120, y: (r() - 0.5) * 30, vx: 300 + 400 * r(), vy: (r() - 0.5) * 40, hero: hero && n === 0 }))
      }
      return { ids, events: settle(sim, 1 / 60, 10) }
    }
    const a = scene(false)
    const b = scene(true)
    const others = (ev: typeof a.events, hero: number) => ev.filter((e) => e.ball !== hero)
    expect(others(b.events, b.ids[0]!)).toEqual(others(a.events, a.ids[0]!))
  })

  it('is deterministic, and setHeroBall / isHeroBall flip and read the flag with validation', () => {
    const run = () => {
      const sim = createBallPhysics()
      sim.addHole({ x: 0, y: 0 })
      sim.throwBall({ x: 4, y: 300, power: 0.4, angle: 0, hero: true })
      return settle(sim)
    }
    expect(run()).toEqual(run())
    const sim = createBallPhysics()
    const b = sim.addBall({ x: 0, y: 0, vx: 1, vy: 0 })
    expect(sim.isHeroBall(b)).toBe(false)
    sim.setHeroBall(b)
    expect(sim.isHeroBall(b)).toBe(true)
    sim.setHeroBall(b, false)
    expect(sim.isHeroBall(b)).toBe(false)
    expect(() => sim.setHeroBall(b, 'yes' as never)).toThrow(TypeError)
    expect(() => sim.addBall({ x: 0, y: 0, vx: 1, vy: 0, hero: 1 as never })).toThrow(/ball.hero must be a boolean/)
    expect(() => sim.setHeroBall(999)).toThrow(RangeError)
  })
})
