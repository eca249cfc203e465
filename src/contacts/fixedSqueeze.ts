// The fixed-tick method's velocity solve (src/contacts/fixedSolve.ts): a light ball squeezed between two
// heavier ones, the two contacts solved together. A ball SQUEEZE_MASS_RATIO times lighter than its partner
// (or more), touching it and a second ball as heavy (both within PROJECTION_SLOP), that the pair's impulse
// drives into that second ball within the tick while the two heavy ones close on each other, would
// otherwise be turned by one, then back by the other, sweep after sweep, each heavy ball taking a share of
// the push as small as the mass ratio, and the heavy ones went on closing while the projection held their
// positions. Solved together, the two contacts take impulses j₁, j₂ > 0 such that each leaves at its
// restitution's share of its approach (inelastic past its visits, as the sweeps give a pair), as two heavy
// balls meeting through a light one do: they part at e = 1 and stop at e = 0 (head on; at an angle the
// light ball is squeezed out sideways). Each impulse is a two-body one, so momentum is kept; the block is
// applied only when kinetic energy does not rise, else the plain impulse and the sweeps take the pair, as
// before. A light ball crossing between heavy ones without touching both (a pumped crowd) is not a squeeze:
// with the block taken from within a tick's reach, the pumped crowd of tests/systems/fixedHalve.test.ts kept
// 0.36 of its energy (above 0.97 without), and with the material's restitution in place of the visits' the
// long adversarial run's slowest step took 11.9 s against 3.4 s. A heavy ball at rest takes part by its own
// mass; where the block would leave it slower than BALL_SETTLE_SPEED it stays at rest, held like a wall as
// the sweeps hold it (its inverse mass 0), and the block is solved again so: the light ball's push alone
// leaves such a ball held at every impulse, and a heavy ball carrying a light one into it went on at its
// full speed, shoving both ahead of it through the projection while they stayed at rest. Two or more light
// balls in a row, touching one another, each within 60° of the line from the one before (up to MAX_CHAIN),
// between the two heavy ones are taken as one body: its mass their sum, its velocity their centre of
// mass's, and each of them takes that body's change of velocity (so their motion within the row, and its
// kinetic energy, are left as they were); before, the sweeps turned the row's balls between the two, and
// the heavy ones went on closing while the projection held them apart. A block that would pump a ball past
// CONTACT_SPEED_LIMIT takes less of the two contacts' restitution, down to none (docs/decisions.md §8).
import { RESTITUTION_VISITS, SQUEEZE_MASS_RATIO } from '../config/tolerances.js'
import { B_CROSS, B_IMH, B_IML, B_IMO, B_R1, B_R2, B_SIGMA_C, B_VX, B_VY, blk, closesFaster, closing, holds, impulses, touching } from './fixedBlock.js'
import { reserveSweeps, type FixedContactState } from '../world/fixedState.js'
import { spent } from './fixedCount.js'
import { largestShare, pastLimit, share, shareRows } from '../motion/speedLimit.js'
import { buildAdjacency, meetsWithinTick, nrm, PAIR_VISIT_SHIFT, S_APPROACH, S_E, S_LIMIT, S_SEPARATE, S_SETTLE, solveSlots } from './fixedPairs.js'

/**
 * The last block's numbers (slots, not boxed doubles): j₁ of the pair, j₂ of the second, its approach before,
 * the second pair's normal, and 1 when the second pair took no restitution for its visits or count.
 */
export const squeeze = new Float64Array(9)
export const SQ_J1 = 0
export const SQ_J2 = 1
export const SQ_APPROACH = 2
const SQ_NX = 3
const SQ_NY = 4
export const SQ_BOUND = 5
/** the second heavy ball, and the light balls between the two (1: l alone; more: squeezeChain) */
export const SQ_OTHER = 6
export const SQ_CHAIN = 7
/** pairWithBall's input: the pair's own impulse j (a slot: a double passed to a call V8 does not inline is boxed) */
export const SQ_J = 8

/** Most light balls in a row between the two heavy ones that a block takes. */
const MAX_CHAIN = 8
/** The light balls of the last block, l first, in a row from l's partner to the second heavy ball (SQ_CHAIN of them). */
export const squeezeChain = new Int32Array(MAX_CHAIN)
/** How far a row may bend at each ball: the next ball within 60° of the line from the one before. */
const CHAIN_COS = 0.5

/** Squeezes solved as blocks since the process started (for tests). */
let solved = 0
export function squeezesSolved(): number {
  return solved
}

/** the solve call the pairs' adjacency (F.adjStart, F.adjPairs) was last built for: the first time a call asks */
let builtFor = -1

