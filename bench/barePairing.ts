// The barest loop that does the fixed-tick method's pairing job, the denominator for that method's cost of
// contacts (bench/contacts.ts): at each tick, every moving ball's reach (radius + speed · tick + TOUCH_GAP,
// as the method's), a uniform grid of cell twice the largest reach over the balls' bounding box (at most
// 4n + 64 cells, coarser when the box is large), the balls put in it by a counting sort with their
// positions and reaches copied in cell order, and each ball tested against the rest of its cell, the next
// cell of its row and the three cells of the next row. It only counts the pairs within reach: no
// resting balls, walls, solve, order or state kept from tick to tick, none of which can make a method's
// pairing cheaper. The frames are the moving balls of a recorded run, so the loop sees the same balls as
// the method.
import { BallMode } from '../components/Ball'
import { TOUCH_GAP } from '../src/config/tolerances'
import type { BallPhysics } from '../src/index'

/** The moving balls after each step of a run (entity id, position, velocity, radius), packed per step. */
export interface Frame {
  n: number
  id: Int32Array
  x: Float64Array
  y: Float64Array
  vx: Float64Array
  vy: Float64Array
  r: Float64Array
}

/** Steps sim `steps` times by dt, recording its moving balls (rolling or on a rim) after each step. */
export function recordFrames(sim: BallPhysics, steps: number, dt: number): Frame[] {
  const w = sim.world
  const B = w.Ball
  const frames: Frame[] = []
  for (let s = 0; s < steps; s++) {
    sim.step(dt)
    w.events.count = 0
    const ids = w.moving.dense
    const c = w.moving.count
    const f: Frame = { n: 0, id: new Int32Array(c), x: new Float64Array(c), y: new Float64Array(c), vx: new Float64Array(c), vy: new Float64Array(c), r: new Float64Array(c) }
    for (let i = 0; i < c; i++) {
      const e = ids[i]!
      const m = B.mode[e]
      if (B.live[e] !== 1 || (m !== BallMode.Rolling && m !== BallMode.RimRoll)) continue
      f.id[f.n] = e
      f.x[f.n] = B.x[e]!
      f.y[f.n] = B.y[e]!
      f.vx[f.n] = B.vx[e]!
      f.vy[f.n] = B.vy[e]!
      f.r[f.n] = B.radius[e]!
      f.n++
    }
    frames.push(f)
  }
  return frames
}

/** Scratch of the loop, grown to the largest frame (outside the timed passes after the first). */
const S = {
  reach: new Float64Array(0),
  cell: new Int32Array(0),
  sx: new Float64Array(0),
  sy: new Float64Array(0),
  sr: new Float64Array(0),
  so: new Int32Array(0),
  head: new Int32Array(0),
}

/** Where cellPairs lists the pairs it finds (slots of the frame), when asked to. */
export interface PairSink {
  push(a: number, b: number): void
}

/** Pairs within reach among frame f's balls at tick length `tick`. */
export function pairFrame(f: Frame, tick: number): number {
  const n = f.n
  if (n < 2) return 0
  if (S.reach.length < n) S.reach = new Float64Array(n)
  const reach = S.reach
  for (let i = 0; i < n; i++) {
    const vx = f.vx[i]!
    const vy = f.vy[i]!
    reach[i] = f.r[i]! + Math.sqrt(vx * vx + vy * vy) * tick + TOUCH_GAP
  }
  return cellPairs(n, f.x, f.y, reach, null)
}

/**
 * The grid's pairs: how many of the n discs (centre x[i], y[i], radius rad[i]) overlap, each pair tested
 * once through the cells; with a sink, each such pair (a, b) of slots is also pushed to it.
 */
