// Fixed-tick contacts: a ball the velocity solve made faster than it was when the tick's pairs were found
// (a struck ball at rest, the last ball of a row) can now reach balls it was not paired with, and would
// move into them before the next tick. After each solve round, every such ball's reach is widened to its
// new speed and it is paired again: with the tick's candidates in the ordering grid's cells within its new
// reach (src/contacts/fixedOrder.ts; found through the sweep order, fixedSweep.ts, and packed if they were
// not), with the big ones, and with the resting balls now in its reach (they join the candidates); a ball
// far faster than its size only along its path (src/contacts/fixedCapsule.ts). The solve then runs again
// over all pairs. At most MAX_WIDEN_ROUNDS rounds a tick (src/config/tolerances.ts):
// a chain longer than that is caught at the next tick, by the projection; up to MAX_PASS_ROUNDS while a
// sped-up ball could pass through a ball within the tick, and MAX_CHAIN_ROUNDS along a row
// (systems/fixedContacts.ts).
import { PROJECTION_SLOP, TOUCH_GAP } from '../config/tolerances.js'
import type { BallWorld } from '../world/createWorld.js'
import { pushListed, pushPair, reserveCandidates, reserveSort, type FixedContactState } from '../world/fixedState.js'
import { box, boxRange, gridBox } from './fixedDense.js'
import { listNearWall, markWall, walls } from './fixedGrid.js'
import { seed, seedAlong, seedResting } from './fixedSeed.js'
import { sortIdRange } from '../world/idLists.js'
import { beyondBox, bounds, circle, coverBounds, covers, extendAlong, hasCapsule, madeNow, setTarget, holderList, holdersNow, meetsCircle, nextRound, roundReach, widenAlong, withinCapsule } from './fixedCapsule.js'
import { boundsBox, cutCapsule } from './fixedCut.js'
import { roundCandidates, roundList } from './fixedRounds.js'
import { enterWidened, foundList, holdersIn, joinedFree, joinedList, pairedBefore, pairedBeforeUnpacked } from './fixedNear.js'
import { orderCol, orderRow, unpackedJoin } from './fixedOrder.js'
import { QR, QX, QY, queried, queryBox } from './fixedSweep.js'

/** Widens the reach of the candidates the last round sped up and pairs them again; false when none did. */
export function widenReach(w: BallWorld, F: FixedContactState): boolean {
  nextRound(F.x.length)
  widenHits(F)
  if (F.widenedCount === 0) return false
  // through a slot, as the calls below read it (V8 boxes a double passed to a call it does not inline)
  roundReach[0] = Math.max(F.cell / 2, roundReach[2]!)
  const smallReach = roundReach[0]!
  const restFrom = F.n
  if (F.dense === 1) {
    for (let k = 0; k < F.widenedCount; k++) {
      const g = F.widened[k]!
      if (madeNow(g)) cutCapsule(w, F, g, 0, 0, restFrom)
    }
    for (let k = 0; k < F.widenedCount; k++) {
      const g = F.widened[k]!
      if (hasCapsule(g)) {
        pairNear(F, g, 0, 0, restFrom)
        pushPartners(F, g)
      } else {
        boxRange[0] = F.wide[g]! + smallReach
        pairInGrid(F, g)
        for (let m = 0; m < F.bigCount; m++) consider(F, g, F.big[m]!)
        pairJoined(F, g, restFrom)
      }
      seedFrom(w, F, g)
    }
    addResting(w, F, restFrom)
  } else widenSwept(w, F)
  pairHolders(F)
  for (let k = 0; k < F.widenedCount; k++) {
    const g = F.widened[k]!
    F.reach[g] = F.wide[g]!
    F.grown[g] = 0
    if (hasCapsule(g)) markSwept(F, g)
    else markWall(F, g)
  }
  enterWidened(F)
  return true
}

/** The resting balls not yet candidates (the gather's seen stamps skip those that are) that widened g now reaches. */
function seedFrom(w: BallWorld, F: FixedContactState, g: number): void {
  if (hasCapsule(g)) {
    seedAlong(w, F, g)
    return
  }
  seed[0] = F.x[g]!
  seed[1] = F.y[g]!
  seed[2] = F.wide[g]!
  seedResting(w, F)
}

