// Ball-ball contacts under load, side by side in one run: this module's two contact methods (exact
// event-driven 'on', fixed-tick 'fixed') against rapier2d-compat, matter-js and planck, on two scenes:
//   gas:   a walled square, balls at area fraction 0.2, restitution 0.9 (balls and walls), no holes, no
//          rolling deceleration, 150–350 px/s in random directions;
//   panel: the multi-ball panel: tiles of the default 5 × 5 panel side by side in one walled field (bottom
//          open), 40 balls a tile thrown up the panel at once from a launch band (powers 0.2–0.9, aims
//          ±0.4 rad), the design's deceleration; the peers' holes are sensors that take a ball slower than
//          V_MAX, their deceleration is linear damping.
// Every ball is put down apart from the others (no engine starts by pushing overlaps apart). Each engine
// steps at dt = 1/120 s under tinybench: the mean and the worst step of MEASURED_STEPS steps of a fresh
// scene (the mean: the whole run's time over its steps; the panel's bursts fall from milliseconds a step to
// a tenth of that within the run, and a prediction window is built every few steps, so its median step is
// one with few contacts and no window, and says little about the run), after WARM_STEPS steps of a
// throwaway one of every engine in the process; median of ROUNDS rounds. A
// round runs this module's four settings in one fresh Node process (each measured REPEATS times, in
// turn, the median kept), then the three peers in another: with
// rapier2d's rounds in the same process this module's steps measured 1.5x slower, with and without
// contacts (30 against 18 ns a ball-step on the 10,000-ball panel without contacts), and not when a
// rapier2d world was only made and stepped 30 times before this module's rounds. Printed as ns per
// ball-step and as the ratio
// peer / ours. The cost is divided by the balls still in play (each engine takes balls out at its holes
// at its own rate). Cost per contact = (the run's time with contacts − the same run's with contacts off)
// / the run's contacts, for this module's methods, from the two measured back to back in each round: the
// median of the rounds' values (and, beside it, the same from each method's fastest round, the rounds the
// machine disturbed least: whole rounds of every engine here have run 1.5–2x slower for minutes at a
// time). The median step of each engine is kept in the results too. The
// fixed-tick method runs at its default CONTACT_TICK (1/120 s:
// one contact solve per step here, as the peers) and at 1/240 s. Writes docs/results/contacts.json and docs/figures/contacts.svg.
//
//   npm run bench:contacts          (1,000 and 10,000 balls)
import RAPIER from '@dimforge/rapier2d-compat'
import Matter from 'matter-js'
import * as planck from 'planck'
import { BallMode } from '../components/Ball'
import { contactsFigure, type ContactRow } from './charts'
import { DT, argValue, collectGarbage, median, writeFigure, writeResult } from './lib'
import { recordFrames, timeBarePairing } from './barePairing'
import { R, gas, oursScene, panel, type Scene } from './contactScenes'
import { Bench } from 'tinybench'
import { spawnSync } from 'node:child_process'
import { fileURLToPath } from 'node:url'

const HOLE_R = 18
const V_MAX = 600
const PX = 100
const MEASURED_STEPS = 120
const ROUNDS = 9

/** step: one step; contacts: contacts so far (this module); live: balls still in play (not captured or out) */
type Stepper = { step: () => void; contacts: () => number; live: () => number }

function ours(sc: Scene, mode: 'off' | 'on' | 'fixed', tick = 1 / 120): Stepper {
  const sim = oursScene(sc, mode, tick)
  const w = sim.world
  return {
    step: () => {
      sim.step(DT)
      w.events.count = 0
    },
    contacts: () => w.collide?.contacts ?? w.fixed?.contacts ?? 0,
    live: () => {
      let n = 0
      for (const b of sim.balls()) {
        const m = w.Ball.mode[b]
        if (m !== BallMode.Captured && m !== BallMode.Out) n++
      }
      return n
    },
  }
}


/** Linear damping that matches the deceleration at the scene's typical speed (400 px/s). */
const damping = (sc: Scene) => sc.decel / 400

