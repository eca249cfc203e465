// Rows a far heavier ball drives into a wall at restitution 1: how often a ball passes its neighbour.
//   ROWS random rows: 5–24 radius-0.5 balls 0.5, 2 or 5 px apart on one line, each at a random velocity up
//   to ±1e4, 3e4 or 1e5 px/s along it, a ball of mass 1e3, 1e6 or 1e9 at the row's left end, a closed
//   elastic box 3 px left of the row and 5 px right of it, no deceleration, 1 s at 60 or 120 Hz. On one line a
//   pass shows as two neighbours out of order after a step. The heavy ball pumps the light ones (each bounce
//   off it adds up to twice its speed), which is the regime the fixed tick holds least (docs/known-failures.md).
// Prints and writes, for the fixed tick (and the exact method over the first EXACT_ROWS rows), the rows in
// which a ball passes another, by the heavy ball's mass and the speeds drawn, those of them with lean ticks
// (world.fixed.lean: past the work budget for unlike masses), and the share of the kinetic energy kept after
// the run (the mean over the rows that ran it).
// Writes docs/results/piston-rows.json. About two minutes (the exact method takes most of it).
//
//   npm run bench:piston-rows
import { writeResult } from './lib'
import { PISTON_MASSES as MASSES, PISTON_SPEEDS as SPEEDS, pistonRow, type PistonRow as Row } from './rowScenes'

const ROWS = 1000
const EXACT_ROWS = 100

function kinetic(row: Row): number {
  const { sim, ids } = row
  const mass = sim.world.fixed?.mass ?? sim.world.collide!.mass
  let k = 0
  for (const id of ids) k += 0.5 * mass[id]! * (sim.world.Ball.vx[id]! ** 2 + sim.world.Ball.vy[id]! ** 2)
  return k
}

interface Count {
  rows: number
  passed: number
  passedLean: number
  byMass: Record<string, number>
  bySpeed: Record<string, number>
  kept: number
  seconds: number
}

function count(mode: 'fixed' | 'on', rows: number): Count {
  const c: Count = { rows, passed: 0, passedLean: 0, byMass: {}, bySpeed: {}, kept: 0, seconds: 0 }
  for (const m of MASSES) c.byMass[String(m)] = 0
  for (const v of SPEEDS) c.bySpeed[String(v)] = 0
  const t0 = performance.now()
  for (let seed = 0; seed < rows; seed++) {
    const row = pistonRow(seed, mode)
    const { sim, ids, hz } = row
    const x = sim.world.Ball.x
    const k0 = kinetic(row)
    let passed = false
    for (let f = 0; f < hz; f++) {
      sim.step(1 / hz)
      sim.drainEventsWith(() => {})
      if (!passed) for (let k = 1; k < ids.length; k++) if (!(x[ids[k]!]! > x[ids[k - 1]!]!)) passed = true
    }
    c.kept += kinetic(row) / k0 / rows
    if (!passed) continue
    c.passed++
    c.byMass[String(row.mass)]!++
    c.bySpeed[String(row.speed)]!++
    if ((sim.world.fixed?.lean ?? 0) > 0) c.passedLean++
  }
  c.seconds = (performance.now() - t0) / 1000
  return c
}

const fixed = count('fixed', ROWS)
console.log(`fixed tick: a ball passes another in ${fixed.passed} of ${fixed.rows} rows (${fixed.passedLean} of them with lean ticks); by the heavy ball's mass ${JSON.stringify(fixed.byMass)}, by speed ${JSON.stringify(fixed.bySpeed)}; energy kept ${fixed.kept.toFixed(3)} (${fixed.seconds.toFixed(1)} s)`)
const exact = count('on', EXACT_ROWS)
console.log(`exact method, first ${exact.rows} rows: a ball passes another in ${exact.passed}; energy kept ${exact.kept.toFixed(3)} (${exact.seconds.toFixed(1)} s)`)
const file = writeResult('piston-rows', {
  scene: `${ROWS} random rows: 5-24 radius-0.5 balls 0.5, 2 or 5 px apart on one line, each at up to ±1e4, 3e4 or 1e5 px/s along it, a ball of mass 1e3, 1e6 or 1e9 at the row's left end, a closed box 3 px left of the row and 5 px right of it, restitution 1, no deceleration, 1 s at 60 or 120 Hz (seed s: mulberry32(s + 1))`,
  passed: 'rows in which two neighbours were out of order after some step; passedLean: those whose world counted lean ticks (past the work budget); kept: kinetic energy at the end over the start, the mean over the rows',
  fixed,
  exact,
})
console.log(`wrote ${file}`)
