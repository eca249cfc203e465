// The peers chart (docs/figures/peers.svg): ns per ball-step of each engine on a log scale, one bar per
// scene (balls, contacts off or on), from the rows bench/peers.ts measures.
import type { TopLevelSpec } from 'vega-lite'

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
