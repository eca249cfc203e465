// Adversarial property suite: random sequences of API calls (fast-check, seeded) on a createBallPhysics world
// (METHOD 'exact'; BALL_COLLISIONS 'off' | 'on' | 'fixed' × BALL_RESTITUTION 0, 0.5, 1 × ROLLING_DECEL 0, 300), with
// extreme but valid input: radii 1e-3…200 px and now and then up to MAX_RADIUS, masses 1e-9…1e9, speeds up to
// 1e5 px/s, balls put down on one another, overlapping one, inside a lip circle or aimed at a hole (rim shots),
// at the back of a busy spot's queue or at its front (queue: 'front'), bursts of up to 30 balls at one point,
// holes added and removed, walls of every shape (the panel, 1e-6 px across, narrower than a ball, open edges)
// set and cleared, velocities set, steps of 1e-9 s to 10 s. Each sequence ends with 40 steps of 1/60 s.
// After every call the runner checks the property's invariants:
//   finite   every element of every Ball and Path store of every live ball is finite; every mode is named;
//            no velocity component beyond MAX_SPEED (what setBallVelocity accepts)
//   events   drained events never go back in time, and each lies in the window [time before, time after]
//            of the call that reported it
//   energy   contacts on or fixed: Σ ½·m·v² does not rise across a step that reports collisions and no wall event
//   time     each step returns within STEP_BUDGET_MS (and a whole run within RUN_DEV_MS), budgets scaled
//            by the machine's slowness measured at the start, or measured again when one is exceeded
//            (overBudget) if it is slower by then
//   overlap  contacts on, 0.5 s after the last ball was put down: no two balls on the panel (rolling, rimRoll,
//            resting) overlap by more than 1e-3 px; fixed, the same right after each contact tick's solve,
//            unless the balls cover more than half of a closed box (they may not fit)
//   quiet    after the settling steps, a second of 1/60 s steps, 20 s in steps of MAX_STEP, and a second again: the
//            later second costs at most twice the first plus QUIET_FLOOR_DEV_MS (a cost that grows with time
//            while nothing new happens: a pair that crept into itself grew from 1.6 ms a step to 23 ms in 8 s)
// A failure throws with the API calls made so far written as code, so fast-check's shrunk counterexample
// reads as a repro.
//
// A step runs under a watchdog: a system appended to the schedule throws once the step has run longer than
// twice STEP_BUDGET_MS, so a runaway step ends (as a failure of 'time', or as a discarded run of the other
// properties) instead of hanging vitest; a step that ends is judged against STEP_BUDGET_MS (overBudget). The
// watchdog catches work spread over event passes, which is what every runaway step found so far is; a loop
// inside one system would not be caught.
import { writeFileSync } from 'node:fs'
import fc from 'fast-check'
import { describe, expect, it } from 'vitest'
import { createBallPhysics, MAX_SPEED, type BallEvent, type BallPhysics } from '../src/index'
import { BALL_MODE_NAMES, BallSchema, PathSchema } from '../src/ecs'
import { machineSlowdown, slowdownNow } from './helpers'

// wall-clock budgets stated for the development machine, scaled to this one (tests/helpers.ts)
const SLOWDOWN = machineSlowdown()
/** a step's budget on the development machine, and on this one */
const STEP_DEV_MS = 2000
const STEP_BUDGET_MS = STEP_DEV_MS * SLOWDOWN
console.info(`adversarial: time budgets ×${SLOWDOWN.toFixed(2)} (this machine against the development machine)`)
/**
 * The long version (`npm run bench:adversarial`) sets ADVERSARIAL_SCALE: every property runs that many
 * times as often, on other seeds, and the run's statistics go to ADVERSARIAL_REPORT (a JSON file).
 */
const SCALE = Math.max(1, Number(process.env.ADVERSARIAL_SCALE ?? 1) || 1)
const SEED_SHIFT = SCALE === 1 ? 0 : 7919 * SCALE
const REPORT = process.env.ADVERSARIAL_REPORT
/** a whole run's stepping on the development machine (every step under the budget, but a world that grinds at the pass cap every step) */
const RUN_DEV_MS = 5000
/**
 * Shrinking a counterexample stops this long after it was found. A sequence that fails 'time' takes its
 * whole run budget to fail again, and each candidate the shrinker tries is such a run: at scale 41 the
 * long run's pumped crowd (tests below) shrank for more than 11 minutes without an end in sight.
 */
const SHRINK_BUDGET_MS = 120_000 * SLOWDOWN

/** per property: runs that went over a budget at the start's scale, and how many of them were within at the scale measured then */
const rechecks: Record<string, { over: number; within: number }> = {}
/**
 * Whether `ms` exceeds a budget of `devMs` on the development machine (called between steps, never inside
 * one). `run.scale` starts at the scale measured at the start of the file; the first time a run goes over
 * a budget at it, the machine's slowness is measured again and the run is judged, from then on, at the
 * larger of the two: a long run lasts minutes on a shared machine whose speed drifts (one run at 10×
 * measured 2.66 at its start, and failed a sequence at 13.7 s of stepping that took 15.8 s alone on the same
 * machine, which measured 3.61 and 3.77 for the next two runs). The budgets catch hangs and blow-ups, which
 * are far over either scale.
 */
function overBudget(name: string, run: { scale: number; rechecked: boolean }, ms: number, devMs: number): boolean {
  if (ms <= devMs * run.scale) return false
  if (run.rechecked) return true
  run.rechecked = true
  const r = (rechecks[name] ??= { over: 0, within: 0 })
  r.over++
  run.scale = Math.max(run.scale, slowdownNow())
  if (ms > devMs * run.scale) return true
  r.within++
  return false
}
const SETTLE_STEPS = 40 // 0.67 s at 60 Hz after the last call: past the 0.5 s the overlap check waits for
/** 'quiet': the steps of 1/60 s in each timed second, the steps of MAX_STEP (0.25 s) between them, and the slack, development-machine ms */
const QUIET_STEPS = 60
const QUIET_JUMPS = 80
const QUIET_FLOOR_DEV_MS = 100
/** 'quiet': a whole run's stepping, development-machine ms (22 s more of simulated time than the others') */
const QUIET_RUN_DEV_MS = 20_000
const SEED = 20_240_517

// ---------------------------------------------------------------- operations

type Place =
  | { p: 'free' }
  | { p: 'stack'; k: number } // on the centre of a live ball
  | { p: 'overlap'; k: number; f: number; a: number } // centre distance f/2·(r1 + r2) from a live ball
  | { p: 'inHole'; k: number; f: number; a: number } // inside a hole's lip circle
  // d px outside a hole's lip, aimed off·R beside its centre; `lip`: the speed it should cross the lip at
  | { p: 'aim'; k: number; d: number; off: number; a: number; lip?: number }

type Op =
  | { t: 'addBall'; x: number; y: number; vx: number; vy: number; radius?: number; mass?: number; place: Place; queue?: 'front' }
  | { t: 'throw'; x: number; y: number; power: number; angle: number; radius?: number; mass?: number; place: Place; queue?: 'front' }
  | { t: 'burst'; n: number; x: number; y: number; spread: number; speed: number; radius?: number; mass?: number; seed: number; aim?: Place }
  | { t: 'addHole'; x: number; y: number; radius?: number }
  | { t: 'removeHole'; k: number }
  | { t: 'removeBall'; k: number }
  | { t: 'setVel'; k: number; vx: number; vy: number }
  | { t: 'walls'; minX: number; minY: number; w: number; h: number; e?: number; open?: Record<string, boolean> }
  | { t: 'clearWalls' }
  | { t: 'step'; dt: number }

type Contacts = 'off' | 'on' | 'fixed'

interface Cfg {
  contacts: Contacts
  /** PREDICTION_HORIZON (absent: the default) */
  horizon?: number
  /** the rim model (absent: the design's stages) */
  rim?: 'tabulated'
  /** CONTACT_TRAVEL_HALVINGS (absent: the default) */
  travel?: number
  /** CONTACT_WORK_BUDGET (absent: the default, none) */
  budget?: number
  e: number
  decel: number
}

// ---------------------------------------------------------------- generators

interface Limits {
  /** radius drawn log-uniform in this range (or the default), px */
  radius: [number, number]
  /** now and then a radius from 200 up to MAX_RADIUS = 1e4 */
  huge: boolean
  /** mass drawn log-uniform in this range (or the default (r/11)³) */
  mass: [number, number]
  /** walls 1e-6, 1 or 5 px across: narrower than a ball */
  narrowWalls: boolean
  holes: boolean
  /** most balls one burst (n balls put down at once near one point) adds */
  burst: number
  /** walls at all (setWalls, clearWalls) */
  walls: boolean
  /** bursts' speeds, px/s (default 0, 50, 300, 1,000, 5,000) */
  burstSpeeds?: number[]
}

const FULL: Limits = { radius: [1e-3, 200], huge: true, mass: [1e-9, 1e9], narrowWalls: true, holes: true, burst: 30, walls: true }

const unit = fc.integer({ min: 0, max: 1_000_000 }).map((i) => i / 1_000_000)
const uniform = (lo: number, hi: number) => unit.map((u) => lo + (hi - lo) * u)
const logUniform = (lo: number, hi: number) =>
  fc.integer({ min: Math.round(Math.log10(lo) * 1000), max: Math.round(Math.log10(hi) * 1000) }).map((k) => Math.min(hi, Math.max(lo, 10 ** (k / 1000))))
const signed = (a: fc.Arbitrary<number>) => fc.tuple(a, fc.boolean()).map(([v, s]) => (s ? -v : v))
const coordinate = (panel: number) =>
  fc.oneof(
    { weight: 12, arbitrary: uniform(-20, panel + 20) },
    { weight: 2, arbitrary: fc.integer({ min: 0, max: Math.round(panel / 10) }).map((i) => i * 10) },
    { weight: 1, arbitrary: fc.double({ min: -20, max: panel, noNaN: true }) }, // denormals, -0, tiny values
    { weight: 1, arbitrary: signed(logUniform(1e3, 1e9)) },
  )
const speed = fc.oneof(
  { weight: 1, arbitrary: fc.constant(0) },
  { weight: 8, arbitrary: logUniform(1e-3, 1e5) },
  { weight: 1, arbitrary: fc.constantFrom(1e5, 1e-300, 5e-324) },
)
const velocity = fc.tuple(speed, uniform(-Math.PI, Math.PI), fc.boolean()).map(([s, a, axis]) => {
  const q = axis ? Math.round(a / (Math.PI / 2)) * (Math.PI / 2) : a
  return axis ? { vx: Math.round(Math.sin(q)) * s, vy: -Math.round(Math.cos(q)) * s } : { vx: s * Math.sin(q), vy: -s * Math.cos(q) }
})
const aimArb = fc.oneof(
  fc.record({ p: fc.constant('aim' as const), k: fc.nat(50), d: uniform(0, 200), off: uniform(-1.3, 1.3), a: uniform(0, 6.3) }),
  // rim shots: the default ball rolls on the rim for δ ≈ 0.58…0.68·R at a lip speed ≈ 467…498 px/s
  fc.record({ p: fc.constant('aim' as const), k: fc.nat(50), d: uniform(0, 200), off: signed(uniform(0.57, 0.69)), a: uniform(0, 6.3), lip: uniform(460, 505) }),
)
const place: fc.Arbitrary<Place> = fc.oneof(
  { weight: 4, arbitrary: fc.constant<Place>({ p: 'free' }) },
  { weight: 2, arbitrary: fc.nat(50).map((k): Place => ({ p: 'stack', k })) },
  { weight: 2, arbitrary: fc.record({ p: fc.constant('overlap' as const), k: fc.nat(50), f: uniform(0, 1.99), a: uniform(0, 6.3) }) },
  { weight: 2, arbitrary: fc.record({ p: fc.constant('inHole' as const), k: fc.nat(50), f: unit, a: uniform(0, 6.3) }) },
  { weight: 3, arbitrary: aimArb },
)
const dt = fc.constantFrom(1e-9, 1 / 240, 1 / 60, 1 / 60, 1 / 60, 0.1, 0.25, 10)
const openEdges = fc.record({ left: fc.boolean(), top: fc.boolean(), right: fc.boolean(), bottom: fc.boolean() }, { requiredKeys: [] })
const PANEL_HOLES = [50, 130, 210, 290, 370].flatMap((x) => [130, 190, 250, 310, 370].map((y) => ({ x, y })))

function opArbs(L: Limits) {
  const x = coordinate(420)
  const y = coordinate(480)
  const radius = fc.oneof(
    { weight: 4, arbitrary: fc.constant(undefined) },
    { weight: 5, arbitrary: logUniform(L.radius[0], L.radius[1]) },
    { weight: L.huge ? 1 : 0, arbitrary: fc.oneof(logUniform(200, 1e4), fc.constant(1e4)) },
  )
  const mass = fc.oneof(
    { weight: 3, arbitrary: fc.constant(undefined) },
    { weight: 3, arbitrary: logUniform(L.mass[0], L.mass[1]) },
    { weight: 1, arbitrary: fc.constantFrom(L.mass[0], L.mass[1]) },
  )
  // one ball in three put down or thrown at the front of the queue where its spot is busy (a player's throw
  // into a launcher burst), the others at the back (the default)
  const queue = fc.constantFrom<'front' | undefined>(undefined, undefined, 'front')
  const addBall = fc.record({ x, y, v: velocity, radius, mass, place, queue }).map(({ v, ...o }): Op => ({ t: 'addBall', ...o, vx: v.vx, vy: v.vy }))
  const launch = fc.oneof({ weight: 2, arbitrary: fc.constant({ x: 210, y: 450 }) }, { weight: 3, arbitrary: fc.record({ x, y }) })
  const thrown = fc
    .record({ at: launch, power: fc.oneof(unit, fc.constantFrom(0, 1)), angle: uniform(-2 * Math.PI, 2 * Math.PI), radius, mass, place, queue })
    .map(({ at, ...o }): Op => ({ t: 'throw', ...at, ...o }))
  const burst = fc.record({
    t: fc.constant('burst' as const),
    n: fc.integer({ min: 2, max: L.burst }),
    x,
    y,
    spread: fc.constantFrom(0, 0, 1, 22, 60, 400),
    speed: fc.constantFrom(...(L.burstSpeeds ?? [0, 50, 300, 1000, 5000])),
    radius,
    mass,
    seed: fc.nat(1000),
    aim: fc.option(aimArb, { nil: undefined }),
  })
  const holeAt = fc.oneof({ weight: 2, arbitrary: fc.constantFrom(...PANEL_HOLES) }, { weight: 1, arbitrary: fc.record({ x, y }) })
  const addHole = fc
    .record({ at: holeAt, radius: fc.oneof(fc.constant(undefined), uniform(1, 60), fc.constantFrom(0.01, 500)) })
    .map(({ at, radius: r }): Op => ({ t: 'addHole', ...at, radius: r }))
  const sizes = L.narrowWalls ? fc.constantFrom(1e-6, 1, 5, 21, 60, 420) : fc.constantFrom(60, 200, 420)
  const walls = fc.oneof(
    { weight: 3, arbitrary: fc.record({ t: fc.constant('walls' as const), minX: fc.constant(0), minY: fc.constant(0), w: fc.constant(420), h: fc.constant(480), e: fc.constantFrom(undefined, 0, 0.5, 1), open: openEdges }) },
    { weight: 1, arbitrary: fc.record({ t: fc.constant('walls' as const), minX: x, minY: y, w: sizes, h: sizes, e: fc.constantFrom(undefined, 0, 0.5, 1), open: openEdges }) },
  )
  const op: fc.Arbitrary<Op> = fc.oneof(
    { weight: 5, arbitrary: addBall },
    { weight: 3, arbitrary: thrown },
    { weight: 2, arbitrary: burst },
    { weight: L.holes ? 3 : 0, arbitrary: addHole },
    { weight: L.holes ? 1 : 0, arbitrary: fc.record({ t: fc.constant('removeHole' as const), k: fc.nat(50) }) },
    { weight: 1, arbitrary: fc.record({ t: fc.constant('removeBall' as const), k: fc.nat(50) }) },
    { weight: 2, arbitrary: fc.record({ k: fc.nat(50), v: velocity }).map(({ k, v }): Op => ({ t: 'setVel', k, vx: v.vx, vy: v.vy })) },
    { weight: L.walls ? 2 : 0, arbitrary: walls },
    { weight: L.walls ? 1 : 0, arbitrary: fc.constant<Op>({ t: 'clearWalls' }) },
    { weight: 8, arbitrary: fc.record({ t: fc.constant('step' as const), dt }) },
  )
  // a scene to start from, drawn too: the panel's walls (closed, or open at the bottom), its 25 holes, a burst
  const prelude = fc
    .record({
      walls: L.walls ? fc.constantFrom(undefined, { bottom: false }, { bottom: true }) : fc.constant(undefined),
      e: fc.constantFrom(0, 0.5, 1),
      holes: L.holes ? fc.boolean() : fc.constant(false),
      burst: fc.option(burst, { nil: undefined }),
    })
    .map(({ walls: open, e, holes, burst: b }): Op[] => [
      ...(open ? [{ t: 'walls' as const, minX: 0, minY: 0, w: 420, h: 480, e, open }] : []),
      ...(holes ? PANEL_HOLES.map((h): Op => ({ t: 'addHole', ...h })) : []),
      ...(b ? [b] : []),
    ])
  return { op, prelude }
}

