// Balls: put down (addBall) or thrown (throwBall), re-aimed, made hero, read and removed. A ball added
// inside a lip circle is in transit through that hole (no decision is made for it; if it stops before
// leaving, it falls in).
import { removeEntity } from 'bitecs'
import { BALL_MODE_NAMES, BallMode, type BallModeName } from '../../components/Ball.js'
import { RimMode } from '../../components/RimContact.js'
import { MAX_COORDINATE, MAX_MASS, MAX_RADIUS, MAX_SPEED, MIN_MASS } from '../config/limits.js'
import { launchBall, placeBall } from '../motion/ballFate.js'
import { sampleRimRoll } from '../motion/rimRoll.js'
import { startAt, sampleRolling } from '../motion/rolling.js'
import { addBallEntity, forEachBall } from '../world/balls.js'
import type { BallWorld } from '../world/createWorld.js'
import { rimSlot } from '../world/rimSlots.js'
import { setBallMode } from '../world/ballMode.js'
import { dropGoneHeld, insertId, pushId } from '../world/idLists.js'
import { firstHeldAt, heldAt, heldOn, spotTaken } from '../contacts/spot.js'
import { heldJoin } from '../world/heldGrid.js'
import { betweenSteps, checkBall, checkHole, checkWorld, choice, finite, flag, positive, specObject, within } from './validate.js'
import { cos, sin } from '../math.js'
import { record, specOf } from '../world/recorder.js'

export interface BallSpec {
  x: number
  y: number
  /** px/s, default 0 (put down at rest) */
  vx?: number | undefined
  /** px/s, default 0 */
  vy?: number | undefined
  /** px, default config.BALL_RADIUS */
  radius?: number | undefined
  /** the physical reference decides this ball's lip crossings (docs/physical.md); default false */
  hero?: boolean | undefined
  /**
   * mass for ball-ball contacts, in units of a default ball, in [MIN_MASS, MAX_MASS] = [1e-15, 1e9]; default
   * (radius / BALL_RADIUS)³ (same density), taken into that range. Used only when config.BALL_COLLISIONS is 'on'
   * or 'fixed'.
   */
  mass?: number | undefined
  /**
   * With contacts on, where the ball waits if it is put down where another ball is (mode 'held'; launched
   * when its spot is clear, systems/launcher.ts): 'back' (the default) behind every ball already waiting on
   * its spot, and held even where the spot is clear but balls wait on it; 'front' ahead of them all, and
   * held only where a ball is on the spot now (for a player's throw during a launcher's burst)
   */
  queue?: 'back' | 'front' | undefined
}

