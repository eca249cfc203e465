// The motion functions a game's own systems call (the ./ecs entry's launchBall, startPath, planRolling,
// restBall, captureBall, …), checked. The systems of the schedule call the unchecked ones in src/motion with
// values they made themselves; a game's system passes its own, and a NaN or a time outside the step went
// straight into the stores (a path started at t = NaN gave every later event NaN). Each check names the
// function and the argument, and is made before anything changes.
//
// Time: between steps every t is the world's time; in a step it lies in the window the step is in,
// [world.time, world.tickEnd] (a ball stopped at an event is at that event's time, pathHot's H_NEXT_T).
//
// A ball given a new fate in a step (launched, rested, captured) leaves the event it was stopped at: its
// Path.mark is cleared, so no stage after the game's decides it again from where it was. With contacts off
// (and the fixed tick), a ball whose path a system restarted, or whose state it sampled at another instant,
// is handed to the next pass, which takes it to the window's end through its events (the integration
// system continues world.marked only); a ball that was not stopped at an event was left where the system
// put it, and its new path was not followed until the next step.
import { BallMode } from '../../components/Ball.js'
import { PathEvent } from '../../components/Path.js'
import { RIM_MODE_NAMES } from '../../components/RimContact.js'
import { MAX_COORDINATE, MAX_SPEED } from '../config/limits.js'
import { CaptureVia, EventType, pushEvent as pushEventRaw, type CaptureViaCode, type EventBuffer, type EventTypeCode } from '../events.js'
import { captureBall as captureRaw, emitHoleEvent as emitRaw, launchBallAt, restBall as restRaw } from '../motion/ballFate.js'
import { planRimRoll as planRimRaw, sampleRimRoll as sampleRimRaw, startRimRoll as startRimRaw } from '../motion/rimRoll.js'
import { planRolling as planRaw, sampleAtDistance as atDistanceRaw, sampleDistance, sampleRolling as sampleRaw, startPathAt } from '../motion/rolling.js'
import { lockAtLip as lockRaw, releaseRim as releaseRaw } from '../world/rimSlots.js'
import { pushId } from '../world/idLists.js'
import { worldOfEvents, type BallWorld } from '../world/createWorld.js'
import { checkBall, checkHole, checkWorld, describe, finite, within } from './validate.js'

const HOLE_EVENTS = [EventType.Skip, EventType.Capture, EventType.Bounce, EventType.RimRoll, EventType.LipOut, EventType.NearMiss] as const
const EVENT_CODES = Object.values(EventType).filter((c) => c !== EventType.Collision)
const VIA_CODES = Object.values(CaptureVia)
const RIM_CODES = RIM_MODE_NAMES.map((_, i) => i)

/** t: the world's time between steps; in a step, within the window the step is in. */
function instant(fn: string, w: BallWorld, t: unknown): number {
  if (!w.stepping) {
    if (t !== w.time) {
      throw new (typeof t === 'number' ? RangeError : TypeError)(
        `${fn}: t must be the world's time between steps (${w.time}), got ${describe(t)}; in a step, a time in the window the step is in`,
      )
    }
    return t
  }
  // (the message built on failure only: a check that passes allocates nothing)
  if (typeof t === 'number' && t >= w.time && t <= w.tickEnd) return t
  return within(`${fn}: t (in a step: within the window [world.time, world.tickEnd])`, t, w.time, w.tickEnd)
}

/** A velocity component: any finite number (a path's is capped at MAX_SPEED along its direction: src/motion/speedLimit.ts). */
function velocity(field: string, v: unknown): number {
  if (typeof v !== 'number') throw new TypeError(`${field} must be a finite number of px/s, got ${describe(v)}`)
  if (!Number.isFinite(v)) throw new RangeError(`${field} must be a finite number of px/s (beyond MAX_SPEED = ${MAX_SPEED} a path is slowed along its direction), got ${v}`)
  return v
}

