// Resting balls cost nothing: 1,000 balls rolling over the 25-hole field, alone and beside 1,000,000 resting
// balls, with ball-ball contacts off and on; ns per step of each, measured side by side in one run (rounds
// interleaved, median of the rounds), and the ratio.
//
// The resting balls sit on a square lattice of pitch 200 px centred on the moving balls' field, so about
// a hundred of them lie among the moving balls: with contacts on, moving balls strike some, and a struck
// ball wakes and rolls (it is then a moving ball and is paid for as one). A third variant keeps only the
// resting balls within reach of the moving ones during the run (within 400 px of the field: 196 balls), so
// the cost of the strikes can be told from the cost of the million: ratio million / within reach.
//
// Writes docs/results/resting.json (or under --out DIR). Prints figures; asserts nothing.
//
//   npm run bench:resting            npm run bench:resting -- --resting 100000   (fewer resting balls)
import { BallMode } from '../src/ecs'
import { createBallPhysics, type BallPhysics } from '../src/index'
import { DT, argValue, collectGarbage, median, medianStepMs, random, writeResult } from './lib'

const MOVING = 1000
const RESTING = Number(argValue('--resting') ?? 1_000_000)
const STEPS = 120
const ROUNDS = 5
const DECEL = 20
const RESTITUTION = 0.9
const PITCH = 200
/** the moving balls' field: [0, FIELD]², 25 holes 400 px apart */
const FIELD = 2000
/** resting balls within this distance of the field can be reached during the run (speeds ≤ 350 px/s, 1 s) */
const REACH = 400
const BALL_R = 11


/** Lattice points (100 + 200·i, 100 + 200·j) round the field's centre, `count` of them, row by row. */
function lattice(count: number): Float64Array {
  const side = Math.ceil(Math.sqrt(count))
  // the field's centre, 1000, lies between lattice columns 4 and 5
  const first = 5 - Math.floor(side / 2)
  const xy = new Float64Array(2 * count)
  for (let k = 0; k < count; k++) {
    xy[2 * k] = 100 + PITCH * (first + (k % side))
    xy[2 * k + 1] = 100 + PITCH * (first + Math.floor(k / side))
  }
  return xy
}

const inReach = (x: number, y: number) => x > -REACH && x < FIELD + REACH && y > -REACH && y < FIELD + REACH

const all = lattice(RESTING)
const near: number[] = []
for (let k = 0; k < RESTING; k++) if (inReach(all[2 * k]!, all[2 * k + 1]!)) near.push(all[2 * k]!, all[2 * k + 1]!)
const nearXY = Float64Array.from(near)

/** The moving balls: 150–350 px/s in random directions, put down clear of each other and of the lattice. */
const moving: { x: number; y: number; vx: number; vy: number }[] = []
{
  const r = random(7)
  const clear = (2 * BALL_R + 1) ** 2
  while (moving.length < MOVING) {
    const a = r() * 2 * Math.PI
    const v = 150 + 200 * r()
    const x = r() * FIELD
    const y = r() * FIELD
    if (moving.some((b) => (b.x - x) ** 2 + (b.y - y) ** 2 < clear)) continue
    let hit = false
    for (let k = 0; k < nearXY.length && !hit; k += 2) hit = (nearXY[k]! - x) ** 2 + (nearXY[k + 1]! - y) ** 2 < clear
    if (hit) continue
    moving.push({ x, y, vx: v * Math.cos(a), vy: v * Math.sin(a) })
  }
}

interface Scene {
  sim: BallPhysics
  /** ids of the resting balls */
  first: number
  last: number
}

/** Holes, then the resting balls (put down at rest: one tiny step settles them), then the moving balls. */
function build(resting: Float64Array, contacts: boolean): Scene {
  const n = resting.length / 2
  const sim = createBallPhysics(
    { ROLLING_DECEL: DECEL, BALL_COLLISIONS: contacts ? 'on' : 'off', BALL_RESTITUTION: RESTITUTION },
    { capacity: n + MOVING + 64 },
  )
  for (let i = 0; i < 5; i++) for (let j = 0; j < 5; j++) sim.addHole({ x: 200 + 400 * i, y: 200 + 400 * j })
  let first = 0
  let last = -1
  for (let k = 0; k < n; k++) {
    const id = sim.addBall({ x: resting[2 * k]!, y: resting[2 * k + 1]!, vx: 0, vy: 0 })
    if (k === 0) first = id
    last = id
  }
  sim.step(1e-6)
  sim.world.events.count = 0
  if (sim.world.moving.count !== 0) throw new Error('resting balls did not settle')
  for (const b of moving) sim.addBall(b)
  return { sim, first, last }
}

