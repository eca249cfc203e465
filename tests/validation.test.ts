// Every entry point validates its input, says what it got, and leaves the world as it was.
import { describe, expect, it } from 'vitest'
import { removeEntity } from 'bitecs'
import { DEFAULT_PANEL, addPanel, createBallPhysics, type BallPhysics, type PanelLayout } from '../src/index'
import { HOT, H_V0, addBall, drainEvents, addHole, addHoles, clearWalls, createBallWorld, createSchedule, forEachBall, isBall, listBalls, listHoles, removeHole, runSchedule, setBallVelocity, setWalls, throwBall, type BallWorld } from '../src/ecs'

/** Everything a failed call could have touched. */
function snapshot(w: BallWorld): string {
  const parts: unknown[] = [w.time, listBalls(w), listHoles(w), w.walls, w.events.count, w.moving.count, w.entityIndex.maxId]
  parts.push(w.holes.count, w.rimNext, w.rimFree.count, w.stepping, w.capacity)
  for (const store of [w.Ball, w.Path, w.Hole, w.RimContact, w.Walls]) {
    for (const [k, arr] of Object.entries(store) as [string, Float64Array][]) parts.push(k, Array.from(arr.subarray(0, 64), String))
  }
  return JSON.stringify(parts)
}

/** A panel, walls, two balls in play and an event left in the buffer. */
function scene(): BallPhysics {
  const sim = createBallPhysics()
  addPanel(sim)
  sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, open: { bottom: true } })
  sim.throwBall({ x: DEFAULT_PANEL.launch.x, y: DEFAULT_PANEL.launch.y, power: 0.5, angle: 0.1 })
  sim.addBall({ x: 400, y: 460, vx: 0, vy: 0 })
  sim.step(1 / 60)
  return sim
}

function expectRefused(sim: BallPhysics, call: () => unknown, type: ErrorConstructor, ...messages: (string | RegExp)[]): Error {
  const before = snapshot(sim.world)
  let caught: unknown = null
  try {
    call()
  } catch (e) {
    caught = e
  }
  expect(caught).toBeInstanceOf(type)
  const message = (caught as Error).message
  for (const m of messages) expect(message).toMatch(m)
  expect(message).not.toMatch(/Cannot convert|Cannot read properties/)
  expect(snapshot(sim.world)).toBe(before)
  return caught as Error
}

const BAD_DT: [unknown, ErrorConstructor, string][] = [
  [-0.05, RangeError, 'got -0.05'],
  [0, RangeError, 'got 0'],
  [NaN, RangeError, 'got NaN'],
  [Infinity, RangeError, 'got Infinity'],
  ['1/60', TypeError, 'got the string "1/60"'],
]

