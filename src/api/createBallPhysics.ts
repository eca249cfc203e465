// The public API: a world, its schedule and clock behind a small typed surface. Every call validates all
// of its input before it changes anything, so a rejected call leaves the world as it was.
import { addComponent, addEntity, entityExists, hasComponent, removeEntity } from 'bitecs'
import { BALL_MODE_NAMES, BallMode, type BallModeName } from '../../components/Ball.js'
import { RimMode } from '../../components/RimContact.js'
import { WallEdge } from '../../components/Walls.js'
import type { BallPhysicsConfig, ConfigOverrides } from '../config/design.js'
import { CaptureVia, drainEventBuffer, type BallEvent } from '../events.js'
import { captureBall, launchBall } from '../motion/ballFate.js'
import { planRolling, sampleRolling, startPath } from '../motion/rolling.js'
import { sampleRimRoll } from '../motion/rimRoll.js'
import { createSchedule, runSchedule, type ScheduleEntry } from '../schedule.js'
import { clearSlot, fitStore } from '../../components/store.js'
import {
  acquireRim,
  addBallEntity,
  addHoleToTable,
  createBallWorld,
  forEachBall,
  isBall,
  removeBallEntity,
  rimSlot,
  type BallWorld,
  type BallWorldOptions,
} from '../world/createWorld.js'

/** Largest |coordinate| accepted, px: keeps squares of distances far from overflow. */
export const MAX_COORDINATE = 1e9
/** Largest |velocity component| accepted, px/s. */
export const MAX_SPEED = 1e7
/** Largest radius accepted, px. */
export const MAX_RADIUS = 1e4
/** Largest |hole value| accepted. */
export const MAX_VALUE = 1e12
/** Largest ball mass accepted, in units of a default ball. */
export const MAX_MASS = 1e9

export interface HoleSpec {
  x: number
  y: number
  /** px, default config.HOLE_RADIUS */
  radius?: number
  /** points, default 1 */
  value?: number
}

export interface BallSpec {
  x: number
  y: number
  vx: number
  vy: number
  /** px, default config.BALL_RADIUS */
  radius?: number
  /** the physical reference decides this ball's lip crossings (docs/physical.md); default false */
  hero?: boolean
  /**
   * mass for ball-ball contacts, in units of a default ball, in (0, MAX_MASS]; default (radius / BALL_RADIUS)³
   * (same density). Used only when config.BALL_COLLISIONS is 'on'.
   */
  mass?: number
}

export interface ThrowSpec {
  x: number
  y: number
  /** 0..1, mapped linearly onto MIN_VY..MAX_VY */
  power: number
  /** radians, 0 = straight up the panel (−y), positive toward +x; in [−2π, 2π] */
  angle: number
  /** px, default config.BALL_RADIUS */
  radius?: number
  /** the physical reference decides this ball's lip crossings (docs/physical.md); default false */
  hero?: boolean
  /**
   * mass for ball-ball contacts, in units of a default ball, in (0, MAX_MASS]; default (radius / BALL_RADIUS)³
   * (same density). Used only when config.BALL_COLLISIONS is 'on'.
   */
  mass?: number
}

export interface WallsSpec {
  /** inner faces of the rectangle, px (y down: top = minY); maxX > minX, maxY > minY */
  minX: number
  minY: number
  maxX: number
  maxY: number
  /** normal restitution at the walls, [0, 1]; default 0.5 */
  restitution?: number
  /** open edges: a ball whose centre crosses one leaves the panel ('gutter' event, mode 'out') */
  open?: { left?: boolean; top?: boolean; right?: boolean; bottom?: boolean }
}

export interface BallState {
  x: number
  y: number
  vx: number
  vy: number
  radius: number
  mode: BallModeName
}

export interface HoleState {
  x: number
  y: number
  radius: number
  value: number
}

