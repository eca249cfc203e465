// The throw solver: a (power, angle) whose exact simulation, from the world's current state, gives a
// chosen outcome at a chosen hole — for games that draw the outcome first and then show a throw that
// produces it.
//
// How: the outcome of a throw is a function of (power, angle) that is constant on regions of that plane
// with sharp edges (the capture boundary, the edges of the paths that pass the other holes).
//   1. A grid over the throws that can reach the hole: ANGLES aims across the cone of straight paths that
//      cross its lip circle (widened by a ball radius), SPEEDS powers spread evenly in the speed the ball
//      would have at the lip. Each throw is simulated in a trial world (the world's config, holes and
//      walls; one ball alone, contacts off), with MAX_STEP steps (the result does not depend on the step).
//      With `along`, the same from other start points on the launch segment, nearest first; when no
//      direct throw gives the outcome, bank shots off each closed wall (the aim whose path, reflected with
//      the walls' restitution, runs to the hole's centre).
//   2. Of the throws with the outcome, the one deepest inside its region (the most grid steps to the
//      nearest throw without it) is taken, and its margin measured by bisection along ±power and ±angle.
//   3. That throw is simulated once more in an exact copy of the world (a snapshot restored: its time,
//      its other balls and, with contacts on, their contacts); if the outcome does not hold there, the
//      next-deepest is tried (four in all).
// Deterministic: the same world and request give the same throw. Cost: tests/solveThrow.test.ts and
// bench/solver.ts (a few ms for a capture on the default panel).
import type { BallWorld } from '../world/createWorld.js'
import { checkHole, checkWorld, describe, finite, readSpec } from '../commands/validate.js'
import { heldCount } from '../commands/balls.js'
import { MAX_COORDINATE, MIN_OUTCOME_STEP } from '../config/limits.js'
import { choice, within } from '../check.js'
import { atan2, hypot } from '../math.js'
import type { BallPhysics } from './createBallPhysics.js'
import { WallEdge } from '../../components/Walls.js'
import { ExactCheck, HORIZON, Trial, type ThrowOutcome } from './throwTrials.js'

export type { ThrowOutcome } from './throwTrials.js'

export interface ThrowRequest {
  /** where the ball is thrown from, px */
  from: { x: number; y: number }
  /**
   * px, default 0: the throw may start anywhere on the level segment from.x ± along (a launcher that
   * slides, a plinko drop line); points nearer from.x are preferred
   */
  along?: number | undefined
  /** the target hole's id */
  hole: number
  /** default 'capture' */
  outcome?: ThrowOutcome | undefined
  /**
   * s, in [1e-4, MAX_STEP]: the step the answer is checked at, in a copy of the world. The outcome is the same
   * at every step (balls held at the launcher leave at launch instants of the world's clock, not at step
   * starts), so this changes only the check's cost. Default: MAX_STEP
   */
  step?: number | undefined
  /**
   * where the throw waits if it is held at a busy launcher (contacts on), as throwBall's `queue`: the answer
   * is for a throw made with the same. Default 'back'
   */
  queue?: 'back' | 'front' | undefined
}

export interface ThrowSolution {
  found: true
  /** where the throw starts (from, or a point of the segment when `along` was given) */
  from: { x: number; y: number }
  /** 0..1, as throwBall's */
  power: number
  /** rad, as throwBall's: 0 = up the panel (−y), positive toward +x */
  angle: number
  /**
   * how far each can be off, alone, with the outcome still holding (measured in the trial world, to
   * within 1/16 of the grid's step): the smaller of the two sides
   */
  margin: { power: number; angle: number }
  /** simulated time from the throw to the outcome, s */
  time: number
  /** throws simulated to find it */
  trials: number
}

export interface ThrowFailure {
  found: false
  power: null
  angle: null
  /** why no throw was found */
  reason: string
  trials: number
}

const OUTCOMES: readonly ThrowOutcome[] = ['capture', 'skip', 'lipOut', 'bounce']
const ANGLES = 25
const SPEEDS = 24

/**
 * A throw from `from` whose exact simulation from the world's current state gives `outcome` at `hole`,
 * preferring the throw with the widest margin; or the reason there is none (see the top of this file).
 */
