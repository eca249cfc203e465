// The fixed-tick projection's move of one overlapping pair apart (config.BALL_COLLISIONS = 'fixed'), shared by
// the projection's sweeps (src/contacts/fixedProject.ts) and its pass out from the walls
// (src/contacts/fixedLayered.ts): along the normal, by inverse mass with each ball taking at least
// MIN_PROJECTION_SHARE, never through a closed wall. Positions only.
import { MIN_PROJECTION_SHARE } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import type { FixedContactState } from '../world/fixedState.js'
import { walls } from './fixedGrid.js'
import { nrm } from './fixedPairs.js'
import { MOVED } from './fixedWallTurn.js'

/** whether the last pushApart() moved ball a, ball b of its pair */
export let movedA = false
export let movedB = false

/**
 * Moves the balls of pair p, overlapping by −nrm.gap along nrm (normal() just set both), apart; sets movedA,
 * movedB. The gap is read from nrm, not passed: a double passed to a call V8 does not inline is boxed, a
 * heap number a push.
 */
export function pushApart(w: BallWorld, F: FixedContactState, p: number): void {
  const a = F.pairA[p]!
  const b = F.pairB[p]!
  const nx = nrm.x
  const ny = nrm.y
  const gap = nrm.gap
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
  F.changed[a]! |= MOVED
  F.changed[b]! |= MOVED
  movedA = F.x[a] !== ax || F.y[a] !== ay
  movedB = F.x[b] !== bx || F.y[b] !== by
}

/**
 * Keeps a moved candidate from being pushed through a closed wall: never further past a wall's inner face
 * than it was when the tick began (an open edge's face is at ±Infinity, so it never holds). A ball whose
 * centre was beyond a wall's line at the tick's start is out of the box on that axis, not pressed into the
 * wall, and is not held on that side: held, a crowd the walls turn back toward a box too small for it (its
 * balls wider than the box) was squeezed onto the box's corners, 20 balls at one point, and every tick's
 * projection ran out of sweeps (tests/systems/fixedWall.test.ts).
 */
export function keepInside(w: BallWorld, F: FixedContactState, i: number): void {
  const eid = F.id[i]!
  const r = F.r[i]!
  const x0 = w.Ball.x[eid]!
  const y0 = w.Ball.y[eid]!
  // (no ±Infinity for "not held": a merge with the global Infinity on a branch V8 has not seen run boxes the
  // other side's double, a heap number a push in a crowd inside its box)
  let x = F.x[i]!
  if (!(x0 < walls.minX)) x = Math.max(x, Math.min(x0, walls.minX + r))
  if (!(x0 > walls.maxX)) x = Math.min(x, Math.max(x0, walls.maxX - r))
  F.x[i] = x
  let y = F.y[i]!
  if (!(y0 < walls.minY)) y = Math.max(y, Math.min(y0, walls.minY + r))
  if (!(y0 > walls.maxY)) y = Math.min(y, Math.max(y0, walls.maxY - r))
  F.y[i] = y
}