interface Measured {
  nsPerStep: number
  /** ball-ball contacts during the measured steps */
  contacts: number
  /** resting balls that were no longer resting after the run (struck: rolling, or captured since) */
  woken: number
  movingAtEnd: number
}

async function measure(resting: Float64Array, contacts: boolean): Promise<Measured> {
  let sc: Scene | null = build(resting, contacts)
  collectGarbage()
  const { sim } = sc
  const c0 = sim.world.collide?.contacts ?? 0
  const ms = await medianStepMs(() => {
    sim.step(DT)
    sim.world.events.count = 0
  }, STEPS)
  let woken = 0
  for (let id = sc.first; id <= sc.last; id++) if (sim.world.Ball.mode[id] !== BallMode.Resting) woken++
  const out = { nsPerStep: ms * 1e6, contacts: (sim.world.collide?.contacts ?? 0) - c0, woken, movingAtEnd: sim.world.moving.count }
  sc = null
  return out
}

// warm the code up on small scenes (both modes, with and without resting balls) before any measurement
for (const contacts of [false, true]) {
  for (const resting of [new Float64Array(0), nearXY]) {
    const { sim } = build(resting, contacts)
    for (let i = 0; i < 60; i++) {
      sim.step(DT)
      sim.world.events.count = 0
    }
  }
}

const VARIANTS = [
  ['alone', new Float64Array(0)],
  ['inReach', nearXY],
  ['all', all],
] as const
type Variant = (typeof VARIANTS)[number][0]

const rows = []
for (const contacts of [false, true]) {
  const runs: Record<Variant, Measured[]> = { alone: [], inReach: [], all: [] }
  for (let round = 0; round < ROUNDS; round++) {
    for (const [name, resting] of VARIANTS) runs[name].push(await measure(resting, contacts))
  }
  const ns = (v: Variant) => median(runs[v].map((m) => m.nsPerStep))
  const last = (v: Variant) => runs[v].at(-1)!
  const row = {
    contacts: contacts ? 'on' : 'off',
    moving: MOVING,
    resting: RESTING,
    restingInReach: nearXY.length / 2,
    nsPerStep: { alone: ns('alone'), inReach: ns('inReach'), all: ns('all') },
    ratio: ns('all') / ns('alone'),
    ratioToInReach: ns('all') / ns('inReach'),
    // the scenes are deterministic: every round has the same counts
    contactsDuringRun: { alone: last('alone').contacts, inReach: last('inReach').contacts, all: last('all').contacts },
    wokenDuringRun: { inReach: last('inReach').woken, all: last('all').woken },
    movingAtEnd: { alone: last('alone').movingAtEnd, inReach: last('inReach').movingAtEnd, all: last('all').movingAtEnd },
  }
  rows.push(row)
}

const k = (n: number) => n.toLocaleString('en-US')
const ns = (v: number) => k(Math.round(v)).padStart(10)
console.log(
  `resting balls: ${k(MOVING)} moving alone, beside the ${k(nearXY.length / 2)} resting balls within their reach, and beside ${k(RESTING)} ` +
    `resting balls; ns per step (median of ${STEPS} steps, median of ${ROUNDS} interleaved rounds), one run`,
)
console.log('contacts  alone       in reach    all resting  all/alone  all/in reach  contacts (alone / reach / all)  woken  moving at end')
for (const r of rows) {
  console.log(
    [
      r.contacts.padEnd(8),
      ns(r.nsPerStep.alone),
      ns(r.nsPerStep.inReach),
      ns(r.nsPerStep.all) + ' ',
      `${r.ratio.toFixed(2)}×`.padStart(9),
      `${r.ratioToInReach.toFixed(2)}×`.padStart(12),
      `  ${r.contactsDuringRun.alone} / ${r.contactsDuringRun.inReach} / ${r.contactsDuringRun.all}`.padEnd(32),
      String(r.wokenDuringRun.all).padStart(5),
      `  ${r.movingAtEnd.alone} / ${r.movingAtEnd.inReach} / ${r.movingAtEnd.all}`,
    ].join('  '),
  )
}
const json = writeResult('resting', {
  dt: DT,
  steps: STEPS,
  rounds: ROUNDS,
  rollingDecel: DECEL,
  ballRestitution: RESTITUTION,
  scene:
    `${MOVING} balls at 150-350 px/s over a ${FIELD} px square with 25 holes; resting balls on a ${PITCH} px square lattice ` +
    `centred on that field (inReach: only those within ${REACH} px of it)`,
  rows,
})
console.log(`wrote ${json}`)
