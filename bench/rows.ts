// Rows struck end on under the fixed-tick method (BALL_COLLISIONS = 'fixed'): the scenes where Gauss-Seidel
// sweeps are weakest (a push must run the length of a chain) and where balls move many diameters a tick.
// Two sets, every setting run to its end, counted, not timed:
//   struck: 768 rows of radius-0.5 balls, 5, 20, 55 or 120 of them, 0, 0.05, 0.3 or 2 px apart, struck by a
//           ball of mass 1, 3 or 100 at 100, 300, 3,000 or 1e4 px/s, restitution 0 or 1 (balls and walls), a
//           closed wall 5 px past the row, 1 s at 60 and at 120 Hz: the settings in which a ball passes its
//           neighbour (its x not ahead of the one before it at a step's end), and those with two balls more
//           than 1e-3 px deep in each other at a step from 0.5 s on;
//   pressed: 200 random rows of radius-11 balls (2–64 balls, touching or 0.01 or 1 px apart, 0, 5 or 30 px
//           from the far wall, strikers of mass 1–1e4 at 100–1,000 px/s, e from 0 to 1, on the row's line or
//           2 px off it), 1 s at 60 Hz: the rows more than 1e-3 px deep between neighbours at a step from
//           0.5 s on (and from 0.25 s), the deepest;
//   free:    1,008 rows with no walls struck end on: restitution 0 or 1, a striker of mass 1 or 100, radii 0.5,
//           3 or 11, 0.05, 1 or 5 px apart, 200 balls at 3,000, 1e4 or 1e5 px/s and 1,000 at 1e5 px/s,
//           CONTACT_TICK 1/120 to 1/7,680 s, stepped at 1/240 s until the push could leave the row: the settings
//           in which a ball passes its neighbour at a step's end;
//   fine:    the struck set's 768 settings at CONTACT_TICK 1/1,920 s, and again at the default tick with
//           CONTACT_TRAVEL_HALVINGS 4 (which halves these ticks where the balls move fast): the same counts
//           (the rows' rules were tuned at the default tick; at 1/1,920 s one of these let a ball through).
// About 5 minutes in all.
// Writes docs/results/rows.json.
//
//   npm run bench:rows
import { createBallPhysics } from '../src/index'
import { writeResult } from './lib'
import { strike, type Struck } from './rowScenes'

interface Pressed {
  n: number
  gap: number
  mass: number
  speed: number
  e: number
  off: number
  dist: number
}

/** The deepest overlap between neighbours from 0.5 s and from 0.25 s. */
function press({ n, gap, mass, speed, e, off, dist }: Pressed): { deepest: number; deepestFromQuarter: number } {
  const r = 11
  const hz = 60
  const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: e, ROLLING_DECEL: 0 })
  sim.setWalls({ minX: -200, minY: -100, maxX: 2 * r + (n - 1) * (2 * r + gap) + r + dist, maxY: 100, restitution: e })
  const ids = [sim.addBall({ x: 0, y: off, vx: speed, vy: 0, mass })]
  for (let i = 0; i < n; i++) ids.push(sim.addBall({ x: 2 * r + gap + i * (2 * r + gap), y: 0, vx: 0, vy: 0 }))
  let deepest = 0
  let deepestFromQuarter = 0
  for (let f = 0; f < hz; f++) {
    sim.step(1 / hz)
    sim.drainEventsWith(() => {})
    if (f + 1 < hz / 4) continue
    const x = sim.world.Ball.x
    const y = sim.world.Ball.y
    for (let k = 1; k < ids.length; k++) {
      const d = 2 * r - Math.hypot(x[ids[k]!]! - x[ids[k - 1]!]!, y[ids[k]!]! - y[ids[k - 1]!]!)
      if (d > deepestFromQuarter) deepestFromQuarter = d
      if (f + 1 >= hz / 2 && d > deepest) deepest = d
    }
  }
  return { deepest, deepestFromQuarter }
}

const t0 = performance.now()
const struck: (Struck & { passed: number; deepest: number })[] = []
for (const n of [5, 20, 55, 120])
  for (const gap of [0, 0.05, 0.3, 2])
    for (const mass of [1, 3, 100])
      for (const speed of [100, 300, 3000, 1e4])
        for (const e of [0, 1])
          for (const hz of [60, 120]) {
            const s = { n, gap, mass, speed, e, hz }
            struck.push({ ...s, ...strike(s) })
          }
const struckResult = summarise('struck', 'radius-0.5 balls, n in {5, 20, 55, 120}, gap in {0, 0.05, 0.3, 2} px, striker mass in {1, 3, 100} at {100, 300, 3000, 1e4} px/s, e in {0, 1}, a closed wall 5 px past the row, 1 s at 60 and 120 Hz', struck)

// the pressed rows: a fixed draw (Park–Miller, seed 1) from the ranges above
let seed = 1
const rand = () => (seed = (seed * 16807) % 2147483647) / 2147483647
const pick = <T>(xs: readonly T[]): T => xs[Math.floor(rand() * xs.length)]!
const pressed: (Pressed & { deepest: number; deepestFromQuarter: number })[] = []
for (let k = 0; k < 200; k++) {
  const p: Pressed = {
    n: 2 + Math.floor(rand() * 63),
    gap: pick([0, 0.01, 1]),
    mass: pick([1, 3, 10, 100, 1e4]),
    speed: pick([100, 300, 1000]),
    e: pick([0, 0.5, 0.95, 1]),
    off: pick([0, 0, 2]),
    dist: pick([0, 5, 30]),
  }
  pressed.push({ ...p, ...press(p) })
}
const pressedDeep = pressed.filter((p) => p.deepest > 1e-3)
const pressedDeepQuarter = pressed.filter((p) => p.deepestFromQuarter > 1e-3)
console.log(
  `pressed rows: ${pressed.length}; over 1e-3 px deep from 0.5 s in ${pressedDeep.length}, from 0.25 s in ${pressedDeepQuarter.length} (deepest from 0.5 s ${Math.max(...pressed.map((p) => p.deepest)).toExponential(2)} px, from 0.25 s ${Math.max(...pressed.map((p) => p.deepestFromQuarter)).toExponential(2)} px)`,
)
for (const p of pressedDeepQuarter) console.log(`  ${JSON.stringify(p)}`)

