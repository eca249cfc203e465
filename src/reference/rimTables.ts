// The rim tables a process has built, shared by every world (each is immutable but for capture rows found
// late, which are the same bits whenever they are found), and what a world may use: its config's table from
// the start, others given by prepareRimTable. src/reference/rimTable.ts builds and reads a table.
import type { BallWorld } from '../world/createWorld.js'
import { checkWorld, describe, readSpec } from '../check.js'
import { MAX_RATIO } from './tolerances.js'
import { MIN_TABLE_RATIO } from '../config/limits.js'
import { TABLE_TOP_SPEED, buildRimTable, captureSpeedAt, fillCaptureRows, type RimTable } from './rimTable.js'
import { referenceCaptureSpeed } from './captureSearch.js'
import { SHIPPED_INERTIA, SHIPPED_RATIO, SHIPPED_ROWS } from './rimTableRows.js'

/**
 * Lets `world` decide crossings of a ball of radius `ballRadius` in a hole of radius `holeRadius` (inertia
 * j) from a table, built now if no world has built it yet: with every capture row (`rows: 'now'`, the
 * default: 0.4–0.5 s for balls of radius 5–9 in an 18-px hole, 4–8 s for radius 13–16) or with the rows
 * found as crossings need them (`rows: 'lazy'`, 35–70 ms now and about 15 ms per row later, inside the step
 * that needs it). A world with RIM_MODEL 'tabulated' has its config's BALL_RADIUS and HOLE_RADIUS table from
 * the start, every row found when the world is made; a crossing of
 * any other sizes without one is decided by the live reference (tens of µs each). A world's decisions
 * depend only on which tables it was given, never on what other worlds built. Returns the time taken, ms.
 */
export function prepareRimTable(
  target: BallWorld | { world: BallWorld },
  holeRadius: number,
  ballRadius: number,
  options: { inertia?: number | undefined; rows?: 'now' | 'lazy' | undefined } = {},
): number {
  const w = checkWorld('prepareRimTable', target !== null && typeof target === 'object' && 'world' in target ? target.world : target)
  checkSizes(holeRadius, ballRadius)
  const o = readSpec('options', options, ['inertia', 'rows'] as const)
  const inertia = o.inertia === undefined ? w.config.BALL_INERTIA : checkInertia('options.inertia', o.inertia as number)
  const rows = o.rows ?? 'now'
  if (rows !== 'now' && rows !== 'lazy') throw new RangeError(`options.rows must be 'now' or 'lazy', got ${String(rows)}`)
  // only the tabulated model reads a world's tables (a hero ball runs the reference live): given to another
  // world, one was built and did nothing
  if (w.config.RIM_MODEL !== 'tabulated') {
    throw new Error(`prepareRimTable: the world's config.RIM_MODEL is '${w.config.RIM_MODEL}'; its tables are read only with RIM_MODEL 'tabulated' (TABULATED_CONFIG)`)
  }
  const t0 = performance.now()
  const t = rimTableFor(holeRadius / ballRadius, inertia)
  if (rows === 'now') fillCaptureRows(t)
  if (!w.rimTables.includes(t)) {
    w.rimTables.push(t)
    // a replay being recorded gives its world the same table (src/commands/replay.ts)
    if (w.recorder !== null) w.recorder.inputs.push(['prepareRimTable', holeRadius, ballRadius, inertia])
  }
  return performance.now() - t0
}

/**
 * The tabulated model's capture speed at offset `delta`, px/s: the largest lip-crossing speed its table
 * captures at that offset (for overlays and charts; builds the geometry's table if need be).
 */
export function tabulatedCaptureSpeed(delta: number, holeRadius: number, ballRadius: number, gravity: number, inertia = 2 / 5): number {
  checkSizes(holeRadius, ballRadius)
  if (typeof delta !== 'number') throw new TypeError(`delta must be a number in [0, holeRadius), got ${describe(delta)}`)
  if (!(delta >= 0 && delta < holeRadius)) throw new RangeError(`delta must be in [0, holeRadius), got ${delta}`)
  if (typeof gravity !== 'number') throw new TypeError(`gravity must be a finite number in (0, ∞), got ${describe(gravity)}`)
  if (!(gravity > 0) || !Number.isFinite(gravity)) throw new RangeError(`gravity must be a finite number in (0, ∞), got ${gravity}`)
  const j = checkInertia('inertia', inertia)
  const t = rimTableFor(holeRadius / ballRadius, j)
  const vs = captureSpeedAt(t, delta / ballRadius)
  // beyond the table's top speed the live reference decides (as in the engine); its rows only say the capture
  // speed lies beyond it (a small ball, R/r above about 1,000: they stop at 64 times the top, and this gave
  // that cap at every δ, a sixth of the reference's speed at R/r 1,800)
  if (vs >= TABLE_TOP_SPEED) return referenceCaptureSpeed(delta, holeRadius, ballRadius, gravity, j)
  return vs * Math.sqrt(gravity * ballRadius)
}

/** A table's hole and ball radii: numbers (TypeError), finite, and R/r in [MIN_TABLE_RATIO, MAX_RATIO] (RangeError). */
function checkSizes(holeRadius: number, ballRadius: number): void {
  if (typeof holeRadius !== 'number') throw new TypeError(`holeRadius must be a finite number in (0, ∞), got ${describe(holeRadius)}`)
  if (!(holeRadius > 0) || !Number.isFinite(holeRadius)) throw new RangeError(`holeRadius must be a finite number in (0, ∞), got ${holeRadius}`)
  if (typeof ballRadius !== 'number') throw new TypeError(`ballRadius must be a number in [holeRadius / ${MAX_RATIO}, holeRadius / ${MIN_TABLE_RATIO}], got ${describe(ballRadius)}`)
  if (!(ballRadius > 0 && holeRadius >= MIN_TABLE_RATIO * ballRadius && holeRadius <= MAX_RATIO * ballRadius)) {
    throw new RangeError(
      `ballRadius must be in [holeRadius / ${MAX_RATIO}, holeRadius / ${MIN_TABLE_RATIO}] = [${holeRadius / MAX_RATIO}, ${holeRadius / MIN_TABLE_RATIO}] ` +
        `(closer to the hole's size a table's rows take minutes), got ${ballRadius}`,
    )
  }
}

/** An inertia factor j: a number (TypeError) in (0, 2/3] (RangeError). */
function checkInertia(field: string, j: number): number {
  if (typeof j !== 'number') throw new TypeError(`${field} must be a number in (0, 2/3], got ${describe(j)}`)
  if (!(j > 0 && j <= 2 / 3)) throw new RangeError(`${field} must be in (0, 2/3], got ${j}`)
  return j
}

/** Tables built so far, by R/r and j (each is immutable, but for rows found late, and shared by every world). */
const cache = new Map<string, RimTable>()

/**
 * The table for R/r = ratio and inertia j: built on first use (about 100 ms), then shared. At the design's
 * geometry (R/r = 18/11, j = 2/5) its capture rows are shipped; at any other, each row is found when a
 * crossing first needs it (about 15 ms). A game that wants no such pause calls this, then fillCaptureRows,
 * when it loads, for each ball and hole size it uses.
 */
export function rimTableFor(ratio: number, inertia: number): RimTable {
  const key = `${ratio}:${inertia}`
  let t = cache.get(key)
  if (t === undefined) {
    const shipped = ratio === SHIPPED_RATIO && inertia === SHIPPED_INERTIA ? new Float64Array(SHIPPED_ROWS) : undefined
    t = buildRimTable(ratio, inertia, shipped)
    cache.set(key, t)
  }
  return t
}
