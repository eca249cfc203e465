// Every public input object refuses a key it does not know (a misspelt optional field would otherwise be
// ignored), with an error that names the key and lists the known ones, and leaves the world as it was.
import { describe, expect, it } from 'vitest'
import {
  DEFAULT_PANEL,
  TABULATED_CONFIG,
  addPanel,
  createBallPhysics,
  createFixedStepClock,
  createReplayPlayer,
  outcomeMap,
  prepareRimTable,
  sampleThrows,
  solveThrow,
  type BallPhysics,
  type OutcomeScene,
  type Replay,
} from '../src/index'
import { addBall, addHole, addHoles, createBallWorld, forEachBall, isBall, listBalls, listHoles, playReplay, setWalls, throwBall } from '../src/ecs'
import { brentRoot, createDopri5Workspace, dopri5, lipEnergy, referenceOutcome, referenceTrace, rollOnLip, singleImpactEscapes, validateReferenceInput } from '../src/reference/index'

/** What a refused call could have touched. */
function state(sim: BallPhysics): string {
  const w = sim.world
  return JSON.stringify([w.time, listBalls(w), listHoles(w), w.walls, w.events.count, w.entityIndex.maxId, Array.from(w.Walls.minX.subarray(0, 8))])
}

function scene(): BallPhysics {
  const sim = createBallPhysics()
  addPanel(sim)
  sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480 })
  sim.throwBall({ x: 210, y: 450, power: 0.5, angle: 0.1 })
  sim.step(1 / 60)
  return sim
}

/** Calls `call`, expects an error naming `field.key` and listing `known`; the world is unchanged. */
function refuses(sim: BallPhysics | null, call: () => unknown, field: string, known: string[]): void {
  const before = sim === null ? '' : state(sim)
  let caught: unknown = null
  try {
    call()
  } catch (e) {
    caught = e
  }
  expect(caught, `${field} was accepted`).toBeInstanceOf(Error)
  const message = (caught as Error).message
  expect(message).toContain(`${field} is not a known key`)
  expect(message).toContain(`known keys: ${known.join(', ')}`)
  if (sim !== null) expect(state(sim)).toBe(before)
}

const BALL = ['x', 'y', 'vx', 'vy', 'radius', 'hero', 'mass']
const THROW = ['x', 'y', 'power', 'angle', 'radius', 'hero', 'mass']
const HOLE = ['x', 'y', 'radius', 'value']
const WALLS = ['minX', 'minY', 'maxX', 'maxY', 'restitution', 'open']

