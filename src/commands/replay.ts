// Replays: a run as its config and its timed inputs, played back bit for bit.
//
// startReplay(world) starts recording: from then on every command that changes the world (addBall,
// throwBall, removeBall, setBallVelocity, setHeroBall, addHole, addHoles, removeHole, setWalls,
// clearWalls, prepareRimTable) and every step appends one input, with its checked arguments, in order
// (src/world/recorder.ts). takeReplay(world) stops and returns the replay: the resolved config, the
// world's options, the inputs, and — when the world already had entities at the start — a snapshot of it
// then. Playing a replay makes a fresh world from the config (and the snapshot), and runs the inputs in
// order: the same events and states, bit for bit, in any engine (the simulation's arithmetic is portable:
// src/math.ts). Not recorded: a game's own bitECS changes (removeEntity, addComponent(Ball) by hand) and
// its own systems in the schedule; a replay plays with the config's schedule.
//
// A replay is plain data (JSON-safe but for −0, which replayToJSON and replayFromJSON keep).
import type { BallPhysicsConfig, ConfigOverrides } from '../config/design.js'
import type { BallWorld } from '../world/createWorld.js'
import type { ReplayInput } from '../world/recorder.js'
import { createSchedule, runSchedule, type ScheduleEntry } from '../schedule.js'
import { prepareRimTable } from '../reference/rimTables.js'
import { addBall, removeBall, setBallMass, setBallVelocity, setHeroBall, throwBall, type BallSpec, type ThrowSpec } from './balls.js'
import { MAX_CAPACITY, createBallWorld } from './createBallWorld.js'
import { addHole, addHoles, removeHole, type HoleSpec } from './holes.js'
import { restoreWorld, snapshotWorld } from './snapshot.js'
import { checkWorld, describe, specObject } from './validate.js'
import { clearWalls, setWalls, type WallsSpec } from './walls.js'

export const REPLAY_FORMAT = 'positron-ball-physics replay'
export const REPLAY_VERSION = 1

export interface Replay {
  format: typeof REPLAY_FORMAT
  version: number
  /** the resolved config of the recorded world */
  config: BallPhysicsConfig
  /** the recorded world's options */
  options: { capacity: number; broadphase: 'auto' | 'grid' | 'scan' }
  /** the world when recording started, as a base64 snapshot; absent when it had no entities */
  start?: string | undefined
  /** the inputs, in order: [command, ...arguments]; ['step', dt] for each step */
  inputs: ReplayInput[]
}

/** Starts recording the world's inputs (see the top of this file); an earlier recording is dropped. */
export function startReplay(world: BallWorld): void {
  const w = checkWorld('startReplay', world)
  if (w.stepping) throw new Error('startRecording (startReplay): the world is in the middle of a step')
  if (w.events.draining) throw new Error('startRecording (startReplay): called from a drainEventsWith callback; start the recording after the drain returns')
  w.recorder = null
  // a world as createBallWorld makes it needs no start state (its config makes it again); any other does: a
  // world that ever had an entity, whose clock has run (steps of an empty world), or with rim tables beyond
  // its config's own (prepareRimTable)
  const c = w.config
  const ownTables = c.RIM_MODEL === 'tabulated' && c.BALL_RADIUS < c.HOLE_RADIUS ? 1 : 0
  const fresh = w.entityIndex.maxId === 0 && w.time === 0 && w.rimTables.length === ownTables
  w.recorder = { inputs: [], start: fresh ? undefined : toBase64(snapshotWorld(w)) }
}

/** Stops recording and returns the replay of everything since startReplay. */
export function takeReplay(world: BallWorld): Replay {
  const w = checkWorld('takeReplay', world, true)
  if (w.recorder === null) throw new Error('takeReplay (stopRecording): the world is not recording; call startReplay (startRecording) first')
  const replay: Replay = {
    format: REPLAY_FORMAT,
    version: REPLAY_VERSION,
    config: { ...w.config },
    options: { capacity: w.capacity, broadphase: w.gridFrom === 0 ? 'grid' : w.gridFrom === Infinity ? 'scan' : 'auto' },
    inputs: w.recorder.inputs,
  }
  if (w.recorder.start !== undefined) replay.start = w.recorder.start
  w.recorder = null
  return replay
}

