// Fixed-tick contacts: a long row the velocity sweeps leave closing moves on as one body. Gauss-Seidel
// sweeps (src/contacts/fixedSolve.ts) carry a push one pair further each, both ways in turn, and even out the
// velocities along a row of touching balls in about the square of its length. A heavy ball ploughing into
// a row of light ones gathers hundreds in front of it, all touching; the sweeps leave the back of that row
// faster than its front, each tick closes it a little more, the projection (its budget also in sweeps)
// cannot open it again, and the balls sink into each other until two pass.
// So when half the sweeps are done without converging, the pairs still closing within the tick join their
// balls into groups, and so do the pairs met RESTITUTION_VISITS times this tick (half way through, the
// sweeps can leave a heavy striker for the moment slower than the ball ahead of it, though it is pushing
// the whole row; the pairs of an elastic row, met once or twice as its pulse runs through, stay apart). A
// group moves on at its centre-of-mass velocity when it is a row (the normals of those pairs within 30° of
// its first pair's line, ROW_LINE_COS: a striker's swept test meets many balls ahead of it on that line, a
// pile's normals turn by 60° or 90°) of at least JAM_MIN_BALLS balls, none of them able to reach a closed
// wall within the tick (a wall is no body to average with: src/contacts/fixedShock.ts holds those rows),
// and its pairs close by more than PROJECTION_SLOP in all. That is the fully inelastic end of the pairs
// still closing: momentum is kept, kinetic energy does not rise (a mass-weighted mean), the row no longer
// closes, and the other half of the sweeps take its new velocities to the balls around it. Pairs with a
// resting candidate (it holds like a wall) join nothing. The sums run over the balls in the order of their
// first pair, which both broadphases give alike (their numbering of the candidates differs), so the bits do
// not depend on the broadphase.
import { JAM_MIN_BALLS, PROJECTION_SLOP, RESTITUTION_VISITS } from '../config/tolerances.js'
import { grownTo, type FixedContactState } from '../world/fixedState.js'
import { meetsWithinTick, normal, nrm, touch } from './fixedPairs.js'
import { keepsLine, rootOf, uniteSized } from './fixedUnion.js'
import { asBefore, foundNow, OTHER, PARTING, REFUSED } from './fixedStamps.js'

/**
 * Union-find over the candidates; by root: the mass, momentum and members summed, whether the group is
 * left alone (a member near a closed wall, or its pairs off its line), and its line
 */
let parent = new Int32Array(256)
let mass = new Float64Array(256)
let px = new Float64Array(256)
let py = new Float64Array(256)
let members = new Int32Array(256)
let excluded = new Uint8Array(256)
let lineX = new Float64Array(256)
let lineY = new Float64Array(256)
/** each pair's closing within the tick (px; 0: not closing; −1: not closing, met RESTITUTION_VISITS times), its normal, and each group's sum of closings */
let closing = new Float64Array(256)
let normalX = new Float64Array(256)
let normalY = new Float64Array(256)
let closes = new Float64Array(256)
/** when each candidate was last summed, and last set (marks from `mark`) */
let seen = new Float64Array(256)
let mark = 0
/** the candidates whose velocities the last settleJams changed */
let list = new Int32Array(256)
/** solve calls that settled a jam, over the process's life (for tests and benchmarks) */
let settled = 0

function root(i: number): number {
  return rootOf(parent, i)
}

/**
 * Settles the jams of a solve that did not converge (see the top of this file); returns how many candidates'
 * velocities changed, listed in jammed().
 */
