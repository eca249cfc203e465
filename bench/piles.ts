// Contacts under arcade abuse: the worst step, for both contact methods.
//   burst: 10,000 balls thrown from the default panel's launch point in one frame (walls, bottom open);
//          the launcher holds each until its spot is clear; 4 s at 60 Hz.
//   pile:  a 100 × 100 pile of resting balls (22.5 px apart) in the corner of a 3,000 px box, pressed by a
//          stream of fast balls (8 a step, put down 60–360 px off the pile, at 1,500 px/s toward the
//          corner), with restitution 0 and 1
//          (balls and walls); 2 s at 60 Hz.
// Prints and writes the mean and worst step (ms), the deepest overlap between balls on the panel at the
// end and at any step (px), the longest time any pair stayed more than 1e-3 px deep (s, seen at the steps'
// ends: the bound is none after 0.5 s), and the contacts per step. A method whose step takes longer than STEP_LIMIT_MS stops its run
// early (the bound on a step's work holds, but a run of such steps would take minutes); the row says so.
// Writes docs/results/piles.json.
//
//   npm run bench:piles
import { DEFAULT_PANEL, addPanel, createBallPhysics, type BallPhysics } from '../src/index'
import { BallMode } from '../components/Ball'
import type { PileRow } from './charts'
import { argValue, cellGrid, cellKey, random, writeResult } from './lib'

const DT = 1 / 60
const STEP_LIMIT_MS = 5_000
const BALLS = Number(argValue('--balls') ?? 10_000)


/** How far apart two ball ids are in a pair's key (ids stay below it). */
const PAIR_KEY = 1 << 24

/**
 * Deepest overlap of two balls on the panel, px, through a grid of cells one diameter wide; the pairs more
 * than OVERLAP_PX deep go into `over` (keys a·PAIR_KEY + b, a < b) when it is given.
 */
function deepestOverlap(sim: BallPhysics, over?: Set<number>): number {
  const B = sim.world.Ball
  const ids = sim.balls().filter((b) => B.mode[b] === BallMode.Rolling || B.mode[b] === BallMode.Resting || B.mode[b] === BallMode.RimRoll)
  let rMax = 0
  for (const b of ids) rMax = Math.max(rMax, B.radius[b]!)
  const cell = 2 * rMax
  const grid = cellGrid(ids, B.x, B.y, cell)
  let worst = 0
  for (const b of ids) {
    const cx = Math.floor(B.x[b]! / cell)
    const cy = Math.floor(B.y[b]! / cell)
    for (let dx = -1; dx <= 1; dx++) {
      for (let dy = -1; dy <= 1; dy++) {
        for (const o of grid.get(cellKey(cx + dx, cy + dy)) ?? []) {
          if (o <= b) continue
          const depth = B.radius[b]! + B.radius[o]! - Math.hypot(B.x[b]! - B.x[o]!, B.y[b]! - B.y[o]!)
          worst = Math.max(worst, depth)
          if (over && depth > OVERLAP_PX) over.add(b * PAIR_KEY + o)
        }
      }
    }
  }
  return worst
}

/** The depth the bound allows after 0.5 s: a pair deeper than this is counted, and for how long. */
const OVERLAP_PX = 1e-3

function contactsOf(sim: BallPhysics): number {
  return sim.world.collide?.contacts ?? sim.world.fixed?.contacts ?? 0
}

