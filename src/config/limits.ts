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
 * Shortest step the throw solver and the outcome estimates simulate a throw at, s (a world's MAX_STEP or a
 * request's step): they step each throw for up to 20–30 s, so at most 300,000 steps.
 */
export const MIN_OUTCOME_STEP = 1e-4
