// Outcome maps and Monte Carlo outcome estimates: which hole a throw ends in, over a grid of throws or a
// distribution of them, for return-to-player figures and for showing a player where their throws go.
//
// A scene is plain data (config, holes, walls), so that worker threads can each build it. Every throw is
// simulated alone on the panel (ball-ball contacts off: throws are independent draws), many at once in
// one world — without contacts a ball's path depends on nothing but its own throw, the holes and the
// walls, so a throw ends the same in any batch. Throw k of a distribution draws its power, angle and start
// point from its own generator, seeded by (seed, k): a run split into chunks, on any number of workers,
// gives the same counts as one run (tests/outcomes.test.ts). Counts are integers and payouts are applied
// to them at the end, so merged results are exact.
import type { ConfigOverrides } from '../config/design.js'
import type { HoleSpec } from '../commands/holes.js'
import type { WallsSpec } from '../commands/walls.js'
import { describe, finite, readSpec, within } from '../check.js'
import { MAX_COORDINATE, MIN_OUTCOME_STEP } from '../config/limits.js'
import { EventType } from '../events.js'
import { cos, log, sin } from '../math.js'
import { mulberry32 } from '../random.js'
import { createBallPhysics, type BallPhysics } from './createBallPhysics.js'

export interface OutcomeScene {
  config?: ConfigOverrides | undefined
  holes: readonly HoleSpec[]
  walls?: WallsSpec | undefined
}

/** A throw distribution: each part a mean and a normal spread (power is clipped to [0, 1]). */
export interface ThrowDistribution {
  power: { mean: number; sd?: number | undefined }
  /** rad, as throwBall's */
  angle: { mean: number; sd?: number | undefined }
  from: { x: number; y: number; sdX?: number | undefined; sdY?: number | undefined }
}

/** Integer counts over a set of throws; merge with mergeTallies, read with summarizeOutcomes. */
export interface OutcomeTally {
  throws: number
  /** throws captured in each hole (the scene's order) */
  captures: number[]
  /** throws never captured (out through an open edge, at rest, or still moving after the time limit) */
  missed: number
  /** lip events at each hole over all throws (a throw may meet a hole more than once) */
  skips: number[]
  bounces: number[]
  lipOuts: number[]
}

/** simulated time after which a throw still moving counts as missed, s */
const LIMIT = 30
/** throws simulated together in one world */
const BATCH = 2048
/** throw indices of a run (first + count): each throw's generator is seeded by a 32-bit mix of its index */
const MAX_THROW_INDEX = 4294967296
/** cells of one outcome map (power steps × angle steps; an Int16Array of the scene's hole indices) */
const MAX_MAP_CELLS = 16777216
/** holes an outcome map can name (its cells are 16-bit) */
const MAX_MAP_HOLES = 32767
/** the largest payout or stake a summary takes (its squares and sums stay finite and exact enough) */
const MAX_PAYOUT = 1e12

function emptyTally(holes: number): OutcomeTally {
  const z = (): number[] => new Array<number>(holes).fill(0)
  return { throws: 0, captures: z(), missed: 0, skips: z(), bounces: z(), lipOuts: z() }
}

const TALLY_KEYS = ['throws', 'captures', 'missed', 'skips', 'bounces', 'lipOuts'] as const

/** Refuses what is not a tally: counts that are not non-negative integers, lists of other lengths, more captured and missed than thrown. */
function checkTally(name: string, tally: unknown): OutcomeTally {
  const t = readSpec(name, tally, TALLY_KEYS)
  const count = (field: string, v: unknown): number => {
    if (typeof v !== 'number') throw new TypeError(`${field} must be a non-negative integer, got ${describe(v)}`)
    if (!Number.isSafeInteger(v) || v < 0) throw new RangeError(`${field} must be a non-negative integer, got ${v}`)
    return v
  }
  const throws = count(`${name}.throws`, t.throws)
  const missed = count(`${name}.missed`, t.missed)
  if (!Array.isArray(t.captures)) throw new TypeError(`${name}.captures must be an array of counts, got ${describe(t.captures)}`)
  const holes = t.captures.length
  let captured = 0
  for (const key of ['captures', 'skips', 'bounces', 'lipOuts'] as const) {
    const list = t[key]
    if (!Array.isArray(list)) throw new TypeError(`${name}.${key} must be an array of counts, got ${describe(list)}`)
    if (list.length !== holes) throw new RangeError(`${name}.${key} has ${list.length} entries; ${name}.captures has ${holes}`)
    for (let i = 0; i < holes; i++) {
      const c = count(`${name}.${key}[${i}]`, list[i])
      if (key === 'captures') captured += c
    }
  }
  if (captured + missed > throws) throw new RangeError(`${name}: ${captured} captured and ${missed} missed of ${throws} throws`)
  return tally as OutcomeTally
}

