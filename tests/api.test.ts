// Bad input: clear errors naming the field and its range, and the world left as it was.
import { describe, expect, it } from 'vitest'
import { DEFAULT_CONFIG, DEFAULT_PANEL, addPanel, createBallPhysics, createReplayPlayer, replayFromJSON, replayToJSON, type BallPhysics } from '../src/index'
import { settle } from './helpers'
import { ballState, listBalls, removeBall } from '../src/ecs'

function snapshot(sim: BallPhysics): string {
  const parts: string[] = [String(sim.time), String(sim.balls()), String(sim.holes()), String(sim.world.events.count)]
  for (const store of [sim.world.Ball, sim.world.Hole, sim.world.RimContact, sim.world.Path]) {
    for (const arr of Object.values(store) as Float64Array[]) parts.push(Array.from(arr.subarray(0, 64)).join(','))
  }
  return parts.join('|')
}

function scene(): BallPhysics {
  const sim = createBallPhysics()
  addPanel(sim)
  sim.throwBall({ x: DEFAULT_PANEL.launch.x, y: DEFAULT_PANEL.launch.y, power: 0.5, angle: 0.1 })
  sim.step(1 / 60)
  sim.drainEvents()
  return sim
}

const bad: [string, (s: BallPhysics) => unknown, RegExp, ErrorConstructor][] = [
  ['addBall x NaN', (s) => s.addBall({ x: NaN, y: 0, vx: 0, vy: 0 }), /ball\.x/, RangeError],
  ['addBall vy Infinity', (s) => s.addBall({ x: 0, y: 0, vx: 0, vy: Infinity }), /ball\.vy/, RangeError],
  ['addBall radius 0', (s) => s.addBall({ x: 0, y: 0, vx: 0, vy: 0, radius: 0 }), /ball\.radius must be in \(0, /, RangeError],
  ['addBall radius < 0', (s) => s.addBall({ x: 0, y: 0, vx: 0, vy: 0, radius: -3 }), /ball\.radius/, RangeError],
  ['addBall x string', (s) => s.addBall({ x: '1' as never, y: 0, vx: 0, vy: 0 }), /ball\.x must be a number/, TypeError],
  ['addBall null', (s) => s.addBall(null as never), /addBall spec/, TypeError],
  ['addHole y Infinity', (s) => s.addHole({ x: 0, y: -Infinity }), /hole\.y/, RangeError],
  ['addHole radius 0', (s) => s.addHole({ x: 0, y: 0, radius: 0 }), /hole\.radius/, RangeError],
  ['addHole value NaN', (s) => s.addHole({ x: 1000, y: 1000, value: NaN }), /hole\.value/, RangeError],
  ['addHole overlapping', (s) => s.addHole({ x: 60, y: 370 }), /overlaps hole/, RangeError],
  ['throw power 1.5', (s) => s.throwBall({ x: 0, y: 0, power: 1.5, angle: 0 }), /throw\.power must be in \[0, 1\]/, RangeError],
  ['throw power -0.1', (s) => s.throwBall({ x: 0, y: 0, power: -0.1, angle: 0 }), /throw\.power/, RangeError],
  ['throw power NaN', (s) => s.throwBall({ x: 0, y: 0, power: NaN, angle: 0 }), /throw\.power/, RangeError],
  ['throw angle NaN', (s) => s.throwBall({ x: 0, y: 0, power: 0.5, angle: NaN }), /throw\.angle/, RangeError],
  ['step 0', (s) => s.step(0), /dt must be a finite number of seconds > 0/, RangeError],
  ['step -1', (s) => s.step(-1), /dt/, RangeError],
  ['step NaN', (s) => s.step(NaN), /dt/, RangeError],
  ['step Infinity', (s) => s.step(Infinity), /dt/, RangeError],
  ['step string', (s) => s.step('0.1' as never), /dt must be a number/, TypeError],
  ['ballState unknown', (s) => s.ballState(9999), /ball 9999 is not a live ball/, RangeError],
  ['ballState of a hole', (s) => s.ballState(s.holes()[0]!), /is not a live ball/, RangeError],
  // a number that is no id is out of range; anything else is the wrong type
  ['ballState 1.5', (s) => s.ballState(1.5), /ball must be a ball id \(a positive integer\), got 1\.5/, RangeError],
  ['ballState -1', (s) => s.ballState(-1), /ball must be a ball id \(a positive integer\), got -1/, RangeError],
  ['ballState string', (s) => s.ballState('3' as never), /ball must be a ball id \(a positive integer\), got the string "3"/, TypeError],
  ['holeState 0', (s) => s.holeState(0), /hole must be a hole id/, RangeError],
  ['removeBall unknown', (s) => s.removeBall(12345), /not a live ball/, RangeError],
  ['holeState of a ball', (s) => s.holeState(s.balls()[0]!), /is not a live hole/, RangeError],
]

describe('bad input', () => {
  for (const [name, call, message, type] of bad) {
    it(`${name}: throws ${type.name} naming the field, and leaves the world unchanged`, () => {
      const sim = scene()
      const before = snapshot(sim)
      expect(() => call(sim)).toThrow(type)
      expect(() => call(sim)).toThrow(message)
      expect(snapshot(sim)).toBe(before)
    })
  }

  it('a removed ball id gives a clear error, and its slot is reused cleanly', () => {
    const sim = createBallPhysics()
    const b = sim.addBall({ x: 0, y: 0, vx: 10, vy: 0 })
    sim.removeBall(b)
    expect(() => sim.ballState(b)).toThrow(/not a live ball of this world \(unknown or removed\)/)
    expect(() => sim.removeBall(b)).toThrow(RangeError)
    const c = sim.addBall({ x: 5, y: 5, vx: 0, vy: 0 })
    expect(sim.ballState(c)).toMatchObject({ x: 5, y: 5, vx: 0, vy: 0, mode: 'rolling' })
    expect(sim.balls()).toEqual([c])
  })

  it('a replay of a game whose own system gives commands during the step plays back with that schedule', () => {
    // the game's system removes the first ball to cross y = 300 mid-step: not recorded (it is the system's
    // to give again); the main entry's player took no schedule, so its playback kept the ball
    const zap = { name: 'zap', run: (w: BallPhysics['world']) => {
      for (const b of listBalls(w)) if (ballState(w, b).mode === 'rolling' && ballState(w, b).y < 300) return void removeBall(w, b)
    } }
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed' })
    sim.schedule.splice(sim.schedule.findIndex((e) => e.name === 'integration') + 1, 0, zap)
    sim.startRecording()
    addPanel(sim)
    for (let i = 0; i < 12; i++) sim.throwBall({ x: 80 + 24 * i, y: 450, power: 0.7, angle: 0.2 - 0.04 * i })
    const live: string[] = []
    for (let i = 0; i < 90; i++) {
      sim.step(1 / 60)
      for (const e of sim.drainEvents()) live.push(`${e.type} ${e.ball} ${e.time}`)
    }
    const replay = replayFromJSON(replayToJSON(sim.stopRecording()))
    const play = (schedule?: BallPhysics['schedule']) => {
      const p = createReplayPlayer(replay, schedule)
      const out: string[] = []
      while (p.next()) for (const e of p.sim.drainEvents()) out.push(`${e.type} ${e.ball} ${e.time}`)
      return { out, balls: p.sim.balls().length }
    }
    expect(play(sim.schedule).out).toEqual(live)
    expect(play(sim.schedule).balls).toBe(sim.balls().length)
    expect(play().balls).toBeGreaterThan(sim.balls().length)
    expect(() => createReplayPlayer(replay, {} as never)).toThrow(/createReplayPlayer: schedule must be an array/)
  })

  it('addBall without vx and vy puts the ball down at rest, as vx: 0, vy: 0 does, and records it so', () => {
    const run = (spec: { x: number; y: number; vx?: number; vy?: number }) => {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'on' })
      sim.startRecording()
      const b = sim.addBall(spec)
      sim.addBall({ x: spec.x - 60, y: spec.y, vx: 300, vy: 0 }) // rolls into it
      for (let i = 0; i < 30; i++) sim.step(1 / 60)
      return { b, state: sim.ballState(b), events: sim.drainEvents().length, replay: sim.stopRecording() }
    }
    const bare = run({ x: 120, y: 300 })
    expect(bare.state).toEqual(run({ x: 120, y: 300, vx: 0, vy: 0 }).state)
    expect(bare.state.vx).not.toBe(0) // it was struck
    expect(bare.events).toBeGreaterThan(0)
    const p = createReplayPlayer(replayFromJSON(replayToJSON(bare.replay)))
    while (p.next());
    expect(p.sim.ballState(bare.b)).toEqual(bare.state)
    const sim = createBallPhysics()
    expect(() => sim.addBall({ x: 0, y: 0, vx: null as never })).toThrow(TypeError)
    // put down still: 'rolling' until the next step, which reports its 'rest' (or 'capture', over a hole)
    // at the instant it was put down
    sim.step(0.25)
    sim.addHole({ x: 300, y: 300 })
    const still = sim.addBall({ x: 100, y: 100 })
    const over = sim.addBall({ x: 305, y: 300 })
    expect(sim.ballState(still)).toMatchObject({ mode: 'rolling', vx: 0, vy: 0 })
    sim.step(1 / 60)
    expect(sim.drainEvents().map((e) => [e.type, e.ball, e.time])).toEqual([
      ['rest', still, 0.25],
      ['capture', over, 0.25],
    ])
    expect([sim.ballState(still).mode, sim.ballState(over).mode]).toEqual(['resting', 'captured'])
  })

  it('no NaN or Infinity reaches a component array under random valid use', () => {
    const sim = createBallPhysics()
    addPanel(sim)
    let seed = 1
    const rand = () => ((seed = (seed * 16807) % 2147483647) - 1) / 2147483646
    for (let i = 0; i < 2000; i++) {
      const op = rand()
      if (op < 0.4) sim.throwBall({ x: rand() * 420, y: 300 + rand() * 200, power: rand(), angle: (rand() - 0.5) * 6 })
      else if (op < 0.5) sim.addBall({ x: rand() * 420, y: rand() * 480, vx: (rand() - 0.5) * 2e5, vy: (rand() - 0.5) * 10 })
      else if (op < 0.6 && sim.balls().length > 0) sim.removeBall(sim.balls()[0]!)
      else sim.step(rand() * 0.3 + 1e-6)
    }
    settle(sim, 0.1, 60)
    for (const store of [sim.world.Ball, sim.world.Path, sim.world.RimContact, sim.world.Hole]) {
      for (const [k, arr] of Object.entries(store) as [string, Float64Array][]) {
        for (let i = 0; i < arr.length; i++) if (!Number.isFinite(arr[i]!)) throw new Error(`${k}[${i}] = ${arr[i]}`)
      }
    }
  })

  it('stores grow past their preallocated capacity and keep every ball intact', () => {
    const sim = createBallPhysics({}, { capacity: 4 })
    const ids = Array.from({ length: 100 }, (_, i) => sim.addBall({ x: i * 30, y: 0, vx: 0, vy: -100 }))
    sim.step(0.1)
    for (const [i, b] of ids.entries()) expect(sim.ballState(b).x).toBe(i * 30)
    expect(sim.world.capacity).toBeGreaterThanOrEqual(101)
  })
})

