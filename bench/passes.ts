// Fast balls of unlike sizes in small closed boxes, under the fixed tick: how often one ball goes into
// another by more than half the smaller radius between the looks (every 1/3,840 s), which no tick's
// projection would part on the side it came from. Counts, not times.
//
// Each scene (seeded): 13–42 balls in a closed square box of 200–600 px, radii 0.5–25 px (log-uniform;
// masses by the default, as the cube of the radius), put down apart; 40 % of them at 1e3–1e5 px/s
// (log-uniform), the rest at a twentieth of that, in random directions; restitution 1 or 0.9 (balls and
// walls), no rolling deceleration; 0.5 s. Run at the default CONTACT_TRAVEL_HALVINGS (4), at 0, and with the
// same scenes at restitution 0 (where the tick is not halved for travel). For each
// scene that has such a look, the deepest one: the two radii and speeds at that look. A ball the heavy ones
// pump to several times 1e5 px/s covers more than its size even at the finest tick (CONTACT_TICK / 2^10),
// where no solve can part it in time (src/contacts/fixedDeep.ts). Writes docs/results/passes.json.
//
//   npm run bench:passes [-- --scenes 600] [--seed N]
import { createBallPhysics, type BallSpec, type ConfigOverrides } from '../src/index'
import { argValue, random, writeResult } from './lib'

const SCENES = Number(argValue('--scenes') ?? 600)
const SEED = Number(argValue('--seed') ?? 1)
const LOOK = 1 / 3840
const SECONDS = 0.5

/** a ball as put down, with its radius */
type Ball = BallSpec & { radius: number }

function draw(r: () => number): { box: number; e: number; balls: Ball[] } {
  const n = 13 + Math.floor(30 * r())
  const box = 200 + 400 * r()
  const e = r() < 0.5 ? 1 : 0.9
  const balls: Ball[] = []
  for (let i = 0; i < n; i++) {
    const radius = 0.5 * Math.exp(r() * Math.log(50))
    for (let tries = 0; tries < 200; tries++) {
      const x = radius + r() * (box - 2 * radius)
      const y = radius + r() * (box - 2 * radius)
      if (balls.some((b) => Math.hypot(b.x - x, b.y - y) < b.radius + radius + 0.5)) continue
      const speed = 1e3 * Math.exp(r() * Math.log(100)) * (r() < 0.4 ? 1 : 0.05)
      const a = 2 * Math.PI * r()
      balls.push({ x, y, vx: speed * Math.cos(a), vy: speed * Math.sin(a), radius })
      break
    }
  }
  return { box, e, balls }
}

interface Deep {
  scene: number
  depth: number
  t: number
  radii: [number, number]
  speeds: [number, number]
}

/**
 * One scene under `config`: its deepest look past half the smaller radius (null if none), and its deepest
 * overlap at a look on a tick of 1/120 s (what a game stepping at 60 or 120 Hz draws).
 */
function play(k: number, sc: ReturnType<typeof draw>, config: ConfigOverrides): { worst: Deep | null; onTick: number } {
  const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: sc.e, ROLLING_DECEL: 0, ...config }, { capacity: sc.balls.length + 8 })
  sim.setWalls({ minX: 0, minY: 0, maxX: sc.box, maxY: sc.box, restitution: sc.e })
  const ids = sc.balls.map((b) => sim.addBall(b))
  let worst: Deep | null = null
  let onTick = 0
  for (let s = 0; s < Math.round(SECONDS / LOOK); s++) {
    sim.step(LOOK)
    sim.drainEvents()
    const st = ids.map((b) => sim.ballState(b))
    for (let i = 0; i < st.length; i++) {
      for (let j = i + 1; j < st.length; j++) {
        const p = st[i]!
        const q = st[j]!
        const depth = p.radius + q.radius - Math.hypot(p.x - q.x, p.y - q.y)
        if ((s + 1) % 32 === 0 && depth > onTick) onTick = depth
        if (depth > 0.5 * Math.min(p.radius, q.radius) && depth > (worst?.depth ?? 0)) {
          worst = { scene: k, depth, t: sim.time, radii: [p.radius, q.radius], speeds: [Math.hypot(p.vx, p.vy), Math.hypot(q.vx, q.vy)] }
        }
      }
    }
  }
  return { worst, onTick }
}

const SETTINGS: { name: string; config: ConfigOverrides; e?: number }[] = [
  { name: 'default (CONTACT_TRAVEL_HALVINGS 4)', config: {} },
  { name: 'CONTACT_TRAVEL_HALVINGS 0', config: { CONTACT_TRAVEL_HALVINGS: 0 } },
  // the same scenes with restitution 0 (balls and walls), where the tick is not halved for travel
  { name: 'restitution 0', config: {}, e: 0 },
]
const results: Record<string, { scenesWithPass: number; scenesOver1e3OnTicks: number; deepestOnTicks: number; deepest: Deep[] }> = {}
const t0 = performance.now()
for (const setting of SETTINGS) {
  const r = random(SEED * 7919 + 17)
  const found: Deep[] = []
  let overOnTicks = 0
  let deepestOnTicks = 0
  for (let k = 0; k < SCENES; k++) {
    const sc = draw(r)
    const { worst, onTick } = play(k, setting.e === undefined ? sc : { ...sc, e: setting.e }, setting.config)
    if (worst !== null) found.push(worst)
    if (onTick > 1e-3) overOnTicks++
    deepestOnTicks = Math.max(deepestOnTicks, onTick)
  }
  found.sort((a, b) => b.depth - a.depth)
  results[setting.name] = { scenesWithPass: found.length, scenesOver1e3OnTicks: overOnTicks, deepestOnTicks, deepest: found }
  console.log(`${setting.name.padEnd(36)} a ball more than half the smaller radius into another in ${found.length} of ${SCENES} scenes; at looks on a 1/120 s tick, over 1e-3 px in ${overOnTicks} (deepest ${deepestOnTicks.toExponential(2)} px)`)
  for (const d of found.slice(0, 8)) {
    console.log(`    scene ${d.scene}: ${d.depth.toFixed(2)} px at t ${d.t.toFixed(4)}, radii ${d.radii.map((x) => x.toFixed(1)).join(' / ')}, speeds ${d.speeds.map((x) => x.toFixed(0)).join(' / ')} px/s`)
  }
}
const seconds = (performance.now() - t0) / 1000
console.log(`${seconds.toFixed(0)} s`)
const file = writeResult('passes', {
  scenes: SCENES,
  seed: SEED,
  look: LOOK,
  seconds: SECONDS,
  runSeconds: seconds,
  definition: 'a scene counts when, at the end of any step of 1/3,840 s, two balls are more than half the smaller radius into each other; deepest lists each such scene\'s deepest look (radii and speeds of the two balls there); scenesOver1e3OnTicks: scenes with two balls more than 1e-3 px into each other at a look on a tick of 1/120 s (what a game stepping at 60 or 120 Hz draws), deepestOnTicks the deepest such look',
  settings: results,
})
console.log(`wrote ${file}`)
