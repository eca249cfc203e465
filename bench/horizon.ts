// How soon each moving ball could touch another, on the contacts benchmark's scenes (bench/contactScenes.ts,
// stepped with the fixed tick at its default 1/120 s for MEASURED_STEPS steps of 1/120 s): after each step,
// for every moving ball, the earliest time, in ticks, at which it could touch any other ball on the panel
// (moving or at rest), by two bounds:
//   speeds     if neither went faster than it goes now: the gap between them over the sum of their speeds
//   relative   if the pair's relative velocity changed only by the scene's rolling deceleration of each
//              moving ball (at most ROLLING_DECEL each, whatever its direction): the first time the gap
//              closes at the relative speed plus that acceleration. Holes, walls and other balls that turn
//              a ball are not counted (a schedule would have to look again at each such change), so this is
//              as far as a pair-by-pair bound can go.
// Counted, not timed. The shares say how much a broadphase could save by not pairing every moving ball at
// every tick (a list kept with a margin, a schedule per ball): a ball that could touch another within its
// next tick must be looked at this tick, one that cannot for k ticks could be looked at once in k.
// `looksPerBallTick` is that ideal: the mean over moving balls and ticks of 1 / max(1, ⌊ticks⌋), with the
// ticks capped at HORIZON. The fixed tick's cost per contact on the panel is about 2× the barest loop that
// pairs every moving ball every tick (bench/contacts.ts); a schedule that never looked at a ball needlessly
// would still look at this share of them, and each look costs more than a ball of the bare loop
// (docs/decisions.md §11: a prototype).
// Writes docs/results/horizon.json.
//
//   npm run bench:horizon
import { BallMode } from '../components/Ball'
import { gas, oursScene, panel, type Scene } from './contactScenes'
import { DT, cellGrid, cellKey, writeResult } from './lib'

const MEASURED_STEPS = 120
const TICK = 1 / 120
/** ticks counted up to this many (a ball that cannot touch another for longer counts as this) */
const HORIZON = 16
/** the shares' bounds, in ticks */
const BOUNDS = [1, 2, 4, 8, 16] as const

interface Bound {
  /** share of moving balls a step whose earliest touch is under 1, 1–2, 2–4, 4–8, 8–16 and 16 or more ticks away */
  shares: Record<string, number>
  looksPerBallTick: number
}
interface HorizonRow extends Bound {
  scene: string
  balls: number
  /** moving balls a step, on average */
  movingPerStep: number
  /** the same by the relative bound (the row's own figures are by the speeds) */
  relative: Bound
}

