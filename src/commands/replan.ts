// When the holes or the walls change, rolling balls continue from where they are now on a path planned
// against the new scene.
import { BallMode } from '../../components/Ball.js'
import { pathStart, PS_T, PS_VX, PS_VY, PS_X, PS_Y, planRolling, sampleRolling, startPath } from '../motion/rolling.js'
import { forEachBall } from '../world/balls.js'
import type { BallWorld } from '../world/createWorld.js'

/** Re-plans every rolling ball from its state at the world's time. */
export function replanRolling(w: BallWorld): void {
  forEachBall(w, (b) => {
    if (w.Ball.mode[b] !== BallMode.Rolling) return
    sampleRolling(w, b, w.time)
    pathStart[PS_X] = w.Ball.x[b]!
    pathStart[PS_Y] = w.Ball.y[b]!
    pathStart[PS_VX] = w.Ball.vx[b]!
    pathStart[PS_VY] = w.Ball.vy[b]!
    pathStart[PS_T] = w.time
    startPath(w, b)
    planRolling(w, b)
  })
}