/** A replay being played: `world` as it stands after the inputs run so far. */
export interface ReplayPlayer {
  readonly world: BallWorld
  /** inputs run so far, of `total` */
  readonly at: number
  readonly total: number
  /** steps run so far */
  readonly steps: number
  /** Runs the inputs up to and including the next step; false when none were left. */
  next(): boolean
}

/**
 * A player for `replay` on a fresh world made from its config (and its start snapshot). `schedule`:
 * the schedule to step with (default: the config's).
 */
export function createReplayPlayer(replay: Replay, schedule?: readonly ScheduleEntry[]): ReplayPlayer {
  checkReplay(replay)
  if (schedule !== undefined && !Array.isArray(schedule)) throw new TypeError(`createReplayPlayer: schedule must be an array of { name, run } entries (or absent: the config's), got ${describe(schedule)}`)
  const world = createBallWorld(replay.config as ConfigOverrides, replay.options)
  if (replay.start !== undefined) restoreWorld(world, fromBase64(replay.start))
  const run = schedule ?? createSchedule(world.config)
  let at = 0
  let steps = 0
  const inputs = replay.inputs
  return {
    world,
    get at() {
      return at
    },
    total: inputs.length,
    get steps() {
      return steps
    },
    next() {
      if (at >= inputs.length) return false
      while (at < inputs.length) {
        const input = inputs[at]!
        try {
          apply(world, run, input)
        } catch (e) {
          const why = e instanceof Error ? e.message : String(e)
          throw new RangeError(`replay input ${at} (${JSON.stringify(input[0])}): ${why}`)
        }
        at++
        if (input[0] === 'step') {
          steps++
          return true
        }
      }
      return true
    },
  }
}

/** Plays the whole replay; returns the world at its end (drain its events, or read them in `onStep`). */
export function playReplay(replay: Replay, onStep?: (world: BallWorld, step: number) => void): BallWorld {
  const p = createReplayPlayer(replay)
  while (p.next()) onStep?.(p.world, p.steps)
  return p.world
}

function apply(w: BallWorld, schedule: readonly ScheduleEntry[], input: ReplayInput): void {
  const a = input
  switch (a[0]) {
    case 'step':
      return runSchedule(w, schedule, a[1] as number)
    case 'addBall':
      return void addBall(w, a[1] as BallSpec)
    case 'throwBall':
      return void throwBall(w, a[1] as ThrowSpec)
    case 'removeBall':
      return removeBall(w, a[1] as number)
    case 'setBallVelocity':
      return setBallVelocity(w, a[1] as number, a[2] as number, a[3] as number)
    case 'setHeroBall':
      return setHeroBall(w, a[1] as number, a[2] as boolean)
    case 'setBallMass':
      return setBallMass(w, a[1] as number, a[2] as number)
    case 'addHole':
      return void addHole(w, a[1] as HoleSpec)
    case 'addHoles':
      return void addHoles(w, a[1] as HoleSpec[])
    case 'removeHole':
      return removeHole(w, a[1] as number)
    case 'setWalls':
      return setWalls(w, a[1] as WallsSpec)
    case 'clearWalls':
      return clearWalls(w)
    case 'prepareRimTable':
      return void prepareRimTable(w, a[1] as number, a[2] as number, { inertia: a[3] as number })
    default:
      throw new RangeError(`unknown command; allowed: step, addBall, throwBall, removeBall, setBallVelocity, setHeroBall, setBallMass, addHole, addHoles, removeHole, setWalls, clearWalls, prepareRimTable`)
  }
}

const REPLAY_KEYS = ['format', 'version', 'config', 'options', 'start', 'inputs'] as const
const OPTION_KEYS = ['capacity', 'broadphase'] as const

