// Closed-form motion shared by the systems: starting a straight path, finding its next event exactly,
// evaluating a ball on its path or on a rim at any time, and the transitions that end a ball's motion.
//
// A straight path is (origin, unit direction, speed v0, start time t0) with constant deceleration a; the
// distance rolled is s(τ) = v0·τ − a·τ²/2. Events are found as distances along the path (where geometry
// is exact) and turned into times once. Nothing here depends on where ticks fall.
import { PathEvent } from '../../components/Path.js'
import { RimMode } from '../../components/RimContact.js'
import { WallEdge } from '../../components/Walls.js'
import { speedAtDistance, stopDistance, fliesOver } from '../geometry.js'
import { W_BOUND, W_FROM, W_UX, W_UY, W_X, W_Y, buildHoleGrid, walk, walkHoleGrid } from '../world/holeGrid.js'
import { type BallWorld } from '../world/createWorld.js'
import { pathChanged } from '../world/contactState.js'
import { HOT, H_NEXT_S, H_NEXT_T, H_T0, H_UX, H_UY, H_V0, H_X0, H_Y0 } from '../world/pathHot.js'
import { NEVER } from '../config/tolerances.js'
import { capped, capVelocity } from './speedLimit.js'
import { MAX_SPEED } from '../config/limits.js'
import { meetNext } from '../world/meetState.js'

// the samplers of a straight path, kept in their own file (this one's callers import them from here)
export { sampleAtDistance, sampleDistance, sampleRolling, sampleRollingAt, sampleTime } from './sample.js'

/**
 * The start of the next path (startPath, launchBall): position, velocity and time, written by the caller
 * just before the call. In a typed array, not passed as arguments: V8 boxes every double passed to a
 * function it does not inline, five heap numbers at each event that starts a path.
 */
export const pathStart = new Float64Array(5)
export const PS_X = 0
export const PS_Y = 1
export const PS_VX = 2
export const PS_VY = 3
export const PS_T = 4

/** Starts a straight path at pathStart's position, velocity and time, and sets the ball's state there. */
export function startPath(w: BallWorld, eid: number): void {
  const P = w.Path
  const B = w.Ball
  const x = pathStart[PS_X]!
  const y = pathStart[PS_Y]!
  let vx = pathStart[PS_VX]!
  let vy = pathStart[PS_VY]!
  const t = pathStart[PS_T]!
  // no component beyond MAX_SPEED (src/motion/speedLimit.ts: a rim's exit can turn a fast ball's velocity
  // onto an axis). overSpeed written out here and below: inlined into launchBall and applyChanges, V8 did
  // not inline it in turn and boxed its two doubles at each call (about 64 bytes a ball the fixed tick's
  // solve changed)
  if (vx > MAX_SPEED || vx < -MAX_SPEED || vy > MAX_SPEED || vy < -MAX_SPEED) {
    capVelocity(vx, vy)
    vx = capped[0]!
    vy = capped[1]!
  }
  // hypot written out: a call V8 does not inline boxes its two arguments and its result
  let speed = Math.sqrt(vx * vx + vy * vy)
  const ux = speed > 0 ? vx / speed : 0
  const uy = speed > 0 ? vy / speed : 0
  // nor the ulp or two beyond it that ux·speed can round to (each try takes an ulp or two off the speed);
  // every later sample, ux·v with v ≤ speed, is then within it too (rounding is monotonic). The factor is
  // 1 − Number.EPSILON written as a number literal: the global Number, read in a branch V8 has not seen
  // taken, is a generic load, and the speed it merges into was boxed at every path (a module constant is of
  // no known type to V8 either)
  for (let k = 0; k < 8; k++) {
    const sx = ux * speed
    const sy = uy * speed
    if (!(sx > MAX_SPEED || sx < -MAX_SPEED || sy > MAX_SPEED || sy < -MAX_SPEED)) break
    speed *= 0.9999999999999998
  }
  // the path's row, written here (a call taking these six doubles boxed them wherever V8 did not inline it)
  const H = w.pathHot
  const h = eid * HOT
  H[h + H_X0] = x
  H[h + H_Y0] = y
  H[h + H_UX] = ux
  H[h + H_UY] = uy
  H[h + H_V0] = speed
  H[h + H_T0] = t
  const C = w.collide
  if (C !== null) C.gen[eid] = (C.gen[eid]! + 1) >>> 0
  P.speed[eid] = speed
  P.s[eid] = 0
  P.sHole[eid] = 0
  P.fromHole[eid] = 0
  if (C !== null) C.partner[eid] = 0
  if (w.meet !== null) w.meet.with[eid] = 0 // a fixed tick's meeting at its instant was the old path's
  B.x[eid] = x
  B.y[eid] = y
  // the closed form's velocity at the origin, ux·v0 (what every later sample of the path gives; without
  // rolling deceleration the integration then never rewrites it)
  B.vx[eid] = ux * speed
  B.vy[eid] = uy * speed
}

