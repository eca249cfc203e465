// Portable elementary functions: the only transcendental functions the simulation uses.
//
// IEEE 754 fixes the result of +, −, ×, ÷ and √ to the bit, but not of Math.sin, cos, atan2, exp, log,
// pow or hypot: each JavaScript engine takes them from its own library (V8 and SpiderMonkey from their
// copies of fdlibm, JavaScriptCore from the system's libm), and they differ in the last bit on some
// arguments. A simulation that called them would drift apart, bit by bit, between a server in Node and a
// player's browser. These are fdlibm's algorithms written in plain arithmetic (the @stdlib packages,
// bundled into the build), so every engine computes the same bits. Errors against Math are tested
// (tests/math.test.ts): within 1 ulp of V8's, 2 for atan2 and hypot (each side within an ulp of the
// true value, on opposite sides), and the same special values.
// tests/math.test.ts also fails if a file of the simulation calls one of Math's inexact functions or
// uses the ** operator.
import stdAtan2 from '@stdlib/math-base-special-atan2'
import stdCos from '@stdlib/math-base-special-cos'
import stdExp from '@stdlib/math-base-special-exp'
import stdExpm1 from '@stdlib/math-base-special-expm1'
import stdLn from '@stdlib/math-base-special-ln'
import stdLog1p from '@stdlib/math-base-special-log1p'
import stdPow from '@stdlib/math-base-special-pow'
import stdSin from '@stdlib/math-base-special-sin'

/** sin x (x in radians), the same bits on every engine (sinCosSlot's) */
export function sin(x: number): number {
  mathSlot[ARG] = x
  sinCosSlot()
  return mathSlot[SIN]!
}
/** cos x (x in radians), the same bits on every engine (sinCosSlot's) */
export function cos(x: number): number {
  mathSlot[ARG] = x
  sinCosSlot()
  return mathSlot[COS]!
}
/** The angle of (x, y) from the +x axis, in (−π, π], the same bits on every engine */
export const atan2: (y: number, x: number) => number = stdAtan2
/** e^x, the same bits on every engine (expSlot's) */
export function exp(x: number): number {
  mathSlot[ARG] = x
  expSlot()
  return mathSlot[RESULT]!
}
/** e^x − 1, accurate for small x, the same bits on every engine (expm1Slot's) */
export function expm1(x: number): number {
  mathSlot[ARG] = x
  expm1Slot()
  return mathSlot[RESULT]!
}
/** natural logarithm, the same bits on every engine */
export const log: (x: number) => number = stdLn
/** ln(1 + x), accurate for small x, the same bits on every engine */
export const log1p: (x: number) => number = stdLog1p
/**
 * x^y, the same bits on every engine. ECMAScript fixes the result exactly when an argument is zero,
 * infinite or NaN (Math.pow then, whose C-library cousin disagrees on several: pow(1, ∞), pow(NaN, 0));
 * otherwise fdlibm's algorithm.
 */
export function pow(x: number, y: number): number {
  if (y === 0) return 1
  if (x === 0 || !Number.isFinite(x) || !Number.isFinite(y)) return Math.pow(x, y)
  // |y| ≥ 2^53 is an even integer: the sign of a negative base drops out
  if (x < 0 && (y >= 9007199254740992 || y <= -9007199254740992)) return stdPow(-x, y)
  return stdPow(x, y)
}

/**
 * √(x² + y²) in plain arithmetic (Math.hypot's rounding differs between engines). Exact to the rounding
 * of the sum for the magnitudes the simulation sees (|x|, |y| below 1e150; the limits keep them far below).
 */
export function hypot(x: number, y: number): number {
  return Math.sqrt(x * x + y * y)
}

/** x² as one multiplication (x ** 2 may go through the engine's pow) */
export function sq(x: number): number {
  return x * x
}

// Allocation-free forms. V8 boxes a double passed to or returned from a function it does not inline (a
// heap number, 16 bytes), and fdlibm's sin, cos, exp and expm1 are a chain of such calls (the reduction,
// the kernels, the polynomials): a rim-rolling ball sampled at every step's end allocated at every one.
// These are the same algorithms, step for step and constant for constant (the @stdlib code above, itself
// fdlibm's), written flat with their argument and results in mathSlot: nothing crosses a call as a double.
// Arguments the simulation never sees (|x| ≥ 2^20·π/2 for sin and cos, results out of the normal range for
// exp) go to the @stdlib functions themselves. tests/mathSlots.test.ts checks every bit against them.

/** The argument (ARG) and results (SIN, COS; RESULT) of sinCosSlot, expSlot and expm1Slot. */
export const mathSlot = new Float64Array(3)
export const ARG = 0
export const SIN = 1
export const COS = 2
export const RESULT = 1

/** a double's two 32-bit words; HI the index of the high word (the sign, the exponent, 20 bits of significand) */
const WORD = new Float64Array(1)
const WORDS = new Uint32Array(WORD.buffer)
const HI = new Uint8Array(new Uint16Array([1]).buffer)[0] === 1 ? 1 : 0
const LO = 1 - HI

