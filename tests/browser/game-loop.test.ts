// The demo's game loop without a browser (demo/game.ts has no pixi): the physics outcome of a throw does
// not depend on the display's frame rate, a frame after a long sleep is capped, and the interpolation's
// previous state is the one before the last step.
import { describe, expect, it } from 'vitest'
import { Game, MAX_FRAME_SECONDS, MAX_STEPS_PER_FRAME, PHYSICS_HZ } from '../../demo/game'
import { createBallPhysics, solveThrow } from '../../src/index'
import { BallMode } from '../../src/ecs'

function play(frameSeconds: () => number, seconds = 6) {
  const g = new Game()
  g.reset()
  const throws = [
    { power: 0.5, angle: -0.22 },
    { power: 0.42, angle: -0.32 },
    { power: 0.56, angle: 0.27 },
    { power: 0.9, angle: 0.05 },
  ]
  const events: string[] = []
  const thrownAt = new Map<number, number>()
  let next = 0
  for (let t = 0; t < seconds; ) {
    if (next < throws.length && t >= next * 0.5) {
      g.throwPlayer(throws[next++]!)
      thrownAt.set(g.live[g.live.length - 1]!, g.sim.time)
    }
    const dt = frameSeconds()
    t += dt
    // a throw starts at the simulation time of the frame it is made in, which depends on the frame rate;
    // what follows from it must not: event times are compared from the throw
    for (const e of g.frame(dt).events) {
      const since = e.time - thrownAt.get(e.ball)!
      events.push(`${e.type}:${e.ball}:${e.hole ?? '-'}:${e.delta?.toFixed(9)}:${e.speed?.toFixed(9)}:${since.toFixed(9)}`)
    }
  }
  return { score: g.score, events }
}

describe('demo game loop', () => {
  it('the outcome is the same at 30, 60, 144 Hz and with jittery frames', () => {
    const at60 = play(() => 1 / 60)
    expect(at60.score).toBeGreaterThan(0)
    expect(at60.events.length).toBeGreaterThan(4)
    expect(play(() => 1 / 30)).toEqual(at60)
    expect(play(() => 1 / 144)).toEqual(at60)
    let s = 1
    const jitter = (): number => {
      s = (s * 16807) % 2147483647
      return 0.004 + (s / 2147483647) * 0.03
    }
    expect(play(jitter)).toEqual(at60)
  })

  it('caps the catch-up after a long frame (a tab that slept)', () => {
    const g = new Game()
    g.reset()
    g.throwPlayer({ power: 0.6, angle: 0.1 })
    const t0 = g.time
    const r = g.frame(30)
    expect(r.steps).toBeLessThanOrEqual(MAX_STEPS_PER_FRAME)
    expect(g.time - t0).toBeCloseTo(MAX_FRAME_SECONDS, 12)
    expect(g.sim.time).toBeCloseTo(MAX_STEPS_PER_FRAME / PHYSICS_HZ, 12)
    expect(g.clock.alpha).toBeGreaterThanOrEqual(0)
    expect(g.clock.alpha).toBeLessThan(1)
  })

  it('keeps the previous step position for interpolation', () => {
    const g = new Game()
    g.reset()
    g.throwPlayer({ power: 0.8, angle: 0 })
    const id = g.live[0]!
    const B = g.sim.world.Ball
    expect(g.prevY[id]).toBe(B.y[id])
    g.frame(1 / PHYSICS_HZ)
    const speed = g.speedFor(0.8)
    // one step of rolling up the panel: previous is one step behind, by about v·dt
    expect(g.prevY[id]! - B.y[id]!).toBeGreaterThan(0)
    expect(g.prevY[id]! - B.y[id]!).toBeLessThanOrEqual(speed / PHYSICS_HZ + 1e-9)
  })

  it('recreates the simulation with pending tuning at the next throw, and rejects bad values', () => {
    const g = new Game()
    g.reset()
    expect(Game.validate({ BALL_RADIUS: -1 })).toMatchObject({ ok: false })
    expect(() => g.setPending({ BALL_RADIUS: -1 })).toThrow(/BALL_RADIUS/)
    g.setPending({ BALL_RADIUS: 9 })
    const gen = g.generation
    expect(g.config.BALL_RADIUS).toBe(11)
    g.throwPlayer({ power: 0.5, angle: 0 })
    expect(g.generation).toBe(gen + 1)
    expect(g.config.BALL_RADIUS).toBe(9)
    expect(g.pending).toBeNull()
  })
})