const cfgArb = (contacts: readonly Contacts[], tabulated = false): fc.Arbitrary<Cfg> =>
  tabulated
    ? fc.record({ contacts: fc.constantFrom(...contacts), e: fc.constantFrom(0, 0.5, 1), decel: fc.constantFrom(0, 300), rim: fc.constant('tabulated' as const) })
    : fc.record({ contacts: fc.constantFrom(...contacts), e: fc.constantFrom(0, 0.5, 1), decel: fc.constantFrom(0, 300) })
const scenario = (L: Limits, contacts: readonly Contacts[] = ['off', 'on', 'fixed'], tabulated = false): fc.Arbitrary<[Cfg, Op[]]> => {
  const { op, prelude } = opArbs(L)
  return fc
    .tuple(cfgArb(contacts, tabulated), prelude, fc.array(op, { minLength: 1, maxLength: 25, size: 'max' }))
    .map(([cfg, pre, ops]): [Cfg, Op[]] => [cfg, [...pre, ...ops]])
}

// ---------------------------------------------------------------- the runner

type Check = 'finite' | 'events' | 'energy' | 'overlap' | 'time' | 'quiet'

class Violation extends Error {}
/** a step or a run went over its wall-clock budget (a failure of 'time'; the other checks discard the run) */
class OverBudget extends Error {}

/** the slowest step seen per property, for the report */
const worst: Record<string, number> = {}
/**
 * Per property, for the report: the SLOWEST_RUNS runs of most stepping, in development-machine ms (a run's
 * stepping over the budget scale it was judged at; one the watchdog stopped, what it had reached), and how
 * many runs stepped more than half the run budget. Runs a shrink tries are left out.
 */
const heavy: Record<string, { slowestRunsDevMs: number[]; runsOverHalfBudget: number; slowestRunCalls?: string }> = {}
/** per property, the run budget its runs were judged by (RUN_DEV_MS, or a property's own: 'quiet') */
const runBudgets: Record<string, number> = {}
const SLOWEST_RUNS = 5
let shrinking = false
function noteRun(name: string, ms: number, scale: number, runDevMs: number, repro: () => string): void {
  if (shrinking) return
  runBudgets[name] = runDevMs
  const h = (heavy[name] ??= { slowestRunsDevMs: [], runsOverHalfBudget: 0 })
  const dev = ms / scale
  if (dev > runDevMs / 2) h.runsOverHalfBudget++
  const list = h.slowestRunsDevMs
  // the long run's report keeps the calls of a property's slowest run when it stepped more than half its
  // budget (a repro of the run nearest to failing; only those, to keep the results file small)
  if (REPORT && dev > runDevMs / 2 && (list.length === 0 || dev > list[0]!)) h.slowestRunCalls = repro()
  if (list.length === SLOWEST_RUNS && dev <= list[SLOWEST_RUNS - 1]!) return
  list.push(Math.round(dev))
  list.sort((a, b) => b - a)
  list.length = Math.min(list.length, SLOWEST_RUNS)
}
/** what the runs of a property exercised: runs, steps, most balls at once, energy or overlap checks made, events by type */
const seen: Record<string, { runs: number; discarded: number; steps: number; balls: number; checked: number; halved: number; mostHalvings: number; lean: number; frontHeld: number; events: Record<string, number> }> = {}

const PANEL_MODES = new Set(['rolling', 'rimRoll', 'resting'])

/**
 * Balls on the panel covering more than half of a closed box: they may not fit side by side at all (ten
 * balls of radius 100 in the panel's 420 × 480 box cover 1.6 times its area), so overlaps cannot all go.
 */
function crowded(sim: BallPhysics): boolean {
  const w = sim.world
  if (w.walls === 0) return false
  const W = w.Walls
  const area = Math.max(0, W.maxX[w.walls]! - W.minX[w.walls]!) * Math.max(0, W.maxY[w.walls]! - W.minY[w.walls]!)
  let cover = 0
  for (const b of sim.balls()) if (PANEL_MODES.has(BALL_MODE_NAMES[w.Ball.mode[b]!]!)) cover += Math.PI * w.Ball.radius[b]! ** 2
  return cover > 0.5 * area
}
const clampCoord = (v: number) => Math.max(-1e9, Math.min(1e9, v))
const lit = (v: unknown) => JSON.stringify(v).replace(/"(\w+)":/g, '$1: ').replace(/,/g, ', ')

function kinetic(sim: BallPhysics): number {
  const B = sim.world.Ball
  const m = (sim.world.collide ?? sim.world.fixed)!.mass
  let ke = 0
  for (const b of sim.balls()) ke += 0.5 * m[b]! * (B.vx[b]! * B.vx[b]! + B.vy[b]! * B.vy[b]!)
  return ke
}

function worstOverlap(sim: BallPhysics): { depth: number; a: number; b: number } {
  const B = sim.world.Ball
  const on = sim.balls().filter((b) => PANEL_MODES.has(BALL_MODE_NAMES[B.mode[b]!]!))
  const out = { depth: 0, a: 0, b: 0 }
  for (let i = 0; i < on.length; i++) {
    for (let j = i + 1; j < on.length; j++) {
      const p = on[i]!
      const q = on[j]!
      const dx = B.x[p]! - B.x[q]!
      const dy = B.y[p]! - B.y[q]!
      const sum = B.radius[p]! + B.radius[q]!
      const reach = sum - out.depth
      if (dx * dx + dy * dy >= reach * reach) continue // not deeper than the worst so far
      const depth = sum - Math.hypot(dx, dy)
      if (depth > out.depth) Object.assign(out, { depth, a: p, b: q })
    }
  }
  return out
}

/** Applies `ops` (then SETTLE_STEPS steps of 1/60 s) and checks `checks` after every call; throws on a violation. */
/**
 * Runs the calls with the checks; with `traced`, returns the run's trace (every drained event and, at the
 * end, every ball's state, as JSON), else ''. (Kept for every run, the trace of an elastic crowd stepped
 * through the 'quiet' tail outgrew the longest string V8 makes: a run at 400 times the runs.)
 */