function matter(sc: Scene): Stepper {
  const engine = Matter.Engine.create({ gravity: { x: 0, y: 0, scale: 0 } })
  const bodies = sc.balls.map((b) => {
    const body = Matter.Bodies.circle(b.x, b.y, R, { frictionAir: damping(sc) * DT, friction: 0, frictionStatic: 0, restitution: sc.restitution, inertia: Infinity })
    Matter.Body.setVelocity(body, { x: b.vx / 60, y: b.vy / 60 })
    return body
  })
  const T = 50
  const wall = (x: number, y: number, w: number, h: number) => Matter.Bodies.rectangle(x, y, w, h, { isStatic: true, restitution: sc.restitution, friction: 0 })
  const walls = [wall(sc.width / 2, -T / 2, sc.width + 2 * T, T), wall(-T / 2, sc.height / 2, T, sc.height), wall(sc.width + T / 2, sc.height / 2, T, sc.height)]
  if (!sc.open) walls.push(wall(sc.width / 2, sc.height + T / 2, sc.width + 2 * T, T))
  const holes = sc.holes.map((h) => Matter.Bodies.circle(h.x, h.y, HOLE_R, { isStatic: true, isSensor: true }))
  Matter.Composite.add(engine.world, [...bodies, ...walls, ...holes])
  const statics = walls.length + holes.length
  const captured: Matter.Body[] = []
  Matter.Events.on(engine, 'collisionStart', (e) => {
    for (const p of e.pairs) {
      const ball = p.bodyA.isSensor ? p.bodyB : p.bodyB.isSensor ? p.bodyA : undefined
      if (ball && ball.speed * 60 < V_MAX) captured.push(ball)
    }
  })
  return {
    step: () => {
      Matter.Engine.update(engine, DT * 1000)
      while (captured.length > 0) Matter.Composite.remove(engine.world, captured.pop()!)
    },
    contacts: () => 0,
    live: () => Matter.Composite.allBodies(engine.world).length - statics,
  }
}

function planckWorld(sc: Scene): Stepper {
  const world = new planck.World({ gravity: planck.Vec2(0, 0) })
  const captured: planck.Body[] = []
  const ground = world.createBody()
  const S = (v: number) => v / PX
  const edges: [number, number, number, number][] = [
    [0, 0, sc.width, 0],
    [0, 0, 0, sc.height],
    [sc.width, 0, sc.width, sc.height],
  ]
  if (!sc.open) edges.push([0, sc.height, sc.width, sc.height])
  for (const [x0, y0, x1, y1] of edges) ground.createFixture({ shape: new planck.Edge(planck.Vec2(S(x0), S(y0)), planck.Vec2(S(x1), S(y1))), restitution: sc.restitution })
  for (const h of sc.holes) world.createBody({ position: planck.Vec2(S(h.x), S(h.y)) }).createFixture({ shape: new planck.Circle(S(HOLE_R)), isSensor: true, userData: 'hole' })
  for (const b of sc.balls) {
    const body = world.createBody({ type: 'dynamic', position: planck.Vec2(S(b.x), S(b.y)), linearDamping: damping(sc), fixedRotation: true })
    body.createFixture({ shape: new planck.Circle(S(R)), density: 1, friction: 0, restitution: sc.restitution })
    body.setLinearVelocity(planck.Vec2(S(b.vx), S(b.vy)))
  }
  world.on('begin-contact', (c) => {
    const a = c.getFixtureA()
    const b = c.getFixtureB()
    const ball = a.getUserData() === 'hole' ? b.getBody() : b.getUserData() === 'hole' ? a.getBody() : undefined
    if (ball && planck.Vec2.lengthOf(ball.getLinearVelocity()) * PX < V_MAX) captured.push(ball)
  })
  return {
    step: () => {
      world.step(DT)
      while (captured.length > 0) world.destroyBody(captured.pop()!)
    },
    contacts: () => 0,
    live: () => world.getBodyCount() - 1 - sc.holes.length,
  }
}

