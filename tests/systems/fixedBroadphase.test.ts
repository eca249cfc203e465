// The fixed-tick method's two broadphases (src/contacts/fixedDense.ts, and the sweep of fixedSweep.ts with
// the packing and ordering of fixedOrder.ts) give the same pairs in the same order: a world forced to take
// one and a world forced to take the other step to the same bits, every event and every ball's state, in
// scenes that reach every branch (resting balls all candidates or looked up, big balls, balls sped up and
// paired again, walls, the sweep's cells by row and by column, balls added and removed as it runs), and in
// random scenes of every size, mass and speed (600 seeds, and 300 more with up to 230 balls, passed when
// this was written; 60 run here).
import { describe, expect, it } from 'vitest'
import { DEFAULT_PANEL, addPanel, createBallPhysics, type BallPhysics } from '../../src/index'
import { rng } from '../helpers'

type Scene = (sim: BallPhysics, step: number) => void

/** Every event and, after each step, every ball's state, as text (numbers to the last bit). */
function trace(make: () => BallPhysics, scene: Scene, steps: number, dt: number, broadphase: number): string[] {
  const sim = make()
  sim.world.fixed!.broadphase = broadphase
  const out: string[] = []
  for (let i = 0; i < steps; i++) {
    scene(sim, i)
    sim.step(dt)
    for (const e of sim.drainEvents()) out.push(JSON.stringify(e))
    const B = sim.world.Ball
    for (const b of sim.balls()) out.push(`${b} ${B.mode[b]} ${B.x[b]} ${B.y[b]} ${B.vx[b]} ${B.vy[b]}`)
  }
  return out
}

function same(make: () => BallPhysics, scene: Scene, steps: number, dt: number, what = ''): number {
  const sweep = trace(make, scene, steps, dt, 0)
  const dense = trace(make, scene, steps, dt, 1)
  for (let i = 0; i < sweep.length; i++) if (sweep[i] !== dense[i]) expect(`${what} ${sweep[i]}`).toBe(`${what} ${dense[i]}`)
  expect(sweep.length).toBe(dense.length)
  return sweep.filter((s) => s.includes('"collision"')).length
}

