// The fixed-tick method halves its tick where the balls cover many of their spacings a tick
// (src/contacts/fixedHalve.ts). A ball is paired with every ball it could reach within a tick in any
// direction, so in a crowd of tiny fast balls every ball was paired with nearly every other: 5,000 balls of
// radius 0.5 at up to 3e4 px/s in a 1,000 px box had hundreds of pairs a candidate, and the solve's sweeps
// over them took 2.6 s for the first step. The halved ticks stay on the world's clock (k·tick), decided from
// the tick's balls alone: the same bits at every frame rate, in both broadphases and across a snapshot.
import { describe, expect, it } from 'vitest'
import fc from 'fast-check'
import { createBallPhysics, type BallPhysics } from '../../src/index'
import { MAX_TICK_CONTACTS, MAX_TICK_HALVINGS, TICK_PAIRS_PER_CANDIDATE } from '../../src/config/tolerances'
import { rng } from '../helpers'

const SIDE = 200
const RADIUS = 0.5

interface GasOptions {
  decel?: number
  restitution?: number
  /** the box's side, px (default SIDE) */
  side?: number
  /** px (default RADIUS; cut to fit the lattice) */
  radius?: number
  seed?: number
}

/** n balls on a lattice in a closed box (walls of the balls' restitution), at up to vmax px/s in random directions. */
function gas(n: number, vmax: number, o: GasOptions = {}): BallPhysics {
  const { decel = 0, restitution = 1, side = SIDE, radius = RADIUS, seed = 4242 } = o
  const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', ROLLING_DECEL: decel, BALL_RESTITUTION: restitution }, { capacity: n + 8 })
  sim.setWalls({ minX: 0, minY: 0, maxX: side, maxY: side, restitution })
  const r = rng(seed)
  const k = Math.ceil(Math.sqrt(n))
  const pitch = side / k
  // balls put down on others would be held
  const rad = Math.min(radius, 0.45 * pitch)
  for (let i = 0; i < n; i++) {
    const a = r() * 2 * Math.PI
    const v = vmax * r()
    sim.addBall({ x: pitch * ((i % k) + 0.5), y: pitch * (Math.floor(i / k) + 0.5), vx: v * Math.cos(a), vy: v * Math.sin(a), radius: rad })
  }
  return sim
}

/** Every ball's state to the last bit. */
/** 50 tiny balls of mass 3.5e5 at 5,000 px/s, 8 of mass 4.3e6 at 3e4 px/s and 80 of mass 1 at 1e5 px/s in a closed elastic box */
function pumped(seed: number, travel?: number): BallPhysics {
  const random = rng(seed)
  const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 1, ROLLING_DECEL: 0, CONTACT_TRAVEL_HALVINGS: travel }, { capacity: 256 })
  sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 1 })
  for (const [n, radius, mass, speed] of [[50, 0.0115, 3.5e5, 5000], [8, 11, 4.3e6, 3e4], [80, 11, 1, 1e5]] as const) {
    for (let i = 0; i < n; i++) {
      const a = random() * 2 * Math.PI
      sim.addBall({ x: 15 + 390 * random(), y: 15 + 450 * random(), vx: speed * Math.cos(a), vy: speed * Math.sin(a), radius, mass })
    }
  }
  return sim
}

function state(sim: BallPhysics): string {
  const B = sim.world.Ball
  return sim
    .balls()
    .map((b) => `${b} ${B.mode[b]} ${B.x[b]} ${B.y[b]} ${B.vx[b]} ${B.vy[b]}`)
    .join('\n')
}

/** Pairs of balls within each other's reach (radius + speed · tick + 1e-6) at a tick of `tick` s, per ball. */
function pairsPerBall(sim: BallPhysics, tick: number): number {
  const bs = sim.balls().map((b) => sim.ballState(b))
  let pairs = 0
  for (let i = 0; i < bs.length; i++) {
    for (let j = i + 1; j < bs.length; j++) {
      const a = bs[i]!
      const b = bs[j]!
      const s = a.radius + Math.hypot(a.vx, a.vy) * tick + b.radius + Math.hypot(b.vx, b.vy) * tick + 2e-6
      if ((a.x - b.x) ** 2 + (a.y - b.y) ** 2 < s * s) pairs++
    }
  }
  return pairs / bs.length
}

