// Holes: added one by one or as a set (all or nothing), and removed. A hole added under a resting ball
// captures it; a ball inside its lip circle when it is added is in transit through it. Removing a hole
// frees the balls it holds: a ball rolling on its rim leaves on the tangent at the rim speed, a ball in
// transit, skipping or entering rolls on; captured balls stay captured. Rolling balls are re-planned.
import { addComponent, addEntity, removeEntity } from 'bitecs'
import { BallMode } from '../../components/Ball.js'
import { RimMode } from '../../components/RimContact.js'
import { clearSlot, fitStore } from '../../components/store.js'
import { MAX_COORDINATE, MAX_RADIUS, MAX_VALUE } from '../config/limits.js'
import { CaptureVia, cutEvents } from '../events.js'
import { captureBall, launchBall } from '../motion/ballFate.js'
import { sampleRimRoll } from '../motion/rimRoll.js'
import { startAt, sampleRolling } from '../motion/rolling.js'
import { forEachBall } from '../world/balls.js'
import type { BallWorld } from '../world/createWorld.js'
import { addHoleToTable, cellKey, isLiveHole, overlappingHole, removeHoleFromTable } from '../world/holeTable.js'
import { bigRadius } from '../world/holeGrid.js'
import { acquireRim, releaseRim } from '../world/rimSlots.js'
import { replanRolling } from './replan.js'
import { betweenSteps, checkHole, checkWorld, describe, finite, positive, readSpec } from './validate.js'
import { record } from '../world/recorder.js'

export interface HoleSpec {
  x: number
  y: number
  /** px, default config.HOLE_RADIUS */
  radius?: number | undefined
  /** points, default 1 */
  value?: number | undefined
}

interface CheckedHole {
  x: number
  y: number
  radius: number
  value: number
}

function readHole(w: BallWorld, name: string, spec: unknown): CheckedHole {
  const s = readSpec(name, spec, ['x', 'y', 'radius', 'value'] as const)
  return {
    x: finite(`${name}.x`, s.x, MAX_COORDINATE),
    y: finite(`${name}.y`, s.y, MAX_COORDINATE),
    radius: s.radius === undefined ? w.config.HOLE_RADIUS : positive(`${name}.radius`, s.radius, MAX_RADIUS),
    value: s.value === undefined ? 1 : finite(`${name}.value`, s.value, MAX_VALUE),
  }
}

function checkClear(w: BallWorld, h: CheckedHole): void {
  const other = overlappingHole(w, h.x, h.y, h.radius)
  if (other === 0) return
  const min = h.radius + w.Hole.radius[other]!
  throw new RangeError(
    `hole at (${h.x}, ${h.y}) with radius ${h.radius} overlaps hole ${other}: lip circles may not overlap ` +
      `(centres at least ${min} px apart)`,
  )
}

/**
 * Throws for the first spec (in order) whose lip circle overlaps an earlier one's: through a hash of cells
 * sized for the holes' radii, with the few far wider than the rest (the hole grid's rule, holeGrid.ts:
 * bigRadius) tested against every earlier hole instead (sized for one of radius 1e4, the cells held every hole
 * of a 40,000-hole set, and the check took 4.5 s).
 */
function checkApart(list: readonly CheckedHole[]): void {
  const n = list.length
  const radii = new Float64Array(n)
  for (let i = 0; i < n; i++) radii[i] = list[i]!.radius
  const limit = bigRadius(radii)
  let maxR = 0
  for (const h of list) if (h.radius <= limit && h.radius > maxR) maxR = h.radius
  const cell = 4 * maxR
  const byCell = new Map<number, number[]>()
  const wide: number[] = []
  for (let i = 0; i < n; i++) {
    const h = list[i]!
    // the earliest overlapping spec, as a scan of the earlier ones would name it
    let first = -1
    const overlaps = (j: number): void => {
      const o = list[j]!
      const dx = h.x - o.x
      const dy = h.y - o.y
      const min = h.radius + o.radius
      if (dx * dx + dy * dy < min * min && (first < 0 || j < first)) first = j
    }
    if (h.radius > limit) {
      for (let j = 0; j < i; j++) overlaps(j)
    } else {
      for (const j of wide) overlaps(j)
      const reach = h.radius + maxR
      for (let cy = Math.floor((h.y - reach) / cell), cy1 = Math.floor((h.y + reach) / cell); cy <= cy1; cy++) {
        for (let cx = Math.floor((h.x - reach) / cell), cx1 = Math.floor((h.x + reach) / cell); cx <= cx1; cx++) {
          const bucket = byCell.get(cellKey(cx, cy))
          if (bucket !== undefined) for (const j of bucket) overlaps(j)
        }
      }
    }
    if (first >= 0) {
      const o = list[first]!
      throw new RangeError(`holes[${i}] at (${h.x}, ${h.y}) overlaps holes[${first}]: lip circles may not overlap (centres at least ${h.radius + o.radius} px apart)`)
    }
    if (h.radius > limit) {
      wide.push(i)
      continue
    }
    const key = cellKey(Math.floor(h.x / cell), Math.floor(h.y / cell))
    const bucket = byCell.get(key)
    if (bucket === undefined) byCell.set(key, [i])
    else bucket.push(i)
  }
}

