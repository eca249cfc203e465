// Replays (src/commands/replay.ts): a recorded session — every command and step — plays back with the
// same events, states and snapshot, bit for bit, through JSON; recording can start mid-run; commands that
// fail record nothing; bad replays are refused by name. (The cross-engine playback: tests/engines.test.ts.)
import { describe, expect, it } from 'vitest'
import {
  addPanel,
  createBallPhysics,
  createReplayPlayer,
  prepareRimTable,
  replayFromJSON,
  replayToJSON,
  TABULATED_CONFIG,
  type BallEvent,
  type BallPhysics,
  type ConfigOverrides,
  type Replay,
} from '../src/index.js'

function random(seed: number): () => number {
  let s = seed
  return () => {
    s = (s * 16807) % 2147483647
    return (s - 1) / 2147483646
  }
}

/** Every kind of input, at different steps; returns each step's drained events. */
function session(sim: BallPhysics, steps: number, seed = 9): BallEvent[][] {
  const r = random(seed)
  const out: BallEvent[][] = []
  for (let step = 0; step < steps; step++) {
    if (step < 40 && step % 2 === 0) for (let k = 0; k < 6; k++) sim.throwBall({ x: 60 + 300 * r(), y: 450 - 30 * r(), power: r(), angle: (r() - 0.5) * 1.2 })
    if (step === 10) sim.addBall({ x: 200, y: 300, vx: -0, vy: -350, radius: 9, mass: 0.5 })
    if (step === 20) for (const b of sim.balls().slice(0, 8)) if (sim.ballState(b).mode === 'rolling') sim.setBallVelocity(b, 40 * r(), -250)
    if (step === 25) sim.setHeroBall(sim.balls()[5]!, true)
    if (step === 26) sim.setBallMass(sim.balls()[7]!, 40)
    if (step === 30) sim.removeBall(sim.balls()[2]!)
    if (step === 35) sim.addHole({ x: 30, y: 30, radius: 12, value: 5 })
    if (step === 50) sim.removeHole(sim.holes()[4]!)
    if (step === 60) sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 0.3, open: { bottom: true, top: true } })
    if (step === 80) sim.clearWalls()
    sim.step(step % 3 === 0 ? 1 / 30 : 1 / 60)
    out.push(sim.drainEvents())
  }
  return out
}

function states(sim: BallPhysics) {
  return { time: sim.time, balls: sim.balls().map((b) => ({ b, ...sim.ballState(b) })), holes: sim.holes() }
}

function play(replay: Replay): { events: BallEvent[][]; sim: BallPhysics } {
  const p = createReplayPlayer(replayFromJSON(replayToJSON(replay)))
  const events: BallEvent[][] = []
  while (p.next()) events.push(p.sim.drainEvents())
  return { events, sim: p.sim }
}

const CONFIGS: Array<[string, ConfigOverrides]> = [
  ['the design', {}],
  ['contacts on', { BALL_COLLISIONS: 'on' }],
  ['contacts fixed', { BALL_COLLISIONS: 'fixed' }],
  ['the tabulated model', TABULATED_CONFIG],
  ['the tick-sampled naive method', { METHOD: 'naive' }],
]

