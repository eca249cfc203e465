// Bundled (the module's own code, its packages imported) and run in a Node process of its own by
// tests/allocation.test.ts, as a game runs the module: the test runner's transform keeps each module apart,
// and V8 inlines differently there (the boxing this checks for did not show under it, nor in a bundle that
// took bitecs in, nor after a shorter warm-up). Light balls pumped by heavy ones in a small closed box
// under the fixed tick: 240 balls of mass 100 at 600 px/s and 480 of mass 0.01 and radius 4 at 50 px/s,
// restitution 1, no speed limit. The tick is halved four times (16 ticks a step) and at every tick the
// solve gives hundreds of balls a new path. A throwaway box runs first (V8 optimises on what it has seen),
// then a fresh one is measured over windows of WINDOW steps, each after a collection.
// Prints one line of JSON: the heap's growth per ball-step and per contact tick in each window (NaN: a
// collection ran in it), the moving balls, and the ticks a step.
import { MAX_SPEED, createBallPhysics, type BallPhysics } from '../../src/index.js'
import { heapWindow, run } from './harness.js'

const WINDOW = 60
/** CONTACT_TIMING from the environment ('instant': the pairs alone at their tick meet at their instant, src/contacts/fixedMeet.ts) */
const TIMING = process.env.CONTACT_TIMING === 'instant' ? 'instant' : 'auto'

function pumpedBox(): BallPhysics {
  let seed = 3
  const random = (): number => ((seed = (seed * 16807) % 2147483647) - 1) / 2147483646
  const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 1, ROLLING_DECEL: 0, CONTACT_SPEED_LIMIT: MAX_SPEED, CONTACT_TIMING: TIMING }, { capacity: 730 })
  sim.setWalls({ minX: 0, minY: 0, maxX: 600, maxY: 600, restitution: 1 })
  for (let i = 0; i < 240; i++) {
    const a = random() * 6.283
    sim.addBall({ x: 20 + 560 * random(), y: 20 + 560 * random(), vx: 600 * Math.cos(a), vy: 600 * Math.sin(a), mass: 100 })
  }
  for (let i = 0; i < 480; i++) {
    const a = random() * 6.283
    sim.addBall({ x: 20 + 560 * random(), y: 20 + 560 * random(), vx: 50 * Math.cos(a), vy: 50 * Math.sin(a), mass: 0.01, radius: 4 })
  }
  return sim
}

run(pumpedBox(), 2000)
const sim = pumpedBox()
run(sim, 600)
const F = sim.world.fixed!
const perBallStep: number[] = []
const perTick: number[] = []
const ticks0 = F.ticks
for (let w = 0; w < 6; w++) {
  const ticks = F.ticks
  const { grown, ballSteps, clean } = await heapWindow(sim, WINDOW)
  perBallStep.push(clean ? grown / ballSteps : NaN)
  perTick.push(clean ? grown / (F.ticks - ticks) : NaN)
}
console.log(JSON.stringify({ perBallStep, perTick, moving: sim.world.moving.count, ticksPerStep: (F.ticks - ticks0) / (6 * WINDOW), timed: sim.world.meet!.timed }))
