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