/** A widened candidate's partners with a capsule (scratch, one widening at a time), listed by ball id. */
let partners: Uint32Array = new Uint32Array(64)
let partnerCount = 0
/**
 * Widened candidate g, which has a capsule (src/contacts/fixedCapsule.ts): into partners, the candidates
 * before `upTo` that what it covers now meets and did not before. Looked up where they can be: the small
 * ones of the tick's gather in the dense grid's cells of its cover (dense ticks; on sweep ticks
 * gridPartners listed them, F.pe2[peFrom..peTo)), the big ones, those the widening added, and the
 * balls with a capsule (a capsule reaches far from its ball: those only through their list, with a widened
 * one from the lower id).
 */
function pairNear(F: FixedContactState, g: number, peFrom: number, peTo: number, upTo: number): void {
  partnerCount = 0
  if (F.dense === 1) {
    coverBounds(F, g, roundReach[0]!)
    if (boundsBox(F)) {
      for (let gy = box[2]!; gy <= box[3]!; gy++) {
        for (let q = F.start[gy * F.cols + box[0]!]!, e = F.start[gy * F.cols + box[1]! + 1]!; q < e; q++) offer(F, g, F.si[q]!)
      }
    }
  } else {
    for (let t = peFrom; t < peTo; t++) offer(F, g, F.packAt[F.pe2[t]!]!)
  }
  for (let m = 0; m < F.bigCount; m++) offer(F, g, F.big[m]!)
  // the resting balls the rounds added and those with a capsule, where they can be (fixedNear.ts)
  for (let k = 0, free = joinedFree(F, upTo), jl = joinedList(); k < free; k++) offer(F, g, jl[k]!)
  setTarget(F, g)
  const near = holdersIn(F)
  const list = near < 0 ? holderList() : foundList()
  for (let h = 0, count = near < 0 ? holdersNow() : near; h < count; h++) {
    const j = list[h]!
    if (j === g || j >= upTo || beyondBox(F, j)) continue
    const grownJ = F.grown[j] === 1
    if (grownJ && F.id[j]! < F.id[g]!) continue
    if ((!covers(F, g, false, j, false) || !pairedBefore(F, g, j)) && covers(F, g, true, j, grownJ)) partners = pushListed(partners, partnerCount++, j)
  }
}

/** Candidate j, without a capsule, into g's partners if what g covers now meets it and did not before. */
function offer(F: FixedContactState, g: number, j: number): void {
  if (j === g || hasCapsule(j)) return
  const grownJ = F.grown[j] === 1
  // listed already (most of those near it: a circle test) first
  if ((!covers(F, g, false, j, false) || !pairedBefore(F, g, j)) && covers(F, g, true, j, grownJ)) partners = pushListed(partners, partnerCount++, j)
}

/** Pairs g with its partners in the order of their ball ids (the same whichever broadphase found them). */
function pushPartners(F: FixedContactState, g: number): void {
  const n = partnerCount
  // heapsort by id: no scratch beyond the list
  for (let i = (n >> 1) - 1; i >= 0; i--) siftDown(F, i, n)
  for (let end = n - 1; end > 0; end--) {
    const top = partners[0]!
    partners[0] = partners[end]!
    partners[end] = top
    siftDown(F, 0, end)
  }
  for (let k = 0; k < n; k++) {
    const j = partners[k]!
    pushPair(F, g < j ? g : j, g < j ? j : g)
  }
  partnerCount = 0
}

function siftDown(F: FixedContactState, i: number, n: number): void {
  for (;;) {
    let m = i
    const a = 2 * i + 1
    const b = a + 1
    if (a < n && F.id[partners[a]!]! > F.id[partners[m]!]!) m = a
    if (b < n && F.id[partners[b]!]! > F.id[partners[m]!]!) m = b
    if (m === i) return
    const t = partners[i]!
    partners[i] = partners[m]!
    partners[m] = t
    i = m
  }
}

