// The benchmarks' charts as vega-lite specs, from the rows the benchmarks write to their results files:
// docs/figures/scale.svg (bench/scale.ts) and docs/figures/peers.svg (bench/peers.ts).
import type { TopLevelSpec } from 'vega-lite'

export interface ScaleRow {
  balls: number
  holes: number
  /** ns per ball-step */
  ours: number
  plain: number
  ratio: number
  heapBytesPerBall: number
}

/** ns per ball-step against the number of balls: this module over each hole count, and the plain loop. */
export function scaleFigure(rows: readonly ScaleRow[], steps: number, rounds: number): TopLevelSpec {
  const firstHoles = rows[0]?.holes
  const data = rows.flatMap((r) => [
    { balls: r.balls, series: `this module, ${r.holes.toLocaleString('en-US')} holes`, ns: r.ours },
    ...(r.holes === firstHoles ? [{ balls: r.balls, series: 'plain loop (moves only)', ns: r.plain }] : []),
  ])
  return {
    $schema: 'https://vega.github.io/schema/vega-lite/v6.json',
    title: {
      text: 'Cost per ball-step against the number of balls',
      subtitle: `dt = 1/120 s, median step of ${steps}, median of ${rounds} rounds, one run on a 2-core machine`,
    },
    width: 520,
    height: 300,
    data: { values: data },
    mark: { type: 'line', point: true },
    encoding: {
      x: { field: 'balls', type: 'quantitative', scale: { type: 'log' }, title: 'balls' },
      y: { field: 'ns', type: 'quantitative', title: 'ns per ball-step' },
      color: { field: 'series', type: 'nominal', title: null, legend: { orient: 'top-left', labelLimit: 300 } },
    },
  }
}

export interface PeerRow {
  balls: number
  contacts: 'off' | 'on'
  /** ns per ball-step */
  ours: number
  matter: number
  planck: number
  rapier: number
  'matter/ours': number
  'planck/ours': number
  'rapier/ours': number
}

const ENGINES = [
  ['this module', 'ours'],
  ['matter-js', 'matter'],
  ['planck', 'planck'],
  ['rapier2d-compat', 'rapier'],
] as const

/** ns per ball-step of each engine on a log scale, one bar per scene (balls, contacts off or on). */
export function peersFigure(rows: readonly PeerRow[], steps: number, rounds: number): TopLevelSpec {
  const scenes = rows.map((r) => `${r.balls.toLocaleString('en-US')} balls, contacts ${r.contacts}`)
  const data = rows.flatMap((r, i) => ENGINES.map(([engine, key]) => ({ engine, scene: scenes[i]!, ns: r[key] })))
  const top = 10 ** Math.ceil(Math.log10(Math.max(...data.map((d) => d.ns)) * 1.5))
  return {
    $schema: 'https://vega.github.io/schema/vega-lite/v6.json',
    title: {
      text: 'Cost per ball-step: this module against general 2D engines',
      subtitle: `same scene, dt = 1/120 s, median step of ${steps}, median of ${rounds} rounds, one run on a 2-core machine`,
    },
    width: 560,
    height: 320,
    data: { values: data },
    encoding: {
      x: { field: 'engine', type: 'nominal', sort: ENGINES.map((e) => e[0]), title: null, axis: { labelAngle: 0 } },
      xOffset: { field: 'scene', type: 'nominal', sort: scenes },
      y: { field: 'ns', type: 'quantitative', stack: null, scale: { type: 'log', domain: [1, top] }, title: 'ns per ball-step (log scale)' },
      color: { field: 'scene', type: 'nominal', title: null, sort: scenes, legend: { orient: 'top-left', labelLimit: 300 } },
    },
    layer: [
      { mark: { type: 'bar' } },
      { mark: { type: 'text', dy: -6, fontSize: 9 }, encoding: { text: { field: 'ns', type: 'quantitative', format: '.3~r' } } },
    ],
  }
}

export interface ContactRow {
  scene: 'gas' | 'panel'
  balls: number
  /** ns per ball-step */
  off: number
  exact: number
  fixed: number
  fixed240: number
  rapier: number
  matter: number
  planck: number
  meanLive: Record<string, number>
  /** ns per ball-step from the median step (the fields above: from the mean step), per engine */
  median?: Record<string, number>
  worstMs: { exact: number; fixed: number; fixed240: number; rapier: number; matter: number; planck: number }
  contactsPerStep: { exact: number; fixed: number; fixed240: number }
  usPerContact: { exact: number; fixed: number; fixed240: number }
  /** the same from each method's fastest round against the fastest without contacts (usPerContact: median of the rounds) */
  usPerContactLeast?: { exact: number; fixed: number; fixed240: number }
  /** the measure used before: the median steps' difference over the mean contacts a step */
  usPerContactMedianStep?: { exact: number; fixed: number; fixed240: number }
  /** the barest pairing loop over the same run's moving balls (bench/barePairing.ts), the fixed tick's denominator */
  barePairing?: { usPerStep: number; nsPerMovingBall: number; pairsPerStep: number; usPerContact: number; fixedExtraOverBare: number }
}

