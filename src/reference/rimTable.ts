// The reference-tabulated rim model's table: the rigid-sphere reference (src/reference/) evaluated once per
// geometry on a (δ, v) grid, so a lip crossing is decided by a lookup instead of an integration.
//
// In the reference's scaled units (lengths in r, speeds in √(g·r), times in √(r/g)) an outcome depends only
// on R/r, δ/r, v/√(g·r) and j, so one table serves every hole and ball of the same ratio R/r and inertia.
//
//   capture   v ≤ v_c(δ): the capture speed located per δ row by bisection (every row of the reference's map
//             at the game's geometry has a single capture→escape transition, so capture is v ≤ v_c(δ)),
//             interpolated linearly between rows. A cell is never decided by interpolating across the
//             boundary: the boundary itself is what is interpolated.
//   outcome   kind (captured, rolled round the lip and out, bounced, skipped), exit point (as the turn to it
//             from the crossing and its distance from the hole centre), direction and speed, time and turn on the lip: bilinear on a coarser grid over the corners of the same kind
//             as the nearest one (so a roll-out is never blended with a bounce), else the nearest such node.
//
// Above the table's top speed the caller asks the live reference (a rare, fast ball; see tabulatedRimSystem).
import { simulateScaled } from './sphereLip.js'
import { isGuarded, type ReferenceOutcome } from './types.js'
import { atan2, cos, sin } from '../math.js'

/** Outcome kinds stored per node. */
export const RimKind = {
  /** captured; turn and time are those of the drop */
  Captured: 0,
  /** escaped after rolling at least ROLL_TURN round the lip */
  Rolled: 1,
  /** escaped after at least one impact with the lip, with less turn */
  Bounced: 2,
  /** flew over with no impact */
  Skipped: 3,
  /** a guard of the reference stopped the run (no outcome): left to the six stages */
  Guarded: 4,
} as const
export type RimKindCode = (typeof RimKind)[keyof typeof RimKind]

/** Turn on the lip (rad) from which an outcome counts as a rim roll (about 20°, as the hero ball's). */
export const ROLL_TURN = (20 * Math.PI) / 180

/** Grid sizes of a table: rows of the capture boundary; nodes of the outcome grid. */
export const TABLE_ROWS = 96
export const TABLE_DELTA_NODES = 32
export const TABLE_SPEED_NODES = 64
/** top of the outcome grid, scaled speed v/√(g·r): 7.2 is 2,000 px/s at the design's geometry */
export const TABLE_TOP_SPEED = 7.2

// per-node values, stride VALUES
const TURN = 0
const TIME = 1
const EXIT_TURN = 2
const EXIT_RADIUS = 3
const EXIT_COS = 4
const EXIT_SIN = 5
const EXIT_SPEED = 6
const VALUES = 7

export interface RimTable {
  /** R/r and j the table was built for */
  readonly ratio: number
  readonly inertia: number
  /** scaled capture speed at δ/r = ratio·i/(TABLE_ROWS − 1) (the last row just inside the lip); NaN until found */
  readonly vc: Float64Array
  /** RimKind per node, row-major by δ then v */
  readonly kind: Uint8Array
  /** VALUES numbers per node (scaled units) */
  readonly values: Float64Array
  /** build time, ms */
  readonly buildMs: number
}

/**
 * Where an outcome lookup writes (scaled units; exit values only for escapes; exitCos and exitSin give the
 * exit direction relative to the tangent at the exit point: exitRelative). Module scratch: no allocation.
 */
export const rimOut = { kind: 0 as RimKindCode, turn: 0, time: 0, exitTurn: 0, exitRadius: 0, exitCos: 1, exitSin: 0, exitSpeed: 0 }

/**
 * The exit direction `exitAngle` (reference frame) relative to the tangent of the circle about the hole at
 * the exit point, taken the way the ball turns (the angle falls): the exit point lies at psi0 − exitTurn,
 * where that tangent points at psi0 − exitTurn − π/2. exitAngleFrom undoes it.
 */
export function exitRelative(exitAngle: number, psi0: number, exitTurn: number): number {
  return exitAngle - (psi0 - exitTurn - Math.PI / 2)
}
export function exitAngleFrom(relative: number, psi0: number, exitTurn: number): number {
  return relative + (psi0 - exitTurn - Math.PI / 2)
}

