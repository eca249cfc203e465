// A step that an error ends part-done (a game's system throws): the error reaches the caller, and the world
// then refuses to go on, with an error that names the system, rather than stepping on from a state no
// system finished. Before, the next step threw "its event was not handled by any system" for good (or, with
// exact contacts, stepped on once from the broken state), and a snapshot carried the broken state along.
import { describe, expect, it } from 'vitest'
import { DEFAULT_PANEL, addPanel, createBallPhysics, type BallPhysics } from '../src/index'
import { listBalls, type BallWorld } from '../src/ecs'

const METHODS = ['off', 'on', 'fixed'] as const

/** A panel with a few throws and a ball that stops at t = 1 s; `game` runs after integration. */
function scene(method: (typeof METHODS)[number], game: (w: BallWorld) => void): { sim: BallPhysics; stopper: number } {
  const sim = createBallPhysics({ BALL_COLLISIONS: method })
  addPanel(sim, DEFAULT_PANEL)
  for (let k = 0; k < 6; k++) sim.throwBall({ x: 90 + 45 * k, y: 450, power: 0.3 + 0.1 * k, angle: 0.05 * (k - 3) })
  const stopper = sim.addBall({ x: 400, y: 460, vx: 0, vy: -300 })
  sim.schedule.splice(sim.schedule.findIndex((e) => e.name === 'integration') + 1, 0, { name: 'gameSystem', run: game })
  return { sim, stopper }
}

/** Every ball's state and the events, as text (the same bits give the same text). */
function state(sim: BallPhysics): string {
  const balls = listBalls(sim.world).map((b) => JSON.stringify([b, sim.ballState(b)]))
  return `${sim.time} ${balls.join(';')} ${JSON.stringify(sim.drainEvents())}`
}

describe('a step ended part-done by an error', () => {
  for (const method of METHODS) {
    it(`refuses to go on, naming the system and its error; reads work; a snapshot from before it steps on as if it never threw (${method})`, () => {
      let armed = true
      let snap: Uint8Array | null = null
      const { sim, stopper } = scene(method, (w) => {
        // throws once, in the pass where the stopping ball is marked at its stop (before the stages handle it)
        if (armed && w.marked.count > 0 && w.time > 0.9) {
          armed = false
          throw new Error('transient game bug')
        }
      })
      sim.startRecording()
      let failedAt = -1
      for (let f = 0; f < 90 && failedAt < 0; f++) {
        const before = sim.snapshot()
        try {
          sim.step(1 / 60)
          sim.drainEvents()
        } catch (e) {
          expect((e as Error).message).toBe('transient game bug')
          failedAt = f
          snap = before
        }
      }
      expect(failedAt).toBeGreaterThan(50)
      // every later step and every command that changes the world is refused, naming what failed
      const why = /the world's step at t = .* was ended part-done by an error \(system 'gameSystem' threw in pass \d+: Error: transient game bug\)/
      expect(() => sim.step(1 / 60)).toThrow(why)
      expect(() => sim.step(1 / 60)).toThrow(/runSchedule: /)
      expect(() => sim.addBall({ x: 100, y: 100 })).toThrow(why)
      expect(() => sim.setBallVelocity(stopper, 1, 1)).toThrow(why)
      expect(() => sim.removeBall(stopper)).toThrow(why)
      expect(() => sim.addHole({ x: 10, y: 10 })).toThrow(why)
      expect(() => sim.snapshot()).toThrow(why)
      // reads work, and the recording holds the steps before the failed one only
      expect(sim.ballState(stopper).mode).toBe('rolling')
      expect(Array.isArray(sim.drainEvents())).toBe(true)
      const replay = sim.stopRecording()
      expect(replay.inputs.filter((i) => i[0] === 'step').length).toBe(failedAt)

      // the snapshot taken before the failed step, restored into a new world, goes on as a world that never
      // threw: the same bits
      const { sim: clean } = scene(method, () => {})
      for (let f = 0; f < failedAt; f++) {
        clean.step(1 / 60)
        clean.drainEvents()
      }
      const back = createBallPhysics(sim.config)
      back.restore(snap!)
      back.schedule.splice(0, back.schedule.length, ...clean.schedule)
      for (let f = 0; f < 60; f++) {
        clean.step(1 / 60)
        back.step(1 / 60)
        expect(state(back)).toBe(state(clean))
      }
    })
  }

  it("an error from the module's own systems fails the world the same way (a schedule without the stage that handles a stop)", () => {
    const sim = createBallPhysics()
    const b = sim.addBall({ x: 0, y: 200, vx: 0, vy: -300 })
    sim.schedule.splice(0, sim.schedule.length, ...sim.schedule.filter((e) => e.name === 'integration'))
    let message = ''
    for (let f = 0; f < 120 && message === ''; f++) {
      try {
        sim.step(1 / 60)
      } catch (e) {
        message = (e as Error).message
      }
    }
    expect(message).toMatch(/not handled by any system/)
    expect(() => sim.step(1 / 60)).toThrow(/system 'integration' threw in pass \d+: Error: ball 1: its event/)
    expect(sim.ballState(b).mode).toBe('rolling')
  })

  it('a step refused by its checks fails nothing: bad dt, a step inside a step', () => {
    const sim = createBallPhysics()
    sim.addBall({ x: 0, y: 200, vx: 0, vy: -300 })
    expect(() => sim.step(-1)).toThrow(RangeError)
    expect(() => sim.step(Number.NaN)).toThrow(RangeError)
    sim.step(1 / 60)
    expect(sim.world.failed).toBe(null)
    // a nested step is refused, and the step it was called from is the one that fails
    sim.schedule.push({ name: 'nests', run: () => sim.step(1 / 60) })
    expect(() => sim.step(1 / 60)).toThrow(/a step cannot run inside a step/)
    expect(sim.world.failed).toMatch(/system 'nests' threw in pass 0/)
  })
})
