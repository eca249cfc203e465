// Launcher (not a design stage; ball-ball contacts on only). A ball put down where another ball is waits
// there, held (mode 'held'), with the velocity it was given; at the start of each step the held balls whose
// spots are clear are launched, in the order they came, from their spots with those velocities. An arcade
// launcher firing many balls from one point so lets them out one after another, each as the one before it
// clears the spot, instead of starting them inside one another. The rule adds no kinetic energy (a held ball
// keeps its velocity and is launched only where it overlaps nothing), and a released ball starts
// where it was put, at the step's start: release times are quantised to steps.
// Bounded work: at most MAX_SPOT_CHECKS full checks per step (each against the moving and resting balls
// near the spot, through grids); a held ball overlapping the held ball just before it in the queue waits
// without one. The rest wait for later steps.
// Reads the held queue, Ball, the moving set and the resting grid; writes Ball, Path, RimContact.
import { BallMode } from '../components/Ball.js'
import { MAX_SPOT_CHECKS } from '../src/config/tolerances.js'
import { spotTaken } from '../src/contacts/spot.js'
import { placeBall } from '../src/motion/ballFate.js'
import type { BallWorld } from '../src/world/createWorld.js'

export function launcherSystem(w: BallWorld): void {
  if (w.pass !== 0 || w.held.count === 0) return
  const q = w.held
  const B = w.Ball
  let kept = 0
  let checks = 0
  let last = 0
  for (let i = 0; i < q.count; i++) {
    const eid = q.ids[i]!
    if (B.live[eid] !== 1 || B.mode[eid] !== BallMode.Held) continue
    const x = B.x[eid]!
    const y = B.y[eid]!
    const r = B.radius[eid]!
    let wait: boolean
    if (last !== 0 && overlaps(w, eid, last)) wait = true
    else if (checks >= MAX_SPOT_CHECKS) wait = true
    else {
      checks++
      wait = spotTaken(w, eid, x, y, r)
    }
    if (wait) {
      q.ids[kept++] = eid
      last = eid
      continue
    }
    placeBall(w, eid, x, y, B.vx[eid]!, B.vy[eid]!)
  }
  q.count = kept
}

function overlaps(w: BallWorld, a: number, b: number): boolean {
  const B = w.Ball
  const dx = B.x[a]! - B.x[b]!
  const dy = B.y[a]! - B.y[b]!
  const s = B.radius[a]! + B.radius[b]!
  return dx * dx + dy * dy < s * s
}
