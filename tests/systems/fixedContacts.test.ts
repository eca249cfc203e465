// The fixed-tick contact method (BALL_COLLISIONS 'fixed'): contacts solved at k·CONTACT_TICK.
import fc from 'fast-check'
import { describe, expect, it } from 'vitest'
import { DEFAULT_PANEL, addPanel, createBallPhysics, type BallEvent, type BallPhysics, type ConfigOverrides } from '../../src/index'
import { EXACT, rng, timeBudget } from '../helpers'

const FIXED: ConfigOverrides = { BALL_COLLISIONS: 'fixed' }
const TICK = 1 / 120

function run(sim: BallPhysics, seconds: number, dt: number): BallEvent[] {
  const out: BallEvent[] = []
  const n = Math.round(seconds / dt)
  for (let i = 0; i < n; i++) {
    sim.step(dt)
    out.push(...sim.drainEvents())
  }
  return out
}

function onPanel(sim: BallPhysics): number[] {
  return sim.balls().filter((b) => {
    const m = sim.ballState(b).mode
    return m === 'rolling' || m === 'resting' || m === 'rimRoll'
  })
}

/** Deepest overlap of two balls on the panel, px (0: none). */
function worstOverlap(sim: BallPhysics): number {
  const B = sim.world.Ball
  const ids = onPanel(sim)
  let worst = 0
  for (let i = 0; i < ids.length; i++) {
    for (let j = i + 1; j < ids.length; j++) {
      const a = ids[i]!
      const b = ids[j]!
      const o = B.radius[a]! + B.radius[b]! - Math.hypot(B.x[a]! - B.x[b]!, B.y[a]! - B.y[b]!)
      if (o > worst) worst = o
    }
  }
  return worst
}

function kinetic(sim: BallPhysics): number {
  const B = sim.world.Ball
  const F = sim.world.fixed!
  let k = 0
  for (const b of sim.balls()) k += 0.5 * F.mass[b]! * (B.vx[b]! ** 2 + B.vy[b]! ** 2)
  return k
}