function rapier(sc: Scene): Stepper {
  const world = new RAPIER.World({ x: 0, y: 0 })
  world.timestep = DT
  const queue = new RAPIER.EventQueue(true)
  const S = (v: number) => v / PX
  const fixed = world.createRigidBody(RAPIER.RigidBodyDesc.fixed())
  const T = 0.5
  const walls: [number, number, number, number][] = [
    [S(sc.width) / 2 + T, T / 2, S(sc.width) / 2, -T / 2],
    [T / 2, S(sc.height) / 2, -T / 2, S(sc.height) / 2],
    [T / 2, S(sc.height) / 2, S(sc.width) + T / 2, S(sc.height) / 2],
  ]
  if (!sc.open) walls.push([S(sc.width) / 2 + T, T / 2, S(sc.width) / 2, S(sc.height) + T / 2])
  for (const [hx, hy, cx, cy] of walls) world.createCollider(RAPIER.ColliderDesc.cuboid(hx, hy).setTranslation(cx, cy).setRestitution(sc.restitution).setFriction(0), fixed)
  const holeHandles = new Set<number>()
  for (const h of sc.holes) {
    const col = world.createCollider(
      RAPIER.ColliderDesc.ball(S(HOLE_R)).setTranslation(S(h.x), S(h.y)).setSensor(true).setActiveEvents(RAPIER.ActiveEvents.COLLISION_EVENTS),
      fixed,
    )
    holeHandles.add(col.handle)
  }
  for (const b of sc.balls) {
    const body = world.createRigidBody(
      RAPIER.RigidBodyDesc.dynamic().setTranslation(S(b.x), S(b.y)).setLinvel(S(b.vx), S(b.vy)).setLinearDamping(damping(sc)).lockRotations(),
    )
    world.createCollider(RAPIER.ColliderDesc.ball(S(R)).setRestitution(sc.restitution).setFriction(0), body)
  }
  const captured: number[] = []
  return {
    step: () => {
      world.step(queue)
      queue.drainCollisionEvents((h1, h2, started) => {
        if (!started) return
        const ballCollider = holeHandles.has(h1) ? h2 : holeHandles.has(h2) ? h1 : -1
        if (ballCollider < 0) return
        const body = world.getCollider(ballCollider)?.parent()
        if (body) {
          const v = body.linvel()
          if (Math.hypot(v.x, v.y) * PX < V_MAX) captured.push(body.handle)
        }
      })
      while (captured.length > 0) {
        const body = world.getRigidBody(captured.pop()!)
        if (body) world.removeRigidBody(body)
      }
    },
    contacts: () => 0,
    live: () => world.bodies.len() - 1,
  }
}

interface Sample {
  /** ns per live ball-step: mean step / mean balls in play over the measured steps */
  ns: number
  /** the same from the median step */
  nsMedian: number
  /** worst step, ms */
  worstMs: number
  contactsPerStep: number
}

/** Mean balls in play over the measured steps, from an untimed run of the same fresh scene (all engines are deterministic). */
function meanLive(make: () => Stepper): number {
  const s = make()
  let sum = 0
  for (let i = 0; i < MEASURED_STEPS; i++) {
    s.step()
    sum += s.live()
  }
  return sum / MEASURED_STEPS
}

async function measure(name: string, live: number, make: () => Stepper): Promise<Sample> {
  const s = make()
  collectGarbage()
  const c0 = s.contacts()
  const bench = new Bench({ time: 0, iterations: MEASURED_STEPS, warmup: false })
  bench.add(name, s.step)
  await bench.run()
  const r = bench.tasks[0]!.result as { latency?: { mean: number; p50: number; max: number }; error?: unknown }
  if (!r.latency) throw new Error(`${name}: benchmark failed: ${String(r.error)}`)
  return { ns: (r.latency.mean * 1e6) / live, nsMedian: (r.latency.p50 * 1e6) / live, worstMs: r.latency.max, contactsPerStep: (s.contacts() - c0) / MEASURED_STEPS }
}