function adjacency(F: FixedContactState, call: number): void {
  if (builtFor === call) return
  builtFor = call
  // the projection's adjacency, free until it builds its own after the solve (src/contacts/fixedProject.ts)
  reserveSweeps(F, F.n, F.pairCount)
  buildAdjacency(F)
}

/**
 * Pair p (a, b), approaching along nrm, whose lighter ball `l` (a or b) touches a second ball
 * SQUEEZE_MASS_RATIO times heavier than l or more, which the pair's impulse `j` would drive l into within
 * the tick while that ball and l's partner close on each other, or touches a row of light balls that ends
 * at such a ball (chainTo): the two end contacts solved together, the new velocities written to the heavy
 * balls and the light ones. Returns the second pair's index, with j₁, j₂, its approach, the second heavy
 * ball and the row's length in `squeeze`; -1, changing nothing, when there is no such ball or the block does not hold (an impulse not
 * above 0, or kinetic energy rising). `call` numbers the solve call (the pairs do not change within one).
 * A heavy ball at rest (l's partner or the second ball) that the block would leave slower than
 * BALL_SETTLE_SPEED is held like a wall: the block is solved again with its inverse mass 0.
 */
export function pairWithBall(F: FixedContactState, p: number, l: number, call: number): number {
  const j = squeeze[SQ_J]!
  const a = F.pairA[p]!
  const b = F.pairB[p]!
  const h = l === a ? b : a
  const sigma = l === a ? 1 : -1
  const n1x = nrm.x
  const n1y = nrm.y
  const iml = F.im[l]!
  const imh = F.im[h]!
  // l's velocity after the pair's impulse alone: the reach it is driven at
  const vlx = F.vx[l]!
  const vly = F.vy[l]!
  const tx = vlx - sigma * j * iml * n1x
  const ty = vly - sigma * j * iml * n1y
  // l touching its partner (within PROJECTION_SLOP): else no squeeze, and nothing more to look at
  if (!touching(F, l, h)) return -1
  adjacency(F, call)
  let q = -1
  let o = -1
  closing[1] = 0 // the fastest closing so far (closesFaster reads it)
  F.vx[l] = tx
  F.vy[l] = ty
  for (let k = F.adjStart[l]!, e = F.adjStart[l + 1]!; k < e; k++) {
    const r = F.adjPairs[k]!
    if (r === p) continue
    const m = F.pairA[r] === l ? F.pairB[r]! : F.pairA[r]!
    if (m === h || SQUEEZE_MASS_RATIO * F.im[m]! > iml) continue
    // l touching both (a squeeze, not a light ball crossing between them), the two heavy ones closing on
    // each other along the line of their centres, and l driven into m within the tick
    if (!touching(F, l, m) || !closesFaster(F, h, m) || !meetsWithinTick(F, l, m)) continue
    closing[1] = closing[0]!
    q = r
    o = m
    squeeze[SQ_NX] = nrm.x
    squeeze[SQ_NY] = nrm.y
  }
  F.vx[l] = vlx
  F.vy[l] = vly
  nrm.x = n1x
  nrm.y = n1y
  // l alone between the two, or a row of light balls touching one another from l to the second heavy ball
  // (taken as one body: a push crosses such a row at once, as the light balls between two heavy ones)
  let count = 1
  squeezeChain[0] = l
  if (q < 0) {
    q = chainTo(F, l, h)
    if (q < 0) return -1
    // whole numbers as V8 holds them (`| 0`: a chain's length and a ball's index): read from the slots as
    // doubles, they were boxed where passed to a call V8 does not inline (pastLimit below)
    o = squeeze[SQ_OTHER]! | 0
    count = squeeze[SQ_CHAIN]! | 0
  }
  // the light side as one body: its inverse mass and velocity (l's own when alone)
  let imv = iml
  let vvx = vlx
  let vvy = vly
  let w1 = solveSlots[S_APPROACH]!
  let s1 = solveSlots[S_SEPARATE]!
  if (count > 1) {
    let mass = 0
    let px = 0
    let py = 0
    for (let k = 0; k < count; k++) {
      const c = squeezeChain[k]!
      const m = 1 / F.im[c]!
      mass += m
      px += m * F.vx[c]!
      py += m * F.vy[c]!
    }
    imv = 1 / mass
    vvx = px / mass
    vvy = py / mass
    // the pair's approach and separation for the row's velocity (the separation the same share of it)
    const share = s1 / w1
    w1 = sigma * ((vvx - F.vx[h]!) * n1x + (vvy - F.vy[h]!) * n1y)
    if (!(w1 > 0)) return -1
    s1 = share * w1
  }
  // the second contact's normal, from the light side to o
  const n2x = squeeze[SQ_NX]!
  const n2y = squeeze[SQ_NY]!
  const imo = F.im[o]!
  const w2 = (vvx - F.vx[o]!) * n2x + (vvy - F.vy[o]!) * n2y
  const last = squeezeChain[count - 1]!
  // the second pair's restitution as the solve gives a pair's: none past its visits, or for a light ball past its count
  const bound = F.pairHit[q]! >> PAIR_VISIT_SHIFT >= RESTITUTION_VISITS || spent(F, last, o)
  const s2 = w2 >= solveSlots[S_SETTLE]! && !bound ? solveSlots[S_E]! * w2 : 0
  const sigmaC = sigma * (n1x * n2x + n1y * n2y)
  const cross = n1x * n2y - n1y * n2x
  // a heavy ball at rest that the block would leave slower than BALL_SETTLE_SPEED stays at rest
  // (applyChanges): it holds like a wall, as in the sweeps (its inverse mass taken as 0), and the block is
  // solved again so
  let imhUsed = imh
  let imoUsed = imo
  let j1 = 0
  let j2 = 0
  let hx = 0
  let hy = 0
  let lx = 0
  let ly = 0
  let ox = 0
  let oy = 0
  let mh = 0
  let ml = 0
  let mo = 0
  let before = 0
  // the share of the two contacts' restitution, and the stage: 0 the block, 1 again with a heavy ball held,
  // 2 again at none, 3 again at the largest share that keeps CONTACT_SPEED_LIMIT (below)
  let f = 1
  let stage = 0
  for (;;) {
    blk[B_IMH] = imhUsed
    blk[B_IML] = imv
    blk[B_IMO] = imoUsed
    blk[B_SIGMA_C] = sigmaC
    blk[B_CROSS] = cross
    blk[B_R1] = w1 + f * s1
    blk[B_R2] = w2 + f * s2
    if (!impulses(squeeze)) return -1
    j1 = squeeze[SQ_J1]!
    j2 = squeeze[SQ_J2]!
    // the three velocities after: h takes σ·j₁·n₁, l −σ·j₁·n₁ − j₂·n₂, o +j₂·n₂ (σ: +1 when l is the pair's a)
    hx = F.vx[h]! + sigma * j1 * imhUsed * n1x
    hy = F.vy[h]! + sigma * j1 * imhUsed * n1y
    lx = vvx - sigma * j1 * imv * n1x - j2 * imv * n2x
    ly = vvy - sigma * j1 * imv * n1y - j2 * imv * n2y
    ox = F.vx[o]! + j2 * imoUsed * n2x
    oy = F.vy[o]! + j2 * imoUsed * n2y
    if (stage === 0) {
      blk[B_VX] = hx
      blk[B_VY] = hy
      const heldH = holds(F, h)
      blk[B_VX] = ox
      blk[B_VY] = oy
      const heldO = holds(F, o)
      stage = 1
      if (heldH) imhUsed = 0
      if (heldO) imoUsed = 0
      if (heldH || heldO) continue
    }
    if (stage === 1) {
      // kinetic energy of the three bodies (a row's motion within itself is not changed: each of its balls
      // takes the row's change of velocity)
      mh = imhUsed > 0 ? 1 / imhUsed : 0
      ml = 1 / imv
      mo = imoUsed > 0 ? 1 / imoUsed : 0
      before = mh * (F.vx[h]! * F.vx[h]! + F.vy[h]! * F.vy[h]!) + ml * (vvx * vvx + vvy * vvy) + mo * (F.vx[o]! * F.vx[o]! + F.vy[o]! * F.vy[o]!)
      if (mh * (hx * hx + hy * hy) + ml * (lx * lx + ly * ly) + mo * (ox * ox + oy * oy) > before + 8 * Number.EPSILON * before) return -1
      // nor past CONTACT_SPEED_LIMIT: where a velocity component would go beyond it and beyond its size
      // before, the two contacts take the largest share of their restitution that keeps every one within,
      // down to none, as the plain impulse does (largestShare, src/motion/speedLimit.ts; each component is
      // linear in the share): the block again at none, then at that share
      if (!(s1 > 0 || s2 > 0)) break
      for (let k = 0; k < count + 2; k++) {
        // h, o, then the light side's balls (l alone takes lx, ly; a row's balls the row's change)
        const c = k === 0 ? h : k === 1 ? o : squeezeChain[k - 2]!
        const cx = F.vx[c]!
        const cy = F.vy[c]!
        shareRows[6 * k] = cx
        shareRows[6 * k + 1] = k === 0 ? hx : k === 1 ? ox : count === 1 ? lx : cx + (lx - vvx)
        shareRows[6 * k + 3] = cy
        shareRows[6 * k + 4] = k === 0 ? hy : k === 1 ? oy : count === 1 ? ly : cy + (ly - vvy)
      }
      share[1] = solveSlots[S_LIMIT]!
      if (!pastLimit(2 * (count + 2))) break
      f = 0
      stage = 2
      continue
    }
    if (stage === 3) break
    for (let k = 0; k < count + 2; k++) {
      const c = k < 2 ? 0 : squeezeChain[k - 2]!
      shareRows[6 * k + 2] = k === 0 ? hx : k === 1 ? ox : count === 1 ? lx : F.vx[c]! + (lx - vvx)
      shareRows[6 * k + 5] = k === 0 ? hy : k === 1 ? oy : count === 1 ? ly : F.vy[c]! + (ly - vvy)
    }
    largestShare(2 * (count + 2))
    if (share[0] === 0) break
    f = share[0]!
    stage = 3
  }
  if (stage > 1 && mh * (hx * hx + hy * hy) + ml * (lx * lx + ly * ly) + mo * (ox * ox + oy * oy) > before + 8 * Number.EPSILON * before) return -1
  F.vx[h] = hx
  F.vy[h] = hy
  if (count === 1) {
    F.vx[l] = lx
    F.vy[l] = ly
  } else {
    const dx = lx - vvx
    const dy = ly - vvy
    for (let k = 0; k < count; k++) {
      const c = squeezeChain[k]!
      F.vx[c] = F.vx[c]! + dx
      F.vy[c] = F.vy[c]! + dy
    }
  }
  F.vx[o] = ox
  F.vy[o] = oy
  squeeze[SQ_OTHER] = o
  squeeze[SQ_CHAIN] = count
  solved++
  squeeze[SQ_APPROACH] = w2
  squeeze[SQ_BOUND] = bound && w2 >= solveSlots[S_SETTLE]! ? 1 : 0
  return q
}