describe('unknown keys in command inputs', () => {
  it('addBall, throwBall (sim and ecs) refuse a misspelt key', () => {
    const sim = scene()
    refuses(sim, () => sim.addBall({ x: 1, y: 2, vx: 0, vy: 0, radious: 4 } as never), 'ball.radious', BALL)
    refuses(sim, () => sim.throwBall({ x: 210, y: 450, power: 0.5, angle: 0, hro: true } as never), 'throw.hro', THROW)
    refuses(sim, () => throwBall(sim.world, { x: 210, y: 450, power: 0.5, angle: 0, Mass: 2 } as never), 'throw.Mass', THROW)
  })

  it('addHole, addHoles and addPanel refuse a hole spec with an unknown key, adding none', () => {
    const sim = scene()
    refuses(sim, () => sim.addHole({ x: 30, y: 30, radus: 5 } as never), 'hole.radus', HOLE)
    refuses(sim, () => addHole(sim.world, { x: 30, y: 30, points: 5 } as never), 'hole.points', HOLE)
    refuses(sim, () => addHoles(sim.world, [{ x: 30, y: 30 }, { x: 30, y: 90, vaule: 3 } as never]), 'holes[1].vaule', HOLE)
    const fresh = createBallPhysics()
    const layout = { ...DEFAULT_PANEL, holes: [...DEFAULT_PANEL.holes, { x: 5, y: 5, value: 1, r: 3 }] }
    refuses(fresh, () => addPanel(fresh, layout as never), 'holes[25].r', HOLE)
    refuses(fresh, () => addPanel(fresh, { ...DEFAULT_PANEL, lanch: { x: 0, y: 0 } } as never), 'layout.lanch', ['width', 'height', 'launch', 'holes'])
  })

  it('setWalls refuses an unknown key (and open an unknown edge)', () => {
    const sim = scene()
    refuses(sim, () => sim.setWalls({ minX: 5, minY: 0, maxX: 420, maxY: 480, restitutoin: 1 } as never), 'walls.restitutoin', WALLS)
    refuses(sim, () => setWalls(sim.world, { minX: 5, minY: 0, maxX: 420, maxY: 480, max: 3 } as never), 'walls.max', WALLS)
    expect(() => sim.setWalls({ minX: 5, minY: 0, maxX: 420, maxY: 480, open: { botom: true } as never })).toThrow(/walls\.open\.botom is not an edge/)
  })

  it('createBallPhysics / createBallWorld options, and the config, refuse unknown keys', () => {
    refuses(null, () => createBallPhysics({}, { broadfase: 'grid' } as never), 'options.broadfase', ['capacity', 'broadphase'])
    refuses(null, () => createBallWorld({}, { Capacity: 10 } as never), 'options.Capacity', ['capacity', 'broadphase'])
    expect(() => createBallPhysics({ rolling_decel: 1 } as never)).toThrow(/config\.rolling_decel is not a known key/)
  })

  it('createFixedStepClock refuses { Hz: 60 }', () => {
    refuses(null, () => createFixedStepClock({ Hz: 60 } as never), 'options.Hz', ['hz', 'maxStepsPerFrame'])
  })

  it('solveThrow refuses an unknown key in the request and in request.from', () => {
    const sim = scene()
    const hole = sim.holes()[0]!
    refuses(sim, () => solveThrow(sim, { from: DEFAULT_PANEL.launch, hole, outcom: 'skip' } as never), 'solveThrow request.outcom', ['from', 'hole', 'outcome', 'along'])
    refuses(sim, () => solveThrow(sim, { from: { x: 210, y: 450, z: 0 } as never, hole }), 'request.from.z', ['x', 'y'])
  })

  it('prepareRimTable refuses an unknown option', () => {
    const sim = scene()
    refuses(sim, () => prepareRimTable(sim, 18, 11, { intertia: 0.4 } as never), 'options.intertia', ['inertia', 'rows'])
  })

  it('sampleThrows and outcomeMap refuse unknown keys in the scene, the distribution and the map spec', () => {
    const good: OutcomeScene = { holes: DEFAULT_PANEL.holes }
    const dist = { power: { mean: 0.5 }, angle: { mean: 0 }, from: { x: 210, y: 450 } }
    refuses(null, () => sampleThrows({ ...good, wall: {} } as never, dist, 1, 1), 'scene.wall', ['config', 'holes', 'walls'])
    refuses(null, () => sampleThrows(good, { ...dist, power: { mean: 0.5, sigma: 0.1 } } as never, 1, 1), 'distribution.power.sigma', ['mean', 'sd'])
    refuses(null, () => sampleThrows(good, { ...dist, from: { x: 210, y: 450, sdx: 3 } } as never, 1, 1), 'distribution.from.sdx', ['x', 'y', 'sdX', 'sdY'])
    refuses(null, () => sampleThrows(good, { ...dist, aim: 0 } as never, 1, 1), 'distribution.aim', ['power', 'angle', 'from'])
    const spec = { from: { x: 210, y: 450 }, power: { min: 0, max: 1, steps: 2 }, angle: { min: 0, max: 0, steps: 1 } }
    refuses(null, () => outcomeMap({ ...good, confg: {} } as never, spec), 'scene.confg', ['config', 'holes', 'walls'])
    refuses(null, () => outcomeMap(good, { ...spec, angle: { min: 0, max: 0, step: 1 } } as never), 'spec.angle.step', ['min', 'max', 'steps'])
    refuses(null, () => outcomeMap(good, spec, { from: 0, until: 1 } as never), 'rows.until', ['from', 'to'])
    // the scene's holes and walls are checked by the commands that add them
    refuses(null, () => sampleThrows({ holes: [{ x: 1, y: 1, r: 2 }] } as never, dist, 1, 1), 'hole.r', HOLE)
    refuses(null, () => outcomeMap({ ...good, walls: { minX: 0, minY: 0, maxX: 420, maxY: 480, e: 1 } } as never, spec), 'walls.e', WALLS)
  })

  it('replays refuse unknown keys at the top and in their inputs', () => {
    const sim = createBallPhysics()
    sim.startRecording()
    sim.addHole({ x: 100, y: 100 })
    sim.step(1 / 60)
    const replay = sim.stopRecording()
    refuses(null, () => createReplayPlayer({ ...replay, extra: 1 } as never), 'replay.extra', ['format', 'version', 'config', 'options', 'start', 'inputs'])
    refuses(null, () => playReplay({ ...replay, options: { ...replay.options, size: 1 } } as Replay), 'options.size', ['capacity', 'broadphase'])
    const inputs = replay.inputs.map((i) => (i[0] === 'addHole' ? ['addHole', { ...(i[1] as object), depth: 1 }] : i)) as Replay['inputs']
    expect(() => createReplayPlayer({ ...replay, inputs }).next()).toThrow(/replay input 0 \("addHole"\): hole\.depth is not a known key/)
  })

  it('the reference refuses an unknown key in its input', () => {
    const input = { delta: 1, speed: 300, holeRadius: 18, ballRadius: 11, gravity: 6953, inertia: 0.4 }
    const known = ['delta', 'speed', 'holeRadius', 'ballRadius', 'gravity', 'inertia']
    refuses(null, () => referenceOutcome({ ...input, j: 0.4 } as never), 'input.j', known)
    refuses(null, () => referenceTrace({ ...input, g: 1 } as never), 'input.g', known)
    refuses(null, () => validateReferenceInput({ ...input, mass: 1 } as never), 'input.mass', known)
  })

  it('a spec with every known key still works, and inherited or symbol keys are not own string keys', () => {
    const sim = createBallPhysics({ BALL_COLLISIONS: 'on' })
    expect(() => sim.addBall({ x: 1, y: 2, vx: 0, vy: 0, radius: 4, hero: false, mass: 1 })).not.toThrow()
    const proto = { x: 50, y: 50 }
    expect(() => sim.addHole(Object.assign(Object.create(proto) as object, { radius: 10 }) as never)).not.toThrow()
    expect(() => sim.throwBall({ x: 200, y: 450, power: 0.3, angle: 0, [Symbol('tag')]: 1 } as never)).not.toThrow()
  })
})