export function settleJams(F: FixedContactState): number {
  const n = F.n
  if (parent.length < n) {
    parent = new Int32Array(2 * n)
    mass = grownTo(mass, 2 * n)
    px = grownTo(px, 2 * n)
    py = grownTo(py, 2 * n)
    members = new Int32Array(2 * n)
    excluded = new Uint8Array(2 * n)
    lineX = grownTo(lineX, 2 * n)
    lineY = grownTo(lineY, 2 * n)
    seen = grownTo(seen, 2 * n)
    list = new Int32Array(2 * n)
    closes = grownTo(closes, 2 * n)
  }
  if (closing.length < F.pairCount) {
    closing = grownTo(closing, 2 * F.pairCount)
    normalX = grownTo(normalX, 2 * F.pairCount)
    normalY = grownTo(normalY, 2 * F.pairCount)
  }
  // members: each group's size while the pairs join them (no row of JAM_MIN_BALLS: nothing to settle)
  for (let i = 0; i < n; i++) {
    parent[i] = i
    members[i] = 1
  }
  let largest = 1
  const pairs = F.pairCount
  for (let p = 0; p < pairs; p++) {
    const a = F.pairA[p]!
    const b = F.pairB[p]!
    closing[p] = 0
    if (a >= F.restFrom || b >= F.restFrom) continue
    // a pair whose balls have not changed since the sweeps last found it refused or parting does not close;
    // one tested here and not closing is stamped as found (the rules after this one and the next sweep take
    // it so, src/contacts/fixedStamps.ts)
    let approach = 0
    if (asBefore(F, p) === OTHER) {
      if (meetsWithinTick(F, a, b)) {
        approach = -((F.vx[b]! - F.vx[a]!) * nrm.x + (F.vy[b]! - F.vy[a]!) * nrm.y)
        if (!(approach > 0)) foundNow(F, p, touch.c <= 0 ? PARTING : OTHER)
      } else foundNow(F, p, REFUSED)
    }
    if (approach > 0) closing[p] = approach * F.tick
    else {
      // not closing now, but met RESTITUTION_VISITS times this tick (pressed together, not bounced apart):
      // joined along the line of its centres
      if (F.pairHit[p]! >> 1 < RESTITUTION_VISITS) continue
      normal(F, a, b)
      closing[p] = -1
    }
    normalX[p] = nrm.x
    normalY[p] = nrm.y
    const size = uniteSized(parent, members, a, b)
    if (size > largest) largest = size
  }
  if (largest < JAM_MIN_BALLS) return 0
  for (let i = 0; i < n; i++) {
    mass[i] = 0
    px[i] = 0
    py[i] = 0
    members[i] = 0
    excluded[i] = 0
    closes[i] = 0
    lineX[i] = 0
    lineY[i] = 0
  }
  for (let k = 0; k < F.nearWallCount; k++) excluded[F.nearWall[k]!] = 1
  // the sums, each ball at its first pair, and each group's closing
  const summed = ++mark
  for (let p = 0; p < pairs; p++) {
    const a = F.pairA[p]!
    sum(F, a, summed)
    sum(F, F.pairB[p]!, summed)
    if (closing[p] === 0) continue
    const r = root(a)
    if (closing[p]! > 0) closes[r] = closes[r]! + closing[p]!
    if (!keepsLine(lineX, lineY, r, normalX, normalY, p)) excluded[r] = 1
  }
  const set = ++mark
  let count = 0
  for (let p = 0; p < pairs; p++) {
    count = settle(F, F.pairA[p]!, set, count)
    count = settle(F, F.pairB[p]!, set, count)
  }
  if (count > 0) settled++
  return count
}

function sum(F: FixedContactState, i: number, summed: number): void {
  if (seen[i] === summed || i >= F.restFrom) return
  seen[i] = summed
  const r = root(i)
  const m = F.mass[F.id[i]!]!
  mass[r] = mass[r]! + m
  px[r] = px[r]! + m * F.vx[i]!
  py[r] = py[r]! + m * F.vy[i]!
  members[r]!++
  if (excluded[i] === 1) excluded[r] = 1
}

function settle(F: FixedContactState, i: number, set: number, count: number): number {
  if (seen[i] === set || i >= F.restFrom) return count
  seen[i] = set
  const r = root(i)
  if (members[r]! < JAM_MIN_BALLS || excluded[r] !== 0 || !(closes[r]! > PROJECTION_SLOP)) return count
  const vx = px[r]! / mass[r]!
  const vy = py[r]! / mass[r]!
  if (vx === F.vx[i] && vy === F.vy[i]) return count
  F.vx[i] = vx
  F.vy[i] = vy
  list[count] = i
  return count + 1
}

export function jammed(): Int32Array {
  return list
}

export function jamsSettled(): number {
  return settled
}