/** Steps of a throwaway scene of each engine before a round's measurements (each round runs in a fresh process). */
const WARM_STEPS = 240
/** Measurements of each of this module's settings in a round, taken in turn. */
const REPEATS = 3

/** The engines of a group, for scene sc; a group's rounds each run in a process of their own. */
function group(name: string, sc: Scene): [string, () => Stepper][] {
  if (name === 'ours') {
    return [
      ['off', () => ours(sc, 'off')],
      ['exact', () => ours(sc, 'on')],
      ['fixed', () => ours(sc, 'fixed')],
      ['fixed240', () => ours(sc, 'fixed', 1 / 240)],
    ]
  }
  return [
    ['rapier', () => rapier(sc)],
    ['matter', () => matter(sc)],
    ['planck', () => planckWorld(sc)],
  ]
}

const child = argValue('--child')
if (child !== undefined) {
  // one round of one group on one scene: the balls in play, then each engine's sample, as JSON on stdout
  if (child === 'peers') await RAPIER.init()
  const sc = (argValue('--scene') === 'gas' ? gas : panel)(Number(argValue('--balls')))
  const engines = group(child, sc)
  // a fresh process: the code of every engine in it warms on a throwaway scene first
  for (const [, mk] of engines) {
    const throwaway = mk()
    for (let i = 0; i < WARM_STEPS; i++) throwaway.step()
  }
  // this module's settings are measured REPEATS times each, in turn, so that the one with contacts and the
  // one without see the same spells of the machine; the round's figure for each is the median
  const repeats = child === 'ours' ? REPEATS : 1
  const live = new Map(engines.map(([key, mk]) => [key, meanLive(mk)]))
  const samples = new Map<string, Sample[]>(engines.map(([key]) => [key, []]))
  for (let k = 0; k < repeats; k++) for (const [key, mk] of engines) samples.get(key)!.push(await measure(key, live.get(key)!, mk))
  const out: Record<string, (Sample & { live: number }) | Bare> = {}
  for (const [key] of engines) {
    const s = samples.get(key)!
    out[key] = { ns: median(s.map((x) => x.ns)), nsMedian: median(s.map((x) => x.nsMedian)), worstMs: median(s.map((x) => x.worstMs)), contactsPerStep: median(s.map((x) => x.contactsPerStep)), live: live.get(key)! }
  }
  // the barest pairing loop over the moving balls of the same run with the fixed tick (bench/barePairing.ts)
  if (child === 'ours') out.bare = timeBarePairing(recordFrames(oursScene(sc, 'fixed', 1 / 120), MEASURED_STEPS, DT), 1 / 120, 5 * REPEATS)
  process.stdout.write(JSON.stringify(out))
  process.exit(0)
}

/** The bare pairing loop's figures of a round (bench/barePairing.ts): µs a step, pairs and moving balls a step. */
interface Bare {
  usPerStep: number
  pairsPerStep: number
  movingPerStep: number
}

/** Runs one round of a group in a fresh Node process (this script, already bundled). */
function round(name: string, scene: string, n: number): Record<string, (Sample & { live: number }) | Bare> {
  const r = spawnSync(process.execPath, ['--expose-gc', fileURLToPath(import.meta.url), '--child', name, '--scene', scene, '--balls', String(n)], {
    encoding: 'utf8',
    maxBuffer: 1 << 20,
    stdio: ['ignore', 'pipe', 'inherit'],
  })
  if (r.status !== 0) throw new Error(`${name} on ${scene} ${n}: the round's process failed (${r.status})`)
  return JSON.parse(r.stdout) as Record<string, (Sample & { live: number }) | Bare>
}