/**
 * Writes pathStart: position, velocity and start time. Small enough that V8 inlines it at its callers (the
 * allocation test holds with it); where it does not, its five doubles are boxed, which is why launchBall
 * writes the slots itself.
 */
export function startAt(x: number, y: number, vx: number, vy: number, t: number): void {
  pathStart[PS_X] = x
  pathStart[PS_Y] = y
  pathStart[PS_VX] = vx
  pathStart[PS_VY] = vy
  pathStart[PS_T] = t
}

/** startPath with the start as arguments: what `./ecs` exports as startPath, for a game's own systems. */
export function startPathAt(w: BallWorld, eid: number, x: number, y: number, vx: number, vy: number, t: number): void {
  startAt(x, y, vx, vy, t)
  startPath(w, eid)
}

// The planner's working state, kept in module scope so that planning allocates nothing (it never runs
// re-entrantly).
// Doubles live in an object's fields, updated in place: a module-level `let` holding a double gets a fresh
// heap number at every write (V8), which made every plan allocate.
// NEVER is kept here too: a module constant is a variable of a bundle to V8, of no known type, and one
// merged into a double (t and end in planRolling) made V8 box that double at every plan.
// Q.d and Q.t are timeTo's distance and result.
const Q = { x0: 0.5, y0: 0.5, ux: 0.5, uy: 0.5, s: 0.5, foot: 0.5, best: 0.5, stop: 0.5, change: 0.5, v0: 0.5, decel: 0.5, g: 0.5, never: NEVER, d: 0.5, t: 0.5 }

/**
 * Q.t = the time from the path's start to its stop (`stop`) or to where it has rolled Q.d (Infinity if it
 * stops first), for Q.v0 and Q.decel: stopTime and timeToDistance (src/geometry.ts) written out, the same
 * bits. V8 does not always inline those two into planRolling (it spends its inlining budget there first),
 * and a call it does not inline boxes every double it takes and returns: 16 bytes a plan. Infinity is
 * written 1 / 0, a number literal: the global Infinity in a branch V8 has not seen taken is a generic
 * load, and the double it merges with is boxed.
 */
function timeTo(stop: boolean): void {
  const v0 = Q.v0
  const decel = Q.decel
  const d = Q.d
  if (stop) Q.t = v0 <= 0 ? 0 : decel > 0 ? v0 / decel : 1 / 0
  else if (d <= 0) Q.t = 0
  else {
    const disc = v0 * v0 - 2 * decel * d
    const denom = disc < 0 ? 0 : v0 + Math.sqrt(disc)
    Q.t = denom > 0 ? (2 * d) / denom : 1 / 0
  }
}
/**
 * With ball-ball contacts on, the planner also finds the earliest candidate that may change the path's
 * closed form (Q.change): not a near miss, not the exit from a locked hole, not a lip crossing the skip-over
 * rule will fly over. Contact predictions then cover the path up to it (src/contacts/predict.ts), and the
 * events before it need no new prediction. The hole walk goes on to it.
 */