export function cellPairs(n: number, x: Float64Array, y: Float64Array, rad: Float64Array, sink: PairSink | null): number {
  if (n < 2) return 0
  if (S.cell.length < n) {
    S.cell = new Int32Array(n)
    S.sx = new Float64Array(n)
    S.sy = new Float64Array(n)
    S.sr = new Float64Array(n)
    S.so = new Int32Array(n)
  }
  const { cell, sx, sy, sr, so } = S
  let max = 0
  let minX = Infinity
  let minY = Infinity
  let maxX = -Infinity
  let maxY = -Infinity
  for (let i = 0; i < n; i++) {
    const rr = rad[i]!
    if (rr > max) max = rr
    const xi = x[i]!
    const yi = y[i]!
    if (xi < minX) minX = xi
    if (xi > maxX) maxX = xi
    if (yi < minY) minY = yi
    if (yi > maxY) maxY = yi
  }
  let size = 2 * max
  let cols = Math.floor((maxX - minX) / size) + 1
  let rows = Math.floor((maxY - minY) / size) + 1
  while (cols * rows > 4 * n + 64) {
    size *= 1.5
    cols = Math.floor((maxX - minX) / size) + 1
    rows = Math.floor((maxY - minY) / size) + 1
  }
  const cells = cols * rows
  if (S.head.length < cells + 1) S.head = new Int32Array(2 * (cells + 1))
  const head = S.head
  head.fill(0, 0, cells + 1)
  const inv = 1 / size
  for (let i = 0; i < n; i++) {
    const c = Math.floor((y[i]! - minY) * inv) * cols + Math.floor((x[i]! - minX) * inv)
    cell[i] = c
    head[c + 1]!++
  }
  for (let c = 0; c < cells; c++) head[c + 1]! += head[c]!
  // scatter in cell order; head[c] becomes the end of cell c (its start: head[c − 1], or 0)
  for (let i = 0; i < n; i++) {
    const o = head[cell[i]!]!++
    sx[o] = x[i]!
    sy[o] = y[i]!
    sr[o] = rad[i]!
    so[o] = i
  }
  let found = 0
  for (let c = 0; c < cells; c++) {
    const s0 = c > 0 ? head[c - 1]! : 0
    const e0 = head[c]!
    if (s0 === e0) continue
    const cx = c % cols
    const right = cx + 1 < cols
    const below = c + cols < cells
    // the next cell of the row, and the three of the next row (one run of the cell order each)
    const r0 = right ? head[c]! : 0
    const r1 = right ? head[c + 1]! : 0
    const b0 = below ? head[c + cols - (cx > 0 ? 2 : 1)]! : 0
    const b1 = below ? head[c + cols + (right ? 1 : 0)]! : 0
    for (let a = s0; a < e0; a++) {
      for (let b = a + 1; b < e0; b++) found += within(sx, sy, sr, so, a, b, sink)
      for (let b = r0; b < r1; b++) found += within(sx, sy, sr, so, a, b, sink)
      for (let b = b0; b < b1; b++) found += within(sx, sy, sr, so, a, b, sink)
    }
  }
  return found
}

/** Whether the discs at places a and b of the cell order overlap (and if so, pushed to the sink). */
function within(sx: Float64Array, sy: Float64Array, sr: Float64Array, so: Int32Array, a: number, b: number, sink: PairSink | null): number {
  const dx = sx[b]! - sx[a]!
  const dy = sy[b]! - sy[a]!
  const s = sr[a]! + sr[b]!
  if (dx * dx + dy * dy >= s * s) return 0
  if (sink !== null) sink.push(so[a]!, so[b]!)
  return 1
}

/**
 * The loop over every frame, `passes` times: the median pass's µs a step, the pairs a step and the moving
 * balls a step.
 */
export function timeBarePairing(frames: readonly Frame[], tick: number, passes: number): { usPerStep: number; pairsPerStep: number; movingPerStep: number } {
  let pairs = 0
  let moving = 0
  for (const f of frames) {
    pairs += pairFrame(f, tick)
    moving += f.n
  }
  const times: number[] = []
  for (let p = 0; p < passes; p++) {
    let check = 0
    const t = process.hrtime.bigint()
    for (const f of frames) check += pairFrame(f, tick)
    times.push(Number(process.hrtime.bigint() - t) / 1000 / frames.length)
    if (check !== pairs) throw new Error(`bare pairing: ${check} pairs in a pass, ${pairs} in the first`)
  }
  times.sort((a, b) => a - b)
  return { usPerStep: times[times.length >> 1]!, pairsPerStep: pairs / frames.length, movingPerStep: moving / frames.length }
}
