// Guards and tolerances of the reference model, in scaled units (r = g = 1: lengths in r, times in √(r/g)):
// the lip integrator's tolerances and step caps, the flight search's sampling and root tolerance, the shortest
// hop resolved (held rolls), and the phase and time limits of a run.

/** DOPRI5 relative tolerance on the lip: E/m drifts ~3e-13 per time unit (measured 3.4e-10 over 1000 units) */
export const LIP_RTOL = 1e-11
/** DOPRI5 absolute tolerance on the lip (state components are O(1) in units r = g = 1) */
export const LIP_ATOL = 1e-12
/** largest lip step (time units √(r/g)): the lift-off function N cannot dip below 0 and back unseen */
export const LIP_MAX_STEP = 0.05
/** DOPRI5 step cap per lip phase (a 1000-unit roll takes ~10⁵ steps at the tolerances above) */
export const LIP_MAX_STEPS = 2_000_000
/** smallest flight search step: at most this time (units √(r/g)) ... */
export const FLIGHT_SAMPLE_TIME = 1 / 64
/** ... and at most this distance (units r) of travel; only a lip graze shorter than this can be missed */
export const FLIGHT_SAMPLE_DISTANCE = 0.02
/** a landing closer to the flight's start than this (time units) is the start itself (the first crossing) */
export const FLIGHT_MIN_TIME = 1e-9
/**
 * Shortest hop resolved (time units √(r/g); 1e-3 ≈ 47 µs for a golf ball): a flight whose gap to the lip is
 * not open at this time after take-off is treated as no flight (held roll, see HELD_EVENTS in lipRoll.ts).
 * Small enough to leave every ordinary lift-off and bounce alone (their gap ≈ −N t² or c t³ is far above
 * rounding here), large enough that chattering hops cannot pile up without end.
 */
export const HOLD_PROBE_TIME = 1e-3
/** a held ball is released into flight when its free path is open at this time (freePathClearance, flight.ts) */
export const HOLD_RELEASE_TIME = 2 * HOLD_PROBE_TIME
/** Brent tolerance on flight event times (time units): machine level for O(1) flight times */
export const FLIGHT_ROOT_TOL = 1e-14
/** lip and flight phases before the run is stopped (a chain of impacts shortening without end) */
export const MAX_PHASES = 400
/** time (units √(r/g)) before the run is stopped (a steady roll round the lip that never decides) */
export const MAX_TIME = 2000
/**
 * Integrator steps of the lip phases a live run inside the engine may take (a hero ball's crossing, a
 * tabulated crossing off its table): past it the crossing is left to the stages, as one the run's other
 * guards stop. On a 24 × 24 grid of (δ, v) for R/r from 1.001 to 2, every run that decided took at most
 * 18,819 steps (645 for R/r ≥ 1.08), and every steady roll to MAX_TIME 120,000–485,000 (60–210 ms each,
 * where the budget stops it within about 10 ms). Tables and the public functions run without it.
 */
export const LIVE_STEP_BUDGET = 20_000
/**
 * The model's domain, scaled: a hole at most MAX_RATIO ball radii wide, a ball at most MAX_SCALED_SPEED × √(g·r)
 * fast. Beyond them the geometry's differences (the gap to the lip beside R/r) or the squared speeds lose their
 * digits: at R/r = 1e10 the flight search stalls on steps that round away, at 1e14 it hung, at 1e20 a ball that
 * must drop in was reported as hopping out, and a speed of 1e160 overflowed. The public functions refuse such
 * input; the engine leaves such a crossing to the stages, as it does a ball not smaller than the hole.
 */
export const MAX_RATIO = 1e8
export const MAX_SCALED_SPEED = 1e12
/** flight search samples before the run is stopped (a guard; ordinary flights take a few hundred at most) */
export const FLIGHT_MAX_SAMPLES = 1_000_000
