// Shared by the benchmarks: where results go, the tinybench step timer, JSON and SVG writers.
// Every benchmark prints its figures and writes files; none asserts a time (the machines are shared and
// noisy: compare ratios measured side by side in one run, not absolute times across runs).
import { mkdirSync, writeFileSync } from 'node:fs'
import { join } from 'node:path'
import { Bench } from 'tinybench'
import type { TopLevelSpec } from 'vega-lite'
import { renderSvg } from '../scripts/vegaSvg'

/** Step of every benchmark scene, s. */
export const DT = 1 / 120

/**
 * The benchmarks' seeded scenes: the Park–Miller minimal standard generator, uniform in (0, 1). Integer
 * arithmetic exact in doubles, so a seed draws the same scene in every run and engine.
 */
export function random(seed: number): () => number {
  let s = seed
  return () => ((s = (s * 16807) % 2147483647) - 1) / 2147483646
}

/** Value of `--name X` on the command line, or undefined. */
export function argValue(name: string): string | undefined {
  const i = process.argv.indexOf(name)
  return i >= 0 ? process.argv[i + 1] : undefined
}

/**
 * Where results go: `--out DIR` writes DIR/results/*.json and DIR/figures/*.svg; the default is `docs`
 * (the committed results). `npm run bench -- --quick` passes test-artifacts/bench-quick.
 */
export function outDir(): string {
  return argValue('--out') ?? 'docs'
}

export function writeResult(name: string, data: object): string {
  const dir = join(outDir(), 'results')
  mkdirSync(dir, { recursive: true })
  const file = join(dir, `${name}.json`)
  writeFileSync(file, JSON.stringify({ date: new Date().toISOString(), node: process.version, ...data }, null, 2) + '\n')
  return file
}

export async function writeFigure(name: string, spec: TopLevelSpec): Promise<string> {
  const dir = join(outDir(), 'figures')
  mkdirSync(dir, { recursive: true })
  const file = join(dir, `${name}.svg`)
  writeFileSync(file, await renderSvg(spec))
  return file
}

/** Lets go of garbage before a measurement when Node runs with --expose-gc (the npm scripts pass it). */
export function collectGarbage(): void {
  const gc = (globalThis as { gc?: () => void }).gc
  if (gc) {
    gc()
    gc()
  }
}

/**
 * Median time of one call of `step`, ms, over `iterations` calls in a row, timed by tinybench (no time
 * budget, no warm-up: the caller warms the code on a scene of its own, then hands over a fresh one, so
 * that every engine or variant is measured over the same stretch of simulated time).
 */
export async function medianStepMs(step: () => void, iterations: number): Promise<number> {
  const bench = new Bench({ time: 0, iterations, warmup: false })
  bench.add('step', step)
  await bench.run()
  const r = bench.tasks[0]!.result as { state: string; latency?: { p50: number }; error?: unknown }
  if (!r.latency) throw new Error(`benchmark failed: ${String(r.error ?? r.state)}`)
  return r.latency.p50
}

export const median = (a: readonly number[]): number => {
  const s = [...a].sort((p, q) => p - q)
  const m = s.length >> 1
  return s.length % 2 === 1 ? s[m]! : (s[m - 1]! + s[m]!) / 2
}

/**
 * The limit: one step of a bare loop over four Float64Array columns that only moves the balls, with the
 * rolling deceleration. One function for every run (a loop in a fresh closure per run can start cold, in
 * V8's interpreter, at 100+ ns per ball-step).
 */
/** The barest loop that moves balls: x += vx·dt, y += vy·dt over two pairs of columns, nothing else. */
export function bareStep(x: Float64Array, y: Float64Array, vx: Float64Array, vy: Float64Array, n: number): void {
  for (let i = 0; i < n; i++) {
    x[i] = x[i]! + vx[i]! * DT
    y[i] = y[i]! + vy[i]! * DT
  }
}

export function plainStep(x: Float64Array, y: Float64Array, vx: Float64Array, vy: Float64Array, n: number, decel: number): void {
  for (let i = 0; i < n; i++) {
    const u = vx[i]!
    const w = vy[i]!
    const sp = Math.sqrt(u * u + w * w)
    const k = sp > decel * DT ? (sp - decel * DT) / sp : 0
    x[i] = x[i]! + u * DT
    y[i] = y[i]! + w * DT
    vx[i] = u * k
    vy[i] = w * k
  }
}

/** A grid cell's key for cellGrid (columns and rows within ±2¹⁹). */
export function cellKey(cx: number, cy: number): number {
  return cx * 1_048_576 + cy
}

/** Balls `ids` by the grid cell of side `cell` their centre (X, Y) lies in, keyed by cellKey: for the benches' neighbour scans. */
export function cellGrid(ids: readonly number[], X: ArrayLike<number>, Y: ArrayLike<number>, cell: number): Map<number, number[]> {
  const grid = new Map<number, number[]>()
  for (const b of ids) {
    const k = cellKey(Math.floor(X[b]! / cell), Math.floor(Y[b]! / cell))
    const list = grid.get(k)
    if (list) list.push(b)
    else grid.set(k, [b])
  }
  return grid
}
