// One hole far wider than the rest: 1,000 balls rolling (200–600 px/s, the design's deceleration) over
// 3,600 holes of 18 px at a 60 px pitch, with and without one more hole of radius 1e4 far off the field.
// The hole grid keeps up to 16 holes more than 4× the median radius out of its cells (src/world/holeGrid.ts);
// sized for the wide hole, its cells held every hole of the field, and every path planned scanned them all.
// And the same field after one ball of radius 1e4 was put down and stepped once and removed: the cells
// were sized for the widest ball planned, and kept that size for good; they now serve any ball from the
// widest hole's radius on (a ball no smaller than a hole rolls over it).
// Median step time of steps 30–149 at 1/120 s, ROUNDS rounds alternating the three scenes in one process;
// each ratio is that scene ÷ the field alone (the denominator: the same field with neither, same rounds).
// Prints and writes docs/results/big-hole.json; asserts nothing.
//
//   npm run bench:big-hole
import { addHoles } from '../src/ecs'
import { createBallPhysics } from '../src/index'
import { DT, collectGarbage, median, random, writeResult } from './lib'

const ROUNDS = 7
const BALLS = 1000

/** Median µs a step of the scene: the field alone, with the wide hole, or after the wide ball. */
function run(scene: 'field' | 'wideHole' | 'wideBall'): number {
  const sim = createBallPhysics()
  const holes: { x: number; y: number; radius?: number }[] = []
  for (let i = 0; i < 60; i++) for (let j = 0; j < 60; j++) holes.push({ x: 30 + 60 * i, y: 30 + 60 * j })
  if (scene === 'wideHole') holes.push({ x: 50_000, y: 50_000, radius: 1e4 })
  addHoles(sim.world, holes)
  if (scene === 'wideBall') {
    const wide = sim.addBall({ x: 50_000, y: 50_000, radius: 1e4, vx: 10, vy: 0 })
    sim.step(DT)
    sim.removeBall(wide)
  }
  const r = random(3)
  for (let k = 0; k < BALLS; k++) {
    const a = 2 * Math.PI * r()
    const v = 200 + 400 * r()
    sim.addBall({ x: 3600 * r(), y: 3600 * r(), vx: v * Math.cos(a), vy: v * Math.sin(a) })
  }
  collectGarbage()
  const times: number[] = []
  for (let s = 0; s < 150; s++) {
    const t = performance.now()
    sim.step(DT)
    if (s >= 30) times.push((performance.now() - t) * 1000)
    sim.drainEventsWith(() => {})
  }
  return median(times)
}

const without: number[] = []
const withWide: number[] = []
const afterBall: number[] = []
for (let k = 0; k < ROUNDS; k++) {
  without.push(run('field'))
  withWide.push(run('wideHole'))
  afterBall.push(run('wideBall'))
}
const a = median(without)
const b = median(withWide)
const c = median(afterBall)
console.log(`1,000 balls over 3,600 holes: ${a.toFixed(1)} µs a step; with one hole of radius 1e4 far off: ${b.toFixed(1)} µs (${(b / a).toFixed(2)}×, the field alone the denominator)`)
console.log(`after one ball of radius 1e4 was put down and removed: ${c.toFixed(1)} µs (${(c / a).toFixed(2)}×, the same denominator)`)
console.log(`rounds (field / wide hole / after the wide ball): ${without.map((t, i) => `${t.toFixed(0)}/${withWide[i]!.toFixed(0)}/${afterBall[i]!.toFixed(0)}`).join(' ')}`)
writeResult('big-hole', {
  balls: BALLS,
  holes: 3600,
  rounds: ROUNDS,
  usPerStepWithout: a,
  usPerStepWith: b,
  ratio: b / a,
  usPerStepAfterWideBall: c,
  ratioAfterWideBall: c / a,
  roundsWithout: without,
  roundsWith: withWide,
  roundsAfterWideBall: afterBall,
})