describe('fixed-tick contacts', () => {
  it('head-on, equal masses, e = 1, a pair alone at its tick: velocities exchanged at the touch, where the exact method puts it', () => {
    const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 1, ROLLING_DECEL: 0, CONTACT_TIMING: 'instant' })
    const a = sim.addBall({ x: 0, y: 0, vx: 300, vy: 0 })
    const b = sim.addBall({ x: 100, y: 0, vx: -200, vy: 0 })
    const touch = (100 - 22) / 500
    const ev = run(sim, 0.5, 1 / 60).filter((e) => e.type === 'collision')
    expect(ev).toHaveLength(1)
    // not on a tick: 0.156 s is 18.72 ticks
    expect(Math.abs(ev[0]!.time - touch)).toBeLessThan(1e-12)
    expect(sim.ballState(a).vx).toBeCloseTo(-200, 9)
    expect(sim.ballState(b).vx).toBeCloseTo(300, 9)
    // from the touch: a at 300·0.156 − 200·0.344, b at 100 − 200·0.156 + 300·0.344
    expect(sim.ballState(a).x).toBeCloseTo(-22, 9)
    expect(sim.ballState(b).x).toBeCloseTo(172, 9)
    expect(sim.world.meet!.timed).toBe(1)
  })

  it('a ball struck by two at once: the contacts at the tick, up to one tick early', () => {
    const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 1, ROLLING_DECEL: 0, CONTACT_TIMING: 'instant' })
    sim.addBall({ x: 0, y: 0, vx: 300, vy: 0 })
    sim.addBall({ x: 100, y: 0, vx: 0, vy: 0 })
    sim.addBall({ x: 200, y: 0, vx: -300, vy: 0 })
    const ev = run(sim, 0.5, 1 / 60).filter((e) => e.type === 'collision')
    expect(ev.length).toBeGreaterThanOrEqual(2)
    const t = ev[0]!.time
    const touch = (100 - 22) / 300
    // a tick of the clock, k/120 s
    expect(t).toBe(Math.round(t * 120) / 120)
    expect(t).toBeLessThanOrEqual(touch)
    expect(touch - t).toBeLessThan(TICK)
    expect(sim.world.meet!.timed).toBe(0)
  })

  it('unequal masses and restitution: the two-body law, momentum to 1e-9', () => {
    const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 0.5, ROLLING_DECEL: 0 })
    const a = sim.addBall({ x: 0, y: 0, vx: 400, vy: 0, mass: 3 })
    const b = sim.addBall({ x: 60, y: 0, vx: 0, vy: 0, mass: 1 })
    run(sim, 0.3, 1 / 60)
    const va = sim.ballState(a).vx
    const vb = sim.ballState(b).vx
    expect(Math.abs(3 * va + vb - 1200) / 1200).toBeLessThan(EXACT)
    expect(vb - va).toBeCloseTo(0.5 * 400, 9)
  })

  it('swept: a contact iff the straight-line touch falls within the next tick; near misses pass (fast-check)', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 50, max: 1e5, noNaN: true }),
        fc.double({ min: 0, max: 30, noNaN: true }),
        fc.constantFrom(1 / 30, 1 / 60, 0.1),
        (speed, offset, dt) => {
          const sim = createBallPhysics({ ...FIXED, ROLLING_DECEL: 0, BALL_RESTITUTION: 1 })
          sim.addBall({ x: 0, y: 0, vx: speed, vy: 0 })
          sim.addBall({ x: 30 + speed * 0.2, y: offset, vx: 0, vy: 0 })
          // the touch comes within 0.2 s + 30 px / speed ≤ 0.8 s: a run of 1 s sees it at every speed
          const ev = run(sim, 1, dt).filter((e) => e.type === 'collision')
          expect(ev.length, `speed ${speed} offset ${offset} dt ${dt}`).toBe(offset < 22 ? 1 : 0)
        },
      ),
      { numRuns: 300, seed: 7 },
    )
  })

  it('a 1e5 px/s ball crossing a row of 40 resting balls in 0.1 s steps strikes the first, not through it', () => {
    const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 1 })
    const row: number[] = []
    for (let i = 0; i < 40; i++) row.push(sim.addBall({ x: 500 + 23 * i, y: 0, vx: 0, vy: 0 }))
    const fast = sim.addBall({ x: 0, y: 0, vx: 1e5, vy: 0 })
    sim.step(0.1)
    const ev = sim.drainEvents().filter((e) => e.type === 'collision')
    expect(ev[0]).toMatchObject({ ball: row[0], other: fast })
    // the striker never got past the first ball of the row
    expect(sim.ballState(fast).x).toBeLessThan(sim.ballState(row[0]!).x)
  })

  it('a struck ball sped up by the solve is paired again within the tick: a fast striker into a gapped row leaves no overlap', () => {
    for (const speed of [2000, 20_000]) {
      const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 1, ROLLING_DECEL: 0 })
      const row: number[] = []
      for (let i = 0; i < 4; i++) row.push(sim.addBall({ x: 300 + 23 * i, y: 100, vx: 0, vy: 0 }))
      sim.addBall({ x: 300 - 23 - speed / 240, y: 100, vx: speed, vy: 0 })
      for (let s = 0; s < 12; s++) {
        sim.step(1 / 240)
        sim.drainEvents()
        expect(worstOverlap(sim), `${speed} px/s, step ${s}`).toBeLessThanOrEqual(1e-9)
      }
      // the momentum ran down the row to its last ball
      expect(sim.ballState(row[3]!).vx).toBeGreaterThan(0.9 * speed)
    }
  })

  it('the same scene at 30, 60, 120 and 240 Hz gives bit-identical contacts and final states', () => {
    const scene = (dt: number) => {
      const r = rng(21)
      const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 0.8 })
      sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 0.6 })
      for (let i = 0; i < 3; i++) for (let j = 0; j < 3; j++) sim.addHole({ x: 90 + 120 * i, y: 100 + 120 * j })
      const placed: [number, number][] = []
      while (placed.length < 60) {
        const a = r() * 2 * Math.PI
        const v = 100 + 500 * r()
        const x = 20 + 380 * r()
        const y = 20 + 440 * r()
        if (placed.some(([px, py]) => Math.hypot(px - x, py - y) < 22)) continue
        placed.push([x, y])
        sim.addBall({ x, y, vx: v * Math.cos(a), vy: v * Math.sin(a) })
      }
      const ev = run(sim, 3, dt)
      const B = sim.world.Ball
      return {
        contacts: ev.filter((e) => e.type === 'collision').map((e) => `${e.ball}-${e.other}@${e.time}`),
        state: sim.balls().map((b) => [B.x[b], B.y[b], B.vx[b], B.vy[b], B.mode[b]]),
      }
    }
    const base = scene(1 / 60)
    expect(base.contacts.length).toBeGreaterThan(20)
    for (const dt of [1 / 30, 1 / 120, 1 / 240]) {
      const other = scene(dt)
      expect(other.contacts).toEqual(base.contacts)
      expect(other.state).toEqual(base.state)
    }
  })

  it('random scenes in a box: kinetic energy never rises from step to step, momentum is kept without walls (fast-check)', () => {
    fc.assert(
      fc.property(fc.integer({ min: 1, max: 1e6 }), fc.double({ min: 0, max: 1, noNaN: true }), fc.boolean(), (seed, e, walls) => {
        const r = rng(seed)
        const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: e, ROLLING_DECEL: 0, BALL_SETTLE_SPEED: 0 })
        if (walls) sim.setWalls({ minX: 0, minY: 0, maxX: 300, maxY: 300, restitution: 1 })
        for (let i = 0; i < 40; i++) {
          sim.addBall({ x: 15 + 270 * r(), y: 15 + 270 * r(), vx: 900 * (r() - 0.5), vy: 900 * (r() - 0.5), radius: 5 + 10 * r(), mass: 0.1 + 5 * r() })
        }
        const momentum = () => {
          const B = sim.world.Ball
          const F = sim.world.fixed!
          let px = 0
          let py = 0
          for (const b of sim.balls()) {
            px += F.mass[b]! * B.vx[b]!
            py += F.mass[b]! * B.vy[b]!
          }
          return [px, py] as const
        }
        let k = kinetic(sim)
        const p0 = momentum()
        for (let s = 0; s < 30; s++) {
          sim.step(1 / 60)
          sim.drainEvents()
          const k2 = kinetic(sim)
          expect(k2).toBeLessThanOrEqual(k * (1 + 1e-12) + 1e-9)
          k = k2
        }
        if (!walls) {
          const p = momentum()
          const scale = Math.max(1, Math.hypot(p0[0], p0[1]), k)
          expect(Math.abs(p[0] - p0[0]) / scale).toBeLessThan(1e-9)
          expect(Math.abs(p[1] - p0[1]) / scale).toBeLessThan(1e-9)
        }
      }),
      { numRuns: 40, seed: 3 },
    )
  })

  it('balls made to overlap are pushed apart within a few ticks, adding no kinetic energy', () => {
    const sim = createBallPhysics({ ...FIXED, ROLLING_DECEL: 0 })
    const B = sim.world.Ball
    const ids: number[] = []
    for (let i = 0; i < 20; i++) ids.push(sim.addBall({ x: 100 + 30 * i, y: 100, vx: 0, vy: 0 }))
    // the game moves balls by hand onto one another (at rest: no kinetic energy to gain)
    for (let i = 0; i < 20; i++) B.x[ids[i]!] = 100 + 12 * i
    expect(worstOverlap(sim)).toBeGreaterThan(9)
    for (let s = 0; s < 6; s++) sim.step(1 / 60)
    expect(worstOverlap(sim)).toBeLessThanOrEqual(1e-3)
    expect(kinetic(sim)).toBe(0)
  })

  it('a big ball in a long, thin field of candidates (one ball 65,000 px away) meets the balls in its way', () => {
    // the sparse grid once capped its columns for a field one row high, and the big ball's cell range fell
    // past the last column: it went through a ball for ten ticks (38 px deep; adversarial counterexample)
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 0, ROLLING_DECEL: 0 })
    sim.addBall({ x: -65_000, y: 0, vx: 0, vy: 1 })
    sim.addBall({ x: -20, y: 0, vx: 170, vy: 0, radius: 90, mass: 1 })
    for (let i = 0; i < 5; i++) sim.addBall({ x: 150 + 30 * i, y: 0, vx: -50, vy: 0 })
    let contacts = 0
    for (let i = 0; i < 60; i++) {
      sim.step(1 / 60)
      contacts += sim.drainEvents().filter((e) => e.type === 'collision').length
      expect(worstOverlap(sim), `step ${i}`).toBeLessThanOrEqual(1e-3)
    }
    expect(contacts).toBeGreaterThan(0)
  })

  it('a ball creeping into a resting one below BALL_SETTLE_SPEED is held by it, between ticks too (it once went on into it)', () => {
    // the resting ball keeps still (it would leave slower than BALL_SETTLE_SPEED), so it holds like a wall;
    // the creeping ball once kept its approach and moved into it until the next tick's projection
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 0, ROLLING_DECEL: 0 })
    const still = sim.addBall({ x: 0, y: 0, vx: 0, vy: 0 })
    sim.addBall({ x: 0.3, y: -28.2, vx: 0, vy: 1, radius: 16.7 }) // touches it about 0.5 s in
    sim.step(1 / 240) // step ends fall between ticks from here on
    for (let i = 0; i < 60; i++) {
      sim.step(1 / 60)
      expect(worstOverlap(sim), `t = ${sim.time}`).toBeLessThanOrEqual(1e-3)
    }
    expect(sim.ballState(still)).toMatchObject({ x: 0, y: 0, mode: 'resting' })
  })

  it('a light ball wedged between a heavy one and a wall squirts out: the velocity sweeps go on past CONTACT_ITERATIONS until it does', () => {
    // adversarial counterexample: a ball of radius 84 (445 times the mass) drove a default ball into the top
    // wall at an angle; each sweep passed the light ball a little of the push, 32 sweeps left the pair
    // approaching, and the big ball moved 0.9 px into the light one before the next tick. Step ends fall
    // between ticks here (a 1/240 s step)
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 0, ROLLING_DECEL: 0 })
    sim.addBall({ x: 0, y: -20, vx: 0, vy: 0, radius: 1, mass: 1 })
    sim.addBall({ x: 0, y: -20, vx: 0, vy: 0, radius: 1, mass: 1 })
    sim.throwBall({ x: 3.662860000000002, y: 10, power: 1, angle: 4.962962410435011 })
    for (let i = 0; i < 3; i++) sim.step(1 / 60)
    sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, open: {} })
    sim.addBall({ x: -20, y: -20, vx: -3.6644673094240367e-13, vy: 2992.264636608189, radius: 1, mass: 1374.0419750125147 })
    sim.step(1 / 240)
    sim.step(1 / 60)
    sim.addHole({ x: 394.06532, y: 307.12264 })
    sim.throwBall({ x: 489.4962756543867, y: 515.2403785500787, power: 1, angle: -0.42478480457704776, radius: 84.33347577642752 })
    sim.removeBall(1)
    const spawned = sim.time
    for (let i = 0; i < 39; i++) {
      sim.step(1 / 60)
      if (sim.time - spawned >= 0.5) expect(worstOverlap(sim), `t = ${sim.time}`).toBeLessThanOrEqual(1e-3)
    }
  })

  it('a heavy ball driving a light one straight into a wall: the pair and the wall are solved together, no overlap between ticks', () => {
    // each impulse took m/(m + M) of the heavy ball's approach and the wall sent the light ball back each
    // sweep: the sweeps ran out with the pair closing, and the heavy ball (mass 1,374 at 3,000 px/s) went
    // 2.8 px into the light one before the next tick (adversarial counterexample)
    for (const e of [0, 0.9]) {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: e, ROLLING_DECEL: 0 })
      sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 0.5 })
      const light = sim.addBall({ x: 200, y: 400, vx: 0, vy: 3000 })
      const heavy = sim.addBall({ x: 201, y: 380, vx: 0, vy: 3000, radius: 1, mass: 1374 })
      sim.step(1 / 240) // step ends fall between ticks from here on
      let walls = 0
      const ke = () => ['light', 'heavy'].reduce((k, _, i) => {
        const s = sim.ballState(i === 0 ? light : heavy)
        return k + 0.5 * (i === 0 ? 1 : 1374) * (s.vx ** 2 + s.vy ** 2)
      }, 0)
      let last = ke()
      let turned = Infinity
      for (let i = 0; i < 20; i++) {
        sim.step(1 / 60)
        walls += sim.drainEvents().filter((ev) => ev.type === 'wall').length
        expect(worstOverlap(sim), `e = ${e}, t = ${sim.time}`).toBeLessThanOrEqual(1e-3)
        const k = ke()
        expect(k).toBeLessThanOrEqual(last * (1 + 1e-12))
        last = k
        turned = Math.min(turned, sim.ballState(heavy).vy)
      }
      expect(walls).toBeGreaterThan(0)
      // stopped or sent back by the wall, through the light ball or once it slipped aside (later it may
      // reach the far wall and come back)
      expect(turned, `e = ${e}`).toBeLessThanOrEqual(0)
    }
  })

  it('two identical runs give bit-identical state', () => {
    const once = () => {
      const r = rng(8)
      const sim = createBallPhysics(FIXED)
      sim.setWalls({ minX: 0, minY: 0, maxX: 300, maxY: 300, restitution: 0.7 })
      for (let i = 0; i < 150; i++) sim.addBall({ x: 15 + 270 * r(), y: 15 + 270 * r(), vx: 800 * (r() - 0.5), vy: 800 * (r() - 0.5) })
      run(sim, 2, 1 / 60)
      const B = sim.world.Ball
      return sim.balls().flatMap((b) => [B.x[b], B.y[b], B.vx[b], B.vy[b]])
    }
    expect(once()).toEqual(once())
  })
})

