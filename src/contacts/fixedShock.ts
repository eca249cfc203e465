// Fixed-tick contacts: a row pressed into a closed wall is held by the wall (shock propagation). Gauss-Seidel
// sweeps (src/contacts/fixedSolve.ts) carry the wall's push back along a row one pair a sweep, and take a
// heavy ball's push down by about the mass ratio a sweep, so a heavy ball pressing a row into a wall was
// never stopped: the sweeps ran out with the row still closing, the projection held the positions to a
// fraction of a pixel, and the heavy ball went on pressing at nearly its full speed, tick after tick (a ball
// of mass 1e4 at 300 px/s into 16 touching balls at a wall: 297 px/s and 0.6 px deep after 0.3 s).
// So when half the sweeps are done without converging, the pairs that meet within the tick, touch, or took
// an impulse this tick join their balls into groups (resting candidates too: a ball lying at the wall is
// where a row is held). A group is held when its closing pairs close by more than PROJECTION_SLOP in all,
// the normals of all its pairs keep within 30° of one line (a row, not a pile), and one of its balls is pushed by its
// closing pairs into a closed wall within its reach, along the wall's normal (its anchor). With restitution
// below 1, a pile is held too where one of its closing pairs has a ball SQUEEZE_MASS_RATIO times heavier
// than the other: heavy balls pressing light ones into a corner pile were never stopped either (the long
// adversarial run at 59×: 76 of 166 rolling balls kept up to 3.3e4 px/s while the projection held them
// still, and their reach halved the tick 5 times, 1,797 ticks for a step of 0.25 s against 30); a pile of
// like balls is left to the sweeps, which settle it, and an elastic one too (held, a pumped elastic crowd
// lost two thirds of its energy where it keeps 0.97 of it, tests/systems/fixedHalve.test.ts). From the
// anchors, breadth first, each ball that meets one already reached meets it as if that one could not move:
// the wall first sends the anchor back with its restitution (the solve's own wall step), then each next ball
// leaves the one before with BALL_RESTITUTION (0 below BALL_SETTLE_SPEED) of their approach, its normal
// speed never raised. So no ball's kinetic energy rises (the wall takes the momentum), and a row stops
// closing in one pass over its pairs, whatever its length. The other half of the sweeps then take the new
// velocities to the balls around. Everything runs in the order of the pairs, which both broadphases give
// alike.
import { PROJECTION_SLOP, ROW_LINE_COS, SQUEEZE_MASS_RATIO, TOUCH_GAP } from '../config/tolerances.js'
import type { FixedContactState } from '../world/fixedState.js'
import type { BallWorld } from '../world/createWorld.js'
import { walls } from './fixedGrid.js'
import { meetsWithinTick, normal, nrm, reportPair, S_APPROACH, S_J, solveSlots } from './fixedPairs.js'
import { keepsLine, rootOf, unite } from './fixedUnion.js'
import { asBefore, PARTING, REFUSED } from './fixedStamps.js'

/** Union-find over the candidates; by root: the group's closing, whether it has an anchor, whether it bends, and its line */
let parent = new Int32Array(256)
let closes = new Float64Array(256)
let anchored = new Uint8Array(256)
let bent = new Uint8Array(256)
let heavy = new Uint8Array(256)
let lineX = new Float64Array(256)
let lineY = new Float64Array(256)
/** each candidate's push from its closing pairs (the sum of approach × normal, into it) */
let pushX = new Float64Array(256)
let pushY = new Float64Array(256)
/** each pair's approach (−1: its balls are not linked; 0: linked, not closing) and its normal */
let approachOf = new Float64Array(256)
let normalX = new Float64Array(256)
let normalY = new Float64Array(256)
/** the anchors of the current call: candidates whose anchorAt is anchorMark */
let anchorAt = new Uint32Array(256)
let anchorMark = 0
/** the linked pairs of the held groups by candidate (CSR), the breadth-first queue, and the candidates reached */
let start = new Int32Array(257)
let fill = new Int32Array(256)
let adj = new Int32Array(512)
let queue = new Int32Array(256)
let reached = new Uint8Array(256)
/** the candidates whose velocities the last holdRows changed */
let list = new Int32Array(256)
/** solve calls that held a row at a wall, over the process's life (for tests and benchmarks) */
let held = 0

function root(i: number): number {
  return rootOf(parent, i)
}

