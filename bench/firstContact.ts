// Two balls in a closed box: when each contact method meets their first contact, against a reference made
// here from the straight paths alone. Where a tick's travel is more than the balls' diameters, the fixed tick
// turns a ball at its wall at the tick and can leave the path the exact method keeps (README: Ball-ball
// contacts); this counts how often that makes the first contact late or misses it, and whether one ball ever
// goes through the other.
//
// Each scene (seeded): a box 60–1,000 px a side, two balls of radius 0.5–25 px put down apart, one at
// 1e3–1e5 px/s, the other at rest or up to 1,000 px/s (both log-uniform where a range spans decades),
// ROLLING_DECEL 0 (straight paths), one restitution in 0.3–1 for the balls and the walls. The reference
// follows the two paths from wall to wall until the balls first touch (within HORIZON). A method's first
// contact is its first 'collision' event; for the fixed tick (event time: the tick that met it, which may
// be up to a tick before the touch) it is
//   on time  at or before the touch, by at most CONTACT_TICK (the tick that meets it: its spacing is
//            CONTACT_TICK or finer);
//   late     after the touch, within CONTACT_TICK of it;
//   missed   none within CONTACT_TICK after the touch (the balls passed each other, or met only later);
//   early    more than CONTACT_TICK before the touch (another contact, on a path a wall turn changed).
// The exact method is held to 1e-7 s of the reference. Every world is stepped at 1/7,680 s (the fixed tick
// gives the same bits at any steps, tests/systems/fixedContacts.test.ts) until a tick after the touch, and the
// deepest overlap at a step's end is kept: "through" counts the scenes where one ball's centre came within
// the other. Writes docs/results/first-contact.json.
//
//   npm run bench:first-contact [-- --scenes 3000] [--seed N] [--show]
import { createBallPhysics, type BallPhysics, type ConfigOverrides } from '../src/index'
import { argValue, random, writeResult } from './lib'

const SCENES = Number(argValue('--scenes') ?? 3000)
/** print each scene in which a ball's centre came within the other ball (to replay it) */
const SHOW = process.argv.includes('--show')
const HORIZON = 0.25
const LOOK = 1 / 7680
const TICK = 1 / 120

interface Ball {
  x: number
  y: number
  vx: number
  vy: number
  r: number
}
interface Scene {
  w: number
  h: number
  e: number
  a: Ball
  b: Ball
}

const logUniform = (r: () => number, lo: number, hi: number) => lo * Math.exp(r() * Math.log(hi / lo))

function draw(r: () => number): Scene {
  const w = logUniform(r, 60, 1000)
  const h = logUniform(r, 60, 1000)
  const cap = Math.min(25, Math.min(w, h) / 4)
  const ball = (speed: number): Ball => {
    const rad = logUniform(r, 0.5, cap)
    const ang = 2 * Math.PI * r()
    return { x: rad + (w - 2 * rad) * r(), y: rad + (h - 2 * rad) * r(), vx: speed * Math.cos(ang), vy: speed * Math.sin(ang), r: rad }
  }
  for (;;) {
    const a = ball(logUniform(r, 1e3, 1e5))
    const b = ball(r() < 0.25 ? 0 : 1000 * r())
    // apart by more than a hundredth of a px
    if (Math.hypot(a.x - b.x, a.y - b.y) > a.r + b.r + 0.01) return { w, h, e: 0.3 + 0.7 * r(), a, b }
  }
}

/** When a (with velocity) next reaches a wall of the box along one axis: the time, or Infinity. */
function wallTime(p: number, v: number, r: number, size: number): number {
  if (v > 0) return (size - r - p) / v
  if (v < 0) return (r - p) / v
  return Infinity
}

/**
 * The reference: the first time the balls touch within HORIZON (Infinity if they do not), following both
 * straight paths, each reflected at the walls with restitution e (a speed below 1 px/s along an axis is
 * left at 0 there, as BALL_SETTLE_SPEED does).
 */
function reference(sc: Scene): number {
  const a = { ...sc.a }
  const b = { ...sc.b }
  const R = a.r + b.r
  let t = 0
  for (let events = 0; events < 100_000; events++) {
    const dx = b.x - a.x
    const dy = b.y - a.y
    const ux = b.vx - a.vx
    const uy = b.vy - a.vy
    // |d + u·s| = R, the first root with s ≥ 0 while closing
    const A = ux * ux + uy * uy
    const B = dx * ux + dy * uy
    const C = dx * dx + dy * dy - R * R
    let meet = Infinity
    if (A > 0 && B < 0) {
      const disc = B * B - A * C
      if (disc >= 0) meet = Math.max(0, (-B - Math.sqrt(disc)) / A)
    }
    const walls = [wallTime(a.x, a.vx, a.r, sc.w), wallTime(a.y, a.vy, a.r, sc.h), wallTime(b.x, b.vx, b.r, sc.w), wallTime(b.y, b.vy, b.r, sc.h)]
    const next = Math.min(...walls)
    if (meet <= next) return t + meet <= HORIZON ? t + meet : Infinity
    if (t + next > HORIZON) return Infinity
    t += next
    for (const ball of [a, b]) {
      ball.x += ball.vx * next
      ball.y += ball.vy * next
    }
    const turn = (v: number) => (Math.abs(sc.e * v) < 1 ? 0 : -sc.e * v)
    if (walls[0] === next) a.vx = turn(a.vx)
    if (walls[1] === next) a.vy = turn(a.vy)
    if (walls[2] === next) b.vx = turn(b.vx)
    if (walls[3] === next) b.vy = turn(b.vy)
  }
  return Infinity
}

