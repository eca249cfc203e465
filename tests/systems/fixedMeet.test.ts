// The fixed tick's pairs alone at their tick meet at their instant (src/contacts/fixedMeet.ts).
import { describe, expect, it } from 'vitest'
import { DEFAULT_PANEL, addPanel, createBallPhysics, type BallEvent, type BallPhysics, type ConfigOverrides } from '../../src/index'
import { rng } from '../helpers'
import { delayMotion } from '../../src/motion/pause'

const FIXED: ConfigOverrides = { BALL_COLLISIONS: 'fixed', CONTACT_TIMING: 'instant' }

function run(sim: BallPhysics, steps: number, dt: number): BallEvent[] {
  const out: BallEvent[] = []
  for (let i = 0; i < steps; i++) {
    sim.step(dt)
    out.push(...sim.drainEvents())
  }
  return out
}

/** Every ball's state, to the bit. */
function states(sim: BallPhysics): string {
  return sim
    .balls()
    .map((b) => {
      const s = sim.ballState(b)
      return `${b}:${s.mode}:${s.x}:${s.y}:${s.vx}:${s.vy}`
    })
    .join(' ')
}

/**
 * One collision in each run, the fixed tick's met at its instant: at the exact method's time (within 1e-9 s),
 * with its impulse, and the balls `ids` ending in its modes, positions and velocities (within 1e-5).
 */
function expectAsExact(exact: { sim: BallPhysics; ev: BallEvent[] }, fixed: { sim: BallPhysics; ev: BallEvent[] }, ids: number[]): void {
  const ee = exact.ev.filter((e) => e.type === 'collision')
  const ef = fixed.ev.filter((e) => e.type === 'collision')
  expect(ee).toHaveLength(1)
  expect(ef).toHaveLength(1)
  expect(Math.abs(ef[0]!.time - ee[0]!.time)).toBeLessThan(1e-9)
  expect(ef[0]!.impulse).toBeCloseTo(ee[0]!.impulse, 5)
  expect(fixed.sim.world.meet!.timed).toBe(1)
  for (const b of ids) {
    const s = exact.sim.ballState(b)
    const f = fixed.sim.ballState(b)
    expect(f.mode).toBe(s.mode)
    expect(Math.abs(f.x - s.x) + Math.abs(f.y - s.y)).toBeLessThan(1e-5)
    expect(Math.abs(f.vx - s.vx) + Math.abs(f.vy - s.vy)).toBeLessThan(1e-5)
  }
}

/** Two balls on the default panel's deceleration meeting at an angle, the second slower and heavier. */
function glancing(config: ConfigOverrides): BallPhysics {
  const sim = createBallPhysics({ BALL_RESTITUTION: 0.9, ...config })
  sim.addBall({ x: 100, y: 300, vx: 420, vy: -130 })
  sim.addBall({ x: 190, y: 262, vx: -60, vy: 15, mass: 2 })
  return sim
}

