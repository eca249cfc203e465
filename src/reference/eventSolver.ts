// The reference: an exact event-driven solver of the game model for one ball over a set of holes, with no
// ticks and no ECS. It walks from event to event along the closed forms of src/geometry.ts:
//   straight roll  s(τ) = v0·τ − a·τ²/2        lip crossing where |x(s) − c| = R, contact where = R − r/2,
//                                               exit where the path leaves a lip circle, near miss at the
//                                               closest approach p when R ≤ δ < R + r, stop at v0²/(2a)
//   rim roll       v_t(τ) = v_t0·e^(−μτ)        drop at ln(v_t0/v_drop)/μ, pop off at −ln(1 − μ·arc/v_t0)/μ
// and decides each event by the six stages in the core's order (skip-over, capture, COG gate, bounce or
// rim roll). It shares no code with systems/ (only the closed forms), so the ECS core can be checked against
// it. Events on one straight segment are listed once, sorted by (distance, stop first, hole id), and
// consumed in order; a decision that changes the velocity starts a new segment.
import type { BallPhysicsConfig } from '../config/design.js'
import type { BallEventType, CaptureViaName } from '../events.js'
import {
  capturesClean,
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
  vSkip,
} from '../geometry.js'
import { atan2, cos, hypot, sin, sq } from '../math.js'

export interface SolverHole {
  x: number
  y: number
  /** px, default config.HOLE_RADIUS */
  radius?: number
  /** reported in events; default: the index + 1 (ties between holes at one distance go to the lower id) */
  id?: number
}

export interface SolverBall {
  x: number
  y: number
  vx: number
  vy: number
  /** px, default config.BALL_RADIUS */
  radius?: number
}

export interface SolverEvent {
  type: BallEventType
  hole?: number
  time: number
  /** δ and v at the lip crossing of the hole (a near miss without one: closest approach and speed there) */
  delta?: number
  speed?: number
  via?: CaptureViaName
}

export type SolverMode = 'rolling' | 'captured' | 'resting'

export interface SolverResult {
  events: SolverEvent[]
  x: number
  y: number
  vx: number
  vy: number
  mode: SolverMode
  /** time of the last event, or tMax if the ball still rolls */
  time: number
}

export interface SolverOptions {
  /** stop solving at this time if the ball still rolls (ROLLING_DECEL = 0), s; default 600 */
  tMax?: number
  /** safety bound on events; default 100,000 */
  maxEvents?: number
}

const Kind = { Stop: 0, Lip: 1, Contact: 2, Exit: 3, Near: 4 } as const
type KindCode = (typeof Kind)[keyof typeof Kind]

interface Candidate {
  s: number
  kind: KindCode
  hole: number
}

interface Hole {
  x: number
  y: number
  R: number
  id: number
}

/** Orders candidates on a segment: by distance, a stop before anything at the same distance, then hole id. */
function before(a: Candidate, b: Candidate): number {
  if (a.s !== b.s) return a.s - b.s
  if ((a.kind === Kind.Stop) !== (b.kind === Kind.Stop)) return a.kind === Kind.Stop ? -1 : 1
  return a.hole - b.hole
}

function insert(list: Candidate[], c: Candidate): void {
  let k = 0
  while (k < list.length && before(list[k]!, c) <= 0) k++
  list.splice(k, 0, c)
}