function measure(sc: Scene): HorizonRow {
  const sim = oursScene(sc, 'fixed', TICK)
  const B = sim.world.Ball
  const bySpeeds = new Array<number>(BOUNDS.length + 1).fill(0)
  const byRelative = new Array<number>(BOUNDS.length + 1).fill(0)
  let looks = 0
  let looksRelative = 0
  let moving = 0
  for (let s = 0; s < MEASURED_STEPS; s++) {
    sim.step(DT)
    sim.world.events.count = 0
    const ids: number[] = []
    let vMax = 0
    let rMax = 0
    for (const b of sim.balls()) {
      const m = B.mode[b]
      if (m !== BallMode.Rolling && m !== BallMode.RimRoll && m !== BallMode.Resting) continue
      ids.push(b)
      if (m !== BallMode.Resting) vMax = Math.max(vMax, Math.hypot(B.vx[b]!, B.vy[b]!))
      rMax = Math.max(rMax, B.radius[b]!)
    }
    // a grid whose cells hold every ball a moving one could reach within HORIZON ticks in the 3 × 3 around it
    // (the relative speed is at most the sum of the speeds, and the decelerations only slow the balls)
    const cell = 2 * rMax + 2 * HORIZON * TICK * vMax + 1
    const grid = cellGrid(ids, B.x, B.y, cell)
    for (const b of ids) {
      if (B.mode[b] === BallMode.Resting) continue
      moving++
      const vb = Math.hypot(B.vx[b]!, B.vy[b]!)
      let soonest: number = HORIZON
      let soonestRelative: number = HORIZON
      const cx = Math.floor(B.x[b]! / cell)
      const cy = Math.floor(B.y[b]! / cell)
      for (let dx = -1; dx <= 1; dx++) {
        for (let dy = -1; dy <= 1; dy++) {
          for (const o of grid.get(cellKey(cx + dx, cy + dy)) ?? []) {
            if (o === b) continue
            const still = B.mode[o] === BallMode.Resting
            const ovx = still ? 0 : B.vx[o]!
            const ovy = still ? 0 : B.vy[o]!
            const vo = Math.hypot(ovx, ovy)
            const gap = Math.hypot(B.x[o]! - B.x[b]!, B.y[o]! - B.y[b]!) - B.radius[b]! - B.radius[o]!
            const ticks = gap <= 0 ? 0 : gap / ((vb + vo) * TICK)
            if (ticks < soonest) soonest = ticks
            // gap = u·t + a·t²/2: u the relative speed, a the decelerations of the moving balls of the pair
            const u = Math.hypot(B.vx[b]! - ovx, B.vy[b]! - ovy)
            const a = (still ? 1 : 2) * sc.decel
            const t = gap <= 0 ? 0 : (2 * gap) / (u + Math.sqrt(u * u + 2 * a * gap))
            if (t / TICK < soonestRelative) soonestRelative = t / TICK
          }
        }
      }
      bySpeeds[binOf(soonest)]!++
      byRelative[binOf(soonestRelative)]!++
      looks += 1 / Math.max(1, Math.floor(soonest))
      looksRelative += 1 / Math.max(1, Math.floor(soonestRelative))
    }
  }
  const shares = (counts: number[]) => {
    const out: Record<string, number> = {}
    NAMES.forEach((n, i) => (out[n] = counts[i]! / moving))
    return out
  }
  return {
    scene: sc.name,
    balls: sc.balls.length,
    movingPerStep: moving / MEASURED_STEPS,
    shares: shares(bySpeeds),
    looksPerBallTick: looks / moving,
    relative: { shares: shares(byRelative), looksPerBallTick: looksRelative / moving },
  }
}

const NAMES = ['under 1', '1-2', '2-4', '4-8', '8-16', '16+']
function binOf(ticks: number): number {
  let k = 0
  while (k < BOUNDS.length && ticks >= BOUNDS[k]!) k++
  return k
}

const rows: HorizonRow[] = []
for (const make of [gas, panel]) {
  for (const n of [1000, 10_000]) {
    const row = measure(make(n))
    rows.push(row)
    const text = (b: Bound) =>
      Object.entries(b.shares)
        .map(([k, v]) => `${k} ${(100 * v).toFixed(1)} %`)
        .join(', ') + `; ideal looks a ball-tick ${b.looksPerBallTick.toFixed(2)}`
    console.log(`${row.scene.padEnd(6)} ${String(row.balls).padStart(6)} balls, ${row.movingPerStep.toFixed(0)} moving a step; ticks to the earliest touch`)
    console.log(`  by the speeds:   ${text(row)}`)
    console.log(`  by the relative: ${text(row.relative)}`)
  }
}
const json = writeResult('horizon', {
  steps: MEASURED_STEPS,
  tick: TICK,
  horizon: HORIZON,
  method: 'after each step, per moving ball: min over other balls on the panel of gap / ((its speed + theirs) · tick), capped at horizon; shares by bound; looksPerBallTick = mean of 1 / max(1, floor(ticks)). relative: the same with the first t at which gap = u·t + a·t²/2 (u the relative speed, a the scene deceleration times the moving balls of the pair), turns by holes, walls and balls not counted',
  rows,
})
console.log(`wrote ${json}`)
