// The portable elementary functions (src/math.ts) against the engine's Math: within 1 ulp (2 for atan2
// and hypot) over the ranges the simulation uses and far beyond, the same special values; and no file of the simulation calls a
// Math function whose rounding engines may differ on, or uses **.
import { readdirSync, readFileSync, statSync } from 'node:fs'
import { join, relative, resolve } from 'node:path'
import { describe, expect, it } from 'vitest'
import { atan2, cos, exp, expm1, hypot, log, log1p, pow, sin, sq } from '../src/math.js'

const root = resolve(import.meta.dirname, '..')
const f64 = new Float64Array(1)
const i64 = new BigInt64Array(f64.buffer)

/** Distance in units in the last place between two finite doubles of the same sign (0 when equal). */
function ulps(a: number, b: number): number {
  if (a === b) return 0
  if (!Number.isFinite(a) || !Number.isFinite(b)) return Number.POSITIVE_INFINITY
  f64[0] = a
  const ia = i64[0]!
  f64[0] = b
  const ib = i64[0]!
  if ((a < 0) !== (b < 0)) return Number.POSITIVE_INFINITY
  const d = ia > ib ? ia - ib : ib - ia
  return Number(d)
}

function random(seed: number): () => number {
  let s = seed
  return () => {
    s = (s * 16807) % 2147483647
    return (s - 1) / 2147483646
  }
}

/** Largest ulp distance over n arguments drawn from gen; also how many differ at all. */
function worst(n: number, gen: () => number[], ours: (...a: number[]) => number, theirs: (...a: number[]) => number): { max: number; differ: number } {
  let max = 0
  let differ = 0
  for (let i = 0; i < n; i++) {
    const args = gen()
    const u = ulps(ours(...args), theirs(...args))
    if (u > 0) differ++
    if (u > max) max = u
  }
  return { max, differ }
}

describe('portable elementary functions', () => {
  const r = random(7)
  const N = 100_000
  const cases: Array<[string, (...a: number[]) => number, (...a: number[]) => number, () => number[]]> = [
    ['sin on [−2π, 2π]', sin, Math.sin, () => [(r() - 0.5) * 4 * Math.PI]],
    ['sin on [−1e6, 1e6]', sin, Math.sin, () => [(r() - 0.5) * 2e6]],
    ['cos on [−2π, 2π]', cos, Math.cos, () => [(r() - 0.5) * 4 * Math.PI]],
    ['cos on [−1e6, 1e6]', cos, Math.cos, () => [(r() - 0.5) * 2e6]],
    ['atan2 on [−1e3, 1e3]²', atan2, Math.atan2, () => [(r() - 0.5) * 2e3, (r() - 0.5) * 2e3]],
    ['atan2 at tiny and huge ratios', atan2, Math.atan2, () => [(r() - 0.5) * 1e-9, (r() - 0.5) * 1e9]],
    ['exp on [−50, 50]', exp, Math.exp, () => [(r() - 0.5) * 100]],
    ['expm1 on [−1e-3, 1e-3]', expm1, Math.expm1, () => [(r() - 0.5) * 2e-3]],
    ['expm1 on [−50, 50]', expm1, Math.expm1, () => [(r() - 0.5) * 100]],
    ['log on (0, 1e6]', log, Math.log, () => [r() * 1e6 + 1e-300]],
    ['log near 1', log, Math.log, () => [1 + (r() - 0.5) * 1e-6]],
    ['log1p on (−1, 1e3]', log1p, Math.log1p, () => [-1 + 1e-12 + r() * 1e3]],
    ['pow of (0, 1e3] to [−1, 1]', pow, Math.pow, () => [r() * 1e3 + 1e-12, (r() - 0.5) * 2]],
    ['pow of (0, 2] to [−0.25, −0.1] (the ODE step control)', pow, Math.pow, () => [r() * 2 + 1e-12, -0.1 - 0.15 * r()]],
  ]
  for (const [name, ours, theirs, gen] of cases) {
    const bound = name.startsWith('atan2') ? 2 : 1
    it(`${name}: within ${bound} ulp of Math`, () => {
      const { max } = worst(N, gen, ours, theirs)
      expect(max).toBeLessThanOrEqual(bound)
    })
  }

  it('hypot and sq are the plain products and square root, within 2 ulp of Math.hypot', () => {
    const { max } = worst(N, () => [(r() - 0.5) * 2e5, (r() - 0.5) * 2e5], hypot, Math.hypot)
    expect(max).toBeLessThanOrEqual(2)
    expect(hypot(3, 4)).toBe(5)
    expect(sq(1.5)).toBe(2.25)
  })

  it('the special values are those of Math', () => {
    const specials = [Number.NaN, 0, -0, Infinity, -Infinity, 1, -1, 0.5, -2.5, 3, 1e-310, Number.MAX_VALUE, -Number.MAX_VALUE]
    const same = (a: number, b: number) => Object.is(a, b)
    for (const x of specials) {
      expect(same(sin(x), Math.sin(x))).toBe(true)
      expect(same(cos(x), Math.cos(x))).toBe(true)
      expect(same(exp(x), Math.exp(x)) || ulps(exp(x), Math.exp(x)) <= 1).toBe(true)
      expect(same(expm1(x), Math.expm1(x)) || ulps(expm1(x), Math.expm1(x)) <= 1).toBe(true)
      expect(same(log(x), Math.log(x)) || ulps(log(x), Math.log(x)) <= 1).toBe(true)
      expect(same(log1p(x), Math.log1p(x)) || ulps(log1p(x), Math.log1p(x)) <= 1).toBe(true)
      for (const y of specials) {
        expect(same(atan2(y, x), Math.atan2(y, x)) || ulps(atan2(y, x), Math.atan2(y, x)) <= 2).toBe(true)
        expect(same(pow(x, y), Math.pow(x, y)) || ulps(pow(x, y), Math.pow(x, y)) <= 1).toBe(true)
      }
    }
  })

  it('the ulp measure sees a one-bit difference (the bounds above can fail)', () => {
    expect(ulps(0.1, 0.1 + 2 ** -56)).toBe(1)
    expect(ulps(1, 1)).toBe(0)
    expect(ulps(Number.MAX_VALUE, Infinity)).toBe(Infinity)
    expect(ulps(Number.NaN, 1)).toBe(Infinity)
  })
})

