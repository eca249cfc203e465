// Speed against accuracy: every method at 30, 60, 120, 240 Hz on 10,000 seeded throws at the default panel,
// against the exact event-driven reference (src/reference/eventSolver.ts). Writes docs/results/accuracy.json and
// docs/figures/accuracy-vs-speed.svg (under DIR with --out DIR; npm run bench runs it), and prints the
// README table.
//   npm run accuracy
import { mkdirSync, writeFileSync } from 'node:fs'
import { join } from 'node:path'
import { outDir } from '../bench/lib'
import { cpus } from 'node:os'
import type { TopLevelSpec } from 'vega-lite'
import { METHOD_SPECS, measureAccuracy, panelThrows, referenceRuns, runMethod, type Accuracy } from './accuracyLib'
import { renderSvg } from './vegaSvg'

const SEED = 2024
const N = Number(process.env.ACCURACY_THROWS ?? 10_000)
const RATES = [30, 60, 120, 240] as const
const TIMING_RUNS = 3 // the accuracy run plus two timing-only runs; the median is reported

const throws = panelThrows(SEED, N)
const t0 = performance.now()
const refs = referenceRuns(throws)
const refMs = performance.now() - t0
console.log(`reference: ${N} throws solved event to event in ${refMs.toFixed(0)} ms`)

// warm the JIT on every method before anything is timed
for (const spec of METHOD_SPECS) runMethod(spec, 60, throws.slice(0, 500), false)

interface Row extends Accuracy {
  method: string
  hz: number
  nsPerBallStep: number
  nsSamples: number[]
  ballSteps: number
  ratioToExact?: number
}
const rows: Row[] = []
for (const hz of RATES) {
  for (const spec of METHOD_SPECS) {
    const run = runMethod(spec, hz, throws)
    const acc = measureAccuracy(run, refs)
    rows.push({ method: spec.label, hz, ...acc, nsPerBallStep: 0, nsSamples: [run.ns / run.ballSteps], ballSteps: run.ballSteps })
    console.log(`${spec.label.padEnd(10)} ${hz} Hz: sequence differs ${(100 * acc.sequenceDiffers).toFixed(2)} %`)
  }
}
// timing-only runs, interleaved over all methods and rates so that machine noise spreads over all of them
for (let k = 1; k < TIMING_RUNS; k++) {
  for (const row of rows) {
    const spec = METHOD_SPECS.find((s) => s.label === row.method)!
    const run = runMethod(spec, row.hz, throws, false)
    row.nsSamples.push(run.ns / run.ballSteps)
  }
}
for (const row of rows) {
  const s = [...row.nsSamples].sort((a, b) => a - b)
  row.nsPerBallStep = s[Math.floor(s.length / 2)]!
}
for (const row of rows) {
  const exact = rows.find((r) => r.method === 'exact' && r.hz === row.hz)!
  row.ratioToExact = row.nsPerBallStep / exact.nsPerBallStep
}

/** Pareto front: no other point is at least as fast and at least as accurate, and better in one. */
function paretoFront(get: (r: Row) => number): Set<Row> {
  const front = new Set<Row>()
  const cost = (r: Row) => r.nsPerBallStep * r.hz
  for (const r of rows) {
    const dominated = rows.some((q) => q !== r && cost(q) <= cost(r) && get(q) <= get(r) && (cost(q) < cost(r) || get(q) < get(r)))
    if (!dominated) front.add(r)
  }
  return front
}
const frontSeq = paretoFront((r) => r.sequenceDiffers)
const frontPos = paretoFront((r) => r.posErrP95)

mkdirSync(join(outDir(), 'results'), { recursive: true })
mkdirSync(join(outDir(), 'figures'), { recursive: true })
writeFileSync(
  join(outDir(), 'results', 'accuracy.json'),
  JSON.stringify(
    {
      generated: new Date().toISOString(),
      machine: { cpus: cpus().length, model: cpus()[0]?.model, node: process.version },
      throws: N,
      seed: SEED,
      distribution: 'tests/multiball.test.ts: x = 210 ± 150 px, y = 450, power U[0, 1], angle U[−0.7, 0.7] rad; all throws in one world',
      reference: 'src/eventSolver.ts, one ball at a time',
      timing: `median of ${TIMING_RUNS} runs; ns per ball-step = step wall time / Σ moving balls at each step's start`,
      rows: rows.map((r) => ({ ...r, paretoSequence: frontSeq.has(r), paretoPosition: frontPos.has(r) })),
    },
    null,
    2,
  ),
)

