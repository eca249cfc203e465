// The game model against the physical reference on a (δ, v) grid (docs/physical.md). The game's side is
// the engine itself: one hole, a ball shot to cross the lip at exactly (δ, v) (as tests/helpers.ts shoot()),
// stepped until it is captured or at rest; nothing here re-derives the systems' formulas.
import { createBallPhysics, type BallPhysics } from '../api/createBallPhysics.js'
import type { ConfigOverrides } from '../config/design.js'
import { referenceOutcome } from '../reference/index.js'
import { isGuarded } from '../reference/types.js'
import type { ScheduleEntry } from '../schedule.js'

export interface DeltaSpeedGrid {
  /** cell centres: δ_i = (i + ½)·R/nDelta, v_k = (k + ½)·vMax/nSpeed */
  nDelta: number
  nSpeed: number
  holeRadius: number
  maxSpeed: number
}

export function gridDelta(g: DeltaSpeedGrid, i: number): number {
  return ((i + 0.5) * g.holeRadius) / g.nDelta
}

export function gridSpeed(g: DeltaSpeedGrid, k: number): number {
  return ((k + 0.5) * g.maxSpeed) / g.nSpeed
}

/** The grid of the issue: δ in [0, R), v in (0, 800] px/s. */
export function gameGrid(nDelta: number, nSpeed: number, holeRadius = 18, maxSpeed = 800): DeltaSpeedGrid {
  return { nDelta, nSpeed, holeRadius, maxSpeed }
}

/** A capture map: 1 captured, 0 escaped, row-major by δ then v (index i·nSpeed + k). */
export type CaptureMap = Uint8Array

export interface ReferenceMapResult {
  map: CaptureMap
  /** cells where a guard (time or phase limit) stopped the reference; they count as escapes */
  guarded: number
}

/** The reference's capture map at radii R, r, gravity g and inertia j. */
export function referenceMap(g: DeltaSpeedGrid, ballRadius: number, gravity: number, inertia: number): ReferenceMapResult {
  const map = new Uint8Array(g.nDelta * g.nSpeed)
  let guarded = 0
  const input = { delta: 0, speed: 0, holeRadius: g.holeRadius, ballRadius, gravity, inertia }
  for (let i = 0; i < g.nDelta; i++) {
    input.delta = gridDelta(g, i)
    for (let k = 0; k < g.nSpeed; k++) {
      input.speed = gridSpeed(g, k)
      const o = referenceOutcome(input)
      if (isGuarded(o.ending)) guarded++
      map[i * g.nSpeed + k] = o.captured ? 1 : 0
    }
  }
  return { map, guarded }
}

/** Distance before the lip at which a shot starts, px (as tests/helpers.ts shoot()). */
export const SHOT_LEAD = 60
/** A shot that has not settled after this much simulated time is an error. */
const SHOT_MAX_TIME = 60

/**
 * A reusable one-hole engine: `shot(δ, v)` adds a ball that crosses the lip at exactly (δ, v), steps until
 * it is captured, at rest or out, removes it and says whether it was captured.
 */
export interface ShotRig {
  sim: BallPhysics
  shot(delta: number, speed: number, hero?: boolean): boolean
}

export function createShotRig(overrides: ConfigOverrides = {}, schedule?: readonly ScheduleEntry[]): ShotRig {
  const sim = createBallPhysics(overrides)
  if (schedule) sim.schedule.splice(0, sim.schedule.length, ...schedule)
  const hole = sim.addHole({ x: 0, y: 0 })
  const R = sim.holeState(hole).radius
  const a = sim.config.ROLLING_DECEL
  const step = sim.config.MAX_STEP
  return {
    sim,
    shot(delta, speed, hero = false) {
      const lipX = -Math.sqrt(Math.max(0, R * R - delta * delta))
      const v0 = Math.sqrt(speed * speed + 2 * a * SHOT_LEAD)
      const ball = sim.addBall({ x: lipX - SHOT_LEAD, y: delta, vx: v0, vy: 0, hero })
      const t0 = sim.time
      // modes 0 and 1 (rolling, on a rim) still move; the rest have settled
      while (sim.world.Ball.mode[ball]! <= 1) {
        if (sim.time - t0 > SHOT_MAX_TIME) throw new Error(`shot (δ = ${delta}, v = ${speed}) did not settle`)
        sim.step(step)
      }
      const captured = sim.world.Ball.mode[ball] === 2
      sim.drainEvents()
      sim.removeBall(ball)
      return captured
    },
  }
}

/** The engine's capture map with `overrides` (and optionally another schedule). */
export function engineMap(g: DeltaSpeedGrid, overrides: ConfigOverrides = {}, schedule?: readonly ScheduleEntry[]): CaptureMap {
  const rig = createShotRig(overrides, schedule)
  if (rig.sim.config.HOLE_RADIUS !== g.holeRadius) throw new RangeError('engineMap: the grid and the config disagree on HOLE_RADIUS')
  const map = new Uint8Array(g.nDelta * g.nSpeed)
  for (let i = 0; i < g.nDelta; i++) {
    const d = gridDelta(g, i)
    for (let k = 0; k < g.nSpeed; k++) map[i * g.nSpeed + k] = rig.shot(d, gridSpeed(g, k)) ? 1 : 0
  }
  return map
}

/** Share of cells on which two maps agree, in [0, 1]. */
export function agreement(a: CaptureMap, b: CaptureMap): number {
  if (a.length !== b.length) throw new RangeError('agreement: maps of different sizes')
  let same = 0
  for (let i = 0; i < a.length; i++) if (a[i] === b[i]) same++
  return same / a.length
}

/** Cells the game captures and the reference does not, and the other way round. */
export function disagreement(game: CaptureMap, ref: CaptureMap): { gameOnly: number; referenceOnly: number } {
  let gameOnly = 0
  let referenceOnly = 0
  for (let i = 0; i < game.length; i++) {
    if (game[i] === 1 && ref[i] === 0) gameOnly++
    else if (game[i] === 0 && ref[i] === 1) referenceOnly++
  }
  return { gameOnly, referenceOnly }
}