describe('config', () => {
  it('rejects non-finite, out-of-range and unknown keys with the key and its range', () => {
    expect(() => createBallPhysics({ V_MAX: NaN })).toThrow(/config\.V_MAX must be in \(0, 1000000\]/)
    expect(() => createBallPhysics({ RIM_RESTITUTION: 1.2 })).toThrow(/config\.RIM_RESTITUTION must be in \[0, 1\], got 1.2/)
    expect(() => createBallPhysics({ ROLLING_DECEL: -1 })).toThrow(/config\.ROLLING_DECEL/)
    expect(() => createBallPhysics({ MAX_EVENT_PASSES: 2.5 })).toThrow(/an integer/)
    expect(() => createBallPhysics({ HOLE_RADUS: 3 } as never)).toThrow(/config\.HOLE_RADUS is not a known key/)
    expect(() => createBallPhysics({ MIN_VY: 500, MAX_VY: 400 })).toThrow(/config\.MAX_VY/)
    expect(() => createBallPhysics({ V_MAX: '600' as never })).toThrow(TypeError)
  })

  it('keeps GRAVITY and V_SKIP_MAX consistent: either derives the other, both must agree', () => {
    const d = createBallPhysics().config
    expect(d.GRAVITY).toBeCloseTo((640 * 640 * 11) / (2 * 18 * 18), 9)
    const g = createBallPhysics({ GRAVITY: 9000 }).config
    expect(g.V_SKIP_MAX).toBeCloseTo(18 * Math.sqrt((2 * 9000) / 11), 9)
    const v = createBallPhysics({ V_SKIP_MAX: 500 }).config
    expect(v.GRAVITY).toBeCloseTo((500 * 500 * 11) / (2 * 18 * 18), 9)
    expect(() => createBallPhysics({ GRAVITY: 9000, V_SKIP_MAX: 640 })).toThrow(/GRAVITY = 9000 implies V_SKIP_MAX/)
    expect(createBallPhysics({ GRAVITY: d.GRAVITY, V_SKIP_MAX: 640 }).config.V_SKIP_MAX).toBe(640)
    // the defaults spread with one size changed hold both: the error says how to leave one out, and that works
    expect(() => createBallPhysics({ ...DEFAULT_CONFIG, HOLE_RADIUS: 20 })).toThrow(/spread from DEFAULT_CONFIG .* holds both: leave one out/)
    const { GRAVITY: _g, ...rest } = DEFAULT_CONFIG
    expect(createBallPhysics({ ...rest, HOLE_RADIUS: 20 }).config.V_SKIP_MAX).toBe(640)
  })

  it('the defaults are the design table', () => {
    expect(createBallPhysics().config).toMatchObject({
      HOLE_RADIUS: 18,
      BALL_RADIUS: 11,
      V_MAX: 600,
      V_SKIP_MAX: 640,
      RIM_RESTITUTION: 0.3,
      RIM_FRICTION: 0.3,
      RIM_ROLL_RATIO: 1.4,
      RIM_ROLL_FRICTION: 5,
      RIM_ROLL_DROP_SPEED: 110,
      MIN_VY: 175,
      MAX_VY: 700,
    })
  })
})