describe('steps', () => {
  for (const [dt, type, message] of BAD_DT) {
    it(`runSchedule and sim.step refuse dt = ${String(dt)} with a ${type.name}`, () => {
      const sim = scene()
      expectRefused(sim, () => runSchedule(sim.world, sim.schedule, dt as number), type, message, /dt/)
      expectRefused(sim, () => sim.step(dt as number), type, message, /dt/)
    })
  }

  it('with the fixed tick, runSchedule refuses a dt over MAX_STEP (every contact tick of it is solved: 1e9 s ran for minutes with one ball at rest); the exact method takes it', () => {
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed' })
    sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480 })
    sim.addBall({ x: 100, y: 100 })
    sim.step(1 / 60)
    for (const dt of [0.25 + 1e-9, 10, 1e9]) expectRefused(sim, () => runSchedule(sim.world, sim.schedule, dt), RangeError, `dt must be in (0, MAX_STEP = 0.25] s, got ${dt}`, /MAX_STEP/)
    runSchedule(sim.world, sim.schedule, 0.25)
    expect(sim.time).toBeCloseTo(1 / 60 + 0.25, 12)
    const exact = createBallPhysics({ BALL_COLLISIONS: 'on' })
    exact.addBall({ x: 100, y: 100 })
    runSchedule(exact.world, exact.schedule, 1e9)
    expect(exact.time).toBe(1e9)
  })

  it('runSchedule refuses a schedule that is not an array, and a world that is not one', () => {
    const sim = scene()
    for (const bad of [{}, null, 'integration', { length: 1, 0: sim.schedule[0] }]) {
      expectRefused(sim, () => runSchedule(sim.world, bad as never, 1 / 60), TypeError, /schedule must be an array/)
    }
    expectRefused(sim, () => runSchedule({} as never, sim.schedule, 1 / 60), TypeError, /runSchedule: world must be/)
  })

  it('forEachBall and isBall refuse what is not a world, and forEachBall a callback that is not a function', () => {
    const sim = scene()
    expectRefused(sim, () => forEachBall({} as never, () => {}), TypeError, /forEachBall: world must be/)
    expectRefused(sim, () => forEachBall(sim.world, 'each' as never), TypeError, /forEachBall: fn must be a function/, /got the string "each"/)
    expectRefused(sim, () => isBall(null as never, 1), TypeError, /isBall: world must be/)
    const seen: number[] = []
    forEachBall(sim.world, (b) => void seen.push(b))
    expect(seen.length).toBeGreaterThan(0)
    expect(seen).toEqual(listBalls(sim.world))
    expect(seen.every((b) => isBall(sim.world, b))).toBe(true)
  })

  /**
   * A world with a hole at (200, 100) and walls, a ball rolling into the hole; `call` runs from a system at
   * the first event marked in a step (with the hole's and the ball's ids). Returns whether it ran, and what
   * the steps threw.
   */
  function callMidStep(w: BallWorld, call: (w: BallWorld, hole: number, ball: number) => void): { tried: boolean; error: unknown; hole: number; ball: number } {
    const hole = addHole(w, { x: 200, y: 100 })
    setWalls(w, { minX: 0, minY: 0, maxX: 420, maxY: 480 })
    const ball = addBall(w, { x: 100, y: 100, vx: 300, vy: 0 })
    const schedule = createSchedule(w.config)
    let tried = false
    schedule.splice(schedule.findIndex((e) => e.name === 'integration') + 1, 0, {
      name: 'edit',
      run: (ww) => {
        if (tried || ww.marked.count === 0) return
        tried = true
        call(ww, hole, ball)
      },
    })
    let error: unknown
    try {
      for (let i = 0; i < 60; i++) runSchedule(w, schedule, 1 / 60)
    } catch (e) {
      error = e
    }
    return { tried, error, hole, ball }
  }

  it('addHole, addHoles, removeHole, setWalls and clearWalls from a system during a step throw, naming the command, and change nothing (a hole removed at a ball\'s lip crossing gave it a skip at the step\'s end)', () => {
    const calls: Record<string, (w: BallWorld, hole: number) => void> = {
      addHole: (w) => void addHole(w, { x: 300, y: 140 }),
      addHoles: (w) => void addHoles(w, [{ x: 300, y: 140 }]),
      removeHole: (w, hole) => removeHole(w, hole),
      setWalls: (w) => setWalls(w, { minX: 0, minY: 0, maxX: 250, maxY: 300 }),
      clearWalls: (w) => clearWalls(w),
    }
    for (const [name, call] of Object.entries(calls)) {
      const w = createBallWorld()
      const r = callMidStep(w, call)
      expect(r.tried, name).toBe(true)
      expect(String(r.error), name).toMatch(new RegExp(`${name}: the world is in the middle of a step \\(called from a system\\?\\); change holes and walls between steps`))
      expect(listHoles(w), name).toEqual([r.hole])
      expect(w.walls, name).not.toBe(0)
      expect(w.Walls.maxX[w.walls], name).toBe(420)
    }
  })

  it("a game's own removeEntity of a hole or of the walls from a system ends the step in an error that says so, and the world is refused after (a ball at its lip crossing took a 'skip' at t = 1e300, and the world went on)", () => {
    for (const what of ['hole', 'walls'] as const) {
      const w = createBallWorld()
      const r = callMidStep(w, (ww, hole) => removeEntity(ww, what === 'hole' ? hole : ww.walls))
      expect(r.tried, what).toBe(true)
      const said = what === 'hole' ? `hole ${r.hole} was removed during a step` : 'the walls \\(entity \\d+\\) were removed during a step'
      expect(String(r.error), what).toMatch(new RegExp(`^Error: step \\(runSchedule\\): ${said} \\(bitECS removeEntity from a system\\?\\), which is not supported: holes and walls change between steps`))
      expect(w.failed, what).toMatch(new RegExp(`^${said}`))
      expect(() => runSchedule(w, createSchedule(w.config), 1 / 60), what).toThrow(/was ended part-done by an error/)
      // (the step's events stay drainable, as a failed step's do, and are as little to be trusted)
      expect(Array.isArray(drainEvents(w))).toBe(true)
    }
  })

  it('addBall, throwBall and setBallVelocity from a system during a step throw, naming the command (they started at the step\'s start: a ball added at a lip crossing went where the frame rate put it)', () => {
    const calls: Record<string, (w: BallWorld, hole: number, ball: number) => void> = {
      addBall: (w) => void addBall(w, { x: 100, y: 200, vx: 300, vy: 0 }),
      throwBall: (w) => void throwBall(w, { x: 100, y: 200, power: 0.5, angle: 0 }),
      setBallVelocity: (w, _hole, ball) => setBallVelocity(w, ball, 0, 300),
    }
    for (const [name, call] of Object.entries(calls)) {
      const w = createBallWorld({ BALL_COLLISIONS: 'on' })
      const r = callMidStep(w, call)
      expect(r.tried, name).toBe(true)
      expect(String(r.error), name).toMatch(new RegExp(`${name}: the world is in the middle of a step \\(called from a system\\?\\); put balls down and set their velocities between steps`))
      expect(listBalls(w), name).toEqual([r.ball])
      // the step it broke off is part-done, so that world goes no further (tests/failedStep.test.ts); in a
      // world set up the same, between steps, the same call works
      expect(w.failed, name).toMatch(new RegExp(`system 'edit' threw in pass \\d+: Error: ${name}: the world is in the middle of a step`))
      const fresh = createBallWorld({ BALL_COLLISIONS: 'on' })
      call(fresh, addHole(fresh, { x: 200, y: 100 }), addBall(fresh, { x: 100, y: 100, vx: 300, vy: 0 }))
    }
  })

  it('createSchedule refuses what is not a world\'s config, naming the field and its allowed values (it returned an empty schedule, and steps moved no ball)', () => {
    expect(() => createSchedule('x' as never)).toThrow(/createSchedule: config must be a world's config .*got the string "x"/)
    expect(() => createSchedule(null as never)).toThrow(TypeError)
    expect(() => createSchedule({} as never)).toThrow(/config\.METHOD must be one of 'exact', 'naive', 'v1', got undefined/)
    expect(() => createSchedule({ METHOD: 'bogus' } as never)).toThrow(RangeError)
    expect(() => createSchedule({ METHOD: 'naive', SUBSTEPS: 0 } as never)).toThrow(/config\.SUBSTEPS must be an integer in \[1, 64\], got 0/)
    expect(() => createSchedule({ METHOD: 'v1', SUBSTEPS: 2.5 } as never)).toThrow(RangeError)
    // a world's own configs give its schedules: the default for 'exact', SUBSTEPS copies of the group otherwise
    expect(createSchedule(createBallWorld().config).map((e) => e.name)).toEqual(createSchedule().map((e) => e.name))
    const one = createSchedule(createBallWorld({ METHOD: 'naive', SUBSTEPS: 1 }).config).length
    expect(one).toBeGreaterThan(0)
    expect(createSchedule(createBallWorld({ METHOD: 'naive', SUBSTEPS: 4 }).config)).toHaveLength(4 * one)
  })

  it('runSchedule and sim.step refuse a schedule entry that is not { name, run } with name a string and run a function, naming the entry; the world is unchanged', () => {
    const sim = scene()
    const good = sim.schedule[0]!
    const cases: [unknown[], RegExp, string][] = [
      [[null], /schedule\[0\]/, 'got null'],
      [[good, { name: 'mine', run: 5 }], /schedule\[1\]/, 'got an object'],
      [[good, good, 'integration'], /schedule\[2\]/, 'got the string "integration"'],
      [[{ name: 'no run' }], /schedule\[0\]/, 'run is a function'],
      [[good, { run: () => {} }], /schedule\[1\]/, 'name is a string'],
      [[{ name: 7, run: () => {} }], /schedule\[0\]/, 'name is a string'],
    ]
    for (const [bad, which, got] of cases) {
      expectRefused(sim, () => runSchedule(sim.world, bad as never, 1 / 60), TypeError, which, got)
      const kept = sim.schedule.splice(0, sim.schedule.length, ...(bad as never[]))
      expectRefused(sim, () => sim.step(1 / 60), TypeError, which)
      sim.schedule.splice(0, sim.schedule.length, ...kept)
    }
  })

  it('a step run from inside a system throws; the outer step completes exactly as without the attempt', () => {
    const tried = scene()
    const twin = scene()
    const errors: unknown[] = []
    tried.schedule.push({
      name: 'nested',
      run: (w) => {
        for (const attempt of [() => tried.step(0.01), () => runSchedule(w, tried.schedule, 0.01), () => runSchedule(w, createSchedule(), 1 / 60)]) {
          try {
            attempt()
          } catch (e) {
            errors.push(e)
          }
        }
      },
    })
    twin.schedule.push({ name: 'nothing', run: () => {} })
    const t0 = tried.time
    expect(tried.step(1 / 60)).toBe(1 / 60)
    twin.step(1 / 60)
    expect(errors.length).toBeGreaterThanOrEqual(3)
    for (const e of errors) expect((e as Error).message).toMatch(/already stepping/)
    expect(tried.time).toBe(t0 + 1 / 60)
    expect(tried.world.stepping).toBe(false)
    expect(snapshot(tried.world)).toBe(snapshot(twin.world))
    expect(tried.drainEvents()).toEqual(twin.drainEvents())
  })

  it('a nested step left uncaught fails the outer step, and the world then refuses to go on, naming it', () => {
    const sim = scene()
    let armed = true
    sim.schedule.push({ name: 'nested', run: () => void (armed && sim.step(0.01)) })
    expect(() => sim.step(1 / 60)).toThrow(/already stepping/)
    expect(sim.world.stepping).toBe(false)
    armed = false
    const t = sim.time
    expect(() => sim.step(1 / 60)).toThrow(/part-done by an error \(system 'nested' threw in pass 0: Error: step \(runSchedule\): the world is already stepping/)
    expect(sim.time).toBe(t)
  })

  it('a system called outside a step (a game running the systems itself) throws, naming the system, and changes nothing', () => {
    for (const method of ['exact', 'naive', 'v1'] as const) {
      for (const contacts of method === 'exact' ? (['off', 'on', 'fixed'] as const) : (['off'] as const)) {
        const sim = createBallPhysics({ METHOD: method, BALL_COLLISIONS: contacts })
        addPanel(sim)
        sim.throwBall({ x: DEFAULT_PANEL.launch.x, y: DEFAULT_PANEL.launch.y, power: 0.5, angle: 0.1 })
        sim.step(1 / 60)
        for (const entry of createSchedule(sim.world.config)) {
          expectRefused(sim, () => entry.run(sim.world), Error, `${entry.run.name}: a system runs inside a step`, 'runSchedule(world, schedule, dt)')
          // given what is not a ball world (a bitECS world of the game's own, say), it says that instead
          expect(() => entry.run({ components: [] } as unknown as typeof sim.world)).toThrow(new TypeError(`${entry.run.name}: world must be a world made by createBallWorld, got an object that is not one`))
        }
        // the same systems in a schedule step as ever
        expect(() => sim.step(1 / 60)).not.toThrow()
      }
    }
  })
})

