// The independent rigid-sphere model (src/physical/independent.ts) as a second yardstick (docs/physical.md,
// "An independent model"): its capture map on the (δ, v) cells the game reaches (v ≤ MAX_VY), the agreement
// with it of the design, the physical preset, the tabulated model, the live reference and the hero ball;
// where it and the reference put the capture boundary, row by row; and its own checks (step halving, the
// look-ahead of a lift-off, energy). Writes docs/results/independent.json (under DIR with --out DIR).
//
//   npm run independent
import { mkdirSync, writeFileSync } from 'node:fs'
import { join } from 'node:path'
import { outDir } from '../bench/lib'
import { DEFAULT_CONFIG, type ConfigOverrides } from '../src/config/design'
import { PHYSICAL_CONFIG, TABULATED_CONFIG } from '../src/config/presets'
import { agreement, createShotRig, disagreement, engineMap, gameGrid, gridDelta, gridSpeed, referenceMap, type CaptureMap } from '../src/physical/agreement'
import { INDEPENDENT_STEP, LOOK_AHEAD, MAX_PHASES, MAX_TIME, independentOutcome } from '../src/physical/independent'
import { independentMap, rowBoundaries, rowSwitches } from '../src/physical/independentMap'
import { referenceOutcome } from '../src/reference/index'
import { tabulatedCaptureSpeed } from '../src/reference/rimTables'

const R = DEFAULT_CONFIG.HOLE_RADIUS
const r = DEFAULT_CONFIG.BALL_RADIUS
const G = DEFAULT_CONFIG.GRAVITY
const J = DEFAULT_CONFIG.BALL_INERTIA
const V_TOP = DEFAULT_CONFIG.MAX_VY
/** the fine grid of npm run physical (0.1 px × 4 px/s cells), cut at the game's top throw speed */
const GRID = gameGrid(180, Math.round(V_TOP / 4), R, V_TOP)
/** bisections of a boundary inside its 4 px/s cell: 4 px/s / 2³⁰ ≈ 4e-9 px/s */
const BISECTIONS = 30
/** every this many rows, the boundary is bisected again at half the step */
const HALVING_ROW_STRIDE = 10

const log = (s: string) => console.log(s)
const pct = (x: number) => `${(100 * x).toFixed(2)} %`
const seconds = (t0: number) => (performance.now() - t0) / 1000
const start = performance.now()
const cells = GRID.nDelta * GRID.nSpeed
log(`grid: ${GRID.nDelta} × ${GRID.nSpeed} cell centres, δ in [0, ${R}) px, v in (0, ${V_TOP}] px/s (MAX_VY); R = ${R}, r = ${r} px, g = ${G.toFixed(1)} px/s², j = ${J}`)

// ---- the independent map and the reference's ----
let t0 = performance.now()
const indep = independentMap(GRID, r, G, J)
const indepSeconds = seconds(t0)
log(
  `independent model: ${cells} cells in ${indepSeconds.toFixed(1)} s (${indep.steps} RK4 steps of ${INDEPENDENT_STEP} √(r/g)); ` +
    `${indep.guarded} stopped by a guard (counted as escapes), ${indep.held} held on the lip at least once; largest energy drift on the lip ${indep.energyDrift.toExponential(1)}`,
)
t0 = performance.now()
const ref = referenceMap(GRID, r, G, J)
const refSeconds = seconds(t0)
// the cells the independent model's guard stopped: does the reference's stop them too?
let bothGuarded = 0
for (let c = 0; c < cells; c++) {
  if (indep.guardedCells[c] !== 1) continue
  const i = Math.floor(c / GRID.nSpeed)
  const o = referenceOutcome({ delta: gridDelta(GRID, i), speed: gridSpeed(GRID, c - i * GRID.nSpeed), holeRadius: R, ballRadius: r, gravity: G, inertia: J })
  if (o.ending === 'timeLimit' || o.ending === 'phaseLimit') bothGuarded++
}
log(`reference: ${refSeconds.toFixed(1)} s, ${ref.guarded} stopped by a guard (${bothGuarded} of them cells the independent model's guard stops too)`)