function runScenario(name: string, cfg: Cfg, ops: readonly Op[], checks: readonly Check[], inspect?: (sim: BallPhysics) => void, runDevMs = RUN_DEV_MS, traced = false): string {
  const on = (c: Check) => checks.includes(c)
  const overrides = {
    METHOD: 'exact',
    BALL_COLLISIONS: cfg.contacts,
    BALL_RESTITUTION: cfg.e,
    ROLLING_DECEL: cfg.decel,
    ...(cfg.rim === undefined ? {} : { RIM_MODEL: cfg.rim }),
    ...(cfg.horizon === undefined ? {} : { PREDICTION_HORIZON: cfg.horizon }),
    ...(cfg.travel === undefined ? {} : { CONTACT_TRAVEL_HALVINGS: cfg.travel }),
    ...(cfg.budget === undefined ? {} : { CONTACT_WORK_BUDGET: cfg.budget }),
  } as const
  const trace: string[] = []
  const sim = createBallPhysics(overrides)
  const calls: string[] = []
  const log = (s: string) => {
    const last = calls.length - 1
    const m = last >= 0 ? /^(?:for \(let i = 0; i < (\d+); i\+\+\) )?(sim\.step\(.*\))$/.exec(calls[last]!) : null
    if (m && s === m[2]) calls[last] = `for (let i = 0; i < ${Number(m[1] ?? 1) + 1}; i++) ${s}`
    else calls.push(s)
  }
  const repro = () => `const sim = createBallPhysics(${lit(overrides)})\n${calls.join('\n')}`
  let stepStart = 0
  sim.schedule.push({
    name: 'watchdog',
    run: () => {
      const ms = performance.now() - stepStart
      if (ms > 2 * STEP_BUDGET_MS) throw new OverBudget(`step still running after ${ms.toFixed(0)} ms (pass ${sim.world.pass})`)
    },
  })
  const stats = (seen[name] ??= { runs: 0, discarded: 0, steps: 0, balls: 0, checked: 0, halved: 0, mostHalvings: 0, lean: 0, frontHeld: 0, events: {} })
  let halved = false
  let lean = false
  stats.runs++
  let lastSpawn = 0
  // fixed-tick contacts resolve overlaps at each contact tick; between ticks a ball whose path changes (a
  // wall, a stop) can move up to one tick's travel into a neighbour. So the overlap check looks right after
  // each tick's solve, by a probe after the solve in the schedule
  let tickOverlap: { depth: number; a: number; b: number; t: number } | null = null
  if (cfg.contacts === 'fixed' && on('overlap')) {
    let ticks = 0
    let capped = 0
    const at = sim.schedule.findIndex((e) => e.name === 'fixedContacts')
    sim.schedule.splice(at + 1, 0, {
      name: 'overlapProbe',
      run: (w) => {
        if (w.fixed!.ticks === ticks) return
        ticks = w.fixed!.ticks
        // a tick whose projection spent its budget may leave more than its slop: the next ticks take it out
        const spent = w.fixed!.capped !== capped
        capped = w.fixed!.capped
        if (spent || w.time - lastSpawn < 0.5) return
        // the probe's own time is not the step's: the time budgets hold the library's work (the probe's
        // all-pairs pass was half the stepping of a 250-ball crowd whose tick was halved, 15,495 ticks)
        const probeStart = performance.now()
        if (!crowded(sim)) {
          const o = worstOverlap(sim)
          stats.checked++
          if (o.depth > (tickOverlap?.depth ?? 1e-3)) tickOverlap = { ...o, t: w.time }
        }
        stepStart += performance.now() - probeStart
      },
    })
  }
  const frames = (n: number, dt: number) => Array.from({ length: n }, (): Op => ({ t: 'step', dt }))
  const tail = on('quiet') ? [...frames(QUIET_STEPS, 1 / 60), ...frames(QUIET_JUMPS, 0.25), ...frames(QUIET_STEPS, 1 / 60)] : []
  const all: Op[] = [...ops, ...frames(SETTLE_STEPS, 1 / 60), ...tail]
  // 'quiet': the stepping of the first and the last timed second, by the index in `all` where each begins
  const quiet = { first: 0, last: 0, from: ops.length + SETTLE_STEPS }
  let index = -1
  let lastEvent = -Infinity
  let stepping = 0
  const budget = { scale: SLOWDOWN, rechecked: false }
  const ball = (k: number) => {
    const bs = sim.balls()
    return bs.length === 0 ? 0 : bs[k % bs.length]!
  }
  /** where a spawn goes, and for an aimed one the direction it goes in */
  const spot = (op: { x: number; y: number; radius?: number; place: Place }): { x: number; y: number; dir?: { ux: number; uy: number }; speed?: number } => {
    const pl = op.place
    if (pl.p === 'free') return { x: op.x, y: op.y }
    if (pl.p === 'aim') {
      const hs = sim.holes()
      if (hs.length === 0) return { x: op.x, y: op.y }
      const h = sim.holeState(hs[pl.k % hs.length]!)
      const d = h.radius + (op.radius ?? sim.config.BALL_RADIUS) + pl.d
      const x = clampCoord(h.x + Math.cos(pl.a) * d)
      const y = clampCoord(h.y + Math.sin(pl.a) * d)
      // toward the point off·R to the side of the centre
      const tx = h.x - Math.sin(pl.a) * pl.off * h.radius - x
      const ty = h.y + Math.cos(pl.a) * pl.off * h.radius - y
      const len = Math.hypot(tx, ty)
      if (!(len > 0)) return { x, y }
      const dir = { ux: tx / len, uy: ty / len }
      if (pl.lip === undefined) return { x, y, dir }
      // the start speed that crosses the lip at `lip` px/s after rolling to it at ROLLING_DECEL
      const cx = h.x - x
      const cy = h.y - y
      const delta = Math.abs(cx * dir.uy - cy * dir.ux)
      const toLip = Math.max(0, cx * dir.ux + cy * dir.uy - Math.sqrt(Math.max(0, h.radius * h.radius - delta * delta)))
      return { x, y, dir, speed: Math.sqrt(pl.lip * pl.lip + 2 * sim.config.ROLLING_DECEL * toLip) }
    }
    if (pl.p === 'inHole') {
      const hs = sim.holes()
      if (hs.length === 0) return { x: op.x, y: op.y }
      const h = sim.holeState(hs[pl.k % hs.length]!)
      const d = pl.f * h.radius * 0.999
      return { x: clampCoord(h.x + Math.cos(pl.a) * d), y: clampCoord(h.y + Math.sin(pl.a) * d) }
    }
    const b = ball(pl.k)
    if (b === 0) return { x: op.x, y: op.y }
    const s = sim.ballState(b)
    // a ball may roll past the coordinate bound, which bounds only what commands accept: spawns on it stay within
    if (pl.p === 'stack') return { x: clampCoord(s.x), y: clampCoord(s.y) }
    const d = ((s.radius + (op.radius ?? sim.config.BALL_RADIUS)) * pl.f) / 2
    return { x: clampCoord(s.x + Math.cos(pl.a) * d), y: clampCoord(s.y + Math.sin(pl.a) * d) }
  }
  const fail = (what: string) => {
    throw new Violation(`${what}\n--- repro (the failing call is the last one):\n${repro()}`)
  }

  for (const op of all) {
    index++
    const t0 = sim.time
    const ke0 = on('energy') && op.t === 'step' && cfg.contacts !== 'off' ? kinetic(sim) : 0
    const kicks0 = sim.world.kicks
    switch (op.t) {
      case 'addBall':
      case 'throw': {
        const p = spot(op)
        const opt = { ...(op.radius === undefined ? {} : { radius: op.radius }), ...(op.mass === undefined ? {} : { mass: op.mass }), ...(op.queue === undefined ? {} : { queue: op.queue }) }
        // a front put is counted where it went ahead of a ball already held (one more ball ahead of that one)
        const heldBefore = op.queue === 'front' ? sim.balls().filter((b) => sim.ballState(b).mode === 'held').map((b) => [b, sim.heldAhead(b)] as const) : []
        let id: number
        if (op.t === 'addBall') {
          const s = p.speed ?? Math.max(Math.hypot(op.vx, op.vy), p.dir ? 50 : 0) // an aimed shot keeps its speed (at least 50 px/s)
          const spec = p.dir ? { x: p.x, y: p.y, vx: s * p.dir.ux, vy: s * p.dir.uy, ...opt } : { x: p.x, y: p.y, vx: op.vx, vy: op.vy, ...opt }
          id = sim.addBall(spec)
          log(`sim.addBall(${lit(spec)}) // ${id}`)
        } else {
          const angle = p.dir ? Math.atan2(p.dir.ux, -p.dir.uy) : op.angle
          const spec = { x: p.x, y: p.y, power: op.power, angle, ...opt }
          id = sim.throwBall(spec)
          log(`sim.throwBall(${lit(spec)}) // ${id}`)
        }
        if (heldBefore.some(([b, ahead]) => sim.heldAhead(b) === ahead + 1)) stats.frontHeld++
        lastSpawn = sim.time
        break
      }
      case 'burst': {
        let a = op.seed * 7919 + 1
        const r = () => (a = (a * 16807) % 2147483647) / 2147483647
        // an aimed burst is a volley: every ball in the same direction, at least 50 px/s
        const at = op.aim ? spot({ x: op.x, y: op.y, ...(op.radius === undefined ? {} : { radius: op.radius }), place: op.aim }) : { x: op.x, y: op.y }
        const v = at.speed ?? (at.dir ? Math.max(op.speed, 50) : op.speed)
        for (let j = 0; j < op.n; j++) {
          const g = r() * 2 * Math.PI
          const spec = {
            x: clampCoord(at.x + (r() - 0.5) * op.spread),
            y: clampCoord(at.y + (r() - 0.5) * op.spread),
            vx: at.dir ? v * at.dir.ux : v * Math.sin(g),
            vy: at.dir ? v * at.dir.uy : -v * Math.cos(g),
            ...(op.radius === undefined ? {} : { radius: op.radius }),
            ...(op.mass === undefined ? {} : { mass: op.mass }),
          }
          log(`sim.addBall(${lit(spec)}) // ${sim.addBall(spec)}`)
        }
        lastSpawn = sim.time
        break
      }
      case 'addHole': {
        const r = op.radius ?? sim.config.HOLE_RADIUS
        const clash = sim.holes().some((h) => {
          const s = sim.holeState(h)
          return Math.hypot(s.x - op.x, s.y - op.y) < s.radius + r + 1e-6
        })
        if (clash) break
        const spec = { x: op.x, y: op.y, ...(op.radius === undefined ? {} : { radius: op.radius }) }
        log(`sim.addHole(${lit(spec)}) // ${sim.addHole(spec)}`)
        break
      }
      case 'removeHole': {
        const hs = sim.holes()
        if (hs.length === 0) break
        const h = hs[op.k % hs.length]!
        sim.removeHole(h)
        log(`sim.removeHole(${h})`)
        break
      }
      case 'removeBall': {
        const b = ball(op.k)
        if (b === 0) break
        sim.removeBall(b)
        log(`sim.removeBall(${b})`)
        break
      }
      case 'setVel': {
        const b = ball(op.k)
        if (b === 0) break
        const mode = sim.ballState(b).mode
        if (mode === 'captured' || mode === 'out') break
        sim.setBallVelocity(b, op.vx, op.vy)
        log(`sim.setBallVelocity(${b}, ${op.vx}, ${op.vy})`)
        break
      }
      case 'walls': {
        // a box at the coordinate limit keeps a pixel of room for its width (the limit bounds every edge)
        const minX = Math.min(op.minX, 1e9 - 1)
        const minY = Math.min(op.minY, 1e9 - 1)
        const maxX = clampCoord(minX + op.w)
        const maxY = clampCoord(minY + op.h)
        const spec = {
          minX,
          minY,
          maxX: maxX > minX ? maxX : minX + 1,
          maxY: maxY > minY ? maxY : minY + 1,
          ...(op.e === undefined ? {} : { restitution: op.e }),
          ...(op.open === undefined ? {} : { open: op.open }),
        }
        sim.setWalls(spec)
        log(`sim.setWalls(${lit(spec)})`)
        break
      }
      case 'clearWalls':
        sim.clearWalls()
        log('sim.clearWalls()')
        break
      case 'step': {
        log(`sim.step(${op.dt})`)
        stepStart = performance.now()
        try {
          sim.step(op.dt)
        } catch (err) {
          if (err instanceof OverBudget) noteRun(name, stepping + performance.now() - stepStart, budget.scale, runDevMs, repro)
          if (err instanceof OverBudget && on('time')) fail(`slow step: ${err.message}`)
          throw err
        }
        const ms = performance.now() - stepStart
        stepping += ms
        if (on('quiet') && index >= quiet.from) {
          const k = index - quiet.from
          if (k < QUIET_STEPS) quiet.first += ms
          else if (k >= QUIET_STEPS + QUIET_JUMPS) quiet.last += ms
        }
        worst[name] = Math.max(worst[name] ?? 0, ms)
        const slowStep = overBudget(name, budget, ms, STEP_DEV_MS)
        if (slowStep || overBudget(name, budget, stepping, runDevMs)) {
          noteRun(name, stepping, budget.scale, runDevMs, repro)
          const what = slowStep ? `step took ${ms.toFixed(0)} ms` : `steps took ${stepping.toFixed(0)} ms in all`
          if (on('time')) fail(`slow: ${what}`)
          throw new OverBudget(what)
        }
        break
      }
    }
    const t1 = sim.time
    const events: BallEvent[] = sim.drainEvents()
    if (traced) trace.push(JSON.stringify(events))
    if (op.t === 'step') stats.steps++
    // runs whose fixed tick was halved (src/contacts/fixedHalve.ts)
    if (!halved && (sim.world.fixed?.halvings ?? 0) > 0) {
      halved = true
      stats.halved++
    }
    stats.mostHalvings = Math.max(stats.mostHalvings, sim.world.fixed?.halvings ?? 0)
    // runs with a tick solved past its span's work budget (src/contacts/fixedBudget.ts)
    if (!lean && (sim.world.fixed?.lean ?? 0) > 0) {
      lean = true
      stats.lean++
    }
    stats.balls = Math.max(stats.balls, sim.balls().length)
    for (const e of events) stats.events[e.type] = (stats.events[e.type] ?? 0) + 1
    if (on('events')) {
      for (const e of events) {
        if (!(e.time >= lastEvent)) fail(`event order: ${lit(e)} drained after an event at ${lastEvent}`)
        if (!(e.time >= t0 && e.time <= t1)) fail(`event window: ${lit(e)} outside the call's window [${t0}, ${t1}]`)
        lastEvent = e.time
      }
    }
    if (on('finite')) {
      const w = sim.world
      for (const b of sim.balls()) {
        for (const [store, schema, label] of [[w.Ball, BallSchema, 'Ball'], [w.Path, PathSchema, 'Path']] as const) {
          for (const key of Object.keys(schema)) {
            const v = (store as unknown as Record<string, ArrayLike<number>>)[key]![b]!
            if (!Number.isFinite(v)) fail(`non-finite store: ${label}.${key}[${b}] = ${v}`)
          }
        }
        for (let k = 0; k < 8; k++) if (!Number.isFinite(w.pathHot[8 * b + k]!)) fail(`non-finite path row: pathHot[${8 * b + k}] = ${w.pathHot[8 * b + k]}`)
        const m = w.Ball.mode[b]!
        if (BALL_MODE_NAMES[m] === undefined) fail(`bad mode: Ball.mode[${b}] = ${m}`)
        const vx = w.Ball.vx[b]!
        const vy = w.Ball.vy[b]!
        if (Math.abs(vx) > MAX_SPEED || Math.abs(vy) > MAX_SPEED) fail(`velocity beyond MAX_SPEED: Ball.vx/vy[${b}] = ${vx}, ${vy}`)
      }
    }
    // (a ball the launcher knocked off its spot takes the launcher's energy, as a throw does)
    if (on('energy') && op.t === 'step' && cfg.contacts !== 'off' && sim.world.kicks === kicks0 && events.some((e) => e.type === 'collision') && !events.some((e) => e.type === 'wall')) {
      const ke1 = kinetic(sim)
      stats.checked++
      if (ke1 > ke0 * (1 + 1e-9) + 1e-9) fail(`energy rise: kinetic energy ${ke0} -> ${ke1} over a step with collisions and no wall event`)
    }
    if (tickOverlap !== null) {
      const o: { depth: number; a: number; b: number; t: number } = tickOverlap
      fail(`overlap: balls ${o.a} and ${o.b} overlap by ${o.depth} px after the contact tick at t = ${o.t} (last spawn at ${lastSpawn})`)
    }
    if (on('overlap') && cfg.contacts === 'on' && sim.time - lastSpawn >= 0.5) {
      const o = worstOverlap(sim)
      stats.checked++
      if (o.depth > 1e-3) fail(`overlap: balls ${o.a} and ${o.b} overlap by ${o.depth} px at t = ${sim.time} (last spawn at ${lastSpawn})`)
    }
  }
  noteRun(name, stepping, budget.scale, runDevMs, repro)
  if (on('quiet') && quiet.last > 2 * quiet.first + QUIET_FLOOR_DEV_MS * budget.scale) {
    // judged again at the machine's slowness now, as the budgets are (overBudget)
    budget.scale = Math.max(budget.scale, slowdownNow())
    if (quiet.last > 2 * quiet.first + QUIET_FLOOR_DEV_MS * budget.scale) fail(`quiet: the second of steps after the settling ones took ${quiet.first.toFixed(1)} ms, the one 20 s later (ending at t = ${sim.time}) ${quiet.last.toFixed(1)} ms`)
  }
  if (traced) for (const b of sim.balls()) trace.push(JSON.stringify(sim.ballState(b)))
  inspect?.(sim)
  return trace.join('\n')
}

/**
 * A property over `arb`: runs `body` (by default the scenario, checking `checks`) on each generated sequence;
 * a run over budget fails 'time' and is discarded by the others. Every property writes its outcome to the
 * long run's report, so that bench/adversarial.ts lists each one, passed or failed.
 */
function property(
  name: string,
  arb: fc.Arbitrary<[Cfg, Op[]]>,
  checks: readonly Check[],
  numRuns: number,
  seed: number,
  body: (cfg: Cfg, ops: Op[]) => void = (cfg, ops) => void runScenario(name, cfg, ops, checks),
): void {
  let failure: string | null = null
  // when the first counterexample was found: shrinking stops SHRINK_BUDGET_MS later (every later candidate is
  // discarded, and fast-check reports the smallest counterexample so far)
  let failedAt = -1
  let firstFailure: string | null = null
  // the first failing run's calls, before any shrink (the long version runs one that failed 'time' to its end)
  const first: { run: [Cfg, Op[]] | null } = { run: null }
  let toEnd: ToEnd | null = null
  try {
    fc.assert(
      fc.property(arb, ([cfg, ops]) => {
        if (failedAt >= 0 && performance.now() - failedAt > SHRINK_BUDGET_MS) fc.pre(false)
        shrinking = failedAt >= 0
        try {
          body(cfg, ops)
        } catch (err) {
          if (err instanceof OverBudget) {
            seen[name]!.discarded++
            fc.pre(false)
          }
          if (failedAt < 0) {
            failedAt = performance.now()
            // the run that failed first, before any shrink: its own error (the shrunk one's may differ)
            firstFailure = String(err instanceof Error ? err.message : err).split('\n')[0]!
            first.run = [cfg, ops]
          }
          throw err
        }
      }),
      // the error (its violation and the repro of the shrunk sequence) goes into the message, so the long run's
      // report says what failed, not only the sequence
      { seed: seed + SEED_SHIFT, numRuns: numRuns * SCALE, interruptAfterTimeLimit: 120_000 * SCALE, markInterruptAsFailure: true, includeErrorInReport: true },
    )
  } catch (err) {
    // without the stack frames fast-check copies into its message (they name this machine's paths)
    failure = String(err instanceof Error ? err.message : err)
      .split('\n')
      .filter((line) => !/^\s+at /.test(line))
      .join('\n')
    // (both are set inside the property's closure: read as their declared types)
    const slow = (firstFailure as string | null)?.startsWith('slow') === true
    if (REPORT && first.run !== null && slow) toEnd = runToEnd(name, first.run[0], first.run[1], runBudgets[name] ?? RUN_DEV_MS)
    throw err
  } finally {
    console.info(`${name}: slowest step ${(worst[name] ?? 0).toFixed(1)} ms; exercised ${JSON.stringify(seen[name])}`)
    if (REPORT) {
      report[name] = { passed: failure === null, numRuns: numRuns * SCALE, seed: seed + SEED_SHIFT, slowestStepMs: worst[name] ?? 0, runBudgetDevMs: runBudgets[name] ?? RUN_DEV_MS, ...heavy[name], firstFailure, budgetScale: SLOWDOWN, budgetRechecks: rechecks[name] ?? { over: 0, within: 0 }, ...seen[name], firstFailureToEnd: toEnd, failure }
      writeFileSync(REPORT, JSON.stringify(report, null, 2) + '\n')
    }
  }
}

const report: Record<string, object> = {}

/** A failing run's calls stepped to their end, without the run budget (see runToEnd). */
interface ToEnd {
  /**
   * the calls' ms (their steps nearly all of it), and the same in development-machine ms at the larger of the
   * slowness measured at the file's start and a new measure just after (the budgets' own rule: overBudget)
   */
  ms: number
  devMs: number
  /** times the property's run budget that is */
  overBudget: number
  steps: number
  /** contact ticks solved (the fixed tick), and the simulated time reached */
  ticks: number
  time: number
  /** null when every call ran; else why it stopped (a step over its own budget, or a check) */
  stopped: string | null
}

/**
 * The long version's account of a run that failed 'time': a run over the run budget is stopped where it
 * crosses it, so the time it is reported with is always just over the budget, however far past it the
 * calls would go. This runs the first failing run's calls (as drawn, before any shrink) to their end, with
 * no run budget and no check but the step budget (a step over it still stops the run: a hang), and says
 * how long they took.
 */
function runToEnd(name: string, cfg: Cfg, ops: Op[], runDevMs: number): ToEnd {
  shrinking = false
  const key = `${name} (to its end)`
  let stopped: string | null = null
  let ticks = 0
  let time = 0
  const t0 = performance.now()
  try {
    runScenario(key, cfg, ops, [], (sim) => {
      ticks = sim.world.fixed?.ticks ?? 0
      time = sim.time
    }, 1 / 0)
  } catch (err) {
    stopped = String(err instanceof Error ? err.message : err).split('\n')[0]!
  }
  const ms = performance.now() - t0
  const devMs = ms / Math.max(SLOWDOWN, slowdownNow())
  return { ms: Math.round(ms), devMs: Math.round(devMs), overBudget: Math.round((10 * devMs) / runDevMs) / 10, steps: seen[key]?.steps ?? 0, ticks, time, stopped }
}

