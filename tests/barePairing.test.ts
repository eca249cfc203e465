// The contacts benchmark's denominator (bench/barePairing.ts): its grid finds exactly the pairs within reach
// that a test of every pair finds, on frames where the grid's cells are fine, coarsened, or the balls sit
// on cell borders.
import { describe, expect, it } from 'vitest'
import fc from 'fast-check'
import { pairFrame, recordFrames, type Frame } from '../bench/barePairing'
import { skinPerBall, skinRebuild, type SkinList } from '../bench/skinPairing'
import { oursScene, panel } from '../bench/contactScenes'
import { TOUCH_GAP } from '../src/config/tolerances'
import { DEFAULT_PANEL, createBallPhysics } from '../src/index'

function frameOf(balls: readonly { x: number; y: number; vx: number; vy: number; r: number }[]): Frame {
  const n = balls.length
  const f: Frame = { n, id: new Int32Array(n), x: new Float64Array(n), y: new Float64Array(n), vx: new Float64Array(n), vy: new Float64Array(n), r: new Float64Array(n) }
  balls.forEach((b, i) => {
    f.id[i] = i + 1
    f.x[i] = b.x
    f.y[i] = b.y
    f.vx[i] = b.vx
    f.vy[i] = b.vy
    f.r[i] = b.r
  })
  return f
}

function everyPair(f: Frame, tick: number): number {
  const reach = (i: number) => f.r[i]! + Math.sqrt(f.vx[i]! * f.vx[i]! + f.vy[i]! * f.vy[i]!) * tick + TOUCH_GAP
  let n = 0
  for (let i = 0; i < f.n; i++) {
    for (let j = i + 1; j < f.n; j++) {
      const dx = f.x[j]! - f.x[i]!
      const dy = f.y[j]! - f.y[i]!
      const s = reach(i) + reach(j)
      if (dx * dx + dy * dy < s * s) n++
    }
  }
  return n
}

