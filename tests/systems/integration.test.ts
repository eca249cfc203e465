import { describe, expect, it } from 'vitest'
import { createBallPhysics } from '../../src/index'
import { HOT, H_T0, H_UX, H_UY, H_V0, H_X0, H_Y0 } from '../../src/ecs'
import { EXACT, sequence, settle, shoot } from '../helpers'

describe('integration system', () => {
  it('moves a free ball on the closed form s = v0·t − a·t²/2 and reports its stop at exactly v0/a', () => {
    const sim = createBallPhysics()
    const a = sim.config.ROLLING_DECEL
    const b = sim.addBall({ x: 0, y: 0, vx: 300, vy: -400 })
    sim.step(0.2)
    sim.step(0.17)
    const t = 0.37
    const s = 500 * t - 0.5 * a * t * t
    const st = sim.ballState(b)
    expect(st.x).toBeCloseTo(0.6 * s, 9)
    expect(st.y).toBeCloseTo(-0.8 * s, 9)
    expect(Math.hypot(st.vx, st.vy)).toBeCloseTo(500 - a * t, 9)
    const ev = settle(sim, 0.1)
    expect(sequence(ev)).toEqual(['rest'])
    expect(Math.abs(ev[0]!.time - 500 / a)).toBeLessThan(EXACT)
    const end = sim.ballState(b)
    expect(end.mode).toBe('resting')
    expect(Math.hypot(end.x, end.y)).toBeCloseTo((500 * 500) / (2 * a), 9)
  })

  it('finds the lip crossing at its exact time and reports the exact (δ, v) there', () => {
    const { sim } = shoot(5, 700, {}, 60)
    const a = sim.config.ROLLING_DECEL
    const v0 = Math.sqrt(700 * 700 + 2 * a * 60)
    const ev = settle(sim, 1 / 30)
    expect(ev[0]!.type).toBe('skip')
    expect(Math.abs(ev[0]!.time - (v0 - 700) / a)).toBeLessThan(EXACT)
    expect(Math.abs(ev[0]!.delta! - 5)).toBeLessThan(EXACT)
    expect(Math.abs(ev[0]!.speed! - 700)).toBeLessThan(EXACT)
  })

  it('does not lose a lip crossing that falls exactly on a step boundary', () => {
    const { sim } = shoot(2, 700, {}, 60)
    const a = sim.config.ROLLING_DECEL
    const tLip = (Math.sqrt(700 * 700 + 2 * a * 60) - 700) / a
    sim.step(tLip) // the step ends on the crossing
    const first = sim.drainEvents()
    const rest = settle(sim, 1 / 60)
    const all = [...first, ...rest]
    expect(all.filter((e) => e.type === 'skip')).toHaveLength(1)
  })

  it('reports a near miss at the closest approach when only the footprint passes over the hole', () => {
    const { sim } = shoot(20, 300, {}, 60) // R = 18 ≤ δ < R + r = 29
    const a = sim.config.ROLLING_DECEL
    const ev = settle(sim)
    expect(sequence(ev)).toEqual(['nearMiss', 'rest'])
    // closest approach is at x = 0: the lead plus the (virtual) half chord, 60 px from the start
    const v0 = Math.sqrt(300 * 300 + 2 * a * 60)
    const dist = 60 + 0 // shoot() starts at lipX − lead with lipX = 0 for δ ≥ R
    const tCa = (v0 - Math.sqrt(v0 * v0 - 2 * a * dist)) / a
    expect(Math.abs(ev[0]!.time - tCa)).toBeLessThan(EXACT)
    expect(ev[0]!.delta).toBeCloseTo(20, 9)
  })

  it('reports nothing for a path whose footprint misses the hole (δ ≥ R + r)', () => {
    const { sim } = shoot(29.5, 300)
    expect(sequence(settle(sim))).toEqual(['rest'])
  })

  it('unlocks a hole when the centre leaves its lip circle, so the next hole in line decides afresh', () => {
    const sim = createBallPhysics({ ROLLING_DECEL: 0 })
    const h1 = sim.addHole({ x: 0, y: 0 })
    const h2 = sim.addHole({ x: 100, y: 0 })
    sim.addBall({ x: -100, y: 3, vx: 680, vy: 0 })
    for (let i = 0; i < 60; i++) sim.step(1 / 60)
    const ev = sim.drainEvents()
    expect(ev.map((e) => [e.type, e.hole])).toEqual([
      ['skip', h1],
      ['skip', h2],
    ])
  })

  it('without rolling deceleration the step writes only positions, and every state is the closed form to the bit (velocity ux·v0 from the start of the path)', () => {
    const sim = createBallPhysics({ ROLLING_DECEL: 0 })
    for (let i = 0; i < 5; i++) for (let j = 0; j < 5; j++) sim.addHole({ x: 60 + 80 * i, y: 60 + 80 * j })
    const balls: number[] = []
    for (let n = 0; n < 300; n++) balls.push(sim.addBall({ x: (n * 37) % 400, y: (n * 53) % 400, vx: ((n * 13) % 91) - 45.3, vy: ((n * 29) % 83) - 40.7 }))
    const w = sim.world
    const B = w.Ball
    // the path's fields from the ball's row in world.pathHot
    const P = (b: number, k: number) => w.pathHot[b * HOT + k]!
    let checked = 0
    for (let s = 0; s < 90; s++) {
      sim.step(1 / 60)
      sim.drainEvents()
      for (const b of balls) {
        if (B.mode[b] !== 0) continue
        const got = [B.x[b]!, B.y[b]!, B.vx[b]!, B.vy[b]!]
        // the general form (what sampleRolling writes), evaluated here: d = v0·τ − ½·0·τ², x = x0 + ux·d
        const tau = w.time - P(b, H_T0)
        const d = P(b, H_V0) * tau - 0.5 * 0 * tau * tau
        const v = P(b, H_V0) - 0 * tau
        expect(got).toEqual([P(b, H_X0) + P(b, H_UX) * d, P(b, H_Y0) + P(b, H_UY) * d, P(b, H_UX) * v, P(b, H_UY) * v])
        checked++
      }
    }
    expect(checked).toBeGreaterThan(10_000)
  })

  it('keeps a ball rolling forever when ROLLING_DECEL is 0, its position exact after many steps', () => {
    const sim = createBallPhysics({ ROLLING_DECEL: 0 })
    const b = sim.addBall({ x: 1, y: 2, vx: 3, vy: -4 })
    for (let i = 0; i < 1000; i++) sim.step(0.01)
    const st = sim.ballState(b)
    expect(st.mode).toBe('rolling')
    expect(st.x).toBeCloseTo(1 + 3 * 10, 9)
    expect(st.y).toBeCloseTo(2 - 4 * 10, 9)
  })
})
