// How soon each moving ball could touch another, on the contacts benchmark's scenes (bench/contactScenes.ts,
// stepped with the fixed tick at its default 1/120 s for MEASURED_STEPS steps of 1/120 s): after each step,
// for every moving ball, the earliest time, in ticks, at which it could touch any other ball on the panel
// (moving or at rest) if neither went faster than it goes now: the gap between them over the sum of their
// speeds. Counted, not timed. The shares say how much a broadphase could save by not pairing every moving
// ball at every tick (a list kept with a margin, a schedule per ball): a ball that could touch another
// within its next tick must be looked at this tick, one that cannot for k ticks could be looked at once in
// k. `looksPerBallTick` is that ideal: the mean over moving balls and ticks of 1 / max(1, ⌊ticks⌋), with
// the ticks capped at HORIZON. The fixed tick's cost per contact on the panel is about 2× the barest loop
// that pairs every moving ball every tick (bench/contacts.ts); a schedule that never looked at a ball
// needlessly would still look at this share of them.
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

interface HorizonRow {
  scene: string
  balls: number
  /** moving balls a step, on average */
  movingPerStep: number
  /** share of moving balls a step whose earliest touch is under 1, 1–2, 2–4, 4–8, 8–16 and 16 or more ticks away */
  shares: Record<string, number>
  looksPerBallTick: number
}

function measure(sc: Scene): HorizonRow {
  const sim = oursScene(sc, 'fixed', TICK)
  const B = sim.world.Ball
  const counts = new Array<number>(BOUNDS.length + 1).fill(0)
  let looks = 0
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
    const cell = 2 * rMax + 2 * HORIZON * TICK * vMax + 1
    const grid = cellGrid(ids, B.x, B.y, cell)
    for (const b of ids) {
      const m = B.mode[b]
      if (m === BallMode.Resting) continue
      moving++
      const vb = Math.hypot(B.vx[b]!, B.vy[b]!)
      let soonest: number = HORIZON
      const cx = Math.floor(B.x[b]! / cell)
      const cy = Math.floor(B.y[b]! / cell)
      for (let dx = -1; dx <= 1; dx++) {
        for (let dy = -1; dy <= 1; dy++) {
          for (const o of grid.get(cellKey(cx + dx, cy + dy)) ?? []) {
            if (o === b) continue
            const vo = B.mode[o] === BallMode.Resting ? 0 : Math.hypot(B.vx[o]!, B.vy[o]!)
            const gap = Math.hypot(B.x[o]! - B.x[b]!, B.y[o]! - B.y[b]!) - B.radius[b]! - B.radius[o]!
            const ticks = gap <= 0 ? 0 : gap / ((vb + vo) * TICK)
            if (ticks < soonest) soonest = ticks
          }
        }
      }
      let k = 0
      while (k < BOUNDS.length && soonest >= BOUNDS[k]!) k++
      counts[k]!++
      looks += 1 / Math.max(1, Math.floor(soonest))
    }
  }
  const names = ['under 1', '1-2', '2-4', '4-8', '8-16', '16+']
  const shares: Record<string, number> = {}
  names.forEach((n, i) => (shares[n] = counts[i]! / moving))
  return { scene: sc.name, balls: sc.balls.length, movingPerStep: moving / MEASURED_STEPS, shares, looksPerBallTick: looks / moving }
}

const rows: HorizonRow[] = []
for (const make of [gas, panel]) {
  for (const n of [1000, 10_000]) {
    const row = measure(make(n))
    rows.push(row)
    const shares = Object.entries(row.shares)
      .map(([k, v]) => `${k} ${(100 * v).toFixed(1)} %`)
      .join(', ')
    console.log(`${row.scene.padEnd(6)} ${String(row.balls).padStart(6)} balls, ${row.movingPerStep.toFixed(0)} moving a step; ticks to the earliest touch: ${shares}; ideal looks a ball-tick ${row.looksPerBallTick.toFixed(2)}`)
  }
}
const json = writeResult('horizon', {
  steps: MEASURED_STEPS,
  tick: TICK,
  horizon: HORIZON,
  method: 'after each step, per moving ball: min over other balls on the panel of gap / ((its speed + theirs) · tick), capped at horizon; shares by bound; looksPerBallTick = mean of 1 / max(1, floor(ticks))',
  rows,
})
console.log(`wrote ${json}`)