function code(fn: string, field: string, value: unknown, codes: readonly number[]): number {
  if (typeof value !== 'number' || !codes.includes(value)) {
    throw new (typeof value === 'number' ? RangeError : TypeError)(`${fn}: ${field} must be one of the codes ${codes.join(', ')}, got ${describe(value)}`)
  }
  return value
}

function notHeld(fn: string, w: BallWorld, b: number): void {
  if (w.Ball.mode[b] === BallMode.Held) {
    throw new RangeError(`${fn}: ball ${b} is held by the launcher (mode held: it waits for its spot to clear); it starts when the launcher releases it`)
  }
}

function rimBall(fn: string, w: BallWorld, b: number): void {
  if (w.Ball.mode[b] !== BallMode.RimRoll) throw new RangeError(`${fn}: ball ${b} is not rolling on a rim (its mode is not rimRoll)`)
}

/** In a step, a ball that leaves the event it was stopped at; with contacts off, a new path is followed. */
function leaveEvent(w: BallWorld, b: number, moves: boolean): void {
  if (!w.stepping) return
  if (moves) follow(w, b)
  w.Path.mark[b] = PathEvent.None
}

/**
 * In a step with contacts off (or the fixed tick), the next pass takes ball b to the window's end: the
 * integration system continues the balls in world.marked only. (With exact contacts every moving ball is
 * sampled at the window's end.)
 */
function follow(w: BallWorld, b: number): void {
  if (!w.stepping || w.collide !== null || w.config.METHOD !== 'exact') return
  // a ball stopped at an event is listed; so is one the stages handled this pass (taken on twice, the second
  // would find it at its next event, marked, and throw): a scan of the pass's list, which a stage that
  // launches a ball before clearing its mark (launchBall clears it) does without
  if (w.Path.mark[b] !== PathEvent.None) return
  const list = w.marked
  for (let i = 0; i < list.count; i++) if (list.ids[i] === b) return
  pushId(list, b)
}

/** the fields a path's start names in each function's errors (made once: a check that passes builds no string) */
const START_FIELDS = {
  launchBall: ['launchBall: ball', 'launchBall: x', 'launchBall: y', 'launchBall: vx', 'launchBall: vy'],
  startPath: ['startPath: ball', 'startPath: x', 'startPath: y', 'startPath: vx', 'startPath: vy'],
} as const

/** A path's start, checked (launchBall, startPath): the ball, then x, y, vx, vy, then t; returns the ball. */
function checkStart(fn: keyof typeof START_FIELDS, w: BallWorld, ball: number, x: number, y: number, vx: number, vy: number, t: number): number {
  const f = START_FIELDS[fn]
  const b = checkBall(w, f[0], ball)
  notHeld(fn, w, b)
  finite(f[1], x, MAX_COORDINATE)
  finite(f[2], y, MAX_COORDINATE)
  velocity(f[3], vx)
  velocity(f[4], vy)
  instant(fn, w, t)
  return b
}

/** Starts `ball` rolling from (x, y) with velocity (vx, vy) at time t: its new path, planned, and the ball moving. */
export function launchBall(world: BallWorld, ball: number, x: number, y: number, vx: number, vy: number, t: number): void {
  const w = checkWorld('launchBall', world)
  const b = checkStart('launchBall', w, ball, x, y, vx, vy, t)
  leaveEvent(w, b, true)
  launchBallAt(w, b, x, y, vx, vy, t)
}

/** Writes the start of `ball`'s next straight path (plan it with planRolling); the mode is left as it is. */
export function startPath(world: BallWorld, ball: number, x: number, y: number, vx: number, vy: number, t: number): void {
  const w = checkWorld('startPath', world)
  startPathAt(w, checkStart('startPath', w, ball, x, y, vx, vy, t), x, y, vx, vy, t)
}

/**
 * Finds the next event of `ball` on its straight path (after startPath, or after its radius was written:
 * the events of a path depend on it). In a step with contacts off, the next pass follows the new plan.
 */
