// The six failures of the v1 rule (docs/design.md §2), each pinned by a test.
import { describe, expect, it } from 'vitest'
import { DEFAULT_PANEL, createBallPhysics } from '../src/index'
import { sequence, settle, shoot } from './helpers'

describe('v1 failures (docs/design.md §2) stay fixed', () => {
  it('1. no skip-over: a ball fast enough to fly over the hole skips it, straight and undistorted', () => {
    const { sim, ball } = shoot(2, 680)
    expect(sequence(settle(sim))).toEqual(['skip', 'rest'])
    expect(sim.ballState(ball).y).toBe(2)
  })

  it('2. random-feeling rim bounces: head-on contacts carom back, glancing ones skim on (one rule, asymmetric)', () => {
    const head = shoot(0, 620, { ROLLING_DECEL: 0 })
    head.sim.step(0.2)
    const glance = shoot(15, 0.97 * 640 * Math.sqrt(1 - 225 / 324), { ROLLING_DECEL: 0 })
    glance.sim.step(0.3)
    expect(sequence(head.sim.drainEvents())[0]).toBe('bounce')
    expect(sequence(glance.sim.drainEvents())[0]).toBe('bounce')
    expect(head.sim.ballState(head.ball).vx).toBeLessThan(0)
    expect(glance.sim.ballState(glance.ball).vx).toBeGreaterThan(0)
  })

  it('3. bounces carried too much energy: a head-on bounce stops within two hole widths of the impact', () => {
    const { sim, ball } = shoot(0, 620)
    const ev = settle(sim)
    expect(sequence(ev)).toEqual(['bounce', 'nearMiss', 'rest'])
    const st = sim.ballState(ball)
    const impactX = -12.5 // contact circle, head-on
    expect(Math.abs(st.x - impactX)).toBeLessThan(2 * 36)
  })

  it('4. covering captures: a ball resting with its rim over the hole but its centre outside does not score', () => {
    const sim = createBallPhysics()
    sim.addHole({ x: 0, y: 0 })
    const a = sim.config.ROLLING_DECEL
    // comes to rest with its centre 20 px from the hole centre (R = 18): footprint covers the lip
    const b = sim.addBall({ x: -20 - 100, y: 0, vx: Math.sqrt(2 * a * 100), vy: 0 })
    const ev = settle(sim)
    expect(sequence(ev)).toEqual(['rest'])
    expect(sim.ballState(b).x).toBeCloseTo(-20, 9)
    expect(sim.ballState(b).mode).toBe('resting')
  })

  it('5. throw-speed range: the meter maps onto 175..700 px/s; power 0 cannot reach the first row, the top row needs mid-meter', () => {
    const sim = createBallPhysics()
    const { launch } = DEFAULT_PANEL
    const b0 = sim.throwBall({ x: launch.x, y: launch.y, power: 0, angle: 0 })
    const b1 = sim.throwBall({ x: launch.x, y: launch.y, power: 1, angle: 0 })
    expect(Math.hypot(sim.ballState(b0).vx, sim.ballState(b0).vy)).toBeCloseTo(175, 9)
    expect(Math.hypot(sim.ballState(b1).vx, sim.ballState(b1).vy)).toBeCloseTo(700, 9)
    const rows = [...new Set(DEFAULT_PANEL.holes.map((h) => h.y))].sort((p, q) => q - p)
    // smallest power whose straight throw reaches a row's lip, each row alone on the panel
    const reach = (rowY: number) => {
      for (let p = 0; p <= 1; p += 0.005) {
        const s = createBallPhysics()
        s.addHole({ x: launch.x, y: rowY })
        s.throwBall({ x: launch.x, y: launch.y, power: p, angle: 0 })
        if (settle(s, 1 / 30).some((e) => e.hole !== undefined)) return p
      }
      return Infinity
    }
    expect(reach(rows[0]!)).toBeGreaterThan(0)
    const top = reach(rows.at(-1)!)
    expect(top).toBeGreaterThan(0.35)
    expect(top).toBeLessThan(0.6)
  })

  it('6. tangential brushes got sucked in: a glancing contact (δ > R − r/2) deflects out and never rolls', () => {
    for (const delta of [13, 14, 16]) {
      const k = Math.sqrt(1 - (delta * delta) / 324)
      const { sim, ball } = shoot(delta, 620 * k)
      const seq = sequence(settle(sim))
      expect(seq).not.toContain('rimRoll')
      expect(seq[0]).toBe('bounce')
      expect(sim.ballState(ball).mode).toBe('resting')
    }
  })
})
