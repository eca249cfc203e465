// The fixed-tick method's contact solve (config.BALL_COLLISIONS = 'fixed'), at one contact tick, over the
// pairs of src/contacts/fixedGrid.ts:
//   velocities: up to CONTACT_ITERATIONS sweeps over the pairs (then the closed walls) in a fixed order.
//     A pair that approaches and would touch within the tick takes the two-body impulse
//     j = (1 + e)·w / (1/m_a + 1/m_b) (e = BALL_RESTITUTION, or 0 below BALL_SETTLE_SPEED): every impulse is
//     a two-body contact, so momentum is kept and kinetic energy never rises, sweep by sweep; a pair takes
//     its restitution once a tick, and closes inelastically when pushed together again within it. "Would touch
//     within the tick" is the swept test on straight lines at the present velocities, and the impulse acts
//     along the normal at that first touch, so a glancing contact leaves as it would at its instant, up to
//     one tick early. A closed wall within reach reflects the normal velocity with the walls' restitution.
//   positions: sweeps that move every overlapping pair apart along the normal, shared by inverse mass (each
//     taking at least a tenth), and
//     keep balls inside the closed walls, until no overlap is deeper than PROJECTION_SLOP (at most
//     MAX_PROJECTION_SWEEPS). Only positions change: the projection adds no kinetic energy.
// In the projection, the part of a push that a closed wall keeps a ball from taking goes to the other ball
// of the pair, so a heavy ball cannot drive a light one through the wall.
// Then every ball the solve changed starts a fresh path from its new state at the tick (a ball on a rim or
// in a hole's lock is in transit there, as after a contact in the exact method); a resting ball wakes only
// if it leaves at BALL_SETTLE_SPEED or more.
import { BallMode } from '../../components/Ball.js'
import { EventType, pushCollisionEvent, pushEvent } from '../events.js'
import { launchBall, placeBall } from '../motion/ballFate.js'
import type { BallWorld } from '../world/createWorld.js'
import { touchBall, type FixedContactState } from '../world/fixedState.js'
import { holeAt } from '../world/holeTable.js'
import { MAX_PROJECTION_SWEEPS, MIN_PROJECTION_SHARE, PROJECTION_SLOP } from '../config/tolerances.js'
import { restingInsert, restingRemove } from '../world/restingGrid.js'
import { walls } from './fixedGrid.js'
import { strikeLeavesRim } from './law.js'

/** Normal of pair p (a→b) into nrm; returns the gap (negative: overlap). */
const nrm = { x: 1, y: 0 }
function normal(F: FixedContactState, a: number, b: number): number {
  const dx = F.x[b]! - F.x[a]!
  const dy = F.y[b]! - F.y[a]!
  const d = Math.sqrt(dx * dx + dy * dy)
  if (d > 0) {
    nrm.x = dx / d
    nrm.y = dy / d
  } else {
    // coincident centres: apart along the relative velocity, else along +x (the lower index to the left)
    const rx = F.vx[a]! - F.vx[b]!
    const ry = F.vy[a]! - F.vy[b]!
    const s = Math.sqrt(rx * rx + ry * ry)
    nrm.x = s > 0 ? rx / s : 1
    nrm.y = s > 0 ? ry / s : 0
  }
  return d - F.r[a]! - F.r[b]!
}

/** pairHit bits: the pair took an impulse this tick; its contact was reported */
const IMPULSED = 1
const REPORTED = 2
/** changed bit of a candidate whose wall hit this tick was reported */
const WALL_REPORTED = 4