/**
 * The angle of the crossing point about the hole centre in the reference's frame (the ball comes along +x at
 * y = δ): the exit point lies exitTurn radians further round (the angle falls), at distance exitRadius.
 */
export function crossingAngle(ratio: number, ds: number): number {
  return atan2(ds, -Math.sqrt(ratio * ratio - ds * ds))
}

/**
 * A reference outcome (scaled units, at R/r = ratio and δ/r = ds) in the table's terms, into rimOut: the
 * kind; the turn and time; for an escape, the exit point in polar form about the hole (its angle counted
 * from the crossing the way the ball turns, unwrapped to the turn the reference rolled, so rolls round the
 * lip interpolate as arcs), the exit direction relative to the lip's tangent there, and the exit speed.
 */
export function referenceToOut(o: ReferenceOutcome, ratio: number, ds: number): void {
  const out = rimOut
  out.turn = o.turnAngle
  out.time = o.duration
  if (isGuarded(o.ending)) {
    out.kind = RimKind.Guarded
    return
  }
  if (o.captured) {
    out.kind = RimKind.Captured
    return
  }
  out.kind = o.turnAngle >= ROLL_TURN ? RimKind.Rolled : o.impacts > 0 ? RimKind.Bounced : RimKind.Skipped
  const psi0 = crossingAngle(ratio, ds)
  let turn = psi0 - atan2(o.exitY!, o.exitX!)
  turn -= 2 * Math.PI * Math.floor(turn / (2 * Math.PI))
  while (turn + Math.PI < o.turnAngle) turn += 2 * Math.PI
  out.exitTurn = turn
  out.exitRadius = Math.sqrt(o.exitX! * o.exitX! + o.exitY! * o.exitY!)
  const rel = exitRelative(o.exitAngle!, psi0, turn)
  out.exitCos = cos(rel)
  out.exitSin = sin(rel)
  out.exitSpeed = o.exitSpeed!
}

/** δ/r of row i (the last row sits just inside the lip: the reference needs |δ| < R). */
function rowDelta(ratio: number, i: number): number {
  return i === TABLE_ROWS - 1 ? ratio * (1 - 1e-9) : (ratio * i) / (TABLE_ROWS - 1)
}

/** δ/r and v/√(g·r) of outcome node (i, k). */
function nodeDelta(ratio: number, i: number): number {
  return i === TABLE_DELTA_NODES - 1 ? ratio * (1 - 1e-9) : (ratio * i) / (TABLE_DELTA_NODES - 1)
}
function nodeSpeed(k: number): number {
  return (TABLE_TOP_SPEED * (k + 1)) / TABLE_SPEED_NODES
}

const BISECTION_STEPS = 24

/**
 * Builds the table for R/r = ratio and inertia j. Deterministic. The outcome grid takes about 100 ms. The
 * capture rows are found when first needed, each on its own (about 15 ms a row: a run near the boundary
 * rolls round the lip for long), unless `rows` passes them (the design's geometry ships them:
 * src/reference/rimTableRows.ts); fillCaptureRows computes them all at once.
 */
export function buildRimTable(ratio: number, inertia: number, rows?: Float64Array): RimTable {
  if (!(ratio > 1) || !Number.isFinite(ratio)) throw new RangeError(`ratio (hole radius / ball radius) must be in (1, ∞), got ${ratio}`)
  if (!(inertia > 0 && inertia <= 2 / 3)) throw new RangeError(`inertia must be in (0, 2/3], got ${inertia}`)
  if (rows !== undefined && rows.length !== TABLE_ROWS) throw new RangeError(`rows must hold ${TABLE_ROWS} capture speeds, got ${rows.length}`)
  const t0 = performance.now()
  const nD = TABLE_DELTA_NODES
  const nV = TABLE_SPEED_NODES
  const kind = new Uint8Array(nD * nV)
  const values = new Float64Array(nD * nV * VALUES)
  for (let i = 0; i < nD; i++) {
    const ds = nodeDelta(ratio, i)
    for (let k = 0; k < nV; k++) {
      referenceToOut(simulateScaled(ratio, ds, nodeSpeed(k), inertia, null), ratio, ds)
      const n = i * nV + k
      const at = n * VALUES
      const o = rimOut
      kind[n] = o.kind
      values[at + TURN] = o.turn
      values[at + TIME] = o.time
      if (o.kind !== RimKind.Captured && o.kind !== RimKind.Guarded) {
        values[at + EXIT_TURN] = o.exitTurn
        values[at + EXIT_RADIUS] = o.exitRadius
        values[at + EXIT_COS] = o.exitCos
        values[at + EXIT_SIN] = o.exitSin
        values[at + EXIT_SPEED] = o.exitSpeed
      }
    }
  }
  const vc = rows === undefined ? new Float64Array(TABLE_ROWS).fill(NaN) : rows
  return { ratio, inertia, vc, kind, values, buildMs: performance.now() - t0 }
}

