// Id lists without allocation: a growable list, and the sparse set of the balls that move.
import { BallMode } from '../../components/Ball.js'
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

/** Puts an id into a list at index `at` (0 ≤ at ≤ count), the ids from there on one place later. */
export function insertId(list: IdList, at: number, eid: number): void {
  pushId(list, eid)
  list.ids.copyWithin(at + 1, at, list.count - 1)
  list.ids[at] = eid
}

/**
 * Takes the held balls removed between steps (world.heldGone, src/world/balls.ts: forgetBall) out of the
 * launcher's queue in one pass, keeping the others in order: a removed ball's row is cleared, and an id
 * reused since is not a held ball until it joins the queue again, which this runs before. Called by every
 * reader of the queue that a command or a step starts (the step, putting a ball down on a held one,
 * snapshots, heldCount), so removing n held balls costs O(n + queue) instead of n scans of the queue.
 */
export function dropGoneHeld(w: BallWorld): void {
  if (w.heldGone === 0) return
  const q = w.held
  const B = w.Ball
  let n = 0
  for (let i = 0; i < q.count; i++) {
    const eid = q.ids[i]!
    if (B.live[eid] === 1 && B.mode[eid] === BallMode.Held) q.ids[n++] = eid
  }
  q.count = n
  w.heldGone = 0
}

/** Takes every occurrence of an id out of a list, keeping the others in order. */
export function dropId(list: IdList, eid: number): void {
  const ids = list.ids
  let n = 0
  for (let i = 0; i < list.count; i++) if (ids[i] !== eid) ids[n++] = ids[i]!
  list.count = n
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
  /** balls added or removed since `dense` was last put in id order */
  churn: number
  /** orderMoving's scratch (it becomes `dense`, and `dense` the scratch) */
  spare: Uint32Array
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
    m.spare = new Uint32Array(next.length)
  }
  m.sparse[eid] = m.count
  m.dense[m.count++] = eid
  m.churn++
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
  m.churn++
}

/**
 * Puts the moving balls back in ascending id order, so a pass walks the per-ball arrays in memory order.
 * Swap-removals and recycled ids scatter the order over time; with 100,000 balls refilled as they fall in,
 * a scattered order cost about 3× the step of an ordered one (cache misses). No sort: the moving ids are
 * set as bits of a bitmap (an eighth of a kilobyte a thousand ids, in the first-level cache), then read
 * back in ascending order; the cost is in the moving balls, not in the ids in use.
 */
export function orderMoving(world: BallWorld): void {
  const m = world.moving
  m.churn = 0
  if (m.spare.length < m.dense.length) m.spare = new Uint32Array(m.dense.length)
  const words = (Math.min(m.sparse.length, world.entityIndex.maxId + 1) >>> 5) + 1
  if (bits.length < words) bits = new Int32Array(Math.max(words, 2 * bits.length))
  const dense = m.dense
  const n = m.count
  for (let i = 0; i < n; i++) {
    const eid = dense[i]!
    bits[eid >>> 5] |= 1 << (eid & 31)
  }
  const out = m.spare
  const sparse = m.sparse
  let k = 0
  for (let wd = 0; wd < words && k < n; wd++) {
    let b = bits[wd]!
    if (b === 0) continue
    bits[wd] = 0
    const base = wd << 5
    while (b !== 0) {
      const low = b & -b
      const eid = base + 31 - Math.clz32(low)
      sparse[eid] = k
      out[k++] = eid
      b ^= low
    }
  }
  m.spare = dense
  m.dense = out
}

/** orderMoving's bitmap: all zero between calls (each call clears the words it set) */
let bits = new Int32Array(1024)

/**
 * Sorts ids[from..to) ascending (an insertion sort for a few, the typed array's sort beyond 64). Lists built by
 * walking a grid or the moving set come in an order that depends on when each ball was put there, which
 * can differ between frame rates; the code that acts on them in turn sorts them by id first.
 */
export function sortIdRange(ids: Uint32Array, from: number, to: number): void {
  if (to - from > 64) {
    ids.subarray(from, to).sort()
    return
  }
  for (let i = from + 1; i < to; i++) {
    const v = ids[i]!
    let j = i - 1
    while (j >= from && ids[j]! > v) {
      ids[j + 1] = ids[j]!
      j--
    }
    ids[j + 1] = v
  }
}
