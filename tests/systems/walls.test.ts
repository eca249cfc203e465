import { describe, expect, it } from 'vitest'
import { DEFAULT_SCHEDULE } from '../../src/ecs'
import { createBallPhysics, type BallEvent, type BallPhysics } from '../../src/index'
import { EXACT, rng } from '../helpers'

function run(sim: BallPhysics, dt: number, seconds: number): BallEvent[] {
  const out: BallEvent[] = []
  while (sim.time < seconds - 1e-12) {
    sim.step(Math.min(dt, seconds - sim.time))
    out.push(...sim.drainEvents())
  }
  return out
}

describe('walls system', () => {
  it('bounces a ball off a closed wall at the exact instant its centre is one radius from it', () => {
    const sim = createBallPhysics({ ROLLING_DECEL: 0 })
    sim.setWalls({ minX: 0, minY: 0, maxX: 400, maxY: 400, restitution: 0.5 })
    const b = sim.addBall({ x: 100, y: 200, vx: 300, vy: 40 })
    const ev = run(sim, 1 / 60, 1.5)
    expect(ev[0]!.type).toBe('wall')
    expect(Math.abs(ev[0]!.time - (400 - 11 - 100) / 300)).toBeLessThan(EXACT)
    const st = sim.ballState(b)
    expect(st.vx).toBeCloseTo(-150, 9) // normal speed × e
    expect(st.vy).toBeCloseTo(40, 9) // tangential kept
  })

  // a ball wider than its box met the far face at once after each bounce, for ever at one instant: with
  // contacts on every step ran out of passes and the whole world waited (found by the adversarial suite)
  it('a ball wider than its box stops on that axis at its first wall (no endless bounces at one instant); the others move on', () => {
    for (const contacts of ['off', 'on', 'fixed'] as const) {
      const sim = createBallPhysics({ ROLLING_DECEL: 0, BALL_COLLISIONS: contacts })
      sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 1200, restitution: 1 })
      const wide = sim.addBall({ x: -523, y: 100, vx: 925, vy: 0, radius: 300 })
      const other = sim.addBall({ x: 200, y: 1000, vx: 300, vy: 0 })
      const ev = run(sim, 1 / 60, 1)
      const wideWalls = ev.filter((e) => e.type === 'wall' && e.ball === wide)
      expect(wideWalls.length, contacts).toBe(1)
      expect(sim.ballState(wide).vx, contacts).toBe(0)
      // the other ball was not held: it reached the right wall at 300 px/s and came back
      expect(ev.filter((e) => e.type === 'wall' && e.ball === other).length, contacts).toBe(1)
      expect(sim.ballState(other).x, contacts).toBeCloseTo(409 - 300 * (1 - 209 / 300), 6)
    }
  })

  // the fixed tick's velocity sweeps turned such a ball at the wall with −e·v in every sweep: with e = 1 a
  // crowd of them never converged (each sweep turned every one back, so every call ran all its sweeps: a long
  // adversarial run's crowd in a 1e-6 px box took 0.5–0.8 s a frame) and a ball could leave a tick still
  // moving across the box (up to 1,488 px/s in this scene at e = 1, at 49 of its 60 step ends)
  it('a crowd wedged in a box narrower than its balls keeps no speed across it, in every contact mode', () => {
    for (const contacts of ['off', 'on', 'fixed'] as const) {
      for (const e of [1, 0.5]) {
        const sim = createBallPhysics({ ROLLING_DECEL: 0, BALL_COLLISIONS: contacts, BALL_RESTITUTION: e })
        sim.setWalls({ minX: 0, minY: 0, maxX: 1e-6, maxY: 400, restitution: e })
        const next = rng(7)
        const ids: number[] = []
        for (let i = 0; i < 16; i++) ids.push(sim.addBall({ x: 6 * (next() - 0.5), y: 12 + 23 * i, vx: 0, vy: 3000 * (next() - 0.5) }))
        let collisions = 0
        for (let k = 0; k < 60; k++) {
          sim.step(1 / 60)
          collisions += sim.drainEvents().filter((ev) => ev.type === 'collision').length
          for (const b of ids) expect(Math.abs(sim.ballState(b).vx), `${contacts} e ${e} step ${k} ball ${b}`).toBe(0)
        }
        // the balls did meet (their impulses had a part across the box, their centres not in line)
        if (contacts !== 'off') expect(collisions, `${contacts} e ${e}`).toBeGreaterThan(100)
      }
    }
  })

  it('lets a ball out through an open edge: a gutter event at the crossing, then it is out of play', () => {
    const sim = createBallPhysics({ ROLLING_DECEL: 0 })
    sim.setWalls({ minX: 0, minY: 0, maxX: 400, maxY: 400, open: { bottom: true } })
    const b = sim.addBall({ x: 200, y: 300, vx: 0, vy: 200 })
    const ev = run(sim, 1 / 60, 2)
    expect(ev.map((e) => e.type)).toEqual(['gutter'])
    expect(Math.abs(ev[0]!.time - 0.5)).toBeLessThan(EXACT)
    expect(sim.ballState(b)).toMatchObject({ mode: 'out', y: 400 })
    expect(sim.world.moving.count).toBe(0)
  })

  it('keeps 1,000 fast balls inside a closed box, with the same events at 30 Hz and 240 Hz', () => {
    const mk = () => {
      const sim = createBallPhysics({ ROLLING_DECEL: 20 })
      sim.setWalls({ minX: 0, minY: 0, maxX: 600, maxY: 500, restitution: 0.9 })
      sim.addHole({ x: 300, y: 250 })
      const rand = rng(8)
      for (let i = 0; i < 1000; i++) {
        const a = rand() * 2 * Math.PI
        const v = 100 + 3000 * rand()
        sim.addBall({ x: 20 + 560 * rand(), y: 20 + 460 * rand(), vx: v * Math.cos(a), vy: v * Math.sin(a) })
      }
      return sim
    }
    const a = mk()
    const b = mk()
    const ea = run(a, 1 / 30, 3)
    const eb = run(b, 1 / 240, 3)
    expect(ea.filter((e) => e.type === 'wall').length).toBeGreaterThan(3000)
    expect(ea.map((e) => `${e.ball}${e.type}${e.time}`)).toEqual(eb.map((e) => `${e.ball}${e.type}${e.time}`))
    for (const id of a.balls()) {
      const s = a.ballState(id)
      if (s.mode === 'captured') continue
      expect(s.x).toBeGreaterThanOrEqual(11 - 1e-9)
      expect(s.x).toBeLessThanOrEqual(589 + 1e-9)
      expect(s.y).toBeGreaterThanOrEqual(11 - 1e-9)
      expect(s.y).toBeLessThanOrEqual(489 + 1e-9)
    }
  })

  it('a world without walls gives exactly the events of a schedule without the walls system', () => {
    const mk = () => {
      const sim = createBallPhysics()
      for (let i = 0; i < 5; i++) sim.addHole({ x: 60 * i, y: 0 })
      const rand = rng(3)
      for (let i = 0; i < 200; i++) sim.addBall({ x: -100 + 400 * rand(), y: 100, vx: 200 * (rand() - 0.5), vy: -300 - 300 * rand() })
      return sim
    }
    const a = mk()
    const b = mk()
    b.schedule.splice(b.schedule.findIndex((s) => s.name === 'walls'), 1)
    expect(b.schedule.length).toBe(DEFAULT_SCHEDULE.length - 1)
    expect(run(a, 1 / 60, 3)).toEqual(run(b, 1 / 60, 3))
  })

  it('rejects a degenerate rectangle or restitution, naming the field; clearWalls lets balls roll on', () => {
    const sim = createBallPhysics({ ROLLING_DECEL: 0 })
    expect(() => sim.setWalls({ minX: 10, minY: 0, maxX: 10, maxY: 5 })).toThrow(/walls\.maxX must be > walls\.minX/)
    expect(() => sim.setWalls({ minX: 0, minY: 0, maxX: 10, maxY: 5, restitution: 2 })).toThrow(/walls\.restitution must be in \[0, 1\]/)
    expect(() => sim.setWalls({ minX: NaN, minY: 0, maxX: 10, maxY: 5 })).toThrow(/walls\.minX/)
    sim.setWalls({ minX: 0, minY: 0, maxX: 100, maxY: 100 })
    const b = sim.addBall({ x: 50, y: 50, vx: 100, vy: 0 })
    sim.step(0.1)
    sim.clearWalls()
    run(sim, 0.1, 2)
    expect(sim.ballState(b).x).toBeCloseTo(50 + 200, 9)
  })
})