export function planRolling(world: BallWorld, ball: number): void {
  const w = checkWorld('planRolling', world)
  const b = checkBall(w, 'planRolling: ball', ball)
  notHeld('planRolling', w, b)
  if (w.Ball.mode[b] !== BallMode.Rolling) throw new RangeError(`planRolling: ball ${b} is not rolling (its mode is not rolling; launchBall puts a ball in motion)`)
  planRaw(w, b)
  follow(w, b)
}

/** Writes `ball`'s state at time t on its straight path (clamped at its stop) into its stores. */
export function sampleRolling(world: BallWorld, ball: number, t: number): void {
  const w = checkWorld('sampleRolling', world)
  const b = checkBall(w, 'sampleRolling: ball', ball)
  if (w.Ball.mode[b] !== BallMode.Rolling) throw new RangeError(`sampleRolling: ball ${b} is not rolling (its mode is not rolling)`)
  sampleRaw(w, b, instant('sampleRolling', w, t))
  follow(w, b)
}

/** Writes `ball`'s state where its straight path has covered distance d (px, ≥ 0) into its stores. */
export function sampleAtDistance(world: BallWorld, ball: number, d: number): void {
  const w = checkWorld('sampleAtDistance', world)
  const b = checkBall(w, 'sampleAtDistance: ball', ball)
  if (w.Ball.mode[b] !== BallMode.Rolling) throw new RangeError(`sampleAtDistance: ball ${b} is not rolling (its mode is not rolling)`)
  sampleDistance[0] = within('sampleAtDistance: d', d, 0, 2 * MAX_COORDINATE)
  atDistanceRaw(w, b)
  follow(w, b)
}

/** `ball` stops where it is, at time t, outside every hole: a 'rest' event, mode resting. */
export function restBall(world: BallWorld, ball: number, t: number): void {
  const w = checkWorld('restBall', world)
  const b = checkBall(w, 'restBall: ball', ball)
  notHeld('restBall', w, b)
  const pt = instant('restBall', w, t)
  leaveEvent(w, b, false)
  restRaw(w, b, pt)
}

/** `ball` falls into `hole` at time t: it sits at the hole's centre, captured, and its lock is given back. */
export function captureBall(world: BallWorld, ball: number, hole: number, t: number, via: CaptureViaCode): void {
  const w = checkWorld('captureBall', world)
  const b = checkBall(w, 'captureBall: ball', ball)
  notHeld('captureBall', w, b)
  const h = checkHole(w, 'captureBall: hole', hole)
  const pt = instant('captureBall', w, t)
  const v = code('captureBall', 'via', via, VIA_CODES) as CaptureViaCode
  leaveEvent(w, b, false)
  captureRaw(w, b, h, pt, v)
}

/** Buffers a hole event of `ball` at `hole` at time t, with the lip crossing's (δ, v) when its lock has one. */
export function emitHoleEvent(world: BallWorld, type: (typeof HOLE_EVENTS)[number], ball: number, hole: number, t: number, via: CaptureViaCode = CaptureVia.None): void {
  const w = checkWorld('emitHoleEvent', world)
  const b = checkBall(w, 'emitHoleEvent: ball', ball)
  const ty = code('emitHoleEvent', 'type', type, HOLE_EVENTS) as (typeof HOLE_EVENTS)[number]
  const h = checkHole(w, 'emitHoleEvent: hole', hole)
  const pt = instant('emitHoleEvent', w, t)
  emitRaw(w, ty, b, h, pt, code('emitHoleEvent', 'via', via, VIA_CODES) as CaptureViaCode)
}

/**
 * Appends an event to a world's event buffer (world.events): type (any but a collision, which names two
 * balls), a live ball of that world and a live hole (0: none), the time (as the other functions take it:
 * the world's time between steps, in a step within the window the step is in), and (δ, v) when hasDV.
 */
