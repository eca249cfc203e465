// Entity checks for the commands (the field checks are in src/check.ts).
import { describe } from '../check.js'
import type { BallWorld } from '../world/createWorld.js'
import { isLiveBall } from '../world/balls.js'
import { isLiveHole } from '../world/holeTable.js'

export { checkWorld, choice, describe, finite, flag, positive, readSpec, specObject, within } from '../check.js'

function checkId(field: string, eid: unknown, kind: string): number {
  // not a number: the wrong type; a number that is not a positive integer: out of range
  if (typeof eid !== 'number') throw new TypeError(`${field} must be a ${kind} id (a positive integer), got ${describe(eid)}`)
  if (!Number.isInteger(eid) || eid < 1) throw new RangeError(`${field} must be a ${kind} id (a positive integer), got ${describe(eid)}`)
  return eid
}

/** The id of a live ball of the world. */
export function checkBall(world: BallWorld, field: string, eid: unknown): number {
  const b = checkId(field, eid, 'ball')
  if (!isLiveBall(world, b)) {
    if (isLiveHole(world, b)) throw new RangeError(`${field} ${b} is not a live ball of this world: it is a hole`)
    throw new RangeError(`${field} ${b} is not a live ball of this world (unknown or removed)`)
  }
  return b
}

/** The id of a live hole of the world. */
export function checkHole(world: BallWorld, field: string, eid: unknown): number {
  const h = checkId(field, eid, 'hole')
  if (isLiveBall(world, h)) throw new RangeError(`${field} ${h} is not a live hole of this world: it is a ball`)
  // a hole is one with a row in the table (a Hole component a game added by hand has none: removeHole would
  // remove the game's entity)
  if (!isLiveHole(world, h)) {
    throw new RangeError(`${field} ${h} is not a live hole of this world (unknown or removed)`)
  }
  return h
}

/**
 * Holes and walls change, and balls are put down or given velocities, between steps only (a game's system
 * may remove a ball mid-step): re-planned or started from the world's time, the step's start, while the
 * step's balls were each at their own instant within it, they took events at wrong times (a hole a system
 * removed at a ball's lip crossing gave that ball a 'skip' at the step's end) or went where the frame rate
 * put them. `what` says what to do instead.
 */
export function betweenSteps(w: BallWorld, command: string, what: string): void {
  if (w.stepping) throw new Error(`${command}: the world is in the middle of a step (called from a system?); ${what}`)
}
