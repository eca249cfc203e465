import { describe, expect, it } from 'vitest'
import { captureWindow, createBallPhysics } from '../../src/index'
import { sequence, settle, shoot } from '../helpers'

describe('capture system (Stage 1)', () => {
  for (const v of [50, 200, 400, 550, 599]) {
    it(`captures clean inside the window δ_eff(v) and not outside it, v = ${v}`, () => {
      const w = captureWindow(v, 18, 600, 'ellipse')
      const inside = settle(shoot(w * (1 - 1e-6), v).sim)
      expect(sequence(inside)[0]).toBe('capture:clean')
      if (w * (1 + 1e-3) < 18) {
        const outside = settle(shoot(w * (1 + 1e-3), v).sim)
        expect(sequence(outside)[0]).not.toBe('capture:clean')
      }
    })
  }

  it('never captures clean above V_MAX, even dead centre', () => {
    expect(sequence(settle(shoot(0, 600.001).sim))[0]).toBe('bounce')
  })

  it('puts a captured ball at the hole centre, at rest, with the exact (δ, v) on the event', () => {
    const { sim, ball } = shoot(3, 250)
    const ev = settle(sim)
    expect(ev).toHaveLength(1)
    expect(ev[0]).toMatchObject({ type: 'capture', via: 'clean', ball })
    expect(ev[0]!.delta).toBeCloseTo(3, 9)
    expect(ev[0]!.speed).toBeCloseTo(250, 9)
    expect(sim.ballState(ball)).toMatchObject({ x: 0, y: 0, vx: 0, vy: 0, mode: 'captured' })
  })

  it('a ball that stops with its centre inside a lip circle falls in (via rest)', () => {
    const sim = createBallPhysics()
    const h = sim.addHole({ x: 0, y: 0 })
    // added inside the lip, slow: in transit, then stops inside
    const b = sim.addBall({ x: 10, y: 0, vx: 20, vy: 0 })
    const ev = settle(sim)
    expect(sequence(ev)).toEqual(['capture:rest'])
    expect(ev[0]!.hole).toBe(h)
    expect(ev[0]!.delta).toBeUndefined() // it never crossed the lip
    expect(sim.ballState(b).mode).toBe('captured')
  })

  it('a ball at rest added on a hole is captured at the next step', () => {
    const sim = createBallPhysics()
    sim.addHole({ x: 0, y: 0 })
    sim.addBall({ x: 1, y: 1, vx: 0, vy: 0 })
    sim.step(1 / 60)
    expect(sequence(sim.drainEvents())).toEqual(['capture:rest'])
  })
})

describe('a ball not smaller than the hole bridges it', () => {
  // it fell in cleanly, through a hole narrower than itself
  for (const [name, config] of [['design', {}], ['tabulated', { RIM_MODEL: 'tabulated' as const, BALL_INERTIA: 0.4 }], ['contacts on', { BALL_COLLISIONS: 'on' as const }], ['fixed tick', { BALL_COLLISIONS: 'fixed' as const }], ['naive method', { METHOD: 'naive' as const }], ['v1 method', { METHOD: 'v1' as const }]] as const) {
    it(`${name}: rolled across it, put down on it, a hole added under it: no event there, never captured`, () => {
      const sim = createBallPhysics(config)
      const hole = sim.addHole({ x: 0, y: 0 }) // radius 18
      const across = sim.addBall({ x: 0, y: 80, vx: 0, vy: -400, radius: 18 })
      const onIt = sim.addBall({ x: 300, y: 0, vx: 0, vy: 0, radius: 40 })
      sim.addHole({ x: 300, y: 0, radius: 30 })
      sim.addHole({ x: 600, y: 0, radius: 20 })
      const putDown = sim.addBall({ x: 600, y: 0, vx: 0, vy: 0, radius: 25 })
      const events: string[] = []
      for (let i = 0; i < 120; i++) {
        sim.step(1 / 60)
        for (const e of sim.drainEvents()) if (e.hole !== undefined) events.push(`${e.type} ${e.ball} ${e.hole}`)
      }
      expect(events).toEqual([])
      expect(sim.ballState(across).mode).toBe('resting')
      expect(sim.ballState(across).y).toBeLessThan(-18) // rolled over the hole's far lip
      expect(sim.ballState(onIt).mode).toBe('resting')
      expect(sim.ballState(putDown).mode).toBe('resting')
      expect(sim.balls().filter((b) => sim.ballState(b).mode === 'captured')).toEqual([])
      expect(sim.holeState(hole).radius).toBe(18)
    })
  }
  it('a config whose balls are wider than its holes: 200 throws, no capture', () => {
    const sim = createBallPhysics({ BALL_RADIUS: 50, HOLE_RADIUS: 10 })
    sim.addHole({ x: 210, y: 200 })
    let captures = 0
    for (let i = 0; i < 200; i++) sim.throwBall({ x: 200 + (i % 20), y: 450, power: (i % 10) / 10, angle: 0 })
    for (let i = 0; i < 240; i++) {
      sim.step(1 / 60)
      for (const e of sim.drainEvents()) if (e.type === 'capture') captures++
    }
    expect(captures).toBe(0)
  })
})