describe('addPanel is all or nothing', () => {
  const layout = (holes: unknown[]): PanelLayout => ({ ...DEFAULT_PANEL, holes: holes as PanelLayout['holes'] })
  const [h0, h1, h2, h3] = DEFAULT_PANEL.holes as PanelLayout['holes']

  it('a bad third hole (x NaN, x a string) adds none', () => {
    const sim = createBallPhysics()
    expectRefused(sim, () => addPanel(sim, layout([h0, h1, { x: NaN, y: 10, value: 5 }, h3])), RangeError, /holes\[2\]\.x/, /got NaN/)
    expectRefused(sim, () => addPanel(sim, layout([h0, h1, { x: '5', y: 10, value: 5 }, h3])), TypeError, /holes\[2\]\.x/, /the string "5"/)
    expect(listHoles(sim.world)).toEqual([])
  })

  it('a third hole overlapping an earlier one, or two neighbours overlapping, adds none', () => {
    const sim = createBallPhysics()
    expectRefused(sim, () => addPanel(sim, layout([h0, h1, { x: h0!.x + 10, y: h0!.y, value: 1 }, h3])), RangeError, /holes\[2\].*overlaps holes\[0\]/)
    expectRefused(sim, () => addPanel(sim, layout([h0, h1, h2, { x: h2!.x + 20, y: h2!.y + 20, value: 1 }])), RangeError, /holes\[3\].*overlaps holes\[2\]/)
    expect(listHoles(sim.world)).toEqual([])
    addPanel(sim, layout([h0, h1, h2, h3]))
    expect(listHoles(sim.world)).toHaveLength(4)
  })

  it("a layout overlapping the world's holes adds none", () => {
    const sim = createBallPhysics()
    sim.addHole({ x: h2!.x + 3, y: h2!.y - 3 })
    expectRefused(sim, () => addPanel(sim), RangeError, /overlaps hole/)
    expect(listHoles(sim.world)).toHaveLength(1)
  })

  it('a hole that is not an object is a TypeError naming its index, and adds none', () => {
    const sim = createBallPhysics()
    expectRefused(sim, () => addPanel(sim, layout([h0, h1, null, h3])), TypeError, /holes\[2\]/)
    // a target that is not a world made by createBallWorld is refused in addPanel's name
    expect(() => addPanel({} as never)).toThrow(/^addPanel: world must be a world made by createBallWorld/)
  })
})

