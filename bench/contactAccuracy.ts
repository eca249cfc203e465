// The two contact methods against each other: cost against accuracy of outcomes. On the default panel
// (walls, bottom open), a burst of balls is thrown at once from a launch band below the holes; each ball
// ends captured in a hole, out through the open bottom, or at rest on the panel. The exact method
// (BALL_COLLISIONS 'on') is the reference; each other run is scored by
//   agreement: the share of balls whose end (which hole, out, or at rest) is the reference's;
//   hole error: the total variation distance between the run's and the reference's distribution of ends
//     over all seeds (what a payout table sees);
// and by its cost (ns per ball-step over the whole run). Two references for what the numbers can mean:
// the exact method with every spawn moved by 1e-9 px (many-ball outcomes are chaotic: this is the most
// any method can agree with the reference ball by ball), and contacts off. Writes
// docs/results/contact-accuracy.json and docs/figures/contact-accuracy.svg.
//
//   npm run bench:contact-accuracy
import { DEFAULT_PANEL, createBallPhysics, type ConfigOverrides } from '../src/index'
import { contactAccuracyFigure, type AccuracyPoint } from './charts'
import { argValue, random, writeFigure, writeResult } from './lib'

const SEEDS = Number(argValue('--seeds') ?? 24)
const DT = 1 / 60
const SECONDS = 8

interface Method {
  name: string
  config: ConfigOverrides
  jitter?: number
}

const METHODS: Method[] = [
  { name: 'exact, spawns moved 1e-9 px', config: { BALL_COLLISIONS: 'on' }, jitter: 1e-9 },
  ...[1 / 60, 1 / 120, 1 / 240, 1 / 480, 1 / 960].map((tick) => ({ name: `fixed, tick 1/${Math.round(1 / tick)} s`, config: { BALL_COLLISIONS: 'fixed' as const, CONTACT_TICK: tick } })),
  { name: 'contacts off', config: { BALL_COLLISIONS: 'off' } },
]

/**
 * Ends of every ball ('h<id>', 'out', 'rest') and the run's cost, ns per ball-step: `resting` balls put down
 * at rest first (seeded spots on the panel, clear of the holes and of each other), then the burst of `balls`.
 */
function play(balls: number, seed: number, config: ConfigOverrides, jitter = 0, resting = 0): { ends: string[]; ns: number } {
  const sim = createBallPhysics({ BALL_RESTITUTION: 0.9, ...config })
  for (const h of DEFAULT_PANEL.holes) sim.addHole(h)
  sim.setWalls({ minX: 0, minY: 0, maxX: DEFAULT_PANEL.width, maxY: DEFAULT_PANEL.height, restitution: 0.9, open: { bottom: true } })
  const r = random(seed)
  const ids: number[] = []
  const spots: number[] = []
  while (spots.length < 2 * resting) {
    const x = 20 + r() * (DEFAULT_PANEL.width - 40)
    const y = 20 + r() * (DEFAULT_PANEL.height - 200)
    if (DEFAULT_PANEL.holes.some((h) => Math.hypot(h.x - x, h.y - y) < 40)) continue
    let clear = true
    for (let k = 0; k < spots.length; k += 2) if (Math.hypot(spots[k]! - x, spots[k + 1]! - y) < 24) clear = false
    if (!clear) continue
    spots.push(x, y)
    ids.push(sim.addBall({ x: x + jitter, y: y + jitter, vx: 0, vy: 0 }))
  }
  // a launch band of 10 columns, 40 px apart, below the lowest row of holes, jittered
  for (let i = 0; i < balls; i++) {
    const x = 30 + 40 * (i % 10) + (r() - 0.5) * 16 + jitter
    const y = DEFAULT_PANEL.height - 150 + 40 * Math.floor(i / 10) + (r() - 0.5) * 16 + jitter
    const speed = 175 + (0.2 + 0.7 * r()) * 525
    const angle = (r() - 0.5) * 0.8
    ids.push(sim.addBall({ x, y, vx: speed * Math.sin(angle), vy: -speed * Math.cos(angle) }))
  }
  const into = new Map<number, number>()
  let busy = 0
  const steps = Math.round(SECONDS / DT)
  for (let s = 0; s < steps; s++) {
    const t0 = performance.now()
    sim.step(DT)
    busy += performance.now() - t0
    for (const e of sim.drainEvents()) if (e.type === 'capture') into.set(e.ball, e.hole!)
  }
  const ns = (busy * 1e6) / steps / (balls + resting)
  const ends = ids.map((b) => {
    const m = sim.ballState(b).mode
    if (m === 'captured') return `h${into.get(b)}`
    return m === 'out' ? 'out' : 'rest'
  })
  return { ends, ns }
}

