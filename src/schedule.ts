// The step pipeline as data: an ordered list of named systems. One step runs the list once over every
// moving ball (pass 0), then again for the balls that stopped at an event, until no ball has an event left
// before the step's end or MAX_EVENT_PASSES is reached (the balls still behind then wait out the rest of the
// step where they are: src/motion/pause.ts). A game may read the list, reorder with care, or add its own systems; each added system
// runs in every pass and can tell passes apart by `world.pass` (a step is one window or several: the fixed
// tick's contact ticks and the launcher's instants split it, and each window starts at pass 0).
import { bounceSystem } from '../systems/bounce.js'
import { captureSystem } from '../systems/capture.js'
import { collisionsSystem } from '../systems/collisions.js'
import { cogGateSystem } from '../systems/cogGate.js'
import { fixedContactsSystem } from '../systems/fixedContacts.js'
import { tabulatedRimSystem } from '../systems/tabulatedRim.js'
import { heroReferenceSystem } from '../systems/heroReference.js'
import { integrationSystem, setLipBatching } from '../systems/integration.js'
import { launcherSystem } from '../systems/launcher.js'
import { rimRollSystem } from '../systems/rimRoll.js'
import { skipOverSystem } from '../systems/skipOver.js'
import { dropGoneHeld, orderMoving } from './world/idLists.js'
import { MOVING_ORDER_CHURN, MOVING_ORDER_MIN, TICK_SNAP } from './config/tolerances.js'
import { nearTick } from './contacts/fixedHalve.js'
import { gridInstant, instantOut, tickInstant } from './world/gridTime.js'
import { wallsSystem } from '../systems/walls.js'
import { NAIVE_SUBSTEP, V1_SUBSTEP, repeatSubsteps } from '../systems/variants/naive/schedule.js'
import { v1RuleSystem } from '../systems/variants/v1Rule.js'
import { CONFIG_RANGES, METHODS, type BallPhysicsConfig } from './config/design.js'
import { checkWorld, describe } from './check.js'
import { waitOutStep } from './motion/pause.js'
import type { BallWorld } from './world/createWorld.js'
import type { ScheduleEntry } from './world/system.js'
import { record } from './world/recorder.js'

export type { ScheduleEntry, System } from './world/system.js'
/**
 * the launcher (held balls whose spots are clear; a no-op unless contacts are on and a ball is held), the
 * fixed-tick contact solve (a no-op unless BALL_COLLISIONS is 'fixed' and a contact tick starts the pass), integration, the hero ball's reference (only balls flagged hero; docs/physical.md), skip-over (Stage 5),
 * capture (Stage 1), COG gate (Stage 6), bounce (Stages 2, 4), rim-roll (Stage 3), then the panel's walls
 * (a no-op in a world without walls), then ball-ball contacts (a no-op unless BALL_COLLISIONS is 'on').
 */
export const DEFAULT_SCHEDULE: readonly ScheduleEntry[] = Object.freeze([
  Object.freeze({ name: 'launcher', run: launcherSystem }),
  Object.freeze({ name: 'fixedContacts', run: fixedContactsSystem }),
  Object.freeze({ name: 'integration', run: integrationSystem }),
  Object.freeze({ name: 'heroReference', run: heroReferenceSystem }),
  Object.freeze({ name: 'tabulatedRim', run: tabulatedRimSystem }),
  Object.freeze({ name: 'skipOver', run: skipOverSystem }),
  Object.freeze({ name: 'capture', run: captureSystem }),
  Object.freeze({ name: 'cogGate', run: cogGateSystem }),
  Object.freeze({ name: 'bounce', run: bounceSystem }),
  Object.freeze({ name: 'rimRoll', run: rimRollSystem }),
  Object.freeze({ name: 'walls', run: wallsSystem }),
  Object.freeze({ name: 'collisions', run: collisionsSystem }),
])

/**
 * A fresh, editable schedule for the config's METHOD: the default schedule for 'exact' (or no config);
 * for the tick-sampled 'naive' and 'v1' (docs/accuracy.md), their sub-step group repeated SUBSTEPS times.
 */