describe('fixed tick: a pair alone at its tick meets at its instant', () => {
  it('with deceleration, at an angle, unequal masses: the time, the velocities and the positions of the exact method', () => {
    const exact = glancing({ BALL_COLLISIONS: 'on' })
    const fixed = glancing(FIXED)
    const ee = run(exact, 60, 1 / 120).filter((e) => e.type === 'collision')
    const ef = run(fixed, 60, 1 / 120).filter((e) => e.type === 'collision')
    expect(ee).toHaveLength(1)
    expect(ef).toHaveLength(1)
    // the exact method stops its search within 1e-7 px of the touch: its instant is that much earlier
    expect(Math.abs(ef[0]!.time - ee[0]!.time)).toBeLessThan(1e-9)
    expect(ef[0]!.time * 120 % 1).toBeGreaterThan(0.01)
    expect(ef[0]!.impulse).toBeCloseTo(ee[0]!.impulse, 5)
    for (const b of exact.balls()) {
      const s = exact.ballState(b)
      const f = fixed.ballState(b)
      expect(Math.abs(f.x - s.x) + Math.abs(f.y - s.y)).toBeLessThan(1e-5)
      expect(Math.abs(f.vx - s.vx) + Math.abs(f.vy - s.vy)).toBeLessThan(1e-5)
    }
    expect(fixed.world.meet!.timed).toBe(1)
  })

  it('the same bits at 30, 60, 120 and 240 Hz, and momentum kept, over a burst of 40 balls on the panel', () => {
    const burst = (hz: number): { bits: string; sim: BallPhysics } => {
      const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 0.9 })
      addPanel(sim)
      sim.setWalls({ minX: 0, minY: 0, maxX: DEFAULT_PANEL.width, maxY: DEFAULT_PANEL.height, restitution: 0.9, open: { bottom: true } })
      const r = rng(5)
      for (let i = 0; i < 40; i++) {
        const x = 30 + 40 * (i % 10) + (r() - 0.5) * 16
        const y = DEFAULT_PANEL.height - 150 + 40 * Math.floor(i / 10) + (r() - 0.5) * 16
        const speed = 175 + (0.2 + 0.7 * r()) * 525
        const angle = (r() - 0.5) * 0.8
        sim.addBall({ x, y, vx: speed * Math.sin(angle), vy: -speed * Math.cos(angle) })
      }
      run(sim, hz, 1 / hz)
      return { bits: states(sim), sim }
    }
    const at30 = burst(30)
    expect(at30.sim.world.meet!.timed).toBeGreaterThan(10)
    for (const hz of [60, 120, 240]) expect(burst(hz).bits).toBe(at30.bits)
  })

  it("with CONTACT_TIMING 'tick' the pair meets at its tick, up to one tick early", () => {
    const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 1, ROLLING_DECEL: 0, CONTACT_TIMING: 'tick' })
    const a = sim.addBall({ x: 0, y: 0, vx: 300, vy: 0 })
    const b = sim.addBall({ x: 100, y: 0, vx: -200, vy: 0 })
    const ev = run(sim, 60, 1 / 120).filter((e) => e.type === 'collision')
    expect(ev).toHaveLength(1)
    // paired at 18/120 s, 0.006 s before the touch
    expect(ev[0]!.time).toBe(18 / 120)
    expect(sim.world.meet!.timed).toBe(0)
    expect(sim.ballState(a).vx).toBeCloseTo(-200, 9)
    // leaving from where they were at the tick: 3 px apart, not touching
    expect(sim.ballState(b).x - sim.ballState(a).x).toBeCloseTo(22 + 3 + 500 * (0.5 - 0.15), 9)
    expect(() => createBallPhysics({ ...FIXED, CONTACT_TIMING: 'exact' as never })).toThrow(/CONTACT_TIMING/)
  })

  it("CONTACT_TIMING 'auto' (the default): at the instant while the world has holes, at the tick without", () => {
    const pair = (hole: boolean) => {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 1, ROLLING_DECEL: 0 })
      expect(sim.world.config.CONTACT_TIMING).toBe('auto')
      if (hole) sim.addHole({ x: 5000, y: 5000 })
      sim.addBall({ x: 0, y: 0, vx: 300, vy: 0 })
      sim.addBall({ x: 100, y: 0, vx: -200, vy: 0 })
      return run(sim, 60, 1 / 120).filter((e) => e.type === 'collision')[0]!.time
    }
    expect(Math.abs(pair(true) - 0.156)).toBeLessThan(1e-12)
    expect(pair(false)).toBe(18 / 120)
  })

  it('a pair and its instant between steps: a snapshot taken there steps on to the same bits', () => {
    // touch at 0.156 s, paired at the tick 18/120 s = 0.15 s; steps of 1/480 s end at 0.1541667 s in between
    const make = () => {
      const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 1, ROLLING_DECEL: 0 })
      sim.addBall({ x: 0, y: 0, vx: 300, vy: 0 })
      sim.addBall({ x: 100, y: 0, vx: -200, vy: 0 })
      return sim
    }
    const whole = make()
    run(whole, 74, 1 / 480)
    const bytes = whole.snapshot()
    run(whole, 200, 1 / 480)
    const copy = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 1, ROLLING_DECEL: 0 })
    copy.restore(bytes)
    const ev = run(copy, 200, 1 / 480).filter((e) => e.type === 'collision')
    expect(ev).toHaveLength(1)
    expect(Math.abs(ev[0]!.time - 0.156)).toBeLessThan(1e-12)
    expect(states(copy)).toBe(states(whole))
  })

  it('a new velocity given to one ball before the instant: the solve it asks for times the pair again', () => {
    const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 1, ROLLING_DECEL: 0 })
    const a = sim.addBall({ x: 0, y: 0, vx: 300, vy: 0 })
    const b = sim.addBall({ x: 100, y: 0, vx: -200, vy: 0 })
    run(sim, 74, 1 / 480)
    expect(sim.drainEvents()).toHaveLength(0)
    // at 74/480 s: a at 46.25, b at 69.1667, 0.91667 px apart, now closing at 450 px/s
    sim.setBallVelocity(a, 250, 0)
    const touch = 74 / 480 + (100 - 22 - 500 * (74 / 480)) / 450
    const ev = run(sim, 200, 1 / 480).filter((e) => e.type === 'collision')
    expect(ev).toHaveLength(1)
    expect(Math.abs(ev[0]!.time - touch)).toBeLessThan(1e-12)
    expect(sim.world.meet!.timed).toBe(2)
    // equal masses, e = 1: exchanged
    expect(sim.ballState(a).vx).toBeCloseTo(-200, 9)
    expect(sim.ballState(b).vx).toBeCloseTo(250, 9)
  })

  it('walls set between the tick and the instant: the two still meet at it', () => {
    const make = (walls: boolean) => {
      const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 1, ROLLING_DECEL: 0 })
      sim.addBall({ x: 100, y: 100, vx: 300, vy: 0 })
      sim.addBall({ x: 200, y: 100, vx: -200, vy: 0 })
      run(sim, 74, 1 / 480)
      if (walls) sim.setWalls({ minX: 0, minY: 0, maxX: 1000, maxY: 1000, restitution: 1 })
      return sim
    }
    const walled = make(true)
    const ev = run(walled, 20, 1 / 480).filter((e) => e.type === 'collision')
    expect(ev).toHaveLength(1)
    expect(Math.abs(ev[0]!.time - 0.156)).toBeLessThan(1e-12)
    const open = make(false)
    run(open, 20, 1 / 480)
    for (const b of open.balls()) {
      expect(walled.ballState(b).x).toBeCloseTo(open.ballState(b).x, 9)
      expect(walled.ballState(b).vx).toBe(open.ballState(b).vx)
    }
  })

  it('a ball of the pair delayed (a step out of passes waits it out): neither takes the impulse at the instant', () => {
    const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 1, ROLLING_DECEL: 0 })
    const a = sim.addBall({ x: 0, y: 0, vx: 300, vy: 0 })
    const b = sim.addBall({ x: 100, y: 0, vx: -200, vy: 0 })
    run(sim, 74, 1 / 480)
    const M = sim.world.meet!
    expect([M.with[a], M.with[b]]).toEqual([b, a])
    expect(M.t[a]).toBe(M.t[b])
    // as src/motion/pause.ts does to a ball still behind at a step's end: its motion 1 ms later
    delayMotion(sim.world, a, 0.001)
    const ev = run(sim, 200, 1 / 480).filter((e) => e.type === 'collision')
    expect(ev).toHaveLength(1)
    // met by the next tick instead
    expect(ev[0]!.time).toBe(19 / 120)
    expect(sim.ballState(a).vx + sim.ballState(b).vx).toBeCloseTo(100, 9)
    expect(sim.ballState(b).x - sim.ballState(a).x).toBeGreaterThan(22)
  })

  it('one ball of the pair removed before the instant: the other goes on as it was', () => {
    const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 1, ROLLING_DECEL: 0 })
    const a = sim.addBall({ x: 0, y: 0, vx: 300, vy: 0 })
    const b = sim.addBall({ x: 100, y: 0, vx: -200, vy: 0 })
    run(sim, 74, 1 / 480)
    sim.removeBall(b)
    // a new ball takes b's id and is put down far away, at rest
    const c = sim.addBall({ x: 400, y: 400, vx: 0, vy: 0 })
    const ev = run(sim, 100, 1 / 480)
    expect(ev.filter((e) => e.type === 'collision')).toHaveLength(0)
    expect(sim.ballState(a).vx).toBe(300)
    expect(sim.ballState(a).x).toBeCloseTo(300 * (174 / 480), 9)
    expect(sim.ballState(c).x).toBe(400)
  })

  // the head-on pair of the tests above (touch at 0.156 s, paired at the tick 18/120 s) with a third ball
  // within reach of the first, which no contact of the tick touches
  const withThird = (third: { x: number; y: number; vx: number; vy: number }) => {
    const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 1, ROLLING_DECEL: 0 })
    const a = sim.addBall({ x: 0, y: 0, vx: 300, vy: 0 })
    sim.addBall({ x: 100, y: 0, vx: -200, vy: 0 })
    const c = sim.addBall(third)
    const ev = run(sim, 24, 1 / 120).filter((e) => e.type === 'collision')
    return { sim, a, c, ev }
  }

  it('a third ball within reach that keeps clear of the meeting: the pair still meets at its instant', () => {
    // 25 px above the first ball (radii 11), moving with it: paired with it at every tick, never touching
    const { sim, a, c, ev } = withThird({ x: 0, y: 25, vx: 300, vy: 0 })
    expect(ev).toHaveLength(1)
    expect(Math.abs(ev[0]!.time - 0.156)).toBeLessThan(1e-12)
    expect(sim.world.meet!.timed).toBe(1)
    expect(sim.ballState(a).vx).toBeCloseTo(-200, 9)
    expect(sim.ballState(c)).toMatchObject({ vx: 300, vy: 0, y: 25 })
  })

  it('a third ball the first would reach on its way to the instant: the pair meets at its tick', () => {
    // at the tick 18/120 s the first ball is at (45, 0) and this one at (55, 20), 22.4 px apart (radii 11);
    // sent back at the tick, the first ball leaves it, but going on to the instant (46.8, 0) it would be
    // 21.6 px from it: the pair is solved at the tick, as without the instant
    const { sim, c, ev } = withThird({ x: 55, y: 20 - 0.15, vx: 0, vy: 1 })
    expect(ev).toHaveLength(1)
    expect(ev[0]!.time).toBe(18 / 120)
    expect(sim.world.meet!.timed).toBe(0)
    expect(sim.ballState(c)).toMatchObject({ vx: 0, vy: 1 })
    for (const b of sim.balls()) for (const o of sim.balls()) {
      if (o <= b) continue
      const p = sim.ballState(b)
      const q = sim.ballState(o)
      expect(Math.hypot(p.x - q.x, p.y - q.y)).toBeGreaterThan(22 - 1e-9)
    }
  })
})

