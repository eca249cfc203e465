// A closed wall within reach turns a candidate at the contact tick (src/contacts/fixedSolve.ts), so that the
// solve meets what the wall sends back within the same tick: a row pressed into a wall is held by it, a ball
// turned there meets the ball behind it. A candidate that only the wall turned, and that no pair, row or
// projection then touched, met nothing: unless a pair could meet it on its own way to the wall or back from
// it within the tick, it is given back the velocity it had, and the walls system turns it at the wall
// itself, at its instant, as with contacts off. (Turned at the tick, such a ball left the
// tick short of its wall, up to a tick's travel: a ball at 700 px/s 5 px from its wall was sent back from
// there, 10 px off its path, its 'wall' event stamped with the tick's time, whenever another ball was within
// reach.) The 'wall' event of a candidate that keeps its turn is written here, at the tick.
import { EventType, appendEvent } from '../events.js'
import type { BallWorld } from '../world/createWorld.js'
import type { FixedContactState } from '../world/fixedState.js'
import { walls } from './fixedGrid.js'
import { meetsWithinTick, S_SETTLE, solveSlots, swept } from './fixedPairs.js'

/** changed bit of a candidate whose wall hit this tick was reported */
export const WALL_REPORTED = 4
/** changed bit of a candidate a closed wall turned in this tick's solve */
export const WALL_TURNED = 8
/** changed bit of a candidate the wall turned by BALL_SETTLE_SPEED or more: a 'wall' event if it keeps the turn */
export const WALL_DUE = 16
/** changed bit of a candidate whose velocity the solve changed (a pair, a squeeze, a jam, a held row, a wall) */
export const VELOCITY = 1
/** changed bit of a candidate whose velocity a pair, a squeeze, a jam or a held row changed */
const HIT = 32
/** changed bits a pair, a squeeze, a jam or a held row sets: VELOCITY and HIT */
export const STRUCK = VELOCITY | HIT
/** changed bit of a candidate the projection moved (src/contacts/fixedPush.ts) */
export const MOVED = 2

/** changed bit of a candidate keepWallTurns gives back its velocity (within the call) */
const LONE = 64

/** the turned velocities of the lone candidates, for those a pair keeps turned (grown, never shrunk) */
let turnedVx = new Float64Array(64)
let turnedVy = new Float64Array(64)

/**
 * Gives back their velocities to the candidates only a wall turned (see above), unless one of its pairs
 * would meet within the tick at that velocity (on straight lines, the swept test) or on its way back from
 * the wall (meetsAfterWall), or its partner is such a candidate too (both reach the wall within the tick:
 * the first back would meet the other on its way in, between the ticks): those keep the turn. Reports the
 * kept turns' 'wall' events at the tick.
 */
export function keepWallTurns(w: BallWorld, F: FixedContactState): void {
  const B = w.Ball
  // grown before the loop: grown within it, it dropped the turns already kept there (which then read 0, and
  // depended on the worlds stepped before in the process)
  if (turnedVx.length < F.n) {
    turnedVx = new Float64Array(2 * F.n)
    turnedVy = new Float64Array(2 * F.n)
  }
  let lone = 0
  for (let k = 0; k < F.nearWallCount; k++) {
    const i = F.nearWall[k]!
    const c = F.changed[i]!
    if ((c & WALL_TURNED) === 0 || (c & (HIT | MOVED)) !== 0) continue
    turnedVx[i] = F.vx[i]!
    turnedVy[i] = F.vy[i]!
    // gathered at rest, a candidate has velocity 0 and no wall turns it: its gathered velocity is its own
    const eid = F.id[i]!
    F.vx[i] = B.vx[eid]!
    F.vy[i] = B.vy[eid]!
    F.changed[i] = c | LONE
    lone++
  }
  if (lone > 0) {
    const overlap = F.overlap
    for (let p = 0; p < F.pairCount; p++) {
      const a = F.pairA[p]!
      const b = F.pairB[p]!
      const la = (F.changed[a]! & LONE) !== 0
      const lb = (F.changed[b]! & LONE) !== 0
      if (!la && !lb) continue
      if ((la && lb) || meetsWithinTick(F, a, b) || (la ? meetsAfterWall(F, a, b) : meetsAfterWall(F, b, a))) {
        if (la) keepTurn(F, a)
        if (lb) keepTurn(F, b)
      }
    }
    F.overlap = overlap
  }
  for (let k = 0; k < F.nearWallCount; k++) {
    const i = F.nearWall[k]!
    const c = F.changed[i]!
    if ((c & LONE) !== 0) {
      F.changed[i] = 0
      continue
    }
    if ((c & (WALL_TURNED | WALL_DUE | WALL_REPORTED)) === (WALL_TURNED | WALL_DUE)) {
      const ev = appendEvent(w.events, EventType.Wall, F.id[i]!, 0, false)
      w.events.time[ev] = w.time
      F.changed[i] = c | WALL_REPORTED
    }
  }
}