export function createSchedule(config?: Readonly<BallPhysicsConfig>): ScheduleEntry[] {
  if (config === undefined) return DEFAULT_SCHEDULE.slice()
  if (typeof config !== 'object' || config === null) {
    throw new TypeError(`createSchedule: config must be a world's config (world.config) or undefined, got ${describe(config)}`)
  }
  const method: unknown = config.METHOD
  if (method === 'exact') return DEFAULT_SCHEDULE.slice()
  if (method !== 'naive' && method !== 'v1') {
    throw new RangeError(`createSchedule: config.METHOD must be one of ${METHODS.map((m) => `'${m}'`).join(', ')}, got ${describe(method)}`)
  }
  const n: unknown = config.SUBSTEPS
  const { min, max } = CONFIG_RANGES.SUBSTEPS
  if (typeof n !== 'number' || !Number.isInteger(n) || n < min || n > max) {
    throw new RangeError(`createSchedule: config.SUBSTEPS must be an integer in [${min}, ${max}], got ${describe(n)}`)
  }
  return repeatSubsteps(method === 'naive' ? NAIVE_SUBSTEP : V1_SUBSTEP, n)
}

/**
 * Advances the world by exactly dt seconds with the given schedule. dt is not capped here (the public
 * API's step does that); it must be finite and > 0, and with the fixed tick at most MAX_STEP (its work
 * grows with dt: every contact tick of the step is solved).
 */
export function runSchedule(world: BallWorld, schedule: readonly ScheduleEntry[], dt: number): void {
  checkWorld('runSchedule', world)
  dropGoneHeld(world)
  if (!Array.isArray(schedule)) throw new TypeError(`runSchedule: schedule must be an array of { name, run } entries, got ${describe(schedule)}`)
  for (let i = 0; i < schedule.length; i++) {
    const entry: unknown = schedule[i]
    if (typeof entry !== 'object' || entry === null || typeof (entry as ScheduleEntry).run !== 'function' || typeof (entry as ScheduleEntry).name !== 'string') {
      throw new TypeError(`runSchedule: schedule[${i}] must be a { name, run } entry whose name is a string and whose run is a function (world) => void, got ${describe(entry)}`)
    }
  }
  if (typeof dt !== 'number') throw new TypeError(`dt must be a number of seconds > 0, got ${describe(dt)}`)
  if (!Number.isFinite(dt) || dt <= 0) throw new RangeError(`dt must be a finite number of seconds > 0, got ${dt}`)
  // the fixed tick solves every tick of the step (its work grows with dt, moving balls or not: 1e9 s ran
  // for minutes); the exact method's work per step is bounded by its passes, whatever dt
  if (world.fixed !== null && dt > world.config.MAX_STEP) {
    throw new RangeError(`runSchedule: with BALL_COLLISIONS 'fixed', dt must be in (0, MAX_STEP = ${world.config.MAX_STEP}] s, got ${dt} (each contact tick of the step is solved; run a longer span as several steps)`)
  }
  if (world.stepping) {
    throw new Error('step (runSchedule): the world is already stepping (called from inside a system or an observer?); a step cannot run inside a step')
  }
  const recorded = world.recorder === null ? 0 : world.recorder.inputs.length
  if (world.recorder !== null) record(world, ['step', dt])
  world.stepping = true
  try {
    // the order the moving balls are walked in changes no result (contacts off: each ball's path is its own;
    // exact contacts: each pair's search is the same either way round, and events are taken in time order),
    // and walking them in id order keeps the per-ball arrays in cache. (The fixed-tick method solves
    // contacts in the order it gathers them.)
    const m = world.moving
    if (world.fixed === null && m.churn * MOVING_ORDER_CHURN > m.count && m.count > MOVING_ORDER_MIN) orderMoving(world)
    runPasses(world, schedule, dt)
    // a hole or the walls removed by a system (src/commands/holes.ts): the step's results are not to be trusted
    if (world.failed !== null) throw new Error(`step (runSchedule): ${world.failed}`)
  } catch (e) {
    // the step is part-done: the world refuses to go on (src/check.ts), and a step that failed records
    // nothing, as a command that fails does (a replay of it would run the whole step)
    if (world.failed === null) world.failed = `the step threw ${errorText(e)}`
    if (world.recorder !== null) world.recorder.inputs.length = recorded
    throw e
  } finally {
    world.stepping = false
  }
}

function errorText(e: unknown): string {
  return e instanceof Error ? `${e.name}: ${e.message}` : describe(e)
}

/** runPasses' step end (see there) */
const stepEnd = new Float64Array(1)