export function solveThrow(target: BallPhysics | BallWorld, request: ThrowRequest): ThrowSolution | ThrowFailure {
  const world = checkWorld('solveThrow', 'world' in target && 'step' in target ? target.world : (target as BallWorld))
  const s = readSpec('solveThrow request', request, ['from', 'hole', 'outcome', 'along', 'step', 'queue'] as const)
  const f = readSpec('request.from', s.from, ['x', 'y'] as const)
  const fx = finite('request.from.x', f.x, MAX_COORDINATE)
  const fy = finite('request.from.y', f.y, MAX_COORDINATE)
  const hole = checkHole(world, 'request.hole', s.hole)
  const along = s.along === undefined ? 0 : finite('request.along', s.along, MAX_COORDINATE)
  // the segment from.x ± along lies within the coordinates a throw may start at
  const alongMax = MAX_COORDINATE - Math.abs(fx)
  if (!(along >= 0 && along <= alongMax)) throw new RangeError(`request.along must be in [0, ${alongMax}] (from.x ± along within ±${MAX_COORDINATE}), got ${along}`)
  const outcome = s.outcome === undefined ? 'capture' : (s.outcome as ThrowOutcome)
  if (typeof outcome !== 'string' || !OUTCOMES.includes(outcome)) {
    // the wrong type a TypeError, a string not among the outcomes a RangeError
    const message = `request.outcome must be one of ${OUTCOMES.join(', ')}, got ${describe(s.outcome)}`
    throw typeof outcome === 'string' ? new RangeError(message) : new TypeError(message)
  }
  const maxStep = world.config.MAX_STEP
  // the throws are stepped for up to HORIZON seconds: at MAX_STEP (the grid) and at request.step (the answer)
  if (maxStep < MIN_OUTCOME_STEP) throw new RangeError(`solveThrow: the world's MAX_STEP must be at least ${MIN_OUTCOME_STEP} s (its throws are stepped at it for up to ${HORIZON} s), got ${maxStep}`)
  const step = s.step === undefined ? maxStep : within('request.step', s.step, MIN_OUTCOME_STEP, maxStep)
  const queue = choice('request.queue', s.queue, ['back', 'front'] as const)
  if (world.stepping) throw new Error('solveThrow: the world is in the middle of a step')
  if (world.events.draining) throw new Error('solveThrow: called from a drainEventsWith callback (it copies the world by snapshot); call it after the drain returns')

  // the grid's throws at MAX_STEP (a grid of them among a thousand balls costs seconds at 1/60 s); the
  // answer is checked at request.step
  const trial = new Trial(world, hole)
  const cfg = world.config
  const H = world.Hole
  const hx = H.x[hole]!
  const hy = H.y[hole]!
  const R = H.radius[hole]!
  // 1–2. direct throws from the start points, nearest from.x first, until one has room on every side (two
  // grid steps) or three points have given any; bank shots off the closed walls from from.x when none did
  const found: Candidate[] = []
  const starts = along > 0 ? [0, 1, -1, 2, -2, 3, -3, 4, -4].map((k) => fx + (k * along) / 4) : [fx]
  for (let n = 0; n < starts.length; n++) {
    const x = starts[n]!
    if (hypot(hx - x, hy - fy) <= R) continue
    searchCone(trial, x, fy, outcome, directCone(cfg.BALL_RADIUS, x, fy, hx, hy, R), found)
    // enough: a throw with room on every side, or any throw once three points have been searched
    if (found.some((c) => c.depth >= 2) || (found.length > 0 && n >= 2)) break
  }
  let banked = false
  if (found.length === 0 && hypot(hx - fx, hy - fy) > R) {
    for (const cone of bankCones(world, fx, fy, hx, hy, R)) {
      banked = true
      searchCone(trial, fx, fy, outcome, cone, found)
    }
  }
  if (found.length === 0) {
    const where = along > 0 ? `anywhere on (${fx} ± ${along}, ${fy})` : `from (${fx}, ${fy})`
    const ways = banked ? 'direct and off the closed walls' : world.walls === 0 ? 'direct only (no walls)' : 'direct only (no bank shot off the walls toward it)'
    return fail(`no throw ${where} gives ${outcome} at hole ${hole}: ${trial.count} throws tried, ${ways}, over the powers and aims that reach it`, trial.count)
  }
  found.sort((a, b) => b.depth - a.depth || a.order - b.order)
  const exact = new ExactCheck(world, hole, step, queue)
  const tries = Math.min(found.length, 4)
  for (let n = 0; n < tries; n++) {
    const c = found[n]!
    // 3. the throw in an exact copy of the world
    const time = exact.run(c.x, fy, c.power, c.angle, outcome)
    if (time < 0) continue
    const margin = {
      power: Math.min(edge(trial, c.x, fy, c, outcome, c.dp, 0), edge(trial, c.x, fy, c, outcome, -c.dp, 0)),
      angle: Math.min(edge(trial, c.x, fy, c, outcome, 0, c.da), edge(trial, c.x, fy, c, outcome, 0, -c.da)),
    }
    return { found: true, from: { x: c.x, y: fy }, power: c.power, angle: c.angle, margin, time, trials: trial.count + exact.count }
  }
  // every one waited at a launcher's queue past the horizon: say so (the throw is not wrong, only late)
  if (exact.heldThrough === tries) {
    const why =
      queue === 'back'
        ? `behind the balls queued there (${heldCount(world)} held) for longer than the ${HORIZON} s a throw is followed: try again when the launcher has room, or ask for a throw at the front of the queue (request.queue 'front')`
        : `for longer than the ${HORIZON} s a throw is followed (a ball is on it all that time): try again when the launcher has room`
    return fail(`a ball thrown from (${found[0]!.x}, ${fy}) now waits held at its spot ${why}`, trial.count + exact.count)
  }
  return fail(`throws that give ${outcome} at hole ${hole} with the panel alone do not with the world's other balls (${tries} tried)`, trial.count + exact.count)
}

