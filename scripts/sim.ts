// Headless run of the built-in panel: throws a game's worth of balls (seeded, so every run is the same),
// steps at 120 Hz until every ball has stopped, and prints what happened.
//   npm run sim                      10 balls, seed 1
//   npm run sim -- --balls 1000 --seed 7 --quiet
import { DEFAULT_PANEL, addPanel, createBallPhysics, createFixedStepClock, type BallEvent } from '../src/index'

function arg(name: string, fallback: number): number {
  const i = process.argv.indexOf(`--${name}`)
  if (i < 0) return fallback
  const v = Number(process.argv[i + 1])
  if (!Number.isFinite(v)) throw new RangeError(`--${name} must be a number, got ${process.argv[i + 1]}`)
  return v
}
const balls = arg('balls', 10)
const seed = arg('seed', 1)
const quiet = process.argv.includes('--quiet')
if (!Number.isInteger(balls) || balls < 1 || balls > 1e6) throw new RangeError(`--balls must be an integer in [1, 1000000], got ${balls}`)

let state = seed >>> 0 || 1
const rand = () => {
  state = (state * 16807) % 2147483647
  return (state - 1) / 2147483646
}

const sim = createBallPhysics({}, { capacity: balls + 64 })
const holes = addPanel(sim)
const valueOf = new Map(holes.map((h) => [h, sim.holeState(h).value]))
const throws = new Map<number, { power: number; angle: number }>()
for (let i = 0; i < balls; i++) {
  const power = rand()
  const angle = (rand() - 0.5) * 0.9
  throws.set(sim.throwBall({ x: DEFAULT_PANEL.launch.x, y: DEFAULT_PANEL.launch.y, power, angle }), { power, angle })
}

const clock = createFixedStepClock({ hz: 120 })
const events: BallEvent[] = []
const fmt = (n: number | undefined, d = 1) => (n === undefined ? '' : n.toFixed(d))
while (sim.balls().some((b) => ['rolling', 'rimRoll'].includes(sim.ballState(b).mode)) && sim.time < 60) {
  clock.advance(1 / 60, (dt) => sim.step(dt))
  for (const e of sim.drainEvents()) {
    events.push(e)
    if (!quiet) {
      const t = throws.get(e.ball)!
      const where = e.hole === undefined ? '' : ` hole ${e.hole} (${valueOf.get(e.hole)} pts)`
      const dv = e.delta === undefined ? '' : ` δ = ${fmt(e.delta, 2)} px, v = ${fmt(e.speed)} px/s`
      console.log(
        `t = ${e.time.toFixed(4)} s  ball ${e.ball} (power ${t.power.toFixed(2)}, aim ${fmt((t.angle * 180) / Math.PI)}°)  ${e.type}${e.via ? ` via ${e.via}` : ''}${where}${dv}`,
      )
    }
  }
}

const count = (type: string, via?: string) => events.filter((e) => e.type === type && (via === undefined || e.via === via)).length
const score = events.filter((e) => e.type === 'capture').reduce((s, e) => s + (valueOf.get(e.hole!) ?? 0), 0)
console.log(`\n${balls} balls on the default ${DEFAULT_PANEL.holes.length}-hole panel, simulated ${sim.time.toFixed(2)} s`)
console.log(
  `captured ${count('capture')} (clean ${count('capture', 'clean')}, after a rim roll ${count('capture', 'rimRoll')}, at rest over a hole ${count('capture', 'rest')}), at rest on the panel ${count('rest')}`,
)
console.log(`skips ${count('skip')}, bounces ${count('bounce')}, rim rolls ${count('rimRoll')}, lip-outs ${count('lipOut')}, near misses ${count('nearMiss')}`)
console.log(`score ${score}`)