// ---------------------------------------------------------------- the properties

/** no radius above 200 px or below 2 px (a smaller ball's default mass (r/11)³ is below 0.006), given masses
 * within 1e-3…1e3 (with default masses up to 6,000: ratios up to about 1e7 instead of 1e18), no walls
 * narrower than a ball: what the runaway steps need */
const NO_RUNAWAY: Limits = { radius: [2, 200], huge: false, mass: [1e-3, 1e3], narrowWalls: false, holes: true, burst: 30, walls: true }
/** full ranges without walls: a step with a wall event is not checked for energy, and with walls most steps have one */
const FULL_NO_WALLS: Limits = { ...FULL, walls: false }
/** bursts of up to 150 balls of radii up to 3 px (now and then a huge one), up to 1e5 px/s: crowds whose balls reach many others a tick, where the fixed tick is halved */
const CROWDS: Limits = { ...FULL, radius: [1e-3, 3], burst: 150, burstSpeeds: [300, 5000, 3e4, 1e5] }

describe('adversarial API sequences (fast-check, seeded)', () => {
  it('every element of every Ball and Path store of every live ball stays finite; every mode is a BALL_MODE_NAMES mode', () => {
    property('finite', scenario(FULL), ['finite'], 100, SEED + 1)
    // some of its balls were put down at the front of a queue with held balls behind them
    expect(seen['finite']!.frontHeld).toBeGreaterThan(0)
  }, 120_000 * SCALE)

  it('drained events never go back in time, and each lies in the window of the call that reported it', () => {
    property('events', scenario(FULL), ['events'], 100, SEED + 2)
  }, 120_000 * SCALE)

  it('contacts on: kinetic energy does not rise across a step with collisions and no wall event', () => {
    property('energy', scenario(FULL, ['on']), ['energy'], 60, SEED + 3)
  }, 120_000 * SCALE)

  it('contacts on, no walls: kinetic energy does not rise across a step with collisions', () => {
    property('energy (no walls)', scenario(FULL_NO_WALLS, ['on']), ['energy'], 120, SEED + 8)
  }, 120_000 * SCALE)

  // over the full ranges since the swept-capsule hash drops stale entries (a step's cost grew with the
  // square of its events: docs/known-failures.md)
  it('every step returns within 2 s, and a run of 65 steps within 5 s (budgets scaled to this machine), over the full ranges, every contact mode', () => {
    property('time (full)', scenario(FULL), ['time'], 150, SEED + 5)
  }, 120_000 * SCALE)

  it('fixed-tick contacts: kinetic energy does not rise across a step with collisions and no wall event (full ranges)', () => {
    property('energy (fixed)', scenario(FULL, ['fixed']), ['energy'], 60, SEED + 11)
  }, 120_000 * SCALE)

  it('fixed-tick contacts, full ranges (radii 1e-3 px to the maximum, masses 1e-9…1e9, degenerate walls): every step returns within 2 s, a run within 5 s', () => {
    property('time (fixed, full)', scenario(FULL, ['fixed']), ['time'], 80, SEED + 12)
  }, 120_000 * SCALE)

  it('fixed-tick contacts, full ranges: 0.5 s after the last spawn no two balls on the panel overlap by more than 1e-3 px', () => {
    property('overlap (fixed, full)', scenario(FULL, ['fixed']), ['overlap'], 80, SEED + 13)
  }, 120_000 * SCALE)

  it('fixed-tick contacts, bursts of up to 150 balls (the tick halved in some): stores finite, events in order and in their window, every step within its time budget, no overlap over 1e-3 px 0.5 s after the last spawn', () => {
    property('crowds (fixed)', scenario(CROWDS, ['fixed']), ['finite', 'events', 'time', 'overlap'], 60, SEED + 15)
    expect(seen['crowds (fixed)']!.halved).toBeGreaterThan(0)
  }, 120_000 * SCALE)

  // a game that bounds its frames (CONTACT_WORK_BUDGET, src/contacts/fixedBudget.ts): the lean ticks past the
  // budget keep every invariant but the pairing of balls sped up beyond their reach
  it('fixed-tick contacts with CONTACT_WORK_BUDGET 1 (the least), bursts of up to 150 balls: stores finite, events in order and in their window, every step within its time budget, no overlap over 1e-3 px 0.5 s after the last spawn; kinetic energy does not rise without walls', () => {
    const budgeted = (L: Limits) => scenario(L, ['fixed']).map(([cfg, ops]): [Cfg, Op[]] => [{ ...cfg, budget: 1 }, ops])
    property('crowds (fixed, budget)', budgeted(CROWDS), ['finite', 'events', 'time', 'overlap'], 30, SEED + 41)
    property('energy (fixed, budget)', budgeted({ ...CROWDS, walls: false }), ['energy'], 20, SEED + 42)
    expect(seen['crowds (fixed, budget)']!.lean).toBeGreaterThan(0)
    expect(seen['energy (fixed, budget)']!.lean).toBeGreaterThan(0)
  }, 120_000 * SCALE)

  it('fixed-tick contacts, bursts of up to 150 balls, no walls: kinetic energy does not rise across a step with collisions', () => {
    property('energy (fixed, crowds)', scenario({ ...CROWDS, walls: false }, ['fixed']), ['energy'], 40, SEED + 16)
    expect(seen['energy (fixed, crowds)']!.halved).toBeGreaterThan(0)
  }, 120_000 * SCALE)

  // radii and masses where balls collide more often than they fly apart (two million contacts in the long run)
  it('fixed-tick contacts, radii 2–200 px, masses 1e-3…1e3: from 0.5 s after the last spawn, no overlap over 1e-3 px after any tick', () => {
    property('overlap (fixed)', scenario(NO_RUNAWAY, ['fixed']), ['overlap'], 100, SEED + 14)
  }, 120_000 * SCALE)

  it('tabulated rim model, every contact mode, full ranges: stores finite, events in order and in their window, every step within its time budget', () => {
    property('tabulated', scenario(FULL, ['off', 'on', 'fixed'], true), ['finite', 'events', 'time'], 80, SEED + 21)
  }, 120_000 * SCALE)

  it('tabulated rim model, contacts on: 0.5 s after the last spawn no two balls on the panel overlap by more than 1e-3 px', () => {
    property('tabulated overlap', scenario(NO_RUNAWAY, ['on'], true), ['overlap'], 60, SEED + 22)
  }, 120_000 * SCALE)

  // with holes: rim rolls start where the ball is (they started on the lip circle, r/2 further out, and could
  // land inside a neighbour)
  it('contacts on: 0.5 s after the last spawn no two balls on the panel overlap by more than 1e-3 px', () => {
    property('overlap', scenario(NO_RUNAWAY, ['on']), ['overlap'], 100, SEED + 7)
  }, 120_000 * SCALE)

  // the other properties end 0.67 s after the last call: a cost that grows with time alone shows only later
  it('every contact mode, full ranges: a second of steps 20 s after the calls costs at most twice the first second after them (plus 100 ms)', () => {
    property('quiet', scenario(FULL), ['finite', 'events', 'quiet'], 40, SEED + 51, (cfg, ops) => void runScenario('quiet', cfg, ops, ['finite', 'events', 'quiet'], undefined, QUIET_RUN_DEV_MS))
  }, 120_000 * SCALE)
})

// ---------------------------------------------------------------- the prediction horizon

/**
 * Contacts on: every sequence of calls run twice, predicting one step at a time (PREDICTION_HORIZON 0) and
 * keeping predictions for half a second across steps, gives the same trace bit for bit (every event, every
 * final state). A prediction kept after a command changed a path it depends on would show here.
 */
describe('contacts on: predictions kept across steps', () => {
  it('any API sequence gives the same events and states, bit for bit, with PREDICTION_HORIZON 0 and 0.5 s', () => {
    const name = 'horizon'
    property(name, scenario(NO_RUNAWAY, ['on']), [], 60, SEED + 31, (cfg, ops) => {
      const stepwise = runScenario(name, { ...cfg, horizon: 0 }, ops, [], undefined, RUN_DEV_MS, true)
      const kept = runScenario(name, { ...cfg, horizon: 0.5 }, ops, [], undefined, RUN_DEV_MS, true)
      if (kept !== stepwise) {
        const a = stepwise.split('\n')
        const b = kept.split('\n')
        const i = a.findIndex((line, k) => line !== b[k])
        throw new Error(`traces differ at line ${i}:\n  horizon 0:   ${a[i]?.slice(0, 400)}\n  horizon 0.5: ${b[i]?.slice(0, 400)}`)
      }
    })
  }, 150_000 * SCALE)
})

// ---------------------------------------------------------------- shrunk counterexamples