/**
 * Each widened candidate without a capsule against the candidates with one that were not widened this
 * round (those widened find their partners themselves, pairNear).
 */
function pairHolders(F: FixedContactState): void {
  const count = holdersNow()
  if (count === 0) return
  const list = holderList()
  for (let k = 0; k < F.widenedCount; k++) {
    const g = F.widened[k]!
    if (hasCapsule(g)) continue
    setTarget(F, g)
    for (let h = 0; h < count; h++) {
      const c = list[h]!
      if (F.grown[c] === 1 || beyondBox(F, c)) continue
      if (covers(F, g, false, c, false) || !covers(F, g, true, c, false)) continue
      pushPair(F, g < c ? g : c, g < c ? c : g)
    }
  }
}

/** A candidate with a capsule is listed near the walls when the box of its sweep crosses one. */
function markSwept(F: FixedContactState, g: number): void {
  coverBounds(F, g, 0)
  if (bounds[0]! > walls.minX && bounds[1]! < walls.maxX && bounds[2]! > walls.minY && bounds[3]! < walls.maxY) return
  listNearWall(F, g)
}

/** Lists the candidates the last round sped up beyond their reach (F.widened, with F.wide, F.grown); the widest new reach into roundReach[1] (and [2]). */
function widenHits(F: FixedContactState): void {
  const tick = F.tick
  F.widenedCount = 0
  let widest = 0
  // those that may have changed since the last round (src/contacts/fixedRounds.ts), else every one changed
  const listed = roundCandidates(F, true)
  const list = listed < 0 ? F.hit : roundList()
  const count = listed < 0 ? F.hitCount : listed
  for (let h = 0; h < count; h++) {
    const i = list[h]!
    const vx = F.vx[i]!
    const vy = F.vy[i]!
    let wide = F.r[i]! + Math.sqrt(vx * vx + vy * vy) * tick + TOUCH_GAP
    // wider by no more than the projection's slop: at worst it moves that far into a neighbour, which the
    // next tick's projection takes out
    if (!(wide > F.reach[i]! + PROJECTION_SLOP) || withinCapsule(F, i)) continue
    // far beyond its size: along its path only (src/contacts/fixedCapsule.ts); going on past where its
    // capsule was cut (src/contacts/fixedCut.ts): along the rest of its path
    if (extendAlong(F, i) || widenAlong(F, i)) wide = F.reach[i]!
    F.wide[i] = wide
    F.grown[i] = 1
    F.widened[F.widenedCount++] = i
    if (wide > widest) widest = wide
  }
  roundReach[1] = widest
  if (widest > roundReach[2]!) roundReach[2] = widest
}

/**
 * The widening on a sweep tick (only the balls that touch are packed): each widened candidate's partners
 * in the ordering grid's cells within its reach (packed first if they were not), by place; the big ones;
 * the resting balls now in its reach.
 */
function widenSwept(w: BallWorld, F: FixedContactState): void {
  const widest = roundReach[1]!
  if (widest > F.reachMax) F.reachMax = widest
  gridPartners(w, F)
  reserveSort(F, F.peCount)
  const restFrom = F.n
  // every capsule cut before any is paired (pairNear tests the capsules of the others)
  for (let k = 0, t = 0; k < F.widenedCount; k++) {
    const from = t
    for (; t < F.peCount && F.pe1[t] === k; t++);
    const g = F.widened[k]!
    if (madeNow(g)) cutCapsule(w, F, g, from, t, restFrom)
  }
  for (let k = 0, t = 0; k < F.widenedCount; k++) {
    const g = F.widened[k]!
    const holder = hasCapsule(g)
    if (holder) {
      // with a capsule: those gridPartners listed (packed now) and the rest where they can be, by id
      const from = t
      for (; t < F.peCount && F.pe1[t] === k; t++);
      pairNear(F, g, from, t, restFrom)
      pushPartners(F, g)
      seedFrom(w, F, g)
      continue
    }
    // its partners in the grid's cells, by place (cell, then index)
    const from = t
    for (; t < F.peCount && F.pe1[t] === k; t++) {
      const j = F.packAt[F.pe2[t]!]!
      F.key1[t - from] = (orderRow(F, F.y[j]!) * F.cols + orderCol(F, F.x[j]!)) * F.n + j
    }
    for (let a = 1; a < t - from; a++) {
      const v = F.key1[a]!
      let b = a - 1
      while (b >= 0 && F.key1[b]! > v) {
        F.key1[b + 1] = F.key1[b]!
        b--
      }
      F.key1[b + 1] = v
    }
    for (let a = 0; a < t - from; a++) {
      const j = F.key1[a]! % F.n
      pushPair(F, g < j ? g : j, g < j ? j : g)
    }
    for (let m = 0; m < F.bigCount; m++) consider(F, g, F.big[m]!)
    pairJoined(F, g, restFrom)
    seedFrom(w, F, g)
  }
  addResting(w, F, restFrom)
}

