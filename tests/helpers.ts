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

/** A small seeded generator (mulberry32) for reproducible random scenes. */
export function rng(seed: number): () => number {
  let a = seed >>> 0
  return () => {
    a = (a + 0x6d2b79f5) >>> 0
    let t = a
    t = Math.imul(t ^ (t >>> 15), t | 1)
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61)
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296
  }
}

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