function runPasses(world: BallWorld, schedule: readonly ScheduleEntry[], dt: number): void {
  const F = world.fixed
  // read back from a slot, the end is a double to V8; as clockEnd returns it, it is an object, and the
  // window's stop (the tick or the end) merged with it was boxed at every tick
  stepEnd[0] = clockEnd(world, world.time + dt, dt)
  const end = stepEnd[0]!
  if (F === null) {
    if (world.collide === null) {
      world.tickEnd = end
      runWindow(world, schedule)
      return
    }
    // exact contacts: while balls are held, the step is split at the launch instants, where the launcher acts
    for (;;) {
      const next = launchInstant(world)
      world.tickEnd = next < end ? next : end
      runWindow(world, schedule)
      if (world.time >= end) return
    }
  }
  // fixed-tick contacts: the step is split at the contact ticks k·tick, tick = CONTACT_TICK / 2^halvings
  // (the same instants at every frame rate), and the contacts are solved at each (by the schedule's
  // fixedContacts system); a solve asked for between steps (a ball put down or given a new velocity) runs in
  // the next step's first pass
  for (;;) {
    // the instants through a slot, not returned, and no double passed to a call here: V8 boxes those for a
    // call it does not inline, a few heap numbers a tick
    tickInstant(world, F.halvings, F.nextTick)
    const tick = instantOut[0]!
    if (tick <= world.time) {
      F.due = true
      F.nextTick++
      continue
    }
    // a step whose end is the tick but for rounding (a clock summed from 1/120 s steps drifts a few ulps
    // from k·(1/120)) ends at the tick, solved, and the clock is back on the ticks; else a sliver window
    // before or after the tick integrated every ball again
    // (nearTick(tick, end, dt) written out: its three doubles were boxed at every tick)
    const gap = Math.abs(tick - end)
    const onTick = gap <= TICK_SNAP * tick && gap < 0.5 * dt
    const stop = onTick || tick < end ? tick : end
    // held balls leave at the ticks, the halved ones too (ticks of the world's clock, decided from its state,
    // so the same at every frame rate; k·CONTACT_TICK = (k·2^h)·(CONTACT_TICK / 2^h), the same double, is
    // among them): a window that starts on one
    world.launchDue = false
    if (world.held.count > 0) {
      tickInstant(world, F.halvings, F.nextTick - 1)
      world.launchDue = world.time === instantOut[0]
    }
    world.tickEnd = stop
    runWindow(world, schedule)
    F.due = false
    // the window reached the next tick: `tick`, or, when a solve at its start (one a command asked for)
    // halved the tick, the next tick of the finer spacing, where the window then ended (or ends anyway:
    // src/contacts/fixedHalve.ts)
    tickInstant(world, F.halvings, F.nextTick)
    if (world.time === instantOut[0]) {
      // the tick's solve right at the end of the window that reaches it: a step that ends on a tick ends
      // solved (what the game draws), and the next window starts from the solved state
      F.nextTick++
      F.due = true
      world.pass = 0
      for (let i = 0; i < schedule.length; i++) if (schedule[i]!.run === fixedContactsSystem) schedule[i]!.run(world)
      F.due = false
    }
    // the step's end, or the tick it ends on (a window that a halving took to a tick within TICK_SNAP past
    // the end ends there too)
    if (world.time >= end || (onTick && world.time === stop)) return
  }
}

/**
 * The step's end on the exact method's clock: an end that is k·CONTACT_TICK but for rounding is that
 * instant (a clock summed from 1/30 s steps and one summed from 1/240 s steps part by a few ulps within a
 * second; on the grid, the same simulated time is the same double at 30, 60, 120 and 240 Hz, so commands
 * given there act at the same instant, and held balls leave at the same launch instants); any other end on
 * its rate's grid (rateEnd). Both contact methods' steps end there (k·CONTACT_TICK is a tick of every spacing
 * of the fixed tick, which also ends a step that falls a few ulps off any of its ticks on the tick); the
 * tick-sampled methods keep the summed clock.
 */
function clockEnd(world: BallWorld, end: number, dt: number): number {
  if (world.config.METHOD !== 'exact') return end
  const L = world.config.CONTACT_TICK
  const at = gridInstant(L, 0, Math.round(end / L))
  return nearTick(at, end, dt) ? at : rateEnd(end, dt)
}