/** Computes every capture row of `t` not yet known; returns them (what the generator ships). */
export function fillCaptureRows(t: RimTable): Float64Array {
  for (let i = 0; i < TABLE_ROWS; i++) if (Number.isNaN(t.vc[i]!)) t.vc[i] = captureRow(t, i)
  return t.vc
}

/** The capture rows of R/r = ratio and inertia j, computed in full (about 1.5 s). */
export function captureRows(ratio: number, inertia: number): Float64Array {
  return fillCaptureRows(buildRimTable(ratio, inertia))
}

/**
 * Row i's scaled capture speed, found on its own (the same bits in whatever order rows are asked for): the
 * capture speed falls with δ, so it lies between the last captured node of the grid row at or beyond the
 * row's δ and the first escaped node of the grid row at or before it; bisected from there.
 */
function captureRow(t: RimTable, i: number): number {
  const ratio = t.ratio
  const ds = rowDelta(ratio, i)
  const nD = TABLE_DELTA_NODES
  const nV = TABLE_SPEED_NODES
  const f = (ds / ratio) * (nD - 1)
  const below = Math.min(nD - 1, Math.floor(f))
  const above = Math.min(nD - 1, Math.ceil(f))
  // first escaped node at or before this δ: an upper bound
  let hi = TABLE_TOP_SPEED * 4
  for (let k = 0; k < nV; k++) {
    if (t.kind[below * nV + k] !== RimKind.Captured) {
      hi = nodeSpeed(k)
      break
    }
  }
  // last captured node at or beyond: a lower bound
  let lo = 0
  for (let k = nV - 1; k >= 0; k--) {
    if (t.kind[above * nV + k] === RimKind.Captured) {
      lo = nodeSpeed(k)
      break
    }
  }
  const captured = (v: number) => simulateScaled(ratio, ds, v, t.inertia, null).captured
  // the bounds hold if the capture speed falls with δ; check them, widening if they do not
  while (lo > 0 && !captured(lo)) lo *= 0.5
  if (lo < 1e-9) lo = 0
  while (hi < TABLE_TOP_SPEED * 64 && captured(hi)) hi *= 2
  if (lo === 0) {
    // nothing captured at the grid's speeds: look below its first node
    lo = hi
    while (lo > 1e-6 && !captured(lo)) {
      hi = lo
      lo *= 0.5
    }
    if (lo <= 1e-6) return 0
  }
  for (let s = 0; s < BISECTION_STEPS; s++) {
    const mid = 0.5 * (lo + hi)
    if (captured(mid)) lo = mid
    else hi = mid
  }
  return lo
}

/** Scaled capture speed at δ/r = ds: linear between the rows (ds in [0, ratio)); a row not yet known is found now. */
export function captureSpeedAt(t: RimTable, ds: number): number {
  const f = (ds / t.ratio) * (TABLE_ROWS - 1)
  let i = Math.floor(f)
  if (i >= TABLE_ROWS - 1) return rowAt(t, TABLE_ROWS - 1)
  if (i < 0) i = 0
  const u = f - i
  const a = rowAt(t, i)
  return a + (rowAt(t, i + 1) - a) * u
}

function rowAt(t: RimTable, i: number): number {
  let v = t.vc[i]!
  if (Number.isNaN(v)) v = t.vc[i] = captureRow(t, i)
  return v
}

/**
 * The outcome at (ds, vs) (scaled), given the decision `captured` (from captureSpeedAt), into rimOut:
 * corners of the cell of the kind wanted (captured, or the escape kind of the nearest escaped corner),
 * blended bilinearly; else the nearest node of that kind along the row. vs above the grid's top is clamped.
 */
