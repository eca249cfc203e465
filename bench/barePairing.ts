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

/** The moving balls after each step of a run (position, velocity, radius), packed per step. */
export interface Frame {
  n: number
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
    const f: Frame = { n: 0, x: new Float64Array(c), y: new Float64Array(c), vx: new Float64Array(c), vy: new Float64Array(c), r: new Float64Array(c) }
    for (let i = 0; i < c; i++) {
      const e = ids[i]!
      const m = B.mode[e]
      if (B.live[e] !== 1 || (m !== BallMode.Rolling && m !== BallMode.RimRoll)) continue
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
  head: new Int32Array(0),
}

/** Pairs within reach among frame f's balls at tick length `tick`. */
export function pairFrame(f: Frame, tick: number): number {
  const n = f.n
  if (n < 2) return 0
  if (S.reach.length < n) {
    S.reach = new Float64Array(n)
    S.cell = new Int32Array(n)
    S.sx = new Float64Array(n)
    S.sy = new Float64Array(n)
    S.sr = new Float64Array(n)
  }
  const { reach, cell, sx, sy, sr } = S
  let max = 0
  let minX = Infinity
  let minY = Infinity
  let maxX = -Infinity
  let maxY = -Infinity
  for (let i = 0; i < n; i++) {
    const vx = f.vx[i]!
    const vy = f.vy[i]!
    const rr = f.r[i]! + Math.sqrt(vx * vx + vy * vy) * tick + TOUCH_GAP
    reach[i] = rr
    if (rr > max) max = rr
    const x = f.x[i]!
    const y = f.y[i]!
    if (x < minX) minX = x
    if (x > maxX) maxX = x
    if (y < minY) minY = y
    if (y > maxY) maxY = y
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
    const c = Math.floor((f.y[i]! - minY) * inv) * cols + Math.floor((f.x[i]! - minX) * inv)
    cell[i] = c
    head[c + 1]!++
  }
  for (let c = 0; c < cells; c++) head[c + 1]! += head[c]!
  // scatter in cell order; head[c] becomes the end of cell c (its start: head[c − 1], or 0)
  for (let i = 0; i < n; i++) {
    const o = head[cell[i]!]!++
    sx[o] = f.x[i]!
    sy[o] = f.y[i]!
    sr[o] = reach[i]!
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
      const x = sx[a]!
      const y = sy[a]!
      const ra = sr[a]!
      for (let b = a + 1; b < e0; b++) found += within(x, y, ra, sx[b]!, sy[b]!, sr[b]!)
      for (let b = r0; b < r1; b++) found += within(x, y, ra, sx[b]!, sy[b]!, sr[b]!)
      for (let b = b0; b < b1; b++) found += within(x, y, ra, sx[b]!, sy[b]!, sr[b]!)
    }
  }
  return found
}

function within(x: number, y: number, r: number, xb: number, yb: number, rb: number): number {
  const dx = xb - x
  const dy = yb - y
  const s = r + rb
  return dx * dx + dy * dy < s * s ? 1 : 0
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
