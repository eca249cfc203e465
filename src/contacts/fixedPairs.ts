// The fixed-tick solve's pairs (src/contacts/fixedSolve.ts, fixedProject.ts): a pair's normal and gap, its
// swept test, and sweeps over listed pairs. After the full sweeps, a sweep need only meet the pairs with a
// ball whose velocity or position changed since the pair was last met (the others cannot take an impulse or
// a push): each candidate's pairs are indexed (CSR), and a sweep takes its pairs in pair order from a heap,
// so that a pair ahead of the sweep joins it when one of its balls changes and a pair behind joins the next
// sweep, as in a full Gauss-Seidel sweep.
import { appendCollision } from '../events.js'
import type { BallWorld } from '../world/createWorld.js'
import type { FixedContactState } from '../world/fixedState.js'

/** F.pairHit: bit 0, the pair's contact was reported this tick; from PAIR_VISIT_SHIFT up, its impulses this tick (up to RESTITUTION_VISITS) */
export const PAIR_REPORTED = 1
export const PAIR_VISIT_SHIFT = 1

/**
 * The velocity solve's numbers (src/contacts/fixedSolve.ts and the rules it calls), in slots rather than
 * arguments: the tick's time, the restitution, the settle speed, the contact tick's key (set once a solve),
 * and a pair's approach, inverse masses, share of restitution and impulse. A double passed to (or returned
 * from) a call V8 does not inline is boxed, and which of these calls it inlines changes with the process: up
 * to 9 bytes a ball-step on the gas.
 */
export const solveSlots = new Float64Array(10)
export const S_T = 0
export const S_E = 1
export const S_SETTLE = 2
export const S_APPROACH = 3
export const S_IMA = 4
export const S_IMB = 5
export const S_SEPARATE = 6
export const S_CLOCK = 7
export const S_J = 8
/** config.CONTACT_SPEED_LIMIT (set once a solve) */
export const S_LIMIT = 9

/**
 * Pair p of candidates a and b, met at solveSlots' approach with its impulse: its first meeting of the tick at
 * the settle speed or above is a 'collision' event at the tick's time, the pair reported in F.pairHit.
 */
export function reportPair(w: BallWorld, F: FixedContactState, p: number, a: number, b: number): void {
  const approach = solveSlots[S_APPROACH]!
  if ((F.pairHit[p]! & PAIR_REPORTED) !== 0 || !(approach >= solveSlots[S_SETTLE]!)) return
  F.pairHit[p] = F.pairHit[p]! | PAIR_REPORTED
  F.contacts++
  const ia = F.id[a]!
  const ib = F.id[b]!
  const ev = w.events
  const i = appendCollision(ev, ia < ib ? ia : ib, ia < ib ? ib : ia)
  ev.time[i] = solveSlots[S_T]!
  ev.speed[i] = approach
  ev.impulse[i] = solveSlots[S_J]!
}

/**
 * Normal of pair p (a→b) into nrm.x, nrm.y, and the gap into nrm.gap (negative: overlap). Written, not
 * returned: a double returned from a call V8 does not inline is boxed, a heap number a pair a sweep.
 */
export const nrm = { x: 1, y: 0, gap: 0.5 }
export function normal(F: FixedContactState, a: number, b: number): void {
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
  nrm.gap = d - F.r[a]! - F.r[b]!
}

/** 1 + a millionth: clear of normal()'s rounding (a few ulps) by orders of magnitude */
const APART = 1 + 1e-6

/**
 * Whether candidates a and b are clearly apart: their centres further than their radii's sum by more than a
 * millionth of it, so that normal() would find them not overlapping (gap ≥ 0) whatever its rounding. The
 * projection's sweeps pass such a pair by without the square root and the divisions (most of a crowd's pairs).
 */
export function apart(F: FixedContactState, a: number, b: number): boolean {
  const dx = F.x[b]! - F.x[a]!
  const dy = F.y[b]! - F.y[a]!
  const s = (F.r[a]! + F.r[b]!) * APART
  return dx * dx + dy * dy > s * s
}

/**
 * The swept test on straight lines: whether two balls whose radii add up to S, the second at (dx, dy) from
 * the first and moving at (ux, uy) relative to it, touch now or will within `span`. Leaves in `touch` the
 * squared gap term c (≤ 0: touching or overlapping now) and, when c > 0 and they meet, the time of the first
 * touch (slots, not a returned double, which V8 boxes when the call is not inlined).
 */
export function swept(dx: number, dy: number, ux: number, uy: number, S: number, span: number): boolean {
  const c = dx * dx + dy * dy - S * S
  touch.c = c
  if (c <= 0) return true
  const half = dx * ux + dy * uy
  if (half >= 0) return false
  const disc = half * half - (ux * ux + uy * uy) * c
  if (disc < 0) return false
  // first root of |d + u·τ| = S, in the form that keeps its digits when the pair barely approaches
  const tau = c / (-half + Math.sqrt(disc))
  touch.tau = tau
  return tau <= span
}

/** swept's results */
export const touch = { c: 0, tau: 0 }