/** Solves one ball from time 0 until it is captured, rests, or tMax passes. */
export function solveBall(
  config: Readonly<BallPhysicsConfig>,
  holeSpecs: readonly SolverHole[],
  ball: SolverBall,
  options: SolverOptions = {},
): SolverResult {
  const tMax = options.tMax ?? 600
  const maxEvents = options.maxEvents ?? 100_000
  const a = config.ROLLING_DECEL
  const r = ball.radius ?? config.BALL_RADIUS
  const holes: Hole[] = holeSpecs.map((h, i) => ({ x: h.x, y: h.y, R: h.radius ?? config.HOLE_RADIUS, id: h.id ?? i + 1 }))
  const byId = new Map(holes.map((h) => [h.id, h]))
  const events: SolverEvent[] = []

  // the lock: the hole whose lip circle the centre is inside (no new decision from it until the exit),
  // and the (δ, v) of its lip crossing
  let lock = 0
  let lip: { delta: number; speed: number } | undefined
  for (const h of holes) {
    if (sq(ball.x - h.x) + sq(ball.y - h.y) < h.R * h.R) lock = h.id // added inside: in transit
  }

  const holeEvent = (type: BallEventType, hole: number, time: number, via?: CaptureViaName): void => {
    const e: SolverEvent = { type, hole, time }
    if (lip !== undefined && lock === hole) {
      e.delta = lip.delta
      e.speed = lip.speed
    }
    if (via !== undefined) e.via = via
    events.push(e)
  }
  const done = (x: number, y: number, vx: number, vy: number, mode: SolverMode, time: number): SolverResult => ({
    events,
    x,
    y,
    vx,
    vy,
    mode,
    time,
  })

  // the current straight segment
  let x0 = ball.x
  let y0 = ball.y
  let t0 = 0
  let vx0 = ball.vx
  let vy0 = ball.vy
  let fromHole = 0

  for (let guard = 0; guard < maxEvents; guard++) {
    const v0 = hypot(vx0, vy0)
    const ux = v0 > 0 ? vx0 / v0 : 0
    const uy = v0 > 0 ? vy0 / v0 : 0
    const at = (s: number) => ({ x: x0 + ux * s, y: y0 + uy * s, v: speedAtDistance(s, v0, a) })
    const timeAt = (c: Candidate) => t0 + (c.kind === Kind.Stop ? stopTime(v0, a) : timeToDistance(c.s, v0, a))

    // every event of this segment, in order
    const list: Candidate[] = []
    const sStop = stopDistance(v0, a)
    if (sStop < Infinity) list.push({ s: sStop, kind: Kind.Stop, hole: 0 })
    if (v0 > 0) {
      for (const h of holes) {
        const p = (h.x - x0) * ux + (h.y - y0) * uy
        const c = (h.x - x0) * uy - (h.y - y0) * ux
        if (c * c < h.R * h.R) {
          const half = Math.sqrt(h.R * h.R - c * c)
          if (h.id === lock) list.push({ s: Math.max(0, p + half), kind: Kind.Exit, hole: h.id })
          else if (p > 0) list.push({ s: Math.max(0, p - half), kind: Kind.Lip, hole: h.id })
        } else if (h.id === lock) {
          list.push({ s: 0, kind: Kind.Exit, hole: h.id })
        } else if (c * c < sq(h.R + r) && p > 0 && h.id !== fromHole) {
          list.push({ s: p, kind: Kind.Near, hole: h.id })
        }
      }
    }
    list.sort(before)

    let newSegment = false
    while (list.length > 0 && !newSegment) {
      const ev = list.shift()!
      if (ev.s === Infinity) break
      const t = timeAt(ev)
      if (t > tMax) break
      const here = at(ev.s)
      const h = byId.get(ev.hole)
      if (ev.kind === Kind.Stop) {
        if (lock !== 0) {
          const hl = byId.get(lock)!
          holeEvent('capture', lock, t, 'rest')
          return done(hl.x, hl.y, 0, 0, 'captured', t)
        }
        events.push({ type: 'rest', time: t })
        return done(here.x, here.y, 0, 0, 'resting', t)
      }
      if (h === undefined) continue
      if (ev.kind === Kind.Exit) {
        if (lock === h.id) {
          lock = 0
          lip = undefined
        }
        continue
      }
      const c = Math.abs((h.x - x0) * uy - (h.y - y0) * ux)
      if (ev.kind === Kind.Near) {
        events.push({ type: 'nearMiss', hole: h.id, time: t, delta: c, speed: here.v })
        continue
      }
      if (ev.kind === Kind.Lip) {
        lock = h.id
        lip = { delta: c, speed: here.v }
        const p = (h.x - x0) * ux + (h.y - y0) * uy
        // Stage 5: flies over, locked until the exit
        if (here.v > vSkip(c, h.R, r, config.GRAVITY)) {
          holeEvent('skip', h.id, t)
          insert(list, { s: Math.max(ev.s, p + Math.sqrt(h.R * h.R - c * c)), kind: Kind.Exit, hole: h.id })
          continue
        }
        // Stage 1: clean capture
        if (capturesClean(c, here.v, h.R, config.V_MAX, config.CAPTURE_WINDOW)) {
          holeEvent('capture', h.id, t, 'clean')
          return done(h.x, h.y, 0, 0, 'captured', t)
        }
        // Stage 6: a brush bounces at the lip; otherwise on to the contact circle
        const rc = cogRadius(h.R, r)
        if (c >= rc) {
          ;[vx0, vy0] = bounce(here.x - h.x, here.y - h.y, ux * here.v, uy * here.v, config)
        } else {
          insert(list, { s: Math.max(ev.s, p - Math.sqrt(rc * rc - c * c)), kind: Kind.Contact, hole: h.id })
          continue
        }
      } else {
        // Kind.Contact: Stage 3's entry test at the contact circle
        const nx = here.x - h.x
        const ny = here.y - h.y
        const vx = ux * here.v
        const vy = uy * here.v
        const vn = vx * nx + vy * ny
        const vt = vx * ny - vy * nx
        if (Math.abs(vt) > config.RIM_ROLL_RATIO * Math.abs(vn)) {
          holeEvent('rimRoll', h.id, t)
          const len = hypot(nx, ny)
          const vtCcw = (-vx * ny + vy * nx) / len
          const vt0 = Math.abs(vtCcw)
          const dir = vtCcw >= 0 ? 1 : -1
          const phi0 = atan2(ny, nx)
          const mu = config.RIM_ROLL_FRICTION
          const tDrop = rollDropTime(vt0, mu, config.RIM_ROLL_DROP_SPEED)
          const tPop = rollPopTime(vt0, mu, popArc(config.RIM_ROLL_MAX_TURNS, h.R))
          if (!(tPop < tDrop)) {
            if (t + tDrop > tMax) return done(here.x, here.y, vx, vy, 'rolling', tMax)
            holeEvent('capture', h.id, t + tDrop, 'rimRoll')
            return done(h.x, h.y, 0, 0, 'captured', t + tDrop)
          }
          // pop off along the tangent at the end of the arc
          const tEnd = t + tPop
          // the centre rides the contact circle, where the roll began
          const rho = cogRadius(h.R, r)
          const phi = phi0 + (dir * rollArc(tPop, vt0, mu)) / rho
          const v = rollSpeed(tPop, vt0, mu)
          holeEvent('lipOut', h.id, tEnd)
          holeEvent('nearMiss', h.id, tEnd)
          fromHole = h.id
          x0 = h.x + rho * cos(phi)
          y0 = h.y + rho * sin(phi)
          vx0 = -dir * sin(phi) * v
          vy0 = dir * cos(phi) * v
          t0 = tEnd
          newSegment = true
          continue
        }
        ;[vx0, vy0] = bounce(nx, ny, vx, vy, config)
      }
      // a bounce (at the lip for a brush, at the contact circle otherwise): new segment from here
      holeEvent('bounce', h.id, t)
      holeEvent('nearMiss', h.id, t)
      fromHole = h.id
      x0 = here.x
      y0 = here.y
      t0 = t
      newSegment = true
    }
    if (!newSegment) {
      // no event left before tMax: the ball rolls on (ROLLING_DECEL = 0)
      const tau = tMax - t0
      const s = v0 * tau - 0.5 * a * tau * tau
      const v = v0 - a * tau
      return done(x0 + ux * s, y0 + uy * s, ux * v, uy * v, 'rolling', tMax)
    }
  }
  throw new Error(`solveBall: more than ${maxEvents} events`)
}

