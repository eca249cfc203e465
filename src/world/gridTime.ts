// The instants of the world's contact grid, k·CONTACT_TICK / 2^h (the exact method's launch instants, the
// fixed tick's ticks at h halvings, the ends a step snaps to): the double nearest the rational time. Where
// CONTACT_TICK is 1/N s for a whole N (1/120 s, the default), the instant is the division k / (N·2^h),
// rounded once: the same double as m / n for every rate n whose step boundary m/n it is (src/schedule.ts,
// rateEnd), and the same at every spacing (k·2^h / (N·2^h) is k / N). Elsewhere the product k·(CONTACT_TICK
// / 2^h), itself the same double at every spacing (a power of two scales it exactly). As a product on
// the 1/N grid, 23 steps of 1/60 s read 0.3833333333333333, an ulp short of 23/60, and a game comparing the
// clock with 23 / 60 fired a step late at 60 Hz and not at 240 Hz.

import type { BallWorld } from './createWorld.js'

/** N when `tick` is the double nearest 1/N for a whole N (up to 2^30), else 0. */
function wholeRate(tick: number): number {
  const n = Math.round(1 / tick)
  return n >= 1 && n <= 0x40000000 && 1 / n === tick ? n : 0
}

/**
 * gridInstant(CONTACT_TICK, h, k) into instantOut[0]: for the fixed tick's clock, at every tick. Indices in,
 * the double out through a slot: V8 boxes a double passed to or returned from a call it does not inline. The
 * division is written out here, not a call of gridInstant: inlined into runPasses, whose inlining budget
 * is spent, this function's own calls stay calls (a call of wholeRate boxed the tick at every tick), so
 * wholeRate's test is written out too.
 */
export function tickInstant(w: BallWorld, h: number, k: number): void {
  const tick = w.config.CONTACT_TICK
  const r = Math.round(1 / tick)
  const n = r >= 1 && r <= 0x40000000 && 1 / r === tick ? r : 0
  instantOut[0] = n > 0 ? k / (n * (1 << h)) : k * (tick / (1 << h))
}

/** tickInstant's answer */
export const instantOut = new Float64Array(1)

/** The k-th instant of the grid of spacing `tick` / 2^h, `tick` being CONTACT_TICK (see above). */
export function gridInstant(tick: number, h: number, k: number): number {
  const n = wholeRate(tick)
  return n > 0 ? k / (n * (1 << h)) : k * (tick / (1 << h))
}
