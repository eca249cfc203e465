// The adversarial suite's long version: tests/adversarial.test.ts with every property run
// ADVERSARIAL_SCALE times as often (default 10) on other seeds, under vitest in a process of its own.
// Prints each property's result, runs, slowest step and slowest runs (in development-machine ms, against the
// run budget), and writes docs/results/adversarial.json. A run that failed its time budget was stopped where
// it crossed it; the suite runs it again (as drawn) without the run budget and this prints how long it took.
// A property whose slowest run stepped more than half its budget keeps that run's calls (a repro to paste
// into a script) as `slowestRunCalls` in the results file.
//
//   npm run bench:adversarial [-- --scale 10]
import { spawnSync } from 'node:child_process'
import { mkdirSync, readFileSync } from 'node:fs'
import { join } from 'node:path'
import { argValue, outDir, writeResult } from './lib'

const scale = Number(argValue('--scale') ?? 10)
const dir = join('test-artifacts', 'adversarial')
mkdirSync(dir, { recursive: true })
const file = join(dir, 'report.json')
const t0 = Date.now()
const run = spawnSync(process.platform === 'win32' ? 'npx.cmd' : 'npx', ['vitest', 'run', 'tests/adversarial.test.ts'], {
  env: { ...process.env, ADVERSARIAL_SCALE: String(scale), ADVERSARIAL_REPORT: file },
  stdio: ['ignore', 'pipe', 'pipe'],
  encoding: 'utf8',
})
const seconds = (Date.now() - t0) / 1000
/** a failing run run again to its end (tests/adversarial.test.ts, runToEnd) */
type ToEnd = { ms: number; devMs: number; overBudget: number; steps: number; ticks: number; time: number; stopped: string | null }
let report: Record<string, { passed: boolean; numRuns: number; runs: number; discarded: number; steps: number; slowestStepMs: number; firstFailure?: string | null; runBudgetDevMs?: number; slowestRunsDevMs?: number[]; runsOverHalfBudget?: number; slowestRunCalls?: string; budgetRechecks?: { over: number; within: number }; firstFailureToEnd?: ToEnd | null; failure: string | null }> = {}
try {
  report = JSON.parse(readFileSync(file, 'utf8'))
} catch {
  console.error(run.stdout?.slice(-4000), run.stderr?.slice(-4000))
  throw new Error('the adversarial suite wrote no report')
}
for (const [name, r] of Object.entries(report)) {
  console.log(`${r.passed ? 'pass' : 'FAIL'}  ${name.padEnd(24)} ${String(r.runs).padStart(5)} runs  ${String(r.steps).padStart(7)} steps  slowest step ${r.slowestStepMs.toFixed(0).padStart(5)} ms${r.slowestRunsDevMs?.length ? `  slowest runs ${r.slowestRunsDevMs.join(', ')} ms dev. (budget ${r.runBudgetDevMs}; ${r.runsOverHalfBudget} runs over half${r.slowestRunCalls ? '; the slowest one\'s calls: slowestRunCalls in the results file' : ''})` : ''}${r.budgetRechecks && r.budgetRechecks.over > 0 ? `  (${r.budgetRechecks.over} runs over a budget at the start's scale, ${r.budgetRechecks.within} of them within at the scale measured then)` : ''}${r.failure ? `\n      ${r.failure.split('\n').filter((l, i) => i < 3 || l.startsWith('Got ')).join('\n      ')}${r.firstFailure ? `\n      the first failing run, before shrinking: ${r.firstFailure}` : ''}${toEnd(r.firstFailureToEnd)}` : ''}`)
}
/**
 * A run over its budget is stopped where it crosses it, so the time it fails with is always just over the
 * budget: what the same calls take to their end (tests/adversarial.test.ts, runToEnd) says how far over.
 */
function toEnd(e: ToEnd | null | undefined): string {
  if (!e) return ''
  const how = e.stopped === null ? `to its end (${e.steps} steps, ${e.time.toFixed(3)} s simulated, ${e.ticks} contact ticks)` : `until stopped after ${e.steps} steps: ${e.stopped}`
  return `\n      that run as drawn, run again without the run budget ${how}: ${e.ms} ms, ${e.devMs} ms dev. (${e.overBudget}× the run budget)`
}
const failed = Object.entries(report).filter(([, r]) => !r.passed).map(([name]) => name)
// a test of the file that is not a property (a named counterexample) fails the run too: say so, with vitest's
// own account of it
if (run.status !== 0 && failed.length === 0) console.log(`FAIL  vitest exited with ${run.status} outside the listed properties:\n${run.stdout?.slice(-3000)}`)
const json = writeResult('adversarial', { scale, seconds, vitestExit: run.status, failed, properties: report })
console.log(`${seconds.toFixed(0)} s; wrote ${json} (results under ${outDir()})`)
if (run.status !== 0) process.exitCode = 1
