// The exact event-driven reference (src/eventSolver.ts): hand-derived cases with closed-form times, then
// agreement with the ECS core's 'exact' method on thousands of throws at the default panel.
import { describe, expect, it } from 'vitest'
import { DEFAULT_PANEL, addPanel, createBallPhysics, resolveConfig, type BallEvent } from '../src/index'
import { solveBall, throwVelocity } from '../src/reference/eventSolver'
import { EXACT, POSITION_TOLERANCE, rng } from './helpers'

const cfg = resolveConfig()
const R = 18
const r = 11
const RHO_C = R - r / 2 // 12.5
const A = 300 // ROLLING_DECEL
const LEAD = 100 // the ball starts at x = -LEAD, the hole is at the origin

/** Start speed that reaches the lip circle (x = −√(R² − δ²)) at `speed`, with deceleration A. */
function startSpeed(delta: number, speed: number): number {
  const s = LEAD - Math.sqrt(R * R - delta * delta)
  return Math.sqrt(speed * speed + 2 * A * s)
}
/** Time to roll distance s from speed v0 with deceleration A: the smaller root of v0·t − A·t²/2 = s. */
const tAt = (v0: number, s: number) => (v0 - Math.sqrt(v0 * v0 - 2 * A * s)) / A

describe('event solver: hand-derived cases', () => {
  it('dead-centre at 663.9 px/s skips (v_skip(0) = 640) at t = (v0 − v_lip)/a, then rests at v0²/(2a) = 816.7 px', () => {
    const v0 = 700
    const res = solveBall(cfg, [{ x: 0, y: 0 }], { x: -LEAD, y: 0, vx: v0, vy: 0 })
    const vLip = Math.sqrt(v0 * v0 - 2 * A * (LEAD - R))
    expect(vLip).toBeGreaterThan(640)
    expect(res.events.map((e) => e.type)).toEqual(['skip', 'rest'])
    expect(res.events[0]!.time).toBeCloseTo((v0 - vLip) / A, 12)
    expect(res.events[0]!.speed).toBeCloseTo(vLip, 9)
    expect(res.events[0]!.delta).toBe(0)
    expect(res.events[1]!.time).toBeCloseTo(v0 / A, 12)
    expect(res.mode).toBe('resting')
    expect(res.x).toBeCloseTo(-LEAD + (v0 * v0) / (2 * A), 9)
  })

  it('δ = 5 px at 300 px/s is inside the window δ_eff = 18·√(1 − 0.25) = 15.6 px: a clean capture at the lip time', () => {
    const v0 = startSpeed(5, 300)
    const res = solveBall(cfg, [{ x: 0, y: 0 }], { x: -LEAD, y: 5, vx: v0, vy: 0 })
    expect(res.events).toHaveLength(1)
    expect(res.events[0]).toMatchObject({ type: 'capture', via: 'clean', hole: 1 })
    expect(res.events[0]!.time).toBeCloseTo(tAt(v0, LEAD - Math.sqrt(R * R - 25)), 12)
    expect(res.events[0]!.speed).toBeCloseTo(300, 9)
    expect([res.x, res.y, res.mode]).toEqual([0, 0, 'captured'])
  })

  it('head-on at 620 px/s (above V_MAX, below V_SKIP_MAX) bounces at ρ_c = 12.5 px with 0.3 of its speed, straight back', () => {
    const v0 = startSpeed(0, 620)
    const res = solveBall(cfg, [{ x: 0, y: 0 }], { x: -LEAD, y: 0, vx: v0, vy: 0 })
    expect(res.events.map((e) => e.type)).toEqual(['bounce', 'nearMiss', 'rest'])
    const vC = Math.sqrt(v0 * v0 - 2 * A * (LEAD - RHO_C))
    const tC = tAt(v0, LEAD - RHO_C)
    expect(res.events[0]!.time).toBeCloseTo(tC, 12)
    const vOut = 0.3 * vC // e·v_n, all of it normal
    expect(res.events[2]!.time).toBeCloseTo(tC + vOut / A, 12)
    expect(res.x).toBeCloseTo(-RHO_C - (vOut * vOut) / (2 * A), 9)
    expect(res.y).toBe(0)
    expect(res.mode).toBe('resting')
  })

  // δ = 11.5 px is in the rolling band (0.814·12.5 = 10.17 < δ < 12.5); at the contact circle the
  // tangential speed is v_c·δ/ρ_c. It pops off iff the arc to the drop speed, (v_t0 − 110)/5, exceeds
  // 0.565 turns of the lip circle (63.9 px), i.e. v_t0 > 429.5 px/s.
  const POP_ARC = 0.565 * 2 * Math.PI * R
  const roll = (vLip: number) => {
    const delta = 11.5
    const v0 = startSpeed(delta, vLip)
    const sC = LEAD - Math.sqrt(RHO_C * RHO_C - delta * delta)
    const vC = Math.sqrt(v0 * v0 - 2 * A * sC)
    const res = solveBall(cfg, [{ x: 0, y: 0 }], { x: -LEAD, y: delta, vx: v0, vy: 0 })
    return { res, tC: tAt(v0, sC), vt0: (vC * delta) / RHO_C }
  }

  // the lip speed must be above the window (δ_eff(v) < 11.5 ⇔ v > 461.6) and below v_skip(11.5) = 492.3
  it('a rim roll with v_t0 below 429.5 px/s drops in at t_c + ln(v_t0/110)/5', () => {
    const { res, tC, vt0 } = roll(465)
    expect(vt0).toBeLessThan(110 + 5 * POP_ARC)
    expect(res.events.map((e) => (e.via ? `${e.type}:${e.via}` : e.type))).toEqual(['rimRoll', 'capture:rimRoll'])
    expect(res.events[0]!.time).toBeCloseTo(tC, 12)
    expect(res.events[1]!.time).toBeCloseTo(tC + Math.log(vt0 / 110) / 5, 12)
  })

  it('a rim roll with v_t0 above 429.5 px/s pops off at t_c − ln(1 − 5·63.9/v_t0)/5, leaving at v_t0 − 5·63.9 along the tangent', () => {
    const { res, tC, vt0 } = roll(480)
    expect(vt0).toBeGreaterThan(110 + 5 * POP_ARC)
    expect(res.events.map((e) => e.type)).toEqual(['rimRoll', 'lipOut', 'nearMiss', 'rest'])
    const tPop = tC - Math.log(1 - (5 * POP_ARC) / vt0) / 5
    expect(res.events[1]!.time).toBeCloseTo(tPop, 12)
    // contact at angle atan2(δ, −√(ρ_c² − δ²)) on the far side going +x, i.e. clockwise in angle (y down)
    const phi0 = Math.atan2(11.5, -Math.sqrt(RHO_C * RHO_C - 11.5 * 11.5))
    const phi = phi0 - POP_ARC / RHO_C // the centre rides the contact circle: 63.9 px of arc turn it 0.81 turns
    const vOut = vt0 - 5 * POP_ARC // v_t(τ) = v_t0 − μ·arc(τ) for the exponential decay
    const run = (vOut * vOut) / (2 * A)
    expect(res.events[3]!.time).toBeCloseTo(tPop + vOut / A, 9)
    expect(res.x).toBeCloseTo(RHO_C * Math.cos(phi) + Math.sin(phi) * run, 9)
    expect(res.y).toBeCloseTo(RHO_C * Math.sin(phi) - Math.cos(phi) * run, 9)
  })

  it('a brush at δ = 15 px and 340 px/s (δ_eff(340) = 14.8 px, v_skip(15) = 353.8 px/s) bounces at the lip and never rolls', () => {
    const v0 = startSpeed(15, 340)
    const res = solveBall(cfg, [{ x: 0, y: 0 }], { x: -LEAD, y: 15, vx: v0, vy: 0 })
    expect(res.events.map((e) => e.type)).toEqual(['bounce', 'nearMiss', 'rest'])
    expect(res.events[0]!.time).toBeCloseTo(tAt(v0, LEAD - Math.sqrt(R * R - 225)), 12)
    expect(Math.hypot(res.x, res.y)).toBeGreaterThan(R)
  })
})

