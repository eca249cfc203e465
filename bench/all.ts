// npm run bench: every benchmark, each in a Node process of its own (pipeline, scale, peers, contacts, pairing,
// contact-accuracy, first-contact, passes, piles, pile-strike, rows, piston-rows, horizon, the adversarial suite's long version, resting, recycling, dense, big-hole, solver, then
// the physical reference's fidelity against cost, the independent model's map and the tick-sampled methods'
// accuracy), then
// a summary of the results files with the floors checked. The floors print PASS or FAIL; they are not
// assertions (the machine is shared and noisy), so the exit status only says whether every benchmark ran.
//
//   npm run bench                  full run: writes docs/results/*.json and docs/figures/*.svg
//   npm run bench -- --quick       (or npm run bench:quick) no 1M rows (scale up to 100k balls, 100k resting
//                                  balls), 2,500-ball piles, 8 accuracy seeds, the adversarial suite at 2×;
//                                  writes under test-artifacts/bench-quick/, leaving docs/ alone
//   npm run bench -- --out DIR     results under DIR/results and DIR/figures
import { spawnSync } from 'node:child_process'
import { readFileSync } from 'node:fs'
import { join } from 'node:path'
import type { AccuracyPoint, ContactRow, PeerRow, PileRow, ScaleRow } from './charts'
import { argValue } from './lib'

const quick = process.argv.includes('--quick')
const out = argValue('--out') ?? (quick ? 'test-artifacts/bench-quick' : 'docs')

const benches: [string, string[]][] = [
  ['bench/pipeline.ts', []],
  ['bench/scale.ts', quick ? ['--max', '100000'] : []],
  ['bench/peers.ts', []],
  ['bench/contacts.ts', []],
  ['bench/pairing.ts', []],
  ['bench/contactAccuracy.ts', quick ? ['--seeds', '8'] : []],
  ['bench/firstContact.ts', quick ? ['--scenes', '1000'] : []],
  ['bench/passes.ts', quick ? ['--scenes', '200'] : []],
  ['bench/piles.ts', quick ? ['--balls', '2500'] : []],
  ['bench/pileStrike.ts', []],
  ['bench/rows.ts', []],
  ['bench/pistonRows.ts', []],
  ['bench/horizon.ts', []],
  ['bench/adversarial.ts', quick ? ['--scale', '2'] : []],
  ['bench/resting.ts', quick ? ['--resting', '100000'] : []],
  ['bench/recycling.ts', quick ? ['--throws', '100000'] : []],
  ['bench/dense.ts', []],
  ['bench/bigHole.ts', []],
  ['bench/solver.ts', []],
  // the physical reference against the game models (fidelity against cost), the independent rigid-sphere
  // model against both, and the tick-sampled methods' accuracy against speed: scripts, also run on their
  // own (npm run physical, npm run independent, npm run accuracy)
  ['scripts/physical.ts', []],
  ['scripts/independent.ts', []],
  ['scripts/accuracy.ts', []],
]
const failed: string[] = []
for (const [entry, args] of benches) {
  console.log(`\n== ${entry} ${args.join(' ')}`.trimEnd())
  const t0 = Date.now()
  const r = spawnSync(process.execPath, ['--expose-gc', 'scripts/run-ts.mjs', entry, ...args, '--out', out], { stdio: 'inherit' })
  if (r.status !== 0) failed.push(entry)
  console.log(`   (${((Date.now() - t0) / 1000).toFixed(0)} s)`)
}

/**
 * A benchmark's results file, if that benchmark ran to the end in this run (the adversarial suite's also when
 * it exits with a failure: its file then says which test failed).
 */