export function mergeTallies(a: OutcomeTally, b: OutcomeTally): OutcomeTally {
  checkTally('a', a)
  checkTally('b', b)
  if (a.captures.length !== b.captures.length) throw new RangeError(`mergeTallies: tallies of ${a.captures.length} and ${b.captures.length} holes`)
  const add = (x: number[], y: number[]): number[] => x.map((v, i) => v + y[i]!)
  return {
    throws: a.throws + b.throws,
    captures: add(a.captures, b.captures),
    missed: a.missed + b.missed,
    skips: add(a.skips, b.skips),
    bounces: add(a.bounces, b.bounces),
    lipOuts: add(a.lipOuts, b.lipOuts),
  }
}

/** Refuses a scene that is not an object of the known keys (each part is checked by its own command). */
function checkScene(scene: unknown): void {
  const s = readSpec('scene', scene, ['config', 'holes', 'walls'] as const)
  if (!Array.isArray(s.holes)) throw new TypeError(`scene.holes must be an array of holes, got ${describe(s.holes)}`)
}

/** A number's allowed range, and whether it may be left out. */
type Range = readonly [lo: number, hi: number, optional: boolean]

/**
 * Refuses a spec whose parts are not objects of the known keys, or whose numbers are not numbers (TypeError)
 * or lie outside their ranges (RangeError), each named by its field.
 */
function checkParts(name: string, spec: unknown, parts: Record<string, Record<string, Range>>): void {
  const s = readSpec(name, spec, Object.keys(parts))
  for (const key of Object.keys(parts)) {
    const fields = parts[key]!
    const part = readSpec(`${name}.${key}`, s[key], Object.keys(fields))
    for (const field of Object.keys(fields)) {
      const [lo, hi, optional] = fields[field]!
      if (!(optional && part[field] === undefined)) within(`${name}.${key}.${field}`, part[field], lo, hi)
    }
  }
}

const TURN = 2 * Math.PI
const C = MAX_COORDINATE
const DIST_PARTS: Record<string, Record<string, Range>> = {
  power: { mean: [0, 1, false], sd: [0, 1e3, true] },
  angle: { mean: [-TURN, TURN, false], sd: [0, 1e3, true] },
  from: { x: [-C, C, false], y: [-C, C, false], sdX: [0, C, true], sdY: [0, C, true] },
}
const MAP_PARTS: Record<string, Record<string, Range>> = {
  from: { x: [-C, C, false], y: [-C, C, false] },
  power: { min: [0, 1, false], max: [0, 1, false], steps: [1, MAX_MAP_CELLS, false] },
  angle: { min: [-TURN, TURN, false], max: [-TURN, TURN, false], steps: [1, MAX_MAP_CELLS, false] },
}

/** The scene's world (contacts off), its hole ids in the scene's order. */
function build(scene: OutcomeScene, capacity: number): { sim: BallPhysics; index: Map<number, number> } {
  const sim = createBallPhysics({ ...scene.config, BALL_COLLISIONS: 'off' }, { capacity })
  const index = new Map<number, number>()
  scene.holes.forEach((h, i) => index.set(sim.addHole(h), i))
  if (scene.walls !== undefined) sim.setWalls(scene.walls)
  return { sim, index }
}

/**
 * Simulates throws given as (x, y, power, angle) quadruples, all at once in a fresh world; calls
 * `fate(k, holeIndex)` for each (−1: missed) and counts lip events into `tally` when given.
 */
function simulate(scene: OutcomeScene, throws: Float64Array, n: number, fate: (k: number, hole: number) => void, tally?: OutcomeTally): void {
  const { sim, index } = build(scene, n + scene.holes.length + 8)
  const first = sim.throwBall({ x: throws[0]!, y: throws[1]!, power: throws[2]!, angle: throws[3]! })
  for (let k = 1; k < n; k++) sim.throwBall({ x: throws[4 * k]!, y: throws[4 * k + 1]!, power: throws[4 * k + 2]!, angle: throws[4 * k + 3]! })
  const captured = new Int32Array(n).fill(-1)
  const visit = (e: { code: number; ball: number; hole: number }): void => {
    const h = index.get(e.hole)
    if (h === undefined) return
    if (e.code === EventType.Capture) captured[e.ball - first] = h
    else if (tally !== undefined) {
      if (e.code === EventType.Skip) tally.skips[h]!++
      else if (e.code === EventType.Bounce) tally.bounces[h]!++
      else if (e.code === EventType.LipOut) tally.lipOuts[h]!++
    }
  }
  const dt = sim.config.MAX_STEP
  if (dt < MIN_OUTCOME_STEP) throw new RangeError(`scene.config.MAX_STEP must be at least ${MIN_OUTCOME_STEP} s for outcome estimates (the throws are stepped at it for up to ${LIMIT} s), got ${dt}`)
  // the world's moving set holds its rolling and rim-rolling balls (contacts off: none is ever held)
  for (let t = 0; t < LIMIT && sim.world.moving.count > 0; t += dt) {
    sim.step(dt)
    sim.drainEventsWith(visit)
  }
  for (let k = 0; k < n; k++) fate(k, captured[k]!)
}