function runScene(scene: string, method: string, sim: BallPhysics, steps: number, each?: (step: number) => void): PileRow {
  let worst = 0
  let total = 0
  let done = 0
  let early = false
  const c0 = contactsOf(sim)
  // after each step (outside its time): the pairs more than OVERLAP_PX deep, and the step each began at
  const since = new Map<number, number>()
  let deepestAny = 0
  let longest = 0
  for (let s = 0; s < steps; s++) {
    each?.(s)
    const t0 = performance.now()
    sim.step(DT)
    const ms = performance.now() - t0
    sim.drainEvents()
    total += ms
    worst = Math.max(worst, ms)
    done++
    const over = new Set<number>()
    deepestAny = Math.max(deepestAny, deepestOverlap(sim, over))
    for (const key of since.keys()) if (!over.has(key)) since.delete(key)
    for (const key of over) {
      if (!since.has(key)) since.set(key, s)
      longest = Math.max(longest, s + 1 - since.get(key)!)
    }
    if (ms > STEP_LIMIT_MS) {
      early = true
      break
    }
  }
  const row: PileRow = {
    scene,
    method,
    steps: done,
    stoppedEarly: early,
    meanStepMs: total / done,
    worstStepMs: worst,
    deepestOverlapPx: deepestOverlap(sim),
    deepestAnyStepPx: deepestAny,
    longestOverS: longest * DT,
    contactsPerStep: (contactsOf(sim) - c0) / done,
  }
  console.log(
    `${scene.padEnd(12)} ${method.padEnd(6)} steps ${String(done).padStart(4)}${early ? ' (stopped: a step over 5 s)' : ''}  mean ${row.meanStepMs.toFixed(1).padStart(7)} ms  worst ${row.worstStepMs.toFixed(1).padStart(7)} ms  ` +
      `deepest overlap ${row.deepestOverlapPx.toExponential(1)} px (at any step ${row.deepestAnyStepPx.toExponential(1)}; a pair over ${OVERLAP_PX} px for ${row.longestOverS.toFixed(3)} s at most)  contacts/step ${row.contactsPerStep.toFixed(0)}`,
  )
  return row
}

function burst(mode: 'on' | 'fixed'): PileRow {
  const sim = createBallPhysics({ BALL_COLLISIONS: mode }, { capacity: BALLS + 64 })
  addPanel(sim)
  sim.setWalls({ minX: 0, minY: 0, maxX: DEFAULT_PANEL.width, maxY: DEFAULT_PANEL.height, open: { bottom: true } })
  const r = random(4242)
  for (let i = 0; i < BALLS; i++) sim.throwBall({ x: DEFAULT_PANEL.launch.x, y: DEFAULT_PANEL.launch.y, power: 0.3 + 0.7 * r(), angle: (r() - 0.5) * 1.2 })
  return runScene(`burst ${BALLS}`, mode === 'on' ? 'exact' : 'fixed', sim, 240)
}

function pile(mode: 'on' | 'fixed', e: number): PileRow {
  const side = Math.round(Math.sqrt(BALLS))
  const sim = createBallPhysics({ BALL_COLLISIONS: mode, BALL_RESTITUTION: e }, { capacity: BALLS + 1000 })
  const box = 3000
  sim.setWalls({ minX: 0, minY: 0, maxX: box, maxY: box, restitution: e })
  for (let i = 0; i < side; i++) for (let j = 0; j < side; j++) sim.addBall({ x: 12 + 22.5 * i, y: 12 + 22.5 * j, vx: 0, vy: 0 })
  const r = random(99)
  const speed = 1500
  const edge = 22.5 * side
  return runScene(`pile e=${e}`, mode === 'on' ? 'exact' : 'fixed', sim, 120, () => {
    for (let k = 0; k < 8; k++) {
      const x = edge + 60 + 300 * r()
      const y = edge + 60 + 300 * r()
      const d = Math.hypot(x, y)
      sim.addBall({ x, y, vx: (-speed * x) / d, vy: (-speed * y) / d })
    }
  })
}

const rows: PileRow[] = []
for (const mode of ['fixed', 'on'] as const) {
  rows.push(burst(mode))
  rows.push(pile(mode, 0))
  rows.push(pile(mode, 1))
}
const json = writeResult('piles', {
  dt: DT,
  balls: BALLS,
  stepLimitMs: STEP_LIMIT_MS,
  timing: 'performance.now() around each step, one run',
  overlap: `deepestOverlapPx: at the end; deepestAnyStepPx: at any step's end; longestOverS: the longest run of steps' ends at which one pair stayed more than ${OVERLAP_PX} px deep, in s (the overlap check is outside the steps' times)`,
  rows,
})
console.log(`wrote ${json}`)
