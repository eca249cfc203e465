// A small seeded generator (mulberry32): 32-bit integer arithmetic only, so the same seed gives the same
// numbers in every JavaScript engine. Used for the Monte Carlo throws (src/api/outcomes.ts); games may use
// it for throws that a server and a browser must draw alike.

/** A generator of uniform numbers in [0, 1) from a 32-bit seed. */
export function mulberry32(seed: number): () => number {
  let a = seed >>> 0
  return () => {
    a = (a + 0x6d2b79f5) >>> 0
    let t = a
    t = Math.imul(t ^ (t >>> 15), t | 1)
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61)
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296
  }
}