describe('replays', () => {
  for (const [name, config] of CONFIGS) {
    it(`${name}: a recorded session plays back through JSON with every event, state and (exact method) the snapshot bit-identical`, () => {
      const sim = createBallPhysics(config)
      sim.startRecording()
      addPanel(sim)
      sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, open: { bottom: true } })
      const events = session(sim, 150)
      const replay = sim.stopRecording()
      expect(replay.start).toBeUndefined()
      expect(replay.inputs.filter((i) => i[0] === 'step')).toHaveLength(150)
      const back = play(replay)
      expect(back.events).toEqual(events)
      expect(states(back.sim)).toEqual(states(sim))
      if (sim.config.METHOD === 'exact') expect(back.sim.snapshot()).toEqual(sim.snapshot())
      expect(events.flat().length).toBeGreaterThan(100)
    })
  }

  it('recording started mid-run carries a snapshot of the start, and plays back bit-identically', () => {
    const sim = createBallPhysics({ BALL_COLLISIONS: 'on' })
    addPanel(sim)
    session(sim, 30, 1)
    sim.startRecording()
    const events = session(sim, 60, 2)
    const replay = sim.stopRecording()
    expect(typeof replay.start).toBe('string')
    const back = play(replay)
    expect(back.events).toEqual(events)
    expect(states(back.sim)).toEqual(states(sim))
  })

  it('a table prepared for another ball size is part of the replay', () => {
    const sim = createBallPhysics(TABULATED_CONFIG)
    sim.startRecording()
    addPanel(sim)
    prepareRimTable(sim, 18, 8, { rows: 'lazy' })
    for (let i = 0; i < 40; i++) sim.throwBall({ x: 100 + 5 * i, y: 450, power: 0.02 * i, angle: 0.01 * i - 0.2, radius: 8 })
    const events: BallEvent[][] = []
    for (let s = 0; s < 120; s++) {
      sim.step(1 / 60)
      events.push(sim.drainEvents())
    }
    const replay = sim.stopRecording()
    expect(replay.inputs.some((i) => i[0] === 'prepareRimTable')).toBe(true)
    expect(play(replay).events).toEqual(events)
  })

  it('a command that fails records nothing', () => {
    const sim = createBallPhysics()
    sim.startRecording()
    expect(() => sim.addBall({ x: Number.NaN, y: 0, vx: 0, vy: 0 })).toThrow(/ball\.x/)
    expect(() => sim.step(-1)).toThrow(/dt/)
    sim.addHole({ x: 100, y: 100 })
    expect(() => sim.addHole({ x: 101, y: 100 })).toThrow(/overlaps/)
    expect(sim.stopRecording().inputs).toEqual([['addHole', { x: 100, y: 100, radius: 18, value: 1 }]])
  })

  it('keeps −0 through JSON', () => {
    const sim = createBallPhysics()
    sim.startRecording()
    const b = sim.addBall({ x: 0, y: 0, vx: -0, vy: 10 })
    sim.setBallVelocity(b, -0, 5)
    const back = replayFromJSON(replayToJSON(sim.stopRecording()))
    expect(Object.is((back.inputs[0]![1] as { vx: number }).vx, -0)).toBe(true)
    expect(Object.is(back.inputs[1]![2], -0)).toBe(true)
  })

  it('refuses a bad replay by name, and names the input that fails', () => {
    const sim = createBallPhysics()
    sim.startRecording()
    sim.addBall({ x: 0, y: 0, vx: 0, vy: 10 })
    sim.step(1 / 60)
    const good = sim.stopRecording()
    expect(() => createReplayPlayer(null as unknown as Replay)).toThrow(/replay must be a replay object/)
    expect(() => createReplayPlayer({ ...good, format: 'x' } as unknown as Replay)).toThrow(/replay\.format/)
    expect(() => createReplayPlayer({ ...good, version: 2 })).toThrow(/replay\.version 2/)
    expect(() => createReplayPlayer({ ...good, inputs: [['step']] as unknown as Replay['inputs'] }).next()).toThrow(/replay input 0 \("step"\): dt must be a number/)
    expect(() => createReplayPlayer({ ...good, inputs: [['fly', 1]] }).next()).toThrow(/replay input 0 \("fly"\): unknown command/)
    expect(() => createReplayPlayer({ ...good, config: { ...good.config, BALL_RADIUS: -1 } })).toThrow(/BALL_RADIUS/)
    expect(() => sim.stopRecording()).toThrow(/not recording/)
    // replayFromJSON checks as the player does: an unknown key, a wrong version or a text that is no replay
    const text = replayToJSON(good)
    expect(() => replayFromJSON(text.replace('{', '{"extra":1,'))).toThrow(/replay\.extra is not a known key/)
    expect(() => replayFromJSON(text.replace(/"version":\d+/, '"version":2'))).toThrow(/replay\.version 2/)
    expect(() => replayFromJSON('null')).toThrow(TypeError)
    // the recorded world's options are part of a replay: checked, each field named
    const { options: _options, ...noOptions } = good
    expect(() => createReplayPlayer(noOptions as Replay)).toThrow(/^replay\.options must be the recorded world's options \{ capacity, broadphase \}, got undefined$/)
    expect(() => replayFromJSON(replayToJSON(noOptions as Replay))).toThrow(TypeError)
    expect(() => createReplayPlayer({ ...good, options: { ...good.options, capacity: 0 } })).toThrow(/^replay\.options\.capacity must be an integer in \[1, 67108864\], got 0$/)
    expect(() => createReplayPlayer({ ...good, options: { ...good.options, broadphase: 'hash' as 'grid' } })).toThrow(/^replay\.options\.broadphase must be 'auto', 'grid' or 'scan', got the string "hash"$/)
    expect(() => createReplayPlayer({ ...good, options: { ...good.options, cap: 1 } as Replay['options'] })).toThrow(/replay\.options\.cap is not a known key/)
    // text that is not JSON says whose text it was
    expect(() => replayFromJSON(text.slice(0, -1))).toThrow(SyntaxError)
    expect(() => replayFromJSON(text.slice(0, -1))).toThrow(/^replayFromJSON: text is not JSON \(a replay as replayToJSON writes it\): /)
    expect(replayFromJSON(text)).toEqual(good)
  })
})