describe('fixed-tick broadphases', () => {
  it('a burst of balls thrown up four tiles of the panel (the sweep by column), walls open at the bottom', () => {
    const W = DEFAULT_PANEL.width
    const H = DEFAULT_PANEL.height
    const make = () => {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed' }, { capacity: 512 })
      sim.setWalls({ minX: 0, minY: 0, maxX: 2 * W, maxY: 2 * H, restitution: 0.9, open: { bottom: true } })
      for (let t = 0; t < 4; t++) for (const h of DEFAULT_PANEL.holes) sim.addHole({ x: h.x + (t % 2) * W, y: h.y + Math.floor(t / 2) * H })
      const r = rng(7)
      for (let i = 0; i < 160; i++) {
        const t = Math.floor(i / 40)
        const j = i % 40
        const speed = 175 + (0.2 + 0.7 * r()) * 525
        const a = (r() - 0.5) * 0.8
        sim.addBall({ x: (t % 2) * W + 30 + 40 * (j % 10) + (r() - 0.5) * 16, y: Math.floor(t / 2) * H + H - 150 + 40 * Math.floor(j / 10) + (r() - 0.5) * 16, vx: speed * Math.sin(a), vy: -speed * Math.cos(a) })
      }
      return sim
    }
    expect(same(make, () => {}, 150, 1 / 60)).toBeGreaterThan(50)
  })

  it('light balls at rest and heavy ones at 1,000 px/s in closed walls of restitution 0: the projection pushes balls into moving ones it was not paired with, paired in the same tick', () => {
    // seeds whose scene makes such a pairing (4 of the first 40 seeds; 9 before a ball only a wall turned kept
    // its path to the wall, src/contacts/fixedWallTurn.ts, when these were 4, 27 and 30)
    for (const seed of [12, 24, 34]) {
      // by broadphase: the sweep's (0), the dense one's (1)
      const joins = [0, 0]
      const make = () => {
        const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', ROLLING_DECEL: 0, BALL_RESTITUTION: 0 }, { capacity: 128 })
        sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 0 })
        const r = rng(seed)
        for (let i = 0; i < 13; i++) {
          const a = r() * 2 * Math.PI
          sim.addBall({ x: 137 + (r() - 0.5) * 22, y: 372 + (r() - 0.5) * 22, vx: 1000 * Math.cos(a), vy: 1000 * Math.sin(a), mass: 1e-9 })
        }
        sim.step(10)
        for (let i = 0; i < 15; i++) {
          const a = r() * 2 * Math.PI
          sim.addBall({ x: 200 + (r() - 0.5) * 400, y: 264 + (r() - 0.5) * 400, vx: 1000 * Math.cos(a), vy: 1000 * Math.sin(a), radius: 7.7, mass: 1 })
        }
        return sim
      }
      const scene: Scene = (sim, step) => {
        if (step === 59) joins[sim.world.fixed!.broadphase]! += sim.world.fixed!.movingJoins
      }
      same(make, scene, 60, 1 / 60, `seed ${seed}`)
      // the same-tick pairing with moving balls ran, as often on both broadphases
      expect(joins[0], `seed ${seed}`).toBeGreaterThan(0)
      expect(joins[1], `seed ${seed}`).toBe(joins[0])
    }
  })

  it('a gas of mixed sizes and masses with one very fast ball (big balls), balls removed and added as it runs', () => {
    const make = () => {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', ROLLING_DECEL: 0, BALL_RESTITUTION: 0.9 }, { capacity: 512 })
      sim.setWalls({ minX: 0, minY: 0, maxX: 700, maxY: 700, restitution: 0.9 })
      const r = rng(11)
      for (let i = 0; i < 300; i++) {
        const a = r() * 2 * Math.PI
        const v = 150 + 200 * r()
        sim.addBall({ x: 20 + 35 * (i % 19) + r() * 4, y: 20 + 35 * Math.floor(i / 19) + r() * 4, vx: v * Math.cos(a), vy: v * Math.sin(a), radius: 8 + 6 * r(), mass: 0.2 + 4 * r() })
      }
      sim.addBall({ x: 350, y: 690, vx: 9000, vy: -7000, radius: 6 })
      // two big balls within each other's reach but further apart than one reach and half a cell
      sim.addBall({ x: 100, y: 620, vx: 12000, vy: 0, radius: 6 })
      sim.addBall({ x: 290, y: 620, vx: -12000, vy: 0, radius: 6 })
      return sim
    }
    const scene: Scene = (sim, step) => {
      if (step % 20 !== 10) return
      const ids = sim.balls()
      sim.removeBall(ids[(step * 7) % ids.length]!)
      sim.addBall({ x: 350, y: 350, vx: 2000, vy: 100 * (step % 3) })
    }
    expect(same(make, scene, 120, 1 / 120)).toBeGreaterThan(500)
  })

  it('packed ids far apart (sorted as numbers, not through a bitmap of the ids), and a crowd of more than 512 pairs a tick (sorted by radix)', () => {
    // ids are reused last out, first in: after 5,000 balls are removed, the gas's ids are 5,000 and down
    const sparse = () => {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', ROLLING_DECEL: 0 }, { capacity: 6000 })
      const gone: number[] = []
      for (let i = 0; i < 5000; i++) gone.push(sim.addBall({ x: 10 + (i % 100) * 30, y: 10 + Math.floor(i / 100) * 30 }))
      for (const e of gone) sim.removeBall(e)
      sim.step(1 / 60)
      sim.setWalls({ minX: 0, minY: 0, maxX: 240, maxY: 240, restitution: 1 })
      const r = rng(5)
      for (let i = 0; i < 40; i++) {
        const a = r() * 2 * Math.PI
        sim.addBall({ x: 20 + 32 * (i % 7) + r() * 4, y: 20 + 32 * Math.floor(i / 7) + r() * 4, vx: 500 * Math.cos(a), vy: 500 * Math.sin(a) })
      }
      expect(Math.min(...sim.balls())).toBeGreaterThan(4900)
      return sim
    }
    expect(same(sparse, () => {}, 90, 1 / 60)).toBeGreaterThan(100)
    const crowd = () => {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', ROLLING_DECEL: 0, BALL_RESTITUTION: 0.9 }, { capacity: 1024 })
      sim.setWalls({ minX: 0, minY: 0, maxX: 400, maxY: 400, restitution: 0.9 })
      const r = rng(9)
      for (let i = 0; i < 700; i++) {
        const a = r() * 2 * Math.PI
        sim.addBall({ x: 8 + 14.5 * (i % 27) + r() * 2, y: 8 + 14.5 * Math.floor(i / 27) + r() * 2, vx: 400 * Math.cos(a), vy: 400 * Math.sin(a), radius: 5 })
      }
      return sim
    }
    expect(same(crowd, () => {}, 20, 1 / 60)).toBeGreaterThan(500)
  })

  it('a pile at rest struck by a stream (resting balls looked up, then all candidates), with walls all round', () => {
    const make = () => {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed' }, { capacity: 512 })
      sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 0.5 })
      addPanel(sim)
      for (let i = 0; i < 90; i++) sim.addBall({ x: 12 + 22.5 * (i % 18), y: 468 - 22.5 * Math.floor(i / 18), vx: 0, vy: 0 })
      return sim
    }
    const scene: Scene = (sim, step) => {
      if (step < 100 && step % 4 === 0) sim.addBall({ x: 30 + ((step * 37) % 360), y: 60, vx: (step % 7) * 40 - 120, vy: 900 })
    }
    expect(same(make, scene, 240, 1 / 60)).toBeGreaterThan(50)
  })
})