function placeHole(w: BallWorld, h: CheckedHole): number {
  const eid = addEntity(w)
  fitStore(w.Hole, eid)
  addComponent(w, eid, w.IsHole)
  addComponent(w, eid, w.Hole)
  w.Hole.x[eid] = h.x
  w.Hole.y[eid] = h.y
  w.Hole.radius[eid] = h.radius
  w.Hole.value[eid] = h.value
  addHoleToTable(w, eid)
  // balls already out there: a ball inside the new lip circle follows the rule for a ball added inside a
  // hole (a resting one falls in), unless it is not smaller than the hole
  forEachBall(w, (b) => {
    const mode = w.Ball.mode[b]
    if (mode === BallMode.Rolling) sampleRolling(w, b, w.time)
    else if (mode !== BallMode.Resting) return
    const dx = w.Ball.x[b]! - h.x
    const dy = w.Ball.y[b]! - h.y
    if (dx * dx + dy * dy >= h.radius * h.radius) return
    // a ball not smaller than the hole bridges it
    if (!(w.Ball.radius[b]! < h.radius)) return
    const slot = acquireRim(w, b)
    w.RimContact.hole[slot] = eid
    w.RimContact.hasLip[slot] = 0
    if (mode === BallMode.Resting) captureBall(w, b, eid, w.time, CaptureVia.Rest)
    else w.RimContact.mode[slot] = RimMode.Transit
  })
  return eid
}

/** Adds a hole; returns its entity id. Lip circles may not overlap. Rolling balls are re-planned. */
export function addHole(world: BallWorld, spec: HoleSpec): number {
  const w = checkWorld('addHole', world)
  betweenSteps(w, 'addHole', 'change holes and walls between steps')
  const h = readHole(w, 'hole', spec)
  checkClear(w, h)
  if (w.recorder !== null) record(w, ['addHole', { ...h }])
  const eid = placeHole(w, h)
  replanRolling(w)
  return eid
}

/**
 * Adds a set of holes, all or nothing: every spec is read and checked (against the world's holes and each
 * other) before the first is added. Returns their ids in order.
 */
export function addHoles(world: BallWorld, specs: readonly HoleSpec[]): number[] {
  const w = checkWorld('addHoles', world)
  betweenSteps(w, 'addHoles', 'change holes and walls between steps')
  if (!Array.isArray(specs)) throw new TypeError(`holes must be an array of hole specs, got ${describe(specs)}`)
  const list: CheckedHole[] = []
  for (let i = 0; i < specs.length; i++) list.push(readHole(w, `holes[${i}]`, specs[i]))
  for (const h of list) checkClear(w, h)
  checkApart(list)
  if (w.recorder !== null) record(w, ['addHoles', list.map((h) => ({ ...h }))])
  const ids = list.map((h) => placeHole(w, h))
  replanRolling(w)
  return ids
}

/** Removes a hole (see the top of this file for the balls it holds). */
export function removeHole(world: BallWorld, hole: number): void {
  const w = checkWorld('removeHole', world)
  betweenSteps(w, 'removeHole', 'change holes and walls between steps')
  const h = checkHole(w, 'hole', hole)
  if (w.recorder !== null) record(w, ['removeHole', h])
  removeEntity(w, h) // forgetHole runs here
}

/** onRemove(Hole): the simulation forgets the hole and frees the balls it holds. */
export function forgetHole(w: BallWorld, eid: number): void {
  if (!isLiveHole(w, eid)) return // a Hole a game added by hand, and removed: never a hole
  // a game's removeEntity of a hole from a system: bitECS has removed it, and the balls of the step under
  // way, each at its own instant, cannot be re-planned from one (a ball at its lip crossing took a 'skip' at
  // t = 1e300): the step ends in an error (src/schedule.ts) and the world is refused as after any failed step
  if (w.stepping && w.failed === null) w.failed = `hole ${eid} was removed during a step (bitECS removeEntity from a system?), which is not supported: holes and walls change between steps (removeHole)`
  removeHoleFromTable(w, eid)
  forEachBall(w, (b) => {
    const slot = w.Ball.rim[b]!
    if (slot === 0 || w.RimContact.hole[slot] !== eid) return
    const mode = w.Ball.mode[b]
    if (mode === BallMode.RimRoll) {
      sampleRimRoll(w, b, w.time)
      releaseRim(w, b)
      startAt(w.Ball.x[b]!, w.Ball.y[b]!, w.Ball.vx[b]!, w.Ball.vy[b]!, w.time)
      launchBall(w, b)
    } else {
      if (mode === BallMode.Rolling) sampleRolling(w, b, w.time)
      releaseRim(w, b)
    }
  })
  cutEvents(w.events, eid)
  clearSlot(w.Hole, eid)
  replanRolling(w)
}