/**
 * A step of 1/n s, n a whole number (1/50, 1/100, 1/144 s), whose end is m/n s but for rounding ends on
 * the double nearest m/n (m / n: a division of two whole numbers, rounded once). That double depends on
 * the rational time alone, so two rates read the same clock at every boundary they share, those off
 * CONTACT_TICK's grid too (50 and 100 Hz share every 1/50 s; on the 1/120 s grid, one in five). A step
 * that is not 1/n s, or a clock off its grid (after steps of other lengths), keeps the summed end.
 */
function rateEnd(end: number, dt: number): number {
  const n = Math.round(1 / dt)
  if (!(n >= 1) || Math.abs(dt * n - 1) > TICK_SNAP) return end
  const m = Math.round(end * n)
  if (!(m <= Number.MAX_SAFE_INTEGER)) return end
  const at = m / n
  return nearTick(at, end, dt) ? at : end
}

/**
 * Held balls leave at launch instants, k·CONTACT_TICK of the world's clock, with exact contacts (the fixed
 * tick's are its ticks: runPasses): the same instants at every frame rate, where a step's start would make
 * the release time depend on it. Sets world.launchDue (the window that starts now starts on one, and a ball
 * is held) and returns the first instant after the world's time (Infinity when no ball is held, or when
 * the clock is too coarse for the tick: then the launcher acts at every window's start).
 */
function launchInstant(world: BallWorld): number {
  if (world.held.count === 0) {
    world.launchDue = false
    return Infinity
  }
  const L = world.config.CONTACT_TICK
  const t = world.time
  let k = Math.ceil(t / L)
  while (k > 0 && gridInstant(L, 0, k - 1) >= t) k--
  while (gridInstant(L, 0, k) < t) k++
  const due = gridInstant(L, 0, k) === t
  const next = gridInstant(L, 0, due ? k + 1 : k)
  if (!(next > t)) {
    world.launchDue = true
    return Infinity
  }
  world.launchDue = due
  return next
}

/**
 * Runs the passes from the world's time to world.tickEnd, which the caller sets (a double passed to a call V8
 * does not inline is boxed).
 */
function runWindow(world: BallWorld, schedule: readonly ScheduleEntry[]): void {
  // events at this instant from here on come after those of the window that ended here (src/events.ts)
  world.events.windowFrom = world.time
  // with ball-ball contacts a pass handles one event (or a few lip crossings), so the bound is per moving ball:
  // the most moving at once in the step, grown as passes set balls moving. Counted at the step's start alone,
  // a held ball launched into a resting crowd at the start of a step ran out of passes at one frame rate and
  // not at another, and their events parted (docs/known-failures.md)
  const perBall = world.config.MAX_EVENT_PASSES
  const contacts = world.collide !== null
  let maxPasses = contacts ? perBall * (world.moving.count + 1) : perBall
  setLipBatching(contacts && world.config.RIM_MODEL !== 'tabulated' && isDefault(schedule))
  let i = 0
  try {
    for (world.pass = 0; world.pass < maxPasses; world.pass++) {
      for (i = 0; i < schedule.length; i++) schedule[i]!.run(world)
      if (world.marked.count === 0) break
      if (contacts) maxPasses = Math.max(maxPasses, perBall * (world.moving.count + 1))
    }
  } catch (e) {
    world.failed = `system '${schedule[i]!.name}' threw in pass ${world.pass}: ${errorText(e)}`
    throw e
  } finally {
    setLipBatching(false)
    world.launchDue = false
  }
  // out of passes: the balls still behind wait out the step (src/motion/pause.ts), none is left behind
  if (world.pass === maxPasses && world.config.METHOD === 'exact') waitOutStep(world)
  world.time = world.tickEnd
  // the last pass's list is spent (a pass takes `marked` into it): kept, it named balls a game could remove
  // between steps, and a snapshot after a step of one pass carried them (restore refused it)
  world.todo.count = 0
}

/** The default schedule's systems, in its order (a copy from createSchedule is one). */
function isDefault(schedule: readonly ScheduleEntry[]): boolean {
  if (schedule.length !== DEFAULT_SCHEDULE.length) return false
  for (let i = 0; i < schedule.length; i++) if (schedule[i]!.run !== DEFAULT_SCHEDULE[i]!.run) return false
  return true
}

/** The default schedule with the v1 rule ahead of the six stages: for charting the v1 model (docs/physical.md). */
export function v1Schedule(): ScheduleEntry[] {
  const s = DEFAULT_SCHEDULE.slice()
  s.splice(s.findIndex((e) => e.name === 'integration') + 1, 0, { name: 'v1Rule', run: v1RuleSystem })
  return s
}
