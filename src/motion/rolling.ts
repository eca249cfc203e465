// Closed-form motion shared by the systems: starting a straight path, finding its next event exactly,
// evaluating a ball on its path or on a rim at any time, and the transitions that end a ball's motion.
//
// A straight path is (origin, unit direction, speed v0, start time t0) with constant deceleration a; the
// distance rolled is s(τ) = v0·τ − a·τ²/2. Events are found as distances along the path (where geometry
// is exact) and turned into times once. Nothing here depends on where ticks fall.
import { BallMode } from '../../components/Ball.js'
import { PathEvent } from '../../components/Path.js'
import { RimMode } from '../../components/RimContact.js'
import { WallEdge } from '../../components/Walls.js'
import { CaptureVia, EventType, pushEvent, type CaptureViaCode } from '../events.js'
import {
  cogRadius,
  popArc,
  rollArc,
  rollDropTime,
  rollPopTime,
  rollSpeed,
  speedAtDistance,
  stopDistance,
  stopTime,
  timeToDistance,
} from '../geometry.js'
import { buildHoleGrid, walkHoleGrid } from '../world/holeGrid.js'
import { addMoving, releaseRim, removeMoving, type BallWorld } from '../world/createWorld.js'
import { restingInsert, restingRemove } from '../contacts/state.js'

/** Stand-in for "never" in time arrays (component arrays hold no Infinity). */
export const NEVER = 1e300

/**
 * A lip crossing this far (px) behind the ball still counts as happening now. It covers rounding of a
 * path origin placed on a circle; it is far below any distance the game can show.
 */
export const LIP_EPSILON = 1e-7

/** Starts a straight path at (x, y) with velocity (vx, vy) at time t, and sets the ball's state there. */
export function startPath(w: BallWorld, eid: number, x: number, y: number, vx: number, vy: number, t: number): void {
  const P = w.Path
  const B = w.Ball
  const speed = Math.hypot(vx, vy)
  P.x0[eid] = x
  P.y0[eid] = y
  P.t0[eid] = t
  P.v0[eid] = speed
  P.ux[eid] = speed > 0 ? vx / speed : 0
  P.uy[eid] = speed > 0 ? vy / speed : 0
  P.speed[eid] = speed
  P.s[eid] = 0
  P.sHole[eid] = 0
  P.fromHole[eid] = 0
  if (w.collide !== null) w.collide.partner[eid] = 0
  B.x[eid] = x
  B.y[eid] = y
  B.vx[eid] = vx
  B.vy[eid] = vy
}

// The planner's working state, kept in module scope so that planning allocates nothing (it never runs
// re-entrantly).
// Doubles live in an object's fields, updated in place: a module-level `let` holding a double gets a fresh
// heap number at every write (V8), which made every plan allocate.
const Q = { x0: 0.5, y0: 0.5, ux: 0.5, uy: 0.5, s: 0.5, foot: 0.5, best: 0.5 }
let qSHole = 0
let qFrom = 0
let qLocked = 0
let qXyr: Float64Array = new Float64Array(0)
let qIds: Uint32Array = new Uint32Array(0)
let bestHole = 0
let bestKind = 0