export interface ThrowSpec {
  x: number
  y: number
  /** 0..1, mapped linearly onto MIN_VY..MAX_VY */
  power: number
  /** radians, 0 = straight up the panel (−y), positive toward +x; in [−2π, 2π] */
  angle: number
  /** px, default config.BALL_RADIUS */
  radius?: number | undefined
  /** the physical reference decides this ball's lip crossings (docs/physical.md); default false */
  hero?: boolean | undefined
  /** as BallSpec.mass */
  mass?: number | undefined
  /** as BallSpec.queue */
  queue?: 'back' | 'front' | undefined
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

const BALL_KEYS = ['x', 'y', 'vx', 'vy', 'radius', 'hero', 'mass', 'queue'] as const
const THROW_KEYS = ['x', 'y', 'power', 'angle', 'radius', 'hero', 'mass', 'queue'] as const
const QUEUES = ['back', 'front'] as const

function massOf(w: BallWorld, field: string, value: unknown, radius: number): number {
  if (value === undefined) {
    // (radius / BALL_RADIUS)³, within the accepted masses: with a small BALL_RADIUS it passed MAX_MASS (or
    // overflowed), with a tiny radius it fell to 0
    const k = radius / w.config.BALL_RADIUS
    const m = k * k * k
    return m < MIN_MASS ? MIN_MASS : m > MAX_MASS ? MAX_MASS : m
  }
  return within(field, value, MIN_MASS, MAX_MASS)
}

function newBall(w: BallWorld, x: number, y: number, vx: number, vy: number, radius: number, hero: boolean, mass: number, front: boolean): number {
  // removed held balls leave the queue before an id is reused: one listed at a removed ball's place would
  // be taken for it once held
  dropGoneHeld(w)
  const eid = addBallEntity(w)
  w.Ball.radius[eid] = radius
  w.Ball.hero[eid] = hero ? 1 : 0
  if (w.collide !== null) w.collide.mass[eid] = mass
  if (w.fixed !== null) w.fixed.mass[eid] = mass
  // with contacts on, a ball put down where another is, or waits, waits there until its spot is clear and the
  // balls that came before it have left (systems/launcher.ts); one put down at the front of the queue waits
  // only where a ball is, ahead of those waiting there
  if ((w.collide !== null || w.fixed !== null) && ((!front && heldOn(w, eid, x, y, radius)) || spotTaken(w, eid, x, y, radius))) {
    const B = w.Ball
    B.x[eid] = x
    B.y[eid] = y
    B.vx[eid] = vx
    B.vy[eid] = vy
    setBallMode(w, eid, BallMode.Held)
    const at = front ? firstHeldAt(w, eid, x, y, radius) : -1
    if (at >= 0) insertId(w.held, at, eid)
    else pushId(w.held, eid)
    heldJoin(w, eid)
    return eid
  }
  placeBall(w, eid, x, y, vx, vy)
  return eid
}

/** Puts a ball down at (x, y) with velocity (vx, vy) (default 0, at rest), now; returns its entity id. */
export function addBall(world: BallWorld, spec: BallSpec): number {
  const w = checkWorld('addBall', world)
  betweenSteps(w, 'addBall', 'put balls down and set their velocities between steps (a system may remove a ball)')
  // each field read once, into locals (a ball added in a burst allocates nothing here)
  const s = specObject('addBall spec', spec, BALL_KEYS, 'ball')
  const sx = s.x
  const sy = s.y
  const svx = s.vx
  const svy = s.vy
  const sRadius = s.radius
  const sHero = s.hero
  const sMass = s.mass
  const sQueue = s.queue
  const x = finite('ball.x', sx, MAX_COORDINATE)
  const y = finite('ball.y', sy, MAX_COORDINATE)
  const vx = svx === undefined ? 0 : finite('ball.vx', svx, MAX_SPEED)
  const vy = svy === undefined ? 0 : finite('ball.vy', svy, MAX_SPEED)
  const radius = sRadius === undefined ? w.config.BALL_RADIUS : positive('ball.radius', sRadius, MAX_RADIUS)
  const hero = flag('ball.hero', sHero)
  const mass = massOf(w, 'ball.mass', sMass, radius)
  const front = choice('ball.queue', sQueue, QUEUES) === 'front'
  if (w.recorder !== null) record(w, ['addBall', specOf({ x: sx, y: sy, vx: svx, vy: svy, radius: sRadius, hero: sHero, mass: sMass, queue: sQueue })])
  return newBall(w, x, y, vx, vy, radius, hero, mass, front)
}

/** The throw's velocity: speed MIN_VY + power·(MAX_VY − MIN_VY), at `angle` from straight up the panel. */
export function throwVelocity(world: BallWorld, power: number, angle: number): { vx: number; vy: number } {
  const cfg = world.config
  const speed = cfg.MIN_VY + power * (cfg.MAX_VY - cfg.MIN_VY)
  return { vx: speed * sin(angle), vy: -speed * cos(angle) }
}

/** Throws a ball from (x, y) with the meter's power and an aim; returns its entity id. */
export function throwBall(world: BallWorld, spec: ThrowSpec): number {
  const w = checkWorld('throwBall', world)
  betweenSteps(w, 'throwBall', 'put balls down and set their velocities between steps (a system may remove a ball)')
  const s = specObject('throwBall spec', spec, THROW_KEYS, 'throw')
  const sx = s.x
  const sy = s.y
  const sPower = s.power
  const sAngle = s.angle
  const sRadius = s.radius
  const sHero = s.hero
  const sMass = s.mass
  const sQueue = s.queue
  const x = finite('throw.x', sx, MAX_COORDINATE)
  const y = finite('throw.y', sy, MAX_COORDINATE)
  const power = within('throw.power', sPower, 0, 1)
  const angle = finite('throw.angle', sAngle, 2 * Math.PI)
  const radius = sRadius === undefined ? w.config.BALL_RADIUS : positive('throw.radius', sRadius, MAX_RADIUS)
  const hero = flag('throw.hero', sHero)
  const mass = massOf(w, 'throw.mass', sMass, radius)
  const front = choice('throw.queue', sQueue, QUEUES) === 'front'
  if (w.recorder !== null) {
    record(w, ['throwBall', specOf({ x: sx, y: sy, power: sPower, angle: sAngle, radius: sRadius, hero: sHero, mass: sMass, queue: sQueue })])
  }
  const cfg = w.config
  const speed = cfg.MIN_VY + power * (cfg.MAX_VY - cfg.MIN_VY)
  return newBall(w, x, y, speed * sin(angle), -speed * cos(angle), radius, hero, mass, front)
}

/**
 * Removes a ball: the same as bitECS removeEntity on it (the simulation forgets it, the game's components
 * go with it, and events buffered for it are dropped at the next drain).
 */
export function removeBall(world: BallWorld, ball: number): void {
  const w = checkWorld('removeBall', world)
  const b = checkBall(w, 'ball', ball)
  if (w.recorder !== null) record(w, ['removeBall', b])
  removeEntity(w, b)
}

/**
 * Sets a ball's velocity now: wakes a resting ball, re-aims a rolling one, and knocks a ball off a rim
 * (it leaves on a straight path, the hole locked until it is out). Captured and out balls cannot move.
 */
export function setBallVelocity(world: BallWorld, ball: number, vx: number, vy: number): void {
  const w = checkWorld('setBallVelocity', world)
  betweenSteps(w, 'setBallVelocity', 'put balls down and set their velocities between steps (a system may remove a ball)')
  const b = checkBall(w, 'ball', ball)
  const nvx = finite('vx', vx, MAX_SPEED)
  const nvy = finite('vy', vy, MAX_SPEED)
  const mode = w.Ball.mode[b]!
  if (w.recorder !== null && mode !== BallMode.Captured && mode !== BallMode.Out) record(w, ['setBallVelocity', b, nvx, nvy])
  if (mode === BallMode.Held) {
    // it leaves with this velocity when its spot is clear
    w.Ball.vx[b] = nvx
    w.Ball.vy[b] = nvy
    return
  }
  if (mode === BallMode.Captured || mode === BallMode.Out) {
    throw new RangeError(`ball ${b} is ${BALL_MODE_NAMES[mode]}: only rolling, rimRoll, resting or held balls can be given a velocity`)
  }
  if (mode === BallMode.RimRoll) {
    sampleRimRoll(w, b, w.time)
    w.RimContact.mode[rimSlot(w, b)] = RimMode.Transit
  } else if (mode === BallMode.Rolling) {
    sampleRolling(w, b, w.time)
  }
  startAt(w.Ball.x[b]!, w.Ball.y[b]!, nvx, nvy, w.time)
  launchBall(w, b)
  // fixed-tick contacts: the new path up to the next tick is checked at the next step's start
  if (w.fixed !== null) w.fixed.due = true
}

/**
 * Sets a ball's mass for ball-ball contacts (in units of a default ball, in [MIN_MASS, MAX_MASS]), from its
 * next contact on: a power-up's heavy ball. Between steps, as velocities. With contacts off a ball's mass is
 * not kept (as addBall's): the call checks its input and changes nothing.
 */
export function setBallMass(world: BallWorld, ball: number, mass: number): void {
  const w = checkWorld('setBallMass', world)
  betweenSteps(w, 'setBallMass', 'set masses between steps (the contacts of a step under way read them)')
  const b = checkBall(w, 'ball', ball)
  const m = within('mass', mass, MIN_MASS, MAX_MASS)
  if (w.recorder !== null) record(w, ['setBallMass', b, m])
  if (w.collide !== null) w.collide.mass[b] = m
  if (w.fixed !== null) w.fixed.mass[b] = m
}

/**
 * Makes a ball a hero (or not): from its next lip crossing on, the physical reference decides it instead
 * of the six stages (systems/heroReference.ts). Costs one reference run per hero lip crossing.
 */
export function setHeroBall(world: BallWorld, ball: number, hero = true): void {
  const w = checkWorld('setHeroBall', world)
  const b = checkBall(w, 'ball', ball)
  const on = flag('hero', hero)
  if (w.recorder !== null) record(w, ['setHeroBall', b, on])
  w.Ball.hero[b] = on ? 1 : 0
}

/** True for a hero ball. */
export function isHeroBall(world: BallWorld, ball: number): boolean {
  const w = checkWorld('isHeroBall', world, true)
  return w.Ball.hero[checkBall(w, 'ball', ball)] === 1
}

/** A ball's state at the end of the last step (a new object). */
export function ballState(world: BallWorld, ball: number): BallState {
  const w = checkWorld('ballState', world, true)
  const b = checkBall(w, 'ball', ball)
  const B = w.Ball
  return { x: B.x[b]!, y: B.y[b]!, vx: B.vx[b]!, vy: B.vy[b]!, radius: B.radius[b]!, mode: BALL_MODE_NAMES[B.mode[b]!]! }
}

/**
 * For a ball held at its spot (mode 'held': contacts on, put down where another ball is or waits), how many
 * held balls wait ahead of it on that spot: those before it in the launcher's queue that overlap it, which
 * leave before it does. -1 for a ball that is not held. For a game's "your ball waits behind n balls".
 */
export function heldAhead(world: BallWorld, ball: number): number {
  const w = checkWorld('heldAhead', world, true)
  const b = checkBall(w, 'ball', ball)
  const B = w.Ball
  if (B.mode[b] !== BallMode.Held) return -1
  const q = w.held
  let ahead = 0
  for (let i = 0; i < q.count && q.ids[i] !== b; i++) if (heldAt(w, q.ids[i]!, b, B.x[b]!, B.y[b]!, B.radius[b]!)) ahead++
  return ahead
}

/**
 * How many balls wait held at their spots in the launcher's queue (contacts on: put down on another ball),
 * for a game's "n balls waiting" and to notice a launcher firing faster than its spots clear (each spot lets
 * out a ball about every 1/16 s at the defaults, and the queue grows without limit beyond that).
 */
export function heldCount(world: BallWorld): number {
  const w = checkWorld('heldCount', world, true)
  dropGoneHeld(w)
  return w.held.count
}

/** A hole's geometry and value (a new object). */
export function holeState(world: BallWorld, hole: number): HoleState {
  const w = checkWorld('holeState', world, true)
  const h = checkHole(w, 'hole', hole)
  const H = w.Hole
  return { x: H.x[h]!, y: H.y[h]!, radius: H.radius[h]!, value: H.value[h]! }
}

/** ids of the live balls, ascending (a new array). */
export function listBalls(world: BallWorld): number[] {
  const w = checkWorld('listBalls', world, true)
  const out: number[] = []
  forEachBall(w, (b) => void out.push(b))
  return out
}

/** ids of the holes, in the order they were added (a new array). */
export function listHoles(world: BallWorld): number[] {
  const w = checkWorld('listHoles', world, true)
  return Array.from(w.holes.ids.subarray(0, w.holes.count))
}