describe('fixed-tick broadphases, random scenes', () => {
  it('rows of tiny balls struck end on at 1e5 px/s, square and slanting, a heavy striker, walls (capsules cut at the first ball met, src/contacts/fixedCut.ts, and lengthened): the same bits', () => {
    const make = () => {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 1, ROLLING_DECEL: 0, BALL_RADIUS: 0.5 })
      sim.setWalls({ minX: -20, minY: -20, maxX: 420, maxY: 60, restitution: 1 })
      for (let row = 0; row < 6; row++) for (let c = 0; c < 60; c++) sim.addBall({ x: 10 + c * (2 + (row % 3)), y: row * 7, vx: 0, vy: 0 })
      for (let row = 0; row < 6; row++) {
        const slant = row % 2 === 0 ? 0 : 0.3
        sim.addBall({ x: 8 - 2 * slant, y: row * 7 + slant, vx: 1e5, vy: slant * 5e3, mass: row === 5 ? 100 : 1 })
      }
      return sim
    }
    expect(same(make, () => {}, 30, 1 / 120, 'rows')).toBeGreaterThan(300)
  })

  it('a pile struck by heavier balls while balls of other sizes, tiny ones among them, move alone far off: the bounds that scale with the tick\'s balls count only the balls taking part (src/contacts/fixedActive.ts), so the same bits', () => {
    // the dense broadphase packs every candidate, the sweep only the balls that take part; when the bounds
    // on pairs a ball and the smallest radius read the packed candidates, 4 of these 40 seeds parted (40
    // of 400)
    let contacts = 0
    for (let seed = 1; seed <= 40; seed++) {
      const r = rng(seed)
      const pick = <T>(a: readonly T[]): T => a[Math.floor(r() * a.length)]!
      const specs: { x: number; y: number; vx: number; vy: number; radius?: number; mass?: number }[] = []
      const K = 20 + Math.floor(r() * 60)
      const rad = pick([3, 5, 10])
      const gap = pick([0, 0.1, 1])
      const cols = Math.ceil(Math.sqrt(K))
      for (let k = 0; k < K; k++) specs.push({ x: 200 + (k % cols) * (2 * rad + gap), y: 300 + Math.floor(k / cols) * (2 * rad + gap), vx: 0, vy: 0, radius: rad })
      const S = 1 + Math.floor(r() * 4)
      for (let k = 0; k < S; k++) specs.push({ x: 100, y: 300 + k * 3 * rad, vx: pick([1000, 3000, 8000]), vy: (r() - 0.5) * 200, radius: pick([rad, 2 * rad]), mass: pick([1, 10, 100]) })
      const M = Math.floor(r() * 120)
      for (let k = 0; k < M; k++) specs.push({ x: 1000 + (k % 20) * 45, y: 50 + Math.floor(k / 20) * 45, vx: (r() - 0.5) * 20, vy: (r() - 0.5) * 20, radius: pick([0.5, 1, 5, 10]) })
      const e = pick([0, 0.9, 1])
      const dt = pick([1 / 60, 1 / 120])
      const make = () => {
        const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: e, ROLLING_DECEL: 0 }, { capacity: 512 })
        sim.setWalls({ minX: 0, minY: 0, maxX: 2000, maxY: 1000, restitution: e })
        for (const b of specs) sim.addBall(b)
        return sim
      }
      contacts += same(make, () => {}, 40, dt, `seed ${seed}`)
    }
    expect(contacts).toBeGreaterThan(1000)
  })

  it('60 seeded scenes (radii 2–200 px, masses 1e-3…1e3, speeds to 6,000 px/s, holes, walls open or closed, balls put down on others, removed, set moving): the same bits', () => {
    let contacts = 0
    for (let seed = 1; seed <= 60; seed++) {
      const r = rng(1000 + seed)
      const pick = <T>(a: readonly T[]): T => a[Math.floor(r() * a.length)]!
      const e = pick([0, 0.5, 0.9, 1])
      const decel = pick([0, 300])
      const walls = r() < 0.7
      const open = { left: r() < 0.2, right: r() < 0.2, top: r() < 0.2, bottom: r() < 0.4 }
      // holes on a lattice 100 px apart (lip circles may not overlap)
      const holes = Array.from({ length: 16 }, (_, k) => ({ x: 60 + 100 * (k % 4), y: 80 + 110 * Math.floor(k / 4), radius: pick([undefined, 18, 40]) })).filter(() => r() < 0.3)
      const spec = () => {
        const radius = r() < 0.8 ? undefined : pick([2, 5, 30, 80, 200])
        const mass = r() < 0.7 ? undefined : pick([1e-3, 0.1, 10, 1e3])
        const speed = pick([0, 0, 100, 400, 1500, 6000])
        const a = r() * 2 * Math.PI
        return { x: r() * 420, y: r() * 480, vx: speed * Math.cos(a), vy: speed * Math.sin(a), radius, mass }
      }
      const first = Array.from({ length: 10 + Math.floor(r() * 60) }, spec)
      const later = Array.from({ length: 40 }, () => ({ at: Math.floor(r() * 60), kind: pick(['add', 'add', 'remove', 'kick']), ball: spec(), k: Math.floor(r() * 1000) }))
      const make = () => {
        const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: e, ROLLING_DECEL: decel }, { capacity: 256 })
        if (walls) sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: e, open })
        for (const h of holes) sim.addHole(h)
        for (const b of first) sim.addBall(b)
        return sim
      }
      const scene: Scene = (sim, step) => {
        for (const op of later) {
          if (op.at !== step) continue
          const ids = sim.balls()
          if (op.kind === 'add') sim.addBall(op.ball)
          else if (ids.length === 0) continue
          else if (op.kind === 'remove') sim.removeBall(ids[op.k % ids.length]!)
          else {
            const b = ids[op.k % ids.length]!
            const mode = sim.ballState(b).mode
            if (mode === 'rolling' || mode === 'rimRoll' || mode === 'resting') sim.setBallVelocity(b, op.ball.vx, op.ball.vy)
          }
        }
      }
      contacts += same(make, scene, 90, pick([1 / 120, 1 / 60, 1 / 45]), `seed ${seed}`)
    }
    expect(contacts).toBeGreaterThan(1000)
  })
})