describe('fixed tick: a meeting after bookkeeping of its own (a near miss, a skip-over, the exit from a locked hole)', () => {
  // a at 1,000 px/s meets b at −100 px/s head on at 178 / 1,100 s; paired at the tick 19/120 s, when a is at
  // x = 158.3, and a is at 161.8 at the instant. A hole beside a's path (radius 18) whose event falls between
  // the two: a near miss at its closest approach (centre 23 px off the path), or a lip crossing at 17.937 px
  // off it, which a flies over (v_skip is 53 px/s there), and the exit from its lip circle 3 px later.
  const TOUCH = 178 / 1100
  const head = (offset: number | null, firstA: boolean, hz = 120) => {
    const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 1, ROLLING_DECEL: 0 })
    if (offset !== null) sim.addHole({ x: 160, y: offset, radius: 18 })
    else sim.addHole({ x: 5000, y: 5000 })
    const A = { x: 0, y: 0, vx: 1000, vy: 0 }
    const B = { x: 200, y: 0, vx: -100, vy: 0 }
    const ids = firstA ? [sim.addBall(A), sim.addBall(B)] : [sim.addBall(B), sim.addBall(A)].reverse()
    const ev = run(sim, hz / 2, 1 / hz)
    const bits = ids.map((b) => {
      const s = sim.ballState(b)
      return `${s.mode}:${s.x}:${s.y}:${s.vx}:${s.vy}`
    })
    return { sim, ev, bits, a: ids[0]!, b: ids[1]! }
  }

  it('a near miss of one ball between the tick and the instant: the pair meets at its instant, with the bits of a panel without the hole', () => {
    const plain = head(null, true)
    expect(plain.sim.world.meet!.timed).toBe(1)
    for (const firstA of [true, false]) {
      const r = head(23, firstA)
      const col = r.ev.filter((e) => e.type === 'collision')
      expect(col).toHaveLength(1)
      expect(Math.abs(col[0]!.time - TOUCH)).toBeLessThan(1e-12)
      expect(r.sim.world.meet!.timed).toBe(1)
      // the near miss on the way in, before the meeting, and again on the way back
      const near = r.ev.filter((e) => e.type === 'nearMiss' && e.ball === r.a).map((e) => e.time)
      expect(near[0]).toBeCloseTo(0.16, 12)
      expect(near[0]!).toBeGreaterThan(19 / 120)
      expect(near[0]!).toBeLessThan(col[0]!.time)
      expect(near).toHaveLength(2)
      expect(r.bits).toEqual(plain.bits)
    }
  })

  it('a skip-over and the exit from the lip circle between the tick and the instant: the pair meets at its instant, the same bits at 30, 60, 120 and 240 Hz', () => {
    const plain = head(null, true)
    for (const firstA of [true, false]) {
      const r = head(17.937, firstA)
      const col = r.ev.filter((e) => e.type === 'collision')
      expect(col).toHaveLength(1)
      expect(Math.abs(col[0]!.time - TOUCH)).toBeLessThan(1e-12)
      const skips = r.ev.filter((e) => e.type === 'skip' && e.ball === r.a).map((e) => e.time)
      expect(skips[0]!).toBeGreaterThan(19 / 120)
      expect(skips[0]!).toBeLessThan(col[0]!.time)
      expect(r.bits).toEqual(plain.bits)
      for (const hz of [30, 60, 240]) expect(head(17.937, firstA, hz).bits).toEqual(r.bits)
    }
  })

  it('a ball whose path a hole changes before the instant (its contact circle: a bounce): the pair meets at its tick', () => {
    // a at 500 px/s crosses the lip of a hole 10 px beside its path, too slow to fly over, and reaches the
    // contact circle between the tick 24/120 s and the instant (0.2049 s without the hole), where the COG gate
    // sends it on a new path
    const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 1, ROLLING_DECEL: 0 })
    sim.addHole({ x: 108, y: -10, radius: 18 })
    sim.addBall({ x: 0, y: 0, vx: 500, vy: 0 })
    sim.addBall({ x: 115, y: 100, vx: 0, vy: -400 })
    const col = run(sim, 60, 1 / 120).filter((e) => e.type === 'collision')
    expect(col).toHaveLength(1)
    expect(col[0]!.time).toBe(24 / 120)
    expect(sim.world.meet!.timed).toBe(0)
  })
})

