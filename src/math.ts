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

/** sin x (x in radians), the same bits on every engine */
export const sin: (x: number) => number = stdSin
/** cos x (x in radians), the same bits on every engine */
export const cos: (x: number) => number = stdCos
/** The angle of (x, y) from the +x axis, in (−π, π], the same bits on every engine */
export const atan2: (y: number, x: number) => number = stdAtan2
/** e^x, the same bits on every engine */
export const exp: (x: number) => number = stdExp
/** e^x − 1, accurate for small x, the same bits on every engine */
export const expm1: (x: number) => number = stdExpm1
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
