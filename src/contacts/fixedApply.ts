// The fixed-tick method's last act at a tick: every ball the solve (src/contacts/fixedSolve.ts) or the
// projection (fixedProject.ts) changed starts a fresh path from its new state at the tick (a ball on a rim
// or in a hole's lock is in transit there, as after a contact in the exact method); a resting ball wakes
// only if it leaves at BALL_SETTLE_SPEED or more.
import { BallMode } from '../../components/Ball.js'
import { launchBall, placeBall } from '../motion/ballFate.js'
import { pathStart, PS_T, PS_VX, PS_VY, PS_X, PS_Y } from '../motion/rolling.js'
import type { BallWorld } from '../world/createWorld.js'
import { touchBall, type FixedContactState } from '../world/fixedState.js'
import { holeAt } from '../world/holeTable.js'
import { restingInsert, restingRemove } from '../world/restingGrid.js'
import { strikeLeavesRim } from './law.js'

/** Gives every changed ball a fresh path from its state at the tick, the world's time (see above). */
export function applyChanges(w: BallWorld, F: FixedContactState): void {
  const B = w.Ball
  const t = w.time
  const settle = w.config.BALL_SETTLE_SPEED
  for (let i = 0; i < F.n; i++) {
    const c = F.changed[i]!
    if (c === 0) continue
    const eid = F.id[i]!
    if ((c & 2) !== 0) touchBall(F, eid)
    const vx = F.vx[i]!
    const vy = F.vy[i]!
    // pathStart written here, not through startAt: where V8 does not inline that call, its five doubles
    // were boxed for every ball the solve changed (5 bytes a ball-step on the gas)
    pathStart[PS_X] = F.x[i]!
    pathStart[PS_Y] = F.y[i]!
    pathStart[PS_VX] = vx
    pathStart[PS_VY] = vy
    pathStart[PS_T] = t
    if (B.mode[eid] === BallMode.Resting) {
      if (Math.sqrt(vx * vx + vy * vy) >= settle) launchBall(w, eid)
      else if ((c & 2) !== 0) moveResting(w, eid)
      continue
    }
    strikeLeavesRim(w, eid)
    launchBall(w, eid)
  }
}

/** A resting ball the projection moved (to pathStart's position): it stays at rest there. */
function moveResting(w: BallWorld, eid: number): void {
  const x = pathStart[PS_X]!
  const y = pathStart[PS_Y]!
  restingRemove(w, eid)
  w.Ball.x[eid] = x
  w.Ball.y[eid] = y
  // pushed over a hole, it falls in (in transit there, it stops inside the lip circle)
  if (holeAt(w, x, y, w.Ball.radius[eid]!) !== 0) {
    placeBall(w, eid, x, y, 0, 0, pathStart[PS_T]!)
    return
  }
  restingInsert(w, eid)
}
