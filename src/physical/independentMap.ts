// The independent model's capture map on a (δ, v) grid, and the capture boundary of any model row by row:
// where a map switches between capture and escape along v in each δ row, and a model's own switch speed
// bisected inside that cell (docs/physical.md, "An independent model").
import { gridDelta, gridSpeed, type CaptureMap, type DeltaSpeedGrid } from './agreement.js'
import { independentOutcome, type IndependentOptions } from './independent.js'

export interface IndependentMapResult {
  map: CaptureMap
  /** cells stopped by a guard (time or phase limit); they count as escapes */
  guarded: number
  /** 1 where a guard stopped the run, indexed as the map */
  guardedCells: Uint8Array
  /** cells whose ball was held on the lip at least once (N < 0 while its free path cut into the lip) */
  held: number
  /** largest relative energy drift over any roll on the lip */
  energyDrift: number
  /** RK4 steps over all cells */
  steps: number
}

/** The independent model's capture map at radii R (the grid's), r, gravity g and inertia j. */
export function independentMap(g: DeltaSpeedGrid, ballRadius: number, gravity: number, inertia: number, options: IndependentOptions = {}): IndependentMapResult {
  const map = new Uint8Array(g.nDelta * g.nSpeed)
  const guardedCells = new Uint8Array(g.nDelta * g.nSpeed)
  let guarded = 0
  let held = 0
  let energyDrift = 0
  let steps = 0
  const input = { delta: 0, speed: 0, holeRadius: g.holeRadius, ballRadius, gravity, inertia }
  for (let i = 0; i < g.nDelta; i++) {
    input.delta = gridDelta(g, i)
    for (let k = 0; k < g.nSpeed; k++) {
      input.speed = gridSpeed(g, k)
      const o = independentOutcome(input, options)
      if (o.ending === 'timeLimit' || o.ending === 'phaseLimit') {
        guarded++
        guardedCells[i * g.nSpeed + k] = 1
      }
      if (o.held > 0) held++
      if (o.energyDrift > energyDrift) energyDrift = o.energyDrift
      steps += o.steps
      map[i * g.nSpeed + k] = o.captured ? 1 : 0
    }
  }
  return { map, guarded, guardedCells, held, energyDrift, steps }
}

/** The cells k of row i after which the map switches (k captured and k + 1 escaped, or the other way). */
export function rowSwitches(g: DeltaSpeedGrid, map: CaptureMap, i: number): number[] {
  const out: number[] = []
  for (let k = 0; k + 1 < g.nSpeed; k++) if (map[i * g.nSpeed + k] !== map[i * g.nSpeed + k + 1]) out.push(k)
  return out
}

/**
 * The speed in [lo, hi] where `captured` switches, bisected `iterations` times; `captured(lo)` and
 * `captured(hi)` must differ. Returns the middle of the last bracket.
 */
export function bisectSwitch(captured: (v: number) => boolean, lo: number, hi: number, iterations: number): number {
  const low = captured(lo)
  if (captured(hi) === low) throw new RangeError('bisectSwitch: the model does not switch between lo and hi')
  for (let n = 0; n < iterations; n++) {
    const m = 0.5 * (lo + hi)
    if (captured(m) === low) lo = m
    else hi = m
  }
  return 0.5 * (lo + hi)
}

export interface RowBoundary {
  delta: number
  /** switch speeds of model a and of model b, px/s, one per switch of the row (empty: no switch below the grid's top) */
  a: number[]
  b: number[]
  /** b − a per switch when both maps switch in the same cells, else undefined */
  difference?: number[]
}

/**
 * Row by row, the switch speeds of two models whose maps are `mapA` and `mapB` (each bisected inside its
 * own map's switch cells), and their difference where the two switch in the same cells.
 */
export function rowBoundaries(
  g: DeltaSpeedGrid,
  mapA: CaptureMap,
  capturedA: (delta: number, speed: number) => boolean,
  mapB: CaptureMap,
  capturedB: (delta: number, speed: number) => boolean,
  iterations: number,
): RowBoundary[] {
  const rows: RowBoundary[] = []
  for (let i = 0; i < g.nDelta; i++) {
    const delta = gridDelta(g, i)
    const sa = rowSwitches(g, mapA, i)
    const sb = rowSwitches(g, mapB, i)
    const a = sa.map((k) => bisectSwitch((v) => capturedA(delta, v), gridSpeed(g, k), gridSpeed(g, k + 1), iterations))
    const b = sb.map((k) => bisectSwitch((v) => capturedB(delta, v), gridSpeed(g, k), gridSpeed(g, k + 1), iterations))
    const row: RowBoundary = { delta, a, b }
    if (sa.length === sb.length && sa.every((k, n) => k === sb[n])) row.difference = a.map((v, n) => b[n]! - v)
    rows.push(row)
  }
  return rows
}
