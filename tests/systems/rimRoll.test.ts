import { describe, expect, it } from 'vitest'
import fc from 'fast-check'
import { createBallPhysics, popArc, rollDropTime } from '../../src/index'
import { cogRadius, rollArc, rollSpeed } from '../../src/geometry'
import { rimRollAt, rimRollState } from '../../src/motion/rimRoll'
import { sampleTime } from '../../src/motion/rolling'
import { rimSlot } from '../../src/ecs'
import { EXACT, sequence, settle, shoot, watchRim } from '../helpers'

/** A (δ, v) that rolls: between the roll threshold and the gate, inside the rim band. */
const ROLL_DROP = { delta: 11, v: 490 }
const ROLL_POP = { delta: 12.3, v: 459 }

describe('rim-roll system (Stage 3)', () => {
  it('keeps the centre on the contact circle (R − r/2) and decays the speed as v_t0·e^(−μτ) exactly, at any dt', () => {
    for (const dt of [1 / 240, 1 / 60, 0.1, 0.25]) {
      const { sim, ball } = shoot(ROLL_DROP.delta, ROLL_DROP.v, {}, 30)
      let t0 = -1
      let vt0 = 0
      let before = sim.ballState(ball)
      for (let i = 0; i < 400 && t0 < 0; i++) {
        before = sim.ballState(ball)
        sim.step(1 / 2000)
        const ev = sim.drainEvents()
        const roll = ev.find((e) => e.type === 'rimRoll')
        if (roll) t0 = roll.time
      }
      expect(t0).toBeGreaterThan(0)
      // the roll starts where the ball is: no jump across the 1/2000 s step that took the contact
      const start = sim.ballState(ball)
      expect(Math.hypot(start.x - before.x, start.y - before.y)).toBeLessThan((ROLL_DROP.v * 1.01) / 2000)
      vt0 = sim.world.RimContact.speed0[rimSlot(sim.world, ball)]!
      const mu = sim.config.RIM_ROLL_FRICTION
      const tDrop = rollDropTime(vt0, mu, 110)
      // step to just before the drop, with the dt under test
      while (sim.time + dt < t0 + tDrop) {
        sim.step(dt)
        const st = sim.ballState(ball)
        expect(st.mode).toBe('rimRoll')
        expect(Math.abs(Math.hypot(st.x, st.y) - (18 - 11 / 2))).toBeLessThan(EXACT)
        const v = Math.hypot(st.vx, st.vy)
        expect(Math.abs(v - vt0 * Math.exp(-mu * (sim.time - t0)))).toBeLessThan(1e-9)
        expect(v).toBeGreaterThan(0)
      }
    }
  })

  it('drops in when the speed falls to RIM_ROLL_DROP_SPEED, at t0 + ln(v_t0/110)/μ', () => {
    const { sim, ball } = shoot(ROLL_DROP.delta, ROLL_DROP.v)
    const rim = watchRim(sim, ball)
    const ev = settle(sim)
    expect(sequence(ev)).toEqual(['rimRoll', 'capture:rimRoll'])
    expect(rimSlot(sim.world, ball)).toBe(0) // the capture gave the row back
    const vt0 = rim.speed0!
    expect(Math.abs(ev[1]!.time - ev[0]!.time - Math.log(vt0 / 110) / 5)).toBeLessThan(EXACT)
    expect(ev[1]!.delta).toBeCloseTo(ROLL_DROP.delta, 9)
  })

  it('pops off after RIM_ROLL_MAX_TURNS of the lip circle and leaves the hole along the tangent', () => {
    const { sim, ball } = shoot(ROLL_POP.delta, ROLL_POP.v)
    const rim = watchRim(sim, ball)
    const ev = settle(sim)
    expect(sequence(ev)).toEqual(['rimRoll', 'lipOut', 'nearMiss', 'rest'])
    expect(rim.arc).toBeCloseTo(popArc(sim.config.RIM_ROLL_MAX_TURNS, 18), 9)
    const st = sim.ballState(ball)
    expect(Math.hypot(st.x, st.y)).toBeGreaterThan(18)
    expect(st.mode).toBe('resting')
  })

  it('gives the same roll events at dt = 1/240 and dt = 0.25 s (larger than 1/μ = 0.2 s)', () => {
    const a = settle(shoot(ROLL_POP.delta, ROLL_POP.v).sim, 1 / 240)
    const b = settle(shoot(ROLL_POP.delta, ROLL_POP.v).sim, 0.25)
    expect(b.map((e) => e.type)).toEqual(a.map((e) => e.type))
    b.forEach((e, i) => expect(Math.abs(e.time - a[i]!.time)).toBeLessThan(EXACT))
  })

  it('with RIM_ROLL_FRICTION = 0 the roll never slows, so it always pops off', () => {
    const { sim } = shoot(ROLL_DROP.delta, ROLL_DROP.v, { RIM_ROLL_FRICTION: 0 })
    expect(sequence(settle(sim)).slice(0, 2)).toEqual(['rimRoll', 'lipOut'])
  })

  it('a roll that starts below the drop speed drops at once', () => {
    const sim = createBallPhysics({ RIM_ROLL_DROP_SPEED: 1000 })
    sim.addHole({ x: 0, y: 0 })
    sim.addBall({ x: -60, y: ROLL_DROP.delta, vx: Math.sqrt(490 ** 2 + 2 * 300 * (60 - Math.sqrt(324 - 121))), vy: 0 })
    const ev = settle(sim)
    expect(sequence(ev)).toEqual(['rimRoll', 'capture:rimRoll'])
    expect(ev[1]!.time).toBe(ev[0]!.time)
  })

  it('samples a roll with the very bits of cogRadius, rollArc and rollSpeed (written out there so that no double crosses a call), friction 0 included (fast-check)', () => {
    const checked = new Set<number>()
    fc.assert(
      fc.property(fc.constantFrom(0, 0.2, 5, 1e3), fc.double({ min: 0, max: 30, noNaN: true }), (mu, after) => {
        const { sim, ball } = shoot(ROLL_DROP.delta, ROLL_DROP.v, { RIM_ROLL_FRICTION: mu, RIM_ROLL_MAX_TURNS: 100 }, 30)
        for (let i = 0; i < 200 && sim.ballState(ball).mode !== 'rimRoll'; i++) sim.step(1 / 1000)
        if (sim.ballState(ball).mode !== 'rimRoll') return
        const slot = rimSlot(sim.world, ball)
        const RC = sim.world.RimContact
        const t = RC.time0[slot]! + after
        sampleTime[0] = t
        rimRollAt(sim.world, ball)
        const tau = t - RC.time0[slot]!
        expect(rimRollState.radius).toBe(cogRadius(sim.world.Hole.radius[RC.hole[slot]!]!, sim.world.Ball.radius[ball]!))
        expect(rimRollState.arc).toBe(rollArc(tau, RC.speed0[slot]!, mu))
        expect(rimRollState.speed).toBe(rollSpeed(tau, RC.speed0[slot]!, mu))
        checked.add(mu)
      }),
      { numRuns: 100, seed: 11 },
    )
    // every friction drawn put the ball on its rim
    expect([...checked].sort((a, b) => a - b)).toEqual([0, 0.2, 5, 1e3])
  })
})
