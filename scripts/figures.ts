// The design's figures, drawn from the engine and the closed forms of src/geometry.ts:
//   docs/figures/regime-map.svg   outcomes of a dense (δ, v) grid shot at one hole by the engine, with the
//                                 closed-form boundaries drawn over them
//   docs/figures/skip-over.svg    the skip-over chord, and the parallel capture and skip curves
//   docs/figures/cog-geometry.svg the ball and hole at five path offsets, showing the COG gate
//   npm run figures
import { mkdirSync, writeFileSync } from 'node:fs'
import type { TopLevelSpec } from 'vega-lite'
import { createBallPhysics, resolveConfig } from '../src/index'
import { cogRadius, popArc, rollRatioDelta, vSkip } from '../src/geometry'
import { renderSvg } from './vegaSvg'

const cfg = resolveConfig()
const R = cfg.HOLE_RADIUS
const r = cfg.BALL_RADIUS
const A = cfg.ROLLING_DECEL
const RHO_C = cogRadius(R, r)
const DELTA_ROLL = rollRatioDelta(R, r, cfg.RIM_ROLL_RATIO)
const vCapture = (delta: number) => cfg.V_MAX * Math.sqrt(Math.max(0, 1 - (delta * delta) / (R * R))) // δ = δ_eff(v), solved for v
const skip = (delta: number) => vSkip(delta, R, r, cfg.GRAVITY)
const OUTCOMES = ['skip', 'clean capture', 'bounce', 'rim roll → drop', 'rim roll → pop off'] as const
const COLORS = ['#9ecae1', '#74c476', '#fdae6b', '#6a51a3', '#e7298a']
const range = (a: number, b: number, n: number) => Array.from({ length: n + 1 }, (_, i) => a + ((b - a) * i) / n)
const circle = (cx: number, cy: number, rad: number, extra: Record<string, unknown> = {}, n = 120) =>
  range(0, 2 * Math.PI, n).map((t, i) => ({ x: cx + rad * Math.cos(t), y: cy + rad * Math.sin(t), i, ...extra }))

/** The engine's outcome for a ball crossing the lip at offset δ with speed v (hole at the origin, ball along +x). */
function outcome(delta: number, v: number): (typeof OUTCOMES)[number] | 'none' {
  const sim = createBallPhysics()
  sim.addHole({ x: 0, y: 0 })
  const lead = 60
  sim.addBall({ x: -Math.sqrt(R * R - delta * delta) - lead, y: delta, vx: Math.sqrt(v * v + 2 * A * lead), vy: 0 })
  const types: string[] = []
  for (let i = 0; i < 200 && sim.world.moving.count > 0; i++) {
    sim.step(0.05)
    for (const e of sim.drainEvents()) types.push(e.via ? `${e.type}:${e.via}` : e.type)
  }
  const first = types.find((t) => t !== 'nearMiss')
  if (first === 'skip') return 'skip'
  if (first === 'capture:clean') return 'clean capture'
  if (first === 'bounce') return 'bounce'
  if (first === 'rimRoll') return types.includes('lipOut') ? 'rim roll → pop off' : 'rim roll → drop'
  return 'none'
}

// ---- regime map ----
const D_STEP = 0.2
const V_STEP = 4
const cells: { d0: number; d1: number; v0: number; v1: number; outcome: string }[] = []
for (let d = D_STEP / 2; d < R; d += D_STEP) {
  for (let v = V_STEP / 2; v < 720; v += V_STEP) {
    const o = outcome(d, v)
    if (o !== 'none') cells.push({ d0: d - D_STEP / 2, d1: d + D_STEP / 2, v0: v - V_STEP / 2, v1: v + V_STEP / 2, outcome: o })
  }
}
const counts = Object.fromEntries(OUTCOMES.map((o) => [o, cells.filter((c) => c.outcome === o).length]))
console.log(`regime map: ${cells.length} cells`, counts)

