// Balls as bitECS entities. A ball is an entity with the Ball and Path components (and RimContact while a
// hole holds it). The world keeps its own stores in step with bitECS through two observers, registered by
// createBallWorld:
//   - onAdd(Ball): the entity's rows are zeroed and it becomes a live ball, out of play (mode 'out') until
//     a command puts it on the panel (addBall and throwBall do both at once);
//   - onRemove(Ball): fired by removeEntity (ours or the game's) and by removeComponent(Ball). The
//     simulation forgets the ball: it leaves the moving set, gives back its RimContact slot, leaves the
//     resting grid and the step's lists of balls stopped at an event (a game's system may remove a ball
//     mid-step), its pending contacts go stale, its rows are zeroed and, removed between steps, the events
//     buffered for it are dropped at the next drain (its id may be handed to a new entity before then).
import { addComponent, addEntity, entityExists, hasComponent, removeComponent, removeEntity } from 'bitecs'
import { BallMode, clearBallRow } from '../../components/Ball.js'
import { clearPathRow } from '../../components/Path.js'
import { clearSlot } from '../../components/store.js'
import { cutEvents } from '../events.js'
import { NO_CONTACT, forgetPredictions } from './contactState.js'
import { ensureCapacity, type BallWorld } from './createWorld.js'
import { dropId, removeMoving } from './idLists.js'
import { clearPathHot } from './pathHot.js'
import { restingRemove } from './restingGrid.js'
import { releaseRim } from './rimSlots.js'
import { isLiveHole } from './holeTable.js'
import { checkWorld, describe } from '../check.js'

/** Makes a ball entity (Ball and Path), out of play at the origin; a command then places and launches it. */
export function addBallEntity(world: BallWorld): number {
  const eid = addEntity(world)
  try {
    addComponent(world, eid, world.Ball) // adoptBall runs here (and adds Path)
  } catch (e) {
    // an onAdd(Ball) observer of the game's that removed the entity: bitECS's addComponent went on and failed
    // on it with an error of its own
    if (!entityExists(world, eid)) {
      throw new Error(`addBall (throwBall): an onAdd(world.Ball) observer removed entity ${eid} while it was being made a ball (${e instanceof Error ? e.message : describe(e)}); remove a ball after the command that made it returns. Nothing was added`)
    }
    removeEntity(world, eid) // (adoptBall took the Ball off again: no entity is left half-made)
    throw e
  }
  return eid
}

/**
 * onAdd(Ball): the entity becomes a live ball (with Path) with zeroed rows, default radius and mass, out of
 * play. A hole or the walls cannot also be a ball (a hole given Ball by hand was listed as both, and could
 * not be removed): the Ball is taken off again and the game's addComponent throws.
 */
export function adoptBall(world: BallWorld, eid: number): void {
  if (isLiveHole(world, eid) || eid === world.walls) {
    removeComponent(world, eid, world.Ball) // forgetBall returns at once: not a ball yet
    throw new Error(`addComponent(world, ${eid}, world.Ball): entity ${eid} is ${eid === world.walls ? 'the walls' : 'a hole'}, which cannot also be a ball; make balls with addBall or throwBall (the entity is left as it was)`)
  }
  try {
    ensureCapacity(world, eid)
  } catch (e) {
    // out of memory growing the stores: the entity is not left a Ball the simulation does not know (a game's
    // query would list it); stores already grown stay grown, and the world goes on
    removeComponent(world, eid, world.Ball)
    throw new RangeError(`addComponent(world, ${eid}, world.Ball): the ball stores could not grow to hold entity ${eid} (${e instanceof Error ? e.message : describe(e)}); the entity is left as it was`)
  }
  if (!hasComponent(world, eid, world.Path)) addComponent(world, eid, world.Path)
  if (world.Ball.live[eid] !== 1) world.ballCount++
  clearBallRows(world, eid)
  const B = world.Ball
  B.live[eid] = 1
  B.radius[eid] = world.config.BALL_RADIUS
  B.mode[eid] = BallMode.Out
  const C = world.collide
  if (C !== null) {
    // a reused id starts with no contact history (its version is not reset: stale heap entries stay stale)
    C.mass[eid] = 1
    C.partner[eid] = 0
    C.lastContact[eid] = NO_CONTACT
  }
  if (world.fixed !== null) world.fixed.mass[eid] = 1
  world.kickStreak[eid] = 0
  world.kickAfter[eid] = 0
  for (let i = 0; i < world.ballStores.length; i++) clearSlot(world.ballStores[i]!, eid)
}

/** onRemove(Ball): the simulation forgets the ball (see the top of this file). */
export function forgetBall(world: BallWorld, eid: number): void {
  if (!isLiveBall(world, eid)) return
  world.ballCount--
  // between steps a held ball stays listed until the queue's next reader takes every removed one out in one
  // pass (dropGoneHeld, src/world/idLists.ts: its cleared row is no longer live); mid-step it leaves at once
  if (world.Ball.mode[eid] === BallMode.Held) {
    if (world.stepping) dropId(world.held, eid)
    else world.heldGone++
  }
  removeMoving(world, eid)
  // removed mid-step by a game's system: the next pass must not continue it (its zeroed path is due at
  // once, so with contacts on the pass would take its events for ever); between steps no list names it
  // (a window ends with `todo` spent, and `marked` is empty unless its passes ran out)
  dropId(world.marked, eid)
  if (world.stepping) dropId(world.todo, eid)
  releaseRim(world, eid)
  restingRemove(world, eid)
  forgetPredictions(world, eid)
  // between steps, the events buffered for it are dropped (its id may be handed to a new entity before the
  // next drain); removed mid-step by a game's system, it keeps those it had until then, which are history at
  // any frame rate (a finer rate drains them before the removal: dropping them made the events depend on it)
  if (!world.stepping) cutEvents(world.events, eid)
  clearBallRows(world, eid)
  // a Ball removed by removeComponent leaves an entity the game keeps: it is no longer a ball at all
  if (hasComponent(world, eid, world.Path)) removeComponent(world, eid, world.Path)
  if (hasComponent(world, eid, world.RimContact)) removeComponent(world, eid, world.RimContact)
}

/** True when `eid` is a live ball of this world. */
export function isBall(world: BallWorld, eid: number): boolean {
  checkWorld('isBall', world, true)
  return isLiveBall(world, eid)
}

/** isBall without the world's check, for callers that made it */
export function isLiveBall(world: BallWorld, eid: number): boolean {
  return eid > 0 && eid < world.capacity && world.Ball.live[eid] === 1
}

/** Calls `fn` for every live ball, in ascending id order. */
export function forEachBall(world: BallWorld, fn: (eid: number) => void): void {
  checkWorld('forEachBall', world, true)
  if (typeof fn !== 'function') throw new TypeError(`forEachBall: fn must be a function (eid) => void, got ${describe(fn)}`)
  if (world.ballCount === 0) return
  const live = world.Ball.live
  for (let eid = 1, n = Math.min(live.length, world.entityIndex.maxId + 1); eid < n; eid++) if (live[eid] === 1) fn(eid)
}

/**
 * Zeroes a ball's rows of Ball, Path and world.pathHot (the stores' rows field by field, beside their
 * schemas; tests/lifecycle.test.ts checks that no field is left out).
 */
export function clearBallRows(world: BallWorld, eid: number): void {
  clearBallRow(world.Ball, eid)
  clearPathRow(world.Path, eid)
  clearPathHot(world, eid)
}
