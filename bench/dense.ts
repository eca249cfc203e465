// Dense events with recycling: N balls rolling with the design's deceleration over 25 holes on a
// 400 × 400 panel (contacts off); every 10 steps the captured and stopped balls are removed and as many new
// ones thrown in, so ids are recycled and the moving set churns. ns per ball-step: the median of steps
// 200–599 (performance.now() around each step, the refill outside it), at 1,000, 10,000 and 100,000 balls,
// twice in the same run: as the schedule runs it (the moving balls put back in id order once a sixteenth
// of them have changed: src/world/idLists.ts, orderMoving), and with that ordering held off (the scattered
// order swap-removals and recycled ids leave). Prints and writes docs/results/dense.json; asserts nothing.
//
//   npm run bench:dense
import { createBallPhysics } from '../src/index'
import { collectGarbage, random, writeResult } from './lib'

const SIZES = [1_000, 10_000, 100_000]
const STEPS = 600
const FROM = 200

function run(n: number, ordered: boolean): number {
  const r = random(5)
  const sim = createBallPhysics({ ROLLING_DECEL: 300 }, { capacity: n + 64 })
  for (let i = 0; i < 5; i++) for (let j = 0; j < 5; j++) sim.addHole({ x: 40 + 80 * i, y: 40 + 80 * j })
  const spawn = () => {
    const a = r() * 2 * Math.PI
    const v = 200 + 400 * r()
    sim.addBall({ x: r() * 400, y: r() * 400, vx: v * Math.cos(a), vy: v * Math.sin(a) })
  }
  for (let i = 0; i < n; i++) spawn()
  const w = sim.world
  const B = w.Ball
  const times: number[] = []
  collectGarbage()
  for (let step = 0; step < STEPS; step++) {
    if (!ordered) w.moving.churn = 0
    const t0 = performance.now()
    sim.step(1 / 60)
    times.push(performance.now() - t0)
    w.events.count = 0
    if (step % 10 === 9) {
      const gone: number[] = []
      for (const b of sim.balls()) if (B.mode[b] === 2 || B.mode[b] === 3) gone.push(b)
      for (const b of gone) sim.removeBall(b)
      for (let i = 0; i < gone.length; i++) spawn()
    }
  }
  const late = times.slice(FROM).sort((a, b) => a - b)
  return (late[late.length >> 1]! * 1e6) / n
}

const rows = SIZES.map((n) => {
  const scattered = run(n, false)
  const ordered = run(n, true)
  console.log(`${n.toLocaleString('en-US').padStart(9)} balls: ${ordered.toFixed(1)} ns per ball-step (${scattered.toFixed(1)} with the order held off)`)
  return { balls: n, ordered, scattered }
})
const at = (n: number) => rows.find((r) => r.balls === n)!
const growth = { ordered: at(100_000).ordered / at(10_000).ordered, scattered: at(100_000).scattered / at(10_000).scattered }
console.log(`100,000 / 10,000: ${growth.ordered.toFixed(2)}× (${growth.scattered.toFixed(2)}× with the order held off)`)
console.log(
  `wrote ${writeResult('dense', {
    steps: STEPS,
    measuredFrom: FROM,
    timing: 'performance.now() around each step; median of the steps from measuredFrom on',
    scene: '25 holes 80 px apart on a 400 x 400 panel, ROLLING_DECEL 300, contacts off; every 10 steps the captured and stopped balls replaced',
    rows,
    growth100kOver10k: growth,
  })}`,
)
