// The struck row of bench/rows.ts, also run by tests/systems/fixedRow.test.ts: n radius-0.5 balls gap px
// apart on one line, struck end on by a ball of the given mass and speed, a closed wall 5 px past the row,
// restitution e (balls and walls), the fixed tick, 1 s at hz.
import { createBallPhysics, type BallPhysicsConfig } from '../src/index'

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