/** A throw of the grid with the outcome: its depth (grid steps to the nearest miss), its grid steps, its place in the search */
interface Candidate {
  /** the start point's x */
  x: number
  power: number
  angle: number
  depth: number
  dp: number
  da: number
  order: number
}

/** A cone of aims (around `aim`, ± `half`) and the path length to the hole's lip along it, px */
interface Cone {
  aim: number
  half: number
  path: number
  /** the fraction of its speed a ball keeps along the path (a wall's restitution on the normal part; 1 direct) */
  keep: number
}

function directCone(r: number, fx: number, fy: number, hx: number, hy: number, R: number): Cone {
  const d = hypot(hx - fx, hy - fy)
  // the straight paths that cross the lip circle, widened by a ball radius
  return { aim: atan2(hx - fx, fy - hy), half: Math.min(Math.PI / 2, asinClamped((R + r) / d)), path: d - R, keep: 1 }
}

/**
 * Bank shots: for each closed wall, the aim whose path, reflected with the walls' restitution at the line
 * a ball radius inside the wall, runs to the hole's centre; the cone around it twice as wide as a direct
 * one of the same length.
 */
function bankCones(world: BallWorld, fx: number, fy: number, hx: number, hy: number, R: number): Cone[] {
  const e = world.walls
  if (e === 0) return []
  const W = world.Walls
  const r = world.config.BALL_RADIUS
  const k = W.restitution[e]!
  if (!(k > 0)) return []
  const open = W.open[e]!
  const cones: Cone[] = []
  const add = (wx: number, wy: number, keep: number): void => {
    const a = hypot(wx - fx, wy - fy)
    const b = hypot(hx - wx, hy - wy)
    if (!(a > 0 && b > R)) return
    cones.push({ aim: atan2(wx - fx, fy - wy), half: Math.min(Math.PI / 4, 2 * asinClamped((R + r) / (a + b))), path: a + b - R, keep })
  }
  // a wall along x = c: the ball meets it at y = w, where (w − fy)·(hx − c) = k·(c − fx)·(hy − w)... in
  // offsets from the line: u_f = fx − c, u_h = hx − c (same sign: both inside), w = (fy·u_h + k·u_f·hy) / (u_h + k·u_f)
  const side = (c: number): void => {
    const uf = fx - c
    const uh = hx - c
    if (uf * uh <= 0) return
    add(c, (fy * uh + k * uf * hy) / (uh + k * uf), Math.sqrt(k))
  }
  const end = (c: number): void => {
    const uf = fy - c
    const uh = hy - c
    if (uf * uh <= 0) return
    add((fx * uh + k * uf * hx) / (uh + k * uf), c, Math.sqrt(k))
  }
  if ((open & WallEdge.Left) === 0) side(W.minX[e]! + r)
  if ((open & WallEdge.Right) === 0) side(W.maxX[e]! - r)
  if ((open & WallEdge.Top) === 0) end(W.minY[e]! + r)
  if ((open & WallEdge.Bottom) === 0) end(W.maxY[e]! - r)
  return cones
}