/** Inexact Math functions: engines round them differently. */
const INEXACT = /\bMath\.(sin|cos|tan|asin|acos|atan|atan2|sinh|cosh|tanh|asinh|acosh|atanh|exp|expm1|log|log1p|log2|log10|pow|cbrt|hypot)\b/

function stripComments(text: string): string {
  return text.replace(/\/\*[\s\S]*?\*\//g, (m) => m.replace(/[^\n]/g, ' ')).replace(/\/\/.*$/gm, '')
}

function sourceFiles(dir: string): string[] {
  const out: string[] = []
  for (const name of readdirSync(dir)) {
    const p = join(dir, name)
    if (statSync(p).isDirectory()) out.push(...sourceFiles(p))
    else if (p.endsWith('.ts')) out.push(p)
  }
  return out
}

/** Places where `text` calls an inexact Math function or uses **, as "line: code" */
function offences(text: string): string[] {
  const lines = stripComments(text).split('\n')
  const found: string[] = []
  lines.forEach((line, i) => {
    if (INEXACT.test(line) || /\*\*/.test(line)) found.push(`${i + 1}: ${line.trim()}`)
  })
  return found
}

describe('the simulation uses only portable arithmetic', () => {
  it('no file under src/, systems/ or components/ calls an inexact Math function or uses ** (src/math.ts is the one place)', () => {
    const bad: string[] = []
    for (const dir of ['src', 'systems', 'components']) {
      for (const file of sourceFiles(join(root, dir))) {
        const rel = relative(root, file)
        if (rel === join('src', 'math.ts')) continue
        for (const o of offences(readFileSync(file, 'utf8'))) bad.push(`${rel}:${o}`)
      }
    }
    expect(bad).toEqual([])
  })

  it('the check sees a call and a power, and skips comments', () => {
    expect(offences('const a = Math.sin(x)')).toHaveLength(1)
    expect(offences('const a = x ** 2')).toHaveLength(1)
    expect(offences('/** Math.sin(x) ** 2 */\n// Math.pow(x, 2)\nconst a = Math.sqrt(x)')).toEqual([])
  })
})