export interface BallPhysics {
  readonly world: BallWorld
  readonly config: Readonly<BallPhysicsConfig>
  /** the pipeline, in order; editable (see schedule.ts) */
  readonly schedule: ScheduleEntry[]
  /** simulation time, s */
  readonly time: number
  addHole(spec: HoleSpec): number
  addBall(spec: BallSpec): number
  throwBall(spec: ThrowSpec): number
  /** Advances by dt seconds (any finite dt > 0; more than MAX_STEP is cut to MAX_STEP). Returns the dt simulated. */
  step(dt: number): number
  /** Events since the last drain, in time order. */
  drainEvents(): BallEvent[]
  ballState(ball: number): BallState
  holeState(hole: number): HoleState
  removeBall(ball: number): void
  /**
   * Sets a ball's velocity now: wakes a resting ball, re-aims a rolling one, and knocks a ball off a rim
   * (it leaves on a straight path, the hole locked until it is out). Captured and out balls cannot move.
   */
  setBallVelocity(ball: number, vx: number, vy: number): void
  /**
   * Makes a ball a hero (or not): from its next lip crossing on, the physical reference decides it instead
   * of the six stages (systems/heroReference.ts). Costs one reference run per hero lip crossing.
   */
  setHeroBall(ball: number, hero?: boolean): void
  /** True for a hero ball. */
  isHeroBall(ball: number): boolean
  /** Puts walls round the panel (or replaces them); rolling balls are re-planned from where they are. */
  setWalls(spec: WallsSpec): void
  /** Removes the walls. */
  clearWalls(): void
  /** ids of the live balls, ascending (a new array) */
  balls(): number[]
  /** ids of the holes (a new array) */
  holes(): number[]
}

function finite(field: string, value: unknown, limit: number): number {
  if (typeof value !== 'number') throw new TypeError(`${field} must be a number in [${-limit}, ${limit}], got ${typeof value}`)
  if (!Number.isFinite(value) || Math.abs(value) > limit) {
    throw new RangeError(`${field} must be a finite number in [${-limit}, ${limit}], got ${value}`)
  }
  return value
}

function positive(field: string, value: unknown, limit: number): number {
  if (typeof value !== 'number') throw new TypeError(`${field} must be a number in (0, ${limit}], got ${typeof value}`)
  if (!Number.isFinite(value) || value <= 0 || value > limit) {
    throw new RangeError(`${field} must be in (0, ${limit}], got ${value}`)
  }
  return value
}

function flag(field: string, value: unknown): boolean {
  if (value === undefined) return false
  if (typeof value !== 'boolean') throw new TypeError(`${field} must be a boolean, got ${typeof value}`)
  return value
}

function spec<T>(name: string, value: T): T {
  if (value === null || typeof value !== 'object') throw new TypeError(`${name} must be an object`)
  return value
}

