// The fixed-tick method at a closed wall: a ball lying still by the wall, struck by a heavier one. The pair
// and the wall are solved together when the impulse would carry the struck ball to the wall within the tick
// (a ball standing still has no reach of its own: the speed the impulse gives it counts). Before, it was
// bounced between the wall and its striker sweep by sweep, the pair closing inelastically from its second
// visit, and the striker stopped dead, short of the ball it struck.
import { describe, expect, it } from 'vitest'
import { createBallPhysics } from '../../src/index'

function strike(radius: number, speed: number, gap: number, e: number) {
  const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: e })
  sim.setWalls({ minX: 0, minY: 0, maxX: 2000, maxY: 2000, restitution: 0.9 })
  const big = sim.addBall({ x: 400, y: 1000, vx: -speed, vy: 0, radius })
  const small = sim.addBall({ x: 11 + gap, y: 1000, vx: 0, vy: 0 })
  const mass = (radius / 11) ** 3
  const ke = () => {
    const b = sim.ballState(big)
    const s = sim.ballState(small)
    return 0.5 * mass * (b.vx ** 2 + b.vy ** 2) + 0.5 * (s.vx ** 2 + s.vy ** 2)
  }
  let approach = 0
  let last = ke()
  let rose = false
  for (let i = 0; i < 60 && approach === 0; i++) {
    sim.step(1 / 60)
    for (const ev of sim.drainEvents()) if (ev.type === 'collision') approach = ev.speed!
    const k = ke()
    if (k > last * (1 + 1e-12)) rose = true
    last = k
  }
  return { approach, big: sim.ballState(big), small: sim.ballState(small), rose }
}

describe('fixed-tick contacts at a closed wall', () => {
  for (const [radius, speed] of [[22, 2500], [22, 600], [60, 2500], [110, 1000]] as const) {
    for (const gap of [0, 0.5, 3]) {
      it(`a ball ${gap} px from the wall, struck by one of radius ${radius} at ${speed} px/s: the striker rebounds at the pair's restitution`, () => {
        const e = 0.9
        const r = strike(radius, speed, gap, e)
        expect(r.approach).toBeGreaterThan(0.5 * speed) // less the rolling deceleration on the way
        // the struck ball is held by the wall (inelastic there); the striker leaves at e times the approach,
        // less its rolling deceleration since
        expect(r.big.vx).toBeGreaterThan(0.8 * e * r.approach)
        expect(r.big.vx).toBeLessThanOrEqual(e * r.approach * (1 + 1e-12))
        expect(r.small.x).toBeGreaterThanOrEqual(11)
        expect(r.rose).toBe(false)
      })
    }
  }
})
