// Bounds on what commands accept: they keep every derived quantity (squared distances, times, impulses)
// finite in double precision.

/** Largest |coordinate| accepted, px: keeps squares of distances far from overflow. */
export const MAX_COORDINATE = 1e9
/** Largest |velocity component| accepted, px/s. */
export const MAX_SPEED = 1e7
/** Largest radius accepted, px. */
export const MAX_RADIUS = 1e4
/** Largest |hole value| accepted. */
export const MAX_VALUE = 1e12
/** Largest ball mass accepted, in units of a default ball. */
export const MAX_MASS = 1e9
/**
 * Smallest ball mass accepted, and the least a default mass (radius / BALL_RADIUS)³ is taken as: 1 / mass and
 * every impulse stay finite (a mass of 5e-324 was accepted, its inverse overflowed, and the fixed tick hung or
 * gave NaN positions; a radius of 1e-120 gave a default mass of 0). A ball of radius 1e-3 with the default
 * BALL_RADIUS weighs 7.5e-13 by default, above it.
 */
export const MIN_MASS = 1e-15
/**
 * Shortest step the throw solver and the outcome estimates simulate a throw at, s (a world's MAX_STEP or a
 * request's step): they step each throw for up to 20–30 s, so at most 300,000 steps.
 */
export const MIN_OUTCOME_STEP = 1e-4
/**
 * Smallest hole-to-ball radius ratio R/r the tabulated rim model builds a table for. Closer to 1 the reference's
 * rolls round the lip last to its time limit, and a table's capture rows take minutes (R/r 1.084: 9 s for all
 * 32 rows; 1.071: 77 s; 1.059: 117 s); a crossing of such a ball in a tabulated world is left to the stages.
 */
export const MIN_TABLE_RATIO = 1.08