/** A generator of its own for throw k of a run seeded `seed` (mulberry32 on a mix of the two). */
function throwRandom(seed: number, k: number): () => number {
  return mulberry32(Math.imul(seed ^ 0x9e3779b9, 0x85ebca6b) ^ Math.imul(k + 1, 0xc2b2ae35))
}

/** Two standard normal draws (Box–Muller, portable functions), into pair */
const pair = [0, 0]
function normals(r: () => number): void {
  const u = 1 - r() // (0, 1]
  const v = r()
  const m = Math.sqrt(-2 * log(u))
  pair[0] = m * cos(2 * Math.PI * v)
  pair[1] = m * sin(2 * Math.PI * v)
}

/**
 * Throws `count` throws of the distribution — throws first … first + count − 1 of the run seeded `seed` —
 * and counts where they end (see the top of this file).
 */
export function sampleThrows(scene: OutcomeScene, dist: ThrowDistribution, count: number, seed: number, first = 0): OutcomeTally {
  checkScene(scene)
  checkParts('distribution', dist, DIST_PARTS)
  if (typeof count !== 'number') throw new TypeError(`count must be a non-negative integer, got ${describe(count)}`)
  if (!Number.isInteger(count) || count < 0 || count > MAX_THROW_INDEX) throw new RangeError(`count must be a non-negative integer ≤ ${MAX_THROW_INDEX}, got ${count}`)
  if (typeof first !== 'number') throw new TypeError(`first must be a non-negative integer, got ${describe(first)}`)
  if (!Number.isInteger(first) || first < 0 || first + count > MAX_THROW_INDEX) {
    throw new RangeError(`first must be a non-negative integer with first + count ≤ ${MAX_THROW_INDEX} (each throw's generator is seeded by its 32-bit index), got ${first} with count ${count}`)
  }
  if (typeof seed !== 'number') throw new TypeError(`seed must be an integer in [0, ${MAX_THROW_INDEX}), got ${describe(seed)}`)
  if (!Number.isInteger(seed) || seed < 0 || seed >= MAX_THROW_INDEX) throw new RangeError(`seed must be an integer in [0, ${MAX_THROW_INDEX}), got ${seed}`)
  const tally = emptyTally(scene.holes.length)
  const buf = new Float64Array(4 * Math.min(BATCH, Math.max(1, count)))
  for (let done = 0; done < count; ) {
    const n = Math.min(BATCH, count - done)
    for (let k = 0; k < n; k++) {
      const r = throwRandom(seed, first + done + k)
      normals(r)
      const p = dist.power.mean + (dist.power.sd ?? 0) * pair[0]!
      let a = dist.angle.mean + (dist.angle.sd ?? 0) * pair[1]!
      // a wide spread can draw past ±2π, throwBall's range: the same direction a whole turn back
      if (a > TURN || a < -TURN) a -= TURN * Math.trunc(a / TURN)
      normals(r)
      buf[4 * k] = dist.from.x + (dist.from.sdX ?? 0) * pair[0]!
      buf[4 * k + 1] = dist.from.y + (dist.from.sdY ?? 0) * pair[1]!
      buf[4 * k + 2] = p < 0 ? 0 : p > 1 ? 1 : p
      buf[4 * k + 3] = a
    }
    simulate(scene, buf, n, (_k, h) => {
      if (h < 0) tally.missed++
      else tally.captures[h]!++
    }, tally)
    tally.throws += n
    done += n
  }
  return tally
}

export interface OutcomeMapSpec {
  from: { x: number; y: number }
  power: { min: number; max: number; steps: number }
  angle: { min: number; max: number; steps: number }
}

/**
 * Which hole each throw of a (power, angle) grid from one point ends in: the scene's hole index, −1 for
 * none; row-major by power (rows) then angle (columns). `rows` limits the work to powers [from, to).
 */