function reserve(n: number, pairs: number): void {
  if (parent.length < n) {
    const m = 2 * n
    parent = new Int32Array(m)
    closes = new Float64Array(m)
    anchored = new Uint8Array(m)
    bent = new Uint8Array(m)
    heavy = new Uint8Array(m)
    lineX = new Float64Array(m)
    lineY = new Float64Array(m)
    pushX = new Float64Array(m)
    pushY = new Float64Array(m)
    start = new Int32Array(m + 1)
    fill = new Int32Array(m)
    queue = new Int32Array(m)
    reached = new Uint8Array(m)
    anchorAt = new Uint32Array(m)
    anchorMark = 0
    list = new Int32Array(m)
  }
  if (approachOf.length < pairs) {
    approachOf = new Float64Array(2 * pairs)
    normalX = new Float64Array(2 * pairs)
    normalY = new Float64Array(2 * pairs)
  }
  if (adj.length < 2 * pairs) adj = new Int32Array(4 * pairs)
}

/**
 * Holds the rows pressed into closed walls of a solve that did not converge (see the top of this file;
 * the tick's time in solveSlots); `e` is the balls' restitution and `settle` BALL_SETTLE_SPEED; `wallBack` sends an anchor back from the
 * walls it moves into within the tick (the solve's own wall step, which keeps its account). Returns how many
 * other candidates' velocities changed, listed in heldBalls().
 */
export function holdRows(w: BallWorld, F: FixedContactState, e: number, settle: number, wallBack: (w: BallWorld, F: FixedContactState, i: number) => number): number {
  const n = F.n
  const pairs = F.pairCount
  // no candidate within reach of a closed wall: nothing to hold
  if (F.nearWallCount === 0) return 0
  reserve(n, pairs)
  for (let i = 0; i < n; i++) {
    parent[i] = i
    pushX[i] = 0
    pushY[i] = 0
  }
  let joined = 0
  for (let p = 0; p < pairs; p++) {
    const a = F.pairA[p]!
    const b = F.pairB[p]!
    approachOf[p] = -1
    // as the sweeps last found the pair, when neither ball has changed since (src/contacts/fixedStamps.ts):
    // refused, it does not meet; parting, it touches with the line of centres for its normal
    const was = asBefore(F, p)
    if (was === PARTING) normal(F, a, b)
    else if (was === REFUSED || !meetsWithinTick(F, a, b)) {
      // met this tick, or touching but for rounding, and not closing now: the row goes on through them
      if (F.pairHit[p]! < 2) {
        const dx = F.x[b]! - F.x[a]!
        const dy = F.y[b]! - F.y[a]!
        const s = F.r[a]! + F.r[b]! + TOUCH_GAP
        if (dx * dx + dy * dy > s * s) continue
      }
      normal(F, a, b)
    }
    const approach = -((F.vx[b]! - F.vx[a]!) * nrm.x + (F.vy[b]! - F.vy[a]!) * nrm.y)
    approachOf[p] = approach > 0 ? approach : 0
    if (approach > 0) {
      pushX[a] = pushX[a]! - approach * nrm.x
      pushY[a] = pushY[a]! - approach * nrm.y
      pushX[b] = pushX[b]! + approach * nrm.x
      pushY[b] = pushY[b]! + approach * nrm.y
    }
    normalX[p] = nrm.x
    normalY[p] = nrm.y
    if (unite(parent, a, b)) joined++
  }
  if (joined === 0) return 0
  // the anchors (only a ball near a closed wall can be one), marked for this call; none: nothing to hold
  const mark = ++anchorMark
  let anchors = false
  for (let k = 0; k < F.nearWallCount; k++) {
    const i = F.nearWall[k]!
    if (!pressedIntoWall(F, i)) continue
    anchorAt[i] = mark
    anchors = true
  }
  if (!anchors) return 0
  for (let i = 0; i < n; i++) {
    closes[i] = 0
    anchored[i] = 0
    bent[i] = 0
    heavy[i] = 0
    lineX[i] = 0
    lineY[i] = 0
    reached[i] = 0
  }
  // each group's closing, and its line: the normal of its first pair, which every other must keep to within
  // ROW_LINE_COS (a ball touching the row from the side, not closing, would be taken as held along the wall)
  for (let p = 0; p < pairs; p++) {
    if (approachOf[p]! < 0) continue
    const r = root(F.pairA[p]!)
    closes[r] = closes[r]! + approachOf[p]! * F.tick
    if (!keepsLine(lineX, lineY, r, normalX, normalY, p)) bent[r] = 1
    if (e < 1 && approachOf[p]! > 0) {
      const ia = F.im[F.pairA[p]!]!
      const ib = F.im[F.pairB[p]!]!
      if (ia >= SQUEEZE_MASS_RATIO * ib || ib >= SQUEEZE_MASS_RATIO * ia) heavy[r] = 1
    }
  }
  for (let k = 0; k < F.nearWallCount; k++) {
    const i = F.nearWall[k]!
    if (anchorAt[i] === mark) anchored[root(i)] = 1
  }
  // only an anchor's group can be held: none is, nothing to link
  let any = false
  for (let k = 0; k < F.nearWallCount && !any; k++) {
    const i = F.nearWall[k]!
    any = anchorAt[i] === mark && holds(root(i))
  }
  if (!any) return 0
  // the linked pairs of the groups held, by candidate, in pair order
  start.fill(0, 0, n + 1)
  for (let p = 0; p < pairs; p++) {
    if (approachOf[p]! < 0 || !holds(root(F.pairA[p]!))) continue
    start[F.pairA[p]! + 1]!++
    start[F.pairB[p]! + 1]!++
  }
  for (let i = 0; i < n; i++) start[i + 1] = start[i + 1]! + start[i]!
  if (start[n] === 0) return 0
  for (let i = 0; i < n; i++) fill[i] = start[i]!
  for (let p = 0; p < pairs; p++) {
    if (approachOf[p]! < 0 || !holds(root(F.pairA[p]!))) continue
    adj[fill[F.pairA[p]!]!++] = p
    adj[fill[F.pairB[p]!]!++] = p
  }
  // the anchors, in the order of their first pair, sent back by their walls; then, breadth first, each ball
  // against the one before it
  let head = 0
  let tail = 0
  let count = 0
  for (let p = 0; p < pairs; p++) {
    if (approachOf[p]! < 0 || !holds(root(F.pairA[p]!))) continue
    for (let s = 0; s < 2; s++) {
      const i = s === 0 ? F.pairA[p]! : F.pairB[p]!
      if (reached[i] === 1 || anchorAt[i] !== mark) continue
      reached[i] = 1
      queue[tail++] = i
      wallBack(w, F, i)
    }
  }
  while (head < tail) {
    const l = queue[head++]!
    for (let q = start[l]!, end = start[l + 1]!; q < end; q++) {
      const p = adj[q]!
      const u = F.pairA[p] === l ? F.pairB[p]! : F.pairA[p]!
      // a ball that does not meet l (at the velocities so far) is left for one it does meet
      if (reached[u] === 1 || !meetsWithinTick(F, l, u)) continue
      reached[u] = 1
      queue[tail++] = u
      count = against(w, F, p, l, u, e, settle, count)
    }
  }
  if (count > 0) held++
  return count
}