describe('fixed tick: a rolling ball alone at its tick with a ball at rest meets it at its instant', () => {
  // a decelerating ball strikes a resting one off centre; the resting one keeps its spot until the instant
  const strike = (config: ConfigOverrides, hz = 120) => {
    const sim = createBallPhysics({ BALL_RESTITUTION: 0.9, ...config })
    sim.addHole({ x: 5000, y: 5000 })
    const a = sim.addBall({ x: 100, y: 300, vx: 420, vy: -30 })
    const r = sim.addBall({ x: 190, y: 285, vx: 0, vy: 0, mass: 1.5 })
    const ev = run(sim, hz / 2, 1 / hz)
    return { sim, a, r, ev }
  }

  it('the time, the velocities and the positions of the exact method; the same bits at 30, 60, 120 and 240 Hz', () => {
    const exact = strike({ BALL_COLLISIONS: 'on' })
    const fixed = strike(FIXED)
    expectAsExact(exact, fixed, [fixed.a, fixed.r])
    // not at a tick
    const t = fixed.ev.find((e) => e.type === 'collision')!.time
    expect(t * 120 % 1).toBeGreaterThan(0.01)
    expect(t * 120 % 1).toBeLessThan(0.99)
    for (const hz of [30, 60, 240]) {
      const other = strike(FIXED, hz)
      expect(states(other.sim)).toBe(states(fixed.sim))
    }
  })

  it('between the tick and the instant the resting ball stays where it is; removed (its id put down elsewhere) or moved, the rolling ball goes on as it was', () => {
    // the pair's tick is 38/120 s (the touch about 0.3188 s); look at 0.3177 s, between the two
    const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 0.9 })
    sim.addHole({ x: 5000, y: 5000 })
    const a = sim.addBall({ x: 100, y: 300, vx: 420, vy: -30 })
    const r = sim.addBall({ x: 190, y: 285, vx: 0, vy: 0, mass: 1.5 })
    const M = sim.world.meet!
    let steps = 0
    while (M.with[a] === 0 && steps < 200) {
      sim.step(1 / 960)
      steps++
    }
    expect(M.with[a]).toBe(r)
    expect(M.with[r]).toBe(a)
    const instant = M.t[a]!
    expect(sim.time).toBeLessThan(instant)
    expect(instant * 120 % 1).toBeGreaterThan(0.01)
    expect(sim.ballState(r)).toMatchObject({ mode: 'resting', x: 190, y: 285, vx: 0, vy: 0 })
    const copy = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 0.9 })
    copy.restore(sim.snapshot())
    // the resting ball removed; a new ball takes its id, at rest far away
    sim.removeBall(r)
    expect(sim.addBall({ x: 400, y: 100, vx: 0, vy: 0, mass: 1.5 })).toBe(r)
    const before = sim.ballState(a)
    const ev = run(sim, 4, 1 / 960)
    expect(ev.filter((e) => e.type === 'collision')).toHaveLength(0)
    expect(sim.ballState(r)).toMatchObject({ mode: 'resting', x: 400, y: 100 })
    expect(sim.ballState(a).vx).toBeLessThan(before.vx)
    expect(Math.sign(sim.ballState(a).vx)).toBe(1)
    // moved while at rest (as the projection of a solve between the tick and the instant moves a ball at
    // rest, src/contacts/fixedApply.ts), 5 px back: the rolling ball goes on as it was, not struck from afar
    const moved = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 0.9 })
    moved.restore(copy.snapshot())
    moved.world.Ball.x[r] = 195
    expect(run(moved, 4, 1 / 960).filter((e) => e.type === 'collision')).toHaveLength(0)
    expect(moved.ballState(r)).toMatchObject({ mode: 'resting', x: 195, vx: 0 })
    // the copy, left alone, meets at the instant
    const met = run(copy, 4, 1 / 960).filter((e) => e.type === 'collision')
    expect(met).toHaveLength(1)
    expect(met[0]!.time).toBe(instant)
    expect(copy.ballState(r).mode).toBe('rolling')
  })
})