function checkReplay(r: Replay): void {
  if (r === null || typeof r !== 'object') throw new TypeError(`replay must be a replay object (from takeReplay), got ${describe(r)}`)
  specObject('replay', r, REPLAY_KEYS)
  if (r.format !== REPLAY_FORMAT) throw new RangeError(`replay.format must be '${REPLAY_FORMAT}', got ${describe(r.format)}`)
  if (r.version !== REPLAY_VERSION) throw new RangeError(`replay.version ${describe(r.version)}: this module plays version ${REPLAY_VERSION}`)
  if (r.config === null || typeof r.config !== 'object') throw new TypeError(`replay.config must be a config object, got ${describe(r.config)}`)
  const o: unknown = r.options
  if (o === null || typeof o !== 'object' || Array.isArray(o)) throw new TypeError(`replay.options must be the recorded world's options { capacity, broadphase }, got ${describe(o)}`)
  const opts = specObject('replay.options', o, OPTION_KEYS)
  const cap = opts.capacity
  if (typeof cap !== 'number' || !Number.isInteger(cap) || cap < 1 || cap > MAX_CAPACITY) {
    throw new (typeof cap === 'number' ? RangeError : TypeError)(`replay.options.capacity must be an integer in [1, ${MAX_CAPACITY}], got ${describe(cap)}`)
  }
  if (opts.broadphase !== 'auto' && opts.broadphase !== 'grid' && opts.broadphase !== 'scan') {
    throw new RangeError(`replay.options.broadphase must be 'auto', 'grid' or 'scan', got ${describe(opts.broadphase)}`)
  }
  if (!Array.isArray(r.inputs)) throw new TypeError(`replay.inputs must be an array, got ${describe(r.inputs)}`)
  for (let i = 0; i < r.inputs.length; i++) {
    if (!Array.isArray(r.inputs[i]) || typeof r.inputs[i]![0] !== 'string') throw new TypeError(`replay.inputs[${i}] must be [command, ...arguments], got ${describe(r.inputs[i])}`)
  }
  if (r.start !== undefined && typeof r.start !== 'string') throw new TypeError(`replay.start must be a base64 snapshot, got ${describe(r.start)}`)
}

/** The replay as JSON text (−0 kept: JSON has no −0). */
export function replayToJSON(replay: Replay): string {
  return JSON.stringify(replay, (_k, v: unknown) => (Object.is(v, -0) ? '-0' : v))
}

/** A replay from replayToJSON's text, checked as a player checks it (an unknown key, a wrong format or version throws here). */
export function replayFromJSON(text: string): Replay {
  if (typeof text !== 'string') throw new TypeError(`replayFromJSON: text must be a string, got ${describe(text)}`)
  let replay: Replay
  try {
    replay = JSON.parse(text, (_k, v: unknown) => (v === '-0' ? -0 : v)) as Replay
  } catch (e) {
    throw new SyntaxError(`replayFromJSON: text is not JSON (a replay as replayToJSON writes it): ${e instanceof Error ? e.message : describe(e)}`)
  }
  checkReplay(replay)
  return replay
}

const B64 = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/'

function toBase64(bytes: Uint8Array): string {
  let out = ''
  for (let i = 0; i < bytes.length; i += 3) {
    const n = (bytes[i]! << 16) | ((bytes[i + 1] ?? 0) << 8) | (bytes[i + 2] ?? 0)
    out += B64[(n >> 18) & 63]! + B64[(n >> 12) & 63]! + (i + 1 < bytes.length ? B64[(n >> 6) & 63]! : '=') + (i + 2 < bytes.length ? B64[n & 63]! : '=')
  }
  return out
}

function fromBase64(text: string): Uint8Array {
  if (text.length % 4 !== 0 || !/^[A-Za-z0-9+/]*={0,2}$/.test(text)) throw new RangeError('replay.start is not base64')
  const pad = text.endsWith('==') ? 2 : text.endsWith('=') ? 1 : 0
  const out = new Uint8Array((text.length / 4) * 3 - pad)
  let o = 0
  for (let i = 0; i < text.length; i += 4) {
    const n = (B64.indexOf(text[i]!) << 18) | (B64.indexOf(text[i + 1]!) << 12) | ((B64.indexOf(text[i + 2]!) & 63) << 6) | (B64.indexOf(text[i + 3]!) & 63)
    if (o < out.length) out[o++] = (n >> 16) & 255
    if (o < out.length) out[o++] = (n >> 8) & 255
    if (o < out.length) out[o++] = n & 255
  }
  return out
}