// ---- the models against it ----
interface Row {
  model: string
  label: string
  config?: ConfigOverrides
  agreement: number
  /** cells the model captures and the independent model escapes, and the other way round */
  modelOnlyCaptures: number
  independentOnlyCaptures: number
  agreementWithReference: number
  mapSeconds: number
}
const heroRig = createShotRig()
const heroMap = (): CaptureMap => {
  const map = new Uint8Array(cells)
  for (let i = 0; i < GRID.nDelta; i++) for (let k = 0; k < GRID.nSpeed; k++) map[i * GRID.nSpeed + k] = heroRig.shot(gridDelta(GRID, i), gridSpeed(GRID, k), true) ? 1 : 0
  return map
}
const models: Array<{ key: string; label: string; config?: ConfigOverrides; make: () => CaptureMap }> = [
  { key: 'design', label: 'design: six stages, DEFAULT_CONFIG', config: {}, make: () => engineMap(GRID) },
  { key: 'preset', label: 'physical preset, PHYSICAL_CONFIG', config: PHYSICAL_CONFIG, make: () => engineMap(GRID, PHYSICAL_CONFIG) },
  { key: 'tabulated', label: 'tabulated reference, TABULATED_CONFIG', config: TABULATED_CONFIG, make: () => engineMap(GRID, TABULATED_CONFIG) },
  { key: 'reference', label: 'live reference (referenceOutcome)', make: () => ref.map },
  { key: 'hero', label: 'hero ball (the reference live in the engine)', config: {}, make: heroMap },
]
const table: Row[] = []
const maps: Record<string, CaptureMap> = {}
for (const m of models) {
  t0 = performance.now()
  const map = m.make()
  const mapSeconds = m.key === 'reference' ? refSeconds : seconds(t0)
  maps[m.key] = map
  const d = disagreement(map, indep.map)
  const row: Row = {
    model: m.key,
    label: m.label,
    agreement: agreement(map, indep.map),
    modelOnlyCaptures: d.gameOnly,
    independentOnlyCaptures: d.referenceOnly,
    agreementWithReference: agreement(map, ref.map),
    mapSeconds,
  }
  if (m.config) row.config = m.config
  table.push(row)
}
const heroOnGuarded = (() => {
  let n = 0
  for (let c = 0; c < cells; c++) if (indep.guardedCells[c] === 1 && maps.hero![c] !== indep.map[c]) n++
  return n
})()
log('')
log('| model | agreement with the independent model | model captures, independent escapes | independent captures, model escapes | agreement with the reference |')
log('|---|---:|---:|---:|---:|')
for (const t of table) log(`| ${t.label} | ${pct(t.agreement)} | ${t.modelOnlyCaptures} | ${t.independentOnlyCaptures} | ${pct(t.agreementWithReference)} |`)
log(`(the hero ball differs on ${heroOnGuarded} guarded cells: a hero whose reference run hits a guard is decided by the six stages)`)
log('')

// ---- the boundary, row by row: independent (a) against the reference (b) ----
const input = { delta: 0, speed: 0, holeRadius: R, ballRadius: r, gravity: G, inertia: J }
const indepCaptures = (delta: number, speed: number, step = INDEPENDENT_STEP) => {
  input.delta = delta
  input.speed = speed
  return independentOutcome(input, { step }).captured
}
const refCaptures = (delta: number, speed: number) => {
  input.delta = delta
  input.speed = speed
  return referenceOutcome(input).captured
}
t0 = performance.now()
const rows = rowBoundaries(GRID, indep.map, indepCaptures, ref.map, refCaptures, BISECTIONS)
const boundarySeconds = seconds(t0)
const diffs = rows.flatMap((row) => row.difference ?? [])
const absDiffs = diffs.map(Math.abs).sort((x, y) => x - y)
const sameCells = rows.filter((row) => row.difference !== undefined).length
const multiple = rows.filter((row) => row.a.length > 1 || row.b.length > 1).map((row) => ({ delta: row.delta, independent: row.a, reference: row.b }))
const boundary = {
  bisections: BISECTIONS,
  rowsSwitchingInTheSameCells: sameCells,
  switches: diffs.length,
  maxAbsDifference: absDiffs[absDiffs.length - 1] ?? 0,
  medianAbsDifference: absDiffs[Math.floor(absDiffs.length / 2)] ?? 0,
  rowsWithMoreThanOneSwitch: multiple,
  seconds: boundarySeconds,
}
log(
  `boundary along v (reference − independent), ${diffs.length} switches in ${sameCells} of ${GRID.nDelta} rows switching in the same cells: ` +
    `max |Δv| ${boundary.maxAbsDifference.toExponential(1)} px/s, median ${boundary.medianAbsDifference.toExponential(1)} px/s (bisected to ${(4 / (1 << BISECTIONS)).toExponential(0)} px/s; ${boundarySeconds.toFixed(1)} s)`,
)
for (const m of multiple) log(`  δ = ${m.delta.toFixed(2)} px switches more than once: independent at ${m.independent.map((v) => v.toFixed(2)).join(', ')}, reference at ${m.reference.map((v) => v.toFixed(2)).join(', ')} px/s`)

// the tabulated model's capture speed against the independent boundary (its first switch in each row)
const tabRows = rows
  .filter((row) => row.a.length > 0)
  .map((row) => ({ delta: row.delta, independent: row.a[0]!, tabulated: tabulatedCaptureSpeed(row.delta, R, r, G, J) }))
  .map((x) => ({ ...x, difference: x.tabulated - x.independent }))