describe('fixed tick: a ball on a rim struck alone meets its striker at the instant', () => {
  const onRim = (config: ConfigOverrides, striker = true, turn = false) => {
    const sim = createBallPhysics(config)
    sim.addHole({ x: 0, y: 0 })
    const lipX = -Math.sqrt(18 * 18 - 11 * 11)
    const b = sim.addBall({ x: lipX - 60, y: 11, vx: Math.sqrt(490 ** 2 + 2 * 300 * 60), vy: 0 })
    for (let i = 0; i < 200 && sim.ballState(b).mode !== 'rimRoll'; i++) sim.step(1 / 500)
    expect(sim.ballState(b).mode).toBe('rimRoll')
    const st = sim.ballState(b)
    const v = Math.hypot(st.vx, st.vy)
    // a striker 4 px ahead of it along its tangent, coming back along it (it meets the ball 0.2 rad round)
    const s = striker ? sim.addBall({ x: st.x + (26 * st.vx) / v, y: st.y + (26 * st.vy) / v, vx: (-300 * st.vx) / v, vy: (-300 * st.vy) / v }) : 0
    const ev = run(sim, 1, 1 / 2000)
    if (turn) {
      // the striker sent away before the instant, once the meeting is set
      expect(sim.world.meet!.with[b]).toBe(s)
      sim.setBallVelocity(s, (300 * st.vx) / v, (300 * st.vy) / v)
    }
    ev.push(...run(sim, 30, 1 / 500))
    return { sim, b, s, ev }
  }

  it('its striker sent away before the instant: the ball rolls on round the rim as it would alone', () => {
    const alone = onRim(FIXED, false)
    const turned = onRim(FIXED, true, true)
    expect(turned.ev.filter((e) => e.type === 'collision')).toHaveLength(0)
    const a = alone.sim.ballState(alone.b)
    const t = turned.sim.ballState(turned.b)
    expect(t.mode).toBe(a.mode)
    expect(Math.abs(t.x - a.x) + Math.abs(t.y - a.y)).toBeLessThan(1e-9)
    const end = (ev: BallEvent[]) => ev.filter((e) => e.ball === alone.b && e.type !== 'rimRoll').map((e) => `${e.type} ${e.time}`)
    expect(end(turned.ev)).toEqual(end(alone.ev))
  })

  it('the time, the velocities and the positions of the exact method', () => {
    const exact = onRim({ BALL_COLLISIONS: 'on' })
    const fixed = onRim(FIXED)
    expectAsExact(exact, fixed, [fixed.b, fixed.s])
  })
})