// warm every method's code up first, so that no method pays for compilation in its figures
for (const m of [{ name: 'exact', config: { BALL_COLLISIONS: 'on' } } as Method, ...METHODS]) for (let s = 0; s < 4; s++) play(40, 1 + s, m.config)

const points: AccuracyPoint[] = []
// the bursts alone, and one thrown into a field of balls at rest (as a multi-ball mode's panel fills up)
const SCENES = [
  { name: '10 balls', balls: 10, resting: 0, seed: 1000 },
  { name: '40 balls', balls: 40, resting: 0, seed: 1000 },
  { name: '40 into 40 at rest', balls: 40, resting: 40, seed: 2000 },
]
for (const { name: scene, balls, resting, seed: seed0 } of SCENES) {
  const reference: string[][] = []
  for (let s = 0; s < SEEDS; s++) reference.push(play(balls, seed0 + s, { BALL_COLLISIONS: 'on' }, 0, resting).ends)
  const refCount = tally(reference)
  // the reference's own cost, for the chart
  const refNs: number[] = []
  for (let s = 0; s < SEEDS; s++) refNs.push(play(balls, seed0 + s, { BALL_COLLISIONS: 'on' }, 0, resting).ns)
  points.push({ scene, method: 'exact (reference)', ns: mean(refNs), agreement: 1, holeError: 0 })
  for (const m of METHODS) {
    let same = 0
    let total = 0
    const runs: string[][] = []
    const ns: number[] = []
    for (let s = 0; s < SEEDS; s++) {
      const got = play(balls, seed0 + s, m.config, m.jitter, resting)
      runs.push(got.ends)
      ns.push(got.ns)
      got.ends.forEach((e, i) => {
        total++
        if (e === reference[s]![i]) same++
      })
    }
    const count = tally(runs)
    const keys = new Set([...refCount.keys(), ...count.keys()])
    let tv = 0
    for (const k of keys) tv += Math.abs((count.get(k) ?? 0) - (refCount.get(k) ?? 0))
    tv /= 2 * total
    const p: AccuracyPoint = { scene, method: m.name, ns: mean(ns), agreement: same / total, holeError: tv }
    points.push(p)
    console.log(`${p.scene.padEnd(18)} ${m.name.padEnd(30)} agreement ${(100 * p.agreement).toFixed(1).padStart(5)} %   hole error ${(100 * p.holeError).toFixed(1).padStart(4)} %   ${p.ns.toFixed(0).padStart(5)} ns/ball-step`)
  }
}

function tally(runs: string[][]): Map<string, number> {
  const m = new Map<string, number>()
  for (const r of runs) for (const e of r) m.set(e, (m.get(e) ?? 0) + 1)
  return m
}

function mean(a: number[]): number {
  return a.reduce((s, v) => s + v, 0) / a.length
}

const json = writeResult('contact-accuracy', {
  dt: DT,
  seconds: SECONDS,
  seeds: SEEDS,
  scene: 'default panel, walls open at the bottom, a burst of balls thrown at once from a launch band (10 a row, 40 px apart), restitution 0.9; in the third scene into 40 balls put down at rest first (seeded spots clear of the holes and 24 px apart)',
  agreement: "share of balls whose end (hole, out, at rest) is the exact method's, over all seeds",
  holeError: "total variation distance between the distribution of ends and the exact method's, over all seeds",
  cost: 'ns per ball-step over the whole run (wall clock, one run; includes stopped balls)',
  points,
})
const svg = await writeFigure('contact-accuracy', contactAccuracyFigure(points, SEEDS))
console.log(`wrote ${json} and ${svg}`)
