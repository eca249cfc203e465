// The fixed-tick method's energy in elastic scenes. A pair takes its restitution up to RESTITUTION_VISITS
// times a tick, and is solved with a wall (inelastic there) only when its ball is SQUEEZE_MASS_RATIO times
// lighter than its partner; before, dense elastic scenes lost the energy the exact method keeps
// (docs/decisions.md §12).
import { describe, expect, it } from 'vitest'
import { createBallPhysics, mulberry32, type BallPhysics } from '../../src/index'
import { ticksHalvedForTravel } from '../../src/contacts/fixedTravel'
import { ticksRedoneForRestitution } from '../../src/contacts/fixedRedo'

function kinetic(sim: BallPhysics): number {
  const F = sim.world.fixed
  const C = sim.world.collide
  let k = 0
  for (const b of sim.balls()) {
    const s = sim.ballState(b)
    const m = F !== null ? F.mass[b]! : C!.mass[b]!
    k += 0.5 * m * (s.vx * s.vx + s.vy * s.vy)
  }
  return k
}

/** Steps sim `steps` times by 1/60 s, checking that its kinetic energy never rises; the share kept. */
function stepNeverRising(sim: BallPhysics, steps: number): number {
  const k0 = kinetic(sim)
  let last = k0
  for (let s = 0; s < steps; s++) {
    sim.step(1 / 60)
    sim.drainEvents()
    const k = kinetic(sim)
    expect(k).toBeLessThanOrEqual(last * (1 + 1e-12))
    last = k
  }
  return last / k0
}