/** A lone candidate a pair keeps turned: its turned velocity back. */
function keepTurn(F: FixedContactState, i: number): void {
  F.vx[i] = turnedVx[i]!
  F.vy[i] = turnedVy[i]!
  F.changed[i]! &= ~LONE
}

/**
 * Whether lone candidate a, at its own velocity, meets candidate b (on its solved velocity) on its way back
 * from its first closed wall within the tick (straight lines: to the wall, then turned by the walls'
 * restitution), or would reach another wall before the tick's end (a second turn: not followed, as if it
 * met). Given back its velocity, a ball turned at the tick follows the path the walls system gives it, and
 * the solve only met the path it was turned on at the tick: a ball at 26,545 px/s that turned at a wall
 * 2 ms into the tick went through a ball at rest 4.7 px deep, its turned path from the tick clear of it.
 */
function meetsAfterWall(F: FixedContactState, a: number, b: number): boolean {
  const r = F.r[a]!
  let vx = F.vx[a]!
  let vy = F.vy[a]!
  // Infinity written 1 / 0: the global, read in a branch V8 has not seen taken, is a generic load, and the
  // doubles it merges with were boxed at every call
  const hitX = vx < 0 ? (walls.minX + r - F.x[a]!) / vx : vx > 0 ? (walls.maxX - r - F.x[a]!) / vx : 1 / 0
  const hitY = vy < 0 ? (walls.minY + r - F.y[a]!) / vy : vy > 0 ? (walls.maxY - r - F.y[a]!) / vy : 1 / 0
  const tw = Math.max(0, Math.min(hitX, hitY))
  if (!(tw < F.tick)) return false
  // where a meets the wall, and its velocity back from it (both axes at a corner)
  const ax = F.x[a]! + vx * tw
  const ay = F.y[a]! + vy * tw
  if (hitX <= hitY) vx = wedgedOn(F, a, 1) ? 0 : -walls.e * vx
  if (hitY <= hitX) vy = wedgedOn(F, a, 2) ? 0 : -walls.e * vy
  const rest = F.tick - tw
  // a second wall within the tick
  if ((vx < 0 && ax - r - walls.minX < -vx * rest) || (vx > 0 && walls.maxX - ax - r < vx * rest)) return true
  if ((vy < 0 && ay - r - walls.minY < -vy * rest) || (vy > 0 && walls.maxY - ay - r < vy * rest)) return true
  // the swept test from the wall on, b where it is then
  return swept(F.x[b]! + F.vx[b]! * tw - ax, F.y[b]! + F.vy[b]! * tw - ay, F.vx[b]! - vx, F.vy[b]! - vy, r + F.r[b]!, rest)
}

/**
 * Turns candidate i at its closed walls on the axes of `bits` (intoWalls' bits: 1 x, 2 y), in F.vx and F.vy:
 * by the walls' restitution, or to no speed along an axis it is wedged on (wedgedOn) or, when `floored`, along
 * which it moves slower than BALL_SETTLE_SPEED (the solve's turn: such a ball stops at its wall). The solve's
 * wall turn and the guard's (src/contacts/fixedGuard.ts) take a wall by this.
 */
export function turnAtWalls(F: FixedContactState, i: number, bits: number, floored: boolean): void {
  const floor = floored ? solveSlots[S_SETTLE]! : 0
  const vx = F.vx[i]!
  const vy = F.vy[i]!
  if ((bits & 1) !== 0) F.vx[i] = Math.abs(vx) < floor || wedgedOn(F, i, 1) ? 0 : -walls.e * vx
  if ((bits & 2) !== 0) F.vy[i] = Math.abs(vy) < floor || wedgedOn(F, i, 2) ? 0 : -walls.e * vy
}

/**
 * Whether candidate i is wider than the box on the axis of `axis` (intoWalls' bits: 1 x, 2 y), both faces
 * closed (an open one is at infinity): it is wedged there, as the walls system leaves such a ball
 * (systems/walls.ts), and a wall turns it to no speed along that axis (turned back, it would meet the far
 * face at once). The solve's wall turn, the wall pair and the lone-ball check all take the wall by this.
 */
export function wedgedOn(F: FixedContactState, i: number, axis: number): boolean {
  const across = axis === 1 ? walls.maxX - walls.minX : walls.maxY - walls.minY
  return across <= 2 * F.r[i]!
}