interface Free {
  e: number
  mass: number
  radius: number
  gap: number
  speed: number
  n: number
  hz: number
}

/** The first step (of 1/240 s) at which a ball of a free row is not ahead of the one before it (−1: none). */
function free({ e, mass, radius, gap, speed, n, hz }: Free): number {
  const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: e, ROLLING_DECEL: 0, BALL_RADIUS: radius, CONTACT_TICK: 1 / hz })
  const ids = [sim.addBall({ x: 0, y: 0, vx: speed, vy: 0, mass })]
  for (let i = 0; i < n; i++) ids.push(sim.addBall({ x: 4 * radius + i * (2 * radius + gap), y: 0, vx: 0, vy: 0 }))
  const steps = 4 * (Math.ceil(((4 * radius + n * (2 * radius + gap)) / speed) * 60) + 2)
  for (let s = 0; s < steps; s++) {
    sim.step(1 / 240)
    let last = -Infinity
    for (const id of ids) {
      const x = sim.ballState(id).x
      if (!(x > last)) return s
      last = x
    }
  }
  return -1
}

const freeRows: (Free & { passed: number })[] = []
for (const e of [0, 1])
  for (const mass of [1, 100])
    for (const radius of [0.5, 3, 11])
      for (const gap of [0.05, 1, 5])
        for (const speed of [3000, 1e4, 1e5])
          for (const n of speed === 1e5 ? [200, 1000] : [200])
            for (const hz of [120, 240, 480, 960, 1920, 3840, 7680]) {
              const row = { e, mass, radius, gap, speed, n, hz }
              freeRows.push({ ...row, passed: free(row) })
            }
const freePasses = freeRows.filter((r) => r.passed >= 0)
console.log(`free rows: ${freeRows.length}; a ball passes another in ${freePasses.length}`)
for (const r of freePasses) console.log(`  ${JSON.stringify(r)}`)

// the struck settings again, at a finer tick and with the travel rule
const fine: (Struck & { tick: string; passed: number; deepest: number })[] = []
for (const [tick, extra] of [['1/1920', { CONTACT_TICK: 1 / 1920 }], ['travel 4', { CONTACT_TRAVEL_HALVINGS: 4 }]] as const)
  for (const s of struck) {
    const k = { n: s.n, gap: s.gap, mass: s.mass, speed: s.speed, e: s.e, hz: s.hz }
    fine.push({ ...k, tick, ...strike(k, extra) })
  }
const fineResult = summarise('fine', 'the struck settings at CONTACT_TICK 1/1920 s, and at the default tick with CONTACT_TRAVEL_HALVINGS 4', fine)
console.log(`(${((performance.now() - t0) / 1000).toFixed(0)} s)`)

const file = writeResult('rows', {
  struck: struckResult,
  pressed: {
    scenes: 'radius-11 balls, n 2–64, gap in {0, 0.01, 1} px, striker mass in {1, 3, 10, 100, 1e4} at {100, 300, 1000} px/s, e in {0, 0.5, 0.95, 1}, 0 or 2 px off the line, the far wall 0, 5 or 30 px past the row; 200 rows drawn with Park–Miller from seed 1; 1 s at 60 Hz',
    rows: pressed.length,
    deeperThan1e3From05s: pressedDeep.length,
    deeperThan1e3From025s: pressedDeepQuarter.length,
    deepestFrom05s: Math.max(...pressed.map((p) => p.deepest)),
    deepestFrom025s: Math.max(...pressed.map((p) => p.deepestFromQuarter)),
    failing: pressedDeepQuarter,
  },
  free: {
    scenes: 'no walls; e in {0, 1}, striker mass in {1, 100}, radius in {0.5, 3, 11}, gap in {0.05, 1, 5} px, 200 balls at {3000, 1e4, 1e5} px/s and 1,000 at 1e5 px/s, CONTACT_TICK 1/{120, 240, 480, 960, 1920, 3840, 7680} s, steps of 1/240 s',
    rows: freeRows.length,
    passes: freePasses.length,
    failing: freePasses,
  },
  fine: fineResult,
})
console.log(`wrote ${file}`)

/** A set of struck rows counted (printed, and as rows.json has it): the settings in which a ball passes another, those over 1e-3 px deep from 0.5 s. */
function summarise<T extends { passed: number; deepest: number }>(name: string, scenes: string, rows: T[]) {
  const passes = rows.filter((s) => s.passed >= 0)
  const deep = rows.filter((s) => s.deepest > 1e-3)
  const deepest = Math.max(...rows.map((s) => s.deepest))
  console.log(`${name} rows: ${rows.length}; a ball passes another in ${passes.length}; over 1e-3 px deep from 0.5 s in ${deep.length} (deepest ${deepest.toExponential(2)} px)`)
  for (const s of [...passes, ...deep]) console.log(`  ${JSON.stringify(s)}`)
  return { scenes, settings: rows.length, passes: passes.length, deeperThan1e3From05s: deep.length, deepestFrom05s: deepest, failing: [...passes, ...deep] }
}