const read = <T>(name: string): T | undefined => {
  if (failed.includes(`bench/${name}.ts`) && name !== 'adversarial') return undefined
  try {
    return JSON.parse(readFileSync(join(out, 'results', `${name}.json`), 'utf8')) as T
  } catch {
    return undefined
  }
}
interface RestingRow {
  contacts: string
  moving: number
  resting: number
  restingInReach: number
  nsPerStep: { alone: number; inReach: number; all: number }
  ratio: number
  ratioToInReach: number
  contactsDuringRun: { alone: number; inReach: number; all: number }
  wokenDuringRun: { all: number }
}
const pipeline = read<{ balls: number; nsPerBallStep: Record<string, number>; ratioToBare: Record<string, number>; ratioToPlain: Record<string, number> }>('pipeline')
const scale = read<{ rows: ScaleRow[] }>('scale')
const peers = read<{ rows: PeerRow[] }>('peers')
const resting = read<{ rows: RestingRow[] }>('resting')
const contacts = read<{ rows: ContactRow[] }>('contacts')
const accuracy = read<{ points: AccuracyPoint[] }>('contact-accuracy')
const piles = read<{ balls: number; rows: PileRow[] }>('piles')
const rowsBench = read<{ struck: { settings: number; passes: number; deeperThan1e3From05s: number; deepestFrom05s: number }; pressed: { rows: number; deeperThan1e3From05s: number; deepestFrom05s: number } }>('rows')
const dense = read<{ rows: { balls: number; ordered: number; scattered: number }[]; growth100kOver10k: { ordered: number; scattered: number } }>('dense')
const adversarial = read<{ scale: number; seconds: number; vitestExit: number | null; properties: Record<string, { passed: boolean; runs: number; steps: number; slowestStepMs: number }> }>('adversarial')

const k = (n: number) => n.toLocaleString('en-US')
const f = (v: number) => (v >= 100 ? k(Math.round(v)) : v.toFixed(1))
const x = (v: number) => `${v >= 10 ? v.toFixed(0) : v.toFixed(2)}×`

console.log(`\n== summary (${join(out, 'results')}, one run; ns per ball-step unless said otherwise)`)
if (pipeline) {
  const p = pipeline.nsPerBallStep
  const q = pipeline.ratioToPlain
  const b = pipeline.ratioToBare
  console.log(`\npipeline, ${k(pipeline.balls)} balls: bare loop ${p.bareLoop!.toFixed(2)}, plain loop ${p.plainLoop!.toFixed(2)}; open field ${p.openField!.toFixed(2)} (${x(b.openField!)} bare, ${x(q.openField!)} plain), slow balls without deceleration ${p.openFieldSlow!.toFixed(2)} (${x(b.openFieldSlow!)} bare), default panel ${p.panel!.toFixed(2)} (${x(b.panel!)} bare, ${x(q.panel!)} plain)`)
}
if (dense) {
  const g = dense.growth100kOver10k
  console.log(`\ndense events with recycling (ns per ball-step; in brackets with the moving balls' id order held off)`)
  for (const r of dense.rows) console.log(`${k(r.balls).padStart(9)} balls  ${r.ordered.toFixed(1).padStart(6)}  (${r.scattered.toFixed(1)})`)
  console.log(`  100,000 / 10,000: ${x(g.ordered)} (${x(g.scattered)})`)
}
if (scale) {
  console.log('\nscaling (ours beside a plain loop over the same typed arrays that only moves the balls, same run)')
  console.log('    balls   holes   ours ns   plain ns   ours/plain   heap B/ball')
  for (const r of scale.rows) {
    console.log(
      `${k(r.balls).padStart(9)} ${k(r.holes).padStart(7)} ${r.ours.toFixed(2).padStart(9)} ${r.plain.toFixed(2).padStart(10)} ${x(r.ratio).padStart(12)} ${Math.round(r.heapBytesPerBall).toString().padStart(13)}`,
    )
  }
}
if (peers) {
  console.log('\npeers on the same scene (ratio peer / ours, same run)')
  console.log('  balls  contacts      ours   matter-js      planck    rapier2d')
  for (const r of peers.rows) {
    const cell = (v: number, ratio: number) => `${f(v)} (${x(ratio)})`.padStart(16)
    console.log(`${k(r.balls).padStart(7)}  ${r.contacts.padEnd(8)} ${f(r.ours).padStart(7)} ${cell(r.matter, r['matter/ours'])} ${cell(r.planck, r['planck/ours'])} ${cell(r.rapier, r['rapier/ours'])}`)
  }
}
if (resting) {
  console.log('\nresting balls (ns per step: 1k moving alone, beside the resting balls within their reach, beside all the resting balls)')
  console.log('contacts      alone    in reach   all resting   all/alone   all/in reach   contacts alone/reach/all   woken')
  for (const r of resting.rows) {
    console.log(
      `${r.contacts.padEnd(8)} ${k(Math.round(r.nsPerStep.alone)).padStart(10)} ${k(Math.round(r.nsPerStep.inReach)).padStart(11)} ${k(Math.round(r.nsPerStep.all)).padStart(13)} ${x(r.ratio).padStart(11)} ${x(r.ratioToInReach).padStart(14)}   ${`${r.contactsDuringRun.alone}/${r.contactsDuringRun.inReach}/${r.contactsDuringRun.all}`.padEnd(24)} ${String(r.wokenDuringRun.all).padStart(5)}   (${k(r.resting)} resting)`,
    )
  }
}

