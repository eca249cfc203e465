// The panel's frame: an optional rectangle with restitution, whose edges may be open (the gutter).
import { addComponent, addEntity, removeEntity } from 'bitecs'
import { clearSlot, fitStore } from '../../components/store.js'
import { WallEdge } from '../../components/Walls.js'
import { MAX_COORDINATE } from '../config/limits.js'
import type { BallWorld } from '../world/createWorld.js'
import { replanRolling } from './replan.js'
import { betweenSteps, checkWorld, describe, finite, readSpec, within } from './validate.js'
import { record } from '../world/recorder.js'

export interface WallsSpec {
  /** inner faces of the rectangle, px (y down: top = minY); maxX > minX, maxY > minY */
  minX: number
  minY: number
  maxX: number
  maxY: number
  /** normal restitution at the walls, [0, 1]; default 0.5 */
  restitution?: number | undefined
  /** open edges: a ball whose centre crosses one leaves the panel ('gutter' event, mode 'out') */
  open?: { left?: boolean | undefined; top?: boolean | undefined; right?: boolean | undefined; bottom?: boolean | undefined } | undefined
}

const EDGES = { left: WallEdge.Left, top: WallEdge.Top, right: WallEdge.Right, bottom: WallEdge.Bottom } as const

/** The open edges of a mask (WallEdge bits) as a spec's `open` */
export function openSpec(mask: number): { left: boolean; top: boolean; right: boolean; bottom: boolean } {
  return { left: (mask & WallEdge.Left) !== 0, top: (mask & WallEdge.Top) !== 0, right: (mask & WallEdge.Right) !== 0, bottom: (mask & WallEdge.Bottom) !== 0 }
}

function openMask(value: unknown): number {
  if (value === undefined) return 0
  if (value === null || typeof value !== 'object' || Array.isArray(value)) {
    throw new TypeError(`walls.open must be an object with boolean keys left, top, right, bottom, got ${describe(value)}`)
  }
  const given = value as Record<string, unknown>
  let mask = 0
  for (const key of Object.keys(given)) {
    if (!(key in EDGES)) throw new RangeError(`walls.open.${key} is not an edge; the edges are left, top, right, bottom`)
    const v = given[key]
    if (v === undefined) continue
    if (typeof v !== 'boolean') throw new TypeError(`walls.open.${key} must be a boolean, got ${describe(v)}`)
    if (v) mask |= EDGES[key as keyof typeof EDGES]
  }
  return mask
}

/** Puts walls round the panel (or replaces them); rolling balls are re-planned from where they are. */
export function setWalls(world: BallWorld, spec: WallsSpec): void {
  const w = checkWorld('setWalls', world)
  betweenSteps(w, 'setWalls', 'change holes and walls between steps')
  const s = readSpec('setWalls spec', spec, ['minX', 'minY', 'maxX', 'maxY', 'restitution', 'open'] as const, 'walls')
  const minX = finite('walls.minX', s.minX, MAX_COORDINATE)
  const minY = finite('walls.minY', s.minY, MAX_COORDINATE)
  const maxX = finite('walls.maxX', s.maxX, MAX_COORDINATE)
  const maxY = finite('walls.maxY', s.maxY, MAX_COORDINATE)
  if (!(maxX > minX)) throw new RangeError(`walls.maxX must be > walls.minX = ${minX}, got ${maxX}`)
  if (!(maxY > minY)) throw new RangeError(`walls.maxY must be > walls.minY = ${minY}, got ${maxY}`)
  const e = s.restitution === undefined ? 0.5 : within('walls.restitution', s.restitution, 0, 1)
  const open = openMask(s.open)
  if (w.recorder !== null) record(w, ['setWalls', { minX, minY, maxX, maxY, restitution: e, open: openSpec(open) }])
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
  replanRolling(w)
}

/** Removes the walls (a no-op without walls). */
export function clearWalls(world: BallWorld): void {
  const w = checkWorld('clearWalls', world)
  betweenSteps(w, 'clearWalls', 'change holes and walls between steps')
  if (w.recorder !== null) record(w, ['clearWalls'])
  if (w.walls !== 0) removeEntity(w, w.walls) // forgetWalls runs here
}

/** onRemove(Walls): the panel has no walls any more; rolling balls are re-planned. */
export function forgetWalls(w: BallWorld, eid: number): void {
  if (eid !== w.walls) return
  // (as a hole removed mid-step: src/commands/holes.ts, forgetHole)
  if (w.stepping && w.failed === null) w.failed = `the walls (entity ${eid}) were removed during a step (bitECS removeEntity from a system?), which is not supported: holes and walls change between steps (clearWalls)`
  clearSlot(w.Walls, eid)
  w.walls = 0
  replanRolling(w)
}