// drop/pop split: the lip speed whose tangential speed at the contact circle is v_t* = v_drop + μ·arc_pop
const vtSplit = cfg.RIM_ROLL_DROP_SPEED + cfg.RIM_ROLL_FRICTION * popArc(cfg.RIM_ROLL_MAX_TURNS, R)
const splitAt = (delta: number) => {
  const vc = (vtSplit * RHO_C) / delta
  const ds = Math.sqrt(R * R - delta * delta) - Math.sqrt(RHO_C * RHO_C - delta * delta)
  return Math.sqrt(vc * vc + 2 * A * ds)
}
const curves = [
  ...range(0, R, 180).map((d) => ({ d, v: skip(d), curve: 'v_skip(δ) = R·√(2g/r)·√(1 − δ²/R²)' })),
  ...range(0, R, 180).map((d) => ({ d, v: vCapture(d), curve: 'δ = δ_eff(v) = R·√(1 − (v/V_MAX)²)' })),
  ...range(DELTA_ROLL, RHO_C, 40).map((d) => ({ d, v: splitAt(d), curve: `drop/pop split: v_t at ρ_c = ${vtSplit.toFixed(1)} px/s` })),
  { d: RHO_C, v: 0, curve: 'COG gate δ = R − r/2' },
  { d: RHO_C, v: 720, curve: 'COG gate δ = R − r/2' },
  { d: DELTA_ROLL, v: 0, curve: 'roll ratio |v_t|/|v_n| = 1.4 at ρ_c' },
  { d: DELTA_ROLL, v: 720, curve: 'roll ratio |v_t|/|v_n| = 1.4 at ρ_c' },
]
const regimeSpec = {
  $schema: 'https://vega.github.io/schema/vega-lite/v6.json',
  title: {
    text: 'Regime map: the engine’s outcome at each (δ, v) at the lip, with the closed-form boundaries',
    subtitle: `one hole, R = ${R} px, r = ${r} px; ${cells.length.toLocaleString('en')} shots on a ${D_STEP} px × ${V_STEP} px/s grid`,
  },
  width: 620,
  height: 460,
  layer: [
    {
      data: { values: cells },
      mark: { type: 'rect' },
      encoding: {
        x: { field: 'd0', type: 'quantitative', title: 'δ, offset of the path from the hole centre, px', scale: { domain: [0, R] } },
        x2: { field: 'd1' },
        y: { field: 'v0', type: 'quantitative', title: 'v, speed at the lip, px/s', scale: { domain: [0, 720], nice: false } },
        y2: { field: 'v1' },
        color: { field: 'outcome', type: 'nominal', title: 'engine outcome', scale: { domain: OUTCOMES, range: COLORS } },
      },
    },
    {
      data: { values: curves },
      mark: { type: 'line', strokeWidth: 1.6, clip: true },
      encoding: {
        x: { field: 'd', type: 'quantitative' },
        y: { field: 'v', type: 'quantitative' },
        detail: { field: 'curve' },
        strokeDash: { field: 'curve', type: 'nominal', title: 'closed form (src/geometry.ts)', legend: { labelLimit: 320, titleLimit: 320, symbolStrokeColor: '#111' } },
        color: { value: '#111' },
      },
    },
  ],
  config: { font: 'sans-serif', background: 'white' },
} as unknown as TopLevelSpec

// ---- skip-over geometry ----
const DELTA = 8
const half = Math.sqrt(R * R - DELTA * DELTA)
const shapes = [
  ...circle(0, 0, R, { part: 'hole (R)' }),
  ...circle(-half, DELTA, r, { part: 'ball at entry (r)' }),
  ...circle(half, DELTA, r, { part: 'ball at exit' }),
]
const chord = [
  { x: -half - 30, y: DELTA, part: 'path' },
  { x: half + 30, y: DELTA, part: 'path' },
]
const notes = [
  { x: 0, y: DELTA + 2.2, text: `chord 2√(R² − δ²) = ${(2 * half).toFixed(1)} px` },
  { x: 1.5, y: DELTA / 2, text: `δ = ${DELTA} px` },
  { x: 0, y: -R - 4, text: 'skip iff chord time 2√(R² − δ²)/v < √(2r/g), time to fall by r' },
]
const band = range(0, R, 180).map((d) => ({ d, lo: vCapture(d), hi: skip(d) }))
const skipSpec = {
  $schema: 'https://vega.github.io/schema/vega-lite/v6.json',
  title: { text: 'Stage 5, skip-over: the chord, and the parallel capture and skip curves' },
  hconcat: [
    {
      width: 380,
      height: 380,
      title: 'top view (y down)',
      layer: [
        {
          data: { values: shapes },
          mark: { type: 'line', strokeWidth: 1.5 },
          encoding: {
            x: { field: 'x', type: 'quantitative', scale: { domain: [-32, 32] }, title: 'px' },
            y: { field: 'y', type: 'quantitative', scale: { domain: [32, -32] }, title: 'px' },
            order: { field: 'i' },
            color: {
              field: 'part',
              type: 'nominal',
              title: null,
              scale: { domain: ['hole (R)', 'ball at entry (r)', 'ball at exit'], range: ['#222', '#3182bd', '#9ecae1'] },
            },
          },
        },
        {
          data: { values: chord },
          mark: { type: 'line', strokeDash: [5, 3], color: '#e6550d' },
          encoding: { x: { field: 'x', type: 'quantitative' }, y: { field: 'y', type: 'quantitative' } },
        },
        {
          data: { values: [{ x: 0, y: 0 }, { x: 0, y: DELTA }] },
          mark: { type: 'line', color: '#e6550d' },
          encoding: { x: { field: 'x', type: 'quantitative' }, y: { field: 'y', type: 'quantitative' } },
        },
        {
          data: { values: notes },
          mark: { type: 'text', fontSize: 10, align: 'left', dx: 3 },
          encoding: { x: { field: 'x', type: 'quantitative' }, y: { field: 'y', type: 'quantitative' }, text: { field: 'text' } },
        },
      ],
    },
    {
      width: 380,
      height: 380,
      title: 'the two curves in the (δ, v) plane',
      layer: [
        {
          data: { values: band },
          mark: { type: 'area', color: '#fdae6b', opacity: 0.5 },
          encoding: {
            x: { field: 'd', type: 'quantitative', title: 'δ, px', scale: { domain: [0, R] } },
            y: { field: 'lo', type: 'quantitative', title: 'v at the lip, px/s', scale: { domain: [0, 700] } },
            y2: { field: 'hi' },
          },
        },
        {
          data: {
            values: [
              ...band.map((b) => ({ d: b.d, v: b.hi, curve: `v_skip(δ), V_SKIP_MAX = ${cfg.V_SKIP_MAX}` })),
              ...band.map((b) => ({ d: b.d, v: b.lo, curve: `capture edge, V_MAX = ${cfg.V_MAX}` })),
            ],
          },
          mark: { type: 'line', strokeWidth: 2 },
          encoding: {
            x: { field: 'd', type: 'quantitative' },
            y: { field: 'v', type: 'quantitative' },
            color: { field: 'curve', type: 'nominal', title: null, scale: { range: ['#31a354', '#3182bd'] }, legend: { labelLimit: 300 } },
          },
        },
        {
          data: {
            values: [
              { d: 1, v: 670, text: 'skips (Region 1)' },
              { d: 1, v: 300, text: 'captured clean (Region 4)' },
              { d: 1, v: 617, text: 'rim band' },
            ],
          },
          mark: { type: 'text', align: 'left', fontSize: 11 },
          encoding: { x: { field: 'd', type: 'quantitative' }, y: { field: 'v', type: 'quantitative' }, text: { field: 'text' } },
        },
      ],
    },
  ],
  resolve: { scale: { color: 'independent' } },
  config: { font: 'sans-serif', background: 'white' },
} as unknown as TopLevelSpec

