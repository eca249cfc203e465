// A heavy ball struck into a resting pile: how much kinetic energy each contact method keeps.
//   A 5 × 5 pile of default balls (radius 11, mass 1) at rest in the corner of a closed 420 × 480 px box,
//   its outer balls touching the walls and the balls touching one another (gap 0) or 2 px apart, struck by one ball of mass 1, 4, 10 or 100
//   at 850 px/s from (100, 100) toward the corner; balls and walls of restitution 1, 0.9 or 0.5, no rolling
//   deceleration, no holes; 2 s at 120 Hz. The striker starts at AIMS points along the line x + y = 200
//   (up to 15 px either side of (100, 100)): a pile's outcome turns on where it is struck. With restitution
//   1 nothing may lose energy, so the share kept is the error itself; below 1, the exact method is the
//   reference.
// Prints and writes, for each scene, the share of the striker's kinetic energy the balls keep after 2 s
// (the mean and the least over the aims) with the exact method, the fixed tick at its default CONTACT_TICK (1/120 s) and at 1/480 s, and the fixed
// tick's impulses closed inelastically past their restitution visits (world.fixed.inelastic).
// Writes docs/results/pile-strike.json.
//
//   npm run bench:pile-strike
import { createBallPhysics, type BallPhysics } from '../src/index'
import { writeResult } from './lib'

const DT = 1 / 120
const STEPS = 240
const SPEED = 850
const RADIUS = 11
const MASSES = [1, 4, 10, 100]
const RESTITUTIONS = [1, 0.9, 0.5]
const GAPS = [0, 2]
const AIMS = 7

interface Setting {
  name: 'exact' | 'fixed' | 'fixed480'
  collisions: 'on' | 'fixed'
  tick?: number
}
const SETTINGS: Setting[] = [
  { name: 'exact', collisions: 'on' },
  { name: 'fixed', collisions: 'fixed' },
  { name: 'fixed480', collisions: 'fixed', tick: 1 / 480 },
]

export interface PileStrikeRow {
  mass: number
  restitution: number
  gap: number
  /** kinetic energy after 2 s over the striker's at the start, by setting: the mean and the least over the aims */
  kept: Record<Setting['name'], number>
  least: Record<Setting['name'], number>
  /** world.fixed.inelastic at the end, summed over the aims, by fixed-tick setting */
  inelastic: { fixed: number; fixed480: number }
}

/** Kinetic energy of every ball, by the masses the contact method holds. */
function kinetic(sim: BallPhysics): number {
  const mass = sim.world.fixed?.mass ?? sim.world.collide!.mass
  let k = 0
  for (const b of sim.balls()) {
    const s = sim.ballState(b)
    k += 0.5 * mass[b]! * (s.vx * s.vx + s.vy * s.vy)
  }
  return k
}

function run(setting: Setting, mass: number, e: number, gap: number, aim: number): { kept: number; inelastic: number } {
  const sim = createBallPhysics({
    BALL_COLLISIONS: setting.collisions,
    BALL_RESTITUTION: e,
    ROLLING_DECEL: 0,
    ...(setting.tick === undefined ? {} : { CONTACT_TICK: setting.tick }),
  })
  sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: e })
  for (let i = 0; i < 5; i++) {
    for (let j = 0; j < 5; j++) {
      sim.addBall({ x: 420 - RADIUS - i * (2 * RADIUS + gap), y: 480 - RADIUS - j * (2 * RADIUS + gap), vx: 0, vy: 0 })
    }
  }
  const off = -15 + (30 * aim) / (AIMS - 1)
  sim.addBall({ x: 100 + off, y: 100 - off, vx: SPEED * Math.SQRT1_2, vy: SPEED * Math.SQRT1_2, mass })
  const k0 = kinetic(sim)
  for (let s = 0; s < STEPS; s++) sim.step(DT)
  return { kept: kinetic(sim) / k0, inelastic: sim.world.fixed?.inelastic ?? 0 }
}

const rows: PileStrikeRow[] = []
const f = (v: number): string => v.toFixed(3)
for (const gap of GAPS) {
  for (const e of RESTITUTIONS) {
    for (const mass of MASSES) {
      const row: PileStrikeRow = { mass, restitution: e, gap, kept: { exact: 0, fixed: 0, fixed480: 0 }, least: { exact: Infinity, fixed: Infinity, fixed480: Infinity }, inelastic: { fixed: 0, fixed480: 0 } }
      for (let aim = 0; aim < AIMS; aim++) {
        for (const setting of SETTINGS) {
          const r = run(setting, mass, e, gap, aim)
          row.kept[setting.name] += r.kept / AIMS
          row.least[setting.name] = Math.min(row.least[setting.name], r.kept)
          if (setting.name !== 'exact') row.inelastic[setting.name] += r.inelastic
        }
      }
      rows.push(row)
      const { kept, least } = row
      console.log(
        `gap ${gap} px, e ${e}, striker mass ${mass}: energy kept (mean, least of ${AIMS} aims) exact ${f(kept.exact)}, ${f(least.exact)}; ` +
          `fixed ${f(kept.fixed)}, ${f(least.fixed)}; fixed 1/480 s ${f(kept.fixed480)}, ${f(least.fixed480)}; inelastic impulses ${row.inelastic.fixed} (${row.inelastic.fixed480})`,
      )
    }
  }
}

const file = writeResult('pile-strike', {
  scene: `a 5 × 5 pile of radius-${RADIUS} balls of mass 1 at rest in the corner of a closed 420 × 480 px box (its outer balls touching the walls, gap px between its balls), struck by one ball of the given mass at ${SPEED} px/s toward the corner from ${AIMS} points along x + y = 200, 5 px apart in x; balls and walls of the given restitution; no deceleration; ${STEPS} steps of 1/120 s`,
  kept: 'kinetic energy of every ball after the run over the striker\'s at the start, the mean over the aims (least: the least); exact: BALL_COLLISIONS \'on\'; fixed: \'fixed\' at the default CONTACT_TICK (1/120 s); fixed480: at 1/480 s',
  inelastic: 'world.fixed.inelastic at the end: impulses closed inelastically past RESTITUTION_VISITS (or MAX_TICK_CONTACTS) though restitution > 0',
  rows,
})
console.log(`wrote ${file}`)