/** Whether the group rooted at r is held (see the top of this file): a row, or with restitution below 1 a pile a heavy ball presses. */
function holds(r: number): boolean {
  return anchored[r] === 1 && (bent[r] === 0 || heavy[r] === 1) && closes[r]! > PROJECTION_SLOP
}

/**
 * Whether candidate i's closing pairs push it into a closed wall it touches within its reach, along the
 * wall's normal (to within ROW_LINE_COS: a ball pushed along a wall is not held by it).
 */
function pressedIntoWall(F: FixedContactState, i: number): boolean {
  const gap = F.reach[i]! - F.r[i]!
  const x = F.x[i]!
  const y = F.y[i]!
  const r = F.r[i]!
  const px = pushX[i]!
  const py = pushY[i]!
  const along = ROW_LINE_COS * Math.sqrt(px * px + py * py)
  if (!(along > 0)) return false
  return (
    (px >= along && walls.maxX - x - r <= gap) ||
    (-px >= along && x - r - walls.minX <= gap) ||
    (py >= along && walls.maxY - y - r <= gap) ||
    (-py >= along && y - r - walls.minY <= gap)
  )
}

/**
 * Ball u after the ball l before it in a held row, over pair p (meetsWithinTick has left their normal in
 * nrm), as if l could not move: their approach along the normal leaves with restitution e (0 below
 * `settle`), u's normal speed never above what it was. A pair whose contact this tick was not yet reported
 * is reported, as the solve reports its impulses.
 */
function against(w: BallWorld, F: FixedContactState, p: number, l: number, u: number, e: number, settle: number, count: number): number {
  const nx = nrm.x
  const ny = nrm.y
  // normal speeds along l→u: they close while u's falls short of l's
  const vu = F.vx[u]! * nx + F.vy[u]! * ny
  const vl = F.vx[l]! * nx + F.vy[l]! * ny
  const approach = vl - vu
  if (!(approach > 0)) return count
  let to = vl + (approach < settle ? 0 : e) * approach
  const speed = Math.abs(vu)
  if (to > speed) to = speed
  else if (to < -speed) to = -speed
  if (to === vu) return count
  F.vx[u] = F.vx[u]! + (to - vu) * nx
  F.vy[u] = F.vy[u]! + (to - vu) * ny
  list[count] = u
  // reported as the solve reports a pair (its time and settle speed are the solve's, in solveSlots)
  solveSlots[S_APPROACH] = approach
  solveSlots[S_J] = F.mass[F.id[u]!]! * (to - vu)
  reportPair(w, F, p, l, u)
  return count + 1
}

export function heldBalls(): Int32Array {
  return list
}

export function rowsHeld(): number {
  return held
}