describe('a non-number where a number goes', () => {
  const values: [string, () => unknown, RegExp][] = [
    ['a symbol', () => Symbol(), /symbol/],
    ['a string', () => '5', /the string "5"/],
    ['null', () => null, /got null/],
    ['a bigint', () => 10n, /bigint/],
  ]
  const entries: [string, string, (sim: BallPhysics, v: unknown) => unknown][] = [
    ['addBall x', 'ball.x', (s, v) => s.addBall({ x: v as number, y: 0, vx: 0, vy: 0 })],
    ['throwBall power', 'throw.power', (s, v) => s.throwBall({ x: 0, y: 0, power: v as number, angle: 0 })],
    ['setWalls restitution', 'walls.restitution', (s, v) => s.setWalls({ minX: 0, minY: 0, maxX: 10, maxY: 10, restitution: v as number })],
    ['setBallVelocity vx', 'vx', (s, v) => s.setBallVelocity(s.balls()[0]!, v as number, 0)],
  ]
  for (const [what, field, call] of entries) {
    for (const [kind, value, says] of values) {
      it(`${what} = ${kind}: a TypeError naming ${field} and what it got`, () => {
        const sim = scene()
        expectRefused(sim, () => call(sim, value()), TypeError, field, says)
      })
    }
  }

  for (const [kind, value, says] of values) {
    it(`config ROLLING_DECEL = ${kind}: a TypeError naming the key and what it got`, () => {
      for (const make of [createBallPhysics, createBallWorld]) {
        let caught: unknown = null
        try {
          make({ ROLLING_DECEL: value() as number })
        } catch (e) {
          caught = e
        }
        expect(caught).toBeInstanceOf(TypeError)
        expect((caught as Error).message).toMatch(/config\.ROLLING_DECEL/)
        expect((caught as Error).message).toMatch(says)
        expect((caught as Error).message).not.toMatch(/Cannot convert/)
      }
    })
  }

  it("setWalls({ restitution: '0.5' }) says it got the string \"0.5\"", () => {
    const sim = scene()
    expectRefused(sim, () => sim.setWalls({ minX: 0, minY: 0, maxX: 10, maxY: 10, restitution: '0.5' as never }), TypeError, 'got the string "0.5"')
  })
})