/**
 * Simulates the grid of a cone — ANGLES aims across it, SPEEDS powers spread evenly in the speed the ball
 * would have at the lip (from a crawl to the fastest throw's) — and appends the throws with the outcome.
 */
function searchCone(trial: Trial, fx: number, fy: number, outcome: ThrowOutcome, cone: Cone, out: Candidate[]): void {
  const cfg = trial.sim.config
  const reach = 2 * cfg.ROLLING_DECEL * cone.path
  const top = cfg.MAX_VY * cone.keep
  const vTop = Math.sqrt(Math.max(0, top * top - reach))
  const angles = new Float64Array(ANGLES)
  for (let i = 0; i < ANGLES; i++) angles[i] = cone.aim - cone.half + (2 * cone.half * i) / (ANGLES - 1)
  const powers = new Float64Array(SPEEDS)
  for (let j = 0; j < SPEEDS; j++) {
    const vLip = (vTop * (j + 0.5)) / SPEEDS
    const v0 = Math.sqrt(vLip * vLip + reach) / cone.keep
    powers[j] = Math.min(1, Math.max(0, (v0 - cfg.MIN_VY) / (cfg.MAX_VY - cfg.MIN_VY)))
  }
  const hit = new Uint8Array(ANGLES * SPEEDS)
  for (let i = 0; i < ANGLES; i++) for (let j = 0; j < SPEEDS; j++) hit[i * SPEEDS + j] = trial.run(fx, fy, powers[j]!, angles[i]!) === outcome ? 1 : 0
  const depth = depthOf(hit)
  const da = angles[1]! - angles[0]!
  for (let k = 0; k < hit.length; k++) {
    if (hit[k] === 0) continue
    const i = Math.floor(k / SPEEDS)
    const j = k % SPEEDS
    // the power step there: to the next grid power (or the one before at the top)
    const dp = Math.abs(j + 1 < SPEEDS ? powers[j + 1]! - powers[j]! : powers[j]! - powers[j - 1]!) || 1 / (4 * SPEEDS)
    out.push({ x: fx, power: powers[j]!, angle: angles[i]!, depth: depth[k]!, dp, da, order: out.length })
  }
}

function fail(reason: string, trials: number): ThrowFailure {
  return { found: false, power: null, angle: null, reason, trials }
}

function asinClamped(x: number): number {
  // asin by its series-free identity asin x = atan2(x, √(1 − x²)), portable
  const c = Math.min(1, Math.max(-1, x))
  return atan2(c, Math.sqrt(1 - c * c))
}

/**
 * How far the throw can move by steps of (dp, da) with the outcome holding: whole steps up to its depth,
 * then bisected to 1/16 of a step. In power (dp ≠ 0) or angle units.
 */
function edge(trial: Trial, fx: number, fy: number, c: Candidate, outcome: ThrowOutcome, dp: number, da: number): number {
  const unit = dp !== 0 ? Math.abs(dp) : Math.abs(da)
  const holds = (t: number): boolean => {
    const p = c.power + dp * t
    if (p < 0 || p > 1) return false
    return trial.run(fx, fy, p, c.angle + da * t) === outcome
  }
  let lo = 0
  let hi = c.depth + 1
  for (let t = 1; t <= c.depth; t++) {
    if (!holds(t)) {
      hi = t
      break
    }
    lo = t
  }
  if (hi === c.depth + 1 && holds(hi)) return hi * unit
  for (let it = 0; it < 4; it++) {
    const mid = (lo + hi) / 2
    if (holds(mid)) lo = mid
    else hi = mid
  }
  return lo * unit
}

/** Steps (Chebyshev) from each hit cell to the nearest miss or the grid's edge; 0 for misses. */
function depthOf(hit: Uint8Array): Uint8Array {
  const depth = new Uint8Array(hit.length)
  for (let i = 0; i < ANGLES; i++) {
    for (let j = 0; j < SPEEDS; j++) {
      if (hit[i * SPEEDS + j] === 0) continue
      let dmin = Math.min(i + 1, ANGLES - i, j + 1, SPEEDS - j)
      for (let di = -dmin + 1; di < dmin; di++) {
        for (let dj = -dmin + 1; dj < dmin; dj++) {
          const a = i + di
          const b = j + dj
          if (hit[a * SPEEDS + b] === 0) dmin = Math.max(Math.abs(di), Math.abs(dj))
        }
      }
      depth[i * SPEEDS + j] = dmin
    }
  }
  return depth
}