let qTrack = false
let qSHole = 0
let qFrom = 0
let qLocked = 0
let qXyr: Float64Array = new Float64Array(0)
let qIds: Uint32Array = new Uint32Array(0)
let bestHole = 0
let bestKind = 0
/** the WallEdge bit of the best candidate when it is a wall or an open edge */
let bestEdge = 0

/** Tests hole `i` of the table against the path; keeps the earliest event. Writes the walk's bound (walk[W_BOUND], src/world/holeGrid.ts). */
function considerHole(i: number): void {
  const hid = qIds[i]!
  const hx = qXyr[3 * i]! - Q.x0
  const hy = qXyr[3 * i + 1]! - Q.y0
  const R = qXyr[3 * i + 2]!
  // a ball not smaller than the hole bridges it: it rolls over, with no event there
  if (Q.foot >= R) return
  const p = hx * Q.ux + hy * Q.uy
  // every event of this hole lies at a distance ≥ p − R: nothing here can beat the best so far
  const bound = qTrack ? Q.change : Q.best
  walk[W_BOUND] = bound
  if (p - R > bound || hid === qLocked) return
  const c = hx * Q.uy - hy * Q.ux
  const c2 = c * c
  if (c2 < R * R) {
    // lip crossing, if the centre is still approaching the hole centre
    if (!(p > Q.s)) return
    let d = p - Math.sqrt(R * R - c2)
    if (d < Q.s) d = Q.s // a rounding error behind (or found inside): decided now, never lost
    if (d < Q.best || (d === Q.best && hid < bestHole && bestKind !== PathEvent.Stop && bestKind < PathEvent.Wall)) {
      Q.best = d
      bestHole = hid
      bestKind = PathEvent.Lip
    }
    // a crossing the skip-over rule flies over keeps the path (the rule systems/skipOver.ts applies)
    if (qTrack && d < Q.change && !fliesOver(speedAtDistance(d, Q.v0, Q.decel), Math.abs(c), R, Q.foot, Q.g)) Q.change = d
  } else {
    const f = R + Q.foot
    if (c2 >= f * f) return
    // near miss at the closest approach, if not already handled and not the hole the path leaves
    if (!(p > Q.s || (p === Q.s && hid > qSHole)) || hid === qFrom) return
    if (p < Q.best || (p === Q.best && hid < bestHole && bestKind !== PathEvent.Stop && bestKind < PathEvent.Wall)) {
      Q.best = p
      bestHole = hid
      bestKind = PathEvent.Near
    }
  }
  walk[W_BOUND] = qTrack ? Q.change : Q.best
}

/**
 * Wall and gutter candidates: the centre reaches a closed wall one radius in, or crosses an open edge.
 * A path that starts beyond a closed wall and heads out of the panel hits it at once.
 */
function considerWalls(w: BallWorld, e: number): void {
  const W = w.Walls
  const open = W.open[e]!
  const r = Q.foot
  // x faces: (coordinate, direction that reaches it, edge bit); then y faces
  for (let axis = 0; axis < 2; axis++) {
    const u = axis === 0 ? Q.ux : Q.uy
    if (u === 0) continue
    const o = axis === 0 ? Q.x0 : Q.y0
    const toMax = u > 0
    const edge = axis === 0 ? (toMax ? WallEdge.Right : WallEdge.Left) : toMax ? WallEdge.Bottom : WallEdge.Top
    const face = axis === 0 ? (toMax ? W.maxX[e]! : W.minX[e]!) : toMax ? W.maxY[e]! : W.minY[e]!
    const isOpen = (open & edge) !== 0
    const target = isOpen ? face : toMax ? face - r : face + r
    let d = (target - o) / u
    // already past the face and moving on out: a closed wall is hit at once, an open edge lets it out at once
    if (d < Q.s) d = Q.s
    // a face the path reaches only beyond any distance a double can hold (u ≈ 0) is never reached
    if (!(d < Infinity)) continue
    if (d < Q.change) Q.change = d
    // walls come before holes at the same distance (they are met first by the footprint)
    if (d < Q.best || (d === Q.best && bestKind !== PathEvent.Stop)) {
      Q.best = d
      bestHole = 0
      bestEdge = edge
      bestKind = isOpen ? PathEvent.Gutter : PathEvent.Wall
    }
  }
}