describe('an optional field given as undefined is as if it were absent (the types allow it: tests/package)', () => {
  /** A scene run with every optional field absent, or given as undefined: the same bits. */
  function run(u: boolean): string {
    const none = u ? undefined : (Symbol('absent') as never)
    const opt = <T extends object>(o: T): T => (u ? o : (Object.fromEntries(Object.entries(o).filter(([, v]) => v !== none)) as T))
    const sim = createBallPhysics(opt({ ROLLING_DECEL: none, GRAVITY: none, V_SKIP_MAX: none, METHOD: none }), opt({ capacity: none, broadphase: none }))
    const w = createBallWorld(opt({ CAPTURE_WINDOW: none }), opt({ capacity: none }))
    const hole = sim.addHole(opt({ x: 210, y: 300, radius: none, value: none }))
    addHoles(w, [opt({ x: 10, y: 10, radius: none, value: none })])
    sim.setWalls(opt({ minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: none, open: none }))
    sim.setWalls(opt({ minX: 0, minY: 0, maxX: 420, maxY: 480, open: opt({ bottom: true, left: none }) }))
    sim.addBall(opt({ x: 100, y: 100, vx: 50, vy: 0, radius: none, hero: none, mass: none }))
    sim.throwBall(opt({ x: 210, y: 450, power: 0.4, angle: 0, radius: none, hero: none, mass: none }))
    const clock = createFixedStepClock(opt({ hz: none, maxStepsPerFrame: none }))
    clock.advance(0.1, (dt) => sim.step(dt))
    const shot = solveThrow(sim, opt({ from: { x: 210, y: 450 }, hole, along: none, outcome: none }))
    prepareRimTable(createBallPhysics(TABULATED_CONFIG), 18, 11, opt({ inertia: none, rows: none }))
    const scene = opt({ config: none, holes: [{ x: 210, y: 300 }], walls: none })
    const tally = sampleThrows(scene, { power: opt({ mean: 0.4, sd: none }), angle: opt({ mean: 0, sd: none }), from: opt({ x: 210, y: 450, sdX: none, sdY: none }) }, 20, 1)
    return JSON.stringify([sim.config, w.config, sim.snapshot().join(), shot, tally, clock.steps, clock.stepSeconds])
  }

  it('addBall, throwBall, addHole(s), setWalls (and open), the config and options, the clock, solveThrow, prepareRimTable, sampleThrows', () => {
    expect(run(true)).toBe(run(false))
  })
})

