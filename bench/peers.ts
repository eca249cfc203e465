// The same scene in general 2D engines a game might pick instead: N balls rolling with deceleration over
// 25 holes that are sensors, capture decided in the engines' contact callbacks (speed below V_MAX when the
// ball touches the sensor), ball-ball contacts filtered out; then with ball-ball contacts on at 1,000 balls
// (this module with BALL_COLLISIONS 'on', restitution 0.9 like the peers' fixtures; the balls put down
// without overlaps, so that no engine starts by pushing overlapping pairs apart).
// Each engine steps at 1/120 s under tinybench; printed as ns per ball-step and as the ratio to this
// module measured in the same run. Each engine's round runs in a Node process of its own, after WARM_STEPS
// steps of two throwaway scenes (half each; the second world a process makes generalises the world's field
// types once, and the code compiled against the first is thrown away then, so the measured scene is the
// third): with the four engines in one process, this module's first 15 to 70 steps of
// a fresh 1,000-ball scene sometimes ran at 100-250 us a step, then fell to about 10 after one step of
// 1-5 ms (V8 threw the step's optimised code away at the world's field-type generalisation and at
// collections that freed objects it had embedded, and compiled it again some tens of steps later), so the
// row read 10-17 or 91-110 ns a ball-step from run to run. Writes
// docs/results/peers.json and docs/figures/peers.svg (or under --out DIR).
//
//   npm run bench:peers            (N = 1,000 and 10,000; contacts on at 1,000)
import RAPIER from '@dimforge/rapier2d-compat'
import Matter from 'matter-js'
import * as planck from 'planck'
import { createBallPhysics } from '../src/index'
import { DT, argValue, collectGarbage, median, medianStepMs, random, writeFigure, writeResult } from './lib'
import { spawnSync } from 'node:child_process'
import { fileURLToPath } from 'node:url'
import { peersFigure, type PeerRow } from './charts'

const HOLE_R = 18
const BALL_R = 11
const V_MAX = 600
const SIZE = 2000
/** rolling deceleration of the scene, px/s²: low, so that balls keep rolling through the measurement */
const DECEL = 20
/** the engines' linear damping that matches DECEL at the scene's typical speed (250 px/s) */
const DAMPING = DECEL / 250
/** planck and rapier work in metres: 100 px to the metre keeps speeds in their comfortable range */
const PX = 100

interface Scene {
  balls: { x: number; y: number; vx: number; vy: number }[]
  holes: { x: number; y: number }[]
}

/** n balls at random over the field; with `separated`, a ball that would overlap an earlier one is drawn again. */
function scene(n: number, separated = false): Scene {
  const r = random(12345)
  const holes = []
  for (let i = 0; i < 5; i++) for (let j = 0; j < 5; j++) holes.push({ x: 200 + 400 * i, y: 200 + 400 * j })
  const balls: Scene['balls'] = []
  while (balls.length < n) {
    const a = r() * 2 * Math.PI
    const v = 150 + 200 * r()
    const x = r() * SIZE
    const y = r() * SIZE
    if (separated && balls.some((b) => (b.x - x) ** 2 + (b.y - y) ** 2 < (2 * BALL_R) ** 2)) continue
    balls.push({ x, y, vx: v * Math.cos(a), vy: v * Math.sin(a) })
  }
  return { balls, holes }
}

type Stepper = () => void

function ours(sc: Scene, contacts: boolean): Stepper {
  const sim = createBallPhysics(
    { ROLLING_DECEL: DECEL, BALL_COLLISIONS: contacts ? 'on' : 'off', BALL_RESTITUTION: 0.9 },
    { capacity: sc.balls.length + 64 },
  )
  for (const h of sc.holes) sim.addHole(h)
  for (const b of sc.balls) sim.addBall(b)
  return () => {
    sim.step(DT)
    sim.world.events.count = 0
  }
}

