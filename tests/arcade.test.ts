// Regressions from arcade load and abuse (the parts fixed so far): each pins one failure that was seen.
import { describe, expect, it } from 'vitest'
import { createBallPhysics } from '../src/index'
import { PathSchema, BallSchema } from '../src/ecs'

function storesFinite(sim: ReturnType<typeof createBallPhysics>): void {
  const w = sim.world
  for (const [name, store] of [['Ball', w.Ball], ['Path', w.Path]] as const) {
    const keys = Object.keys(name === 'Ball' ? BallSchema : PathSchema)
    for (const b of sim.balls()) {
      for (const k of keys) {
        const v = (store as unknown as Record<string, ArrayLike<number>>)[k]![b]!
        expect(Number.isFinite(v), `${name}.${k}[${b}] = ${v}`).toBe(true)
      }
    }
  }
}

describe('nothing infinite, nothing left outside', () => {
  it('a ball put down outside an open edge and moving out leaves at once (gutter, mode out); no Infinity in the stores', () => {
    // no rolling deceleration and a velocity almost along the edge: the far wall is "reached" at 1e307 px
    const sim = createBallPhysics({ ROLLING_DECEL: 0 })
    sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, open: { left: true } })
    const b = sim.addBall({ x: -10, y: 100, vx: -100, vy: 1e-305 })
    storesFinite(sim)
    sim.step(1 / 60)
    expect(sim.drainEvents()).toEqual([{ type: 'gutter', ball: b, time: 0 }])
    expect(sim.ballState(b).mode).toBe('out')
    storesFinite(sim)
  })

  it('a path that would reach a wall only beyond double range has no wall event (and no Infinity)', () => {
    const sim = createBallPhysics({ ROLLING_DECEL: 0 })
    sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480 })
    const b = sim.addBall({ x: 200, y: 100, vx: -1e-300, vy: 0 })
    storesFinite(sim)
    expect(sim.world.Path.nextT[b]).toBeLessThan(Infinity)
    for (let i = 0; i < 10; i++) sim.step(1 / 60)
    storesFinite(sim)
  })

  it('a ball outside an open edge moving back in is not let out', () => {
    const sim = createBallPhysics({ ROLLING_DECEL: 0 })
    sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, open: { left: true } })
    const b = sim.addBall({ x: -10, y: 100, vx: 100, vy: 0 })
    sim.step(1 / 60)
    expect(sim.drainEvents()).toEqual([])
    expect(sim.ballState(b).mode).toBe('rolling')
  })
})

describe('the cost of a scene follows the balls in it now', () => {
  it("the resting grid's reach shrinks when its largest ball leaves (it once kept the largest radius ever seen)", () => {
    const sim = createBallPhysics({ BALL_COLLISIONS: 'on' })
    const C = sim.world.collide!
    const small = sim.addBall({ x: 0, y: 0, vx: 0, vy: 0 })
    sim.step(1 / 60)
    const reach = C.maxRadius
    expect(reach).toBeGreaterThanOrEqual(11)
    expect(reach).toBeLessThan(11 * 1.19)
    const big = sim.addBall({ x: 1e6, y: 0, vx: 0, vy: 0, radius: 1e4 })
    sim.step(1 / 60)
    expect(sim.ballState(big).mode).toBe('resting')
    expect(C.maxRadius).toBeGreaterThanOrEqual(1e4)
    sim.removeBall(big)
    expect(C.maxRadius).toBe(reach)
    sim.removeBall(small)
    expect(C.maxRadius).toBe(0)
  })

  it('a large ball that wakes and rolls away takes its reach with it', () => {
    const sim = createBallPhysics({ BALL_COLLISIONS: 'on' })
    const C = sim.world.collide!
    const big = sim.addBall({ x: 0, y: 0, vx: 0, vy: 0, radius: 500 })
    sim.step(1 / 60)
    expect(C.maxRadius).toBeGreaterThanOrEqual(500)
    sim.setBallVelocity(big, 100, 0)
    expect(C.maxRadius).toBe(0)
  })
})
