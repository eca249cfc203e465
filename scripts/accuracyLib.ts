// Accuracy of a stepping method against the exact event-driven reference (src/eventSolver.ts), and its
// cost, on a seeded set of throws at the default panel. Used by scripts/accuracy.ts (10,000 throws) and by
// tests/accuracy.test.ts (a small sample).
import { DEFAULT_PANEL, addPanel, createBallPhysics, type BallEvent, type SimulationMethod } from '../src/index'
import { solveBall, throwVelocity, type SolverEvent, type SolverResult } from '../src/reference/eventSolver'
import { resolveConfig } from '../src/config/design'
import { mulberry32 } from '../src/random'

export interface Throw {
  x: number
  y: number
  power: number
  angle: number
}

/** mulberry32 (src/random.ts) */
export const rng = mulberry32

/** The throw distribution of tests/multiball.test.ts: x spread ±150 px about the launch point, any power, ±0.7 rad. */
export function panelThrows(seed: number, n: number): Throw[] {
  const rand = rng(seed)
  const out: Throw[] = []
  for (let i = 0; i < n; i++) {
    out.push({
      x: DEFAULT_PANEL.launch.x + (rand() - 0.5) * 300,
      y: DEFAULT_PANEL.launch.y,
      power: rand(),
      angle: (rand() - 0.5) * 1.4,
    })
  }
  return out
}

/** Hole ids as addPanel gives them in a fresh world: 1..25, in layout order. */
export function referenceRuns(throws: readonly Throw[]): SolverResult[] {
  const cfg = resolveConfig()
  const holes = DEFAULT_PANEL.holes.map((h, i) => ({ x: h.x, y: h.y, id: i + 1 }))
  return throws.map((t) => solveBall(cfg, holes, { x: t.x, y: t.y, ...throwVelocity(cfg, t.power, t.angle) }))
}

export interface MethodSpec {
  label: string
  method: SimulationMethod
  substeps: number
}

export const METHOD_SPECS: readonly MethodSpec[] = [
  { label: 'v1', method: 'v1', substeps: 1 },
  { label: 'naive', method: 'naive', substeps: 1 },
  { label: 'naive ×4', method: 'naive', substeps: 4 },
  { label: 'naive ×16', method: 'naive', substeps: 16 },
  { label: 'exact', method: 'exact', substeps: 1 },
]

export interface MethodRun {
  events: BallEvent[][]
  finals: { x: number; y: number; mode: string }[]
  /** step wall time, ns, and the ball-steps it covered (moving balls at each step's start) */
  ns: number
  ballSteps: number
}

/** All throws in one world (balls do not interact), stepped at `hz` until every ball stops (or 60 s). */
export function runMethod(spec: MethodSpec, hz: number, throws: readonly Throw[], keepEvents = true): MethodRun {
  const sim = createBallPhysics({ METHOD: spec.method, SUBSTEPS: spec.substeps }, { capacity: throws.length + 64 })
  const holeIds = addPanel(sim)
  if (holeIds[0] !== 1 || holeIds[24] !== 25) throw new Error('unexpected hole ids')
  const balls = throws.map((t) => sim.throwBall(t))
  const index = new Map(balls.map((b, i) => [b, i]))
  const events: BallEvent[][] = throws.map(() => [])
  const dt = 1 / hz
  let ns = 0
  let ballSteps = 0
  const moving = sim.world.moving
  for (let i = 0; i < hz * 60 && moving.count > 0; i++) {
    ballSteps += moving.count
    const t0 = process.hrtime.bigint()
    sim.step(dt)
    ns += Number(process.hrtime.bigint() - t0)
    const evs = sim.drainEvents()
    if (keepEvents) for (const e of evs) events[index.get(e.ball)!]!.push(e)
  }
  const finals = balls.map((b) => {
    const s = sim.ballState(b)
    return { x: s.x, y: s.y, mode: s.mode }
  })
  return { events, finals, ns, ballSteps }
}

export interface Accuracy {
  throws: number
  /** share of throws whose event sequence (type, hole, capture route) differs from the reference */
  sequenceDiffers: number
  /** share of throws that end differently: other hole, or captured against resting */
  outcomeDiffers: number
  /** |Δδ| and |Δv| of the lip crossings paired along the common prefix of the two sequences */
  lipPairs: number
  deltaErrMean: number
  deltaErrMax: number
  speedErrMean: number
  speedErrMax: number
  /** |final position − reference|, px */
  posErrMean: number
  posErrP95: number
  posErrMax: number
}

const key = (e: { type: string; hole?: number; via?: string }) => `${e.type}:${e.hole ?? 0}:${e.via ?? ''}`
const LIP_TYPES = new Set(['skip', 'capture', 'bounce', 'rimRoll'])

function endOf(events: readonly { type: string; hole?: number }[]): string {
  const last = events[events.length - 1]
  return last === undefined ? 'none' : last.type === 'capture' ? `capture:${last.hole}` : last.type
}

export function measureAccuracy(run: MethodRun, refs: readonly SolverResult[]): Accuracy {
  const n = refs.length
  let seq = 0
  let outcome = 0
  let pairs = 0
  let dSum = 0
  let dMax = 0
  let vSum = 0
  let vMax = 0
  const pos: number[] = []
  for (let i = 0; i < n; i++) {
    const got = run.events[i]!
    const want: readonly SolverEvent[] = refs[i]!.events
    if (got.length !== want.length || got.some((e, k) => key(e) !== key(want[k]!))) seq++
    if (endOf(got) !== endOf(want)) outcome++
    // (δ, v) at the lip: the first decision of each crossing, paired while both sequences visit the same holes
    const a = got.filter((e) => LIP_TYPES.has(e.type) && e.delta !== undefined)
    const b = want.filter((e) => LIP_TYPES.has(e.type) && e.delta !== undefined)
    for (let k = 0; k < Math.min(a.length, b.length); k++) {
      if (a[k]!.hole !== b[k]!.hole) break
      if (k > 0 && a[k]!.hole === a[k - 1]!.hole && a[k]!.delta === a[k - 1]!.delta) continue // same crossing
      const dd = Math.abs(a[k]!.delta! - b[k]!.delta!)
      const dv = Math.abs(a[k]!.speed! - b[k]!.speed!)
      pairs++
      dSum += dd
      vSum += dv
      if (dd > dMax) dMax = dd
      if (dv > vMax) vMax = dv
    }
    const f = run.finals[i]!
    pos.push(Math.hypot(f.x - refs[i]!.x, f.y - refs[i]!.y))
  }
  pos.sort((p, q) => p - q)
  const mean = (xs: number[]) => xs.reduce((s, x) => s + x, 0) / Math.max(1, xs.length)
  return {
    throws: n,
    sequenceDiffers: seq / n,
    outcomeDiffers: outcome / n,
    lipPairs: pairs,
    deltaErrMean: pairs > 0 ? dSum / pairs : 0,
    deltaErrMax: dMax,
    speedErrMean: pairs > 0 ? vSum / pairs : 0,
    speedErrMax: vMax,
    posErrMean: mean(pos),
    posErrP95: pos[Math.min(n - 1, Math.floor(0.95 * n))]!,
    posErrMax: pos[n - 1]!,
  }
}
