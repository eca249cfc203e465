// Rewrites the README's benchmark tables from docs/results/*.json (the files one `npm run bench` writes), so
// the tables are that run's figures and nothing else. The floors table and the prose around the tables are
// written by hand.
//
//   npm run readme-tables            rewrite README.md
//   node scripts/readme-tables.mjs --check   exit 1 when a table differs from the results (tests/readme.test.ts)
import { readFileSync, writeFileSync } from 'node:fs'

const README = 'README.md'
const result = (name) => JSON.parse(readFileSync(`docs/results/${name}.json`, 'utf8'))

const int = (n) => Math.round(n).toLocaleString('en-US')
const one = (v) => (v >= 100 ? int(v) : v.toFixed(1))
const times = (v) => (v >= 10 ? `${v.toFixed(0)}×` : `${v.toFixed(2)}×`)
const ms = (v) => (v < 100 ? v.toFixed(1) : int(v))

/** The rows of every generated table, keyed by the start of the table's header line. */
export function tables() {
  const out = new Map()

  const pipe = result('pipeline')
  const ns = pipe.nsPerBallStep
  const bare = pipe.ratioToBare
  const plain = pipe.ratioToPlain
  out.set('| scene | ns per ball-step |', [
    `| bare loop that only moves the balls (x += vx·dt, y += vy·dt) | ${ns.bareLoop.toFixed(1)} | 1 | ${(ns.bareLoop / ns.plainLoop).toFixed(2)} |`,
    `| plain typed-array loop that moves the balls with the deceleration | ${ns.plainLoop.toFixed(1)} | ${(ns.plainLoop / ns.bareLoop).toFixed(2)} | 1 |`,
    `| full pipeline, balls rolling over an open field of 25 holes | ${ns.openField.toFixed(1)} | ${bare.openField.toFixed(2)} | ${plain.openField.toFixed(2)} |`,
    `| the same field, slow balls (30–70 px/s) and no rolling deceleration (events sparser still) | ${ns.openFieldSlow.toFixed(1)} | ${bare.openFieldSlow.toFixed(2)} | ${plain.openFieldSlow.toFixed(2)} |`,
    `| full pipeline, all balls thrown at the default panel (events dense) | ${ns.panel.toFixed(1)} | ${bare.panel.toFixed(2)} | ${plain.panel.toFixed(2)} |`,
  ])

  const dense = result('dense')
  out.set('| balls | ns per ball-step |', dense.rows.map((r) => `| ${int(r.balls)} | ${r.ordered.toFixed(1)} (${r.scattered.toFixed(1)}) |`))

  out.set(
    '| balls | holes | this module',
    result('scale').rows.map((r) => `| ${int(r.balls)} | ${int(r.holes)} | ${r.ours.toFixed(1)} | ${r.plain.toFixed(1)} | ${r.ratio.toFixed(2)} | ${int(r.heapBytesPerBall)} |`),
  )

  out.set(
    '| balls | ball-ball contacts | this module |',
    result('peers').rows.map(
      (r) =>
        `| ${int(r.balls)} | ${r.contacts} | ${r.ours.toFixed(1)} ns | ${one(r.matter)} ns (${times(r['matter/ours'])}) | ${one(r.planck)} ns (${times(r['planck/ours'])}) | ${one(r.rapier)} ns (${times(r['rapier/ours'])}) |`,
    ),
  )

  out.set(
    "| scene | balls | `'fixed'` (1/120 s)",
    result('contacts').rows.map((r) => {
      const w = r.worstMs
      const u = r.usPerContact
      return (
        `| ${r.scene} | ${int(r.balls)} | ${r.fixed.toFixed(0)} | ${r.fixed240.toFixed(0)} | ${r.exact.toFixed(0)} | ${one(r.rapier)} (${times(r.rapier / r.fixed)}) | ${one(r.matter)} | ${one(r.planck)} | ` +
        `${ms(w.fixed)} / ${ms(w.exact)} / ${ms(w.rapier)} | ${Math.round(r.contactsPerStep.fixed)} | ${u.fixed.toFixed(1)} / ${u.exact.toFixed(1)} | ` +
        `${r.barePairing.nsPerMovingBall.toFixed(0)} ns, ${r.barePairing.usPerContact.toFixed(1)} µs (${times(r.barePairing.fixedExtraOverBare)}) |`
      )
    }),
  )

  out.set(
    '| scene | method | balls ending as in the exact method |',
    result('contact-accuracy')
      .points.filter((p) => p.method !== 'exact (reference)')
      .map((p) => `| ${p.scene} | ${p.method.replace('tick 1/120 s', 'tick 1/120 s (default)')} | ${(p.agreement * 100).toFixed(1)} % | ${(p.holeError * 100).toFixed(1)} % | ${p.ns.toFixed(0)} |`),
  )

  out.set(
    '| scene | method | worst step, ms |',
    result('piles').rows.map((r) => {
      const d = r.deepestOverlapPx
      const scene = r.scene.replace('burst 10000', 'burst of 10,000').replace('pile e=', 'pile, e = ')
      const a = r.deepestAnyStepPx
      return `| ${scene} | ${r.method} | ${ms(r.worstStepMs)} | ${r.meanStepMs.toFixed(1)} | ${r.steps} | ${d === 0 ? '0' : d.toExponential(1)} | ${a === 0 ? '0' : a.toExponential(1)} | ${r.longestOverS.toFixed(3)} | ${int(r.contactsPerStep)} |`
    }),
  )

  out.set(
    '| ball-ball contacts | 1,000 moving alone |',
    result('resting').rows.map((r) => {
      const n = r.nsPerStep
      const c = r.contactsDuringRun
      return `| ${r.contacts} | ${int(n.alone)} ns | ${int(n.inReach)} ns | ${int(n.all)} ns | ${r.ratio.toFixed(2)}× | ${r.ratioToInReach.toFixed(2)}× | ${int(c.alone)} / ${int(c.inReach)} / ${int(c.all)} | ${r.wokenDuringRun.all} |`
    }),
  )
  return out
}

/** `text` with the body of the table whose header starts with `header` replaced by `rows`. */
function replaceTable(text, header, rows) {
  const at = text.indexOf(`\n${header}`)
  if (at < 0) throw new Error(`README.md has no table whose header starts with ${header}`)
  const separator = text.indexOf('\n', text.indexOf('\n', at + 1) + 1) // end of the separator line
  let end = separator + 1
  while (text.startsWith('|', end)) end = text.indexOf('\n', end) + 1
  return text.slice(0, separator + 1) + rows.map((r) => `${r}\n`).join('') + text.slice(end)
}

export function regenerate(text) {
  let out = text
  for (const [header, rows] of tables()) out = replaceTable(out, header, rows)
  return out
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const before = readFileSync(README, 'utf8')
  const after = regenerate(before)
  if (process.argv.includes('--check')) {
    if (after !== before) {
      console.error('README.md: a benchmark table differs from docs/results/*.json; run npm run readme-tables')
      process.exit(1)
    }
    console.log('README.md: every benchmark table matches docs/results/*.json')
  } else {
    writeFileSync(README, after)
    console.log(after === before ? 'README.md: tables already up to date' : 'README.md: tables rewritten from docs/results/*.json')
  }
}
