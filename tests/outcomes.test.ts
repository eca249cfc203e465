// Outcome estimates and maps (src/api/outcomes.ts): the counts do not depend on how a run is split, a
// throw ends the same in a batch as alone, the intervals and the payout are computed right, and a pool of
// workers (tinypool; child processes here, threads in npm run outcomes) gives the counts of one thread.
import { build } from 'esbuild'
import { mkdtempSync, rmSync } from 'node:fs'
import { tmpdir } from 'node:os'
import { join, resolve } from 'node:path'
import { Tinypool } from 'tinypool'
import { describe, expect, it } from 'vitest'
import { createBallPhysics, DEFAULT_PANEL, mergeTallies, outcomeMap, sampleThrows, summarizeOutcomes, type OutcomeScene, type OutcomeTally, type ThrowDistribution } from '../src/index.js'

const scene: OutcomeScene = {
  holes: DEFAULT_PANEL.holes.map((h) => ({ x: h.x, y: h.y, value: h.value })),
  walls: { minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 0.5, open: { bottom: true } },
}
const dist: ThrowDistribution = { power: { mean: 0.45, sd: 0.1 }, angle: { mean: 0, sd: 0.3 }, from: { x: 210, y: 450, sdX: 3 } }

/** The hole index (−1: none) a single throw ends in, simulated alone with 1/60 s steps. */
function alone(power: number, angle: number): number {
  const sim = createBallPhysics()
  const ids = scene.holes.map((h) => sim.addHole(h))
  sim.setWalls(scene.walls!)
  const b = sim.throwBall({ x: 210, y: 450, power, angle })
  for (let t = 0; t < 30; t += 1 / 60) {
    sim.step(1 / 60)
    for (const e of sim.drainEvents()) if (e.type === 'capture' && e.ball === b) return ids.indexOf(e.hole!)
    const m = sim.ballState(b).mode
    if (m !== 'rolling' && m !== 'rimRoll') return -1
  }
  return -1
}