/**
 * For each widened candidate (k-th), the gather's small candidates (reach at most half the ordering cell)
 * in the ordering grid's cells within wide + smallReach of it that it now reaches and did not before, into
 * F.pe1 (k) and F.pe2 (id), in widened order; those not packed are packed first.
 */
function gridPartners(w: BallWorld, F: FixedContactState): void {
  const smallReach = roundReach[0]!
  const B = w.Ball
  const half = F.cell / 2
  const st = F.markStamp
  let joining = 0
  F.peCount = 0
  for (let k = 0; k < F.widenedCount; k++) {
    const g = F.widened[k]!
    const x = F.x[g]!
    const y = F.y[g]!
    // with a capsule: the small balls in the box of its cover, for pairNear
    const holder = hasCapsule(g)
    if (holder) {
      coverBounds(F, g, smallReach)
      if (!boundsBox(F)) continue
      coverBounds(F, g, F.reachMax)
      queried[QX] = (bounds[0]! + bounds[1]!) / 2
      queried[QY] = (bounds[2]! + bounds[3]!) / 2
      queried[QR] = Math.max(bounds[1]! - bounds[0]!, bounds[3]! - bounds[2]!) / 2
    } else {
      // none of the ordering grid's cells within wide + smallReach of it: nothing new to reach
      boxRange[0] = F.wide[g]! + smallReach
      if (!gridBox(F, g)) continue
      // every candidate it can reach is within its reach plus the widest reach of any
      queried[QX] = x
      queried[QY] = y
      queried[QR] = F.wide[g]! + F.reachMax
    }
    queryBox(F)
    for (let q = 0; q < F.foundCount; q++) {
      const e = F.found[q]!
      if (F.reachOf[e]! > half) continue
      const ex = B.x[e]!
      const ey = B.y[e]!
      const gx = orderCol(F, ex)
      const gy = orderRow(F, ey)
      if (gx < box[0]! || gx > box[1]! || gy < box[2]! || gy > box[3]!) continue
      const packed = F.packMark[e] === st && F.packAt[e]! >= 0
      const j = packed ? F.packAt[e]! : -1
      let reached: boolean
      if (holder) {
        // packed: listed for pairNear, which tests it; not packed: listed (and packed first) if it is reached
        if (packed) reached = j !== g && !hasCapsule(j)
        else {
          circle[0] = ex
          circle[1] = ey
          circle[2] = F.reachOf[e]!
          reached = meetsCircle(F, g, true) && (!meetsCircle(F, g, false) || !pairedBeforeUnpacked(F, g, F.reachOf[e]!, B.radius[e]!))
        }
      } else {
        if (packed && (j === g || (F.grown[j] === 1 && j < g) || hasCapsule(j))) continue
        const dx = ex - x
        const dy = ey - y
        const d2 = dx * dx + dy * dy
        const rj = packed ? F.reach[j]! : F.reachOf[e]!
        const now = F.wide[g]! + (packed && F.grown[j] === 1 ? F.wide[j]! : rj)
        const before = F.reach[g]! + rj
        reached = d2 < now * now && (d2 >= before * before || !(packed ? pairedBefore(F, g, j) : pairedBeforeUnpacked(F, g, rj, B.radius[e]!)))
      }
      if (!reached) continue
      F.pe1 = pushListed(F.pe1, F.peCount, k)
      F.pe2 = pushListed(F.pe2, F.peCount++, e)
      if (F.packMark[e] !== st) {
        F.packMark[e] = st
        F.packAt[e] = -1
        F.fresh = pushListed(F.fresh, joining++, e)
      }
    }
  }
  if (joining > 0) unpackedJoin(w, F, F.fresh, joining)
}