export function pushEvent(
  buf: EventBuffer,
  type: EventTypeCode,
  ball: number,
  hole: number,
  time: number,
  hasDV: boolean,
  delta: number,
  speed: number,
  via: CaptureViaCode = CaptureVia.None,
): void {
  const owner = buf !== null && typeof buf === 'object' ? worldOfEvents(buf) : undefined
  if (owner === undefined) throw new TypeError(`pushEvent: buf must be a world's event buffer (world.events), got ${describe(buf)}`)
  const w = checkWorld('pushEvent', owner)
  const ty = code('pushEvent', 'type', type, EVENT_CODES) as EventTypeCode
  const b = checkBall(w, 'pushEvent: ball', ball)
  const h = hole === 0 ? 0 : checkHole(w, 'pushEvent: hole (0: none)', hole)
  const t = instant('pushEvent', w, time)
  if (typeof hasDV !== 'boolean') throw new TypeError(`pushEvent: hasDV must be a boolean, got ${describe(hasDV)}`)
  const d = hasDV ? within('pushEvent: delta', delta, 0, MAX_COORDINATE) : 0
  const s = hasDV ? within('pushEvent: speed', speed, 0, MAX_SPEED) : 0
  pushEventRaw(buf, ty, b, h, t, hasDV, d, s, code('pushEvent', 'via', via, VIA_CODES) as CaptureViaCode)
}

/**
 * Takes a hole lock for `ball` at its lip crossing of `hole` (δ px, v px/s, at time t, in rim mode `mode`):
 * its RimContact slot, which it returns.
 */
export function lockAtLip(world: BallWorld, ball: number, hole: number, delta: number, speed: number, t: number, mode: number): number {
  const w = checkWorld('lockAtLip', world)
  const b = checkBall(w, 'lockAtLip: ball', ball)
  notHeld('lockAtLip', w, b)
  const h = checkHole(w, 'lockAtLip: hole', hole)
  const d = within('lockAtLip: delta', delta, 0, MAX_COORDINATE)
  const s = within('lockAtLip: speed', speed, 0, MAX_SPEED)
  const pt = instant('lockAtLip', w, t)
  const m = code('lockAtLip', 'mode', mode, RIM_CODES)
  return lockRaw(w, b, h, d, s, pt, m)
}

/** Gives back `ball`'s hole lock (its RimContact slot); a no-op when it holds none. */
export function releaseRim(world: BallWorld, ball: number): void {
  const w = checkWorld('releaseRim', world)
  const b = checkBall(w, 'releaseRim: ball', ball)
  if (w.Ball.mode[b] === BallMode.RimRoll) throw new RangeError(`releaseRim: ball ${b} is rolling on a rim (its roll reads the lock); end the roll first (launchBall, captureBall)`)
  releaseRaw(w, b)
}

/** Puts `ball`, which holds a lock at `hole` (lockAtLip), on that hole's rim at time t; returns its angle. */
export function startRimRoll(world: BallWorld, ball: number, hole: number, t: number): number {
  const w = checkWorld('startRimRoll', world)
  const b = checkBall(w, 'startRimRoll: ball', ball)
  notHeld('startRimRoll', w, b)
  const h = checkHole(w, 'startRimRoll: hole', hole)
  const slot = w.Ball.rim[b]!
  if (slot === 0 || w.RimContact.hole[slot] !== h) throw new RangeError(`startRimRoll: ball ${b} holds no lock at hole ${h} (take one with lockAtLip first)`)
  const pt = instant('startRimRoll', w, t)
  leaveEvent(w, b, false)
  return startRimRaw(w, b, h, pt)
}

/** Finds the next event (drop or pop-off) of `ball`, rolling on a rim. */
export function planRimRoll(world: BallWorld, ball: number): void {
  const w = checkWorld('planRimRoll', world)
  const b = checkBall(w, 'planRimRoll: ball', ball)
  rimBall('planRimRoll', w, b)
  planRimRaw(w, b)
  follow(w, b)
}

/** Writes `ball`'s state at time t on the rim into its stores. */
export function sampleRimRoll(world: BallWorld, ball: number, t: number): void {
  const w = checkWorld('sampleRimRoll', world)
  const b = checkBall(w, 'sampleRimRoll: ball', ball)
  rimBall('sampleRimRoll', w, b)
  sampleRimRaw(w, b, instant('sampleRimRoll', w, t))
  follow(w, b)
}