/**
 * True when candidates a and b touch now or will within the tick on straight lines at their present
 * velocities (the swept test); the contact normal, a→b at that first touch, is left in nrm.
 */
export function meetsWithinTick(F: FixedContactState, a: number, b: number): boolean {
  const dx = F.x[b]! - F.x[a]!
  const dy = F.y[b]! - F.y[a]!
  const ux = F.vx[b]! - F.vx[a]!
  const uy = F.vy[b]! - F.vy[a]!
  if (!swept(dx, dy, ux, uy, F.r[a]! + F.r[b]!, F.tick)) return false
  if (touch.c <= 0) {
    if (touch.c < 0) F.overlap = true
    normal(F, a, b)
    return true
  }
  const tau = touch.tau
  // by its own length, not S: d + u·τ is the difference of two lengths of up to a tick's travel, and over S
  // it is a unit vector only to about travel / S ulps (a ball of radius 0.07 at 3e4 px/s striking one at
  // rest left the pair 1.4e-9 of its kinetic energy richer)
  const mx = dx + ux * tau
  const my = dy + uy * tau
  const m = Math.sqrt(mx * mx + my * my)
  if (!(m > 0)) {
    normal(F, a, b)
    return true
  }
  nrm.x = mx / m
  nrm.y = my / m
  return true
}

/** Each candidate's pairs (CSR: F.adjStart, F.adjPairs). */
export function buildAdjacency(F: FixedContactState): void {
  const pairs = F.pairCount
  const adjStart = F.adjStart
  const adjPairs = F.adjPairs
  adjStart.fill(0, 0, F.n + 1)
  for (let p = 0; p < pairs; p++) {
    adjStart[F.pairA[p]! + 1]!++
    adjStart[F.pairB[p]! + 1]!++
  }
  for (let i = 0; i < F.n; i++) adjStart[i + 1]! += adjStart[i]!
  const cursor = F.next // free after the pairing: fill cursors
  for (let i = 0; i < F.n; i++) cursor[i] = adjStart[i]!
  for (let p = 0; p < pairs; p++) {
    adjPairs[cursor[F.pairA[p]!]!++] = p
    adjPairs[cursor[F.pairB[p]!]!++] = p
  }
}

/**
 * Queues the pairs of candidate i, whose velocity or position changed while the pair with key `key` was met:
 * a pair ahead in this sweep joins it (its key's bit in F.dueKeys), one behind (or this one) the next sweep's
 * list (F.active, F.activeCount). Returns the sweep's new count of pairs due.
 */
export function activate(F: FixedContactState, i: number, key: number, back: boolean, stamp: number, size: number): number {
  const pairs = F.pairCount
  const due = F.dueKeys
  for (let q = F.adjStart[i]!, e = F.adjStart[i + 1]!; q < e; q++) {
    const r = F.adjPairs[q]!
    const kr = back ? pairs - 1 - r : r
    if (kr > key) {
      if (F.pairStamp[r] === stamp) continue
      F.pairStamp[r] = stamp
      due[kr >> 5] = due[kr >> 5]! | (1 << (kr & 31))
      size++
    } else if (F.nextStamp[r] !== stamp) {
      F.nextStamp[r] = stamp
      F.active[F.activeCount++] = r
    }
  }
  return size
}

/** the word of F.dueKeys the sweep has reached (scratch: one projection at a time) */
let dueWord = 0

/**
 * Starts a sweep over the pairs listed in F.active (for the next sweep): stamps them and marks their keys
 * due (pair order, reversed for a backward sweep); empties the list. Returns the count of pairs due. The
 * sweep takes them by nextDue in key order, as a heap of the keys gave them (the same bits; a binary heap's
 * pops were a twentieth of a pumped crowd's stepping).
 */
export function startSweep(F: FixedContactState, back: boolean, stamp: number): number {
  const pairs = F.pairCount
  const due = F.dueKeys
  // a sweep its budget cut short left keys due
  due.fill(0, 0, (pairs >> 5) + 1)
  dueWord = 0
  let size = 0
  for (let k = 0; k < F.activeCount; k++) {
    const p = F.active[k]!
    F.pairStamp[p] = stamp
    const key = back ? pairs - 1 - p : p
    due[key >> 5] = due[key >> 5]! | (1 << (key & 31))
    size++
  }
  F.activeCount = 0
  return size
}

/**
 * The least key due in the sweep, taken off (there is one: the sweep's count of pairs due is above 0). Keys
 * join a sweep only ahead of the one it has reached (activate), so the search goes on from the word it
 * reached.
 */
export function nextDue(F: FixedContactState): number {
  const due = F.dueKeys
  let w = dueWord
  while (due[w] === 0) w++
  dueWord = w
  const bits = due[w]!
  const low = bits & -bits
  due[w] = bits ^ low
  return (w << 5) + 31 - Math.clz32(low)
}

/** A fresh stamp for the sweeps' marks (the marks are cleared when the stamps wrap). */
export function nextStamp(F: FixedContactState): number {
  if (F.stamp === 0xffffffff) {
    F.pairStamp.fill(0)
    F.nextStamp.fill(0)
    F.ballStamp.fill(0)
    F.stamp = 0
  }
  return ++F.stamp
}