/**
 * Stage 2, the rim bounce law: v' = (1 − μ_t)·v_t − e·v_n·n̂ with n̂ along (nx, ny), written into `out`.
 * A zero normal (centre on the hole centre) is taken as head-on.
 */
export function rimBounce(
  nx: number,
  ny: number,
  vx: number,
  vy: number,
  restitution: number,
  friction: number,
  out: [number, number],
): [number, number] {
  let len = hypot(nx, ny)
  if (!(len > 0)) {
    const sp = hypot(vx, vy)
    nx = sp > 0 ? -vx / sp : 1
    ny = sp > 0 ? -vy / sp : 0
    len = 1
  }
  nx /= len
  ny /= len
  const vn = vx * nx + vy * ny
  const keep = 1 - friction
  out[0] = keep * (vx - vn * nx) - restitution * vn * nx
  out[1] = keep * (vy - vn * ny) - restitution * vn * ny
  return out
}

function bounce(nx: number, ny: number, vx: number, vy: number, config: Readonly<BallPhysicsConfig>): [number, number] {
  return rimBounce(nx, ny, vx, vy, config.RIM_RESTITUTION, config.RIM_FRICTION, [0, 0])
}

/** Initial velocity of a throw, as the API maps it: power 0..1 onto MIN_VY..MAX_VY, angle 0 = up (−y). */
export function throwVelocity(config: Readonly<BallPhysicsConfig>, power: number, angle: number): { vx: number; vy: number } {
  const speed = config.MIN_VY + power * (config.MAX_VY - config.MIN_VY)
  return { vx: speed * sin(angle), vy: -speed * cos(angle) }
}