describe('setWalls open', () => {
  const walls = { minX: 0, minY: 0, maxX: 420, maxY: 480 }
  const cases: [string, unknown, ErrorConstructor, RegExp][] = [
    ["{ left: 'false' }", { left: 'false' }, TypeError, /walls\.open\.left must be a boolean, got the string "false"/],
    ["{ bottom: 'no' }", { bottom: 'no' }, TypeError, /walls\.open\.bottom/],
    ['{ botom: true }', { botom: true }, RangeError, /walls\.open\.botom is not an edge/],
    ['[]', [], TypeError, /walls\.open must be an object/],
    ['1', 1, TypeError, /walls\.open/],
  ]
  for (const [name, open, type, message] of cases) {
    it(`open: ${name} is refused`, () => {
      const sim = scene()
      expectRefused(sim, () => sim.setWalls({ ...walls, minX: 5, open: open as never }), type, message)
    })
  }

  it('a valid { bottom: true } works: the bottom is open, the others closed', () => {
    const sim = createBallPhysics()
    sim.setWalls({ ...walls, open: { bottom: true } })
    expect(sim.world.Walls.open[sim.world.walls]).toBe(8)
    const b = sim.addBall({ x: 100, y: 400, vx: 0, vy: 500 })
    const c = sim.addBall({ x: 300, y: 100, vx: 0, vy: -500 })
    for (let i = 0; i < 120; i++) sim.step(1 / 60)
    const ev = sim.drainEvents()
    expect(ev.filter((e) => e.ball === b).map((e) => e.type)).toEqual(['gutter'])
    expect(sim.ballState(b).mode).toBe('out')
    expect(ev.filter((e) => e.ball === c).map((e) => e.type)).toContain('wall')
  })
})