/**
 * sin and cos of mathSlot[ARG] into mathSlot[SIN], mathSlot[COS]: fdlibm's reduction by π/2 (rem_pio2,
 * its cases up to 9π/4 and its medium form) and its kernels on the remainder y0 + y1.
 */
export function sinCosSlot(): void {
  const x = mathSlot[ARG]!
  WORD[0] = x
  const hx = WORDS[HI]! | 0
  const ix = hx & 0x7fffffff
  if (ix >= 0x7ff00000) {
    mathSlot[SIN] = NaN
    mathSlot[COS] = NaN
    return
  }
  if (ix >= 0x413921fb) {
    // |x| ≥ 2^20·π/2: Payne–Hanek, in @stdlib
    mathSlot[SIN] = stdSin(x)
    mathSlot[COS] = stdCos(x)
    return
  }
  // x = n·π/2 + (y0 + y1)
  let n: number
  let y0: number
  let y1: number
  const PIO2_1 = 1.57079632673412561417
  const PIO2_1T = 6.07710050650619224932e-11
  if (ix <= 0x3fe921fb) {
    // |x| ≲ π/4: the kernels on x itself
    n = 0
    y0 = x
    y1 = 0
  } else if (ix > 0x401c463b || ((ix & 0xfffff) === 0x921fb && ix <= 0x400f6a7a) || ix === 0x4012d97c || ix === 0x401921fb) {
    // past 9π/4, or near a multiple of π/2 below it: round(x·2/π) and three-part subtraction as far as the cancellation needs
    n = Math.round(x * 6.36619772367581382433e-1)
    let r = x - n * PIO2_1
    let w = n * PIO2_1T
    const j = ix >> 20
    y0 = r - w
    WORD[0] = y0
    let i = j - ((WORDS[HI]! >> 20) & 0x7ff)
    if (i > 16) {
      let t = r
      w = n * 6.0771005063039659766e-11
      r = t - w
      w = n * 2.02226624879595063154e-21 - (t - r - w)
      y0 = r - w
      WORD[0] = y0
      i = j - ((WORDS[HI]! >> 20) & 0x7ff)
      if (i > 49) {
        t = r
        w = n * 2.0222662487111664558e-21
        r = t - w
        w = n * 8.47842766036889956997e-32 - (t - r - w)
        y0 = r - w
      }
    }
    y1 = r - y0 - w
  } else {
    // |x| within 9π/4, away from the multiples of π/2 the medium form handles: k·π/2 subtracted directly
    const k = ix <= 0x4002d97c ? 1 : ix <= 0x400f6a7a ? 2 : ix <= 0x4015fdbc ? 3 : 4
    const tail = k * PIO2_1T
    const head = k * PIO2_1
    if (hx > 0) {
      const z = x - head
      y0 = z - tail
      y1 = z - y0 - tail
      n = k
    } else {
      const z = x + head
      y0 = z + tail
      y1 = z - y0 + tail
      n = -k
    }
  }
  // the kernels on y0 + y1
  const z = y0 * y0
  const w = z * z
  const r = 0.00833333333332248946124 + z * (-1.98412698298579493134e-4 + z * 2.75573137070700676789e-6) + z * w * (-2.50507602534068634195e-8 + z * 1.58969099521155010221e-10)
  const v = z * y0
  const ks = y1 === 0 ? y0 + v * (-1.66666666666666324348e-1 + z * r) : y0 - (z * (0.5 * y1 - v * r) - y1 - v * -1.66666666666666324348e-1)
  let rc = z * (0.0416666666666666 + z * (-0.001388888888887411 + z * 0.00002480158728947673))
  rc += w * w * (-2.7557314351390663e-7 + z * (2.087572321298175e-9 + z * -1.1359647557788195e-11))
  const hz = 0.5 * z
  const u = 1.0 - hz
  const kc = u + ((1.0 - u - hz) + (z * rc - y0 * y1))
  if (n === 0 && ix < 0x3e500000) {
    // sin x = x below 2^-26, cos x = 1 below 2^-27
    mathSlot[SIN] = x
    mathSlot[COS] = ix < 0x3e400000 ? 1 : kc
    return
  }
  switch (n & 3) {
    case 0:
      mathSlot[SIN] = ks
      mathSlot[COS] = kc
      break
    case 1:
      mathSlot[SIN] = kc
      mathSlot[COS] = -ks
      break
    case 2:
      mathSlot[SIN] = -ks
      mathSlot[COS] = -kc
      break
    default:
      mathSlot[SIN] = -kc
      mathSlot[COS] = ks
  }
}