describe('fixed-tick contacts under arcade load', () => {
  it('1,000 balls from the launch point in one frame: held and released, no overlap after 0.5 s, no clump at a hole', () => {
    const sim = createBallPhysics(FIXED)
    addPanel(sim)
    sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, open: { bottom: true } })
    const r = rng(99)
    for (let i = 0; i < 1000; i++) sim.throwBall({ x: DEFAULT_PANEL.launch.x, y: DEFAULT_PANEL.launch.y, power: 0.3 + 0.7 * r(), angle: (r() - 0.5) * 1.2 })
    const captures = new Map<number, number[]>()
    for (let i = 0; i < 60 * 6; i++) {
      sim.step(1 / 60)
      for (const e of sim.drainEvents()) if (e.type === 'capture') captures.set(e.hole!, [...(captures.get(e.hole!) ?? []), e.time])
      if (i >= 30 && i % 30 === 0) expect(worstOverlap(sim)).toBeLessThanOrEqual(1e-3)
    }
    let captured = 0
    for (const [hole, times] of captures) {
      captured += times.length
      for (let k = 2; k < times.length; k++) expect(times[k]! - times[k - 2]!, `hole ${hole}`).toBeGreaterThanOrEqual(0.05)
    }
    expect(captured).toBeGreaterThan(20)
  })

  it('a pile pressed into a corner by a stream of fast balls, e = 0 and e = 1: bounded steps, overlaps resolved', () => {
    for (const e of [0, 1]) {
      const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: e })
      sim.setWalls({ minX: 0, minY: 0, maxX: 400, maxY: 400, restitution: e })
      for (let i = 0; i < 10; i++) for (let j = 0; j < 10; j++) sim.addBall({ x: 12 + 22.5 * i, y: 12 + 22.5 * j, vx: 0, vy: 0 })
      let worstMs = 0
      for (let s = 0; s < 120; s++) {
        if (s % 4 === 0) sim.addBall({ x: 388, y: 388, vx: -900, vy: -900 })
        const t0 = performance.now()
        sim.step(1 / 60)
        worstMs = Math.max(worstMs, performance.now() - t0)
        sim.drainEvents()
      }
      // 0.5 s after the stream stops
      for (let s = 0; s < 30; s++) sim.step(1 / 60)
      expect(worstOverlap(sim), `e = ${e}`).toBeLessThanOrEqual(1e-3)
      expect(worstMs, `e = ${e}`).toBeLessThan(timeBudget(250))
    }
  })

  it('a jammed 17 × 17 box pressed by a stream, e = 0 and e = 1: no overlap 0.5 s after the stream stops', () => {
    // 289 balls on a square lattice 22.5 px apart (0.5 px gaps) in a 400 px box, area fraction 0.69, with
    // a stream into its corner: at e = 0 the stream's balls are driven into the lattice (overlaps of about
    // 0.05 px while pressed); at e = 1 most of them are held at the spot, which the lattice keeps filled
    for (const e of [0, 1]) {
      const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: e })
      sim.setWalls({ minX: 0, minY: 0, maxX: 400, maxY: 400, restitution: e })
      for (let i = 0; i < 17; i++) for (let j = 0; j < 17; j++) sim.addBall({ x: 12 + 22.5 * i, y: 12 + 22.5 * j, vx: 0, vy: 0 })
      for (let s = 0; s < 120; s++) {
        if (s % 4 === 0) sim.addBall({ x: 388, y: 388, vx: -900, vy: -900 })
        sim.step(1 / 60)
        sim.drainEvents()
      }
      for (let s = 0; s < 30; s++) sim.step(1 / 60)
      expect(onPanel(sim).length, `e = ${e}`).toBeGreaterThanOrEqual(e === 0 ? 319 : 289)
      expect(worstOverlap(sim), `e = ${e}`).toBeLessThanOrEqual(1e-3)
    }
  })

  it('a light ball pinned against a wall by a heavy one: steps return, the light ball stays inside, no overlap after 0.5 s', () => {
    const sim = createBallPhysics({ ...FIXED, ROLLING_DECEL: 0 })
    sim.setWalls({ minX: 0, minY: 0, maxX: 400, maxY: 400 })
    const light = sim.addBall({ x: 389, y: 200, vx: 0, vy: 0, mass: 1e-9 })
    const heavy = sim.addBall({ x: 100, y: 200, vx: 1000, vy: 0 })
    for (let s = 0; s < 60; s++) {
      const t0 = performance.now()
      sim.step(1 / 60)
      expect(performance.now() - t0).toBeLessThan(timeBudget(200))
    }
    expect(sim.ballState(light).x).toBeLessThanOrEqual(389 + 1e-9)
    expect(worstOverlap(sim)).toBeLessThanOrEqual(1e-3)
    expect(Number.isFinite(sim.ballState(heavy).vx)).toBe(true)
  })
})

