// The reference's numerical tools as the package exports them: the same functions with their arguments
// checked first (a TypeError for the wrong type, a RangeError naming the field and its range), so a caller's
// NaN cannot pass for a root or make the integrator run without end. The model calls the unchecked ones
// (src/reference/brent.ts, dopri5.ts, singleImpact.ts) with arguments it made itself.
import { describe, readSpec } from '../check.js'
import { brentRoot as brentRootRaw } from './brent.js'
import { dopri5 as dopri5Raw, type Dopri5Options, type Dopri5Result, type Dopri5Workspace, type OdeEvent, type OdeRhs } from './dopri5.js'
import { singleImpactEscapes as singleImpactEscapesRaw } from './singleImpact.js'
import { MAX_RATIO, MAX_SCALED_SPEED } from './tolerances.js'
import { checkFinite } from './types.js'

/** the most steps a dopri5 call may be given (maxSteps): a run past it is a mistake, not a long problem */
const MAX_DOPRI5_STEPS = 1e9

function positiveNumber(field: string, v: unknown): number {
  if (typeof v !== 'number') throw new TypeError(`${field} must be a finite number > 0, got ${describe(v)}`)
  if (!(v > 0 && Number.isFinite(v))) throw new RangeError(`${field} must be a finite number > 0, got ${v}`)
  return v
}

function fn(field: string, v: unknown): void {
  if (typeof v !== 'function') throw new TypeError(`${field} must be a function, got ${describe(v)}`)
}

/** Brent's method on a bracket [a, b] (src/reference/brent.ts), its arguments checked. */
export function brentRoot(f: (x: number) => number, a: number, b: number, fa: number, fb: number, xtol: number, after: 1 | -1): number {
  fn('f', f)
  checkFinite('a', a)
  checkFinite('b', b)
  checkFinite('fa', fa)
  checkFinite('fb', fb)
  positiveNumber('xtol', xtol)
  if (after !== 1 && after !== -1) throw new RangeError(`after must be 1 or -1, got ${describe(after)}`)
  return brentRootRaw(f, a, b, fa, fb, xtol, after)
}

const OPTION_KEYS = ['rtol', 'atol', 'hMax', 'hInit', 'maxSteps'] as const

/** Dormand–Prince 5(4) with events (src/reference/dopri5.ts), its arguments checked. */
export function dopri5(ws: Dopri5Workspace, rhs: OdeRhs, t0: number, y: Float64Array, tEnd: number, opts: Dopri5Options, events: readonly OdeEvent[] = []): Dopri5Result {
  if (ws === null || typeof ws !== 'object' || !Number.isInteger(ws.n)) throw new TypeError(`ws must be a workspace from createDopri5Workspace, got ${describe(ws)}`)
  fn('rhs', rhs)
  checkFinite('t0', t0)
  checkFinite('tEnd', tEnd)
  if (!(y instanceof Float64Array)) throw new TypeError(`y must be a Float64Array, got ${describe(y)}`)
  if (y.length < ws.n) throw new RangeError(`y must hold at least the workspace's ${ws.n} components, got ${y.length}`)
  for (let i = 0; i < ws.n; i++) checkFinite(`y[${i}]`, y[i])
  const o = readSpec('opts', opts, OPTION_KEYS)
  positiveNumber('opts.rtol', o.rtol)
  positiveNumber('opts.atol', o.atol)
  if (o.hMax !== undefined) positiveNumber('opts.hMax', o.hMax)
  if (o.hInit !== undefined) positiveNumber('opts.hInit', o.hInit)
  if (o.maxSteps !== undefined) {
    const m = o.maxSteps
    if (typeof m !== 'number') throw new TypeError(`opts.maxSteps must be an integer in [1, ${MAX_DOPRI5_STEPS}], got ${describe(m)}`)
    if (!(Number.isInteger(m) && m >= 1 && m <= MAX_DOPRI5_STEPS)) throw new RangeError(`opts.maxSteps must be an integer in [1, ${MAX_DOPRI5_STEPS}], got ${m}`)
  }
  if (!Array.isArray(events)) throw new TypeError(`events must be an array of { g, direction }, got ${describe(events)}`)
  for (let e = 0; e < events.length; e++) {
    const ev = readSpec(`events[${e}]`, events[e], ['g', 'direction'] as const)
    fn(`events[${e}].g`, ev.g)
    if (ev.direction !== -1 && ev.direction !== 0 && ev.direction !== 1) throw new RangeError(`events[${e}].direction must be -1, 0 or 1, got ${describe(ev.direction)}`)
  }
  return dopri5Raw(ws, rhs, t0, y, tEnd, opts, events)
}

/** The δ = 0 single-impact escape test in scaled units (src/reference/singleImpact.ts), its arguments checked. */
export function singleImpactEscapes(vs: number, rs: number, j: number): boolean {
  if (typeof vs !== 'number') throw new TypeError(`vs must be a number in [0, ${MAX_SCALED_SPEED}], got ${describe(vs)}`)
  if (!(vs >= 0 && vs <= MAX_SCALED_SPEED)) throw new RangeError(`vs must be in [0, ${MAX_SCALED_SPEED}], got ${vs}`)
  if (typeof rs !== 'number') throw new TypeError(`rs must be a number in (1, ${MAX_RATIO}], got ${describe(rs)}`)
  if (!(rs > 1 && rs <= MAX_RATIO)) throw new RangeError(`rs (R/r) must be in (1, ${MAX_RATIO}], got ${rs}`)
  if (typeof j !== 'number') throw new TypeError(`j must be a number in (0, 2/3], got ${describe(j)}`)
  if (!(j > 0 && j <= 2 / 3)) throw new RangeError(`j must be in (0, 2/3], got ${j}`)
  return singleImpactEscapesRaw(vs, rs, j)
}
