// npm run outcomes: where throws end, by Monte Carlo on worker processes (tinypool) and as a map.
//   1. A throw distribution on the default panel (walls, bottom open) — power, aim and start point each
//      with normal noise — run as chunks of 25,000 throws on 1 and on 2 worker processes, and in this
//      process: the counts must be identical (each throw has its own generator). Prints and writes the
//      probability of each hole with 95 % intervals, the mean payout per throw for the holes' values and
//      the return to player at a stake of 50, and the throws per second on 1 and 2 workers.
//      Workers are child processes, not threads: Node 20 can abort the whole process (an assertion in
//      NodePlatform::ForIsolate) when a worker thread is terminated while V8 still compiles its code in
//      the background, which a pool's teardown does; it aborted a test run once. The counts do not
//      depend on which.
//   2. The outcome map: which hole each (power, angle) of a 240 × 320 grid from the launch point ends
//      in, drawn as docs/figures/outcome-map.svg.
//   npm run outcomes -- --throws N        (default 1,000,000)  writes docs/results/outcomes.json
import { build } from 'esbuild'
import { mkdirSync } from 'node:fs'
import { availableParallelism } from 'node:os'
import { resolve } from 'node:path'
import { Tinypool } from 'tinypool'
import { DEFAULT_PANEL, mergeTallies, outcomeMap, sampleThrows, summarizeOutcomes, type OutcomeScene, type OutcomeTally, type ThrowDistribution } from '../src/index'
import { argValue, writeFigure, writeResult } from '../bench/lib'

const THROWS = Number(argValue('--throws') ?? 1_000_000)
const CHUNK = 25_000
const SEED = 20261123
const STAKE = 50
const scene: OutcomeScene = {
  holes: DEFAULT_PANEL.holes.map((h) => ({ x: h.x, y: h.y, value: h.value })),
  walls: { minX: 0, minY: 0, maxX: DEFAULT_PANEL.width, maxY: DEFAULT_PANEL.height, restitution: 0.5, open: { bottom: true } },
}
// a player aiming up the middle at mid power, with a shaky hand and a launcher that wobbles
const dist: ThrowDistribution = { power: { mean: 0.45, sd: 0.08 }, angle: { mean: 0, sd: 0.25 }, from: { x: DEFAULT_PANEL.launch.x, y: DEFAULT_PANEL.launch.y, sdX: 3 } }
const payouts = DEFAULT_PANEL.holes.map((h) => h.value)

// the worker's code, bundled for Node (tinypool loads a file)
const dir = resolve('node_modules/.cache/outcomes')
mkdirSync(dir, { recursive: true })
const workerFile = resolve(dir, 'worker.mjs')
await build({ entryPoints: ['scripts/outcomesWorker.ts'], outfile: workerFile, bundle: true, format: 'esm', platform: 'node', target: 'node20', logLevel: 'warning' })

const chunks: Array<{ first: number; count: number }> = []
for (let first = 0; first < THROWS; first += CHUNK) chunks.push({ first, count: Math.min(CHUNK, THROWS - first) })

async function onWorkers(workers: number): Promise<{ tally: OutcomeTally; seconds: number }> {
  const pool = new Tinypool({ filename: workerFile, runtime: 'child_process', minThreads: workers, maxThreads: workers, isolateWorkers: false })
  // warm the workers (module load, JIT) on a small chunk each, not timed
  await Promise.all(Array.from({ length: workers }, () => pool.run({ scene, dist, count: 2000, seed: 1, first: 0 })))
  const t0 = performance.now()
  const parts = (await Promise.all(chunks.map((c) => pool.run({ scene, dist, count: c.count, seed: SEED, first: c.first })))) as OutcomeTally[]
  const seconds = (performance.now() - t0) / 1000
  await pool.destroy()
  return { tally: parts.reduce(mergeTallies), seconds }
}