/** Creates a simulation with the design's constants, changed by `overrides` (validated). */
export function createBallPhysics(overrides: ConfigOverrides = {}, options: BallWorldOptions = {}): BallPhysics {
  const w = createBallWorld(overrides, options)
  const cfg = w.config
  const schedule = createSchedule(cfg)

  const checkId = (field: string, eid: unknown, kind: string): number => {
    if (typeof eid !== 'number' || !Number.isInteger(eid) || eid < 1) {
      throw new TypeError(`${field} must be a ${kind} id (a positive integer), got ${String(eid)}`)
    }
    return eid
  }
  const notLive = (field: string, eid: number, kind: string) =>
    new RangeError(`${field} ${eid} is not a live ${kind} of this world (unknown or removed)`)
  const checkBall = (field: string, eid: unknown): number => {
    const b = checkId(field, eid, 'ball')
    if (!isBall(w, b)) throw notLive(field, b, 'ball')
    return b
  }
  const checkHole = (field: string, eid: unknown): number => {
    const h = checkId(field, eid, 'hole')
    if (!entityExists(w, h) || !hasComponent(w, h, w.IsHole)) throw notLive(field, h, 'hole')
    return h
  }

  /** The hole whose lip circle contains (x, y), or 0. */
  const holeAt = (x: number, y: number): number => {
    const t = w.holes
    for (let i = 0; i < t.count; i++) {
      const dx = x - t.xyr[3 * i]!
      const dy = y - t.xyr[3 * i + 1]!
      const R = t.xyr[3 * i + 2]!
      if (dx * dx + dy * dy < R * R) return t.ids[i]!
    }
    return 0
  }

  const massOf = (field: string, value: unknown, radius: number): number => {
    if (value === undefined) {
      const k = radius / cfg.BALL_RADIUS
      return k * k * k
    }
    return positive(field, value, MAX_MASS)
  }

  const newBall = (x: number, y: number, vx: number, vy: number, radius: number, hero: boolean, mass: number): number => {
    const eid = addBallEntity(w)
    w.Ball.radius[eid] = radius
    w.Ball.hero[eid] = hero ? 1 : 0
    if (w.collide !== null) {
      w.collide.mass[eid] = mass
      if (radius > w.collide.maxRadius) w.collide.maxRadius = radius
    }
    // rule for a ball added inside a lip circle: it is in transit through that hole (no decision is made
    // for it); if it stops before leaving, it falls in
    const inside = holeAt(x, y)
    if (inside !== 0) {
      const slot = acquireRim(w, eid)
      w.RimContact.hole[slot] = inside
      w.RimContact.mode[slot] = RimMode.Transit
    }
    launchBall(w, eid, x, y, vx, vy, w.time)
    return eid
  }

  /** Rolling balls continue from where they are now, planned against what changed (holes, walls). */
  const replanRolling = (): void => {
    forEachBall(w, (b) => {
      if (w.Ball.mode[b] !== BallMode.Rolling) return
      sampleRolling(w, b, w.time)
      startPath(w, b, w.Ball.x[b]!, w.Ball.y[b]!, w.Ball.vx[b]!, w.Ball.vy[b]!, w.time)
      planRolling(w, b)
    })
  }

  const sim: BallPhysics = {
    world: w,
    config: cfg,
    schedule,
    get time() {
      return w.time
    },

    addHole(s) {
      spec('addHole spec', s)
      const x = finite('hole.x', s.x, MAX_COORDINATE)
      const y = finite('hole.y', s.y, MAX_COORDINATE)
      const radius = s.radius === undefined ? cfg.HOLE_RADIUS : positive('hole.radius', s.radius, MAX_RADIUS)
      const value = s.value === undefined ? 1 : finite('hole.value', s.value, MAX_VALUE)
      const t = w.holes
      for (let i = 0; i < t.count; i++) {
        const dx = x - t.xyr[3 * i]!
        const dy = y - t.xyr[3 * i + 1]!
        const min = radius + t.xyr[3 * i + 2]!
        if (dx * dx + dy * dy < min * min) {
          throw new RangeError(
            `hole at (${x}, ${y}) with radius ${radius} overlaps hole ${t.ids[i]}: lip circles may not overlap ` +
              `(centres at least ${min} px apart)`,
          )
        }
      }
      const eid = addEntity(w)
      fitStore(w.Hole, eid)
      addComponent(w, eid, w.IsHole)
      addComponent(w, eid, w.Hole)
      w.Hole.x[eid] = x
      w.Hole.y[eid] = y
      w.Hole.radius[eid] = radius
      w.Hole.value[eid] = value
      addHoleToTable(w, eid)
      // balls already out there: a ball inside the new lip circle follows the rule for a ball added inside
      // a hole; then rolling ones continue from where they are, planned against the new hole
      forEachBall(w, (b) => {
        const mode = w.Ball.mode[b]
        if (mode === BallMode.Rolling) sampleRolling(w, b, w.time)
        else if (mode !== BallMode.Resting) return
        const dx = w.Ball.x[b]! - x
        const dy = w.Ball.y[b]! - y
        if (dx * dx + dy * dy >= radius * radius) return
        const slot = acquireRim(w, b)
        w.RimContact.hole[slot] = eid
        w.RimContact.hasLip[slot] = 0
        if (mode === BallMode.Resting) captureBall(w, b, eid, w.time, CaptureVia.Rest)
        else w.RimContact.mode[slot] = RimMode.Transit
      })
      replanRolling()
      return eid
    },

    addBall(s) {
      spec('addBall spec', s)
      const x = finite('ball.x', s.x, MAX_COORDINATE)
      const y = finite('ball.y', s.y, MAX_COORDINATE)
      const vx = finite('ball.vx', s.vx, MAX_SPEED)
      const vy = finite('ball.vy', s.vy, MAX_SPEED)
      const radius = s.radius === undefined ? cfg.BALL_RADIUS : positive('ball.radius', s.radius, MAX_RADIUS)
      const hero = flag('ball.hero', s.hero)
      const mass = massOf('ball.mass', s.mass, radius)
      return newBall(x, y, vx, vy, radius, hero, mass)
    },

    throwBall(s) {
      spec('throwBall spec', s)
      const x = finite('throw.x', s.x, MAX_COORDINATE)
      const y = finite('throw.y', s.y, MAX_COORDINATE)
      if (typeof s.power !== 'number') throw new TypeError(`throw.power must be a number in [0, 1], got ${typeof s.power}`)
      if (!(s.power >= 0 && s.power <= 1)) throw new RangeError(`throw.power must be in [0, 1], got ${s.power}`)
      const angle = finite('throw.angle', s.angle, 2 * Math.PI)
      const radius = s.radius === undefined ? cfg.BALL_RADIUS : positive('throw.radius', s.radius, MAX_RADIUS)
      const hero = flag('throw.hero', s.hero)
      const mass = massOf('throw.mass', s.mass, radius)
      const speed = cfg.MIN_VY + s.power * (cfg.MAX_VY - cfg.MIN_VY)
      return newBall(x, y, speed * Math.sin(angle), -speed * Math.cos(angle), radius, hero, mass)
    },

    step(dt) {
      if (typeof dt !== 'number') throw new TypeError(`dt must be a number of seconds > 0, got ${typeof dt}`)
      if (!Number.isFinite(dt) || dt <= 0) throw new RangeError(`dt must be a finite number of seconds > 0, got ${dt}`)
      // a long frame (a tab that slept) is not caught up: at most MAX_STEP of simulated time per call
      const h = dt > cfg.MAX_STEP ? cfg.MAX_STEP : dt
      runSchedule(w, schedule, h)
      return h
    },

    setBallVelocity(ball, vx, vy) {
      const b = checkBall('ball', ball)
      const nvx = finite('vx', vx, MAX_SPEED)
      const nvy = finite('vy', vy, MAX_SPEED)
      const mode = w.Ball.mode[b]!
      if (mode === BallMode.Captured || mode === BallMode.Out) {
        throw new RangeError(`ball ${b} is ${BALL_MODE_NAMES[mode]}: only rolling, rimRoll or resting balls can be moved`)
      }
      if (mode === BallMode.RimRoll) {
        sampleRimRoll(w, b, w.time)
        w.RimContact.mode[rimSlot(w, b)] = RimMode.Transit
      } else if (mode === BallMode.Rolling) {
        sampleRolling(w, b, w.time)
      }
      launchBall(w, b, w.Ball.x[b]!, w.Ball.y[b]!, nvx, nvy, w.time)
    },

    setHeroBall(ball, hero = true) {
      const b = checkBall('ball', ball)
      w.Ball.hero[b] = flag('hero', hero) ? 1 : 0
    },

    isHeroBall(ball) {
      const b = checkBall('ball', ball)
      return w.Ball.hero[b] === 1
    },

    setWalls(s) {
      spec('setWalls spec', s)
      const minX = finite('walls.minX', s.minX, MAX_COORDINATE)
      const minY = finite('walls.minY', s.minY, MAX_COORDINATE)
      const maxX = finite('walls.maxX', s.maxX, MAX_COORDINATE)
      const maxY = finite('walls.maxY', s.maxY, MAX_COORDINATE)
      if (!(maxX > minX)) throw new RangeError(`walls.maxX must be > walls.minX = ${minX}, got ${maxX}`)
      if (!(maxY > minY)) throw new RangeError(`walls.maxY must be > walls.minY = ${minY}, got ${maxY}`)
      const e = s.restitution === undefined ? 0.5 : s.restitution
      if (typeof e !== 'number' || !(e >= 0 && e <= 1)) throw new RangeError(`walls.restitution must be in [0, 1], got ${e}`)
      const o = s.open ?? {}
      if (o === null || typeof o !== 'object') throw new TypeError('walls.open must be an object of booleans')
      const open = (o.left ? WallEdge.Left : 0) | (o.top ? WallEdge.Top : 0) | (o.right ? WallEdge.Right : 0) | (o.bottom ? WallEdge.Bottom : 0)
      if (w.walls === 0) {
        const eid = addEntity(w)
        fitStore(w.Walls, eid)
        addComponent(w, eid, w.Walls)
        w.walls = eid
      }
      const W = w.Walls
      W.minX[w.walls] = minX
      W.minY[w.walls] = minY
      W.maxX[w.walls] = maxX
      W.maxY[w.walls] = maxY
      W.restitution[w.walls] = e
      W.open[w.walls] = open
      replanRolling()
    },

    clearWalls() {
      if (w.walls === 0) return
      removeEntity(w, w.walls)
      clearSlot(w.Walls, w.walls)
      w.walls = 0
      replanRolling()
    },

    drainEvents() {
      return drainEventBuffer(w.events)
    },

    ballState(ball) {
      const b = checkBall('ball', ball)
      const B = w.Ball
      return { x: B.x[b]!, y: B.y[b]!, vx: B.vx[b]!, vy: B.vy[b]!, radius: B.radius[b]!, mode: BALL_MODE_NAMES[B.mode[b]!]! }
    },

    holeState(hole) {
      const h = checkHole('hole', hole)
      const H = w.Hole
      return { x: H.x[h]!, y: H.y[h]!, radius: H.radius[h]!, value: H.value[h]! }
    },

    removeBall(ball) {
      const b = checkBall('ball', ball)
      removeBallEntity(w, b)
    },

    balls() {
      const out: number[] = []
      forEachBall(w, (b) => void out.push(b))
      return out
    },

    holes() {
      return Array.from(w.holes.ids.subarray(0, w.holes.count))
    },
  }
  return sim
}