describe('fixed-tick contacts, restitution 1: the energy kept', () => {
  it('three balls meeting within one tick keep their kinetic energy (0.617 of it when a pair took its restitution once a tick)', () => {
    const balls = [
      { x: 139.18073000482738, y: 19.830915874668747, vx: 89.84983615314096, vy: 290.2251176687016, radius: 9.443676875438541 },
      { x: 157.17044061563706, y: 12.5, vx: -319.7735630617772, vy: 507.68579689289675, radius: 5.082928522955626 },
      { x: 177.73554763389336, y: 14.657653816077595, vx: -585.8671419663991, vy: 129.45922896465572, radius: 6.802730428986251 },
    ]
    for (const mode of ['on', 'fixed'] as const) {
      const sim = createBallPhysics({ BALL_COLLISIONS: mode, ROLLING_DECEL: 0, BALL_RESTITUTION: 1 })
      for (const b of balls) sim.addBall(b)
      const k0 = kinetic(sim)
      let contacts = 0
      for (let i = 0; i < 60; i++) {
        sim.step(1 / 60)
        contacts += sim.drainEvents().filter((e) => e.type === 'collision').length
      }
      expect(contacts, mode).toBeGreaterThanOrEqual(2)
      expect(kinetic(sim) / k0, mode).toBeGreaterThan(1 - 1e-9)
      expect(kinetic(sim) / k0, mode).toBeLessThanOrEqual(1 + 1e-9)
    }
  })

  it('400 balls in a 600 px box (area fraction 0.42) keep more than 95 % of their energy over 5 s, and it never rises', () => {
    // 10 % when a pair took its restitution once a tick; 17 % when every ball driven into a wall was solved
    // with it (inelastic there), whatever the masses
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', ROLLING_DECEL: 0, BALL_RESTITUTION: 1 })
    sim.setWalls({ minX: 0, minY: 0, maxX: 600, maxY: 600, restitution: 1 })
    const rnd = mulberry32(5)
    const pitch = 600 / 20
    for (let i = 0; i < 400; i++) {
      const a = rnd() * 6.283
      sim.addBall({ x: pitch * ((i % 20) + 0.5), y: pitch * (Math.floor(i / 20) + 0.5), vx: 300 * Math.cos(a), vy: 300 * Math.sin(a) })
    }
    expect(stepNeverRising(sim, 300)).toBeGreaterThan(0.95)
    // a ball covers a tenth of its radius a tick: hardly a pair spends its restitution visits
    expect(sim.world.fixed!.inelastic).toBeLessThan(1e-3 * sim.world.fixed!.contacts)
  })

  it('a box near jamming (340 balls of radius 11 in 420 × 480 px, area fraction 0.64) loses energy at the default tick, and the inelastic count says so; at 1/480 s it keeps it', () => {
    // the README's figure of 99.1–100 % over 1 s is for sparse boxes (150 balls of radii 2–6 px, area
    // fraction 0.04). Kept over 1 s here: equal masses 0.973 at 1/120 s, 1.000 at 1/480 s; masses 1–26
    // 0.749 and 0.970 (0.948 at 1/240 s)
    const kept: number[] = []
    for (const [spread, tick] of [
      [0, 1 / 120],
      [0, 1 / 480],
      [25, 1 / 120],
      [25, 1 / 480],
    ] as const) {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', ROLLING_DECEL: 0, BALL_RESTITUTION: 1, CONTACT_TICK: tick })
      sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 1 })
      const rnd = mulberry32(7)
      for (let n = 0; n < 340; n++) {
        const mass = 1 + rnd() * spread
        sim.addBall({ x: 15 + (n % 17) * 24 + rnd() * 2, y: 15 + Math.floor(n / 17) * 23 + rnd() * 2, vx: (rnd() - 0.5) * 600, vy: (rnd() - 0.5) * 600, mass, radius: 11 })
      }
      kept.push(stepNeverRising(sim, 60))
      const F = sim.world.fixed!
      if (spread > 0 && tick === 1 / 120) expect(F.inelastic).toBeGreaterThan(1e-3 * F.contacts)
    }
    expect(kept[0]).toBeLessThan(0.99)
    expect(kept[1]).toBeGreaterThan(0.999)
    expect(kept[2]).toBeLessThan(0.85)
    expect(kept[3]).toBeGreaterThan(0.95)
  })

  it('a light ball driven toward a wall by a heavy one: elastic everywhere, the two keep their energy (0.48 when the pair and the wall were solved inelastically at the wall)', () => {
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 1, ROLLING_DECEL: 0, BALL_SETTLE_SPEED: 0 })
    sim.setWalls({ minX: 0, minY: 0, maxX: 200, maxY: 200, restitution: 1 })
    sim.addBall({ x: 144.778, y: 138.498, vx: 128.448, vy: -388.943, mass: 1 })
    sim.addBall({ x: 94.464, y: 68.073, vx: 317.24, vy: -169.507, mass: 0.11883 })
    const k0 = kinetic(sim)
    let collisions = 0
    for (let i = 0; i < 600; i++) {
      sim.step(1 / 60)
      for (const e of sim.drainEvents()) if (e.type === 'collision') collisions++
    }
    expect(collisions).toBeGreaterThan(10)
    expect(kinetic(sim) / k0).toBeCloseTo(1, 9)
  })

  it('an elastic gas of mixed sizes (radii 8–14 px, masses up to 5:1) keeps its energy over 10 s (0.91 before)', () => {
    const r = mulberry32(7)
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 1, ROLLING_DECEL: 0, BALL_SETTLE_SPEED: 0 })
    sim.setWalls({ minX: 0, minY: 0, maxX: 600, maxY: 600, restitution: 1 })
    for (let i = 0; i < 200; i++) {
      const a = r() * 2 * Math.PI
      sim.addBall({ x: 30 + (i % 14) * 40, y: 30 + Math.floor(i / 14) * 40, vx: 200 * Math.cos(a), vy: 200 * Math.sin(a), radius: 8 + 6 * r() })
    }
    const k0 = kinetic(sim)
    for (let i = 0; i < 600; i++) sim.step(1 / 60)
    expect(kinetic(sim) / k0).toBeGreaterThan(0.999)
  })

  it('a crowd that covers more than its radius a tick: by default the impulses closed inelastically past the visits bound are counted (world.fixed.inelastic) and the crowd loses its energy; a finer CONTACT_TICK, or the tick halved for the balls\' travel (CONTACT_TRAVEL_HALVINGS 4), keeps it', () => {
    // 200 balls of radius 11 at 3,000 px/s (area fraction 0.38) in the closed elastic 420 × 480 box: at the
    // default 1/120 s tick a ball covers 2.3 radii a tick, pairs meet past their RESTITUTION_VISITS, and the
    // crowd keeps about a tenth of its energy after 1/3 s; at 1/960 s (0.28 radii a tick) 0.99 or more, and as
    // much with CONTACT_TRAVEL_HALVINGS 4, which halves the tick where balls close on their nearest partner by
    // more than half their size a tick (README, "Ball-ball contacts"; docs/known-failures.md)
    const run = (seed: number, tick?: number, travel?: number) => {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 1, ROLLING_DECEL: 0, CONTACT_TICK: tick, CONTACT_TRAVEL_HALVINGS: travel })
      sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 1 })
      const r = mulberry32(seed)
      for (let i = 0; i < 200; i++) {
        const a = r() * 2 * Math.PI
        sim.addBall({ x: 30 * ((i % 14) + 0.5), y: (480 / 15) * (Math.floor(i / 14) + 0.5), vx: 3000 * Math.cos(a), vy: 3000 * Math.sin(a) })
      }
      const k0 = kinetic(sim)
      let halved = 0
      for (let i = 0; i < 20; i++) {
        sim.step(1 / 60)
        halved = Math.max(halved, sim.world.fixed!.halvings)
      }
      return { kept: kinetic(sim) / k0, inelastic: sim.world.fixed!.inelastic, contacts: sim.world.fixed!.contacts, halved }
    }
    for (const seed of [1, 2]) {
      const coarse = run(seed, undefined, 0)
      expect(coarse.kept, `seed ${seed}`).toBeLessThan(0.5)
      expect(coarse.inelastic, `seed ${seed}`).toBeGreaterThan(0.05 * coarse.contacts)
      const halved = ticksHalvedForTravel()
      const travelled = run(seed, undefined, 4)
      expect(ticksHalvedForTravel()).toBeGreaterThan(halved)
      for (const fine of [travelled, run(seed, 1 / 960)]) {
        expect(fine.kept, `seed ${seed}`).toBeGreaterThan(0.98)
        expect(fine.kept, `seed ${seed}`).toBeLessThanOrEqual(1 + 1e-9)
        expect(fine.inelastic, `seed ${seed}`).toBeLessThan(0.001 * fine.contacts)
      }
      // the travel rule's ticks: halved, and no further than it may
      expect(travelled.halved).toBeGreaterThan(0)
      expect(travelled.halved).toBeLessThanOrEqual(4)
    }
  })

  it('a heavier striker into a resting pile in a corner: 2 px apart, the fixed tick keeps the energy as the exact method does (the tick solved again finer); touching, or 100 times heavier, it loses some and counts it; it never rises', () => {
    // bench/pileStrike.ts's scene from one aim: a 5 × 5 pile of default balls in the corner of the closed
    // elastic 420 × 480 box, 2 px apart (or touching), struck toward the corner at 850 px/s by a ball 4, 10
    // or 100 times heavier. The struck balls cross their gaps and meet the pile and the walls within the
    // tick, so pairs meet past their RESTITUTION_VISITS. A small tick of like masses that closes a pair
    // apart at its start so is solved again at a finer spacing (src/contacts/fixedRedo.ts): 2 px apart, 4
    // and 10 times heavier, 0.388 and 0.234 of the energy were left before it. Touching, or with a ball 100
    // times heavier (past PUMP_MASS_RATIO), the rule does not act, and the loss is a known one of the fixed
    // tick (docs/known-failures.md, "A heavier striker into a resting pile")
    const run = (collisions: 'on' | 'fixed', mass: number, gap: number) => {
      const sim = createBallPhysics({ BALL_COLLISIONS: collisions, BALL_RESTITUTION: 1, ROLLING_DECEL: 0 })
      sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 1 })
      for (let i = 0; i < 5; i++) {
        for (let j = 0; j < 5; j++) sim.addBall({ x: 409 - i * (22 + gap), y: 469 - j * (22 + gap), vx: 0, vy: 0 })
      }
      sim.addBall({ x: 100, y: 100, vx: 850 * Math.SQRT1_2, vy: 850 * Math.SQRT1_2, mass })
      const redone = ticksRedoneForRestitution()
      const kept = stepNeverRising(sim, 120)
      return { kept, inelastic: sim.world.fixed?.inelastic ?? 0, redone: ticksRedoneForRestitution() - redone }
    }
    for (const mass of [4, 10]) {
      expect(run('on', mass, 2).kept, `exact, mass ${mass}`).toBeGreaterThan(0.999)
      const apart = run('fixed', mass, 2)
      expect(apart.kept, `fixed, mass ${mass}, 2 px apart`).toBeGreaterThan(0.999)
      expect(apart.redone, `fixed, mass ${mass}, 2 px apart`).toBeGreaterThan(0)
      const touching = run('fixed', mass, 0)
      expect(touching.kept, `fixed, mass ${mass}, touching`).toBeGreaterThan(0.2)
      // whatever it loses went through impulses closed past their visits, and the count says so
      if (touching.kept < 0.999) expect(touching.inelastic, `fixed, mass ${mass}, touching`).toBeGreaterThan(0)
    }
    // a ball 100 times heavier: not solved again, and the loss is there
    const heavy = run('fixed', 100, 2)
    expect(heavy.redone).toBe(0)
    expect(heavy.kept).toBeLessThan(0.9)
    expect(heavy.inelastic).toBeGreaterThan(0)
  })

  it('a tick solved again finer for its restitution gives the same bits at 30, 60 and 240 Hz', () => {
    const run = (hz: number) => {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 1, ROLLING_DECEL: 0 })
      sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 1 })
      for (let i = 0; i < 5; i++) {
        for (let j = 0; j < 5; j++) sim.addBall({ x: 409 - i * 24, y: 469 - j * 24, vx: 0, vy: 0 })
      }
      sim.addBall({ x: 100, y: 100, vx: 850 * Math.SQRT1_2, vy: 850 * Math.SQRT1_2, mass: 10 })
      const redone = ticksRedoneForRestitution()
      for (let f = 0; f < hz; f++) sim.step(1 / hz)
      expect(ticksRedoneForRestitution()).toBeGreaterThan(redone)
      return sim.balls().map((b) => sim.ballState(b))
    }
    const at60 = run(60)
    expect(run(30)).toEqual(at60)
    expect(run(240)).toEqual(at60)
  })
})

describe('fixed-tick contacts: a striker into a light ball lying at a wall, and the wall\'s restitution', () => {
  function strike(mass: number, wallE: number): number {
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 1, ROLLING_DECEL: 0 })
    sim.setWalls({ minX: 0, minY: 0, maxX: 400, maxY: 400, restitution: wallE })
    const a = sim.addBall({ x: 200, y: 200, vx: 300, vy: 0 })
    sim.addBall({ x: 389, y: 200, vx: 0, vy: 0, mass })
    for (let i = 0; i < 60; i++) sim.step(1 / 60)
    return sim.ballState(a).vx
  }
  it('a dead wall takes the push: the striker stops, as the exact method has it (it came back at full speed)', () => {
    expect(strike(0.33, 0)).toBe(0)
    expect(strike(0.1, 0)).toBe(0)
  })
  it('an elastic wall sends it back whole; in between, at most the walls\' restitution of it', () => {
    expect(strike(0.33, 1)).toBeCloseTo(-300, 9)
    expect(strike(0.33, 0.3)).toBeCloseTo(-90, 9)
    expect(strike(0.1, 0.5)).toBeCloseTo(-150, 9)
  })
})