const one = await onWorkers(1)
const two = await onWorkers(2)
// the first chunks again in this process, as one run: the same counts as the chunks merged
const firstChunks = chunks.slice(0, 4)
const sample = firstChunks.reduce((n, c) => n + c.count, 0)
const here = sampleThrows(scene, dist, sample, SEED)
const sameHere = JSON.stringify(here) === JSON.stringify(firstChunks.map((c) => sampleThrows(scene, dist, c.count, SEED, c.first)).reduce(mergeTallies))
const same = JSON.stringify(one.tally) === JSON.stringify(two.tally)
const summary = summarizeOutcomes(two.tally, payouts, STAKE)
const perSecond = { oneWorker: THROWS / one.seconds, twoWorkers: THROWS / two.seconds }
console.log(`${THROWS.toLocaleString('en-US')} throws, chunks of ${CHUNK.toLocaleString('en-US')}; cores here: ${availableParallelism()}`)
console.log(`1 worker: ${(one.seconds).toFixed(2)} s, ${Math.round(perSecond.oneWorker).toLocaleString('en-US')} throws/s`)
console.log(`2 workers: ${(two.seconds).toFixed(2)} s, ${Math.round(perSecond.twoWorkers).toLocaleString('en-US')} throws/s (${(perSecond.twoWorkers / perSecond.oneWorker).toFixed(2)}×)`)
console.log(`counts identical on 1 and 2 workers: ${same}; the first ${sample.toLocaleString('en-US')} in this process as one run and as chunks: ${sameHere}`)
const pct = (x: { p: number; low: number; high: number }): string => `${(100 * x.p).toFixed(3)} % [${(100 * x.low).toFixed(3)}, ${(100 * x.high).toFixed(3)}]`
summary.holes.forEach((h, i) => console.log(`  hole ${String(i).padStart(2)} (value ${String(payouts[i]).padStart(3)}): ${pct(h)}`))
console.log(`  no capture: ${pct(summary.missed)}`)
console.log(`mean payout ${summary.payout.mean.toFixed(3)} [${summary.payout.low.toFixed(3)}, ${summary.payout.high.toFixed(3)}] per throw; RTP at a stake of ${STAKE}: ${(100 * summary.rtp).toFixed(2)} % [${((100 * summary.payout.low) / STAKE).toFixed(2)}, ${((100 * summary.payout.high) / STAKE).toFixed(2)}]`)

// 2. the map
const spec = { from: DEFAULT_PANEL.launch, power: { min: 0, max: 1, steps: 240 }, angle: { min: -1.3, max: 1.3, steps: 320 } }
const t0 = performance.now()
const map = outcomeMap(scene, spec)
const mapSeconds = (performance.now() - t0) / 1000
console.log(`outcome map ${spec.power.steps} × ${spec.angle.steps}: ${mapSeconds.toFixed(2)} s (${Math.round((spec.power.steps * spec.angle.steps) / mapSeconds).toLocaleString('en-US')} throws/s, this process)`)
// a hole's name and colour: its value (the row, 100 at the top) and column; hue by column, darker rows score more
const holeName = (h: number): string => `${payouts[h]} · column ${(h % 5) + 1}`
const HUES = [210, 30, 120, 280, 0]
const names = payouts.map((_v, h) => holeName(h))
const colours = payouts.map((_v, h) => `hsl(${HUES[h % 5]}, 65%, ${72 - 9 * Math.floor(h / 5)}%)`)
// runs of equal cells along each row, one rectangle each
const runs: Array<{ p0: number; p1: number; a0: number; a1: number; hole: string }> = []
const dp = (spec.power.max - spec.power.min) / (spec.power.steps - 1)
const da = (spec.angle.max - spec.angle.min) / (spec.angle.steps - 1)
for (let i = 0; i < spec.power.steps; i++) {
  let j = 0
  while (j < spec.angle.steps) {
    const h = map[i * spec.angle.steps + j]!
    let k = j + 1
    while (k < spec.angle.steps && map[i * spec.angle.steps + k] === h) k++
    if (h >= 0) {
      const p = spec.power.min + i * dp
      runs.push({ p0: p - dp / 2, p1: p + dp / 2, a0: spec.angle.min + (j - 0.5) * da, a1: spec.angle.min + (k - 0.5) * da, hole: holeName(h) })
    }
    j = k
  }
}
await writeFigure('outcome-map', {
  $schema: 'https://vega.github.io/schema/vega-lite/v5.json',
  title: { text: 'Which hole a throw from the launch point ends in', subtitle: 'the default panel with walls, the design config; blank: no capture' },
  width: 600,
  height: 420,
  data: { values: runs },
  mark: { type: 'rect', strokeWidth: 0.5 },
  encoding: {
    x: { field: 'a0', type: 'quantitative', title: 'aim, rad (0 = straight up the panel)', scale: { domain: [spec.angle.min, spec.angle.max] } },
    x2: { field: 'a1' },
    y: { field: 'p0', type: 'quantitative', title: 'power', scale: { domain: [0, 1] } },
    y2: { field: 'p1' },
    color: { field: 'hole', type: 'nominal', title: 'hole: value · column', scale: { domain: names, range: colours }, legend: { columns: 1, symbolLimit: 30, labelFontSize: 10 } },
    stroke: { field: 'hole', type: 'nominal', scale: { domain: names, range: colours }, legend: null },
  },
})
writeResult('outcomes', {
  scene: 'the default 5 × 5 panel with walls (bottom open, restitution 0.5), the design config; each throw alone on the panel',
  distribution: dist,
  throws: THROWS,
  chunk: CHUNK,
  seed: SEED,
  cores: availableParallelism(),
  throwsPerSecond: perSecond,
  workers: 'child processes (tinypool)',
  identicalOn1And2Workers: same,
  identicalAsChunksInThisThread: sameHere,
  stake: STAKE,
  payouts,
  summary,
  map: { ...spec, seconds: mapSeconds, runs: runs.length },
})
