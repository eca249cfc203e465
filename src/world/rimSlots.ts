// A ball's RimContact row: taken when it gets a hole lock (its centre enters a lip circle), given back when
// the lock ends. The store is pooled by slot (components/RimContact.ts). The bitECS RimContact component
// marks the balls rolling on a rim (src/world/ballMode.ts).
import { growStore } from '../../components/store.js'
import { pushId } from './idLists.js'
import type { BallWorld } from './createWorld.js'

/** The ball's RimContact slot: 0, the all-zero row (hole 0, mode None), when it holds no hole lock. */
export function rimSlot(world: BallWorld, eid: number): number {
  return world.Ball.rim[eid]!
}

/**
 * The ball's RimContact slot, taking one for it if it has none (a taken row is all zero). Call it where a
 * ball gets a hole lock, before writing its row; the store may grow, so fetch arrays after the call.
 */
export function acquireRim(world: BallWorld, eid: number): number {
  const held = world.Ball.rim[eid]!
  if (held !== 0) return held
  const pool = world.rimFree
  const slot = pool.count > 0 ? pool.ids[--pool.count]! : world.rimNext++
  if (slot >= world.RimContact.hole.length) growStore(world.RimContact, 2 * world.RimContact.hole.length)
  world.Ball.rim[eid] = slot
  return slot
}

/**
 * Takes a hole lock for a ball at its lip crossing: a RimContact slot recording the hole, (δ, v), the
 * crossing's time and the rim mode. Returns the slot.
 */
export function lockAtLip(world: BallWorld, eid: number, hole: number, delta: number, speed: number, t: number, mode: number): number {
  const rim = acquireRim(world, eid)
  const RC = world.RimContact
  RC.hole[rim] = hole
  RC.mode[rim] = mode
  RC.hasLip[rim] = 1
  RC.delta[rim] = delta
  RC.speed[rim] = speed
  RC.lipTime[rim] = t
  return rim
}

/** Gives back the ball's RimContact slot (zeroed) when its hole lock ends; a no-op when it has none. */
export function releaseRim(world: BallWorld, eid: number): void {
  const slot = world.Ball.rim[eid]!
  if (slot === 0) return
  // every field, written out: this runs at each lock's end (clearSlot's generic loop costs more)
  const RC = world.RimContact
  RC.hole[slot] = 0
  RC.mode[slot] = 0
  RC.hasLip[slot] = 0
  RC.delta[slot] = 0
  RC.speed[slot] = 0
  RC.lipTime[slot] = 0
  RC.angle[slot] = 0
  RC.arc[slot] = 0
  RC.angle0[slot] = 0
  RC.speed0[slot] = 0
  RC.direction[slot] = 0
  RC.time0[slot] = 0
  RC.ride[slot] = 0
  RC.rideTurn[slot] = 0
  RC.rideTime[slot] = 0
  RC.rideFrom[slot] = 0
  RC.rideTo[slot] = 0
  RC.exitVx[slot] = 0
  RC.exitVy[slot] = 0
  pushId(world.rimFree, slot)
  world.Ball.rim[eid] = 0
}
