// When the holes or the walls change, rolling balls continue from where they are now on a path planned
// against the new scene.
import { BallMode } from '../../components/Ball.js'
import { startAt, planRolling, sampleRolling, startPath } from '../motion/rolling.js'
import { forEachBall } from '../world/balls.js'
import { keepMeet } from '../contacts/fixedMeet.js'
import type { BallWorld } from '../world/createWorld.js'

/** Re-plans every rolling ball from its state at the world's time. */
export function replanRolling(w: BallWorld): void {
  forEachBall(w, (b) => {
    if (w.Ball.mode[b] !== BallMode.Rolling) return
    // a fixed tick's pair that meets at its instant (src/contacts/fixedMeet.ts) still does
    const meet = w.meet === null ? 0 : w.meet.with[b]!
    sampleRolling(w, b, w.time)
    startAt(w.Ball.x[b]!, w.Ball.y[b]!, w.Ball.vx[b]!, w.Ball.vy[b]!, w.time)
    startPath(w, b)
    planRolling(w, b)
    if (meet !== 0) keepMeet(w, b, meet)
  })
}
