// Scaling: ns per ball-step and heap bytes per ball for N = 1k, 10k, 100k, 1M balls over 25 and over
// 10,000 holes (same hole density: holes 400 px apart, balls spread over the holes' field), beside a plain
// typed-array loop that only moves the same balls, measured in the same run with tinybench: each row is
// ROUNDS rounds of (this module on a fresh scene, the plain loop on fresh arrays), median of the rounds.
// Writes docs/results/scale.json and docs/figures/scale.svg (or under --out DIR). Prints figures; asserts
// nothing.
//
//   npm run bench:scale                 npm run bench:scale -- --max 100000   (skip the 1M rows)
import { execFileSync } from 'node:child_process'
import { fileURLToPath } from 'node:url'
import { createBallPhysics, type BallPhysics } from '../src/index'
import { scaleFigure, type ScaleRow } from './charts'
import { DT, argValue, collectGarbage, median, medianStepMs, plainStep, random, writeFigure, writeResult } from './lib'

const STEPS = 60
const ROUNDS = 3
const DECEL = 20
const MAX_N = Number(argValue('--max') ?? 1_000_000)
const SIZES = [1_000, 10_000, 100_000, 1_000_000].filter((n) => n <= MAX_N)
const HOLES = [25, 10_000]


function build(n: number, holes: number): BallPhysics {
  const side = Math.round(Math.sqrt(holes))
  const sim = createBallPhysics({ ROLLING_DECEL: DECEL }, { capacity: n + holes + 64 })
  for (let i = 0; i < side; i++) for (let j = 0; j < side; j++) sim.addHole({ x: 200 + 400 * i, y: 200 + 400 * j })
  const r = random(7)
  const field = side * 400
  for (let i = 0; i < n; i++) {
    const a = r() * 2 * Math.PI
    const v = 150 + 200 * r()
    sim.addBall({ x: r() * field, y: r() * field, vx: v * Math.cos(a), vy: v * Math.sin(a) })
  }
  return sim
}

/** The limit: the same balls moved by a bare loop over four Float64Array columns, with the deceleration. */
function plain(n: number) {
  const r = random(7)
  const x = new Float64Array(n)
  const y = new Float64Array(n)
  const vx = new Float64Array(n)
  const vy = new Float64Array(n)
  for (let i = 0; i < n; i++) {
    const a = r() * 2 * Math.PI
    const v = 150 + 200 * r()
    x[i] = r() * 2000
    y[i] = r() * 2000
    vx[i] = v * Math.cos(a)
    vy[i] = v * Math.sin(a)
  }
  return () => plainStep(x, y, vx, vy, n, DECEL)
}


/**
 * Times STEPS steps of a fresh scene: ns per ball-step of the median step. Just before, `warm` runs the
 * same code untimed on a throwaway scene, so that every round is measured warm (the first round after a
 * change of hole count otherwise paid for re-optimisation).
 */
async function nsPerBallStep(n: number, make: () => () => void, warm: () => () => void): Promise<number> {
  {
    const throwaway = warm()
    for (let i = 0; i < 30; i++) throwaway()
  }
  const step = make()
  collectGarbage()
  const ms = await medianStepMs(step, STEPS)
  return (ms * 1e6) / n
}

function oursStep(n: number, holes: number): () => void {
  const sim = build(n, holes)
  return () => {
    sim.step(DT)
    sim.world.events.count = 0
  }
}

/** Heap (JS objects and typed arrays) per ball of a world with n balls, measured in a fresh Node process. */
function heapPerBall(n: number, holes: number): number {
  const out = execFileSync(process.execPath, ['--expose-gc', fileURLToPath(import.meta.url), '--heap', String(n), String(holes)], {
    encoding: 'utf8',
  })
  return Number(out.trim().split('\n').at(-1))
}

if (process.argv.includes('--heap')) {
  const i = process.argv.indexOf('--heap')
  const n = Number(process.argv[i + 1])
  const holes = Number(process.argv[i + 2])
  const gc = (globalThis as { gc?: () => void }).gc!
  gc()
  gc()
  const m0 = process.memoryUsage()
  const sim = build(n, holes)
  sim.step(DT)
  gc()
  gc()
  const m1 = process.memoryUsage()
  if (sim.balls().length !== n) throw new Error('scene lost balls')
  console.log((m1.heapUsed - m0.heapUsed + (m1.arrayBuffers - m0.arrayBuffers)) / n)
  process.exit(0)
}

// warm the code up once, on mid-size scenes over both hole counts (a scan of 25 holes, a grid of 10,000),
// before any row is measured (the plain loop too: cold, its first row measured the interpreter)
for (const holes of HOLES) {
  const sim = build(10_000, holes)
  const base = plain(10_000)
  for (let i = 0; i < 200; i++) {
    sim.step(DT)
    sim.world.events.count = 0
    base()
  }
}

const rows: ScaleRow[] = []
for (const holes of HOLES) {
  for (const n of SIZES) {
    const oursRuns: number[] = []
    const baseRuns: number[] = []
    for (let round = 0; round < ROUNDS; round++) {
      const w = Math.min(n, 10_000)
      oursRuns.push(await nsPerBallStep(n, () => oursStep(n, holes), () => oursStep(w, holes)))
      baseRuns.push(await nsPerBallStep(n, () => plain(n), () => plain(w)))
    }
    const ours = median(oursRuns)
    const base = median(baseRuns)
    const heap = heapPerBall(n, holes)
    rows.push({ balls: n, holes, ours, plain: base, ratio: ours / base, heapBytesPerBall: heap })
    console.log(
      `${String(n).padStart(9)} balls ${String(holes).padStart(6)} holes   ours ${ours.toFixed(2).padStart(6)} ns   plain ${base.toFixed(2).padStart(5)} ns   ${(ours / base).toFixed(2)}×   heap ${heap.toFixed(0)} B/ball`,
    )
  }
}

const json = writeResult('scale', {
  dt: DT,
  steps: STEPS,
  rounds: ROUNDS,
  rollingDecel: DECEL,
  timing: 'tinybench: median step of STEPS steps of a fresh scene; median of ROUNDS rounds, this module and the plain loop interleaved',
  rows,
})

const svg = await writeFigure('scale', scaleFigure(rows, STEPS, ROUNDS))
console.log(`wrote ${json} and ${svg}`)