/** Tests hole `i` of the table against the path; keeps the earliest event. Returns the best distance. */
function considerHole(i: number): number {
  const hid = qIds[i]!
  const hx = qXyr[3 * i]! - Q.x0
  const hy = qXyr[3 * i + 1]! - Q.y0
  const R = qXyr[3 * i + 2]!
  const p = hx * Q.ux + hy * Q.uy
  // every event of this hole lies at a distance ≥ p − R: nothing here can beat the best so far
  if (p - R > Q.best || hid === qLocked) return Q.best
  const c = hx * Q.uy - hy * Q.ux
  const c2 = c * c
  if (c2 < R * R) {
    // lip crossing, if the centre is still approaching the hole centre
    if (!(p > Q.s)) return Q.best
    let d = p - Math.sqrt(R * R - c2)
    if (d < Q.s) d = Q.s // a rounding error behind (or found inside): decided now, never lost
    if (d < Q.best || (d === Q.best && hid < bestHole && bestKind !== PathEvent.Stop && bestKind < PathEvent.Wall)) {
      Q.best = d
      bestHole = hid
      bestKind = PathEvent.Lip
    }
  } else {
    const f = R + Q.foot
    if (c2 >= f * f) return Q.best
    // near miss at the closest approach, if not already handled and not the hole the path leaves
    if (!(p > Q.s || (p === Q.s && hid > qSHole)) || hid === qFrom) return Q.best
    if (p < Q.best || (p === Q.best && hid < bestHole && bestKind !== PathEvent.Stop && bestKind < PathEvent.Wall)) {
      Q.best = p
      bestHole = hid
      bestKind = PathEvent.Near
    }
  }
  return Q.best
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
    if (d < Q.s) {
      if (isOpen) continue // already past an open edge: it has left
      d = Q.s
    }
    // walls come before holes at the same distance (they are met first by the footprint)
    if (d < Q.best || (d === Q.best && bestKind !== PathEvent.Stop)) {
      Q.best = d
      bestHole = edge // for wall events the "hole" slot carries the WallEdge bit
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
  const P = w.Path
  const RC = w.RimContact
  const v0 = P.v0[eid]!
  const decel = w.config.ROLLING_DECEL
  Q.x0 = P.x0[eid]!
  Q.y0 = P.y0[eid]!
  Q.ux = P.ux[eid]!
  Q.uy = P.uy[eid]!
  Q.s = P.s[eid]!
  qSHole = P.sHole[eid]!
  qFrom = P.fromHole[eid]!
  Q.foot = w.Ball.radius[eid]!
  const slot = w.Ball.rim[eid]!
  qLocked = RC.hole[slot]!

  Q.best = stopDistance(v0, decel)
  bestHole = 0
  bestKind = Q.best === Infinity ? PathEvent.None : PathEvent.Stop

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
      const rc = cogRadius(R, Q.foot)
      if (RC.mode[slot] === RimMode.Entering && c2 < rc * rc) {
        d = p - Math.sqrt(rc * rc - c2)
        k = PathEvent.Contact
      } else {
        d = c2 < R * R ? p + Math.sqrt(R * R - c2) : Q.s
      }
      if (d < Q.s) d = Q.s
      if (d < Q.best) {
        Q.best = d
        bestHole = locked
        bestKind = k
      }
    }

    if (w.walls !== 0) considerWalls(w, w.walls)

    const table = w.holes
    qXyr = table.xyr
    qIds = table.ids
    const grid = w.holeGrid
    if (table.count < w.gridFrom) {
      for (let i = 0, n = table.count; i < n; i++) considerHole(i)
    } else {
      if (grid.dirty || Q.foot > grid.ballRadius) buildHoleGrid(grid, table, Math.max(Q.foot, grid.ballRadius, w.config.BALL_RADIUS))
      walkHoleGrid(grid, Q.x0, Q.y0, Q.ux, Q.uy, Q.s, Q.best, considerHole)
    }
  }

  P.nextKind[eid] = bestKind
  P.nextHole[eid] = bestHole
  if (bestKind === PathEvent.None) {
    P.nextS[eid] = 0
    P.nextT[eid] = NEVER
  } else {
    P.nextS[eid] = Q.best
    const tau = bestKind === PathEvent.Stop ? stopTime(v0, decel) : timeToDistance(Q.best, v0, decel)
    P.nextT[eid] = P.t0[eid]! + tau
  }
}

/** Next event of a ball rolling on a rim: the earlier of its drop and its pop-off. */
export function planRimRoll(w: BallWorld, eid: number): void {
  const RC = w.RimContact
  const cfg = w.config
  const slot = w.Ball.rim[eid]!
  const hole = RC.hole[slot]!
  const vt0 = RC.speed0[slot]!
  const tDrop = rollDropTime(vt0, cfg.RIM_ROLL_FRICTION, cfg.RIM_ROLL_DROP_SPEED)
  const tPop = rollPopTime(vt0, cfg.RIM_ROLL_FRICTION, popArc(cfg.RIM_ROLL_MAX_TURNS, w.Hole.radius[hole]!))
  const P = w.Path
  P.nextKind[eid] = PathEvent.RollEnd
  P.nextHole[eid] = hole
  P.nextT[eid] = RC.time0[slot]! + Math.min(tDrop, tPop)
}