describe('error messages say what was wrong, in the caller\'s terms', () => {
  it("createFixedStepClock({ hz: '60' }) is a TypeError saying it got a string; advance('1') too", () => {
    expect(() => createFixedStepClock({ hz: '60' as never })).toThrow(TypeError)
    expect(() => createFixedStepClock({ hz: '60' as never })).toThrow('hz must be a number in [0.1, 10000], got the string "60"')
    expect(() => createFixedStepClock({ maxStepsPerFrame: '8' as never })).toThrow(TypeError)
    expect(() => createFixedStepClock({ hz: 0 })).toThrow(RangeError)
    // a subnormal rate passed a check of hz > 0 and gave a step of Infinity: a clock that never stepped
    expect(() => createFixedStepClock({ hz: 1e-320 })).toThrow('hz must be in [0.1, 10000], got 1e-320')
    expect(createFixedStepClock({ hz: 0.1 }).stepSeconds).toBe(10)
    expect(() => createFixedStepClock().advance('1' as never, () => {})).toThrow(/frameSeconds must be a finite number ≥ 0, got the string "1"/)
  })

  it('the reference says what it got, and refuses null inputs and lip states with a clear TypeError', () => {
    const input = { delta: 1, speed: 300, holeRadius: 18, ballRadius: 11, gravity: 6953, inertia: 0.4 }
    expect(() => referenceOutcome({ ...input, speed: '300' as never })).toThrow(TypeError)
    expect(() => referenceOutcome({ ...input, speed: '300' as never })).toThrow('speed must be a finite number, got the string "300"')
    expect(() => referenceOutcome({ ...input, speed: -1 })).toThrow('speed must be in (0, 1000000000000·√(gravity·ballRadius)] = (0, 276555600196416.22], got -1')
    expect(() => referenceOutcome({ ...input, ballRadius: 20 })).toThrow('ballRadius must be in [holeRadius / 100000000, holeRadius) = [1.8e-7, 18), got 20')
    expect(() => referenceOutcome(null as never)).toThrow(new TypeError('reference input must be an object, got null'))
    expect(() => referenceTrace(undefined as never)).toThrow('reference input must be an object, got undefined')
    const start = { psi: 0, theta: 0.1, psiDot: 1, thetaDot: 0, omegaN: 0 }
    expect(() => rollOnLip(null as never, 0.1, 18, 11, 6953, 0.4)).toThrow(new TypeError('start must be an object, got null'))
    expect(() => rollOnLip({ ...start, theta: 'x' as never }, 0.1, 18, 11, 6953, 0.4)).toThrow('start.theta must be a finite number, got the string "x"')
    expect(() => rollOnLip(start, '1' as never, 18, 11, 6953, 0.4)).toThrow(TypeError)
    expect(() => lipEnergy(null as never, 18, 11, 6953, 0.4)).toThrow('start must be an object, got null')
    expect(rollOnLip(start, 0.01, 18, 11, 6953, 0.4).state.psi).toBeGreaterThan(0)
    // the geometry of lipEnergy; a roll too long for the integrator's steps is a RangeError naming duration
    expect(() => lipEnergy(start, Number.NaN, 11, 6953, 0.4)).toThrow('holeRadius must be a finite number, got NaN')
    expect(() => lipEnergy(start, 18, 11, Number.POSITIVE_INFINITY, 0.4)).toThrow(RangeError)
    expect(Number.isFinite(lipEnergy(start, 18, 11, 6953, 0.4))).toBe(true)
    expect(() => rollOnLip(start, 1e9, 18, 11, 6953, 0.4)).toThrow(/rollOnLip: duration 1000000000 is too long/)
  })

  it('the reference\'s numerical tools check their arguments: no NaN passes for a root, no integration runs without end', () => {
    const f = (x: number): number => x - 0.3
    expect(brentRoot(f, 0, 1, -0.3, 0.7, 1e-12, 1)).toBeCloseTo(0.3, 11)
    expect(() => brentRoot(f, 0, 1, Number.NaN, 0.7, 1e-12, 1)).toThrow('fa must be a finite number, got NaN')
    expect(() => brentRoot(f, 0, 1, -0.3, 0.7, Number.NaN, 1)).toThrow('xtol must be a finite number > 0, got NaN')
    expect(() => brentRoot('f' as never, 0, 1, -0.3, 0.7, 1e-12, 1)).toThrow(TypeError)
    const ws = createDopri5Workspace(1)
    const decay = (_t: number, y: Float64Array, dy: Float64Array): void => {
      dy[0] = -y[0]!
    }
    const y = new Float64Array([1])
    expect(dopri5(ws, decay, 0, y, 1, { rtol: 1e-9, atol: 1e-12 }).status).toBe('reachedEnd')
    expect(y[0]).toBeCloseTo(Math.exp(-1), 8)
    expect(() => dopri5(ws, decay, 0, new Float64Array([Number.NaN]), 1, { rtol: 1e-9, atol: 1e-12, maxSteps: 1e12 })).toThrow('y[0] must be a finite number, got NaN')
    expect(() => dopri5(ws, decay, 0, y, 1, { rtol: 1e-9, atol: 1e-12, maxSteps: Number.POSITIVE_INFINITY })).toThrow(/opts\.maxSteps must be an integer in \[1, 1000000000\]/)
    expect(() => dopri5(ws, decay, 0, y, 1, { rtol: '1e-9' as never, atol: 1e-12 })).toThrow(TypeError)
    expect(() => dopri5(ws, decay, 0, y, 1, { rtol: 1e-9, atol: 1e-12, hMax: Number.NaN })).toThrow('opts.hMax must be a finite number > 0, got NaN')
    expect(() => dopri5(ws, decay, 0, y, 1, { rtol: 1e-9, atol: 1e-12, tol: 1 } as never)).toThrow(/opts\.tol is not a known key/)
    // dead centre at the design's geometry: captured well below its limit (v/√(g·r) about 2.4), out well above
    expect(singleImpactEscapes(1, 18 / 11, 0.4)).toBe(false)
    expect(singleImpactEscapes(10, 18 / 11, 0.4)).toBe(true)
    expect(() => singleImpactEscapes('3' as never, 18 / 11, 0.4)).toThrow(TypeError)
    expect(() => singleImpactEscapes(Number.NaN, 18 / 11, 0.4)).toThrow(/vs must be in/)
    expect(() => singleImpactEscapes(3, -1, 0.4)).toThrow(/rs \(R\/r\) must be in \(1, 100000000\]/)
  })

  it('stopRecording when not recording names the sim methods; startRecording while recording is refused, the recording kept', () => {
    const sim = createBallPhysics()
    expect(() => sim.stopRecording()).toThrow('stopRecording: the simulation is not recording; call startRecording first')
    sim.startRecording()
    sim.addHole({ x: 10, y: 10 })
    expect(() => sim.startRecording()).toThrow(/startRecording: the simulation is already recording; call stopRecording first/)
    sim.step(1 / 60)
    expect(sim.stopRecording().inputs.map((i) => i[0])).toEqual(['addHole', 'step'])
    expect(() => sim.stopRecording()).toThrow(/not recording/)
  })

  it('a ball id given as a hole, or a hole id as a ball, says which it is', () => {
    const sim = scene()
    const ball = sim.balls()[0]!
    const hole = sim.holes()[0]!
    const before = state(sim)
    expect(() => sim.removeHole(ball)).toThrow(new RangeError(`hole ${ball} is not a live hole of this world: it is a ball`))
    expect(() => sim.holeState(ball)).toThrow(/is not a live hole of this world: it is a ball/)
    expect(() => sim.removeBall(hole)).toThrow(new RangeError(`ball ${hole} is not a live ball of this world: it is a hole`))
    expect(() => sim.removeHole(99999)).toThrow(/not a live hole of this world \(unknown or removed\)/)
    expect(state(sim)).toBe(before)
  })
})