const sizes = (argValue('--sizes') ?? '1000,10000').split(',').map(Number)
const rows: ContactRow[] = []
for (const make of [gas, panel]) {
  for (const n of sizes) {
    const sc = make(n)
    const engines = [...group('ours', sc), ...group('peers', sc)]
    const got = new Map<string, Sample[]>(engines.map(([k]) => [k, []]))
    const live = new Map<string, number>()
    const bare: Bare[] = []
    for (let r = 0; r < ROUNDS; r++) {
      for (const name of ['ours', 'peers']) {
        for (const [key, sample] of Object.entries(round(name, sc.name, n))) {
          if ('usPerStep' in sample) {
            bare.push(sample)
            continue
          }
          got.get(key)!.push(sample)
          live.set(key, sample.live)
        }
      }
    }
    const med = (key: string) => {
      const s = got.get(key)!
      return { ns: median(s.map((x) => x.ns)), nsMedian: median(s.map((x) => x.nsMedian)), worstMs: median(s.map((x) => x.worstMs)), contactsPerStep: median(s.map((x) => x.contactsPerStep)) }
    }
    const off = med('off')
    const exact = med('exact')
    const fixed = med('fixed')
    const fixed240 = med('fixed240')
    // the extra cost of a run with contacts over the same run without, per contact (live balls of each),
    // in each round from that round's two measurements: the median of the rounds, and the least
    const perRound = (key: string) =>
      got.get(key)!.map((m, r) =>
        m.contactsPerStep > 0 ? (m.ns * live.get(key)! - got.get('off')![r]!.ns * live.get('off')!) / m.contactsPerStep / 1000 : NaN,
      )
    const perContactUs = (key: string) => median(perRound(key))
    // the former measure, for comparison with runs before the mean step: the median step's extra cost over
    // the run's mean contacts a step (it understates the panel's, whose median step has few contacts)
    const medianStepUs = (key: string) =>
      median(got.get(key)!.map((m, r) => (m.nsMedian * live.get(key)! - got.get('off')![r]!.nsMedian * live.get('off')!) / m.contactsPerStep / 1000))
    // the least-disturbed estimate: each method's fastest round against the fastest round without contacts
    // (the least of the rounds' differences would favour a round whose step without contacts was disturbed)
    const fastest = (key: string) => Math.min(...got.get(key)!.map((m) => m.ns))
    const leastUs = (key: string) => (fastest(key) * live.get(key)! - fastest('off') * live.get('off')!) / med(key).contactsPerStep / 1000
    const row: ContactRow = {
      scene: sc.name,
      balls: n,
      off: off.ns,
      exact: exact.ns,
      fixed: fixed.ns,
      fixed240: fixed240.ns,
      rapier: med('rapier').ns,
      matter: med('matter').ns,
      planck: med('planck').ns,
      meanLive: Object.fromEntries(live),
      median: Object.fromEntries(engines.map(([key]) => [key, med(key).nsMedian])),
      worstMs: { exact: exact.worstMs, fixed: fixed.worstMs, fixed240: fixed240.worstMs, rapier: med('rapier').worstMs, matter: med('matter').worstMs, planck: med('planck').worstMs },
      contactsPerStep: { exact: exact.contactsPerStep, fixed: fixed.contactsPerStep, fixed240: fixed240.contactsPerStep },
      usPerContact: { exact: perContactUs('exact'), fixed: perContactUs('fixed'), fixed240: perContactUs('fixed240') },
      usPerContactLeast: { exact: leastUs('exact'), fixed: leastUs('fixed'), fixed240: leastUs('fixed240') },
      usPerContactMedianStep: { exact: medianStepUs('exact'), fixed: medianStepUs('fixed'), fixed240: medianStepUs('fixed240') },
      barePairing: barePairingRow(bare, fixed.contactsPerStep, (fixed.ns * live.get('fixed')! - off.ns * live.get('off')!) / 1000),
    }
    rows.push(row)
    const f = (v: number) => (v >= 100 ? v.toFixed(0) : v.toFixed(1))
    console.log(
      `${sc.name} ${n}: ns/live ball-step (mean step) off ${f(row.off)}, exact ${f(row.exact)}, fixed ${f(row.fixed)} (1/240: ${f(row.fixed240)}), rapier ${f(row.rapier)} (${f(row.rapier / row.fixed)}× fixed, ${f(row.rapier / row.exact)}× exact), matter ${f(row.matter)}, planck ${f(row.planck)}; ` +
        `worst step ms exact ${f(row.worstMs.exact)}, fixed ${f(row.worstMs.fixed)}, rapier ${f(row.worstMs.rapier)}; ` +
        `contacts/step exact ${f(row.contactsPerStep.exact)}, fixed ${f(row.contactsPerStep.fixed)}; µs/contact (median of rounds; fastest rounds) exact ${f(row.usPerContact.exact)}; ${f(row.usPerContactLeast!.exact)}, fixed ${f(row.usPerContact.fixed)}; ${f(row.usPerContactLeast!.fixed)}; from the median step (former measure) exact ${f(row.usPerContactMedianStep!.exact)}, fixed ${f(row.usPerContactMedianStep!.fixed)}; ` +
        `bare pairing ${f(row.barePairing!.nsPerMovingBall)} ns a moving ball, ${f(row.barePairing!.usPerContact)} µs/contact (the fixed tick's extra time ${f(row.barePairing!.fixedExtraOverBare)}× it)`,
    )
  }
}
const json = writeResult('contacts', {
  dt: DT,
  measuredSteps: MEASURED_STEPS,
  rounds: ROUNDS,
  contactTick: { fixed: 1 / 120, fixed240: 1 / 240 },
  normalisation: 'ns per live ball-step: the mean step (the run of MEASURED_STEPS steps over its steps) divided by the mean number of balls in play (not captured, not out) over the measured steps, per engine; `median` the same from the median step',
  timing: 'tinybench: mean, median and worst step of MEASURED_STEPS steps of a fresh scene after WARM_STEPS steps of a throwaway one, ns per ball-step; median of ROUNDS rounds, each running this module (off, exact, fixed, fixed240, each measured REPEATS times in turn, the median kept) in a fresh Node process and then the peers in another',
  repeats: REPEATS,
  warmSteps: WARM_STEPS,
  perContact: '(ns per ball-step with contacts − the same with contacts off, from the mean steps of the two runs measured back to back in a round) × balls / contacts per step, that is the extra time of the run over its contacts: usPerContact the median of the rounds; usPerContactLeast the same from each method\'s fastest round and the fastest round without contacts; usPerContactMedianStep the measure used before, the median steps\' difference over the mean contacts a step',
  scenes: {
    gas: 'walled square, area fraction 0.2, restitution 0.9, no holes, no deceleration, 150–350 px/s',
    panel: 'tiles of the default 5 × 5 panel in one field open at the bottom, 40 balls a tile thrown up at once from a launch band, ROLLING_DECEL 300',
  },
  barePairing: 'bench/barePairing.ts: the barest loop that pairs the moving balls of a tick (uniform grid by counting sort, pairs within reach; no solve, no resting balls, no walls, no order) over the moving balls after each step of a run with the fixed tick, the median of 5·REPEATS passes in each round\'s process, then the median of the rounds; usPerContact = its µs a step over the fixed tick\'s contacts a step; fixedExtraOverBare = the fixed tick\'s extra µs a step over the run without contacts (mean steps, median of the rounds) over the loop\'s',
  rows,
})

/** The bare pairing loop's row figures from the rounds' samples (medians), against the fixed tick's contacts and extra µs a step. */
function barePairingRow(samples: Bare[], contactsPerStep: number, fixedExtraUs: number): NonNullable<ContactRow['barePairing']> {
  const us = median(samples.map((b) => b.usPerStep))
  const moving = median(samples.map((b) => b.movingPerStep))
  return {
    usPerStep: us,
    nsPerMovingBall: (1000 * us) / moving,
    pairsPerStep: median(samples.map((b) => b.pairsPerStep)),
    usPerContact: us / contactsPerStep,
    fixedExtraOverBare: fixedExtraUs / us,
  }
}
const svg = await writeFigure('contacts', contactsFigure(rows, MEASURED_STEPS, ROUNDS))
console.log(`wrote ${json} and ${svg}`)