describe('waking and moving balls through the API', () => {
  it('a resting ball costs nothing until setBallVelocity wakes it; then it rolls on its new path', () => {
    const sim = createBallPhysics()
    const b = sim.addBall({ x: 0, y: 0, vx: 100, vy: 0 })
    settle(sim)
    expect(sim.ballState(b).mode).toBe('resting')
    expect(sim.world.moving.count).toBe(0)
    sim.setBallVelocity(b, 0, -300)
    expect(sim.world.moving.count).toBe(1)
    sim.step(0.1)
    expect(sim.ballState(b).y).toBeCloseTo(-(300 * 0.1 - 0.5 * 300 * 0.01), 9)
  })

  it('a ball knocked off a rim leaves on a straight path with the hole locked, and never re-enters it at once', () => {
    const sim = createBallPhysics()
    const h = sim.addHole({ x: 0, y: 0 })
    const lipX = -Math.sqrt(18 * 18 - 11 * 11)
    const b = sim.addBall({ x: lipX - 60, y: 11, vx: Math.sqrt(490 ** 2 + 2 * 300 * 60), vy: 0 })
    for (let i = 0; i < 200 && sim.ballState(b).mode !== 'rimRoll'; i++) sim.step(1 / 500)
    expect(sim.ballState(b).mode).toBe('rimRoll')
    const { x, y } = sim.ballState(b)
    sim.setBallVelocity(b, (x / 18) * 400, (y / 18) * 400) // straight out, radially
    const ev = settle(sim)
    expect(ev.filter((e) => e.hole === h && e.type !== 'rimRoll').map((e) => e.type)).toEqual([])
    expect(Math.hypot(sim.ballState(b).x, sim.ballState(b).y)).toBeGreaterThan(18)
  })

  it('refuses to move a captured ball, naming its mode', () => {
    const sim = createBallPhysics()
    sim.addHole({ x: 0, y: 0 })
    const b = sim.addBall({ x: 1, y: 0, vx: 0, vy: 0 })
    sim.step(0.01)
    expect(() => sim.setBallVelocity(b, 1, 1)).toThrow(/is captured: only rolling, rimRoll, resting or held balls can be given a velocity/)
    expect(() => sim.setBallVelocity(b, NaN, 1)).toThrow(/vx/)
  })

  it('1,000,000 resting balls are not iterated: a step with 1,000 moving ones touches only those', () => {
    const sim = createBallPhysics({}, { capacity: 1 << 20 })
    for (let i = 0; i < 1_000_000; i++) sim.addBall({ x: (i % 1000) * 30, y: Math.floor(i / 1000) * 30, vx: 0, vy: 0 })
    sim.step(0.01) // all come to rest at once
    sim.drainEvents()
    expect(sim.world.moving.count).toBe(0)
    for (let i = 0; i < 1000; i++) sim.setBallVelocity(i + 1, 100, 0)
    expect(sim.world.moving.count).toBe(1000)
  })
})
