// The reference-tabulated rim model (RIM_MODEL 'tabulated', TABULATED_CONFIG): its table against the live
// reference, its shipped capture rows, and what a ball does at a tabulated crossing.
import { describe, expect, it } from 'vitest'
import { DEFAULT_CONFIG, TABULATED_CONFIG, createBallPhysics, prepareRimTable, tabulatedCaptureSpeed, type BallEvent } from '../src/index'
import { timeBudget } from './helpers'
import { agreement, engineMap, gameGrid, referenceMap } from '../src/physical/agreement'
import { RimKind, TABLE_ROWS, buildRimTable, captureRows, captureSpeedAt, crossingAngle, outcomeAt, rimOut } from '../src/reference/rimTable'
import { rimTableFor } from '../src/reference/rimTables'
import { SHIPPED_INERTIA, SHIPPED_RATIO, SHIPPED_ROWS } from '../src/reference/rimTableRows'
import { referenceOutcome } from '../src/reference/index'

const cfg = DEFAULT_CONFIG
const R = cfg.HOLE_RADIUS
const r = cfg.BALL_RADIUS
const g = cfg.GRAVITY

/** One hole at the origin, one ball on +x at offset d that crosses the lip at speed v (no rolling loss). */
function shot(d: number, v: number, overrides = {}) {
  const sim = createBallPhysics({ ...TABULATED_CONFIG, ROLLING_DECEL: 0, ...overrides })
  sim.addHole({ x: 0, y: 0 })
  const lipX = -Math.sqrt(R * R - d * d)
  const ball = sim.addBall({ x: lipX - 30, y: d, vx: v, vy: 0 })
  return { sim, ball, lipTime: 30 / v }
}

function run(sim: ReturnType<typeof shot>['sim'], dt: number, seconds: number): BallEvent[] {
  const out: BallEvent[] = []
  while (sim.time < seconds - 1e-12) {
    sim.step(Math.min(dt, seconds - sim.time))
    out.push(...sim.drainEvents())
  }
  return out
}

describe('the rim table', () => {
  it('ships the capture rows of the design geometry, and recomputing them gives the same bits', () => {
    expect(SHIPPED_RATIO).toBe(R / r)
    expect(SHIPPED_INERTIA).toBe(cfg.BALL_INERTIA)
    expect(SHIPPED_ROWS.length).toBe(TABLE_ROWS)
    const rows = captureRows(R / r, cfg.BALL_INERTIA)
    expect(Array.from(rows)).toEqual(SHIPPED_ROWS)
    // and the table built from scratch is the table built from the shipped rows
    const a = buildRimTable(R / r, cfg.BALL_INERTIA, rows)
    const b = rimTableFor(R / r, cfg.BALL_INERTIA)
    expect(Array.from(a.values)).toEqual(Array.from(b.values))
    expect(Array.from(a.kind)).toEqual(Array.from(b.kind))
  }, 60_000)

  it('decides capture as the live reference on ≥ 99.5 % of a grid offset from its nodes, through the engine', () => {
    // 47 × 53 cells: no cell centre on a table row or node
    const grid = gameGrid(47, 53)
    const ref = referenceMap(grid, r, g, cfg.BALL_INERTIA)
    const tab = engineMap(grid, TABULATED_CONFIG)
    const design = engineMap(grid, {})
    const a = agreement(tab, ref.map)
    expect(a).toBeGreaterThanOrEqual(0.995)
    // far ahead of the design's six stages on the same cells (measured 82 %)
    expect(a - agreement(design, ref.map)).toBeGreaterThan(0.1)
  }, 60_000)

  it('the boundary per row: just below v_c captures, just above escapes, in the reference itself', () => {
    const t = rimTableFor(R / r, cfg.BALL_INERTIA)
    for (const d of [0, 3, 7.7, 12, 16.5]) {
      const vc = captureSpeedAt(t, d / r) * Math.sqrt(g * r)
      const input = { delta: d, speed: vc * 0.99, holeRadius: R, ballRadius: r, gravity: g, inertia: cfg.BALL_INERTIA }
      expect(referenceOutcome(input).captured, `δ = ${d}`).toBe(true)
      input.speed = vc * 1.01
      expect(referenceOutcome(input).captured, `δ = ${d}`).toBe(false)
    }
  })

  it('interpolates within one outcome kind: a roll-out never exits inside the lip circle', () => {
    const t = rimTableFor(R / r, cfg.BALL_INERTIA)
    for (let d = 8; d < 17; d += 0.37) {
      const ds = d / r
      for (let v = 150; v < 400; v += 13) {
        const vs = v / Math.sqrt(g * r)
        const captured = vs <= captureSpeedAt(t, ds)
        outcomeAt(t, ds, vs, captured)
        // (it leaves on the lip circle, or lands beyond it after a hop)
        if (rimOut.kind === RimKind.Rolled) expect(rimOut.exitRadius * r).toBeGreaterThanOrEqual(R * (1 - 1e-9))
        expect(Number.isFinite(rimOut.time) && rimOut.time >= 0).toBe(true)
      }
    }
    expect(crossingAngle(R / r, 0)).toBeCloseTo(Math.PI, 12)
  })

  it('rejects a geometry the reference cannot run, naming the field', () => {
    expect(() => buildRimTable(0.9, 0.4)).toThrow(/ratio .* must be in \(1, ∞\)/)
    expect(() => buildRimTable(1.5, 0.9)).toThrow(/inertia must be in \(0, 2\/3\]/)
    expect(() => createBallPhysics({ RIM_MODEL: 'lookup' as never })).toThrow(/RIM_MODEL must be one of 'stages', 'tabulated'/)
    expect(() => createBallPhysics({ RIM_MODEL: 'tabulated', METHOD: 'naive' })).toThrow(/RIM_MODEL 'tabulated' needs config.METHOD 'exact'/)
  })
})