function matter(sc: Scene, contacts: boolean): Stepper {
  const engine = Matter.Engine.create({ gravity: { x: 0, y: 0, scale: 0 } })
  const group = contacts ? 0 : -1
  const bodies = sc.balls.map((b) => {
    const body = Matter.Bodies.circle(b.x, b.y, BALL_R, { frictionAir: DAMPING * DT * 60, friction: 0, restitution: 0.9, collisionFilter: { group } })
    Matter.Body.setVelocity(body, { x: b.vx / 60, y: b.vy / 60 }) // matter's velocity unit: px per 1/60 s
    return body
  })
  const holes = sc.holes.map((h) => Matter.Bodies.circle(h.x, h.y, HOLE_R, { isStatic: true, isSensor: true }))
  Matter.Composite.add(engine.world, [...bodies, ...holes])
  const captured: Matter.Body[] = []
  Matter.Events.on(engine, 'collisionStart', (e) => {
    for (const p of e.pairs) {
      const ball = p.bodyA.isSensor ? p.bodyB : p.bodyB.isSensor ? p.bodyA : undefined
      if (ball && ball.speed * 60 < V_MAX) captured.push(ball)
    }
  })
  return () => {
    Matter.Engine.update(engine, DT * 1000)
    while (captured.length > 0) Matter.Composite.remove(engine.world, captured.pop()!)
  }
}

function planckWorld(sc: Scene, contacts: boolean): Stepper {
  const world = new planck.World({ gravity: planck.Vec2(0, 0) })
  const captured: planck.Body[] = []
  for (const h of sc.holes) {
    world.createBody({ position: planck.Vec2(h.x / PX, h.y / PX) }).createFixture({ shape: new planck.Circle(HOLE_R / PX), isSensor: true, userData: 'hole' })
  }
  for (const b of sc.balls) {
    const body = world.createBody({ type: 'dynamic', position: planck.Vec2(b.x / PX, b.y / PX), linearDamping: DAMPING, bullet: false })
    body.createFixture({ shape: new planck.Circle(BALL_R / PX), density: 1, restitution: 0.9, filterGroupIndex: contacts ? 0 : -1 })
    body.setLinearVelocity(planck.Vec2(b.vx / PX, b.vy / PX))
  }
  world.on('begin-contact', (c) => {
    const a = c.getFixtureA()
    const b = c.getFixtureB()
    const ball = a.getUserData() === 'hole' ? b.getBody() : b.getUserData() === 'hole' ? a.getBody() : undefined
    if (ball && planck.Vec2.lengthOf(ball.getLinearVelocity()) * PX < V_MAX) captured.push(ball)
  })
  return () => {
    world.step(DT)
    while (captured.length > 0) world.destroyBody(captured.pop()!)
  }
}

function rapier(sc: Scene, contacts: boolean): Stepper {
  const world = new RAPIER.World({ x: 0, y: 0 })
  world.timestep = DT
  const queue = new RAPIER.EventQueue(true)
  // groups: balls are in 0x0001 and, with contacts off, filter only holes (0x0002)
  const ballGroups = (0x0001 << 16) | (contacts ? 0x0003 : 0x0002)
  const holeGroups = (0x0002 << 16) | 0x0001
  const holeHandles = new Set<number>()
  for (const h of sc.holes) {
    const body = world.createRigidBody(RAPIER.RigidBodyDesc.fixed().setTranslation(h.x / PX, h.y / PX))
    const col = world.createCollider(
      RAPIER.ColliderDesc.ball(HOLE_R / PX).setSensor(true).setCollisionGroups(holeGroups).setActiveEvents(RAPIER.ActiveEvents.COLLISION_EVENTS),
      body,
    )
    holeHandles.add(col.handle)
  }
  for (const b of sc.balls) {
    const body = world.createRigidBody(
      RAPIER.RigidBodyDesc.dynamic().setTranslation(b.x / PX, b.y / PX).setLinvel(b.vx / PX, b.vy / PX).setLinearDamping(DAMPING),
    )
    world.createCollider(RAPIER.ColliderDesc.ball(BALL_R / PX).setRestitution(0.9).setCollisionGroups(ballGroups), body)
  }
  const captured: number[] = []
  return () => {
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
  }
}

/** Steps measured per engine: 1 s of simulated time, so the scene is the same for every engine throughout. */
const MEASURED_STEPS = 120
/** Rounds per scene, the engines interleaved within a round; each figure is the median of the rounds. */
const ROUNDS = 3