describe('overrides and ids', () => {
  it('createBallPhysics([]), createBallWorld([]) and createBallPhysics(null) are refused', () => {
    expect(() => createBallPhysics([] as never)).toThrow(TypeError)
    expect(() => createBallPhysics([] as never)).toThrow(/got an array/)
    expect(() => createBallWorld([] as never)).toThrow(/got an array/)
    expect(() => createBallPhysics(null as never)).toThrow(/got null/)
    expect(() => createBallWorld(null as never)).toThrow(TypeError)
  })

  it("ballState('27') says it got the string \"27\"; removed and unknown ids are RangeErrors saying so", () => {
    const sim = scene()
    const b = sim.balls()[1]!
    expectRefused(sim, () => sim.ballState('27' as never), TypeError, 'got the string "27"')
    sim.removeBall(b)
    expectRefused(sim, () => sim.ballState(b), RangeError, `ball ${b} is not a live ball`, /unknown or removed/)
    expectRefused(sim, () => sim.ballState(99999), RangeError, 'ball 99999 is not a live ball', /unknown or removed/)
  })
})

describe('each field of a spec is read exactly once', () => {
  /** A getter that gives `first` once and NaN after, counting its reads. */
  function once(first: number) {
    const count = { reads: 0 }
    return {
      count,
      get: () => {
        count.reads++
        return count.reads === 1 ? first : NaN
      },
    }
  }
  function expectFinite(w: BallWorld): void {
    for (const store of [w.Ball, w.Path, w.Hole, w.RimContact, w.Walls]) {
      for (const [k, arr] of Object.entries(store) as [string, Float64Array][]) {
        for (let i = 0; i < arr.length; i++) if (!Number.isFinite(arr[i]!)) expect.fail(`${k}[${i}] = ${arr[i]}`)
      }
    }
  }
  const tenSteps = (sim: BallPhysics) => {
    for (let i = 0; i < 10; i++) sim.step(1 / 60)
  }

  it('throwBall power', () => {
    const sim = scene()
    const p = once(0.5)
    const b = sim.throwBall({ x: 210, y: 450, angle: 0, get power() { return p.get() } })
    expect(p.count.reads).toBe(1)
    expect(sim.world.pathHot[b * HOT + H_V0]).toBe(sim.config.MIN_VY + 0.5 * (sim.config.MAX_VY - sim.config.MIN_VY))
    tenSteps(sim)
    expectFinite(sim.world)
  })

  it('addBall x and vx', () => {
    const sim = scene()
    const x = once(100)
    const vx = once(200)
    const b = sim.addBall({ y: 300, vy: 0, get x() { return x.get() }, get vx() { return vx.get() } })
    expect([x.count.reads, vx.count.reads]).toEqual([1, 1])
    expect(sim.ballState(b)).toMatchObject({ x: 100, vx: 200 })
    tenSteps(sim)
    expectFinite(sim.world)
  })

  it('addHole x', () => {
    const sim = scene()
    const x = once(1000)
    const h = sim.addHole({ y: 1000, get x() { return x.get() } })
    expect(x.count.reads).toBe(1)
    expect(sim.holeState(h).x).toBe(1000)
    sim.addBall({ x: 940, y: 1000, vx: 300, vy: 0 })
    tenSteps(sim)
    expectFinite(sim.world)
  })

  it('setWalls minX', () => {
    const sim = scene()
    const minX = once(0)
    sim.setWalls({ minY: 0, maxX: 420, maxY: 480, get minX() { return minX.get() } })
    expect(minX.count.reads).toBe(1)
    expect(sim.world.Walls.minX[sim.world.walls]).toBe(0)
    sim.addBall({ x: 100, y: 100, vx: -600, vy: 0 })
    tenSteps(sim)
    expectFinite(sim.world)
  })

  it('config overrides (a getter on ROLLING_DECEL), through createBallPhysics and createBallWorld', () => {
    for (const make of [(o: object) => createBallPhysics(o).world, (o: object) => createBallWorld(o)]) {
      const d = once(250)
      const w = make({ get ROLLING_DECEL() { return d.get() } })
      expect(d.count.reads).toBe(1)
      expect(w.config.ROLLING_DECEL).toBe(250)
      addPanel(w)
      throwBall(w, { x: 210, y: 450, power: 0.5, angle: 0.2 })
      const schedule = createSchedule(w.config)
      for (let i = 0; i < 10; i++) runSchedule(w, schedule, 1 / 60)
      expectFinite(w)
    }
  })
})