/** Widened g against the resting balls earlier rounds added (F.gathered to `upTo`; in neither grid), in index order (src/contacts/fixedNear.ts). */
function pairJoined(F: FixedContactState, g: number, upTo: number): void {
  for (let k = 0, free = joinedFree(F, upTo), jl = joinedList(); k < free; k++) consider(F, g, jl[k]!)
}

/** Dense ticks (src/contacts/fixedDense.ts): pairs widened candidate g with the small candidates of the grid cells within boxRange[0] of it. */
function pairInGrid(F: FixedContactState, g: number): void {
  if (!gridBox(F, g)) return
  for (let gy = box[2]!; gy <= box[3]!; gy++) {
    for (let q = F.start[gy * F.cols + box[0]!]!, e = F.start[gy * F.cols + box[1]! + 1]!; q < e; q++) consider(F, g, F.si[q]!)
  }
}

/**
 * Pairs g with j when they can touch within the tick at their new reaches but could not at the reaches
 * they were paired with (so no pair is listed twice); a pair of two widened candidates is listed from the
 * lower index.
 */
function consider(F: FixedContactState, g: number, j: number): void {
  if (j === g || (F.grown[j] === 1 && j < g) || hasCapsule(j)) return
  const dx = F.x[j]! - F.x[g]!
  const dy = F.y[j]! - F.y[g]!
  const d2 = dx * dx + dy * dy
  const now = F.wide[g]! + (F.grown[j] === 1 ? F.wide[j]! : F.reach[j]!)
  const before = F.reach[g]! + F.reach[j]!
  if (d2 >= now * now || (d2 < before * before && pairedBefore(F, g, j))) return
  pushPair(F, g < j ? g : j, g < j ? j : g)
}

/**
 * Gives the resting balls that joined (ids from index `from`) their candidate data and pairs them with the
 * widened candidates: in id order, not the resting grid's (whose chains' order depends on where a step split
 * the tick: docs/decisions.md §12).
 */
function addResting(w: BallWorld, F: FixedContactState, from: number): void {
  if (F.n === from) return
  sortIdRange(F.id, from, F.n)
  reserveCandidates(F, F.n)
  for (let k = from; k < F.n; k++) {
    setRestingCandidate(w, F, k)
    for (let m = 0; m < F.widenedCount; m++) {
      const g = F.widened[m]!
      if (hasCapsule(g)) {
        circle[0] = F.x[k]!
        circle[1] = F.y[k]!
        circle[2] = F.reach[k]!
        if (meetsCircle(F, g, true)) pushPair(F, g < k ? g : k, g < k ? k : g)
        continue
      }
      const dx = F.x[k]! - F.x[g]!
      const dy = F.y[k]! - F.y[g]!
      const s = F.wide[g]! + F.reach[k]!
      if (dx * dx + dy * dy < s * s) pushPair(F, g < k ? g : k, g < k ? k : g)
    }
  }
}

/** Candidate k, a resting ball joining the tick's candidates (room reserved): its data from the stores, at rest, near-wall listing. */
export function setRestingCandidate(w: BallWorld, F: FixedContactState, k: number): void {
  const B = w.Ball
  const eid = F.id[k]!
  F.x[k] = B.x[eid]!
  F.y[k] = B.y[eid]!
  F.r[k] = B.radius[eid]!
  F.vx[k] = 0
  F.vy[k] = 0
  F.im[k] = 1 / F.mass[eid]!
  F.reach[k] = B.radius[eid]! + TOUCH_GAP
  F.changed[k] = 0
  F.grown[k] = 0
  markWall(F, k)
}