/**
 * From l (touching its partner h), a row of light balls touching one another, each within 60° of the line
 * from the one before, up to a ball SQUEEZE_MASS_RATIO times heavier than every one of them or more that
 * touches the last and closes on h along the line of their centres: the row into squeezeChain (l first),
 * its length into squeeze[SQ_CHAIN], that ball into squeeze[SQ_OTHER] and the normal from the last to it
 * into squeeze[SQ_NX], [SQ_NY]. Returns the index of the last pair, -1 when there is no such row (within
 * MAX_CHAIN balls). Every light ball is SQUEEZE_MASS_RATIO times lighter than h or more.
 */
function chainTo(F: FixedContactState, l: number, h: number): number {
  let prev = h
  let cur = l
  let count = 1
  // the row's heaviest ball: the second heavy ball must be that much heavier than each
  let imMin = F.im[l]!
  for (;;) {
    const dx = F.x[cur]! - F.x[prev]!
    const dy = F.y[cur]! - F.y[prev]!
    const dl = Math.sqrt(dx * dx + dy * dy)
    if (!(dl > 0)) return -1
    let next = -1
    let bestCos = CHAIN_COS
    let q = -1
    closing[1] = 0
    for (let k = F.adjStart[cur]!, e = F.adjStart[cur + 1]!; k < e; k++) {
      const r = F.adjPairs[k]!
      const m = F.pairA[r] === cur ? F.pairB[r]! : F.pairA[r]!
      if (m === prev || m === h || inChain(m, count) || !touching(F, cur, m)) continue
      const ex = F.x[m]! - F.x[cur]!
      const ey = F.y[m]! - F.y[cur]!
      const el = Math.sqrt(ex * ex + ey * ey)
      const cos = (ex * dx + ey * dy) / (el * dl)
      if (!(cos > CHAIN_COS)) continue
      if (SQUEEZE_MASS_RATIO * F.im[m]! <= imMin) {
        // a heavy ball: closing on h along the line of their centres
        if (closesFaster(F, h, m)) {
          closing[1] = closing[0]!
          q = r
          squeeze[SQ_OTHER] = m
          squeeze[SQ_NX] = ex / el
          squeeze[SQ_NY] = ey / el
        }
      } else if (SQUEEZE_MASS_RATIO * F.im[h]! <= F.im[m]! && cos > bestCos) {
        bestCos = cos
        next = m
      }
    }
    if (q >= 0 && count > 1) {
      squeeze[SQ_CHAIN] = count
      return q
    }
    if (next < 0 || count === MAX_CHAIN) return -1
    squeezeChain[count++] = next
    if (F.im[next]! < imMin) imMin = F.im[next]!
    prev = cur
    cur = next
  }
}

/** Whether candidate m is among the first `count` balls of squeezeChain. */
function inChain(m: number, count: number): boolean {
  for (let k = 0; k < count; k++) if (squeezeChain[k] === m) return true
  return false
}
