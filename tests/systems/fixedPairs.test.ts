// The fixed-tick pair helpers (src/contacts/fixedPairs.ts): apart(), the projection's shortcut past pairs
// whose balls are clearly apart, never passes by a pair that normal() would find overlapping.
import fc from 'fast-check'
import { describe, expect, it } from 'vitest'
import { apart, normal, nrm } from '../../src/contacts/fixedPairs'
import type { FixedContactState } from '../../src/world/fixedState'

/** Two candidates, 0 and 1, as the projection reads them. */
function pair(x0: number, y0: number, r0: number, x1: number, y1: number, r1: number): FixedContactState {
  const f = (a: number, b: number) => new Float64Array([a, b])
  return { x: f(x0, x1), y: f(y0, y1), r: f(r0, r1), vx: f(0, 0), vy: f(0, 0) } as unknown as FixedContactState
}

describe('fixed tick: apart() against normal()', () => {
  it('a pair apart() passes by has gap ≥ 0 by normal(), for radii 1e-3 to 1e4 at centres up to 1e5 px out, within 3e-6 of touching', () => {
    let passed = 0
    let near = 0
    fc.assert(
      fc.property(
        fc.double({ min: -1e5, max: 1e5, noNaN: true }),
        fc.double({ min: -1e5, max: 1e5, noNaN: true }),
        fc.double({ min: 1e-3, max: 1e4, noNaN: true }),
        fc.double({ min: 1e-3, max: 1e4, noNaN: true }),
        fc.double({ min: 0, max: 2 * Math.PI, noNaN: true }),
        fc.double({ min: -3e-6, max: 3e-6, noNaN: true }),
        (x, y, ra, rb, angle, off) => {
          const d = (ra + rb) * (1 + off)
          const F = pair(x, y, ra, x + d * Math.cos(angle), y + d * Math.sin(angle), rb)
          if (!apart(F, 0, 1)) {
            near++
            return
          }
          passed++
          normal(F, 0, 1)
          expect(nrm.gap).toBeGreaterThanOrEqual(0)
        },
      ),
      { numRuns: 20000, seed: 11 },
    )
    // both sides of the shortcut were drawn (with no margin, APART = 1, the property fails: a pair 1.7e-18 px
    // deep by normal() was passed by)
    expect(passed).toBeGreaterThan(200)
    expect(near).toBeGreaterThan(200)
  })

  it('a pair touching or overlapping is never apart()', () => {
    expect(apart(pair(0, 0, 1, 2, 0, 1), 0, 1)).toBe(false)
    expect(apart(pair(0, 0, 1, 1.5, 0, 1), 0, 1)).toBe(false)
    expect(apart(pair(0, 0, 1, 2.01, 0, 1), 0, 1)).toBe(true)
  })
})
