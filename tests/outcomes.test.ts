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
})