export function outcomeMap(scene: OutcomeScene, spec: OutcomeMapSpec, rows?: { from: number; to: number }): Int16Array {
  checkScene(scene)
  checkParts('spec', spec, MAP_PARTS)
  const P = spec.power
  const A = spec.angle
  if (!Number.isInteger(P.steps) || !Number.isInteger(A.steps)) throw new RangeError(`spec.power.steps and spec.angle.steps must be integers, got ${P.steps} and ${A.steps}`)
  if (P.steps * A.steps > MAX_MAP_CELLS) throw new RangeError(`spec.power.steps × spec.angle.steps must be at most ${MAX_MAP_CELLS}, got ${P.steps} × ${A.steps}`)
  if (scene.holes.length > MAX_MAP_HOLES) throw new RangeError(`scene.holes: an outcome map names at most ${MAX_MAP_HOLES} holes (16-bit cells), got ${scene.holes.length}; use sampleThrows`)
  let r0 = 0
  let r1 = P.steps
  if (rows !== undefined) {
    const part = readSpec('rows', rows, ['from', 'to'] as const)
    r0 = within('rows.from', part.from, 0, P.steps)
    r1 = within('rows.to', part.to, r0, P.steps)
    if (!Number.isInteger(r0) || !Number.isInteger(r1)) throw new RangeError(`rows.from and rows.to must be integers, got ${r0} and ${r1}`)
  }
  const total = (r1 - r0) * A.steps
  const out = new Int16Array(total)
  const buf = new Float64Array(4 * Math.min(BATCH, Math.max(1, total)))
  // cells in row-major order, BATCH throws to a world (a row longer than BATCH takes several)
  for (let done = 0; done < total; ) {
    const n = Math.min(BATCH, total - done)
    for (let k = 0; k < n; k++) {
      const cell = done + k
      const row = r0 + Math.floor(cell / A.steps)
      const j = cell - (row - r0) * A.steps
      buf[4 * k] = spec.from.x
      buf[4 * k + 1] = spec.from.y
      buf[4 * k + 2] = P.steps === 1 ? P.min : P.min + ((P.max - P.min) * row) / (P.steps - 1)
      buf[4 * k + 3] = A.steps === 1 ? A.min : A.min + ((A.max - A.min) * j) / (A.steps - 1)
    }
    const at = done
    simulate(scene, buf, n, (k, h) => {
      out[at + k] = h
    })
    done += n
  }
  return out
}

export interface OutcomeSummary {
  throws: number
  /** per hole: the capture probability and its 95 % Wilson interval */
  holes: Array<{ p: number; low: number; high: number }>
  missed: { p: number; low: number; high: number }
  /** mean payout per throw under `payouts` (per hole; default the holes' values), with its 95 % interval */
  payout: { mean: number; low: number; high: number }
  /** return to player: mean payout / stake */
  rtp: number
  /** per hole: skips, bounces and lip-outs there per throw (a throw may meet a hole more than once) */
  lipEvents: Array<{ skip: number; bounce: number; lipOut: number }>
}

/** Probabilities with 95 % intervals, and the payout per throw for a payout table (see OutcomeSummary). */
export function summarizeOutcomes(tally: OutcomeTally, payouts: readonly number[], stake = 1): OutcomeSummary {
  checkTally('tally', tally)
  const n = tally.throws
  if (!Array.isArray(payouts)) throw new TypeError(`payouts must be an array of numbers, one per hole, got ${describe(payouts)}`)
  if (payouts.length !== tally.captures.length) throw new RangeError(`payouts has ${payouts.length} entries; the tally has ${tally.captures.length} holes`)
  for (let i = 0; i < payouts.length; i++) finite(`payouts[${i}]`, payouts[i], MAX_PAYOUT)
  if (typeof stake !== 'number') throw new TypeError(`stake must be a number in (0, ${MAX_PAYOUT}], got ${describe(stake)}`)
  if (!(stake > 0 && stake <= MAX_PAYOUT)) throw new RangeError(`stake must be in (0, ${MAX_PAYOUT}], got ${stake}`)
  const z = 1.959963984540054
  const wilson = (c: number): { p: number; low: number; high: number } => {
    if (n === 0) return { p: 0, low: 0, high: 1 }
    const p = c / n
    const d = 1 + (z * z) / n
    const centre = (p + (z * z) / (2 * n)) / d
    const half = (z * Math.sqrt((p * (1 - p)) / n + (z * z) / (4 * n * n))) / d
    return { p, low: Math.max(0, centre - half), high: Math.min(1, centre + half) }
  }
  let sum = 0
  let sum2 = 0
  tally.captures.forEach((c, i) => {
    sum += c * payouts[i]!
    sum2 += c * payouts[i]! * payouts[i]!
  })
  const mean = n > 0 ? sum / n : 0
  const variance = n > 1 ? (sum2 - n * mean * mean) / (n - 1) : 0
  const half = n > 0 ? (z * Math.sqrt(Math.max(0, variance))) / Math.sqrt(n) : 0
  return {
    throws: n,
    holes: tally.captures.map(wilson),
    missed: wilson(tally.missed),
    payout: { mean, low: mean - half, high: mean + half },
    rtp: mean / stake,
    lipEvents: tally.captures.map((_c, i) => ({ skip: n > 0 ? tally.skips[i]! / n : 0, bounce: n > 0 ? tally.bounces[i]! / n : 0, lipOut: n > 0 ? tally.lipOuts[i]! / n : 0 })),
  }
}