interface Seen {
  first: number
  deepest: number
}

/** A method's first contact and the deepest overlap at a step's end, stepped at LOOK until `until`. */
function play(sc: Scene, config: ConfigOverrides, until: number): Seen {
  const sim: BallPhysics = createBallPhysics({ ROLLING_DECEL: 0, BALL_RESTITUTION: sc.e, ...config })
  sim.setWalls({ minX: 0, minY: 0, maxX: sc.w, maxY: sc.h, restitution: sc.e })
  const ia = sim.addBall({ x: sc.a.x, y: sc.a.y, vx: sc.a.vx, vy: sc.a.vy, radius: sc.a.r })
  const ib = sim.addBall({ x: sc.b.x, y: sc.b.y, vx: sc.b.vx, vy: sc.b.vy, radius: sc.b.r })
  let first = Infinity
  let deepest = 0
  const steps = Math.ceil(until / LOOK)
  for (let s = 0; s < steps; s++) {
    sim.step(LOOK)
    for (const ev of sim.drainEvents()) if (ev.type === 'collision' && first === Infinity) first = ev.time
    const p = sim.ballState(ia)
    const q = sim.ballState(ib)
    deepest = Math.max(deepest, sc.a.r + sc.b.r - Math.hypot(q.x - p.x, q.y - p.y))
  }
  return { first, deepest }
}

const METHODS: { name: string; config: ConfigOverrides }[] = [
  { name: 'exact', config: { BALL_COLLISIONS: 'on' } },
  { name: 'fixed, halvings 0', config: { BALL_COLLISIONS: 'fixed', CONTACT_TICK: TICK, CONTACT_TRAVEL_HALVINGS: 0 } },
  { name: 'fixed, halvings 4 (default)', config: { BALL_COLLISIONS: 'fixed', CONTACT_TICK: TICK, CONTACT_TRAVEL_HALVINGS: 4 } },
]

type Tally = { onTime: number; late: number; missed: number; early: number; off: number; overlapped: number; through: number; deepest: number; worstLate: number }
const tallies = new Map(METHODS.map((m) => [m.name, { onTime: 0, late: 0, missed: 0, early: 0, off: 0, overlapped: 0, through: 0, deepest: 0, worstLate: 0 } as Tally]))
const SEED = Number(argValue('--seed') ?? 20_261_201)
const r = random(SEED)
let met = 0
let apart = 0
const t0 = performance.now()
for (let k = 0; k < SCENES; k++) {
  const sc = draw(r)
  const touch = reference(sc)
  if (touch === Infinity) {
    apart++
    continue
  }
  met++
  for (const m of METHODS) {
    const seen = play(sc, m.config, Math.min(HORIZON, touch + TICK))
    const T = tallies.get(m.name)!
    const lag = seen.first - touch
    if (m.name === 'exact') {
      if (Math.abs(lag) <= 1e-7) T.onTime++
      else T.off++
    } else if (seen.first === Infinity || lag > TICK) T.missed++
    else if (lag > 1e-9) {
      T.late++
      T.worstLate = Math.max(T.worstLate, lag)
    } else if (lag >= -TICK - 1e-9) T.onTime++
    else T.early++
    if (seen.deepest > 1e-3) T.overlapped++
    if (seen.deepest > Math.min(sc.a.r, sc.b.r)) {
      T.through++
      if (SHOW) console.log(`scene ${k}, ${m.name}: a centre within the other ball`, JSON.stringify(sc), { touch, ...seen })
    }
    T.deepest = Math.max(T.deepest, seen.deepest)
  }
}
const seconds = (performance.now() - t0) / 1000
for (const [name, T] of tallies) {
  console.log(
    `${name.padEnd(28)} ${name === 'exact' ? `within 1e-7 s ${T.onTime} of ${met}, off ${T.off}` : `on time ${T.onTime}, late ${T.late} (worst ${(1000 * T.worstLate).toFixed(2)} ms), missed ${T.missed}, early ${T.early} of ${met}`}; over 1e-3 px deep at a step's end ${T.overlapped}, a centre within the other ball ${T.through} (deepest ${T.deepest.toExponential(2)} px)`,
  )
}
console.log(`${met} scenes meet within ${HORIZON} s by the reference, ${apart} do not (left out); ${seconds.toFixed(0)} s`)
const file = writeResult('first-contact', {
  scenes: SCENES,
  seed: SEED,
  met,
  apart,
  horizon: HORIZON,
  look: LOOK,
  contactTick: TICK,
  seconds,
  definitions:
    'reference: both straight paths from wall to wall (restitution e, a speed below 1 px/s along an axis left at 0) to the first touch within the horizon; exact: its first collision within 1e-7 s of the touch; fixed: onTime at or before the touch by at most CONTACT_TICK, late within CONTACT_TICK after it, missed none within CONTACT_TICK after it, early more than CONTACT_TICK before it; overlapped: deeper than 1e-3 px at the end of a step of 1/7,680 s until a tick after the touch; through: deeper than the smaller radius',
  methods: Object.fromEntries(tallies),
})
console.log(`wrote ${file}`)
