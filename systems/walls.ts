// Panel walls (not a design stage: the panel's frame). Runs only for worlds that have walls.
//   closed wall: v_n' = −e_wall·v_n, tangential speed kept      open edge: the ball leaves (the gutter)
// The hit is a path event like the others (the centre one radius from the wall), found exactly.
// Reads Path.mark, Ball, Walls; writes Ball, Path (a ball out of the panel gives back its RimContact slot);
// emits 'wall' and 'gutter'.
import { BallMode } from '../components/Ball.js'
import { PathEvent } from '../components/Path.js'
import { WallEdge } from '../components/Walls.js'
import { EventType, appendEvent } from '../src/events.js'
import { NEVER } from '../src/config/tolerances.js'
import { PS_T, PS_VX, PS_VY, PS_X, PS_Y, pathStart, planRolling, startPath } from '../src/motion/rolling.js'
import { releaseRim } from '../src/world/rimSlots.js'
import { removeMoving } from '../src/world/idLists.js'
import { type BallWorld } from '../src/world/createWorld.js'
import { setBallMode } from '../src/world/ballMode.js'
import { H_NEXT_T, HOT, setNextT } from '../src/world/pathHot.js'
import { outsideStep } from '../src/world/system.js'

export function wallsSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('wallsSystem', w)
  if (w.walls === 0) return
  const P = w.Path
  const B = w.Ball
  const e = w.Walls.restitution[w.walls]!
  const settle = w.collide === null ? 0 : w.config.BALL_SETTLE_SPEED
  const list = w.marked
  for (let i = 0; i < list.count; i++) {
    const eid = list.ids[i]!
    const mark = P.mark[eid]
    if (mark === PathEvent.Wall) {
      P.mark[eid] = PathEvent.None
      const edge = P.markEdge[eid]!
      const t = w.pathHot[eid * HOT + H_NEXT_T]!
      const horizontal = edge === WallEdge.Left || edge === WallEdge.Right
      // with contacts on, a ball pressed to the wall by others slides along it instead of bouncing forever
      const vn = horizontal ? B.vx[eid]! : B.vy[eid]!
      // a ball wider than its box on this axis (both faces closed) would meet the far face at once, and
      // again, for ever at one instant: it stays wedged on this axis
      const W = w.Walls
      const lo = horizontal ? W.minX[w.walls]! : W.minY[w.walls]!
      const hi = horizontal ? W.maxX[w.walls]! : W.maxY[w.walls]!
      const both = horizontal ? WallEdge.Left | WallEdge.Right : WallEdge.Top | WallEdge.Bottom
      const wedged = (W.open[w.walls]! & both) === 0 && hi - lo <= 2 * B.radius[eid]!
      const k = wedged || Math.abs(vn) < settle ? 0 : -e
      const vx = horizontal ? k * vn : B.vx[eid]!
      const vy = horizontal ? B.vy[eid]! : k * vn
      const ev = appendEvent(w.events, EventType.Wall, eid, 0, false)
      w.events.time[ev] = t
      // the new path's start written here, not through startAt or hotNextT: where V8 did not inline those into
      // this system (with contacts on it runs at every pass, and a pile pressed by a stream has many), their
      // doubles were boxed
      pathStart[PS_X] = B.x[eid]!
      pathStart[PS_Y] = B.y[eid]!
      pathStart[PS_VX] = vx
      pathStart[PS_VY] = vy
      pathStart[PS_T] = t
      startPath(w, eid)
      planRolling(w, eid)
    } else if (mark === PathEvent.Gutter) {
      P.mark[eid] = PathEvent.None
      const ev = appendEvent(w.events, EventType.Gutter, eid, 0, false)
      w.events.time[ev] = w.pathHot[eid * HOT + H_NEXT_T]!
      setBallMode(w, eid, BallMode.Out)
      B.vx[eid] = 0
      B.vy[eid] = 0
      P.speed[eid] = 0
      setNextT(w, eid, NEVER)
      P.nextKind[eid] = PathEvent.None
      releaseRim(w, eid)
      removeMoving(w, eid)
    }
  }
}
