// The allocation-free forms of sin, cos, exp and expm1 (src/math.ts) give every bit @stdlib's functions
// give (fdlibm's algorithms, which the simulation used before them and whose results its replays and
// cross-engine hashes hold), and allocate nothing.
import stdCos from '@stdlib/math-base-special-cos'
import stdExp from '@stdlib/math-base-special-exp'
import stdExpm1 from '@stdlib/math-base-special-expm1'
import stdSin from '@stdlib/math-base-special-sin'
import { build } from 'esbuild'
import fc from 'fast-check'
import { execFileSync } from 'node:child_process'
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs'
import { tmpdir } from 'node:os'
import { join, resolve } from 'node:path'
import { describe, expect, it } from 'vitest'
import { ARG, COS, RESULT, SIN, cos, exp, expSlot, expm1, expm1Slot, mathSlot, sin, sinCosSlot } from '../src/math.js'

const root = resolve(import.meta.dirname, '..')

type Fn = (x: number) => number
const STDLIB: [Fn, Fn, Fn, Fn] = [stdSin, stdCos, stdExp, stdExpm1]

/** the first argument (as a string) at which ours and the reference [sin, cos, exp, expm1] differ in any bit, or '' */
function firstDifference(xs: Iterable<number>, [stdSin, stdCos, stdExp, stdExpm1] = STDLIB): string {
  for (const x of xs) {
    mathSlot[ARG] = x
    sinCosSlot()
    const s = mathSlot[SIN]!
    const c = mathSlot[COS]!
    if (!Object.is(s, stdSin(x)) || !Object.is(sin(x), stdSin(x))) return `sin(${x}): ${s} against ${stdSin(x)}`
    if (!Object.is(c, stdCos(x)) || !Object.is(cos(x), stdCos(x))) return `cos(${x}): ${c} against ${stdCos(x)}`
    mathSlot[ARG] = x
    expSlot()
    if (!Object.is(mathSlot[RESULT], stdExp(x)) || !Object.is(exp(x), stdExp(x))) return `exp(${x}): ${mathSlot[RESULT]} against ${stdExp(x)}`
    mathSlot[ARG] = x
    expm1Slot()
    if (!Object.is(mathSlot[RESULT], stdExpm1(x)) || !Object.is(expm1(x), stdExpm1(x))) return `expm1(${x}): ${mathSlot[RESULT]} against ${stdExpm1(x)}`
  }
  return ''
}

function random(seed: number): () => number {
  let s = seed
  return () => {
    s = (s * 16807) % 2147483647
    return (s - 1) / 2147483646
  }
}

/** the doubles next to x, k steps either way */
function around(x: number, k: number): number[] {
  const f = new Float64Array([x])
  const i = new BigInt64Array(f.buffer)
  const out: number[] = []
  const at = i[0]!
  for (let d = -k; d <= k; d++) {
    i[0] = at + BigInt(d)
    out.push(f[0]!)
  }
  return out
}