export function solveVelocities(w: BallWorld, F: FixedContactState, t: number, iterations: number): void {
  const e = w.config.BALL_RESTITUTION
  const settle = w.config.BALL_SETTLE_SPEED
  for (let it = 0; it < iterations; it++) {
    let moved = false
    // the walls first and last in each sweep, the pairs forward and backward in turn (symmetric
    // Gauss-Seidel): a push runs through a row against a wall either way within a sweep
    if (wallVelocities(w, F, t, settle)) moved = true
    const back = (it & 1) === 1
    for (let k = 0; k < F.pairCount; k++) {
      const p = back ? F.pairCount - 1 - k : k
      const a = F.pairA[p]!
      const b = F.pairB[p]!
      if (!meetsWithinTick(F, a, b)) continue
      const nx = nrm.x
      const ny = nrm.y
      const approach = -((F.vx[b]! - F.vx[a]!) * nx + (F.vy[b]! - F.vy[a]!) * ny)
      if (!(approach > 0)) continue
      const ima = F.im[a]!
      const imb = F.im[b]!
      // restitution once a tick per pair: met again in a later sweep (a third ball pushed them together),
      // the pair closes inelastically, so a light ball between heavy ones cannot be bounced to and fro
      // without end within one tick
      const hit = F.pairHit[p]!
      const j = ((1 + (approach < settle || (hit & IMPULSED) !== 0 ? 0 : e)) * approach) / (ima + imb)
      F.pairHit[p] = hit | IMPULSED
      F.vx[a] = F.vx[a]! - j * ima * nx
      F.vy[a] = F.vy[a]! - j * ima * ny
      F.vx[b] = F.vx[b]! + j * imb * nx
      F.vy[b] = F.vy[b]! + j * imb * ny
      if ((F.changed[a]! & 1) === 0) F.hit[F.hitCount++] = a
      if ((F.changed[b]! & 1) === 0) F.hit[F.hitCount++] = b
      F.changed[a]! |= 1
      F.changed[b]! |= 1
      moved = true
      if ((hit & REPORTED) === 0 && approach >= settle) {
        F.pairHit[p] = hit | IMPULSED | REPORTED
        F.contacts++
        const ia = F.id[a]!
        const ib = F.id[b]!
        pushCollisionEvent(w.events, ia < ib ? ia : ib, ia < ib ? ib : ia, t, approach, j)
      }
    }
    if (wallVelocities(w, F, t, settle)) moved = true
    if (!moved) break
  }
}

/**
 * True when candidates a and b touch now or will within the tick on straight lines at their present
 * velocities (the swept test); the contact normal, a→b at that first touch, is left in nrm.
 */
function meetsWithinTick(F: FixedContactState, a: number, b: number): boolean {
  const dx = F.x[b]! - F.x[a]!
  const dy = F.y[b]! - F.y[a]!
  const S = F.r[a]! + F.r[b]!
  const c = dx * dx + dy * dy - S * S
  if (c <= 0) {
    if (c < 0) F.overlap = true
    normal(F, a, b)
    return true
  }
  const ux = F.vx[b]! - F.vx[a]!
  const uy = F.vy[b]! - F.vy[a]!
  const half = dx * ux + dy * uy
  if (half >= 0) return false
  const disc = half * half - (ux * ux + uy * uy) * c
  if (disc < 0) return false
  // first root of |d + u·τ| = S, in the form that keeps its digits when the pair barely approaches
  const tau = c / (-half + Math.sqrt(disc))
  if (tau > F.tick) return false
  nrm.x = (dx + ux * tau) / S
  nrm.y = (dy + uy * tau) / S
  return true
}

/** A closed wall reflects the normal velocity of a candidate that would reach it within the tick. */
function wallVelocities(w: BallWorld, F: FixedContactState, t: number, settle: number): boolean {
  if (F.nearWallCount === 0) return false
  let moved = false
  const tick = F.tick
  for (let k = 0; k < F.nearWallCount; k++) {
    const i = F.nearWall[k]!
    const x = F.x[i]!
    const y = F.y[i]!
    const r = F.r[i]!
    let vx = F.vx[i]!
    let vy = F.vy[i]!
    let hit = false
    // an open edge's face is at ±Infinity: never within a tick
    if ((vx < 0 && x - r - walls.minX <= -vx * tick) || (vx > 0 && walls.maxX - x - r <= vx * tick)) {
      vx = bounce(vx, settle)
      hit = true
    }
    if ((vy < 0 && y - r - walls.minY <= -vy * tick) || (vy > 0 && walls.maxY - y - r <= vy * tick)) {
      vy = bounce(vy, settle)
      hit = true
    }
    if (!hit) continue
    if ((F.changed[i]! & WALL_REPORTED) === 0 && Math.max(Math.abs(F.vx[i]! - vx), Math.abs(F.vy[i]! - vy)) >= settle) {
      pushEvent(w.events, EventType.Wall, F.id[i]!, 0, t, false, 0, 0)
      F.changed[i]! |= WALL_REPORTED
    }
    F.vx[i] = vx
    F.vy[i] = vy
    if ((F.changed[i]! & 1) === 0) F.hit[F.hitCount++] = i
    F.changed[i]! |= 1
    moved = true
  }
  return moved
}

function bounce(vn: number, settle: number): number {
  return Math.abs(vn) < settle ? 0 : -walls.e * vn
}