describe('a ball at a tabulated crossing', () => {
  it('rolls round the lip and out: rides the lip circle for the reference’s time, to the reference’s exit', () => {
    const d = 10
    const v = 300
    const { sim, ball, lipTime } = shot(d, v)
    const ref = referenceOutcome({ delta: d, speed: v, holeRadius: R, ballRadius: r, gravity: g, inertia: cfg.BALL_INERTIA })
    expect(ref.ending).toBe('rolledOut')
    const events: BallEvent[] = []
    let lastAngle = Infinity
    let samples = 0
    while (sim.time < lipTime + ref.duration + 0.05) {
      sim.step(1 / 240)
      events.push(...sim.drainEvents())
      const st = sim.ballState(ball)
      if (st.mode !== 'rimRoll') continue
      // on the lip circle, turning one way (the ball passes above the hole, y down: the angle falls)
      samples++
      expect(Math.hypot(st.x, st.y)).toBeCloseTo(R, 6)
      const a = Math.atan2(st.y, st.x)
      const unwrapped = a > lastAngle + Math.PI ? a - 2 * Math.PI : a
      expect(unwrapped).toBeLessThan(lastAngle)
      lastAngle = unwrapped
    }
    expect(samples).toBeGreaterThan(30)
    expect(events.map((e) => e.type)).toEqual(['rimRoll', 'lipOut', 'nearMiss'])
    expect(events[0]!.time).toBeCloseTo(lipTime, 12)
    // the ride lasts the reference's time within the table's interpolation (measured 2.6 % here, 40 px/s
    // above the capture speed, where the time changes fastest)
    expect(Math.abs(events[1]!.time - lipTime - ref.duration)).toBeLessThan(0.05 * ref.duration)
    // leaves near the reference's exit point, at its exit speed
    const st = sim.ballState(ball)
    const back = sim.time - events[1]!.time
    // (measured 2.6 px after 4.5 rad round the lip: the turn is interpolated on a grid of 32 × 64 nodes)
    expect(Math.hypot(st.x - st.vx * back - ref.exitX!, st.y - st.vy * back - ref.exitY!)).toBeLessThan(3.5)
    expect(Math.abs(Math.hypot(st.vx, st.vy) - ref.exitSpeed!)).toBeLessThan(0.01 * v)
  })

  it('rolls round the lip and drops in: rimRoll, then capture via rimRoll at the end of the ride', () => {
    const { sim, ball, lipTime } = shot(14, 120)
    const ref = referenceOutcome({ delta: 14, speed: 120, holeRadius: R, ballRadius: r, gravity: g, inertia: cfg.BALL_INERTIA })
    expect(ref.captured).toBe(true)
    const ev = run(sim, 1 / 60, 1)
    expect(ev.map((e) => `${e.type}${e.via ? '/' + e.via : ''}`)).toEqual(['rimRoll', 'capture/rimRoll'])
    expect(Math.abs(ev[1]!.time - lipTime - ref.duration)).toBeLessThan(0.01 * ref.duration)
    expect(sim.ballState(ball).mode).toBe('captured')
  })

  it('a clean drop is captured at the crossing; a fast ball beyond the table asks the live reference', () => {
    const a = shot(2, 200)
    expect(run(a.sim, 1 / 60, 1).map((e) => `${e.type}/${e.via}`)).toEqual(['capture/clean'])
    const b = shot(3, 3000)
    const ev = run(b.sim, 1 / 60, 0.2)
    const ref = referenceOutcome({ delta: 3, speed: 3000, holeRadius: R, ballRadius: r, gravity: g, inertia: cfg.BALL_INERTIA })
    expect(ref.captured).toBe(false)
    expect(ev.map((e) => e.type)).toEqual(ref.impacts === 0 ? ['skip'] : ['bounce', 'nearMiss'])
    expect(ev[0]!.time).toBeCloseTo(b.lipTime, 12)
  })

  it('a bounce is carried across the hole to the reference’s exit point (rolling, hole locked), then leaves at its exit velocity', () => {
    const d = 1.2
    const v = 652
    const { sim, ball, lipTime } = shot(d, v)
    const ref = referenceOutcome({ delta: d, speed: v, holeRadius: R, ballRadius: r, gravity: g, inertia: cfg.BALL_INERTIA })
    expect(ref.captured).toBe(false)
    expect(ref.impacts).toBeGreaterThan(0)
    const ev = run(sim, 1 / 240, lipTime + ref.duration / 2)
    expect(ev.map((e) => e.type)).toEqual(['bounce', 'nearMiss'])
    // half way: rolling, inside the hole's lip circle, locked to it
    const mid = sim.ballState(ball)
    expect(mid.mode).toBe('rolling')
    expect(Math.hypot(mid.x, mid.y)).toBeLessThan(R)
    expect(sim.world.RimContact.mode[sim.world.Ball.rim[ball]!]).toBe(5)
    // at the reference's exit time, at its exit point (within the table's interpolation)
    run(sim, 1e-4, lipTime + ref.duration + 1e-4)
    const st = sim.ballState(ball)
    expect(Math.hypot(st.x - ref.exitX!, st.y - ref.exitY!)).toBeLessThan(1)
    // (the exit speed is interpolated: 3.5 px/s off here, 82 px/s; p90 over the fine grid 1.9 px/s)
    expect(Math.abs(Math.hypot(st.vx, st.vy) - ref.exitSpeed!)).toBeLessThan(5)
  })

  it('a wall met while carried across ends the crossing: the ball bounces off the wall, never beyond it', () => {
    const d = 1.2
    const v = 652
    const sim = createBallPhysics({ ...TABULATED_CONFIG, ROLLING_DECEL: 0 })
    sim.addHole({ x: 0, y: 0 })
    // the right wall cuts through the hole, short of the exit point (x ≈ 17.3)
    sim.setWalls({ minX: -200, minY: -200, maxX: 5 + r, maxY: 200, restitution: 0.5 })
    const ball = sim.addBall({ x: -Math.sqrt(R * R - d * d) - 30, y: d, vx: v, vy: 0 })
    const ev = run(sim, 1 / 120, 1)
    expect(ev.some((e) => e.type === 'wall')).toBe(true)
    expect(sim.ballState(ball).x).toBeLessThanOrEqual(5 + 1e-9)
  })

  it('the same events, bit for bit, at 30, 60 and 240 Hz (a ride ends at its time, not at a tick)', () => {
    const scene = (dt: number) => {
      const sim = createBallPhysics({ ...TABULATED_CONFIG })
      for (let i = 0; i < 5; i++) for (let j = 0; j < 4; j++) sim.addHole({ x: 60 + 80 * i, y: 60 + 80 * j })
      for (let n = 0; n < 200; n++) sim.addBall({ x: 20 + ((n * 37) % 380), y: 330, vx: ((n * 13) % 41) - 20, vy: -(150 + ((n * 29) % 500)) })
      return JSON.stringify(run(sim, dt, 2))
    }
    const at60 = scene(1 / 60)
    expect(at60).toContain('rimRoll')
    expect(at60).toContain('lipOut')
    expect(scene(1 / 30)).toBe(at60)
    expect(scene(1 / 240)).toBe(at60)
  })

  it('a ride or carry ended inside the integration pass (contacts off) gives the bits its own pass gives (exact contacts)', () => {
    const R = DEFAULT_CONFIG.HOLE_RADIUS
    const shots = (mode: 'off' | 'on') => {
      const sim = createBallPhysics({ ...TABULATED_CONFIG, BALL_COLLISIONS: mode }, { capacity: 64 })
      sim.addHole({ x: 0, y: 0 })
      const out: string[] = []
      for (let n = 0; n < 60; n++) {
        const delta = ((n % 20) * R) / 20
        const b = sim.addBall({ x: -Math.sqrt(R * R - delta * delta) - 1, y: delta, vx: 40 + 23 * n, vy: 0 })
        for (let k = 0; k < 10; k++) {
          sim.step(1 / 20)
          const s = sim.ballState(b)
          out.push(`${s.x} ${s.y} ${s.vx} ${s.vy} ${s.mode}`)
        }
        for (const e of sim.drainEvents()) out.push(`${e.type} ${e.time} ${e.type === 'capture' ? e.via : ''}`)
        sim.removeBall(b)
      }
      return out
    }
    const off = shots('off')
    // every kind of ending is among the shots: rides out and in, bounces and skips carried across
    expect(off.filter((l) => l.startsWith('lipOut')).length).toBeGreaterThan(5)
    expect(off.filter((l) => l.startsWith('capture') && l.endsWith('rimRoll')).length).toBeGreaterThan(0)
    expect(off.filter((l) => l.startsWith('bounce') || l.startsWith('skip')).length).toBeGreaterThan(0)
    expect(shots('on')).toEqual(off)
  })

  it('with contacts on, a ball struck while it rides leaves the lip in transit, and every state stays finite', () => {
    const { sim, ball } = shot(10, 300, { BALL_COLLISIONS: 'on' })
    run(sim, 1 / 120, 0.15)
    expect(sim.ballState(ball).mode).toBe('rimRoll')
    const p = sim.ballState(ball)
    // a striker aimed at the riding ball's position a little later
    const striker = sim.addBall({ x: p.x, y: p.y - 60, vx: 0, vy: 900 })
    const ev = run(sim, 1 / 120, 0.6)
    expect(ev.some((e) => e.type === 'collision')).toBe(true)
    for (const b of [ball, striker]) {
      const st = sim.ballState(b)
      expect(Number.isFinite(st.x) && Number.isFinite(st.y) && Number.isFinite(st.vx) && Number.isFinite(st.vy)).toBe(true)
      expect(st.mode).not.toBe('rimRoll')
    }
  })

  it('tabulatedCaptureSpeed beyond the table\'s top speed is the live reference\'s (as the engine decides there); below it, the table\'s', async () => {
    const { referenceCaptureSpeed } = await import('../src/reference/index')
    // a ball of radius 0.01 in an 18-px hole: the rows only say the capture speed lies past the table's top
    // (they stop at 64 times it); this gave that cap, 3,842 px/s at every δ, against the reference's 21,221
    for (const d of [0, 9]) expect(tabulatedCaptureSpeed(d, 18, 0.01, g)).toBe(referenceCaptureSpeed(d, 18, 0.01, g, 0.4))
    expect(tabulatedCaptureSpeed(0, 18, 0.01, g)).toBeGreaterThan(20_000)
    // the design geometry: the table's row, within a px/s of the reference
    const table = tabulatedCaptureSpeed(5, R, r, g)
    expect(Math.abs(table - referenceCaptureSpeed(5, R, r, g, cfg.BALL_INERTIA))).toBeLessThan(1)
  })

  it("a world's own table has every capture row when the world is made: no step builds one", () => {
    // BALL_RADIUS 3: a geometry no test builds before (the table cache is the process's); its rows were found
    // inside the steps whose crossings first needed them (128 first crossings at radius 16.66: one step of 11 s)
    const sim = createBallPhysics({ ...TABULATED_CONFIG, BALL_RADIUS: 3 })
    const t = sim.world.rimTables[0]!
    expect(t.ratio).toBe(R / 3)
    expect(t.vc.length).toBe(TABLE_ROWS)
    expect(Array.from(t.vc).filter((v) => !Number.isFinite(v))).toEqual([])
  })

  it('another ball size: the live reference decides until prepareRimTable gives the world its table', () => {
    const small = 7
    const cases: Array<[number, number]> = [
      [4, 150],
      [12, 300],
    ]
    const outcomes = (prepare: boolean) => {
      const sim = createBallPhysics({ ...TABULATED_CONFIG, ROLLING_DECEL: 0 })
      if (prepare) expect(prepareRimTable(sim, R, small, { rows: 'lazy' })).toBeLessThan(timeBudget(1000))
      sim.addHole({ x: 0, y: 0 })
      return cases.map(([d, v]) => {
        const b = sim.addBall({ x: -Math.sqrt(R * R - d * d) - 20, y: d, vx: v, vy: 0, radius: small })
        for (let i = 0; i < 120; i++) sim.step(1 / 60)
        sim.drainEvents()
        return sim.ballState(b).mode === 'captured'
      })
    }
    const expected = cases.map(([d, v]) => referenceOutcome({ delta: d, speed: v, holeRadius: R, ballRadius: small, gravity: g, inertia: cfg.BALL_INERTIA }).captured)
    expect(outcomes(false)).toEqual(expected)
    expect(outcomes(true)).toEqual(expected)
    const sim = createBallPhysics(TABULATED_CONFIG)
    expect(() => prepareRimTable(sim, 18, 18)).toThrow(/ballRadius must be in \[holeRadius \/ 100000000, holeRadius \/ 1\.08\]/)
    expect(() => prepareRimTable(sim, -1, 5)).toThrow(/holeRadius must be a finite number/)
    expect(() => prepareRimTable(sim, 18, 5, { rows: 'later' as never })).toThrow(/options.rows must be 'now' or 'lazy'/)
    // the wrong type is a TypeError; past the reference's domain (R/r above 1e8) a RangeError; before any work
    expect(() => prepareRimTable(sim, '18' as never, 5)).toThrow(TypeError)
    expect(() => prepareRimTable(sim, 18, 5, { inertia: '0.4' as never })).toThrow(/options.inertia must be a number in \(0, 2\/3\], got the string "0.4"/)
    expect(() => prepareRimTable(sim, 18, 5, { inertia: 1 })).toThrow(RangeError)
    expect(() => prepareRimTable(sim, 1e4, 1e-5)).toThrow(/ballRadius must be in \[holeRadius \/ 100000000, holeRadius \/ 1\.08\] = \[0\.0001, 9259\.25925925926\] \(closer to the hole's size a table's rows take minutes\), got 0\.00001/)
    expect(() => prepareRimTable(null as never, 18, 5)).toThrow(/prepareRimTable: world must be/)
    // only a tabulated world reads its tables (a hero ball runs the reference live): in another, one was
    // built and did nothing
    const stages = createBallPhysics()
    expect(() => prepareRimTable(stages, 18, 8, { rows: 'lazy' })).toThrow(/config\.RIM_MODEL is 'stages'; its tables are read only with RIM_MODEL 'tabulated'/)
    expect(stages.world.rimTables).toEqual([])
    expect(() => tabulatedCaptureSpeed(3, 18, 11, Number.NaN)).toThrow(/gravity must be a finite number in \(0, ∞\), got NaN/)
    expect(() => tabulatedCaptureSpeed(3, 18, 11, -1)).toThrow(RangeError)
    // near the hole's size (R/r under 1.08) a table's rows take minutes (R/r 1.059: 117 s): refused, and such a
    // ball's crossing in a tabulated world is left to the stages, in milliseconds
    expect(() => prepareRimTable(sim, 18, 17)).toThrow(/holeRadius \/ 1\.08\] = \[1\.8e-7, 16\.666666666666664\]/)
    expect(() => createBallPhysics({ ...TABULATED_CONFIG, BALL_RADIUS: 17 })).toThrow(/config\.BALL_RADIUS must be at most HOLE_RADIUS \/ 1\.08 = 16\.666666666666664 with RIM_MODEL 'tabulated'/)
    expect(() => createBallPhysics({ ...TABULATED_CONFIG, BALL_RADIUS: 18 - 1e-9 })).toThrow(RangeError)
    expect(sim.world.rimTables.length).toBe(1)
    const crossing = (config: typeof TABULATED_CONFIG): string[] => {
      const w = createBallPhysics(config)
      w.addHole({ x: 0, y: 0 })
      const b = w.addBall({ x: -40, y: 5, vx: 300, vy: 0, radius: 17 })
      for (let i = 0; i < 60; i++) w.step(1 / 60)
      return w.drainEvents().filter((e) => e.ball === b).map((e) => `${e.type} ${e.time}`)
    }
    const tabulated = crossing(TABULATED_CONFIG)
    expect(tabulated.length).toBeGreaterThan(0)
    expect(tabulated).toEqual(crossing({ ...TABULATED_CONFIG, RIM_MODEL: 'stages' }))
  }, 60_000)
})