describe('allocation-free sin, cos, exp, expm1', () => {
  it('give @stdlib’s bits over the ranges the simulation uses and far beyond', () => {
    const r = random(11)
    const xs: number[] = []
    for (let i = 0; i < 200_000; i++) xs.push((r() - 0.5) * 20) // angles, rim rolls' exponents
    for (let i = 0; i < 100_000; i++) xs.push((r() - 0.5) * 2 * 4e6) // the medium reduction and past it
    for (let i = 0; i < 100_000; i++) xs.push((r() - 0.5) * 1500) // exp's whole range and past it
    for (let i = 0; i < 50_000; i++) xs.push((r() - 0.5) * 2 ** (-60 + 70 * r())) // tiny to moderate
    expect(firstDifference(xs)).toBe('')
  })

  it('give @stdlib’s bits next to every threshold their branches test', () => {
    const xs: number[] = []
    // multiples of π/2, where the reduction cancels (its second and third steps), as far as the medium form
    for (let n = -2000; n <= 2000; n++) xs.push(...around((n * Math.PI) / 2, 3))
    for (let n = 1; n < 1e6; n = Math.ceil(n * 1.37)) xs.push(...around((n * Math.PI) / 2, 2), ...around((-n * Math.PI) / 2, 2))
    // the branch bounds: π/4, 3π/4, 5π/4, 3π/2, 7π/4, 2π, 9π/4, 2^20·π/2; 2^-26, 2^-27, 2^-28, 2^-54
    for (const b of [Math.PI / 4, (3 * Math.PI) / 4, (5 * Math.PI) / 4, (3 * Math.PI) / 2, (7 * Math.PI) / 4, 2 * Math.PI, (9 * Math.PI) / 4, 2 ** 20 * (Math.PI / 2)]) {
      xs.push(...around(b, 40), ...around(-b, 40))
    }
    for (const b of [2 ** -26, 2 ** -27, 2 ** -28, 2 ** -54]) xs.push(...around(b, 5), ...around(-b, 5))
    // exp's and expm1's: ½ln 2, 1.5 ln 2, 56 ln 2, the k at which the scaling changes form, overflow, underflow
    for (const b of [0.5 * Math.LN2, 1.5 * Math.LN2, 56 * Math.LN2, 20 * Math.LN2, 709.436, 709.782712893384, -745.1332191019411, -707.7, 708.4, -0.25]) {
      xs.push(...around(b, 40), ...around(-b, 40))
    }
    for (let k = -1080; k <= 1030; k++) xs.push(...around((k + 0.5) * Math.LN2, 2))
    xs.push(0, -0, NaN, Infinity, -Infinity, Number.MIN_VALUE, -Number.MIN_VALUE, Number.MAX_VALUE, -Number.MAX_VALUE, 1e300, -1e300)
    expect(firstDifference(xs)).toBe('')
  })

  it('give @stdlib’s bits at any double (fast-check)', () => {
    fc.assert(
      fc.property(fc.double(), (x) => firstDifference([x]) === ''),
      { numRuns: 50_000 },
    )
  })

  it('the check sees a one-bit difference in any of the four', () => {
    const oneBitOff = (f: Fn, at: number): Fn => (x) => {
      if (x !== at) return f(x)
      const v = new Float64Array([f(x)])
      new BigInt64Array(v.buffer)[0]! += 1n
      return v[0]!
    }
    for (let k = 0; k < 4; k++) {
      const reference = [...STDLIB] as [Fn, Fn, Fn, Fn]
      reference[k] = oneBitOff(reference[k]!, 0.75)
      expect(firstDifference([0.5, 0.75, 1], reference)).toMatch(/^(sin|cos|exp|expm1)\(0\.75\)/)
      expect(firstDifference([0.5, 1], reference)).toBe('')
    }
  })

  it('allocate nothing once optimised: under 0.05 bytes a call (a loop that boxes a double a call: 16)', async () => {
    const out = await build({
      absWorkingDir: root,
      entryPoints: ['tests/alloc/mathSlotsMain.ts'],
      bundle: true,
      format: 'esm',
      platform: 'node',
      write: false,
      logLevel: 'silent',
    })
    const dir = mkdtempSync(join(tmpdir(), 'math-slots-'))
    try {
      const file = join(dir, 'main.mjs')
      writeFileSync(file, out.outputFiles[0]!.text)
      const text = execFileSync(process.execPath, ['--expose-gc', '--min-semi-space-size=32', '--max-semi-space-size=32', file], { encoding: 'utf8', timeout: 60_000 })
      const { ours, control, sum } = JSON.parse(text.trim()) as { ours: number; control: number; sum: number }
      expect(Number.isFinite(sum)).toBe(true)
      expect(control, 'the control boxes a double a call (the measure can fail)').toBeGreaterThan(10)
      expect(ours).toBeLessThan(0.05)
    } finally {
      rmSync(dir, { recursive: true, force: true })
    }
  })


})