/** e^x of mathSlot[ARG] into mathSlot[RESULT]: @stdlib's exp (reduction by k·ln 2, its rational form, 2^k). */
export function expSlot(): void {
  const x = mathSlot[ARG]!
  if (!(x > -7.45133219101941108420e2 && x <= 7.09782712893383973096e2)) {
    // NaN, ±∞, overflow, underflow
    mathSlot[RESULT] = stdExp(x)
    return
  }
  if (x > -3.725290298461914e-9 && x < 3.725290298461914e-9) {
    mathSlot[RESULT] = 1.0 + x
    return
  }
  // k as an int32 (@stdlib truncates to a double: −0 where this has 0, which changes no bit below, as
  // x − k·ln2_hi and k·ln2_lo are then x and a zero either way)
  const k = (x < 0 ? 1.442695040888963387 * x - 0.5 : 1.442695040888963387 * x + 0.5) | 0
  if (k < -1020 || k > 1022) {
    // e^x near the ends of the normal range: 2^k below is not a normal double
    mathSlot[RESULT] = stdExp(x)
    return
  }
  const hi = x - k * 6.9314718036912381649e-1
  const lo = k * 1.90821492927058770002e-10
  const r = hi - lo
  const t = r * r
  const c = r - t * (0.16666666666666602 + t * (-0.0027777777777015593 + t * (0.00006613756321437934 + t * (-0.0000016533902205465252 + t * 4.1381367970572385e-8))))
  const y = 1.0 - (lo - (r * c) / (2.0 - c) - hi)
  // y·2^k, exact: y is within [0.7, 1.5] and the result normal, as ldexp makes it
  WORDS[HI] = (1023 + k) << 20
  WORDS[LO] = 0
  mathSlot[RESULT] = y * WORD[0]!
}

/** e^x − 1 of mathSlot[ARG] into mathSlot[RESULT]: fdlibm's expm1, as @stdlib writes it. */
export function expm1Slot(): void {
  let x = mathSlot[ARG]!
  if (x === 0) {
    // ±0
    mathSlot[RESULT] = x
    return
  }
  if (!(x > -3.88162421113569373274e1 && x < 7.09782712893383973096e2)) {
    // NaN, ±∞, x ≤ −56·ln 2 (−1), overflow
    mathSlot[RESULT] = stdExpm1(x)
    return
  }
  const sign = x < 0
  const y = sign ? -x : x
  WORD[0] = y
  const hx = WORDS[HI]! | 0
  let k: number
  let c = 0
  if (y > 0.34657359027997264) {
    let hi: number
    let lo: number
    if (y < 1.03972077083991796413) {
      if (sign) {
        hi = x + 6.9314718036912381649e-1
        lo = -1.90821492927058770002e-10
        k = -1
      } else {
        hi = x - 6.9314718036912381649e-1
        lo = 1.90821492927058770002e-10
        k = 1
      }
    } else {
      k = (sign ? 1.442695040888963387 * x - 0.5 : 1.442695040888963387 * x + 0.5) | 0
      hi = x - k * 6.9314718036912381649e-1
      lo = k * 1.90821492927058770002e-10
    }
    x = hi - lo
    c = hi - x - lo
  } else if (hx < 1016070144) {
    // |x| < 2^-54
    mathSlot[RESULT] = x
    return
  } else k = 0
  const halfX = 0.5 * x
  const z = x * halfX
  const r1 = 1.0 + z * (-0.03333333333333313 + z * (0.0015873015872548146 + z * (-0.0000793650757867488 + z * (0.000004008217827329362 + z * -2.0109921818362437e-7))))
  let t = 3.0 - r1 * halfX
  let e = z * ((r1 - t) / (6.0 - x * t))
  if (k === 0) {
    mathSlot[RESULT] = x - (x * e - z)
    return
  }
  e = x * (e - c) - c
  e -= z
  if (k === -1) {
    mathSlot[RESULT] = 0.5 * (x - e) - 0.5
    return
  }
  if (k === 1) {
    mathSlot[RESULT] = x < -0.25 ? -2.0 * (e - (x + 0.5)) : 1.0 + 2.0 * (x - e)
    return
  }
  if (k > 1023) {
    // x within about 0.35 of the overflow: 2^k is not a double
    mathSlot[RESULT] = stdExpm1(mathSlot[ARG]!)
    return
  }
  WORDS[HI] = (1023 + k) << 20
  WORDS[LO] = 0
  const twopk = WORD[0]!
  if (k <= -2 || k > 56) {
    mathSlot[RESULT] = (1.0 - (e - x)) * twopk - 1.0
    return
  }
  if (k < 20) {
    // t = 1 − 2^-k
    WORDS[HI] = 1072693248 - (0x200000 >> k)
    WORDS[LO] = 0
    t = WORD[0]!
    mathSlot[RESULT] = (t - (e - x)) * twopk
    return
  }
  // t = 2^-k
  WORDS[HI] = (1023 - k) << 20
  WORDS[LO] = 0
  t = WORD[0]!
  mathSlot[RESULT] = (x - (e + t) + 1.0) * twopk
}