/** True when a rim roll that started with speed vt0 pops off before it drops. */
export function rollPopsOff(w: BallWorld, eid: number): boolean {
  const RC = w.RimContact
  const cfg = w.config
  const slot = w.Ball.rim[eid]!
  const vt0 = RC.speed0[slot]!
  const tDrop = rollDropTime(vt0, cfg.RIM_ROLL_FRICTION, cfg.RIM_ROLL_DROP_SPEED)
  const tPop = rollPopTime(vt0, cfg.RIM_ROLL_FRICTION, popArc(cfg.RIM_ROLL_MAX_TURNS, w.Hole.radius[RC.hole[slot]!]!))
  return tPop < tDrop
}

/** Ball state at time t on its straight path (clamped at its stop). */
export function sampleRolling(w: BallWorld, eid: number, t: number): void {
  const P = w.Path
  const B = w.Ball
  const v0 = P.v0[eid]!
  const decel = w.config.ROLLING_DECEL
  let tau = t - P.t0[eid]!
  if (tau < 0) tau = 0
  if (decel > 0 && tau * decel > v0) tau = v0 / decel
  const d = v0 * tau - 0.5 * decel * tau * tau
  const v = v0 - decel * tau
  const ux = P.ux[eid]!
  const uy = P.uy[eid]!
  B.x[eid] = P.x0[eid]! + ux * d
  B.y[eid] = P.y0[eid]! + uy * d
  B.vx[eid] = ux * v
  B.vy[eid] = uy * v
  P.speed[eid] = v
}

/** Ball state at distance d along its straight path: exact geometry for an event found at that distance. */
export function sampleAtDistance(w: BallWorld, eid: number, d: number): void {
  const P = w.Path
  const B = w.Ball
  const v = speedAtDistance(d, P.v0[eid]!, w.config.ROLLING_DECEL)
  const ux = P.ux[eid]!
  const uy = P.uy[eid]!
  B.x[eid] = P.x0[eid]! + ux * d
  B.y[eid] = P.y0[eid]! + uy * d
  B.vx[eid] = ux * v
  B.vy[eid] = uy * v
  P.speed[eid] = v
}

/** A rim-rolling ball's state at a time, written by rimRollAt (module scratch: no allocation). */
export const rimRollState = { x: 0, y: 0, vx: 0, vy: 0, speed: 0, angle: 0, arc: 0, radius: 0 }

/** Evaluates a rim-rolling ball at time t into rimRollState: v_t = v_t0·e^(−μτ), exact for every dt. */
export function rimRollAt(w: BallWorld, eid: number, t: number): void {
  const RC = w.RimContact
  const slot = w.Ball.rim[eid]!
  const hole = RC.hole[slot]!
  const R = w.Hole.radius[hole]!
  const vt0 = RC.speed0[slot]!
  const mu = w.config.RIM_ROLL_FRICTION
  let tau = t - RC.time0[slot]!
  if (tau < 0) tau = 0
  const arc = rollArc(tau, vt0, mu)
  const v = rollSpeed(tau, vt0, mu)
  const dir = RC.direction[slot]!
  const phi = RC.angle0[slot]! + (dir * arc) / R
  const c = Math.cos(phi)
  const s = Math.sin(phi)
  const o = rimRollState
  o.x = w.Hole.x[hole]! + R * c
  o.y = w.Hole.y[hole]! + R * s
  o.vx = -dir * s * v
  o.vy = dir * c * v
  o.speed = v
  o.angle = phi
  o.arc = arc
  o.radius = R
}

/** Ball state at time t on the rim (rimRollAt), written into Ball, RimContact and Path. */
export function sampleRimRoll(w: BallWorld, eid: number, t: number): void {
  rimRollAt(w, eid, t)
  const o = rimRollState
  const B = w.Ball
  const slot = B.rim[eid]!
  B.x[eid] = o.x
  B.y[eid] = o.y
  B.vx[eid] = o.vx
  B.vy[eid] = o.vy
  w.RimContact.angle[slot] = o.angle
  w.RimContact.arc[slot] = o.arc
  w.Path.speed[eid] = o.speed
}