/**
 * Finds the next event of a ball on a straight path after the last handled one (Path.s, Path.sHole):
 * its stop, a lip crossing, a near miss, or, for the hole it is inside, the contact circle or the exit.
 * Candidates are ordered by (distance, hole id); a stop wins a tie (a ball that stops exactly on a lip
 * rests there: its centre is not inside).
 */
export function planRolling(w: BallWorld, eid: number): void {
  if (w.collide !== null) pathChanged(w, eid)
  const P = w.Path
  const RC = w.RimContact
  // the path's fields from its row in world.pathHot (one cache line; the same values as the Path store's)
  const H = w.pathHot
  const h = eid * HOT
  const v0 = H[h + H_V0]!
  const decel = w.config.ROLLING_DECEL
  Q.x0 = H[h + H_X0]!
  Q.y0 = H[h + H_Y0]!
  Q.ux = H[h + H_UX]!
  Q.uy = H[h + H_UY]!
  Q.s = P.s[eid]!
  qSHole = P.sHole[eid]!
  qFrom = P.fromHole[eid]!
  Q.foot = w.Ball.radius[eid]!
  const slot = w.Ball.rim[eid]!
  qLocked = RC.hole[slot]!

  Q.best = stopDistance(v0, decel)
  bestHole = 0
  bestKind = Q.best === Infinity ? PathEvent.None : PathEvent.Stop
  const C = w.collide
  Q.stop = Q.best
  Q.change = Q.best
  // the same path, short of where it was found to change (a skip-over, a near miss, a lip exit since):
  // that distance still holds, and the walk goes only to the next event
  qTrack = C !== null || tracking[0] === 1
  if (C !== null && C.changeGen[eid] === C.gen[eid] && C.changeS[eid]! > Q.s) {
    qTrack = false
    Q.change = C.changeS[eid]!
  }
  Q.v0 = v0
  Q.decel = decel
  Q.g = w.config.GRAVITY

  if (v0 > 0) {
    const locked = qLocked
    if (locked !== 0) {
      const hx = w.Hole.x[locked]! - Q.x0
      const hy = w.Hole.y[locked]! - Q.y0
      const R = w.Hole.radius[locked]!
      const p = hx * Q.ux + hy * Q.uy
      const c = hx * Q.uy - hy * Q.ux
      const c2 = c * c
      let d: number
      let k: number = PathEvent.Exit
      const rc = R - Q.foot / 2 // cogRadius, written out (a call V8 does not inline boxes its doubles)
      if (RC.mode[slot] === RimMode.Entering && c2 < rc * rc) {
        d = p - Math.sqrt(rc * rc - c2)
        k = PathEvent.Contact
      } else if (RC.mode[slot] === RimMode.Crossing && H[h + H_T0] === RC.time0[slot] && v0 === RC.speed0[slot]) {
        // a tabulated crossing on its own path: it ends at the reference's exit point (the hole stays
        // locked to there; the next path unlocks it as usual)
        d = RC.rideTo[slot]!
        k = PathEvent.Landing
      } else {
        d = c2 < R * R ? p + Math.sqrt(R * R - c2) : Q.s
      }
      if (d < Q.s) d = Q.s
      if (d < Q.best) {
        Q.best = d
        bestHole = locked
        bestKind = k
      }
      if (k !== PathEvent.Exit && d < Q.change) Q.change = d
    }

    if (w.walls !== 0) considerWalls(w, w.walls)

    const table = w.holes
    qXyr = table.xyr
    qIds = table.ids
    const grid = w.holeGrid
    if (table.count < w.gridFrom) {
      for (let i = 0, n = table.count; i < n; i++) considerHole(i)
    } else {
      if (grid.dirty || (Q.foot > grid.ballRadius && Q.foot < grid.maxRadius)) buildHoleGrid(grid, table, Math.max(Q.foot, grid.ballRadius, w.config.BALL_RADIUS))
      walk[W_X] = Q.x0
      walk[W_Y] = Q.y0
      walk[W_UX] = Q.ux
      walk[W_UY] = Q.uy
      walk[W_FROM] = Q.s
      walk[W_BOUND] = qTrack ? Q.change : Q.best
      walkHoleGrid(grid, considerHole)
    }
  }

  // an event no double can place in time (a distance beyond range, or a crawl that never gets there) is none
  const never = Q.never
  let t = never
  if (bestKind !== PathEvent.None) {
    Q.d = Q.best
    timeTo(bestKind === PathEvent.Stop)
    t = H[h + H_T0]! + Q.t
    if (!(t < never)) bestKind = PathEvent.None
  }
  P.nextKind[eid] = bestKind
  P.nextHole[eid] = bestKind === PathEvent.None ? 0 : bestHole
  P.nextEdge[eid] = bestKind === PathEvent.Wall || bestKind === PathEvent.Gutter ? bestEdge : 0
  if (bestKind === PathEvent.None) {
    H[h + H_NEXT_S] = 0
    H[h + H_NEXT_T] = NEVER
  } else {
    H[h + H_NEXT_S] = Q.best
    H[h + H_NEXT_T] = t
  }
  // a fixed tick's meeting at its instant (src/contacts/fixedMeet.ts) outlives a plan of the same path: it
  // is the next event again once the path's own next event is later (a near miss, a lip exit, a skip-over
  // before it; the meeting was given only where nothing before it changes the path)
  const M = w.meet
  if (M !== null && M.with[eid] !== 0 && H[h + H_NEXT_T]! > M.t[eid]!) meetNext(w, eid)
  if (C !== null) {
    if (qTrack) {
      C.changeS[eid] = Q.change
      C.changeGen[eid] = C.gen[eid]!
    }
    // when the path's closed form may change: at its next event, or later when that keeps the path
    let end = t
    if (Q.change > Q.best && v0 > 0) {
      Q.d = Q.change
      timeTo(Q.change === Q.stop)
      const tc = H[h + H_T0]! + Q.t
      end = tc < never ? tc : never
      if (end < t) end = t
    }
    C.formulaEnd[eid] = end
  }
}

