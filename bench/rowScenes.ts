// The rows of the row benchmarks, also run by the tests. The struck row of bench/rows.ts (and
// tests/systems/fixedRow.test.ts): n radius-0.5 balls gap px apart on one line, struck end on by a ball of the
// given mass and speed, a closed wall 5 px past the row, restitution e (balls and walls), the fixed tick, 1 s
// at hz. The piston row of bench/pistonRows.ts (and tests/systems/fixedGuard.test.ts): drawn from a seed.
import { createBallPhysics, mulberry32, type BallPhysics, type BallPhysicsConfig } from '../src/index'

/** The heavy ball's masses and the speeds a piston row draws from. */
export const PISTON_MASSES = [1e3, 1e6, 1e9]
export const PISTON_SPEEDS = [1e4, 3e4, 1e5]

export interface PistonRow {
  sim: BallPhysics
  /** the heavy ball, then the row in order along the line */
  ids: number[]
  hz: number
  mass: number
  speed: number
}

/**
 * Piston row `seed` (mulberry32(seed + 1)): 5–24 radius-0.5 balls 0.5, 2 or 5 px apart on one line, each at a
 * random velocity up to ±1e4, 3e4 or 1e5 px/s along it, a ball of mass 1e3, 1e6 or 1e9 at the row's left end,
 * a closed box 3 px left of the row and 5 px right of it, restitution 1, no deceleration, 60 or 120 Hz.
 */
export function pistonRow(seed: number, mode: 'fixed' | 'on'): PistonRow {
  const r = mulberry32(seed + 1)
  const n = 5 + Math.floor(r() * 20)
  const gap = [0.5, 2, 5][Math.floor(r() * 3)]!
  const mass = PISTON_MASSES[Math.floor(r() * 3)]!
  const speed = PISTON_SPEEDS[Math.floor(r() * 3)]!
  const hz = r() < 0.5 ? 60 : 120
  const sim = createBallPhysics({ BALL_COLLISIONS: mode, BALL_RESTITUTION: 1, ROLLING_DECEL: 0, BALL_RADIUS: 0.5 })
  sim.setWalls({ minX: -3, minY: -20, maxX: n * (1 + gap) + 5, maxY: 20, restitution: 1 })
  const ids = [sim.addBall({ x: -1 - gap / 2, y: 0, vx: (r() - 0.5) * 2 * speed, vy: 0, mass })]
  for (let i = 0; i < n; i++) ids.push(sim.addBall({ x: i * (1 + gap), y: 0, vx: (r() - 0.5) * 2 * speed, vy: 0 }))
  return { sim, ids, hz, mass, speed }
}

export interface Struck {
  n: number
  gap: number
  mass: number
  speed: number
  e: number
  hz: number
}

/** The first step at which a ball is not ahead of the one before it (−1: none) and the deepest overlap from 0.5 s. */
export function strike({ n, gap, mass, speed, e, hz }: Struck, extra: Partial<BallPhysicsConfig> = {}): { passed: number; deepest: number } {
  const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: e, ROLLING_DECEL: 0, BALL_RADIUS: 0.5, ...extra })
  sim.setWalls({ minX: -50, minY: -20, maxX: n * (1 + gap) + 5, maxY: 20, restitution: e })
  const ids = [sim.addBall({ x: -1 - gap, y: 0, vx: speed, vy: 0, mass })]
  for (let i = 0; i < n; i++) ids.push(sim.addBall({ x: i * (1 + gap), y: 0, vx: 0, vy: 0 }))
  let passed = -1
  let deepest = 0
  for (let f = 0; f < hz; f++) {
    sim.step(1 / hz)
    sim.drainEventsWith(() => {})
    const x = sim.world.Ball.x
    const y = sim.world.Ball.y
    for (let k = 1; k < ids.length && passed < 0; k++) if (!(x[ids[k]!]! > x[ids[k - 1]!]!)) passed = f
    if (f + 1 < hz / 2) continue
    for (let i = 0; i < ids.length; i++) {
      for (let j = i + 1; j < ids.length; j++) {
        const a = ids[i]!
        const b = ids[j]!
        const d = 1 - Math.hypot(x[a]! - x[b]!, y[a]! - y[b]!)
        if (d > deepest) deepest = d
      }
    }
  }
  return { passed, deepest }
}