describe('outcome estimates', () => {
  it('counts do not depend on how the run is split into chunks', () => {
    const whole = sampleThrows(scene, dist, 5000, 11)
    const parts = [sampleThrows(scene, dist, 1234, 11, 0), sampleThrows(scene, dist, 2766, 11, 1234), sampleThrows(scene, dist, 1000, 11, 4000)]
    expect(parts.reduce(mergeTallies)).toEqual(whole)
    expect(whole.throws).toBe(5000)
    expect(whole.captures.reduce((a, b) => a + b, 0) + whole.missed).toBe(5000)
    // and another seed is another sample
    expect(sampleThrows(scene, dist, 5000, 12)).not.toEqual(whole)
  })

  it('a throw ends in the same hole in a batch (the map) as alone', () => {
    const spec = { from: { x: 210, y: 450 }, power: { min: 0.05, max: 0.95, steps: 10 }, angle: { min: -1, max: 1, steps: 21 } }
    const map = outcomeMap(scene, spec)
    let captured = 0
    for (let i = 0; i < 10; i++) {
      for (let j = 0; j < 21; j++) {
        const power = 0.05 + (0.9 * i) / 9
        const angle = -1 + (2 * j) / 20
        expect(map[i * 21 + j], `power ${power} angle ${angle}`).toBe(alone(power, angle))
        if (map[i * 21 + j]! >= 0) captured++
      }
    }
    expect(captured).toBeGreaterThan(40)
    // rows of the map computed apart are the same rows
    expect(outcomeMap(scene, spec, { from: 3, to: 7 })).toEqual(map.slice(3 * 21, 7 * 21))
  })

  it('a throw with no noise lands every time where it lands alone; the interval and payout follow', () => {
    const t = sampleThrows(scene, { power: { mean: 0.2 }, angle: { mean: 0 }, from: { x: 210, y: 450 } }, 300, 1)
    const h = alone(0.2, 0)
    expect(h).toBeGreaterThanOrEqual(0)
    expect(t.captures[h]).toBe(300)
    const payouts = DEFAULT_PANEL.holes.map((x) => x.value)
    const s = summarizeOutcomes(t, payouts, 10)
    expect(s.holes[h]!.p).toBe(1)
    expect(s.holes[h]!.low).toBeGreaterThan(0.98) // Wilson: 1 − 3.84 / (300 + 3.84)
    expect(s.holes[h]!.low).toBeCloseTo(300 / (300 + 1.959963984540054 ** 2), 12)
    expect(s.payout.mean).toBe(payouts[h])
    expect(s.payout.high - s.payout.low).toBe(0)
    expect(s.rtp).toBe(payouts[h]! / 10)
  })

  it('the payout interval covers the mean of a much larger run', () => {
    const payouts = DEFAULT_PANEL.holes.map((x) => x.value)
    const small = summarizeOutcomes(sampleThrows(scene, dist, 4000, 5), payouts)
    const large = summarizeOutcomes(sampleThrows(scene, dist, 40000, 99), payouts)
    expect(large.payout.mean).toBeGreaterThan(small.payout.low)
    expect(large.payout.mean).toBeLessThan(small.payout.high)
    expect(small.payout.high - small.payout.low).toBeGreaterThan(large.payout.high - large.payout.low)
  })

  // (child processes, not worker threads: Node 20 aborts the whole process, here vitest's, when a worker
  // thread is terminated while V8 still compiles its code in the background, "Assertion failed:
  // (data.first) != nullptr" in NodePlatform::ForIsolate; seen once in CI. npm run outcomes runs threads.)
  it('two workers through tinypool give the counts of this thread', async () => {
    const dir = mkdtempSync(join(tmpdir(), 'outcomes-'))
    try {
      const file = join(dir, 'worker.mjs')
      await build({ entryPoints: [resolve(import.meta.dirname, '../scripts/outcomesWorker.ts')], outfile: file, bundle: true, format: 'esm', platform: 'node', target: 'node20', logLevel: 'silent' })
      const pool = new Tinypool({ filename: file, minThreads: 2, maxThreads: 2, runtime: 'child_process' })
      const chunks = [0, 2500, 5000, 7500].map((first) => pool.run({ scene, dist, count: 2500, seed: 3, first }))
      const parts = (await Promise.all(chunks)) as OutcomeTally[]
      await pool.destroy()
      expect(parts.reduce(mergeTallies)).toEqual(sampleThrows(scene, dist, 10000, 3))
    } finally {
      rmSync(dir, { recursive: true, force: true })
    }
  })

  it('refuses bad counts', () => {
    expect(() => sampleThrows(scene, dist, -1, 1)).toThrow(/count must be a non-negative integer/)
    expect(() => sampleThrows(scene, dist, 10, 1, 0.5)).toThrow(/first must be/)
    expect(() => summarizeOutcomes(sampleThrows(scene, dist, 10, 1), [1, 2])).toThrow(/payouts has 2 entries/)
  })

  it('refuses requests that would run without end, name the wrong hole or give NaN, by field, before any work', () => {
    const at = (f: () => unknown, type: ErrorConstructor, message: RegExp): void => {
      const t0 = performance.now()
      expect(f).toThrow(type)
      expect(f).toThrow(message)
      expect(performance.now() - t0).toBeLessThan(2000) // refused, not run
    }
    // sizes: the generator streams are 32-bit, a map's cells 16-bit and at most 2^24
    at(() => sampleThrows(scene, dist, 1e15, 1), RangeError, /count must be a non-negative integer ≤ 4294967296/)
    at(() => sampleThrows(scene, dist, 10, 1, 1e300), RangeError, /first must be a non-negative integer with first \+ count ≤ 4294967296/)
    at(() => sampleThrows(scene, dist, 10, Number.NaN), RangeError, /seed must be an integer in \[0, 4294967296\), got NaN/)
    at(() => sampleThrows(scene, dist, 10, 1.7), RangeError, /seed must be an integer/)
    at(() => sampleThrows(scene, dist, 10, 'abc' as never), TypeError, /seed must be an integer/)
    at(() => sampleThrows(scene, { ...dist, power: { mean: 2 } }, 10, 1), RangeError, /distribution\.power\.mean must be in \[0, 1\], got 2/)
    at(() => sampleThrows(scene, { ...dist, angle: { mean: 0, sd: Number.NaN } }, 10, 1), RangeError, /distribution\.angle\.sd/)
    const spec = { from: { x: 210, y: 450 }, power: { min: 0.2, max: 0.8, steps: 4 }, angle: { min: -0.3, max: 0.3, steps: 5 } }
    at(() => outcomeMap(scene, { ...spec, angle: { min: 0, max: 0, steps: 2e7 } }), RangeError, /spec\.angle\.steps must be in \[1, 16777216\]/)
    at(() => outcomeMap(scene, { ...spec, power: { min: 0, max: 1, steps: 1e5 }, angle: { min: 0, max: 1, steps: 1e5 } }), RangeError, /power\.steps × spec\.angle\.steps must be at most 16777216/)
    at(() => outcomeMap(scene, spec, { from: Number.NaN, to: 2 }), RangeError, /rows\.from must be in \[0, 4\]/)
    at(() => outcomeMap(scene, spec, { from: 3, to: 2 }), RangeError, /rows\.to must be in \[3, 4\]/)
    const many = Array.from({ length: 32768 }, (_, i) => ({ x: 40 * (i % 200), y: 40 * Math.floor(i / 200) }))
    at(() => outcomeMap({ holes: many }, spec), RangeError, /at most 32767 holes/)
    at(() => sampleThrows({ holes: 5 } as never, dist, 1, 1), TypeError, /scene\.holes must be an array of holes, got 5/)
    // steps: each throw is stepped at the scene's MAX_STEP for up to 30 s
    at(() => sampleThrows({ ...scene, config: { MAX_STEP: 1e-9 } }, dist, 1, 1), RangeError, /scene\.config\.MAX_STEP must be at least 0\.0001 s/)
    // summaries: a payout, a stake and a tally that give no number are refused
    const tally = sampleThrows(scene, dist, 20, 1)
    const payouts = scene.holes.map((h) => h.value ?? 0)
    at(() => summarizeOutcomes(tally, payouts, 0), RangeError, /stake must be in \(0, 1000000000000\], got 0/)
    at(() => summarizeOutcomes(tally, payouts.map((p, i) => (i === 3 ? Number.NaN : p))), RangeError, /payouts\[3\] must be a finite number/)
    at(() => summarizeOutcomes(tally, undefined as never), TypeError, /payouts must be an array/)
    at(() => summarizeOutcomes({ ...tally, throws: 1 }, payouts), RangeError, /captured and \d+ missed of 1 throws/)
    at(() => summarizeOutcomes({ ...tally, extra: 1 } as never, payouts), RangeError, /tally\.extra is not a known key/)
    at(() => mergeTallies(tally, { ...tally, skips: [1] }), RangeError, /b\.skips has 1 entries/)
    at(() => mergeTallies(tally, { ...tally, throws: '1' as never }), TypeError, /b\.throws must be a non-negative integer/)
    expect(summarizeOutcomes(mergeTallies(tally, tally), payouts).throws).toBe(40)
  })

  it('a wide angle spread draws past ±2π and throws the same direction a turn back; a map row longer than a batch is split', () => {
    const wide = sampleThrows(scene, { ...dist, angle: { mean: 0, sd: 20 } }, 200, 4)
    expect(wide.throws).toBe(200)
    expect(sampleThrows(scene, { ...dist, angle: { mean: 0, sd: 20 } }, 200, 4)).toEqual(wide)
    const spec = { from: { x: 210, y: 450 }, power: { min: 0.3, max: 0.5, steps: 2 }, angle: { min: -1, max: 1, steps: 2500 } }
    const map = outcomeMap(scene, spec)
    expect(map.length).toBe(5000)
    expect(Array.from(outcomeMap(scene, spec, { from: 1, to: 2 }))).toEqual(Array.from(map.slice(2500)))
    expect(new Set(map).size).toBeGreaterThan(3)
  }, 60_000)
})
