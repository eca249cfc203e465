// Entity lifecycle at full size: 1,000,000 throws through one world on the default panel, finished balls
// (captured or at rest) removed at once, so their ids and store rows are recycled. Heap (JS objects and
// typed arrays, after a full GC) is sampled every 100,000 throws: it must stay bounded by the peak number
// of live balls, not grow with the number thrown. Prints the samples and writes docs/results/recycling.json.
// Asserts nothing (tests/lifecycle.test.ts checks the same at 200,000 throws).
//
//   npm run bench:recycling [-- --throws N] [-- --out DIR]
import { DEFAULT_PANEL, addPanel, createBallPhysics } from '../src/index'
import { random, writeResult } from './lib'

const arg = process.argv.indexOf('--throws')
const THROWS = arg >= 0 ? Number(process.argv[arg + 1]) : 1_000_000
const PER_STEP = 100
const SAMPLE = Math.max(1, Math.floor(THROWS / 10))
const gc = (globalThis as { gc?: () => void }).gc
if (!gc) throw new Error('run with node --expose-gc (npm run bench does)')

function heap(): number {
  gc!()
  gc!()
  const m = process.memoryUsage()
  return m.heapUsed + m.arrayBuffers
}

const rand = random(77)

const base = heap()
const sim = createBallPhysics()
addPanel(sim)
let live = 0
let peak = 0
let thrown = 0
let maxId = 0
const samples: { thrown: number; live: number; peakLive: number; heapBytes: number; capacity: number }[] = []
const t0 = performance.now()
while (thrown < THROWS) {
  for (let i = 0; i < PER_STEP && thrown < THROWS; i++) {
    const b = sim.throwBall({ x: DEFAULT_PANEL.launch.x, y: DEFAULT_PANEL.launch.y, power: rand(), angle: (rand() - 0.5) * 1.2 })
    if (b > maxId) maxId = b
    live++
    thrown++
    if (thrown % SAMPLE === 0) {
      samples.push({ thrown, live, peakLive: peak, heapBytes: heap() - base, capacity: sim.world.capacity })
      const last = samples.at(-1)!
      console.log(
        `${String(thrown).padStart(9)} thrown   ${String(live).padStart(6)} live   peak ${String(peak).padStart(6)}   heap ${(last.heapBytes / 1024).toFixed(0).padStart(7)} KiB   store capacity ${last.capacity}`,
      )
    }
  }
  sim.step(1 / 60)
  for (const e of sim.drainEvents()) {
    if (e.type === 'capture' || e.type === 'rest') {
      sim.removeBall(e.ball)
      live--
    }
  }
  if (live > peak) peak = live
}
const seconds = (performance.now() - t0) / 1000
const first = samples[0]!
const last = samples.at(-1)!
console.log(
  `${THROWS.toLocaleString('en-US')} throws in ${seconds.toFixed(1)} s; peak ${peak} live balls, largest id ${maxId}; ` +
    `heap at the last sample / at the first: ${(last.heapBytes / first.heapBytes).toFixed(2)}`,
)
console.log(`wrote ${writeResult('recycling', { throws: THROWS, throwsPerStep: PER_STEP, peakLive: peak, maxId, seconds, samples })}`)