describe('shrunk counterexamples of the long run', () => {
  // appendEvent may grow the event buffer, replacing its arrays: `buf.time[appendEvent(buf, …)] = t` took the
  // old time array before the call and wrote the time there, so the event that made the buffer grow kept
  // time 0 (a wall event drained at 0 after events at later times, or outside the step's window)
  it('contacts off, tabulated rim: the wall event that grows the event buffer keeps its time (five 1e-9-mass balls in a box 1 × 1e-6 px)', () => {
    const ops = [
      { t: 'burst', n: 5, x: -20, y: -20, spread: 0, speed: 5000, radius: 0.49888448746001224, mass: 1e-9, seed: 0, aim: undefined },
      { t: 'step', dt: 1e-9 },
      { t: 'walls', minX: -20, minY: -20, w: 1, h: 0.000001, e: 1, open: {} },
      { t: 'addBall', x: -20, y: -20, radius: undefined, mass: undefined, place: { p: 'aim', k: 0, d: 0, off: -1.3, a: 0 }, vx: -1.2246467991473532e-16, vy: 1 },
      { t: 'step', dt: 1 / 60 },
    ] as unknown as Op[]
    runScenario('counterexample', { contacts: 'off', e: 0, decel: 0, rim: 'tabulated' }, ops, ['events'])
  })

  it('fixed-tick contacts: a wall event of the solve that grows the event buffer keeps its time (three 1e-9-mass balls stacked on the panel, a 22,961 px/s one)', () => {
    const ops = [
      { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, e: 1, open: { bottom: false } },
      ...PANEL_HOLES.map((h) => ({ t: 'addHole', ...h })),
      { t: 'burst', n: 3, x: 0, y: -20, spread: 0, speed: 5000, radius: undefined, mass: 1e-9, seed: 0, aim: { p: 'aim', k: 0, d: 0, off: -1.3, a: 4.9954653 } },
      { t: 'step', dt: 1 / 60 },
      { t: 'addBall', x: 1000, y: -20, radius: undefined, mass: 1, place: { p: 'overlap', k: 2, f: 0.17149621, a: 5.6048895000000005 }, vx: -2.8119710922773247e-12, vy: 22961.486481123608 },
      { t: 'addBall', x: 0, y: 1000, radius: undefined, mass: undefined, place: { p: 'inHole', k: 0, f: 0.77712, a: 5.5809432 }, vx: -12020.726243229112, vy: 214.75022685836578 },
      { t: 'step', dt: 0.25 },
      { t: 'step', dt: 1e-9 },
    ] as unknown as Op[]
    runScenario('counterexample', { contacts: 'fixed', e: 0, decel: 0 }, ops, ['events'])
  })

  // the crowds property at 10× (a halved tick): light balls struck by heavy ones at 1e5 px/s were sped up
  // beyond any spacing, so the halved tick kept every pair a tick and never went back; its ticks took 2.1 s
  // for one step (97 ms before halving existed). A tick whose pairs a finer one would not thin now goes back
  // to the configured spacing (the scene then cost what it did before halving, about 0.3 s a step: its run
  // is near the run budget either way, so here only each step is held to its budget). Most of that speed was
  // squeezes squirting light balls along the walls; since a squeeze sends no ball further than its wall's
  // length in a tick (src/contacts/fixedWallPair.ts, pairWithWall), the scene keeps 1,000–8,800 pairs for its
  // 215 candidates instead of all 22,500, a finer tick does thin them, and it ends halved once after 4
  // halvings at the most (a squeezed crowd whose finer tick would not thin its pairs: the test below)
  it('fixed-tick contacts: 67 heavy radius-0.24 balls at 1e5 px/s and 147 light ones thrown at 3e4 px/s: no squeeze squirts the light balls across the box, and the halved tick goes back as the crowd spreads, every step within its budget', () => {
    const ops = [
      { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, e: 1, open: { bottom: false } },
      { t: 'burst', n: 67, x: 106.94298, y: -20, spread: 60, speed: 100000, radius: 0.23933157564053875, mass: 86696.1875758216, seed: 300, aim: undefined },
      { t: 'addBall', x: 306.01994, y: 126.82356000000001, radius: 0.034514373933585626, mass: 7.65596606911257e-5, place: { p: 'aim', k: 0, d: 0, off: 0.57, a: 0, lip: 460 }, vx: -0, vy: -0.263633138582538 },
      { t: 'step', dt: 1 / 240 },
      { t: 'burst', n: 147, x: 129.11544, y: -19.99376, spread: 60, speed: 30000, radius: undefined, mass: 1e-9, seed: 2, aim: { p: 'aim', k: 32, d: 4.8064, off: 0.68999904, a: 5.211555300000001, lip: 467.756875 } },
      { t: 'setVel', k: 5, vx: -0.0016602743879715542, vy: 264.24087572697886 },
      { t: 'step', dt: 1 / 60 },
      { t: 'setVel', k: 0, vx: -0.00012002671172106726, vy: 2.728977780168516 },
      { t: 'step', dt: 1 / 60 },
      // (since a ball only a wall turns in a tick keeps its path to the wall, src/contacts/fixedWallTurn.ts,
      // the tick is still halved 3 times at the end of the step above, and back to once in this one)
      { t: 'step', dt: 1 / 60 },
    ] as unknown as Op[]
    let halved = 0
    let pairShare = 1
    const inspect = (sim: BallPhysics) => {
      const F = sim.world.fixed!
      halved = F.halvings
      pairShare = F.pairCount / ((F.n * (F.n - 1)) / 2)
    }
    runScenario('halved crowd', { contacts: 'fixed', e: 0, decel: 0 }, ops, ['finite', 'events', 'time'], inspect, Infinity)
    expect(seen['halved crowd']!.mostHalvings).toBeGreaterThan(halved)
    // squirted, the light balls were paired with nearly every ball to the end: 21,394 pairs of the 23,005
    // possible in its last tick (3,012 now)
    expect(pairShare).toBeLessThan(0.5)
  })

  // the crowds property at 30× (the 1,230th sequence, shrunk): 97 light balls and 14 specks (radius 0.0015,
  // mass 865) at 5e3 px/s, a closed 5 × 60 px box away from them. The box's walls turn the light balls back
  // into the band between its top and bottom lines, where they crowd against its side, and the specks run
  // through them: no solve stops a speck through balls 1e12 times lighter, so tick after tick left such a
  // pair closing into itself by more than the speck's radius, and was solved again 8–10 times finer. The last
  // step took 4,469 ms alone (3,560 ticks); now that a speck closes deep only past 0.5 px (or a quarter of the
  // other radius), 205 ms (183 ticks) (src/contacts/fixedDeep.ts)
  it('fixed-tick contacts: specks of mass 865 at 5e3 px/s through light balls crowded at a small closed box: every step within its budget, the tick not solved again for each speck', () => {
    const ops = [
      { t: 'burst', n: 97, x: 71.28286, y: 408.91732, spread: 400, speed: 5000, radius: undefined, mass: 1e-9, seed: 838, aim: { p: 'aim', k: 15, d: 9.7328, off: -1.2654694, a: 2.2077909 } },
      { t: 'walls', minX: 102.72523999999999, minY: 385.76171999999997, w: 5, h: 60, e: 1, open: { top: false, bottom: false } },
      { t: 'burst', n: 14, x: 283.61518, y: 78.21032000000001, spread: 22, speed: 5000, radius: 0.0014554590805819652, mass: 864.967918775693, seed: 791, aim: { p: 'aim', k: 43, d: 76.1166, off: -0.565123, a: 1.4973083999999999 } },
      { t: 'step', dt: 10 },
      { t: 'throw', x: -15.03936, y: 78.66896, power: 1, angle: 3.249600609020211, radius: undefined, mass: 3349654.3915782794, place: { p: 'overlap', k: 32, f: 1.49497755, a: 0.6506325000000001 }, queue: undefined },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'throw', x: 210, y: 450, power: 0.163926, angle: 4.754385790977878, radius: 0.005508076964054035, mass: undefined, place: { p: 'stack', k: 21 }, queue: 'front' },
      { t: 'step', dt: 0.004166666666666667 },
      { t: 'setVel', k: 46, vx: 102.46111315957302, vy: 63.42583437353105 },
      { t: 'addHole', x: 130, y: 310, radius: undefined },
      { t: 'step', dt: 10 },
    ] as unknown as Op[]
    let ticks = 0
    runScenario('specks in a crowd', { contacts: 'fixed', e: 0, decel: 0 }, ops, ['finite', 'events', 'time'], (sim) => {
      ticks = sim.world.fixed!.ticks
    })
    // 1,201 ticks for the whole sequence (its last step alone took 3,560 before)
    expect(ticks).toBeLessThan(2000)
  })

  // the quiet property at 22× (its 152nd sequence, shrunk): light balls of mass 1e-9 in a closed elastic band
  // of 420 × 60 px among a radius-10,000 ball and fifteen specks of mass 1e9 at 5e3 px/s. The specks pumped
  // them to 1e6–7e6 px/s over the first seconds (Fermi acceleration), and each tick then left one the tick
  // paired near a wall and moving into it, solved again finer, about 40,000 times a second: a second of steps
  // 20 s on cost 236 ms against 25 ms after the settling steps. Contacts no longer pump a ball past
  // CONTACT_SPEED_LIMIT (src/contacts/law.ts)
  it('fixed-tick contacts: light balls among specks of mass 1e9 in a closed elastic band are not pumped past CONTACT_SPEED_LIMIT, so the later second costs what the first did', () => {
    const ops = [
      { t: 'burst', n: 6, x: -20, y: 0, spread: 0, speed: 5000, radius: 1.1455129414455356, mass: 1e-9, seed: 1000, aim: undefined },
      { t: 'addHole', x: 370, y: 370, radius: undefined },
      { t: 'removeHole', k: 32 },
      { t: 'step', dt: 10 },
      { t: 'throw', x: 380.46174, y: 279.27923999999996, power: 1, angle: 4.016073818272433, radius: 4.709773263969529, mass: 0.7396052750582378, place: { p: 'aim', k: 21, d: 164.349, off: 0.4405336000000002, a: 0.8213687999999999 }, queue: undefined },
      { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, e: 0.5, open: { left: true, top: true, bottom: false } },
      { t: 'burst', n: 15, x: 325.68264, y: 167.84012, spread: 0, speed: 5000, radius: 0.2831391995799379, mass: 1000000000, seed: 429, aim: { p: 'aim', k: 20, d: 148.5666, off: 0.7965281999999998, a: 2.1734999999999998 } },
      { t: 'removeHole', k: 48 },
      { t: 'addBall', x: 256.2599, y: 38.56552, radius: 10000, mass: 348.33731503601166, place: { p: 'free' }, queue: undefined, vx: -5e-324, vy: -0 },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'step', dt: 10 },
      { t: 'walls', minX: -1.8558664713801101e-155, minY: 265.32971999999995, w: 420, h: 60, e: 1, open: { left: false, top: false, right: false, bottom: false } },
      { t: 'addHole', x: 290, y: 190, radius: 56.419408000000004 },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'step', dt: 10 },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'step', dt: 0.004166666666666667 },
      { t: 'burst', n: 8, x: 40, y: 320, spread: 0, speed: 0, radius: undefined, mass: 1e-9, seed: 364, aim: undefined },
      { t: 'setVel', k: 30, vx: -0, vy: 246.60393372343387 },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'throw', x: 223.86532, y: 8.138648824613823e-13, power: 0.24155, angle: -0.32651200767289446, radius: 1.8535316234148116, mass: 5.727960309858292, place: { p: 'inHole', k: 50, f: 0.692755, a: 4.2225057 }, queue: undefined },
      { t: 'step', dt: 0.25 },
      { t: 'setVel', k: 44, vx: 0.0032351078780825135, vy: 0.005587576877699492 },
    ] as unknown as Op[]
    let fastest = 0
    runScenario('pumped band', { contacts: 'fixed', e: 1, decel: 0 }, ops, ['finite', 'events', 'quiet'], (sim) => {
      for (const b of sim.balls()) {
        const v = sim.ballState(b)
        fastest = Math.max(fastest, Math.abs(v.vx), Math.abs(v.vy))
      }
    })
    // (a second's cost is a noisy measure: the light balls' speed at the end is not; 1e6–7e6 px/s without the limit)
    expect(fastest).toBeLessThan(1e6)
  })

  // a crowd of 1e9-mass balls and light ones against closed walls: the projection's sweeps ran out with
  // 1.4e-3 px of overlap left after a tick's solve
  it('fixed-tick contacts: 1e9-mass bursts at a rim, light balls, a 1e5 px/s ball, walls open on two edges: no overlap over 1e-3 px after a tick within its projection budget', () => {
    const aim = (d: number, a: number, lip: number) => ({ p: 'aim' as const, k: 0, d, off: 0.57, a, lip })
    const ops = [
      { t: 'addHole', x: 50, y: 130, radius: undefined },
      { t: 'burst', n: 23, x: -20, y: 0, spread: 400, speed: 0, radius: undefined, mass: 1e9, seed: 377, aim: aim(0, 2.7142668, 464.171365) },
      { t: 'burst', n: 16, x: 0, y: -20, spread: 60, speed: 0, radius: undefined, mass: 1e9, seed: 152, aim: aim(150.2672, 4.3570422, 484.717195) },
      { t: 'step', dt: 1 / 60 },
      { t: 'burst', n: 4, x: -20, y: -20, spread: 1, speed: 0, radius: 2.831391995799379, mass: undefined, seed: 149, aim: aim(54.5626, 4.236138899999999, 460) },
      { t: 'setVel', k: 42, vx: 10.423174293933041, vy: -0 },
      { t: 'setVel', k: 26, vx: -1.2246467991473532e-11, vy: 100000 },
      { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, e: undefined, open: { left: true, top: true } },
      { t: 'step', dt: 1e-9 },
    ] as unknown as Op[]
    runScenario('counterexample', { contacts: 'fixed', e: 0, decel: 0 }, ops, ['overlap'])
  })

  // a crowd at up to 1e5 px/s in the panel's closed elastic walls with CONTACT_WORK_BUDGET 1, every tick past
  // the first ones lean (found at 29x the long run): a lean tick's projection pushed a radius-11 ball 7 px,
  // out of one ball into another the tick had not paired with it (5.7 px apart at the tick, just beyond the
  // two reaches), and a lean tick took no rounds to pair it, so the two stayed 1.4 px deep after the tick
  it('fixed-tick contacts with a work budget: a lean tick pairs a ball its projection pushes into one it had not paired', () => {
    const ops = [
      { t: 'burst', n: 93, x: 93.35826, y: 1.0256799999999977, spread: 0, speed: 100000, mass: 1.0046157902783952, seed: 579, aim: { p: 'aim', k: 0, d: 9.556199999999999, off: -0.676728, a: 2.3503977, lip: 467.61796 } },
      { t: 'addHole', x: 91.4097, y: 109.35988, radius: 10.30312 },
      { t: 'throw', x: 349.24016, y: 398.36496, power: 0.188936, angle: 0.008721061206364844, radius: 0.007014552984199714, place: { p: 'overlap', k: 18, f: 1.9899880600000002, a: 2.2233644999999997 } },
      { t: 'addHole', x: 50, y: 370 },
      { t: 'addBall', x: 168.59632000000002, y: 420.36408, radius: 0.002471724145016129, mass: 1000000000, place: { p: 'free' }, vx: -0.08342223854201766, vy: -0.11641456912643863 },
      { t: 'addBall', x: 1321295.6341865766, y: -19.99844, place: { p: 'free' }, vx: 5e-324, vy: -5e-324 },
      { t: 'burst', n: 15, x: -13.199359999999999, y: 460.37496, spread: 60, speed: 5000, radius: 0.00399024902362142, mass: 1.0092528860766845, seed: 760, aim: { p: 'aim', k: 39, d: 133.4718, off: -0.47454419999999997, a: 0.0001134 } },
      { t: 'walls', minX: 324.14164, minY: 430, w: 0.000001, h: 0.000001, e: 0, open: { left: true, top: true, right: false, bottom: true } },
      { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, open: { left: true, top: true, right: true, bottom: false } },
      { t: 'burst', n: 146, x: 439.9931, y: 228.90268, spread: 1, speed: 30000, radius: 0.002978516429429191, seed: 230, aim: { p: 'aim', k: 26, d: 0.00039999999999999996, off: 0.9773478000000002, a: 0.000063 } },
      { t: 'addBall', x: 381.10573999999997, y: 376.32008, place: { p: 'stack', k: 42 }, vx: 4561.266057205212, vy: 99895.92009664552 },
      { t: 'addHole', x: 260, y: 396.36192 },
      { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, e: 1, open: { top: false, right: false } },
      { t: 'throw', x: 210, y: 450, power: 1, angle: -0.33929200658769787, radius: 1, mass: 0.9840111057611337, place: { p: 'free' } },
      { t: 'removeHole', k: 38 },
    ] as unknown as Op[]
    runScenario('counterexample', { contacts: 'fixed', e: 1, decel: 0, budget: 1 }, ops, ['overlap'])
  })

  // 89 balls put down on one point of the top wall at 5,000 px/s with CONTACT_WORK_BUDGET 1, e = 0 (found at 37×
  // the long run): a lean tick whose widening rounds reached their bound (MAX_WIDEN_ROUNDS) left a resting
  // ball the last projection pushed 0.085 px into one the tick had not paired, and did not count the tick as
  // capped, so the overlap check took it for a tick that had solved its overlaps (the next tick took it out;
  // the positions are the same bits either way: only the count changed)
  it('fixed-tick contacts with a work budget: a lean tick whose widening rounds end at their bound with a pushed ball in an unpaired one counts as capped', () => {
    const ops = [
      { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, e: 0, open: { bottom: true } },
      { t: 'burst', n: 89, x: 197.59794, y: 0, spread: 0, speed: 5000, radius: 1.0115794542598986, mass: 1, seed: 2, aim: undefined },
      { t: 'step', dt: 0.25 },
      { t: 'addHole', x: -20, y: -20, radius: 1 },
    ] as unknown as Op[]
    runScenario('counterexample', { contacts: 'fixed', e: 0, decel: 0, budget: 1 }, ops, ['overlap'])
  })

  // 82 balls of radius 0.1 at 1e5 px/s in the closed elastic walls with CONTACT_WORK_BUDGET 1, and 60 more put
  // down among them (found at 29x the long run): the tick was halved 9 times for their speed, and each span's
  // 512 ticks were solved lean after its budget, 1,024 a frame at about 150 us each: the run's steps took
  // 7.3 s. A span now skips its last ticks once its lean ticks have spent its budget again (0.9 s)
  it('fixed-tick contacts with a work budget: a span of a tick halved 9 times skips its last ticks past its budget, and the run keeps its time budget', () => {
    const ops = [
      { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, e: 1, open: { bottom: false } },
      { t: 'burst', n: 82, x: 172.52334, y: 499.49144, spread: 400, speed: 100000, radius: 0.10232929922807542, mass: 5902010.801718442, seed: 2, aim: { p: 'aim', k: 11, d: 114.838, off: -0.34718839999999995, a: 3.9503078999999994 } },
      { t: 'removeBall', k: 14 },
      { t: 'step', dt: 10 },
      { t: 'throw', x: 139.98937999999998, y: 123.72435999999999, power: 0.384739, angle: -0.26633165880072784, mass: 0.011534532578210924, place: { p: 'free' } },
      { t: 'throw', x: 251.01912, y: 192.12256, power: 0, angle: 3.2216278680326464, radius: 0.0018879913490962926, mass: 9.72747223776964e-09, place: { p: 'stack', k: 9 } },
      { t: 'addBall', x: 146554784.09559128, y: 303.98548, radius: 438.5306977749856, mass: 27.47894153102397, place: { p: 'free' }, vx: 0.8185012494249873, vy: 1.227911021631003 },
      { t: 'step', dt: 0.25 },
      { t: 'addBall', x: -5.687908260029906e-273, y: 112.47052, radius: 0.0017538805018417621, mass: 1e-09, place: { p: 'aim', k: 40, d: 75.38040000000001, off: -0.6316492, a: 0.7996589999999999 }, vx: 0.38579967947829635, vy: 0.864015840632588 },
      { t: 'burst', n: 55, x: 283.20762, y: 476.61404, spread: 0, speed: 5000, radius: 0.008709635899560805, seed: 772, aim: { p: 'aim', k: 44, d: 172.0282, off: 0.64096932, a: 2.9706327, lip: 490.779955 } },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'addHole', x: 297.15114, y: 340.74324 },
      { t: 'setVel', k: 0, vx: -0.028183829312644536, vy: 0 },
      { t: 'step', dt: 0.25 },
      { t: 'addBall', x: 286.72294, y: 487.81899999999996, place: { p: 'free' }, vx: 0.008779773674119647, vy: 0.006185539589505897 },
      { t: 'addBall', x: 224.7085, y: 377.99604, radius: 779.8301105232586, mass: 0.0007726805850957021, place: { p: 'free' }, vx: 0, vy: 0.0019724227361148533 },
      { t: 'setVel', k: 16, vx: 0, vy: 0.2630267991895382 },
      { t: 'addBall', x: 297.76063999999997, y: 50.99924, place: { p: 'free' }, vx: -1e-300, vy: 0 },
      { t: 'addHole', x: 290, y: 370 },
      { t: 'addBall', x: 159.65944000000002, y: 92.20352, radius: 0.07464487584100665, mass: 1e-09, place: { p: 'free' }, vx: -8.629785477669705, vy: 0 },
      { t: 'addBall', x: 423.9506, y: 350, mass: 171001531.50902897, place: { p: 'inHole', k: 20, f: 0.101402, a: 1.8921483000000001 }, vx: 0.04997713440463897, vy: -0.04645586046916193 },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'step', dt: 0.1 },
      { t: 'addBall', x: 132.8005, y: 214.95316, radius: 0.23014418174085083, mass: 17619760.46411631, place: { p: 'free' }, vx: 0.03261512073488495, vy: 0.06301793385479981 },
      { t: 'step', dt: 0.016666666666666666 },
    ] as unknown as Op[]
    runScenario('counterexample', { contacts: 'fixed', e: 1, decel: 0, budget: 1 }, ops, ['finite', 'time'])
  })

  // light balls pumped to 5e5 px/s by balls of mass 1e9 in a closed box 1 px wide (found at 61x the long run,
  // 'time (full)', with no budget): the tick stays halved 10 times, 2,048 ticks a frame, and the run's steps
  // take 7.1 s (docs/known-failures.md). With CONTACT_WORK_BUDGET 16 the spans go lean and skip: 0.9 s
  it('fixed-tick contacts with a work budget: light balls pumped in a box 1 px wide step within the run budget', () => {
    const ops = [
      { t: 'burst', n: 25, x: -20, y: 24.347679999999997, spread: 400, speed: 1000, seed: 514, aim: { p: 'aim', k: 2, d: 0.003, off: -1.2999818, a: 6.156139499999999 } },
      { t: 'addHole', x: 250.52324, y: 204.06436000000002 },
      { t: 'burst', n: 11, x: 255.85326000000003, y: 291.4852, spread: 60, speed: 5000, radius: 0.024603676041476272, mass: 1000000000, seed: 779 },
      { t: 'burst', n: 5, x: 222.97292, y: 344.7514, spread: 1, speed: 5000, radius: 0.3372873086588689, seed: 396 },
      { t: 'addBall', x: 198.93608, y: 30, radius: 0.3047894989627983, place: { p: 'inHole', k: 47, f: 0.772971, a: 4.593141 }, vx: 0.00435933448403327, vy: 0.006186744374459098 },
      { t: 'walls', minX: 272.04066, minY: 371.1622, w: 1, h: 420, e: 1, open: { top: false, right: false } },
      { t: 'throw', x: 109.51024000000001, y: 130, power: 1, angle: -3.0266983270627072, radius: 26.121613543992066, place: { p: 'free' } },
      { t: 'addBall', x: 380, y: 375.95036, radius: 0.1233104833228909, mass: 6807.693586937417, place: { p: 'stack', k: 2 }, vx: 0, vy: 5.861381645140288 },
      { t: 'step', dt: 1e-09 },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'addBall', x: 129.33394, y: 37.21872, mass: 0.00159220872705117, place: { p: 'aim', k: 4, d: 120.95100000000001, off: 0.22609079999999993, a: 1.1265156 }, vx: 0, vy: -0.002648500138606701 },
      { t: 'addHole', x: 210, y: 190 },
      { t: 'addBall', x: 131.52722, y: 274.77708, mass: 1000000000, place: { p: 'free' }, vx: 1.4521116175877422, vy: 0 },
      { t: 'step', dt: 10 },
      { t: 'setVel', k: 30, vx: 578.0392556479994, vy: 18654.84349049709 },
      { t: 'addBall', x: 380.75154, y: -1.8566800000000008, place: { p: 'inHole', k: 22, f: 0.784773, a: 1.3621419 }, vx: 0, vy: -374.97300224548337 },
    ] as unknown as Op[]
    runScenario('counterexample', { contacts: 'fixed', e: 1, decel: 0, budget: 16 }, ops, ['finite', 'time'])
  })

  // the 1,462nd sequence of 'crowds (fixed)' at 30x the long run, shrunk: 84 balls at 1e5 px/s put down among 72
  // of mass 1e-9 and 28 specks in the closed elastic box. With no budget its steps take 19 s here (7,636 ticks
  // for 0.67 s simulated; drawn in full, 3.1 times the run budget). Its pairs are mostly of masses 1e9 apart:
  // the default UNLIKE_MASS_BUDGET meters their work, and its spans go lean (3.7 s, 2,664 ticks; 1.1 s, 631
  // ticks, 553 of them lean and 78 spans' last ticks skipped, since that budget counts the pairs of the span's
  // first try instead of every pair of its balls)
  it('fixed-tick contacts, no CONTACT_WORK_BUDGET: light balls pumped by a stream at 1e5 px/s take the budget for unlike masses and step within the run budget', () => {
    const ops = [
      { t: 'burst', n: 69, x: -20, y: 204.27704, spread: 22, speed: 30000, mass: 1e-9, seed: 182, aim: { p: 'aim', k: 10, d: 9.7834, off: -1.1953682, a: 5.5090854 } },
      { t: 'clearWalls' },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'burst', n: 28, x: 199.47474, y: 111.97184000000001, spread: 0, speed: 5000, radius: 0.03689775985701503, seed: 755, aim: { p: 'aim', k: 20, d: 82.67320000000001, off: -0.40546479999999996, a: 4.5559017 } },
      { t: 'burst', n: 3, x: 350, y: 354.97928, spread: 60, speed: 100000, mass: 1e-9, seed: 344, aim: { p: 'aim', k: 43, d: 159.6168, off: -1.016145, a: 5.8142196 } },
      { t: 'burst', n: 84, x: 258.13578, y: 56.63864000000001, spread: 0, speed: 100000, seed: 550, aim: { p: 'aim', k: 34, d: 197.74419999999998, off: -0.20111520000000005, a: 0.038493 } },
      { t: 'addHole', x: 370, y: 310, radius: 52.37248 },
      { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, e: 1, open: { left: false } },
      { t: 'step', dt: 1e-9 },
      { t: 'addHole', x: 210, y: 190, radius: 500 },
    ] as unknown as Op[]
    let lean = 0
    let skipped = 0
    runScenario('counterexample', { contacts: 'fixed', e: 1, decel: 0 }, ops, ['finite', 'events', 'time', 'overlap'], (sim) => {
      lean = sim.world.fixed!.lean
      skipped = sim.world.fixed!.budget[3]!
    })
    expect(lean).toBeGreaterThan(300)
    expect(skipped).toBeGreaterThan(20)
  })

  // the long run's two slowest pumped crowds, shrunk: 'crowds (fixed)' at 83x (the 2,065th sequence: 76 specks of
  // mass 1e9 at 3e4 px/s among 76 balls of mass 6e4 and 169 of mass 1) and at 101x (the 2,348th: 114 specks of
  // mass 1e9 at 1e5 px/s and 120 of mass 1 among 134 light balls), both in the closed elastic box. With the
  // budget for unlike masses at 16 visits to every pair of the span's balls (about 1.04 M a span for 370 balls),
  // they solved 2,217 and 2,998 ticks and stepped in 8.0 and 8.4 s alone (1.6 and 1.3 times the run budget in
  // the long run, on a loaded machine); at 16 visits to each pair the span's first try pairs (about 2,400),
  // 634 and 477 ticks, most spans' last ticks skipped, 1.4-2.0 s (src/contacts/fixedBudget.ts)
  it('fixed-tick contacts, no CONTACT_WORK_BUDGET: pumped crowds of specks of mass 1e9 spend the budget for unlike masses by the pairs they have, skip the last ticks of their spans, and step within the run budget', () => {
    const scale83 = [
        { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, e: 1, open: { bottom: false } },
        { t: 'step', dt: 1e-9 },
        { t: 'burst', n: 76, x: 288.92174, y: 30, spread: 1, speed: 300, radius: undefined, mass: 60255.95860743581, seed: 704, aim: { p: 'aim', k: 31, d: 107.9006, off: 0.6312256799999999, a: 0.5723423999999999, lip: 483.3595 } },
        { t: 'removeBall', k: 32 },
        { t: 'addBall', x: 230, y: 109.51847999999998, radius: 2.958012466551546, mass: 4.24619563946313e-8, place: { p: 'free' }, queue: undefined, vx: -352.3708710424873, vy: -0 },
        { t: 'burst', n: 76, x: 338.74204, y: 2.524840000000001, spread: 22, speed: 30000, radius: 0.11641260294104912, mass: 1000000000, seed: 793, aim: { p: 'aim', k: 45, d: 66.9996, off: -0.58131684, a: 3.7373616, lip: 503.271145 } },
        { t: 'setVel', k: 14, vx: 1.3628036707740054, vy: 3.1108356969045827 },
        { t: 'addBall', x: 400, y: 128.99092000000002, radius: 0.002884031503126606, mass: 0.07328245331389041, place: { p: 'overlap', k: 17, f: 1.9324293, a: 4.3639281 }, queue: 'front', vx: 0.019423480397050948, vy: -0.021229003108429564 },
        { t: 'addBall', x: 70.37988, y: 265.39004, radius: 0.012050359403717974, mass: undefined, place: { p: 'overlap', k: 15, f: 1.55544569, a: 5.8776732 }, queue: undefined, vx: -100000, vy: -0 },
        { t: 'burst', n: 133, x: 120, y: -17.1478, spread: 60, speed: 5000, radius: undefined, mass: undefined, seed: 197, aim: { p: 'aim', k: 13, d: 145.16039999999998, off: 0.6738544799999999, a: 1.6951409999999998, lip: 495.88399 } },
        { t: 'addHole', x: 370, y: 130, radius: 28.109851 },
        { t: 'throw', x: 210, y: 450, power: 0.950777, angle: 5.330465919051946, radius: 0.07906786279998249, mass: 76.38357835776907, place: { p: 'aim', k: 44, d: 178.1244, off: -0.10946260000000008, a: 4.4406621 }, queue: undefined },
        { t: 'setVel', k: 15, vx: -11.194378834671515, vy: -0 },
        { t: 'burst', n: 36, x: 152.10762, y: 170, spread: 22, speed: 5000, radius: undefined, mass: undefined, seed: 795, aim: { p: 'aim', k: 36, d: 124.8588, off: 1.0699728000000002, a: 4.4262350999999995 } },
        { t: 'addBall', x: 179.62022, y: -13.223880000000001, radius: 2.306747188720069, mass: 1000000000, place: { p: 'overlap', k: 23, f: 0.54206207, a: 3.6893745 }, queue: undefined, vx: 5e-324, vy: 5e-324 },
        { t: 'addBall', x: 348.07544, y: 195.38036, radius: undefined, mass: 12882495.51693135, place: { p: 'stack', k: 0 }, queue: 'front', vx: 35809.64371026363, vy: -0 },
        { t: 'step', dt: 0.004166666666666667 },
        { t: 'step', dt: 0.1 },
    ] as unknown as Op[]
    const scale101 = [
        { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, e: 1, open: { bottom: false } },
        { t: 'burst', n: 31, x: 0, y: 263.41612000000003, spread: 400, speed: 300, radius: undefined, mass: 3.944573020752785e-9, seed: 104, aim: { p: 'aim', k: 1, d: 199.9992, off: -0.6495357599999999, a: 2.7456785999999997, lip: 504.999955 } },
        { t: 'step', dt: 0.016666666666666666 },
        { t: 'removeBall', k: 9 },
        { t: 'burst', n: 114, x: 227.61891999999997, y: 379.08752000000004, spread: 1, speed: 100000, radius: 0.004477133041763623, mass: 1000000000, seed: 290, aim: { p: 'aim', k: 43, d: 6.7206, off: -1.2100608, a: 5.3988606 } },
        { t: 'step', dt: 0.004166666666666667 },
        { t: 'addHole', x: 210, y: 370, radius: 0.01 },
        { t: 'throw', x: 240, y: 52.67363999999999, power: 0.922345, angle: -3.930685329947863, radius: 0.0015452544395384142, mass: undefined, place: { p: 'free' }, queue: undefined },
        { t: 'setVel', k: 19, vx: -0, vy: 41.87935651179185 },
        { t: 'throw', x: 210, y: 450, power: 1, angle: 4.844675163842048, radius: undefined, mass: undefined, place: { p: 'aim', k: 9, d: 121.3878, off: 1.1739780000000002, a: 3.7563812999999997 }, queue: undefined },
        { t: 'addHole', x: 210, y: 130, radius: undefined },
        { t: 'burst', n: 120, x: 382.60442, y: 18.514320000000005, spread: 22, speed: 100000, radius: 0.022698648518838224, mass: undefined, seed: 835, aim: { p: 'aim', k: 31, d: 84.23079999999999, off: 0.67872996, a: 1.4477967, lip: 483.917005 } },
        { t: 'burst', n: 103, x: 22698.648518838214, y: 31.216879999999996, spread: 400, speed: 5000, radius: undefined, mass: 3.9627803425543934e-5, seed: 433, aim: { p: 'aim', k: 47, d: 187.571, off: 0.5725954, a: 5.7591198 } },
        { t: 'addHole', x: 343.95062, y: 450, radius: 52.619631000000005 },
    ] as unknown as Op[]
    for (const [ops, most] of [[scale83, 1200], [scale101, 1200]] as const) {
      let ticks = 0
      let skipped = 0
      runScenario('counterexample', { contacts: 'fixed', e: 1, decel: 0 }, ops, ['finite', 'events', 'time', 'overlap'], (sim) => {
        ticks = sim.world.fixed!.ticks
        skipped = sim.world.fixed!.budget[3]!
      })
      expect(ticks).toBeLessThan(most)
      expect(skipped).toBeGreaterThan(20)
    }
  })

  // exact contacts, e = 0: a ball of mass 1e-3 settled against one of mass 1,000 in a corner, which a third
  // ball's hit then nudged toward it at 8.2e-4 px/s, below the settle floor of 1e-3 px/s then: never a
  // contact, the pair sank into itself, 1.00004e-3 px deep 0.67 s after the last spawn (found at 71x the long
  // run). At the floor of 1e-5 px/s the nudge settles the pair
  it('contacts on: a pair nudged together slower than 1e-3 px/s settles instead of sinking into itself', () => {
    const ops = [
      { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, e: 0, open: { bottom: true } },
      { t: 'burst', n: 15, x: -9.762239999999998, y: 48.38364, spread: 400, speed: 5000, mass: 0.001, seed: 23 },
      { t: 'throw', x: 0, y: 0, power: 0, angle: -6.283185307179586, mass: 1000, place: { p: 'inHole', k: 0, f: 0, a: 0 } },
      { t: 'step', dt: 0.1 },
      { t: 'step', dt: 10 },
      { t: 'step', dt: 10 },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'throw', x: 210, y: 450, power: 0, angle: -6.283185307179586, mass: 1, place: { p: 'aim', k: 0, d: 0, off: -1.3, a: 0 } },
    ] as unknown as Op[]
    runScenario('counterexample', { contacts: 'on', e: 0, decel: 0 }, ops, ['overlap'])
  })

  // big and small balls pressed in the panel's walls: the projection's last sweep over the moving balls' pairs
  // was cut short by the budget, and the overlap of the pairs it had reached was read as the whole tick's,
  // so the tick, 3.7e-3 px deep, was not counted in world.fixed.capped (whose ticks the overlap check skips)
  it('fixed-tick contacts: a projection whose budget runs out part way through a sweep counts the tick as capped', () => {
    const aim = (k: number, d: number, off: number, a: number, lip?: number) => ({ p: 'aim' as const, k, d, off, a, ...(lip === undefined ? {} : { lip }) })
    const ops = [
      ...PANEL_HOLES.map((h) => ({ t: 'addHole', ...h })),
      { t: 'burst', n: 11, x: -20, y: 1000, spread: 400, speed: 0, radius: undefined, mass: undefined, seed: 239, aim: aim(36, 56.0618, 0.58703964, 4.0014639, 501.1102) },
      { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, e: undefined, open: { top: true } },
      { t: 'burst', n: 15, x: -20, y: -20, spread: 400, speed: 0, radius: 33.265955329400455, mass: undefined, seed: 526, aim: aim(0, 35.6124, -0.57, 4.987584, 462.86434) },
      { t: 'step', dt: 0.25 },
      { t: 'burst', n: 11, x: -20, y: -20, spread: 60, speed: 1000, radius: 6.591738952443213, mass: undefined, seed: 809, aim: aim(35, 69.0628, -0.5743088, 4.1875029) },
      { t: 'step', dt: 0.25 },
      { t: 'addBall', x: 387.42752, y: 7.344200000000001, radius: 2.1037784397664754, mass: 841.3951416451948, place: { p: 'free' }, vx: -2223.309890651403, vy: -0 },
    ] as unknown as Op[]
    runScenario('counterexample', { contacts: 'fixed', e: 0, decel: 0 }, ops, ['overlap'])
  })

  // eight small balls put down on one point roll out and stop: a rolling ball pushes a resting one, which the
  // projection moved 1.2–1.6e-3 px into a resting ball the tick had not paired with it
  it('fixed-tick contacts: a ball the projection pushes into a resting ball it was not paired with is paired with it in the same tick', () => {
    const ops = [
      { t: 'burst', n: 8, x: 0, y: -20, spread: 0, speed: 50, radius: 1.0914403364487566, mass: 1, seed: 9, aim: undefined },
      { t: 'step', dt: 1e-9 },
    ] as unknown as Op[]
    runScenario('counterexample', { contacts: 'fixed', e: 0, decel: 300 }, ops, ['overlap'])
  })

  // thirteen 1e-9-mass balls and fifteen of mass 1 at 1,000 px/s in closed walls of restitution 0: the
  // projection pushed a light ball out of a heavy one 7 px into a mass-1 ball lying still but still rolling,
  // which the tick had not paired with it, and left them 3.6 px deep after the tick (found at 250x the long
  // run; the same-tick pairing now takes moving balls too)
  it('fixed-tick contacts: a ball the projection pushes into a moving ball it was not paired with is paired with it in the same tick', () => {
    const ops = [
      { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, e: 0, open: { bottom: false } },
      { t: 'burst', n: 13, x: 137.73584, y: 371.99576, spread: 22, speed: 1000, radius: undefined, mass: 1e-9, seed: 8, aim: undefined },
      { t: 'step', dt: 10 },
      { t: 'burst', n: 15, x: 407.74204, y: 264.2112, spread: 400, speed: 1000, radius: 7.709034690644301, mass: 1, seed: 503, aim: undefined },
      { t: 'setVel', k: 13, vx: -1.2246467991473532e-16, vy: 1 },
    ] as unknown as Op[]
    runScenario('counterexample', { contacts: 'fixed', e: 0, decel: 0 }, ops, ['overlap'])
  })

  // the 319th sequence of 'crowds (fixed)' at 30x the long run (after the last guard counted its fronts as
  // groups of balls): a push through balls at rest that its projection's join rounds stopped at their bound
  // (past MAX_WIDEN_ROUNDS, a round that paired more than one ball) left a radius-11 ball at rest pushed
  // 0.0032 px into another at rest that the tick had not paired, and the tick was not counted as capped. Such a
  // tick now pairs what its last projection pushed and counts as capped, as a lean tick does at its bound;
  // the next ticks take the overlap out
  it('fixed-tick contacts: a tick whose join rounds stop at their bound with a pushed ball in an unpaired one counts as capped, and the overlap goes', () => {
    const ops = [
      { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, e: 1, open: { bottom: false } },
      { t: 'addHole', x: 50, y: 130 },
      { t: 'addHole', x: 50, y: 190 },
      { t: 'addHole', x: 50, y: 250 },
      { t: 'addHole', x: 50, y: 310 },
      { t: 'addHole', x: 50, y: 370 },
      { t: 'addHole', x: 130, y: 130 },
      { t: 'addHole', x: 130, y: 190 },
      { t: 'addHole', x: 130, y: 250 },
      { t: 'addHole', x: 130, y: 310 },
      { t: 'addHole', x: 130, y: 370 },
      { t: 'addHole', x: 210, y: 130 },
      { t: 'addHole', x: 210, y: 190 },
      { t: 'addHole', x: 210, y: 250 },
      { t: 'addHole', x: 210, y: 310 },
      { t: 'addHole', x: 210, y: 370 },
      { t: 'addHole', x: 290, y: 130 },
      { t: 'addHole', x: 290, y: 190 },
      { t: 'addHole', x: 290, y: 250 },
      { t: 'addHole', x: 290, y: 310 },
      { t: 'addHole', x: 290, y: 370 },
      { t: 'addHole', x: 370, y: 130 },
      { t: 'addHole', x: 370, y: 190 },
      { t: 'addHole', x: 370, y: 250 },
      { t: 'addHole', x: 370, y: 310 },
      { t: 'addHole', x: 370, y: 370 },
      { t: 'burst', n: 98, x: 439.99908000000005, y: 80, spread: 0, speed: 100000, radius: undefined, mass: undefined, seed: 6, aim: undefined },
      { t: 'throw', x: 0, y: -20, power: 0.221968, angle: -6.283185307179586, radius: undefined, mass: 1e-9, place: { p: 'aim', k: 36, d: 149.7168, off: 0.6535188, a: 5.4148122, lip: 460 }, queue: undefined },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'burst', n: 13, x: 0, y: 0, spread: 60, speed: 5000, radius: undefined, mass: undefined, seed: 482, aim: { p: 'aim', k: 48, d: 86.0906, off: -0.49674299999999993, a: 0.6887349 } },
      { t: 'burst', n: 133, x: 25.3054, y: 223.36676, spread: 60, speed: 300, radius: undefined, mass: undefined, seed: 455, aim: { p: 'aim', k: 11, d: 143.90259999999998, off: -0.7414316000000001, a: 1.1952297 } },
      { t: 'addBall', x: 0, y: 454.26184, radius: 0.03614098626396133, mass: undefined, place: { p: 'free' }, queue: 'front', vx: 0, vy: 6.998419960022734 },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'addHole', x: 409.47164, y: 150.64892, radius: 500 },
      { t: 'burst', n: 64, x: 57.93458, y: 376.80576, spread: 0, speed: 300, radius: 0.0017619760464116293, mass: 2.6121613543992052e-9, seed: 492, aim: { p: 'aim', k: 32, d: 145.2288, off: -0.849862, a: 2.0289906 } },
      { t: 'removeHole', k: 23 },
      { t: 'step', dt: 1e-9 },
      { t: 'step', dt: 1e-9 },
      { t: 'addBall', x: 350, y: 14.288800000000002, radius: 0.004988844874600122, mass: undefined, place: { p: 'aim', k: 22, d: 81.3326, off: 0.6302435999999999, a: 5.0995098, lip: 497.90521 }, queue: 'front', vx: -100000, vy: -0 },
      { t: 'addBall', x: 332.10515999999996, y: 203.93903999999998, radius: 0.07294575102545686, mass: 4.8305880203977284e-8, place: { p: 'stack', k: 21 }, queue: undefined, vx: 8241.38115013002, vy: -0 },
      { t: 'setVel', k: 19, vx: -0, vy: 0.01374041975012515 },
      { t: 'addBall', x: -1.283900025861806e-61, y: 157.0964, radius: 383.70724549227884, mass: undefined, place: { p: 'free' }, queue: undefined, vx: 1.981527025805098, vy: -0 },
      { t: 'throw', x: 0.3366000000000007, y: 150, power: 1, angle: 2.9526572714029022, radius: 0.014028137045619582, mass: undefined, place: { p: 'free' }, queue: undefined },
      { t: 'addHole', x: 60, y: 272.33568, radius: undefined },
      { t: 'step', dt: 10 },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'step', dt: 0.25 },
      { t: 'throw', x: 299.4079, y: 376.4324, power: 0.481514, angle: -5.161159207764684, radius: undefined, mass: 0.24660393372343392, place: { p: 'aim', k: 39, d: 32.190200000000004, off: 0.6274429199999999, a: 2.6513739, lip: 470.081035 }, queue: undefined },
      { t: 'addHole', x: 50, y: 190, radius: 34.632478000000006 },
    ] as unknown as Op[]
    runScenario('counterexample', { contacts: 'fixed', e: 0, decel: 300 }, ops, ['finite', 'events', 'time', 'overlap'])
  })

  // a heavy ball drives a column into the corner (walls of restitution 0): a settling contact's cluster took
  // a ball touching a member across a grid-cell boundary only when that ball's capsule in the hash happened
  // to reach over it, which depends on when the ball was last predicted, so the trace differed with the
  // prediction horizon (the lookups now reach past the touch gap)
  it('contacts on: a settling cluster in a pressed corner is the same with PREDICTION_HORIZON 0 and 0.5 s', () => {
    const ops = [
      { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, e: 0, open: { bottom: true } },
      { t: 'burst', n: 9, x: 0, y: -20, spread: 0, speed: 0, radius: undefined, mass: 0.001, seed: 0, aim: undefined },
      { t: 'burst', n: 13, x: 426.05786, y: 320.1372, spread: 60, speed: 5000, radius: undefined, mass: 1.0046157902783952, seed: 610, aim: undefined },
      { t: 'addHole', x: 290, y: 370, radius: undefined },
      { t: 'addBall', x: -20, y: -20, radius: 2, mass: undefined, place: { p: 'stack', k: 0 }, vx: -1.2246467991473532e-16, vy: 1 },
      { t: 'throw', x: -20, y: -20, power: 0, angle: -6.283185307179586, radius: 2, mass: 1, place: { p: 'overlap', k: 0, f: 0, a: 0 } },
      { t: 'setVel', k: 42, vx: -1.2246467991473532e-16, vy: 1 },
      { t: 'burst', n: 2, x: -20, y: -20, spread: 0, speed: 1000, radius: 5.14043651582426, mass: 1000, seed: 0, aim: { p: 'aim', k: 0, d: 0, off: -0.42512079999999997, a: 0 } },
      { t: 'step', dt: 1e-9 },
      { t: 'step', dt: 1e-9 },
    ] as unknown as Op[]
    const cfg = { contacts: 'on', e: 1, decel: 0 } as const
    const stepwise = runScenario('counterexample', { ...cfg, horizon: 0 }, ops, [], undefined, RUN_DEV_MS, true)
    const kept = runScenario('counterexample', { ...cfg, horizon: 0.5 }, ops, [], undefined, RUN_DEV_MS, true)
    // the scene does reach the pressed corner: a cluster settles in it
    expect(stepwise).toContain('"type":"rest"')
    expect(kept).toBe(stepwise)
  })

  // a ball put down on a ball that had rolled past the coordinate bound (y = 1e9 + 12) was put down where it
  // was, and addBall refused the spawn: the suite's spawns on a ball are held within the bound, as its others
  it('contacts off: a ball stacked on one that has rolled past the coordinate bound is put down within it', () => {
    const ops = [
      { t: 'burst', n: 2, x: -20, y: 1000000000, spread: 0, speed: 50, radius: 1, mass: undefined, seed: 0, aim: undefined },
      { t: 'step', dt: 0.25 },
      { t: 'addBall', x: 0, y: 0, radius: 1, mass: undefined, place: { p: 'stack', k: 7 }, vx: -1.2246467991473532e-11, vy: 100000 },
      { t: 'step', dt: 1e-9 },
    ] as unknown as Op[]
    let far = 0
    runScenario('counterexample', { contacts: 'off', e: 0, decel: 0 }, ops, ['finite', 'events', 'time'], (sim) => {
      for (const b of sim.balls()) far = Math.max(far, Math.abs(sim.ballState(b).y))
    })
    // the first balls did roll past it: the case is still the one the long run found
    expect(far).toBeGreaterThan(1e9)
  })

  // 108 balls (two at 1e5 px/s, 103 of mass 1e-9 at 5,000 px/s, two of mass 4-6e7) in a closed box of
  // 60 × 21 px, narrower than a ball: each ball touched about eighty others, every tick's projection spent
  // its budget, and each push read all the pairs of both its balls to queue them again (5,378 × pairs a
  // tick): a step of 0.25 s took 6.6 s on a machine whose reference workload runs 3.5× slower than the
  // development machine, over the step budget. The projection's queueing now has a budget of its own: 1.8 s
  // (measured alone, as 6.6 s was)
  it('fixed-tick contacts: a crowd jammed in a box narrower than a ball steps within the step budget (the projection bounds its queueing)', () => {
    const ops = [
      { t: 'burst', n: 2, x: -20, y: 0, spread: 0, speed: 100000, radius: undefined, mass: 1, seed: 32, aim: undefined },
      { t: 'burst', n: 103, x: 43.252759999999995, y: 100, spread: 400, speed: 5000, radius: undefined, mass: 1e-9, seed: 0, aim: undefined },
      { t: 'setVel', k: 44, vx: -0.11241288544819156, vy: -0.26415365734078333 },
      { t: 'addHole', x: 50, y: 310, radius: 28.198705 },
      { t: 'addBall', x: 40, y: 448.96252, radius: undefined, mass: 36812897.36425313, place: { p: 'stack', k: 50 }, vx: -0.005807644175213117, vy: -0 },
      { t: 'addBall', x: 3.453558480556791e-236, y: 68.18732, radius: undefined, mass: 57147863.66718666, place: { p: 'aim', k: 36, d: 119.73259999999999, off: -1.0483512, a: 2.4484257 }, vx: 5e-324, vy: -0 },
      { t: 'walls', minX: 195.64202, minY: 193.24419999999998, w: 60, h: 21, e: 1, open: { left: false, right: false, bottom: false } },
      { t: 'step', dt: 1 / 60 },
      { t: 'step', dt: 1 / 240 },
      { t: 'step', dt: 10 },
      { t: 'addBall', x: 38.882760000000005, y: 0, radius: 1.241652307592411, mass: undefined, place: { p: 'aim', k: 39, d: 8.7398, off: 1.0380161999999997, a: 2.7940374 }, vx: -0, vy: -51760.683195056816 },
      { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, e: 0, open: { left: true, top: false, right: true, bottom: true } },
    ] as unknown as Op[]
    let capped = 0
    const t0 = performance.now()
    runScenario('counterexample', { contacts: 'fixed', e: 0, decel: 0 }, ops, ['finite', 'events', 'time', 'overlap'], (sim) => {
      capped = sim.world.fixed!.capped
    })
    // the whole run, 43 steps, within 1.5 s on the development machine (2.7 s on the one above; the 0.25 s
    // step alone took longer before)
    expect(performance.now() - t0).toBeLessThan(1500 * SLOWDOWN)
    // the jam is the one the long run found: its ticks spend the projection's budget (28 ticks; 108 before the
    // velocity sweeps wedged the balls wider than the 21 px box's height, as the walls system does)
    expect(capped).toBeGreaterThan(20)
  })

  // the long run at 43×, after a tick of many pairs a candidate was first solved again for a push's front
  // (DEEP_FRONTS): a crowd of 106 balls at 1e5 px/s among light ones, squeezed by a box 5 × 1e-6 px, has
  // 4–5 pairs a candidate from its radii; solved again at a finer spacing for two balls moving into the
  // walls, it stayed there tick after tick (too many pairs to coarsen back, too few to halve), 17.3 s of
  // stepping against a 12.0 s run budget (0.5 s before that rule). Such a tick is now solved again only when
  // its pairs before the widening rounds are few, and a halved tick whose pairs a finer one would not thin
  // coarsens back
  it('fixed-tick contacts: a crowd squeezed by a box narrower than a ball, its ticks solved again for a ball moving into a wall, coarsens back to the full tick', () => {
    const ops = [
      ...PANEL_HOLES.map((h) => ({ t: 'addHole', ...h })),
      { t: 'burst', n: 12, x: -20, y: -20, spread: 0, speed: 300, radius: undefined, mass: 1.0092528860766834e-06, seed: 0, aim: { p: 'aim', k: 7, d: 0.0022, off: -1.3, a: 0.2997036 } },
      { t: 'addBall', x: 341.10138, y: 39.35592, radius: 1.309181922999407, mass: 121898.95989248673, place: { p: 'aim', k: 38, d: 92.8152, off: 0.65450436, a: 2.9963556, lip: 479.94886 }, vx: -0.054101332267423564, vy: -0.09888774898325502 },
      { t: 'burst', n: 106, x: -8.132970715568789e-118, y: 68.34487999999999, spread: 0, speed: 100000, radius: undefined, mass: undefined, seed: 191, aim: { p: 'aim', k: 38, d: 14.8484, off: 0.6677112000000001, a: 0.3796947 } },
      { t: 'setVel', k: 7, vx: 0, vy: 0.7227698036021704 },
      { t: 'removeBall', k: 10 },
      { t: 'addBall', x: 126.75564, y: 475.72952, radius: undefined, mass: 1.7741894808901643e-06, place: { p: 'free' }, vx: 0.15958791472367326, vy: 0 },
      { t: 'removeHole', k: 46 },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'throw', x: 160.3545, y: -6.105196726911953e-41, power: 1, angle: 5.678152261210034, radius: undefined, mass: 159.220872705117, place: { p: 'free' } },
      { t: 'setVel', k: 28, vx: -0.009243645392322801, vy: -0.007252133915012735 },
      { t: 'throw', x: 210, y: 450, power: 0.850401, angle: 5.961812945087965, radius: 0.11455129414455358, mass: 1.678804018122559e-06, place: { p: 'free' } },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, e: 0, open: { top: false, right: false } },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'addBall', x: 279.11868, y: -1.8029142947010997e-231, radius: undefined, mass: 375837.4042884443, place: { p: 'free' }, vx: 5e-324, vy: 0 },
      { t: 'step', dt: 1e-09 },
      { t: 'addBall', x: 257.5893, y: 489.21416, radius: 0.03265878321723358, mass: 1.4125375446227555e-05, place: { p: 'inHole', k: 0, f: 0.677204, a: 5.3080461 }, vx: 7.005644052881236, vy: 252.25081375923435 },
      { t: 'addHole', x: 210, y: 310, radius: 21.352345 },
      { t: 'step', dt: 0.25 },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'walls', minX: 125.26432, minY: 60, w: 5, h: 1e-06, e: 0.5, open: { left: false, top: false, right: false, bottom: false } },
      { t: 'step', dt: 0.016666666666666666 },
      { t: 'throw', x: 19.02042, y: 287.4032, power: 1, angle: -5.580875986284281, radius: 0.015346169827992941, mass: undefined, place: { p: 'free' } },
      { t: 'step', dt: 1e-09 },
      { t: 'addHole', x: 210, y: 190, radius: undefined },
    ] as unknown as Op[]
    // 1.02 s of simulated time: 122 ticks at the full spacing, 290 before the rule (the burst's own halvings),
    // 298 with it; 355 without the bound on the pairs before the widening, 362 (and still halved at the end)
    // without coarsening such a tick back, and both left out, 12 s of stepping. 332 since a moving light
    // ball is solved with its wall only when its partner closes the room to the wall within the tick; 306 since
    // a tick of at most one pair a candidate before its rounds is solved again for up to DEEP_ROW_FRONTS pairs
    // closing deep. All that with the tick never halved for the balls' travel (CONTACT_TRAVEL_HALVINGS 0, the
    // default); with that rule at 4 (e = 0.5 here) the 1e5 px/s burst's balls halve the ticks while they fly: 470
    for (const travel of [0, 4]) {
      let ticks = 0
      let halvings = -1
      let time = 0
      runScenario('counterexample', { contacts: 'fixed', e: 0.5, decel: 0, travel }, ops, ['finite', 'events', 'time'], (sim) => {
        ticks = sim.world.fixed!.ticks
        halvings = sim.world.fixed!.halvings
        time = sim.time
      })
      expect(time).toBeGreaterThan(1)
      expect(halvings).toBe(0)
      expect(ticks).toBeLessThan(travel === 0 ? 345 : 500)
    }
  })

  // the long run at 41×: a round that widened a ball into a closed wall without new pairs solved once more
  // (so a ball sent to the wall turns at the tick), but a ball the wall cannot send back (one of radius
  // 6,109, wider than its box) kept it going round after round to the rounds' bound: 15.5 s for one step,
  // 0.1 s before and now (the extra solve is once a tick)
  it('fixed-tick contacts: a ball wider than its box among 1e9-mass balls and one at 1e5 px/s: the extra solve at a wall does not repeat round after round', () => {
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 0.5, ROLLING_DECEL: 0 })
    for (const h of PANEL_HOLES) sim.addHole(h)
    sim.addBall({x: -20, y: -20, vx: 0, vy: 0, mass: 1})
    sim.addBall({x: -20, y: -20, vx: 0, vy: 0, mass: 1})
    // 20 balls of mass 1e9 and radius 0.19 thrown together at 485 px/s
    const at = [
      [426.5249233160241, 120.9045731685182], [629.1914400124374, -62.94931021334676], [341.28218097629633, 246.13406936314044],
      [548.9119110666228, 279.0076974806914], [436.95050920175447, 143.72655463900153], [327.739609492398, 236.13513948537542],
      [341.9567092326691, -17.06952577930025], [673.3557889854752, 207.26387963358854], [426.3795030701301, 76.8265004287168],
      [456.57592635399976, -11.887367574954197], [502.4858288288008, -4.156473594367839], [304.6445694583167, 77.79728668029658],
      [344.71670063389814, -29.894045322661412], [522.0394788222063, 234.0389655721126], [293.8604769077856, 29.55378990455604],
      [580.3586991687536, 5.175329992586327], [646.4885388061308, 249.39011539160177], [561.5569859839267, 4.781832607318464],
      [574.6041495509887, 88.45990421966077], [289.14037055719234, 298.7263554826538],
    ]
    for (const [x, y] of at) sim.addBall({ x: x!, y: y!, vx: -484.26774144614166, vy: -30.994415036276248, radius: 0.1927524913190936, mass: 1e9 })
    sim.addBall({x: 327.0159188048871, y: 234.07132244473516, vx: 0.33282967686787496, vy: 0.48904966335167144, radius: 42.072662838444415, mass: 60117373.74832779})
    sim.clearWalls()
    sim.removeBall(32)
    sim.setWalls({minX: 67.2367, minY: 497.80664, maxX: 72.2367, maxY: 557.80664, restitution: 0, open: {left: false, top: false, right: true, bottom: true}})
    sim.addBall({x: 419.99999999999994, y: 227.92247999999998, vx: 0.6665773780504004, vy: 0.7115331283417063})
    sim.addBall({x: 214.91280140510634, y: 179.5051699015897, vx: 0, vy: 301.3006024186122, mass: 1.0889300933334354e-9})
    sim.removeHole(10)
    sim.setWalls({minX: 0, minY: 0, maxX: 420, maxY: 480, open: {left: false, right: true, bottom: false}})
    sim.setBallVelocity(29, 0, -5e-324)
    sim.throwBall({x: 452.4270989075491, y: 6632.63289738339, power: 0, angle: -0.06227790629927736, radius: 6109.420249055721})
    sim.throwBall({x: 344.71670063389814, y: -29.894045322661412, power: 0.000003, angle: 1.5384504888335364, radius: 0.5407543229455808})
    sim.setWalls({minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 1, open: {top: false, right: true, bottom: false}})
    sim.setBallVelocity(43, -5.026548243619013, 99999.99987366906)
    sim.removeBall(26)
    sim.removeHole(23)
    sim.throwBall({x: 147.96125089875497, y: 249.13640857347158, power: 0, angle: -5.775453668877018, radius: 69.82324040771715, mass: 1.0115794542598986})
    sim.setWalls({minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 1, open: {left: false, top: false, right: false, bottom: false}})
    sim.step(1 / 60)
    const t0 = performance.now()
    sim.step(0.25)
    expect(performance.now() - t0).toBeLessThan(STEP_BUDGET_MS / 2)
    for (const b of sim.balls()) expect(Number.isFinite(sim.ballState(b).x)).toBe(true)
  })

  // the long run at 59×: heavy balls (mass 5.2e8) thrown at 1e5 px/s and light ones (9.8) at 5,000 px/s into a
  // closed 420 × 480 box, no deceleration, walls of restitution 0 (and the balls' 0; shrunk again after the
  // change, 0.5). In the corners heavy balls pressed light
  // ones against light ones lying at a wall, in piles (their normals 50° and more apart, not rows): the
  // sweeps take a heavy ball's push down by about the mass ratio each, so they ran out with the pile still
  // closing, the projection held the positions, and 76 of 166 rolling balls kept velocities of up to 3.3e4
  // px/s while they did not move, tick after tick. Their reach halved the tick 5 times: 1,797 ticks for the
  // step of 0.25 s (3.4 s against a step budget of 3.0 s), 90 ms for every frame after
  it.each([0, 0.5])('fixed-tick contacts: heavy balls pressing light ones into a corner pile with restitution %s stop there (no ball keeps a velocity it cannot move at), and the tick is not halved for them', (e) => {
    const ops = [
      { t: 'walls', minX: 0, minY: 0, w: 420, h: 480, e: 0, open: { bottom: false } },
      { t: 'burst', n: 69, x: -20, y: -19.9922, spread: 400, speed: 100000, radius: undefined, mass: 519995996.53351516, seed: 811, aim: { p: 'aim', k: 19, d: 0.002, off: -0.5700015599999999, a: 0.00011970000000000001, lip: 460.000585 } },
      { t: 'burst', n: 114, x: 271.28764, y: 190, spread: 400, speed: 5000, radius: undefined, mass: 9.794899854086989, seed: 889, aim: undefined },
      { t: 'addBall', x: 1.2221053941287913e-55, y: 30690219.88391158, radius: 0.13645831365889247, mass: 2.857590543374944e-9, place: { p: 'inHole', k: 30, f: 0.000955, a: 3.0251213999999997 }, vx: -68.70174968148031, vy: -262.8126568558169 },
      { t: 'step', dt: 10 },
    ] as unknown as Op[]
    let ticks = 0
    let halvings = -1
    let pressing = 0
    runScenario('corner pile', { contacts: 'fixed', e, decel: 0 }, ops, ['finite', 'events', 'time', 'overlap'], (sim) => {
      const F = sim.world.fixed!
      ticks = F.ticks
      halvings = F.halvings
      const B = sim.world.Ball
      const ids = sim.balls().filter((b) => sim.ballState(b).mode === 'rolling' || sim.ballState(b).mode === 'resting')
      for (const a of ids) {
        for (const b of ids) {
          const dx = B.x[b]! - B.x[a]!
          const dy = B.y[b]! - B.y[a]!
          const d = Math.hypot(dx, dy)
          if (a === b || d > B.radius[a]! + B.radius[b]! + 1e-3) continue
          // closing on a ball it touches faster than 100 px/s after the last tick's solve: a push left standing
          if (-((B.vx[b]! - B.vx[a]!) * dx + (B.vy[b]! - B.vy[a]!) * dy) / d > 100) pressing++
        }
      }
    })
    // 0.92 s in all: 110 ticks of 1/120 s, 148 (e = 0) and 177 (e = 0.5) with the tick halved where the heavy
    // balls first strike (e = 0.5, held only at e = 0: 2,579 ticks, 28 pairs closing faster than 100 px/s).
    // A pair or two left closing at the end is what such piles leave: over 72 variants of this scene (the two
    // bursts' seeds + 0…35, both restitutions), 36 end with one or more (144 pair sides in all) with the code
    // before a ball only a wall turns in a tick kept its path to the wall (src/contacts/fixedWallTurn.ts), 44
    // (154) since; this one ends with 2 pairs (e = 0) and 1 (e = 0.5) since, none before. At e = 0.5 the
    // tick is also halved for the heavy balls' travel (CONTACT_TRAVEL_HALVINGS, 4 by default) while they
    // close on the pile: 372 ticks. Since a projection whose last sweep left no overlap over the slop is no
    // longer counted as capped (src/contacts/fixedProject.ts: settled), its tick goes on to pair the balls it
    // pushed into resting ones: over the 72 variants, 35 end with pairs closing (132 pair sides), against 33
    // (122) the day before; this one with 1 pair (e = 0) and 4 (e = 0.5: closing at 104–525 px/s, with 84 of
    // its 184 balls moving faster than 100 px/s), against 1 and none. The failure this guards against left
    // 76 balls standing at up to 3.3e4 px/s
    expect(pressing).toBeLessThanOrEqual(8)
    expect(halvings).toBe(0)
    expect(ticks).toBeLessThan(e === 0 ? 300 : 450)
  })

  // the contact normal from the swept test was d + u·τ over the radii's sum: a difference of two lengths of a
  // tick's travel (250 px) taken to 0.14 px, unit only to 1e-10, so the elastic impulse of equal balls
  // left the pair 0.64 of 4.5e8 (1.4e-9) richer; it is now divided by its own length
  it('fixed-tick contacts: a radius-0.07 ball at 3e4 px/s striking an equal one at rest keeps the energy (the swept normal is a unit vector)', () => {
    const ops = [
      ...PANEL_HOLES.map((h) => ({ t: 'addHole', ...h })),
      { t: 'burst', n: 2, x: -20, y: -20, spread: 0, speed: 30000, radius: 0.06982324040771715, mass: 1, seed: 0, aim: { p: 'aim', k: 0, d: 76.3468, off: 0.38568400000000014, a: 5.3765586 } },
      { t: 'step', dt: 10 },
      { t: 'setVel', k: 0, vx: -1.2246468e-316, vy: 1e-300 },
    ] as unknown as Op[]
    runScenario('counterexample', { contacts: 'fixed', e: 1, decel: 0 }, ops, ['finite', 'events', 'energy'])
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 1, ROLLING_DECEL: 0 })
    const a = sim.addBall({ x: 0, y: 0, vx: 0, vy: 0, radius: 0.06982324040771715 })
    const b = sim.addBall({ x: 139.25, y: -207.63, vx: -16710.100389570063, vy: 24915.307442824993, radius: 0.06982324040771715 })
    const B = sim.world.Ball
    const ke = () => 0.5 * (B.vx[a]! ** 2 + B.vy[a]! ** 2 + B.vx[b]! ** 2 + B.vy[b]! ** 2)
    const before = ke()
    sim.step(1 / 60)
    expect(sim.drainEvents().filter((e) => e.type === 'collision')).toHaveLength(1)
    expect(ke()).toBeLessThanOrEqual(before * (1 + 4 * Number.EPSILON))
  })
})