describe('demo game: replays and called shots', () => {
  /** steps frames of 1/60 s until no ball moves (the round ends) or `max` frames */
  const settle = (g: Game, max = 2000): void => {
    const moving = (id: number): boolean => {
      const m = g.sim.world.Ball.mode[id]
      return m === BallMode.Rolling || m === BallMode.RimRoll || m === BallMode.Held
    }
    for (let i = 0; i < max && (g.replaying !== null || g.live.some(moving)); i++) g.frame(1 / 60)
  }

  it('a replay started during a round leaves that round recorded: it ends after the replay, and plays back the same', () => {
    const g = new Game()
    g.reset()
    g.throwPlayer({ power: 0.5, angle: -0.22 })
    settle(g)
    for (let i = 0; i < 5; i++) g.frame(1 / 60)
    expect(g.roundsRecorded).toBe(1)
    const first = g.lastRound
    // a second round under way, then a replay of the first
    g.burst(30)
    for (let i = 0; i < 20; i++) g.frame(1 / 60)
    const liveTime = g.sim.time
    expect(g.replayLastRound()).toBe(true)
    for (let i = 0; i < 2000 && g.replaying !== null; i++) g.frame(1 / 60)
    expect(g.replaying).toBe(null)
    expect(g.sim.time).toBe(liveTime) // the live world waited
    settle(g)
    for (let i = 0; i < 5; i++) g.frame(1 / 60)
    expect(g.roundsRecorded).toBe(2)
    expect(g.lastRound).not.toBe(first)
    const recorded = g.roundEvents
    expect(recorded.length).toBeGreaterThan(30)
    // the second round, played back, gives its events (a round starts with the burst: its throws are in it)
    expect(g.replayLastRound()).toBe(true)
    for (let i = 0; i < 4000 && g.replaying !== null; i++) g.frame(1 / 60)
    expect(g.replayEvents).toEqual(recorded)
  })

  it('a called shot: the panel waits while it is solved; its answer throws; a throw meanwhile cancels it', () => {
    const g = new Game()
    g.reset()
    g.burst(20)
    for (let i = 0; i < 10; i++) g.frame(1 / 60)
    const call = g.beginCall(12)!
    expect(call).not.toBe(null)
    expect(g.beginCall(3)).toBe(null) // one call at a time
    const t = g.sim.time
    for (let i = 0; i < 10; i++) expect(g.frame(1 / 60).steps).toBe(0)
    expect(g.sim.time).toBe(t)
    // solved on a copy, as the worker does: the same answer as in the world itself
    const copy = createBallPhysics(call.config)
    copy.restore(call.snapshot)
    const answer = solveThrow(copy, call.request)
    expect(answer).toEqual(solveThrow(g.sim, call.request))
    expect(answer.found).toBe(true)
    const left = g.ballsLeft
    expect(g.finishCall(call.token, answer, 1)).toBe(answer)
    expect(g.ballsLeft).toBe(left - 1)
    expect(g.solving).toBe(null)
    expect(g.frame(1 / 60).steps).toBeGreaterThan(0)
    // settings changed while a call is solved wait for the next throw: the answer goes into the world it
    // was solved in (applied first, they rebuilt the world and the solved throw went into another)
    const before = g.sim
    const ballsBefore = g.live.length
    const settled = g.beginCall(12)!
    g.setPending({ ...g.overrides, ROLLING_DECEL: 120 })
    const replyCopy = createBallPhysics(settled.config)
    replyCopy.restore(settled.snapshot)
    const reply = solveThrow(replyCopy, settled.request)
    expect(g.finishCall(settled.token, reply, 1)).toBe(reply)
    expect(g.sim).toBe(before)
    expect(g.live.length).toBe(ballsBefore + (reply.found ? 1 : 0))
    expect(g.pending).toEqual({ ...g.overrides, ROLLING_DECEL: 120 })
    // a call, then the player's own throw: the call's answer is dropped
    const again = g.beginCall(12)!
    g.throwPlayer({ power: 0.4, angle: 0.1 })
    expect(g.solving).toBe(null)
    expect(g.finishCall(again.token, answer, 1)).toBe(null)
    expect(g.ballsLeft).toBe(left - 2 - (reply.found ? 1 : 0))
  })
})