/** Steps of the throwaway scenes before each measurement (two, half each), in the measurement's own process. */
const WARM_STEPS = 240

const ENGINES: Record<string, (sc: Scene, contacts: boolean) => Stepper> = { ours, matter, planck: planckWorld, rapier }

const child = argValue('--child')
if (child !== undefined) {
  // one engine's round in a fresh process: warm its code on a throwaway scene, then measure a fresh one
  if (child === 'rapier') await RAPIER.init()
  const n = Number(argValue('--balls'))
  const contacts = argValue('--contacts') === '1'
  const sc = scene(n, contacts)
  const make = () => ENGINES[child]!(sc, contacts)
  for (let k = 0; k < 2; k++) {
    const throwaway = make()
    for (let i = 0; i < WARM_STEPS / 2; i++) throwaway()
  }
  const step = make()
  collectGarbage()
  process.stdout.write(JSON.stringify({ ns: ((await medianStepMs(step, MEASURED_STEPS)) * 1e6) / n })) // ms per step → ns per ball-step
  process.exit(0)
}

/** One round of one engine, in a fresh Node process (this script, already bundled): ns per ball-step. */
function measure(engine: string, n: number, contacts: boolean): number {
  const r = spawnSync(process.execPath, ['--expose-gc', fileURLToPath(import.meta.url), '--child', engine, '--balls', String(n), '--contacts', contacts ? '1' : '0'], {
    encoding: 'utf8',
    stdio: ['ignore', 'pipe', 'inherit'],
  })
  if (r.status !== 0) throw new Error(`${engine}, ${n} balls: the round's process failed (${r.status})`)
  return (JSON.parse(r.stdout) as { ns: number }).ns
}

const rows: PeerRow[] = []
const runs: [number, boolean][] = [
  [1000, false],
  [10000, false],
  [1000, true],
]
for (const [n, contacts] of runs) {
  const t: Record<'o' | 'm' | 'p' | 'r', number[]> = { o: [], m: [], p: [], r: [] }
  for (let round = 0; round < ROUNDS; round++) {
    t.o.push(measure('ours', n, contacts))
    t.m.push(measure('matter', n, contacts))
    t.p.push(measure('planck', n, contacts))
    t.r.push(measure('rapier', n, contacts))
  }
  const [o, m, p, r] = [median(t.o), median(t.m), median(t.p), median(t.r)]
  rows.push({ balls: n, contacts: contacts ? 'on' : 'off', ours: o, matter: m, planck: p, rapier: r, 'matter/ours': m / o, 'planck/ours': p / o, 'rapier/ours': r / o })
}
const f = (v: number) => (v >= 100 ? v.toFixed(0) : v.toFixed(1))
console.log(`ns per ball-step (median step of ${MEASURED_STEPS} / balls, median of ${ROUNDS} rounds), dt = 1/120 s, 25 sensor holes, one run`)
console.log('balls   contacts  ours      matter-js  planck    rapier2d   matter/ours  planck/ours  rapier/ours')
for (const r of rows) {
  console.log(
    [String(r.balls).padEnd(7), r.contacts.padEnd(9), ...[r.ours, r.matter, r.planck, r.rapier].map((v) => f(v).padEnd(9)), ...[r['matter/ours'], r['planck/ours'], r['rapier/ours']].map((v) => `${f(v)}×`.padEnd(12))]
      .join(' ')
      .trimEnd(),
  )
}
const json = writeResult('peers', {
  dt: DT,
  measuredSteps: MEASURED_STEPS,
  rounds: ROUNDS,
  timing: 'tinybench: median step of MEASURED_STEPS steps of a fresh scene after WARM_STEPS steps of two throwaway ones (half each), each engine\'s round in a Node process of its own, ns per ball-step; median of ROUNDS rounds, the engines interleaved',
  warmSteps: WARM_STEPS,
  rollingDecel: DECEL,
  ballRestitution: 0.9,
  scene: 'balls at 150-350 px/s over a 2000 px square with 25 sensor holes; contacts-on rows: balls put down without overlaps',
  rows,
})

const svg = await writeFigure('peers', peersFigure(rows, MEASURED_STEPS, ROUNDS))
console.log(`wrote ${json} and ${svg}`)