if (contacts) {
  console.log('\ncontacts on (ns per live ball-step from the mean step; ratio rapier / fixed-tick at its default tick; worst step ms; µs per contact)')
  console.log('scene  balls     fixed  fixed 1/240   exact   rapier  matter   planck  rapier/fixed  worst fixed/exact/rapier   µs/contact fixed/exact')
  for (const r of contacts.rows) {
    console.log(
      `${r.scene.padEnd(6)} ${k(r.balls).padStart(6)} ${f(r.fixed).padStart(9)} ${f(r.fixed240).padStart(12)} ${f(r.exact).padStart(7)} ${f(r.rapier).padStart(8)} ${f(r.matter).padStart(7)} ${f(r.planck).padStart(8)} ${x(r.rapier / r.fixed).padStart(13)}  ${`${f(r.worstMs.fixed)}/${f(r.worstMs.exact)}/${f(r.worstMs.rapier)}`.padStart(23)}   ${f(r.usPerContact.fixed)}/${f(r.usPerContact.exact)}`,
    )
  }
}
if (accuracy) {
  console.log('\ncontact methods against the exact one (share of balls ending in the same hole, or out, or at rest; cost ns per ball-step)')
  for (const p of accuracy.points) console.log(`${p.scene.padEnd(9)} ${p.method.padEnd(30)} ${(100 * p.agreement).toFixed(1).padStart(6)} %   distribution error ${(100 * p.holeError).toFixed(1).padStart(4)} %   ${f(p.ns).padStart(5)} ns`)
}
if (piles) {
  console.log(`\narcade abuse (${k(piles.balls)} balls; worst and mean step, ms)`)
  for (const r of piles.rows) {
    console.log(`${r.scene.padEnd(12)} ${r.method.padEnd(6)} worst ${f(r.worstStepMs).padStart(7)}  mean ${f(r.meanStepMs).padStart(7)}  steps ${r.steps}${r.stoppedEarly ? ' (stopped: a step over 5 s)' : ''}  deepest overlap at the end ${r.deepestOverlapPx.toExponential(1)} px, at any step ${r.deepestAnyStepPx.toExponential(1)} px, a pair over 1e-3 px for ${r.longestOverS.toFixed(3)} s at most`)
  }
}

if (rowsBench) {
  const { struck, pressed } = rowsBench
  console.log('\nrows struck end on, fixed tick (settings failing; deepest overlap from 0.5 s)')
  console.log(`struck, radius 0.5   ${struck.settings} settings: a ball passes another in ${struck.passes}, over 1e-3 px in ${struck.deeperThan1e3From05s} (deepest ${struck.deepestFrom05s.toExponential(1)} px)`)
  console.log(`pressed, radius 11   ${pressed.rows} rows: over 1e-3 px in ${pressed.deeperThan1e3From05s} (deepest ${pressed.deepestFrom05s.toExponential(1)} px)`)
}

