// Shared scene builders for the system tests: each builds a fresh world.
import { createBallPhysics, type BallEvent, type BallPhysics, type ConfigOverrides } from '../src/index'
import { createSchedule, drainEvents, rimSlot, runSchedule, type BallWorld } from '../src/ecs'

export interface Shot {
  sim: BallPhysics
  hole: number
  ball: number
  /** x at which the path crosses the lip circle (the hole is at the origin, the ball rolls along +x) */
  lipX: number
}

/**
 * One hole at the origin and one ball rolling along +x at offset `delta` (y = delta), started `lead` px
 * before the lip with the speed that makes it cross the lip at exactly `speed`.
 */
export function shoot(delta: number, speed: number, overrides: ConfigOverrides = {}, lead = 60): Shot {
  const sim = createBallPhysics(overrides)
  const hole = sim.addHole({ x: 0, y: 0 })
  const R = sim.config.HOLE_RADIUS
  const a = sim.config.ROLLING_DECEL
  const lipX = -Math.sqrt(Math.max(0, R * R - delta * delta))
  const v0 = Math.sqrt(speed * speed + 2 * a * lead)
  const ball = sim.addBall({ x: lipX - lead, y: delta, vx: v0, vy: 0 })
  return { sim, hole, ball, lipX }
}

/** Steps until no ball moves (or `maxSeconds` pass); returns every event in time order. */
export function settle(sim: BallPhysics, dt = 1 / 60, maxSeconds = 30): BallEvent[] {
  const events: BallEvent[] = []
  for (let t = 0; t < maxSeconds; t += dt) {
    sim.step(dt)
    events.push(...sim.drainEvents())
    if (sim.balls().every((b) => { const m = sim.ballState(b).mode; return m === 'captured' || m === 'resting' })) break
  }
  return events
}

/** Event types of one ball, with the capture route: e.g. ['rimRoll', 'capture:rimRoll']. */
export function sequence(events: BallEvent[], ball?: number): string[] {
  return events
    .filter((e) => ball === undefined || e.ball === ball)
    .map((e) => (e.via ? `${e.type}:${e.via}` : e.type))
}

/** A small seeded generator (mulberry32, src/random.ts) for reproducible random scenes. */
export { mulberry32 as rng } from '../src/random.js'

/** Named tolerances. */
export const EXACT = 1e-9
export const POSITION_TOLERANCE = 1e-6

/**
 * Keeps a copy of a ball's RimContact row as of the end of each pass, by a system appended to the
 * schedule. Rows are pooled: a ball gives its row back when its hole lock ends, so a test that reads rim
 * data after the ball left the hole (or fell in) reads this copy.
 */
export function watchRim(sim: BallPhysics, ball: number): Record<string, number> {
  const last: Record<string, number> = {}
  sim.schedule.push({
    name: 'watchRim',
    run: (w) => {
      const slot = rimSlot(w, ball)
      if (slot === 0) return
      for (const [k, arr] of Object.entries(w.RimContact)) last[k] = (arr as Float64Array)[slot]!
    },
  })
  return last
}

/** Runs a bare world's schedule n steps of dt through runSchedule; returns the events drained after each. */
export function stepWorld(w: BallWorld, n = 1, dt = 1 / 120): BallEvent[] {
  const schedule = createSchedule(w.config)
  const out: BallEvent[] = []
  for (let i = 0; i < n; i++) {
    runSchedule(w, schedule, dt)
    out.push(...drainEvents(w))
  }
  return out
}

/**
 * A wall-clock budget for this machine: `ms` is stated for the development machine, on which a reference
 * workload (a 150-ball contacts-on box, 30 steps) takes REF_BASE_MS at best; a slower or busier machine,
 * measured once per test file, gets budgets that much larger (up to 8×). The budgets catch hangs and
 * blow-ups of orders of magnitude; a slow CI machine is not taken for one.
 */
export function timeBudget(ms: number): number {
  slowdown ??= slowdownNow()
  return ms * slowdown
}

/** how much slower than the development machine this one runs the reference workload (1 or more) */
export function machineSlowdown(): number {
  return timeBudget(1)
}

/**
 * The same measured again now (not the figure timeBudget keeps): a run of minutes on a shared machine sees
 * its speed drift. Never call it inside a step: it steps worlds of its own.
 */
export function slowdownNow(): number {
  return Math.min(8, Math.max(1, refWorkMs() / REF_BASE_MS))
}

// The development machine ran the reference workload in 33 ms a run when vitest's module runner executed the
// sources; they now run as plain ES modules (vitest.config.ts), which on one machine took 15 ms against 117:
// 33 × 15 / 117. Measured since: 13.7–14.4 ms (best of seven, five times) on a machine that ran a round of
// the contacts benchmark 3.0× slower than its committed run (61 ns a ball-step without contacts against 20),
// that is about 4.6 ms at that run's speed.
const REF_BASE_MS = 4.2
let slowdown: number | undefined

/** The best of seven runs of the reference workload, in ms (the first runs also pay for compilation). */
function refWorkMs(): number {
  let best = Infinity
  for (let run = 0; run < 7; run++) {
    const sim = createBallPhysics({ BALL_COLLISIONS: 'on', ROLLING_DECEL: 0, BALL_RESTITUTION: 0.9 })
    sim.setWalls({ minX: 0, minY: 0, maxX: 400, maxY: 400, restitution: 0.9 })
    let s = 12_345
    const rnd = () => (s = (Math.imul(s, 1_103_515_245) + 12_345) >>> 0) / 2 ** 32
    for (let i = 0; i < 150; i++) sim.addBall({ x: 20 + (i % 15) * 24, y: 20 + Math.floor(i / 15) * 24, vx: (rnd() - 0.5) * 800, vy: (rnd() - 0.5) * 800 })
    const t0 = performance.now()
    for (let i = 0; i < 30; i++) sim.step(1 / 60)
    best = Math.min(best, performance.now() - t0)
  }
  return best
}