describe('event solver agrees with the ECS core', () => {
  it("3,000 seeded throws at the default panel: same event sequence, times and (δ, v) within 1e-9, final state within 1e-6 px", () => {
    const sim = createBallPhysics({}, { capacity: 8192 })
    const ids = addPanel(sim)
    const holes = DEFAULT_PANEL.holes.map((h, i) => ({ x: h.x, y: h.y, id: ids[i]! }))
    const rand = rng(77)
    const n = 3000
    const balls: number[] = []
    const refs: ReturnType<typeof solveBall>[] = []
    for (let i = 0; i < n; i++) {
      const x = DEFAULT_PANEL.launch.x + (rand() - 0.5) * 300
      const y = DEFAULT_PANEL.launch.y
      const power = rand()
      const angle = (rand() - 0.5) * 1.4
      balls.push(sim.throwBall({ x, y, power, angle }))
      refs.push(solveBall(sim.config, holes, { x, y, ...throwVelocity(sim.config, power, angle) }))
    }
    const byBall = new Map<number, BallEvent[]>()
    for (let i = 0; i < 60 * 30 && sim.world.moving.count > 0; i++) {
      sim.step(1 / 60)
      for (const e of sim.drainEvents()) {
        if (!byBall.has(e.ball)) byBall.set(e.ball, [])
        byBall.get(e.ball)!.push(e)
      }
    }
    const kinds = new Set<string>()
    for (let i = 0; i < n; i++) {
      const got = byBall.get(balls[i]!) ?? []
      const want = refs[i]!.events
      expect(got.map((e) => `${e.type}:${e.hole}:${e.via}`), `throw ${i}`).toEqual(want.map((e) => `${e.type}:${e.hole}:${e.via}`))
      got.forEach((e, k) => {
        kinds.add(e.type)
        const f = want[k]!
        expect(Math.abs(e.time - f.time)).toBeLessThan(EXACT)
        expect(Math.abs((e.delta ?? 0) - (f.delta ?? 0))).toBeLessThan(EXACT)
        expect(Math.abs((e.speed ?? 0) - (f.speed ?? 0))).toBeLessThan(EXACT)
      })
      const s = sim.ballState(balls[i]!)
      expect(s.mode).toBe(refs[i]!.mode)
      expect(Math.hypot(s.x - refs[i]!.x, s.y - refs[i]!.y)).toBeLessThan(POSITION_TOLERANCE)
    }
    for (const k of ['skip', 'capture', 'bounce', 'rimRoll', 'lipOut', 'nearMiss', 'rest']) expect(kinds.has(k), k).toBe(true)
  })
})