if (adversarial) {
  console.log(`\nadversarial suite, long version (${adversarial.scale}× the runs of npm test, other seeds, ${adversarial.seconds.toFixed(0)} s)`)
  for (const [name, r] of Object.entries(adversarial.properties)) {
    console.log(`${r.passed ? 'pass' : 'FAIL'}  ${name.padEnd(24)} ${String(r.runs).padStart(5)} runs  ${String(r.steps).padStart(7)} steps  slowest step ${r.slowestStepMs.toFixed(0)} ms`)
  }
  if (adversarial.vitestExit !== 0 && Object.values(adversarial.properties).every((r) => r.passed)) console.log(`FAIL  a named counterexample (vitest exited with ${adversarial.vitestExit}; see its output above)`)
}

console.log('\nfloors (checked, not asserted)')
const check = (ok: boolean | undefined, text: string) => console.log(`${ok === undefined ? 'SKIP' : ok ? 'PASS' : 'FAIL'}  ${text}`)
const row100k = scale?.rows.find((r) => r.balls === 100_000 && r.holes === 25)
check(row100k && row100k.ours <= 12, `100k balls over 25 holes: ${row100k ? row100k.ours.toFixed(2) : '?'} ns per ball-step (floor ≤ 12)`)
check(row100k && row100k.ratio <= 4, `100k balls over 25 holes: ${row100k ? x(row100k.ratio) : '?'} the plain loop (floor ≤ 4×)`)
const peer10k = peers?.rows.find((r) => r.balls === 10_000 && r.contacts === 'off')
check(peer10k && peer10k['rapier/ours'] >= 50, `10k balls: ${peer10k ? x(peer10k['rapier/ours']) : '?'} faster than rapier2d-compat (floor ≥ 50×)`)
check(peer10k && peer10k['matter/ours'] >= 100, `10k balls: ${peer10k ? x(peer10k['matter/ours']) : '?'} faster than matter-js (floor ≥ 100×)`)
// contacts on: the floors hold for the method the README picks for the scene, the better of the two here
for (const n of [1000, 10_000]) {
  for (const scene of ['gas', 'panel'] as const) {
    const r = contacts?.rows.find((q) => q.balls === n && q.scene === scene)
    const fast = r ? Math.max(r.rapier / r.fixed, r.rapier / r.exact) : undefined
    check(r && fast! >= 5, `contacts on, ${scene}, ${k(n)} balls: ${r ? `fixed-tick ${x(r.rapier / r.fixed)}, exact ${x(r.rapier / r.exact)}` : '?'} faster than rapier2d-compat (floor ≥ 5×, the better method)`)
    const us = r ? Math.min(r.usPerContact.fixed, r.usPerContact.exact) : undefined
    const least = r?.usPerContactLeast ? ` (fastest rounds ${r.usPerContactLeast.fixed.toFixed(1)}, ${r.usPerContactLeast.exact.toFixed(1)})` : ''
    check(r && us! <= 3, `contacts on, ${scene}, ${k(n)} balls: ${r ? `fixed-tick ${r.usPerContact.fixed.toFixed(1)}, exact ${r.usPerContact.exact.toFixed(1)}${least}` : '?'} µs per contact, median of the rounds (floor ≤ 3, the better method)`)
    // what no method that looks at every moving ball each tick can beat: the barest loop that only pairs them
    const bare = r?.barePairing
    if (bare) console.log(`      the barest loop pairing the moving balls each tick, alone: ${bare.usPerContact.toFixed(1)} µs per contact (${bare.nsPerMovingBall.toFixed(0)} ns a moving ball); the fixed tick's extra time ${x(bare.fixedExtraOverBare)} that loop's`)
  }
}
// the core near the memory limit, and the reference-tabulated rim model
const b = pipeline?.ratioToBare
check(b && b.openFieldSlow! <= 3, `sparse events (slow balls, no deceleration), ${pipeline ? k(pipeline.balls) : '?'} balls: ${b ? x(b.openFieldSlow!) : '?'} the bare two-array loop (floor ≤ 3×)`)
check(dense && dense.growth100kOver10k.ordered <= 2, `dense events with recycling: 100k balls ${dense ? x(dense.growth100kOver10k.ordered) : '?'} the cost per ball-step of 10k (floor ≤ 2×)`)
const physical = read<{ agreement: { model: string; agreement: number }[]; costPerRimContactUs: { wholeContact: Record<string, number> } }>('physical')
const independent = read<{ agreement: { model: string; agreement: number }[] }>('independent')
const tabRef = physical?.agreement.find((a) => a.model === 'tabulated')?.agreement
const tabInd = independent?.agreement.find((a) => a.model === 'tabulated')?.agreement
const cost = physical?.costPerRimContactUs.wholeContact
const pc = (v: number | undefined) => (v === undefined ? '?' : `${(100 * v).toFixed(2)} %`)
check(tabRef === undefined ? undefined : tabRef >= 0.99, `tabulated rim model: ${pc(tabRef)} agreement with the live reference on the 180 × 200 grid (floor ≥ 99 %)`)
check(tabInd === undefined ? undefined : tabInd >= 0.97, `tabulated rim model: ${pc(tabInd)} agreement with the independent rigid-sphere model at v ≤ 700 px/s (floor ≥ 97 %)`)
check(cost && cost.tabulated! / cost.design! <= 1.3, `tabulated rim model: ${cost ? x(cost.tabulated! / cost.design!) : '?'} the design's cost per rim contact (floor ≤ 1.3×)`)
const million = scale?.rows.filter((r) => r.balls === 1_000_000) ?? []
if (million.length === 0) check(undefined, `1M balls: heap per ball not measured (${quick ? 'quick mode' : 'no 1M rows'}; floor < 450 B)`)
for (const r of million) check(r.heapBytesPerBall < 450, `1M balls over ${k(r.holes)} holes: ${r.heapBytesPerBall.toFixed(1)} B of heap per ball (floor < 450; balls are bitECS entities)`)
const recycling = read<{ throws: number; peakLive: number; samples: { thrown: number; heapBytes: number }[] }>('recycling')
if (recycling) {
  // bounded: the second half of the throws adds (next to) nothing
  const half = recycling.samples[Math.floor((recycling.samples.length - 1) / 2)]!
  const last = recycling.samples.at(-1)!
  const growth = last.heapBytes / half.heapBytes
  check(
    growth <= 1.25,
    `${k(recycling.throws)} throws with recycling: heap ${(last.heapBytes / 1024).toFixed(0)} KiB at the end, ${x(growth)} that at ${k(half.thrown)} throws (peak ${k(recycling.peakLive)} live; bounded: ≤ 1.25×)`,
  )
}

// kept-pair lists against the bare grid (bench/pairing.ts): the pairing a method could keep from tick to tick
const pairing = read<{ rows: { scene: string; balls: number; overGrid: Record<string, number> }[] }>('pairing')
if (pairing) {
  console.log('\npairs kept across ticks against the bare grid of every tick (time ÷ the grid\'s, same run; bench/pairing.ts)')
  for (const r of pairing.rows) {
    const kept = Object.entries(r.overGrid).filter(([name]) => name !== 'grid')
    const best = kept.reduce((a, b) => (b[1] < a[1] ? b : a))
    console.log(`${r.scene.padEnd(6)} ${k(r.balls).padStart(6)}  ${kept.map(([name, v]) => `${name} ${x(v)}`).join(', ')}; the best, ${best[0]}, ${x(best[1])}`)
  }
}

if (failed.length > 0) {
  console.error(`\nbenchmarks that failed or did not finish: ${failed.join(', ')}`)
  process.exit(1)
}