describe('fixed tick: halved where balls cover many spacings a tick', () => {
  it('400 radius-0.5 balls at up to 3e4 px/s in a 200 px box: the tick is halved, its pairs stay near the bound, no overlap survives a tick', () => {
    const sim = gas(400, 3e4)
    const F = sim.world.fixed!
    // at the configured tick every ball reaches most of the box
    expect(pairsPerBall(sim, sim.config.CONTACT_TICK)).toBeGreaterThan(100)
    let most = 0
    let halved = 0
    for (let i = 0; i < 30; i++) {
      sim.step(1 / 60)
      sim.drainEvents()
      most = Math.max(most, F.tickPairs / F.tickFull)
      halved = Math.max(halved, F.halvings)
      expect(F.tick).toBe(sim.config.CONTACT_TICK / 2 ** F.halvings)
      // a step of 1/60 s ends on a tick at every spacing: solved, no overlap deeper than the projection's slop
      const bs = sim.balls().map((b) => sim.ballState(b))
      let deepest = 0
      for (let p = 0; p < bs.length; p++) {
        for (let q = p + 1; q < bs.length; q++) {
          const d = 2 * RADIUS - Math.hypot(bs[p]!.x - bs[q]!.x, bs[p]!.y - bs[q]!.y)
          if (d > deepest) deepest = d
        }
      }
      expect(deepest).toBeLessThan(1e-3)
    }
    expect(halved).toBeGreaterThanOrEqual(3)
    expect(halved).toBeLessThanOrEqual(MAX_TICK_HALVINGS)
    expect(most).toBeLessThanOrEqual(2 * TICK_PAIRS_PER_CANDIDATE)
    expect(F.capped).toBe(0)
  })

  it('kinetic energy never rises and momentum is kept in the halved ticks (no walls, restitution 1)', () => {
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', ROLLING_DECEL: 0, BALL_RESTITUTION: 1 }, { capacity: 400 })
    const r = rng(99)
    for (let i = 0; i < 300; i++) {
      const a = r() * 2 * Math.PI
      const v = 3e4 * r()
      sim.addBall({ x: (i % 20) * 8, y: Math.floor(i / 20) * 8, vx: v * Math.cos(a), vy: v * Math.sin(a), radius: RADIUS })
    }
    const totals = () => {
      let px = 0
      let py = 0
      let ke = 0
      for (const b of sim.balls()) {
        const s = sim.ballState(b)
        px += s.vx
        py += s.vy
        ke += s.vx * s.vx + s.vy * s.vy
      }
      return { px, py, ke }
    }
    const start = totals()
    let last = start.ke
    let halved = 0
    for (let i = 0; i < 20; i++) {
      sim.step(1 / 120)
      halved = Math.max(halved, sim.world.fixed!.halvings)
      const now = totals()
      expect(now.ke).toBeLessThanOrEqual(last * (1 + 1e-12))
      expect(Math.abs(now.px - start.px)).toBeLessThan(1e-9 * Math.sqrt(start.ke) * 300)
      expect(Math.abs(now.py - start.py)).toBeLessThan(1e-9 * Math.sqrt(start.ke) * 300)
      last = now.ke
    }
    expect(halved).toBeGreaterThan(0)
  })

  it('the same bits at 30, 60, 120 and 240 Hz, with a ball thrown in between steps', () => {
    // the first solve (the balls just put down) halves the tick at the start of the first step's window, which
    // then ends at the finer tick (at 30 Hz it had run on to 1/120 s, at 240 Hz to 1/240 s)
    const at: Record<number, string[]> = {}
    for (const hz of [30, 60, 120, 240]) {
      const sim = gas(300, 2e4)
      const out: string[] = []
      const per = hz / 30
      let halved = 0
      for (let i = 0; i < 15 * per; i++) {
        if (i === 5 * per) sim.addBall({ x: 1, y: 100, vx: 1e5, vy: 3, radius: 0.7 })
        sim.step(1 / hz)
        halved = Math.max(halved, sim.world.fixed!.halvings)
        if ((i + 1) % per === 0) out.push(state(sim))
      }
      expect(halved).toBeGreaterThan(0)
      at[hz] = out
    }
    for (const hz of [60, 120, 240]) for (let k = 0; k < at[30]!.length; k++) expect(at[hz]![k]).toBe(at[30]![k])
  })

  it('both broadphases give the same bits when the tick is halved', () => {
    const run = (broadphase: number) => {
      const sim = gas(300, 2e4)
      sim.world.fixed!.broadphase = broadphase
      const out: string[] = []
      let halved = 0
      for (let i = 0; i < 20; i++) {
        sim.step(1 / 60)
        halved = Math.max(halved, sim.world.fixed!.halvings)
        for (const e of sim.drainEvents()) out.push(JSON.stringify(e))
        out.push(state(sim))
      }
      return { out, halved }
    }
    const sweep = run(0)
    const dense = run(1)
    expect(sweep.halved).toBeGreaterThan(0)
    expect(sweep.out.length).toBe(dense.out.length)
    for (let i = 0; i < sweep.out.length; i++) if (sweep.out[i] !== dense.out[i]) expect(sweep.out[i]).toBe(dense.out[i])
  })

  it('a snapshot taken between halved ticks restores to the same run', () => {
    const a = gas(300, 2e4)
    for (let i = 0; i < 7; i++) a.step(1 / 60)
    // between ticks of every spacing: 1/7 of a configured tick on
    a.step(a.config.CONTACT_TICK / 7)
    expect(a.world.fixed!.halvings).toBeGreaterThan(0)
    const bytes = a.snapshot()
    const b = createBallPhysics({ BALL_COLLISIONS: 'fixed', ROLLING_DECEL: 0, BALL_RESTITUTION: 1 }, { capacity: 308 })
    b.restore(bytes)
    for (let i = 0; i < 10; i++) {
      a.step(1 / 60)
      b.step(1 / 60)
      expect(state(b)).toBe(state(a))
    }
  })

  it('back to the configured tick once the balls slow down', () => {
    // a deceleration that stops a 2e4 px/s ball within 0.1 s
    const sim = gas(300, 2e4, { decel: 2e5, restitution: 0.5 })
    const F = sim.world.fixed!
    let halved = 0
    for (let i = 0; i < 60; i++) {
      sim.step(1 / 60)
      halved = Math.max(halved, F.halvings)
    }
    expect(halved).toBeGreaterThan(0)
    expect(F.halvings).toBe(0)
    expect(F.tick).toBe(sim.config.CONTACT_TICK)
  })

  it('no halving on the scenes the method is for: a gas at area fraction 0.2 and a pile pressed by a stream', () => {
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', ROLLING_DECEL: 0, BALL_RESTITUTION: 0.9 }, { capacity: 700 })
    sim.setWalls({ minX: 0, minY: 0, maxX: 400, maxY: 400, restitution: 0.9 })
    const r = rng(5)
    for (let i = 0; i < 200; i++) {
      const a = r() * 2 * Math.PI
      sim.addBall({ x: 20 + (i % 14) * 26.5, y: 20 + Math.floor(i / 14) * 26.5, vx: 350 * Math.cos(a), vy: 350 * Math.sin(a) })
    }
    for (let i = 0; i < 240; i++) {
      if (i % 4 === 0) sim.addBall({ x: 200, y: 380, vx: 0, vy: -1500 })
      sim.step(1 / 120)
      expect(sim.world.fixed!.halvings).toBe(0)
    }
  })

  it('random crowds (100–300 balls of radius 0.05–3 px at up to 1e5 px/s, boxes of 40–400 px, any restitution): kinetic energy never rises, no overlap over 1e-3 px after a step, ticks on the halved spacing', () => {
    let halved = 0
    fc.assert(
      fc.property(
        fc.record({
          n: fc.integer({ min: 100, max: 300 }),
          radius: fc.double({ min: 0.05, max: 3, noNaN: true }),
          vmax: fc.constantFrom(3e3, 3e4, 1e5),
          side: fc.constantFrom(40, 100, 400),
          e: fc.constantFrom(0, 0.5, 1),
          seed: fc.nat(1e6),
        }),
        ({ n, radius, vmax, side, e, seed }) => {
          const sim = gas(n, vmax, { restitution: e, side, radius, seed })
          const F = sim.world.fixed!
          let ke = Infinity
          let most = 0
          for (let s = 0; s < 12; s++) {
            sim.step(1 / 60)
            most = Math.max(most, F.halvings)
            expect(F.tick).toBe(sim.config.CONTACT_TICK / 2 ** F.halvings)
            const bs = sim.balls().map((b) => sim.ballState(b))
            let now = 0
            for (const b of bs) now += b.vx * b.vx + b.vy * b.vy
            // finite, and not rising
            expect(Number.isFinite(now)).toBe(true)
            expect(now).toBeLessThanOrEqual(ke * (1 + 1e-9))
            ke = now
            if (F.capped > 0) continue
            let deepest = 0
            for (let p = 0; p < bs.length; p++) {
              for (let q = p + 1; q < bs.length; q++) {
                const d = bs[p]!.radius + bs[q]!.radius - Math.hypot(bs[p]!.x - bs[q]!.x, bs[p]!.y - bs[q]!.y)
                if (d > deepest) deepest = d
              }
            }
            expect(deepest).toBeLessThan(1e-3)
          }
          if (most > 0) halved++
        },
      ),
      { seed: 77, numRuns: 24 },
    )
    expect(halved).toBeGreaterThan(6)
  }, 120_000)

  it('a crowd that crosses its box in a tick (300 radius-0.3 balls at up to 1e5 px/s in a 100 px box, restitution 1) is halved and keeps its energy', () => {
    // every pair stays listed through the first halvings (the box bounds the reach), so a model that counted a
    // pair as one candidate never halved: the visits bound on restitution then drained the gas to 0.72 of its
    // energy in 1/6 s
    // energy of four draws: the gas is chaotic, and one draw's share says little (over 24 draws, 0.981–1.000,
    // mean 0.9921; 0.961–1.000, mean 0.9925, with CONTACT_TIMING 'instant'; the failure above gave 0.72)
    const kept: number[] = []
    for (const seed of [11, 12, 13, 14]) {
      const sim = gas(300, 1e5, { side: 100, radius: 0.3, seed })
      const ke = () => sim.balls().reduce((e, b) => e + sim.ballState(b).vx ** 2 + sim.ballState(b).vy ** 2, 0)
      const start = ke()
      let halved = 0
      for (let i = 0; i < 10; i++) {
        sim.step(1 / 60)
        halved = Math.max(halved, sim.world.fixed!.halvings)
      }
      expect(halved).toBeGreaterThanOrEqual(4)
      kept.push(ke() / start)
    }
    expect(Math.min(...kept)).toBeGreaterThan(0.95)
    expect(kept.reduce((a, b) => a + b, 0) / kept.length).toBeGreaterThan(0.985)
  }, 60_000)

  it('light balls pumped by heavy ones (restitution 1): past MAX_TICK_CONTACTS contacts in a contact tick of the clock a light ball meets balls 100 times heavier without restitution, so the crowd keeps its energy on fewer ticks', () => {
    // 50 tiny balls of mass 3.5e5 at 5,000 px/s, 8 of mass 4.3e6 at 3e4 px/s and 80 light ones at 1e5 px/s in
    // a closed elastic box. The heavy balls pump the light ones, whose ticks end with several times the
    // pairs they gathered (the spacing was halved by that growth: 10-12 of the 12 steps ended on a tick
    // halved 4 times or more, 409-460 ticks in the 0.2 s, 0.96-0.97 of the energy kept). With the light
    // balls' contacts counted on the clock (src/contacts/fixedCount.ts) the pumping stops where it would
    // cost: 201-210 ticks, 0-1 such steps, 0.955-0.986 of the energy kept (seeds 1-5). That is with the tick
    // never halved for the balls' travel (CONTACT_TRAVEL_HALVINGS 0, the default); with that rule (4) the light
    // balls, at 1e5 px/s covering about 38 times the two radii of a pair a tick at 1/120 s, hold the tick at its
    // 4 halvings or more: 450-490 ticks, 0.98-0.99 of the energy kept (441-520 ticks, 0.94-0.99, since a
    // meeting of a ball pumped earlier in a call counts as pumped: src/contacts/fixedSolve.ts; 591-733 ticks,
    // 0.95-0.99, in the same time, since a tick is solved again for a tiny ball left closing into a big one
    // by more than its radius: src/contacts/fixedDeep.ts; 592-816 since a ball put down on a held one is held
    // behind it: 2-4 more of the 138 wait at the start, and seed 5's crowd, released otherwise, takes 816
    // ticks against 658; 571-785, 0.93-0.99, since a ball a pumped one meets is pumped too, seeds 1-9;
    // 546-732, 0.96-0.99, seeds 1-5, since a speck closes deep only past 0.5 px; without the travel rule
    // 206-256 ticks, 0.85-0.99; since the budget for unlike masses counts the pairs of a span's first try,
    // not every pair of its balls, 319-324 ticks with the rule and 286-333 without, 0.93-1.00 of the
    // energy kept, 13-19 of the 24 spans' last ticks skipped: src/contacts/fixedBudget.ts)
    for (const travel of [0, 4]) {
      const kept: number[] = []
      for (const seed of [1, 2, 3, 4, 5]) {
        const sim = pumped(seed, travel)
        const F = sim.world.fixed!
        const energy = () => sim.balls().reduce((e, b) => e + F.mass[b]! * (sim.ballState(b).vx ** 2 + sim.ballState(b).vy ** 2), 0)
        const start = energy()
        for (let i = 0; i < 12; i++) sim.step(1 / 60)
        // 24 ticks at 1/120 s, 16 times that (384) at 4 halvings
        expect(F.ticks, `seed ${seed}`).toBeLessThan(travel === 0 ? 400 : 850)
        const share = energy() / start
        expect(share).toBeLessThanOrEqual(1)
        kept.push(share)
      }
      kept.sort((a, b) => a - b)
      expect(kept[2]).toBeGreaterThan(0.97)
    }
  })

  it('a snapshot taken within a contact tick of the clock keeps the contacts each ball took in it', () => {
    const a = pumped(1)
    for (let i = 0; i < 3; i++) a.step(1 / 60)
    a.step(a.config.CONTACT_TICK / 3)
    // balls past the count at this instant: the rest of this tick of the clock depends on it
    const key = Math.floor(a.time / a.config.CONTACT_TICK) + 1
    const rest = a.world.fixed!.rest
    expect(a.balls().filter((b) => rest.tickContactsAt[b] === key && rest.tickContacts[b]! >= MAX_TICK_CONTACTS).length).toBeGreaterThan(0)
    const b = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 1, ROLLING_DECEL: 0 }, { capacity: 256 })
    b.restore(a.snapshot())
    for (let i = 0; i < 6; i++) {
      a.step(1 / 60)
      b.step(1 / 60)
      expect(state(b)).toBe(state(a))
    }
  })

  it('the contacts counted on the clock give the same bits at 30 and 120 Hz', () => {
    const a = pumped(2)
    const b = pumped(2)
    for (let i = 0; i < 3; i++) a.step(1 / 30)
    for (let i = 0; i < 12; i++) b.step(1 / 120)
    expect(state(b)).toBe(state(a))
  })

  it('coarsening backs off when the coarser tick is halved again at once (a pile beside balls whose coarse reach covers it)', () => {
    // a touching 50 × 50 pile (pairs from the radii, about 2 a candidate) and 40 balls bouncing up and down
    // at 23,000 px/s 100–144 px from its sides: at the configured tick their reach covers the pile, at half
    // of it not, so each try at the coarser tick lists about 100,000 pairs and is halved again
    const P = 50
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', ROLLING_DECEL: 0, BALL_RESTITUTION: 1 }, { capacity: P * P + 48 })
    const W = 800
    const H = 2 * P + 60
    sim.setWalls({ minX: 0, minY: 0, maxX: W, maxY: H, restitution: 1 })
    const px0 = W / 2 - P
    const py0 = H / 2 - P
    for (let i = 0; i < P * P; i++) sim.addBall({ x: px0 + 1 + (2 + 1e-7) * (i % P), y: py0 + 1 + (2 + 1e-7) * Math.floor(i / P), vx: 1.5, vy: 0, radius: 1 })
    for (let k = 0; k < 20; k++) {
      for (const side of [-1, 1]) {
        const x = side < 0 ? px0 - 100 - 2.2 * k : px0 + 2 * P + 100 + 2.2 * k
        sim.addBall({ x, y: 5 + ((k * 37) % (H - 10)), vx: 0, vy: (k % 2 === 0 ? 1 : -1) * 23000, radius: 1 })
      }
    }
    const F = sim.world.fixed!
    let backoff = 1
    let halved = 0
    for (let i = 0; i < 30; i++) {
      sim.step(1 / 60)
      backoff = Math.max(backoff, F.coarsenBackoff)
      halved = Math.max(halved, F.halvings)
    }
    expect(halved).toBeGreaterThan(0)
    // tries after 2, 4, 8, … ticks: within 30 steps (60 configured ticks) the wait has grown past 8
    expect(backoff).toBeGreaterThanOrEqual(8)
  })

  it("on a halved sweep tick both broadphases list the same pairs (the sweep's unpacked balls get the finer reach too)", () => {
    // a hot gas that halves the tick 7 times, and far from it a row struck through to its last ball g, with a
    // lone ball e beyond g at 1,200 px/s: at the configured tick e's reach (11 px) covers g, at the finer one
    // not. The sweep did not pack e, kept its coarse reach, and listed (g, e) when the widening reached it.
    const pairsOf = (broadphase: number) => {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', ROLLING_DECEL: 0, BALL_RESTITUTION: 1 }, { capacity: 600 })
      const r = rng(12345)
      for (let i = 0; i < 400; i++) {
        const a = r() * 2 * Math.PI
        const v = 3e4 * r()
        sim.addBall({ x: 5 * (i % 20) + 2.5, y: 5 * Math.floor(i / 20) + 2.5, vx: v * Math.cos(a), vy: v * Math.sin(a), radius: 0.5 })
      }
      sim.addBall({ x: 1000, y: 500, vx: 6000, vy: 2, radius: 1 })
      let x = 1000
      for (let k = 0; k < 30; k++) {
        x += 2 + 1e-7
        sim.addBall({ x, y: 500, vx: 0, vy: 2, radius: 1 })
      }
      sim.addBall({ x: x + 12.2, y: 500, vx: 0, vy: 1200, radius: 1 })
      const F = sim.world.fixed!
      F.broadphase = broadphase
      const out: string[] = []
      // the first solve (the balls just put down) and the last tick of each later step
      for (const dt of [1e-9, 1 / 60, 1 / 60]) {
        sim.step(dt)
        const pairs: string[] = []
        for (let p = 0; p < F.pairCount; p++) pairs.push(`${F.id[F.pairA[p]!]}-${F.id[F.pairB[p]!]}`)
        out.push(`${F.halvings}: ${pairs.sort().join(' ')}`)
      }
      return out
    }
    const sweep = pairsOf(0)
    const dense = pairsOf(1)
    expect(Number(sweep[0]!.split(':')[0])).toBeGreaterThanOrEqual(5)
    expect(sweep).toEqual(dense)
  })
})
