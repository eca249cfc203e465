// The fixed tick's rules half way through a solve call (src/contacts/fixedJam.ts, fixedShock.ts) list the
// balls whose velocities they changed in scratch arrays that grow with the tick's candidates. The solve
// read each list before the rule ran, so in the call where a rule's arrays grew it stamped the old list's
// balls and left the ones it changed unstamped (src/contacts/fixedSolve.ts, settle): the sweeps after it
// passed their pairs by. This file runs alone in its worker, so its first scene grows the arrays as a
// fresh process does.
import { describe, expect, it } from 'vitest'
import { createBallPhysics } from '../../src/index'
import { keepAcrossCalls } from '../../src/contacts/fixedCalls'

/** bench:piles' pile at e = 0: 10,000 balls in a corner, 8 more thrown at it a step at 1,500 px/s; a hash of every ball's state after `steps` steps */
function pile(steps: number, keep: boolean): string {
  keepAcrossCalls(keep)
  try {
    let s = 99
    const r = () => ((s = (s * 16807) % 2147483647) - 1) / 2147483646
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 0 }, { capacity: 11_000 })
    sim.setWalls({ minX: 0, minY: 0, maxX: 3000, maxY: 3000, restitution: 0 })
    for (let i = 0; i < 100; i++) for (let j = 0; j < 100; j++) sim.addBall({ x: 12 + 22.5 * i, y: 12 + 22.5 * j, vx: 0, vy: 0 })
    const edge = 2250
    for (let step = 0; step < steps; step++) {
      for (let k = 0; k < 8; k++) {
        const x = edge + 60 + 300 * r()
        const y = edge + 60 + 300 * r()
        const d = Math.hypot(x, y)
        sim.addBall({ x, y, vx: (-1500 * x) / d, vy: (-1500 * y) / d })
      }
      sim.step(1 / 60)
      sim.drainEvents()
    }
    const B = sim.world.Ball
    let h = ''
    for (const b of sim.balls()) h += `${B.x[b]},${B.y[b]},${B.vx[b]},${B.vy[b]};`
    return h
  } finally {
    keepAcrossCalls(true)
  }
}

describe('fixed tick: the rules half way through a call that grow their scratch arrays', () => {
  it("a 10,000-ball pile at e = 0, struck for 19 steps: the same bits whether the solve calls keep their stamps (where the jam rule's arrays grow, in the 19th step) or not", () => {
    const kept = pile(19, true)
    const fresh = pile(19, false)
    expect(kept.length).toBeGreaterThan(100_000)
    expect(kept === fresh).toBe(true)
  }, 60_000)
})