const CONTACT_ENGINES = [
  ['ours, fixed 1/120', 'fixed'],
  ['ours, fixed 1/240', 'fixed240'],
  ['ours, exact', 'exact'],
  ['rapier2d-compat', 'rapier'],
  ['matter-js', 'matter'],
  ['planck', 'planck'],
] as const

/** ns per ball-step with ball-ball contacts on, per engine, one bar per scene (log scale). */
export function contactsFigure(rows: readonly ContactRow[], steps: number, rounds: number): TopLevelSpec {
  const scenes = rows.map((r) => `${r.scene}, ${r.balls.toLocaleString('en-US')} balls`)
  const data = rows.flatMap((r, i) => CONTACT_ENGINES.map(([engine, key]) => ({ engine, scene: scenes[i]!, ns: r[key] })))
  const top = 10 ** Math.ceil(Math.log10(Math.max(...data.map((d) => d.ns)) * 1.5))
  return {
    $schema: 'https://vega.github.io/schema/vega-lite/v6.json',
    title: {
      text: 'Ball-ball contacts on: cost per live ball-step against general 2D engines',
      subtitle: `same scenes, dt = 1/120 s, mean step of ${steps}, median of ${rounds} rounds, one run on a 2-core machine`,
    },
    width: 620,
    height: 320,
    data: { values: data },
    encoding: {
      x: { field: 'engine', type: 'nominal', sort: CONTACT_ENGINES.map((e) => e[0]), title: null, axis: { labelAngle: 0 } },
      xOffset: { field: 'scene', type: 'nominal', sort: scenes },
      y: { field: 'ns', type: 'quantitative', stack: null, scale: { type: 'log', domain: [10, top] }, title: 'ns per live ball-step (log scale)' },
      color: { field: 'scene', type: 'nominal', title: null, sort: scenes, legend: { orient: 'top-left', labelLimit: 300 } },
    },
    layer: [
      { mark: { type: 'bar' } },
      { mark: { type: 'text', dy: -6, fontSize: 8 }, encoding: { text: { field: 'ns', type: 'quantitative', format: '.3~r' } } },
    ],
  }
}

export interface AccuracyPoint {
  scene: string
  method: string
  /** ns per ball-step */
  ns: number
  /** share of balls ending where the exact method's do */
  agreement: number
  /** total variation distance of the distribution of ends from the exact method's */
  holeError: number
}

/** A short label for a method of the accuracy chart: the tick of a fixed run, or what the method is. */
function shortLabel(method: string): string {
  const tick = /tick (1\/\d+)/.exec(method)
  if (tick) return `fixed ${tick[1]}`
  if (method.startsWith('exact, spawns')) return 'exact, spawns ±1e-9 px'
  if (method.startsWith('exact')) return 'exact (reference)'
  return method
}

/** Cost against agreement with the exact method, one panel per scene; the fixed ticks joined by a line. */
export function contactAccuracyFigure(points: readonly AccuracyPoint[], seeds: number): TopLevelSpec {
  const values = points.map((p, i) => ({
    ...p,
    order: i,
    label: shortLabel(p.method),
    family: p.method.startsWith('fixed') ? 'fixed tick' : p.method.startsWith('exact') ? 'exact' : 'contacts off',
    agreementPct: 100 * p.agreement,
  }))
  return {
    $schema: 'https://vega.github.io/schema/vega-lite/v6.json',
    title: {
      text: 'Contact methods: cost against agreement of outcomes with the exact method',
      subtitle: `default panel, a burst thrown at once (the third scene into 40 balls at rest), ${seeds} seeds a scene; agreement: share of balls that end in the same hole (or out, or at rest)`,
    },
    data: { values },
    facet: { column: { field: 'scene', type: 'nominal', title: null } },
    spec: {
      width: 300,
      height: 300,
      encoding: {
        x: { field: 'ns', type: 'quantitative', scale: { type: 'log' }, title: 'ns per ball-step (log scale)' },
        y: { field: 'agreementPct', type: 'quantitative', scale: { domain: [50, 100] }, title: 'balls ending where the exact method says, %' },
        color: { field: 'family', type: 'nominal', title: null, legend: { orient: 'bottom' } },
      },
      layer: [
        { transform: [{ filter: "datum.family === 'fixed tick'" }], mark: { type: 'line', strokeDash: [3, 2] }, encoding: { order: { field: 'order', type: 'quantitative' } } },
        { mark: { type: 'point', filled: true, size: 50 } },
        { mark: { type: 'text', align: 'left', dx: 6, dy: 8, fontSize: 9 }, encoding: { text: { field: 'label', type: 'nominal' } } },
      ],
    },
  } as TopLevelSpec
}

/** A row of bench/piles.ts: one scene under one contact method. */
export interface PileRow {
  scene: string
  method: string
  steps: number
  stoppedEarly: boolean
  meanStepMs: number
  worstStepMs: number
  deepestOverlapPx: number
  /** the deepest overlap at any step's end, px */
  deepestAnyStepPx: number
  /** the longest any pair stayed more than 1e-3 px deep, s (steps' ends) */
  longestOverS: number
  contactsPerStep: number
}
