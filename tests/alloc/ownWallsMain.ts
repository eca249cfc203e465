// Bundled and run in a Node process of its own by tests/allocation.test.ts, as a game runs the module: the
// skipping scene of that file (1,000 balls at 1,200 px/s over 25 tiles of the default panel in closed walls,
// no deceleration) with the walls stage a game's own, written with the ecs entry's checked functions
// (pushEvent, launchBall). In the test runner's process it ran well, but the scene after it there (the
// pressed pile) then allocated 140–400 bytes a ball-step against its 15–37: V8's code for the shared motion
// functions, optimised for a second caller, was compiled again within that scene's short windows. Run here,
// each scene is measured in the process it warmed up in.
// Prints one line of JSON: the heap's growth per ball-step in each window (null: a collection ran in it),
// the moving balls, and how many wall hits the game's stage handled.
import type { BallPhysics } from '../../src/index.js'
import { EventType, HOT, H_NEXT_T, PathEvent, WallEdge, launchBall, pushEvent, type BallWorld } from '../../src/ecs.js'
import { heapWindow, run, skipping } from './harness.js'

const N = 1000
const WINDOW = 300
let hits = 0

function scene(): BallPhysics {
  const sim = skipping(N)
  // the default's bounce off a closed wall (systems/walls.ts), as a game would write it
  const own = (w: BallWorld): void => {
    const P = w.Path
    const B = w.Ball
    const list = w.marked
    for (let i = 0; i < list.count; i++) {
      const eid = list.ids[i]!
      if (P.mark[eid] !== PathEvent.Wall) continue
      // (launchBall clears the mark: the ball leaves its event)
      const t = w.pathHot[eid * HOT + H_NEXT_T]!
      const edge = P.markEdge[eid]!
      const horizontal = edge === WallEdge.Left || edge === WallEdge.Right
      hits++
      pushEvent(w.events, EventType.Wall, eid, 0, t, false, 0, 0)
      launchBall(w, eid, B.x[eid]!, B.y[eid]!, horizontal ? -0.9 * B.vx[eid]! : B.vx[eid]!, horizontal ? B.vy[eid]! : -0.9 * B.vy[eid]!, t)
    }
  }
  sim.schedule.splice(sim.schedule.findIndex((e) => e.name === 'walls'), 0, { name: 'ownWalls', run: own })
  return sim
}

run(scene(), 1500)
const sim = scene()
run(sim, 300)
hits = 0
const perBallStep: (number | null)[] = []
for (let w = 0; w < 4; w++) {
  const { grown, ballSteps, clean } = await heapWindow(sim, WINDOW)
  perBallStep.push(clean ? grown / ballSteps : null)
}
console.log(JSON.stringify({ perBallStep, moving: sim.world.moving.count, hits }))