// ---- COG gate at five offsets ----
const OFFSETS = [4, 8, DELTA_ROLL + 1, RHO_C, 15.5]
const cogPanel = (delta: number) => {
  const passes = delta < RHO_C
  const verdict = passes ? (delta > DELTA_ROLL ? 'gate open: can roll' : 'gate open, too head-on to roll') : 'brush: bounces off'
  return {
    width: 170,
    height: 170,
    title: { text: `δ = ${+delta.toFixed(2)} px`, subtitle: verdict, subtitleColor: passes ? '#31a354' : '#de2d26' },
    layer: [
      {
        data: {
          values: [
            ...circle(0, 0, R, { part: 'lip circle R' }),
            ...circle(0, 0, RHO_C, { part: 'contact circle R − r/2' }),
          ],
        },
        mark: { type: 'line' },
        encoding: {
          x: { field: 'x', type: 'quantitative', scale: { domain: [-32, 32] }, axis: null },
          y: { field: 'y', type: 'quantitative', scale: { domain: [32, -32] }, axis: null },
          order: { field: 'i' },
          detail: { field: 'part' },
          strokeDash: { field: 'part', type: 'nominal', title: null, scale: { domain: ['lip circle R', 'contact circle R − r/2'], range: [[1, 0], [4, 3]] } },
          color: { value: '#222' },
        },
      },
      {
        data: { values: [{ x: -32, y: delta }, { x: 32, y: delta }] },
        mark: { type: 'line', color: '#888', strokeDash: [2, 2] },
        encoding: { x: { field: 'x', type: 'quantitative' }, y: { field: 'y', type: 'quantitative' } },
      },
      {
        data: { values: circle(0, delta, r) },
        mark: { type: 'line', color: passes ? '#31a354' : '#de2d26', strokeWidth: 2 },
        encoding: { x: { field: 'x', type: 'quantitative' }, y: { field: 'y', type: 'quantitative' }, order: { field: 'i' } },
      },
      {
        data: { values: [{ x: 0, y: delta }] },
        mark: { type: 'point', filled: true, size: 30, color: passes ? '#31a354' : '#de2d26' },
        encoding: { x: { field: 'x', type: 'quantitative' }, y: { field: 'y', type: 'quantitative' } },
      },
    ],
  }
}
const cogSpec = {
  $schema: 'https://vega.github.io/schema/vega-lite/v6.json',
  title: {
    text: 'Stage 6, the COG gate: the ball at its closest approach on five paths',
    subtitle: `more than half the ball is over the hole only if its centre gets inside R − r/2 = ${RHO_C} px; rolling also needs |v_t|/|v_n| > 1.4 there (δ > ${DELTA_ROLL.toFixed(2)} px)`,
  },
  hconcat: OFFSETS.map(cogPanel),
  config: { font: 'sans-serif', background: 'white', view: { stroke: null } },
} as unknown as TopLevelSpec

mkdirSync('docs/figures', { recursive: true })
writeFileSync('docs/figures/regime-map.svg', await renderSvg(regimeSpec))
writeFileSync('docs/figures/skip-over.svg', await renderSvg(skipSpec))
writeFileSync('docs/figures/cog-geometry.svg', await renderSvg(cogSpec))
console.log('wrote docs/figures/regime-map.svg, skip-over.svg, cog-geometry.svg')