export function outcomeAt(t: RimTable, ds: number, vs: number, captured: boolean): void {
  const nD = TABLE_DELTA_NODES
  const nV = TABLE_SPEED_NODES
  const fd = (ds / t.ratio) * (nD - 1)
  const fv = (vs / TABLE_TOP_SPEED) * nV - 1
  let i = Math.floor(fd)
  if (i > nD - 2) i = nD - 2
  if (i < 0) i = 0
  let k = Math.floor(fv)
  if (k > nV - 2) k = nV - 2
  if (k < 0) k = 0
  let ud = fd - i
  let uv = fv - k
  ud = ud < 0 ? 0 : ud > 1 ? 1 : ud
  uv = uv < 0 ? 0 : uv > 1 ? 1 : uv
  const kinds = t.kind
  // the kind wanted: captured, or the escape kind of the heaviest escaped corner
  let want: number = RimKind.Captured
  if (!captured) {
    let best = -1
    want = -1
    for (let c = 0; c < 4; c++) {
      const n = (i + (c >> 1)) * nV + k + (c & 1)
      const kc = kinds[n]!
      // a node where a guard stopped the reference has no outcome to lend
      if (kc === RimKind.Captured || kc === RimKind.Guarded) continue
      const wgt = ((c >> 1) === 1 ? ud : 1 - ud) * ((c & 1) === 1 ? uv : 1 - uv)
      if (wgt > best) {
        best = wgt
        want = kc
      }
    }
    if (want < 0) want = nearestKind(t, ud < 0.5 ? i : i + 1, k, false)
  }
  let sum = 0
  let turn = 0
  let time = 0
  let ex = 0
  let ey = 0
  let ec = 0
  let es = 0
  let sp = 0
  const vals = t.values
  for (let c = 0; c < 4; c++) {
    const n = (i + (c >> 1)) * nV + k + (c & 1)
    if (kinds[n] !== want) continue
    const wgt = ((c >> 1) === 1 ? ud : 1 - ud) * ((c & 1) === 1 ? uv : 1 - uv)
    if (wgt === 0) continue
    const at = n * VALUES
    sum += wgt
    turn += wgt * vals[at + TURN]!
    time += wgt * vals[at + TIME]!
    ex += wgt * vals[at + EXIT_TURN]!
    ey += wgt * vals[at + EXIT_RADIUS]!
    ec += wgt * vals[at + EXIT_COS]!
    es += wgt * vals[at + EXIT_SIN]!
    sp += wgt * vals[at + EXIT_SPEED]!
  }
  const o = rimOut
  o.kind = want as RimKindCode
  if (sum === 0) {
    // no corner of that kind: the nearest node of it along the nearer row
    const n = nearestNode(t, ud < 0.5 ? i : i + 1, uv < 0.5 ? k : k + 1, want)
    if (n < 0) {
      o.kind = RimKind.Guarded
      return
    }
    const at = n * VALUES
    sum = 1
    turn = vals[at + TURN]!
    time = vals[at + TIME]!
    ex = vals[at + EXIT_TURN]!
    ey = vals[at + EXIT_RADIUS]!
    ec = vals[at + EXIT_COS]!
    es = vals[at + EXIT_SIN]!
    sp = vals[at + EXIT_SPEED]!
  }
  o.turn = turn / sum
  o.time = time / sum
  o.exitTurn = ex / sum
  o.exitRadius = ey / sum
  const len = Math.sqrt(ec * ec + es * es)
  o.exitCos = len > 0 ? ec / len : 1
  o.exitSin = len > 0 ? es / len : 0
  o.exitSpeed = sp / sum
}

/** The kind of the nearest node along row i from column k that is (captured) or is not (escaped) a capture. */
function nearestKind(t: RimTable, i: number, k: number, captured: boolean): number {
  const nV = TABLE_SPEED_NODES
  for (let d = 0; d < nV; d++) {
    if (k + d < nV) {
      const kc = t.kind[i * nV + k + d]!
      if (kc !== RimKind.Guarded && (kc === RimKind.Captured) === captured) return kc
    }
    if (k - d >= 0) {
      const kc = t.kind[i * nV + k - d]!
      if (kc !== RimKind.Guarded && (kc === RimKind.Captured) === captured) return kc
    }
  }
  return RimKind.Guarded
}

/** The nearest node of kind `want` along row i from column k (−1 when the row has none). */
function nearestNode(t: RimTable, i: number, k: number, want: number): number {
  const nV = TABLE_SPEED_NODES
  for (let d = 0; d < nV; d++) {
    if (k + d < nV && t.kind[i * nV + k + d] === want) return i * nV + k + d
    if (k - d >= 0 && t.kind[i * nV + k - d] === want) return i * nV + k - d
  }
  return -1
}