describe('a world deleted by bitECS deleteWorld (not supported)', () => {
  it('every sim method that reaches the world, and the ecs entry\'s forEachBall and isBall, then throw a clear error instead of a bitECS internal one or a stale answer', async () => {
    const { deleteWorld } = await import('bitecs')
    const sim = scene()
    const ball = sim.balls()[0]!
    deleteWorld(sim.world)
    const calls: [string, () => unknown][] = [
      ['runSchedule', () => sim.step(1 / 60)],
      ['addBall', () => sim.addBall({ x: 0, y: 0, vx: 0, vy: 0 })],
      ['removeBall', () => sim.removeBall(ball)],
      ['addHole', () => sim.addHole({ x: 0, y: 0 })],
      ['drainEvents', () => sim.drainEvents()],
      ['snapshotWorld', () => sim.snapshot()],
      ['setWalls', () => sim.setWalls({ minX: 0, minY: 0, maxX: 1, maxY: 1 })],
      // the ecs entry's readers too: they would read the stores of a world bitECS no longer knows
      ['forEachBall', () => forEachBall(sim.world, () => {})],
      ['isBall', () => isBall(sim.world, ball)],
    ]
    for (const [name, call] of calls) expect(call).toThrow(`${name}: this is not a live world: it was deleted (bitECS deleteWorld), which is not supported (make a new one), or it is a copy of one`)
  })

  it('a copy of a world ({ ...world }) is refused as not live, with both causes named', () => {
    const sim = scene()
    const copy = { ...sim.world }
    expect(() => addBall(copy, { x: 0, y: 0 })).toThrow(/^addBall: this is not a live world: .* or it is a copy of one \(such as \{ \.\.\.world \}\), which has the stores but not bitECS's entities \(pass the world createBallWorld returned\)$/)
    expect(sim.balls().length).toBeGreaterThan(0)
  })
})

describe('a world reset by bitECS resetWorld (not supported)', () => {
  it('every command then throws a clear error, instead of simulating balls bitECS forgot and handing their ids out again', async () => {
    const { resetWorld, addEntity } = await import('bitecs')
    const sim = scene()
    const ball = sim.balls()[0]!
    resetWorld(sim.world)
    addEntity(sim.world) // bitECS hands out id 1 again: a hole's id in the simulation's stores
    const calls: [string, () => unknown][] = [
      ['runSchedule', () => sim.step(1 / 60)],
      ['addBall', () => sim.addBall({ x: 0, y: 0, vx: 0, vy: 0 })],
      ['throwBall', () => sim.throwBall({ x: 210, y: 450, power: 0.5, angle: 0 })],
      ['removeBall', () => sim.removeBall(ball)],
      ['addHole', () => sim.addHole({ x: 0, y: 0 })],
      ['drainEvents', () => sim.drainEvents()],
      ['snapshotWorld', () => sim.snapshot()],
      ['forEachBall', () => forEachBall(sim.world, () => {})],
      ['isBall', () => isBall(sim.world, ball)],
    ]
    for (const [name, call] of calls) expect(call).toThrow(`${name}: the world was reset (bitECS resetWorld), which is not supported`)
  })
})