export function solvePositions(w: BallWorld, F: FixedContactState): void {
  // the velocity sweeps met every pair at the tick's positions: no overlap among them, nothing to move
  if (!F.overlap) return
  for (let it = 0; it < MAX_PROJECTION_SWEEPS; it++) {
    let worst = 0
    const back = (it & 1) === 1
    for (let k = 0; k < F.pairCount; k++) {
      const p = back ? F.pairCount - 1 - k : k
      const a = F.pairA[p]!
      const b = F.pairB[p]!
      const gap = normal(F, a, b)
      if (!(gap < 0)) continue
      const nx = nrm.x
      const ny = nrm.y
      if (-gap > worst) worst = -gap
      // shared by inverse mass, each ball taking at least MIN_PROJECTION_SHARE (a light ball squeezed between
      // heavy ones would otherwise take every push and pass it to and fro); what a wall keeps one ball from
      // taking, the other takes (a ball against a wall is held by it)
      const want = -gap
      const share = Math.min(1 - MIN_PROJECTION_SHARE, Math.max(MIN_PROJECTION_SHARE, F.im[a]! / (F.im[a]! + F.im[b]!)))
      const ax = F.x[a]!
      const ay = F.y[a]!
      F.x[a] = ax - want * share * nx
      F.y[a] = ay - want * share * ny
      keepInside(w, F, a)
      const took = (ax - F.x[a]!) * nx + (ay - F.y[a]!) * ny
      const bx = F.x[b]!
      const by = F.y[b]!
      F.x[b] = bx + (want - took) * nx
      F.y[b] = by + (want - took) * ny
      keepInside(w, F, b)
      // and what a wall keeps b from taking goes back to a
      const left = want - took - ((F.x[b]! - bx) * nx + (F.y[b]! - by) * ny)
      if (left > 0) {
        F.x[a] = F.x[a]! - left * nx
        F.y[a] = F.y[a]! - left * ny
        keepInside(w, F, a)
      }
      F.changed[a]! |= 2
      F.changed[b]! |= 2
    }
    if (worst <= PROJECTION_SLOP) break
  }
}

/**
 * Keeps a moved candidate from being pushed through a closed wall: never further past a wall's inner face
 * than it was when the tick began (a ball outside the box stays outside; an open edge's face is at
 * ±Infinity, so it never holds).
 */
function keepInside(w: BallWorld, F: FixedContactState, i: number): void {
  const eid = F.id[i]!
  const r = F.r[i]!
  const x0 = w.Ball.x[eid]!
  const y0 = w.Ball.y[eid]!
  F.x[i] = Math.min(Math.max(F.x[i]!, Math.min(x0, walls.minX + r)), Math.max(x0, walls.maxX - r))
  F.y[i] = Math.min(Math.max(F.y[i]!, Math.min(y0, walls.minY + r)), Math.max(y0, walls.maxY - r))
}

/** Gives every changed ball a fresh path from its state at the tick t (see the top of this file). */
export function applyChanges(w: BallWorld, F: FixedContactState, t: number): void {
  const B = w.Ball
  const settle = w.config.BALL_SETTLE_SPEED
  for (let i = 0; i < F.n; i++) {
    const c = F.changed[i]!
    if (c === 0) continue
    const eid = F.id[i]!
    if ((c & 2) !== 0) touchBall(F, eid)
    const x = F.x[i]!
    const y = F.y[i]!
    const vx = F.vx[i]!
    const vy = F.vy[i]!
    if (B.mode[eid] === BallMode.Resting) {
      if (Math.sqrt(vx * vx + vy * vy) >= settle) launchBall(w, eid, x, y, vx, vy, t)
      else if ((c & 2) !== 0) moveResting(w, F, eid, x, y, t)
      continue
    }
    strikeLeavesRim(w, eid)
    launchBall(w, eid, x, y, vx, vy, t)
  }
}

/** A resting ball the projection moved: it stays at rest there. */
function moveResting(w: BallWorld, F: FixedContactState, eid: number, x: number, y: number, t: number): void {
  restingRemove(w, eid)
  w.Ball.x[eid] = x
  w.Ball.y[eid] = y
  // pushed over a hole, it falls in (in transit there, it stops inside the lip circle)
  if (holeAt(w, x, y) !== 0) {
    placeBall(w, eid, x, y, 0, 0, t)
    return
  }
  restingInsert(w, eid)
}