/**
 * Puts a ball on the rim of `hole` at time t (Stage 3's start), from its state in Ball: angle, tangential
 * speed |v_t| along the counter-clockwise tangent (−n_y, n_x), direction and start time into its RimContact
 * slot, mode RimRoll. Returns the angle. Shared by the exact and the naive rim-roll systems.
 */
export function startRimRoll(w: BallWorld, eid: number, hole: number, t: number): number {
  const B = w.Ball
  const RC = w.RimContact
  const rim = B.rim[eid]!
  const nx = B.x[eid]! - w.Hole.x[hole]!
  const ny = B.y[eid]! - w.Hole.y[hole]!
  const len = Math.hypot(nx, ny)
  const vt = len > 0 ? (-B.vx[eid]! * ny + B.vy[eid]! * nx) / len : 0
  const phi = Math.atan2(ny, nx)
  RC.mode[rim] = RimMode.Rolling
  RC.angle0[rim] = phi
  RC.speed0[rim] = Math.abs(vt)
  RC.direction[rim] = vt >= 0 ? 1 : -1
  RC.time0[rim] = t
  B.mode[eid] = BallMode.RimRoll
  return phi
}

/** Emits a hole event carrying the lip crossing's (δ, v) when the ball has one for this hole. */
export function emitHoleEvent(
  w: BallWorld,
  type: (typeof EventType)[keyof typeof EventType],
  eid: number,
  hole: number,
  t: number,
  via: CaptureViaCode = CaptureVia.None,
): void {
  const RC = w.RimContact
  const slot = w.Ball.rim[eid]!
  const hasLip = RC.hole[slot] === hole && RC.hasLip[slot] === 1
  pushEvent(w.events, type, eid, hole, t, hasLip, RC.delta[slot]!, RC.speed[slot]!, via)
}

/**
 * The ball falls into `hole` at time t: it sits at the hole centre, at rest, and stops being simulated.
 * Its hole lock ends with the capture event, so its RimContact slot is given back.
 */
export function captureBall(w: BallWorld, eid: number, hole: number, t: number, via: CaptureViaCode): void {
  emitHoleEvent(w, EventType.Capture, eid, hole, t, via)
  const B = w.Ball
  B.mode[eid] = BallMode.Captured
  B.x[eid] = w.Hole.x[hole]!
  B.y[eid] = w.Hole.y[hole]!
  B.vx[eid] = 0
  B.vy[eid] = 0
  w.Path.speed[eid] = 0
  w.Path.nextT[eid] = NEVER
  w.Path.nextKind[eid] = PathEvent.None
  releaseRim(w, eid)
  removeMoving(w, eid)
  if (w.collide !== null) restingRemove(w, eid)
}

/** The ball stops on the panel, outside every hole, at time t. */
export function restBall(w: BallWorld, eid: number, t: number): void {
  pushEvent(w.events, EventType.Rest, eid, 0, t, false, 0, 0)
  const B = w.Ball
  B.mode[eid] = BallMode.Resting
  B.vx[eid] = 0
  B.vy[eid] = 0
  w.Path.speed[eid] = 0
  w.Path.nextT[eid] = NEVER
  w.Path.nextKind[eid] = PathEvent.None
  removeMoving(w, eid)
  // with ball-ball contacts on, a resting ball is found by moving ones through the resting grid
  if (w.collide !== null) restingInsert(w, eid)
}

/** Puts a ball back into motion (rolling) on a fresh straight path; used by the API. */
export function launchBall(w: BallWorld, eid: number, x: number, y: number, vx: number, vy: number, t: number): void {
  if (w.collide !== null) restingRemove(w, eid)
  w.Ball.mode[eid] = BallMode.Rolling
  startPath(w, eid, x, y, vx, vy, t)
  planRolling(w, eid)
  addMoving(w, eid)
}