/** planTracked's flag (a slot) and its answer: the time the path's closed form may change next, s */
const tracking = new Uint8Array(1)
export const changeAt = new Float64Array(1)

/**
 * planRolling, and the time at which the ball's path may change next into changeAt[0]: its stop, a wall or an
 * open edge, a lip crossing the skip-over rule does not fly over, the contact circle or the reference's exit
 * point of a locked hole (as the exact contacts track it, above). Near misses, the exit from a locked hole and
 * skip-overs before it are bookkeeping: each plans the same path again. NEVER for none.
 */
export function planTracked(w: BallWorld, eid: number): void {
  tracking[0] = 1
  planRolling(w, eid)
  tracking[0] = 0
  const never = Q.never
  let t = never
  if (Q.change < 1 / 0) {
    Q.d = Q.change
    timeTo(Q.change === Q.stop)
    t = w.pathHot[eid * HOT + H_T0]! + Q.t
    if (!(t < never)) t = never
  }
  changeAt[0] = t
}

/**
 * The signed offset of a ball's straight path from a hole's centre: the path's closest point to it is at
 * offset·(−uy, ux) from the centre; |offset| is the δ of a lip crossing.
 */
export function pathOffset(w: BallWorld, eid: number, hole: number): number {
  const H = w.pathHot
  const h = eid * HOT
  return (w.Hole.x[hole]! - H[h + H_X0]!) * H[h + H_UY]! - (w.Hole.y[hole]! - H[h + H_Y0]!) * H[h + H_UX]!
}