// The scenes docs/known-failures.md records for the exact method, under the fixed-tick method: each step's
// work is bounded by the balls on the panel and their pairs, not by the events in the step.
describe('fixed-tick contacts on the exact method’s known failures', () => {
  function timed(sim: BallPhysics, steps: number, dt = 1 / 60): number {
    let worst = 0
    for (let i = 0; i < steps; i++) {
      const t0 = performance.now()
      sim.step(dt)
      worst = Math.max(worst, performance.now() - t0)
      sim.drainEvents()
    }
    return worst
  }

  it('balls of radius 640 wider than their walls, and 150 balls in walls 5 px wide: steps of milliseconds', () => {
    const a = createBallPhysics({ ...FIXED, ROLLING_DECEL: 0 })
    a.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 4800, restitution: 1 })
    for (let i = 0; i < 3; i++) a.addBall({ x: 210, y: 700 + 1300 * i, vx: 100, vy: 0, radius: 640 })
    expect(timed(a, 30)).toBeLessThan(timeBudget(200))
    const b = createBallPhysics({ ...FIXED, ROLLING_DECEL: 0 })
    b.setWalls({ minX: 0, minY: 0, maxX: 5, maxY: 4800, restitution: 1 })
    for (let i = 0; i < 150; i++) b.addBall({ x: 2.5, y: 20 + 30 * i, vx: 100, vy: 0 })
    expect(timed(b, 30)).toBeLessThan(timeBudget(200))
  })

  it('300 balls of masses 100 and 0.01 at 5,000 px/s in the panel: steps of milliseconds, speeds within CONTACT_SPEED_LIMIT', () => {
    const sim = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 1, ROLLING_DECEL: 0 })
    sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 1 })
    const r = rng(12345)
    for (let i = 0; i < 300; i++) {
      const a = r() * 2 * Math.PI
      sim.addBall({ x: 11 + r() * 398, y: 11 + r() * 458, vx: 5000 * Math.sin(a), vy: -5000 * Math.cos(a), mass: r() < 0.5 ? 100 : 0.01 })
    }
    expect(timed(sim, 30)).toBeLessThan(timeBudget(250))
    // the heavy balls pump the light ones (the exact method's fastest reaches 1.67e5 px/s within these 30
    // steps, the fixed tick's 1.03e5, 1.39e5 with CONTACT_TIMING 'instant', whose pairs meet as the exact
    // method's do): no component beyond the limit (2e5 px/s by default)
    const B = sim.world.Ball
    const limit = sim.world.config.CONTACT_SPEED_LIMIT
    for (const b of sim.balls()) expect(Math.max(Math.abs(B.vx[b]!), Math.abs(B.vy[b]!))).toBeLessThanOrEqual(limit)
  })

  it('a tiny ball pressed against a wall, and a light ball between two heavy ones: the world goes on', () => {
    const a = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 1, ROLLING_DECEL: 0 })
    a.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 1 })
    a.addBall({ x: 20, y: 240, vx: 0, vy: 0, radius: 0.001 })
    a.addBall({ x: 60, y: 240, vx: -200, vy: 0 })
    const bystander = a.addBall({ x: 100, y: 50, vx: 100, vy: 0 })
    expect(timed(a, 120)).toBeLessThan(timeBudget(100))
    expect(a.ballState(bystander).x).toBeCloseTo(300, 3)
    const b = createBallPhysics({ ...FIXED, BALL_RESTITUTION: 1, ROLLING_DECEL: 0 })
    b.addBall({ x: 0, y: 0, vx: 100, vy: 0, mass: 1e9 })
    b.addBall({ x: 50, y: 0, vx: 0, vy: 0, mass: 1e-9 })
    b.addBall({ x: 100, y: 0, vx: -100, vy: 0, mass: 1e9 })
    const other = b.addBall({ x: 0, y: 300, vx: 100, vy: 0 })
    expect(timed(b, 120)).toBeLessThan(timeBudget(100))
    expect(b.ballState(other).x).toBeCloseTo(200, 3)
  })
})