describe('bare pairing loop (contacts benchmark)', () => {
  it('finds the pairs a test of every pair finds', () => {
    const ball = fc.record({
      x: fc.double({ min: -2000, max: 2000, noNaN: true }),
      y: fc.double({ min: -2000, max: 2000, noNaN: true }),
      vx: fc.double({ min: -2000, max: 2000, noNaN: true }),
      vy: fc.double({ min: -2000, max: 2000, noNaN: true }),
      r: fc.double({ min: 0.5, max: 40, noNaN: true }),
    })
    // a cluster (fine cells), a spread (cells coarsened to 4n + 64), and balls on a lattice (cell borders)
    const cluster = fc.array(ball.map((b) => ({ ...b, x: b.x / 40, y: b.y / 40 })), { minLength: 2, maxLength: 120 })
    const spread = fc.array(ball.map((b) => ({ ...b, x: b.x * 50, r: b.r / 10 })), { minLength: 2, maxLength: 60 })
    const lattice = fc.array(fc.tuple(fc.integer({ min: 0, max: 12 }), fc.integer({ min: 0, max: 12 }), fc.double({ min: 0, max: 2400, noNaN: true })), { minLength: 2, maxLength: 100 })
    fc.assert(
      fc.property(fc.oneof(cluster, spread, lattice.map((a) => a.map(([i, j, v]) => ({ x: 22 * i, y: 22 * j, vx: v, vy: 0, r: 11 })))), (balls) => {
        const f = frameOf(balls)
        expect(pairFrame(f, 1 / 120)).toBe(everyPair(f, 1 / 120))
      }),
      { numRuns: 300, seed: 7 },
    )
  })

  it('pairs balls across every neighbouring cell: beside, above, below and on both diagonals', () => {
    // a ball at the centre of a 3 × 3 block of cells and one in each of the eight cells around it, each
    // within reach of the centre alone (the cell is twice the largest reach: 2 · 12 = 24 px here)
    const balls = [{ x: 36, y: 36, vx: 0, vy: 0, r: 12 }]
    for (const [i, j] of [[-1, -1], [0, -1], [1, -1], [-1, 0], [1, 0], [-1, 1], [0, 1], [1, 1]] as const) {
      balls.push({ x: 36 + 14 * i, y: 36 + 14 * j, vx: 0, vy: 0, r: 12 })
    }
    // corners of the field, so the grid's box is 72 px wide: cells 24 px, the centre cell [24, 48)
    balls.push({ x: 0, y: 0, vx: 0, vy: 0, r: 1e-3 }, { x: 72, y: 72, vx: 0, vy: 0, r: 1e-3 })
    const f = frameOf(balls)
    expect(everyPair(f, 1 / 120)).toBeGreaterThanOrEqual(8)
    expect(pairFrame(f, 1 / 120)).toBe(everyPair(f, 1 / 120))
  })

  it('records the moving balls of a run, step by step', () => {
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed' })
    for (let i = 0; i < 30; i++) sim.throwBall({ x: DEFAULT_PANEL.launch.x + 30 * (i % 6) - 75, y: DEFAULT_PANEL.launch.y - 30 * Math.floor(i / 6), power: 0.3 + 0.02 * i, angle: 0 })
    const frames = recordFrames(sim, 60, 1 / 120)
    expect(frames).toHaveLength(60)
    expect(frames[0]!.n).toBe(30)
    const last = frames[59]!
    expect(last.n).toBeLessThanOrEqual(30)
    expect(everyPair(frames[0]!, 1 / 120)).toBe(pairFrame(frames[0]!, 1 / 120))
  })

  // the neighbour lists set beside the grid (bench/skinPairing.ts) must count its pairs at every frame
  const lists: [string, (K: number) => SkinList][] = [
    ['rebuild', (K) => skinRebuild(K, 1 / 120)],
    ['per ball', (K) => skinPerBall(K, 1 / 120)],
    ['per ball, fine cells', (K) => skinPerBall(K, 1 / 120, 2)],
  ]

  it('neighbour lists count the pairs the grid counts at every frame of a recorded panel burst', () => {
    const frames = recordFrames(oursScene(panel(200), 'fixed', 1 / 120), 90, 1 / 120)
    const pairs = frames.map((f) => pairFrame(f, 1 / 120))
    expect(pairs.reduce((a, b) => a + b, 0)).toBeGreaterThan(100)
    for (const [name, make] of lists) {
      for (const K of [1, 3, 8]) {
        const L = make(K)
        expect(frames.map((f) => L.frame(f)), `${name}, K ${K}`).toEqual(pairs)
        // a skin of K ticks is renewed at most every tick and, on average, far less often than that
        expect(L.entries(), `${name}, K ${K}`).toBeGreaterThanOrEqual(frames[0]!.n)
      }
    }
  })

  it('neighbour lists count the pairs the grid counts when balls jump, turn, leave and come back', () => {
    // balls on random walks: each tick a ball may take a kick (up to 3,000 px/s), jump (a teleport the
    // list sees only as travel), or be away (captured or resting) and come back later
    const walk = fc.record({
      n: fc.integer({ min: 2, max: 30 }),
      ticks: fc.integer({ min: 2, max: 25 }),
      seed: fc.integer({ min: 1, max: 2 ** 31 - 2 }),
      K: fc.integer({ min: 1, max: 6 }),
    })
    fc.assert(
      fc.property(walk, ({ n, ticks, seed, K }) => {
        let s = seed
        const rnd = () => ((s = (s * 16807) % 2147483647) - 1) / 2147483646
        const x = Float64Array.from({ length: n }, () => 300 * rnd())
        const y = Float64Array.from({ length: n }, () => 300 * rnd())
        const vx = Float64Array.from({ length: n }, () => 1200 * (rnd() - 0.5))
        const vy = Float64Array.from({ length: n }, () => 1200 * (rnd() - 0.5))
        const r = Float64Array.from({ length: n }, () => 2 + 14 * rnd())
        const made = lists.map(([, make]) => make(K))
        for (let t = 0; t < ticks; t++) {
          const here = []
          for (let i = 0; i < n; i++) {
            const u = rnd()
            if (u < 0.1) {
              vx[i] = 6000 * (rnd() - 0.5)
              vy[i] = 6000 * (rnd() - 0.5)
            } else if (u < 0.15) {
              x[i] = 300 * rnd()
              y[i] = 300 * rnd()
            }
            x[i]! += vx[i]! / 120
            y[i]! += vy[i]! / 120
            if (rnd() > 0.15) here.push({ x: x[i]!, y: y[i]!, vx: vx[i]!, vy: vy[i]!, r: r[i]!, id: 3 * i + 1 })
          }
          const f = frameOf(here)
          here.forEach((b, k) => (f.id[k] = b.id))
          const want = everyPair(f, 1 / 120)
          for (const L of made) expect(L.frame(f)).toBe(want)
        }
      }),
      { numRuns: 200, seed: 11 },
    )
  })
})