const methodOrder = METHOD_SPECS.map((s) => s.label)
const points = rows.map((r) => ({
  method: r.method,
  hz: r.hz,
  label: `${r.hz}`,
  // cost of one ball for one simulated second: what a game pays for a rate, µs
  us: (r.nsPerBallStep * r.hz) / 1000,
  seq: 100 * r.sequenceDiffers,
  pos: r.posErrP95,
  frontSeq: frontSeq.has(r),
  frontPos: frontPos.has(r),
}))
const panel = (field: 'seq' | 'pos', front: 'frontSeq' | 'frontPos', title: string, log: boolean) => ({
  width: 380,
  height: 300,
  title: { text: title, frame: 'group' },
  layer: [
    {
      data: { values: points.filter((p) => p[front]).sort((a, b) => a.us - b.us) },
      mark: { type: 'line', interpolate: 'step-after', color: '#888', strokeDash: [4, 3] },
      encoding: { x: { field: 'us', type: 'quantitative' }, y: { field, type: 'quantitative' } },
    },
    {
      data: { values: points.filter((p) => p[front]) },
      mark: { type: 'point', size: 260, color: 'black', strokeWidth: 1.5, filled: false },
      encoding: { x: { field: 'us', type: 'quantitative' }, y: { field, type: 'quantitative' } },
    },
    {
      data: { values: points },
      mark: { type: 'point', filled: true, size: 70, opacity: 0.9 },
      encoding: {
        x: { field: 'us', type: 'quantitative', scale: { type: 'log' }, title: 'µs per ball per simulated second (log)' },
        y: {
          field,
          type: 'quantitative',
          scale: log ? { type: 'symlog', constant: 0.01 } : { zero: true },
          axis: log ? { values: [0, 0.01, 0.1, 1, 10, 100, 1000], labelExpr: "'' + datum.value" } : {},
          title: field === 'seq' ? 'events differ, % of throws' : 'final-position error p95, px',
        },
        color: { field: 'method', type: 'nominal', sort: methodOrder, title: 'method', legend: { labelLimit: 300 } },
        shape: { field: 'method', type: 'nominal', sort: methodOrder },
        tooltip: [{ field: 'method' }, { field: 'hz' }, { field: 'us' }, { field }],
      },
    },
    // rate labels, above the point for some methods and below for the others (points can coincide:
    // naive at 120 Hz and naive ×4 at 30 Hz take the same sub-step)
    ...[
      { below: false, dy: -8 },
      { below: true, dy: 12 },
    ].map(({ below, dy }) => ({
      data: { values: points.filter((p) => (p.method === 'naive ×4' || p.method === 'exact') === below) },
      mark: { type: 'text', dx: 7, dy, fontSize: 9, align: 'left' },
      encoding: {
        x: { field: 'us', type: 'quantitative' },
        y: { field, type: 'quantitative' },
        text: { field: 'label' },
        color: { field: 'method', type: 'nominal', sort: methodOrder, legend: null },
      },
    })),
  ],
})
const spec = {
  $schema: 'https://vega.github.io/schema/vega-lite/v6.json',
  title: {
    text: `Accuracy against speed: ${N.toLocaleString('en')} throws at the default panel, each method at 30/60/120/240 Hz`,
    subtitle: 'cost = ns per ball-step × rate; labels: step rate, Hz; ringed: the Pareto front (nothing else is both cheaper and more accurate)',
  },
  hconcat: [
    panel('seq', 'frontSeq', 'Event sequence against the exact reference', false),
    panel('pos', 'frontPos', 'Where the ball ends (symlog)', true),
  ],
  resolve: { scale: { color: 'shared', shape: 'shared' } },
  config: { font: 'sans-serif', background: 'white' },
} as unknown as TopLevelSpec
writeFileSync(join(outDir(), 'figures', 'accuracy-vs-speed.svg'), await renderSvg(spec))

const f = (x: number, d = 2) => (x === 0 ? '0' : Math.abs(x) < 1e-3 ? x.toExponential(0) : x.toFixed(d))
console.log('\n| method | Hz | events differ | outcome differs | δ err mean / max, px | v err mean / max, px/s | final pos err mean / p95 / max, px | ns per ball-step | × exact | µs per ball-second |')
console.log('|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|')
for (const r of rows) {
  console.log(
    `| ${r.method}${frontSeq.has(r) ? ' ★' : ''} | ${r.hz} | ${(100 * r.sequenceDiffers).toFixed(2)} % | ${(100 * r.outcomeDiffers).toFixed(2)} % | ` +
      `${f(r.deltaErrMean, 3)} / ${f(r.deltaErrMax, 1)} | ${f(r.speedErrMean)} / ${f(r.speedErrMax, 1)} | ` +
      `${f(r.posErrMean)} / ${f(r.posErrP95)} / ${f(r.posErrMax, 0)} | ${r.nsPerBallStep.toFixed(0)} | ${r.ratioToExact!.toFixed(1)} | ${((r.nsPerBallStep * r.hz) / 1000).toFixed(1)} |`,
  )
}
