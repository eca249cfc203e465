// Brent's root finder (Brent 1973): inverse quadratic interpolation and secant steps, safeguarded by
// bisection, on a bracketing interval. Used by DOPRI5's event location (on the dense-output interpolant), by
// the reference model's flight search and by the single-impact estimate.

/** iteration cap for Brent's method (it converges in far fewer for smooth functions) */
const BRENT_MAX_ITERATIONS = 200

/**
 * Brent's method on [a, b] where fa and fb have opposite signs (or one is zero). Returns a point within
 * about `xtol` of the root at which f has the sign `after` (or is zero): for an event, the first point at
 * which the crossing has happened, so the caller never starts the next phase just short of the surface.
 */
export function brentRoot(
  f: (x: number) => number,
  a: number,
  b: number,
  fa: number,
  fb: number,
  xtol: number,
  after: 1 | -1,
): number {
  if (fb === 0) return b
  if (fa === 0 && after * fb < 0) return a
  if (fa * fb > 0) throw new RangeError('brentRoot: the interval does not bracket a root')
  let c = a
  let fc = fa
  let d = b - a
  let e = d
  for (let iter = 0; iter < BRENT_MAX_ITERATIONS; iter++) {
    if ((fb > 0 && fc > 0) || (fb < 0 && fc < 0)) {
      c = a
      fc = fa
      d = b - a
      e = d
    }
    if (Math.abs(fc) < Math.abs(fb)) {
      a = b
      b = c
      c = a
      fa = fb
      fb = fc
      fc = fa
    }
    const tol1 = 2 * Number.EPSILON * Math.abs(b) + 0.5 * xtol
    const xm = 0.5 * (c - b)
    if (Math.abs(xm) <= tol1 || fb === 0) return fb === 0 || after * fb > 0 ? b : c
    if (Math.abs(e) >= tol1 && Math.abs(fa) > Math.abs(fb)) {
      // inverse quadratic interpolation (secant when only two points are distinct)
      const s = fb / fa
      let p: number
      let q: number
      if (a === c) {
        p = 2 * xm * s
        q = 1 - s
      } else {
        const qq = fa / fc
        const r = fb / fc
        p = s * (2 * xm * qq * (qq - r) - (b - a) * (r - 1))
        q = (qq - 1) * (r - 1) * (s - 1)
      }
      if (p > 0) q = -q
      p = Math.abs(p)
      if (2 * p < Math.min(3 * xm * q - Math.abs(tol1 * q), Math.abs(e * q))) {
        e = d
        d = p / q
      } else {
        d = xm
        e = d
      }
    } else {
      d = xm
      e = d
    }
    a = b
    fa = fb
    b += Math.abs(d) > tol1 ? d : xm > 0 ? tol1 : -tol1
    fb = f(b)
  }
  return after * fb >= 0 ? b : c
}
