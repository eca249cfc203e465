// Id lists without allocation: a growable list, and the sparse set of the balls that move.
import type { BallWorld } from './createWorld.js'
import { spotJoin } from './spotGrid.js'

/** A growable list of entity ids. */
export interface IdList {
  count: number
  ids: Uint32Array
}

export function createIdList(capacity = 256): IdList {
  return { count: 0, ids: new Uint32Array(capacity) }
}

export function pushId(list: IdList, eid: number): void {
  if (list.count === list.ids.length) {
    const next = new Uint32Array(list.ids.length * 2)
    next.set(list.ids)
    list.ids = next
  }
  list.ids[list.count++] = eid
}

/**
 * The balls that move (rolling or on a rim), as a sparse set: O(1) insert and remove with no allocation,
 * so a ball that stops or falls in costs nothing afterwards. (A bitECS tag did the same job at about a
 * quarter of the dense-scene step time, in add/remove bookkeeping and garbage.)
 */
export interface MovingSet {
  count: number
  dense: Uint32Array
  /** index in `dense` by entity id; valid only where dense[sparse[eid]] === eid */
  sparse: Uint32Array
}

export function isMoving(world: BallWorld, eid: number): boolean {
  const m = world.moving
  const i = m.sparse[eid]!
  return i < m.count && m.dense[i] === eid
}

export function addMoving(world: BallWorld, eid: number): void {
  if (isMoving(world, eid)) return
  const m = world.moving
  if (m.count === m.dense.length) {
    const next = new Uint32Array(m.dense.length * 2)
    next.set(m.dense)
    m.dense = next
  }
  m.sparse[eid] = m.count
  m.dense[m.count++] = eid
  spotJoin(world, eid)
}

/** Removes by swapping the last element in; callers iterating `dense` go from the end to the start. */
export function removeMoving(world: BallWorld, eid: number): void {
  if (!isMoving(world, eid)) return
  const m = world.moving
  const i = m.sparse[eid]!
  const last = m.dense[--m.count]!
  m.dense[i] = last
  m.sparse[last] = i
}
