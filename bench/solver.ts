// The throw solver's cost and success on the default panel with walls: for each outcome (capture, skip,
// lipOut, bounce) and each of the 25 holes, solveThrow from the launch line (±160 px) and from the launch
// point alone; the time per solve (median, worst), how many found, the throws simulated per solve, and
// the margins. Every answer found is checked by simulating it in a world of its own.
//   npm run bench:solver                 writes docs/results/solver.json
import { addPanel, createBallPhysics, DEFAULT_PANEL, solveThrow, type ThrowOutcome } from '../src/index'
import { writeResult } from './lib'

const WALLS = { minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 0.5, open: { bottom: true } }
const sim = createBallPhysics()
const holes = addPanel(sim)
sim.setWalls(WALLS)

/** The first decisive event of a throw at the hole, simulated in a fresh copy of the panel with 1/60 s steps. */
function check(hole: number, from: { x: number; y: number }, power: number, angle: number): ThrowOutcome | null {
  const copy = createBallPhysics()
  const ids = addPanel(copy)
  copy.setWalls(WALLS)
  const h = ids[holes.indexOf(hole)]!
  const b = copy.throwBall({ ...from, power, angle })
  for (let t = 0; t < 20; t += 1 / 60) {
    copy.step(1 / 60)
    for (const e of copy.drainEvents()) if (e.ball === b && e.hole === h && (e.type === 'capture' || e.type === 'skip' || e.type === 'lipOut' || e.type === 'bounce')) return e.type
    const m = copy.ballState(b).mode
    if (m !== 'rolling' && m !== 'rimRoll') return null
  }
  return null
}

const median = (a: number[]): number => [...a].sort((p, q) => p - q)[a.length >> 1] ?? NaN
// warm-up (the JIT), not measured
for (const h of holes.slice(0, 5)) solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: h, along: 160 })

const rows = []
for (const along of [160, 0]) {
  for (const outcome of ['capture', 'skip', 'lipOut', 'bounce'] as const) {
    const ms: number[] = []
    const trials: number[] = []
    const marginPower: number[] = []
    const marginAngle: number[] = []
    let found = 0
    let verified = 0
    for (const hole of holes) {
      const t0 = performance.now()
      const s = solveThrow(sim, { from: DEFAULT_PANEL.launch, hole, outcome, along })
      ms.push(performance.now() - t0)
      trials.push(s.trials)
      if (!s.found) continue
      found++
      marginPower.push(s.margin.power)
      marginAngle.push(s.margin.angle)
      if (check(hole, s.from, s.power, s.angle) === outcome) verified++
    }
    const row = {
      from: along > 0 ? 'launch line (±160 px)' : 'launch point',
      outcome,
      holes: holes.length,
      found,
      verified,
      medianMs: median(ms),
      worstMs: Math.max(...ms),
      medianTrials: median(trials),
      medianMargin: { power: median(marginPower), angle: median(marginAngle) },
    }
    rows.push(row)
    console.log(`${row.from.padEnd(22)} ${outcome.padEnd(8)} found ${String(found).padStart(2)}/25 (verified ${verified})  median ${row.medianMs.toFixed(1).padStart(5)} ms  worst ${row.worstMs.toFixed(1).padStart(5)} ms  ${row.medianTrials} throws  margin ±${row.medianMargin.power.toFixed(3)} power, ±${row.medianMargin.angle.toFixed(4)} rad`)
  }
}
writeResult('solver', {
  date: new Date().toISOString(),
  node: process.version,
  scene: 'the default 5 × 5 panel with walls (bottom open, restitution 0.5), the design config; throws from DEFAULT_PANEL.launch',
  timing: 'performance.now() around each solveThrow call, after 5 warm-up solves',
  verified: 'each throw found, simulated in a fresh copy of the panel with 1/60 s steps, gives the outcome at the hole',
  rows,
})