const tabAbs = tabRows.map((x) => Math.abs(x.difference)).sort((x, y) => x - y)
log(
  `tabulated v_c − independent boundary over ${tabRows.length} rows: median |Δv| ${tabAbs[Math.floor(tabAbs.length / 2)]!.toFixed(3)} px/s, ` +
    `p90 ${tabAbs[Math.floor(0.9 * (tabAbs.length - 1))]!.toFixed(3)}, max ${tabAbs[tabAbs.length - 1]!.toFixed(3)} px/s`,
)

// ---- the independent model's own checks ----
// step halving: the whole map, and the boundary of every HALVING_ROW_STRIDE-th row
t0 = performance.now()
const half = independentMap(GRID, r, G, J, { step: INDEPENDENT_STEP / 2 })
const halfChanged = cells - Math.round(agreement(half.map, indep.map) * cells)
const halving: Array<{ delta: number; step: number; half: number }> = []
for (let i = 0; i < GRID.nDelta; i += HALVING_ROW_STRIDE) {
  const k = rowSwitches(GRID, indep.map, i)[0]
  if (k === undefined) continue
  const d = gridDelta(GRID, i)
  const lo = gridSpeed(GRID, k)
  const hi = gridSpeed(GRID, k + 1)
  const at = (step: number) => {
    let a = lo
    let b = hi
    const low = indepCaptures(d, a, step)
    for (let n = 0; n < BISECTIONS; n++) {
      const m = 0.5 * (a + b)
      if (indepCaptures(d, m, step) === low) a = m
      else b = m
    }
    return 0.5 * (a + b)
  }
  halving.push({ delta: d, step: at(INDEPENDENT_STEP), half: at(INDEPENDENT_STEP / 2) })
}
const halvingMax = Math.max(...halving.map((x) => Math.abs(x.half - x.step)))
log(
  `step halving (${INDEPENDENT_STEP / 2} √(r/g)): ${halfChanged} cells change; the boundary moves by at most ${halvingMax.toExponential(1)} px/s over ${halving.length} rows (${seconds(t0).toFixed(1)} s)`,
)
// the look-ahead of a lift-off, ×4 and ÷4
t0 = performance.now()
const lookAhead = [LOOK_AHEAD / 4, LOOK_AHEAD * 4].map((a) => {
  const m = independentMap(GRID, r, G, J, { lookAhead: a })
  return { lookAhead: a, changedCells: cells - Math.round(agreement(m.map, indep.map) * cells), held: m.held }
})
log(`look-ahead of a lift-off: ${lookAhead.map((x) => `${x.lookAhead} √(r/g): ${x.changedCells} cells change (${x.held} held)`).join('; ')} (${seconds(t0).toFixed(1)} s)`)

// ---- results ----
const total = seconds(start)
const result = {
  date: new Date().toISOString(),
  node: process.version,
  geometry: { holeRadius: R, ballRadius: r, gravity: G, inertia: J },
  grid: { nDelta: GRID.nDelta, nSpeed: GRID.nSpeed, delta: [0, R], speed: [0, V_TOP], cells: 'cell centres' },
  independent: {
    step: INDEPENDENT_STEP,
    lookAhead: LOOK_AHEAD,
    maxTime: MAX_TIME,
    maxPhases: MAX_PHASES,
    seconds: indepSeconds,
    steps: indep.steps,
    guarded: indep.guarded,
    held: indep.held,
    energyDrift: indep.energyDrift,
    captureShare: indep.map.reduce((a, b) => a + b, 0) / cells,
  },
  reference: { seconds: refSeconds, guarded: ref.guarded, guardedWhereIndependentGuarded: bothGuarded },
  agreement: table,
  heroDifferencesOnGuardedCells: heroOnGuarded,
  boundary,
  boundaryRows: rows.map((row) => ({ delta: row.delta, independent: row.a, reference: row.b, difference: row.difference ?? null })),
  tabulatedCaptureSpeed: { rows: tabRows.length, medianAbs: tabAbs[Math.floor(tabAbs.length / 2)], maxAbs: tabAbs[tabAbs.length - 1], byRow: tabRows },
  convergence: { halfStepChangedCells: halfChanged, halfStepBoundary: halving, halfStepBoundaryMaxShift: halvingMax },
  lookAhead,
  seconds: total,
}
mkdirSync(join(outDir(), 'results'), { recursive: true })
const file = join(outDir(), 'results', 'independent.json')
writeFileSync(file, JSON.stringify(result, null, 2) + '\n')
log(`wrote ${file} (${total.toFixed(0)} s in all)`)
