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
  rapier: number
  matter: number
  planck: number
  worstMs: { exact: number; fixed: number; rapier: number; matter: number; planck: number }
  contactsPerStep: { exact: number; fixed: number }
  usPerContact: { exact: number; fixed: number }
}

const CONTACT_ENGINES = [
  ['ours, fixed tick', 'fixed'],
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
      text: 'Ball-ball contacts on: cost per ball-step against general 2D engines',
      subtitle: `same scenes, dt = 1/120 s, CONTACT_TICK 1/240 s, median step of ${steps}, median of ${rounds} rounds, one run on a 2-core machine`,
    },
    width: 620,
    height: 320,
    data: { values: data },
    encoding: {
      x: { field: 'engine', type: 'nominal', sort: CONTACT_ENGINES.map((e) => e[0]), title: null, axis: { labelAngle: 0 } },
      xOffset: { field: 'scene', type: 'nominal', sort: scenes },
      y: { field: 'ns', type: 'quantitative', stack: null, scale: { type: 'log', domain: [10, top] }, title: 'ns per ball-step (log scale)' },
      color: { field: 'scene', type: 'nominal', title: null, sort: scenes, legend: { orient: 'top-left', labelLimit: 300 } },
    },
    layer: [
      { mark: { type: 'bar' } },
      { mark: { type: 'text', dy: -6, fontSize: 8 }, encoding: { text: { field: 'ns', type: 'quantitative', format: '.3~r' } } },
    ],
  }
}
