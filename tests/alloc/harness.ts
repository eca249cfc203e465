// What tests/allocation.test.ts and the scenes it runs as bundles in processes of their own
// (tests/alloc/*Main.ts) share: the skipping scene, and a window of steps timed by the heap's growth.
import { PerformanceObserver } from 'node:perf_hooks'
import { DEFAULT_PANEL, createBallPhysics, type BallPhysics } from '../../src/index.js'

/**
 * Tiles of the default panel side by side in closed walls, n balls at 1,200 px/s (above every capture speed)
 * and no deceleration: they skip over holes, miss them and bounce off the walls for ever, 70 events a step.
 */
export function skipping(n: number): BallPhysics {
  let seed = 99
  const random = (): number => ((seed = (seed * 16807) % 2147483647) - 1) / 2147483646
  const W = DEFAULT_PANEL.width
  const H = DEFAULT_PANEL.height
  const sim = createBallPhysics({ ROLLING_DECEL: 0 }, { capacity: n + 8 })
  sim.setWalls({ minX: 0, minY: 0, maxX: 5 * W, maxY: 5 * H, restitution: 0.9 })
  for (let t = 0; t < 25; t++) for (const h of DEFAULT_PANEL.holes) sim.addHole({ x: h.x + (t % 5) * W, y: h.y + Math.floor(t / 5) * H })
  for (let i = 0; i < n; i++) {
    const a = random() * 2 * Math.PI
    sim.addBall({ x: 5 * W * random(), y: 5 * H * random(), vx: 1200 * Math.cos(a), vy: 1200 * Math.sin(a) })
  }
  return sim
}

/** Steps at 1/120 s, the events dropped. */
export function run(sim: BallPhysics, steps: number): void {
  for (let s = 0; s < steps; s++) {
    sim.step(1 / 120)
    sim.world.events.count = 0
  }
}

let collections = 0
let observing = false

/**
 * One window of `steps` steps at 1/120 s after a collection (run with --expose-gc): the heap's growth, the
 * moving ball-steps, and whether no collection ran in it (else the growth means nothing).
 */
export async function heapWindow(sim: BallPhysics, steps: number): Promise<{ grown: number; ballSteps: number; clean: boolean }> {
  if (!observing) {
    new PerformanceObserver((list) => {
      collections += list.getEntries().length
    }).observe({ entryTypes: ['gc'] })
    observing = true
  }
  ;(globalThis as unknown as { gc: () => void }).gc()
  await new Promise((r) => setTimeout(r, 10))
  const seen = collections
  let ballSteps = 0
  const before = process.memoryUsage().heapUsed
  for (let s = 0; s < steps; s++) {
    ballSteps += sim.world.moving.count
    sim.step(1 / 120)
    sim.world.events.count = 0
  }
  const grown = process.memoryUsage().heapUsed - before
  await new Promise((r) => setTimeout(r, 10))
  return { grown, ballSteps, clean: collections === seen }
}