describe('a recording starts from the state it was started in', () => {
  const key = (e: { type: string; ball: number; hole?: number; time: number }) => `${e.type} ${e.ball} ${e.hole ?? ''} ${e.time}`
  const play = (s: BallPhysics, n: number, log: string[]) => {
    for (let f = 0; f < n; f++) {
      s.step(1 / 60)
      for (const e of s.drainEvents()) log.push(key(e))
    }
  }
  const replayed = (sim: BallPhysics): string[] => {
    const p = createReplayPlayer(replayFromJSON(replayToJSON(sim.stopRecording())))
    const out: string[] = []
    while (p.next()) for (const e of p.sim.drainEvents()) out.push(key(e))
    return out
  }
  const throws = (s: BallPhysics) => {
    for (let i = 0; i < 30; i++) s.throwBall({ x: 80 + 8 * i, y: 450, power: 0.3 + 0.015 * i, angle: 0.3 - 0.02 * i, radius: 7 })
  }

  /** On a world recording: the panel, 30 throws, `frames` steps; the replay gives the same events. */
  const expectSameReplay = (s: BallPhysics, frames: number): void => {
    addPanel(s)
    throws(s)
    const live: string[] = []
    play(s, frames, live)
    expect(live.length).toBeGreaterThan(30)
    expect(replayed(s)).toEqual(live)
  }

  it('a world stepped while empty (an attract loop), then recorded: the replay keeps its clock (it started at 0, every event 0.5 s early)', () => {
    const s = createBallPhysics({ BALL_COLLISIONS: 'on' })
    for (let f = 0; f < 30; f++) s.step(1 / 60)
    s.startRecording()
    expectSameReplay(s, 120)
  })

  it('rim tables prepared before the recording (tabulated model, empty world): the replay has them (its outcomes differed)', () => {
    const s = createBallPhysics(TABULATED_CONFIG)
    prepareRimTable(s, 18, 7)
    s.startRecording()
    expectSameReplay(s, 150)
  })

  it('a fresh world needs no start state: its replay has none', () => {
    const s = createBallPhysics()
    s.startRecording()
    addPanel(s)
    expect(s.stopRecording().start).toBeUndefined()
  })

  it('restore while recording is refused (the replay played an empty world), and changes nothing', () => {
    const server = createBallPhysics({ BALL_COLLISIONS: 'on' })
    addPanel(server)
    throws(server)
    for (let f = 0; f < 30; f++) server.step(1 / 60)
    const s = createBallPhysics({ BALL_COLLISIONS: 'on' })
    s.startRecording()
    expect(() => s.restore(server.snapshot())).toThrow(/restore: the world is recording/)
    expect(s.balls()).toEqual([])
    expect(s.time).toBe(0)
    // restore first, then record: the replay is the run
    const t = createBallPhysics({ BALL_COLLISIONS: 'on' })
    t.restore(server.snapshot())
    t.startRecording()
    const live: string[] = []
    play(t, 90, live)
    expect(live.length).toBeGreaterThan(10)
    expect(replayed(t)).toEqual(live)
  })
})

describe("a game's own entities made while recording", () => {
  it('are not recorded: the replay gives the balls the ids of a world without them, with the same events in creation order', async () => {
    const { addEntity } = await import('bitecs')
    const { createBallWorld, drainEvents, playReplay, runSchedule, createSchedule, startReplay, takeReplay, throwBall } = await import('../src/ecs.js')
    const w = createBallWorld({ BALL_COLLISIONS: 'on' })
    startReplay(w)
    const balls: number[] = []
    for (let i = 0; i < 20; i++) {
      addEntity(w) // the game's own entity, between throws
      balls.push(throwBall(w, { x: 60 + 12 * i, y: 450, power: 0.6, angle: 0.3 - 0.03 * i }))
    }
    const schedule = createSchedule(w.config)
    const live: string[] = []
    const key = (ids: number[], e: BallEvent) => `${e.type} ${ids.indexOf(e.ball)} ${e.other === undefined ? '' : ids.indexOf(e.other)} ${e.time}`
    for (let s = 0; s < 120; s++) {
      runSchedule(w, schedule, 1 / 60)
      for (const e of drainEvents(w)) live.push(key(balls, e))
    }
    const replayed: BallEvent[] = []
    const r = playReplay(takeReplay(w), (world) => replayed.push(...drainEvents(world)))
    replayed.push(...drainEvents(r))
    // the replay's balls are numbered as in a world with no other entities: ids 1..20 where the game's were 2, 4, ..., 40
    const ids = [...new Set(replayed.map((e) => e.ball))].sort((a, b) => a - b)
    expect(ids.length).toBeGreaterThan(10)
    expect(ids.every((b) => b <= 20)).toBe(true)
    expect(balls.filter((b) => b > 20).length).toBeGreaterThan(0)
    const inOrder = Array.from({ length: 20 }, (_, i) => i + 1)
    expect(replayed.map((e) => key(inOrder, e))).toEqual(live)
    expect(live.some((l) => l.startsWith('collision'))).toBe(true)
  })
})
