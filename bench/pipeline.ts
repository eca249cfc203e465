// Pipeline cost per ball-step against two loops over the same balls, each step timed by tinybench (median
// step of a run, median of the runs): the bare loop x += vx·dt, y += vy·dt (the limit: nothing cheaper moves
// balls), and a plain loop that also applies the rolling deceleration (a square root a ball). Three scenes:
// the open field (balls at 300–700 px/s with the design's deceleration), the same field with slow balls
// (30–70 px/s) and no deceleration (the sparse scene), and the default panel (every ball thrown at once). Prints figures and writes
// docs/results/pipeline.json; asserts nothing (machines here are shared and noisy: compare the ratio
// measured side by side in this run, not absolute times across runs).
//
//   npm run bench:pipeline   (N = 100,000)       npm run bench:pipeline -- 20000   (another N)
import { DEFAULT_PANEL, addPanel, createBallPhysics, type BallPhysics } from '../src/index'
import { DT, bareStep, collectGarbage, median, medianStepMs, plainStep, writeResult } from './lib'

const N = Number(process.argv.slice(2).find((a) => /^\d+$/.test(a)) ?? 100_000)
const WARMUP = 30
const STEPS = 120
const REPEATS = 5

function rand(seed: number) {
  let a = seed >>> 0
  return () => {
    a = (a + 0x6d2b79f5) >>> 0
    let t = Math.imul(a ^ (a >>> 15), a | 1)
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61)
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296
  }
}

interface Ball0 {
  x: Float64Array
  y: Float64Array
  vx: Float64Array
  vy: Float64Array
}

/**
 * Open field: 25 holes on a 5 × 5 grid 400 px apart, balls scattered among them (events are sparse) at
 * 300–700 px/s, or `slow`: at 30–70 px/s (events sparser still).
 */
function openField(n: number, slow = false): Ball0 {
  const r = rand(1)
  const b = { x: new Float64Array(n), y: new Float64Array(n), vx: new Float64Array(n), vy: new Float64Array(n) }
  for (let i = 0; i < n; i++) {
    const speed = slow ? 30 + 40 * r() : 300 + 400 * r()
    const ang = r() * 2 * Math.PI
    b.x[i] = r() * 2000
    b.y[i] = r() * 2000
    b.vx[i] = speed * Math.cos(ang)
    b.vy[i] = speed * Math.sin(ang)
  }
  return b
}

function openFieldSim(init: Ball0, n: number, decel?: number): BallPhysics {
  const sim = createBallPhysics(decel === undefined ? {} : { ROLLING_DECEL: decel }, { capacity: n + 64 })
  for (let i = 0; i < 5; i++) for (let j = 0; j < 5; j++) sim.addHole({ x: 200 + 400 * i, y: 200 + 400 * j })
  for (let i = 0; i < n; i++) sim.addBall({ x: init.x[i]!, y: init.y[i]!, vx: init.vx[i]!, vy: init.vy[i]! })
  return sim
}

/** The default panel: every ball thrown from the launch line at once (events are dense). */
function panelSim(n: number): BallPhysics {
  const r = rand(2)
  const sim = createBallPhysics({}, { capacity: n + 64 })
  addPanel(sim)
  for (let i = 0; i < n; i++) {
    sim.throwBall({ x: DEFAULT_PANEL.launch.x + (r() - 0.5) * 300, y: DEFAULT_PANEL.launch.y, power: 0.3 + 0.7 * r(), angle: (r() - 0.5) * 1.2 })
  }
  return sim
}

/** One step of the same balls with the same rolling deceleration, nothing else. */
function plainLoop(b: Ball0, n: number, decel: number): () => void {
  return () => plainStep(b.x, b.y, b.vx, b.vy, n, decel)
}

/** The limit: the same balls moved on straight lines, two multiply-adds a ball. */
function bareLoop(b: Ball0, n: number): () => void {
  return () => bareStep(b.x, b.y, b.vx, b.vy, n)
}


function simStep(sim: BallPhysics): () => void {
  return () => {
    sim.step(DT)
    sim.world.events.count = 0 // a game drains each frame; dropping the buffer here keeps event objects out of the timing
  }
}

/** Runs WARMUP steps untimed, then STEPS timed ones: ns per ball-step of the median step. */
async function nsPerBallStep(step: () => void): Promise<number> {
  for (let i = 0; i < WARMUP; i++) step()
  collectGarbage()
  return ((await medianStepMs(step, STEPS)) * 1e6) / N
}

const decel = createBallPhysics().config.ROLLING_DECEL
const bare: number[] = []
const plain: number[] = []
const open: number[] = []
const slow: number[] = []
const panel: number[] = []
let moving = 0
for (let rep = 0; rep < REPEATS; rep++) {
  bare.push(await nsPerBallStep(bareLoop(openField(N), N)))
  plain.push(await nsPerBallStep(plainLoop(openField(N), N, decel)))

  const sim = openFieldSim(openField(N), N)
  open.push(await nsPerBallStep(simStep(sim)))
  moving = sim.balls().filter((b) => sim.world.Ball.mode[b]! < 2).length
  // the sparse scene: slow balls, no rolling deceleration
  slow.push(await nsPerBallStep(simStep(openFieldSim(openField(N, true), N, 0))))

  panel.push(await nsPerBallStep(simStep(panelSim(N))))
}

const result = {
  balls: N,
  holes: 25,
  dt: DT,
  steps: STEPS,
  warmupSteps: WARMUP,
  repeats: REPEATS,
  timing: 'tinybench: median step of each run of STEPS steps, median of REPEATS runs',
  nsPerBallStep: { bareLoop: median(bare), plainLoop: median(plain), openField: median(open), openFieldSlow: median(slow), panel: median(panel) },
  ratioToBare: { openField: median(open) / median(bare), openFieldSlow: median(slow) / median(bare), panel: median(panel) / median(bare) },
  ratioToPlain: { openField: median(open) / median(plain), openFieldSlow: median(slow) / median(plain), panel: median(panel) / median(plain) },
  openFieldBallsStillMovingAfterRun: moving,
}
console.log(`pipeline benchmark, ${N} balls, 25 holes, dt = 1/120 s, median step of ${STEPS}, median of ${REPEATS} runs`)
console.log(`  bare loop (x += vx·dt, y += vy·dt)    ${result.nsPerBallStep.bareLoop.toFixed(2)} ns/ball-step`)
console.log(`  plain loop (with the deceleration)    ${result.nsPerBallStep.plainLoop.toFixed(2)} ns/ball-step`)
console.log(`  full pipeline, open field (sparse)    ${result.nsPerBallStep.openField.toFixed(2)} ns/ball-step   ${result.ratioToBare.openField.toFixed(2)}× bare   ${result.ratioToPlain.openField.toFixed(2)}× plain`)
console.log(`  the same, slow balls, no deceleration ${result.nsPerBallStep.openFieldSlow.toFixed(2)} ns/ball-step   ${result.ratioToBare.openFieldSlow.toFixed(2)}× bare   ${result.ratioToPlain.openFieldSlow.toFixed(2)}× plain`)
console.log(`  full pipeline, default panel (dense)  ${result.nsPerBallStep.panel.toFixed(2)} ns/ball-step   ${result.ratioToBare.panel.toFixed(2)}× bare   ${result.ratioToPlain.panel.toFixed(2)}× plain`)
console.log(`wrote ${writeResult('pipeline', result)}`)
