// Where do bounced balls stop? docs/decisions.md §4 asks to measure it for the defaults rather than bend the
// constants. Shoots a uniform grid over the bounce region of the (δ, v) plane at one hole and prints the
// distribution of the distance from the impact point to where the ball rests, in hole widths (2R).
//   npm run bounce-distribution
import { createBallPhysics } from '../src/index'

const sim0 = createBallPhysics()
const R = sim0.config.HOLE_RADIUS
const a = sim0.config.ROLLING_DECEL
const dists: number[] = []
let outside = 0
for (let delta = 0.05; delta < R; delta += 0.1) {
  const k = Math.sqrt(1 - (delta * delta) / (R * R))
  for (let v = 600 * k; v <= 640 * k; v += 0.25) {
    const sim = createBallPhysics()
    sim.addHole({ x: 0, y: 0 })
    const lipX = -R * k
    const b = sim.addBall({ x: lipX - 40, y: delta, vx: Math.sqrt(v * v + 2 * a * 40), vy: 0 })
    let impact: { x: number; y: number } | undefined
    for (let i = 0; i < 2000; i++) {
      sim.step(1 / 500)
      const ev = sim.drainEvents()
      const bounce = ev.find((e) => e.type === 'bounce')
      if (bounce && !impact) {
        // the step is short; recover the impact point exactly from the event time on the incoming path
        const tau = bounce.time
        const v0 = Math.sqrt(v * v + 2 * a * 40)
        const s = v0 * tau - 0.5 * a * tau * tau
        impact = { x: lipX - 40 + s, y: delta }
      }
      if (ev.some((e) => e.type !== 'bounce' && e.type !== 'nearMiss')) break
    }
    const st = sim.ballState(b)
    if (!impact || st.mode !== 'resting') continue
    if (Math.hypot(st.x, st.y) >= R) outside++
    dists.push(Math.hypot(st.x - impact.x, st.y - impact.y) / (2 * R))
  }
}
dists.sort((p, q) => p - q)
const q = (f: number) => dists[Math.min(dists.length - 1, Math.floor(f * dists.length))]!
const within = (w: number) => ((100 * dists.filter((d) => d <= w).length) / dists.length).toFixed(1)
console.log(`bounces: ${dists.length} over the bounce region, ROLLING_DECEL = ${a} px/s²; ended outside the hole: ${outside}`)
console.log(`stop distance from impact, hole widths (36 px): min ${q(0).toFixed(2)}, median ${q(0.5).toFixed(2)}, p90 ${q(0.9).toFixed(2)}, max ${q(1).toFixed(2)}`)
console.log(`within 1 hole width: ${within(1)} %, within 2: ${within(2)} %, within 4: ${within(4)} %`)
