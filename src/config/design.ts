// The design table's constants (docs/design.md §5) under their own names, plus the few the
// design leaves open (docs/decisions.md §3, §4, §5, §7): ROLLING_DECEL, RIM_ROLL_MAX_TURNS and the engine's clock bounds.
// GRAVITY and V_SKIP_MAX are one fact written twice (V_SKIP_MAX = R·√(2g/r)); resolveConfig keeps them
// consistent, so they can never disagree.
import { describe } from '../check.js'
import { CONSISTENCY_TOLERANCE } from './tolerances.js'
import { MAX_SPEED, MIN_TABLE_RATIO } from './limits.js'

/** How a world steps: the exact event-driven core, a tick-sampled port of the six stages, or v1's rule. */
export const METHODS = Object.freeze(['exact', 'naive', 'v1'] as const)
export type SimulationMethod = (typeof METHODS)[number]

/**
 * Ball-ball contacts: off (the default: balls pass through each other), on (exact: each contact at its
 * instant, systems/collisions.ts) or fixed (solved at fixed ticks of CONTACT_TICK, systems/fixedContacts.ts).
 */
export const COLLISION_MODES = Object.freeze(['off', 'on', 'fixed'] as const)
export type CollisionMode = (typeof COLLISION_MODES)[number]
/** When the fixed tick's pairs alone at their tick meet (config.CONTACT_TIMING). */
export const CONTACT_TIMINGS = Object.freeze(['auto', 'instant', 'tick'] as const)
export type ContactTiming = (typeof CONTACT_TIMINGS)[number]

export interface BallPhysicsConfig {
  /** R, hole radius, px. */
  HOLE_RADIUS: number
  /** r, ball radius, px. */
  BALL_RADIUS: number
  /** Speed at which the clean-capture window closes, px/s (Stage 1). */
  V_MAX: number
  /** Dead-centre skip speed, px/s (Stage 5): R·√(2g/r) at the default radii. */
  V_SKIP_MAX: number
  /** g, px/s², derived from V_SKIP_MAX unless overridden (then V_SKIP_MAX is derived from it). */
  GRAVITY: number
  /** e, normal coefficient of restitution at the rim (Stages 2 and 4). */
  RIM_RESTITUTION: number
  /** μ_t, share of tangential speed lost at a rim bounce (Stages 2 and 4). */
  RIM_FRICTION: number
  /** |v_t|/|v_n| above which a rim contact rolls instead of bouncing (Stage 3). */
  RIM_ROLL_RATIO: number
  /** μ_roll, exponential decay rate of the rim-roll speed, 1/s (Stage 3). */
  RIM_ROLL_FRICTION: number
  /** Rim-roll speed below which the ball drops in, px/s (Stage 3). */
  RIM_ROLL_DROP_SPEED: number
  /** Arc, in turns of the lip circle, after which a rolling ball pops off (Stage 3; missing from the design table). */
  RIM_ROLL_MAX_TURNS: number
  /** Throw speed at power 0, px/s. */
  MIN_VY: number
  /** Throw speed at power 1, px/s. */
  MAX_VY: number
  /** Constant rolling deceleration on the panel, px/s² (0: no rolling loss). */
  ROLLING_DECEL: number
  /**
   * Shape of the Stage 1 capture window: 'ellipse' (the design: δ_eff = R·√(1 − (v/V_MAX)²)) or
   * 'quadratic' (Penner's fit v_c(δ) = V_MAX·(1 − δ²/R²), so δ_eff = R·√(1 − v/V_MAX)); see docs/physical.md.
   */
  CAPTURE_WINDOW: CaptureWindowShape
  /**
   * How a lip crossing is decided: 'stages' (the design's six closed-form stages) or 'tabulated' (a table of
   * the rigid-sphere reference at the crossing's R/r and BALL_INERTIA: TABULATED_CONFIG, docs/physical.md).
   */
  RIM_MODEL: RimModel
  /** j in I = j·m·r² (2/5 solid, 2/3 thin shell): used by a hero ball's physical reference and the rim table. */
  BALL_INERTIA: number
  /** Largest dt that one step simulates, s; a longer step (a tab that slept) is cut to this. */
  MAX_STEP: number
  /** Bound on event passes in one step; a ball with more events than this finishes them next step. */
  MAX_EVENT_PASSES: number
  /** Stepping method (the schedule the API builds): 'exact' (default), 'naive' or 'v1' (docs/accuracy.md). */
  METHOD: SimulationMethod
  /** Sub-steps per step for the tick-sampled methods ('naive', 'v1'); 'exact' ignores it. */
  SUBSTEPS: number
  /**
   * Ball-ball contacts: 'off' (default; model no more than a scene needs), 'on' (exact, event-driven) or
   * 'fixed' (solved every CONTACT_TICK; for dense scenes). Both need METHOD 'exact' (README: which to pick).
   */
  BALL_COLLISIONS: CollisionMode
  /**
   * With BALL_COLLISIONS 'on': how far ahead, s, contacts are predicted (at least to the step's end). A
   * ball's predicted contacts are kept across steps until its path or a partner's changes, so a ball that
   * meets nothing is predicted about once per horizon instead of once per step; a longer horizon predicts
   * less often over longer swept paths. Changes cost only: every event and state is the same bit for bit
   * at any horizon (0: predict every step, as a step-by-step solver would).
   */
  PREDICTION_HORIZON: number
  /** With BALL_COLLISIONS 'fixed': the contact tick, s; contacts are solved at k·CONTACT_TICK. */
  CONTACT_TICK: number
  /**
   * With BALL_COLLISIONS 'fixed': 'instant': a pair alone at its tick (each ball in no other contact of the
   * tick and clear of the other balls within its reach, moved by no wall or rule) meets at the instant its
   * balls touch, as the exact method's pairs do, and its collision event is at that instant; 'tick': every
   * contact acts at its tick, up to one tick early (cheaper: 8–10 % of the panel bursts' contact time, 14–19 %
   * of a gas's run, whose contacts are mostly such pairs); 'auto' (default): 'instant' while the world has
   * holes, where a contact's instant decides which hole a ball ends in, else 'tick'.
   */
  CONTACT_TIMING: ContactTiming
  /**
   * With BALL_COLLISIONS 'fixed' and BALL_RESTITUTION above 0: most halvings of CONTACT_TICK taken where
   * balls close on their nearest partner by more than half their size a tick, which would otherwise lose an
   * elastic crowd's energy to the solve's inelastic bounds, and let a fast ball in a crowd of more than
   * SMALL_TICK_BALLS pass through its neighbours (docs/fixed-tick.md); at 4 (the default) the tick
   * goes down to CONTACT_TICK / 16 on this account; 0 leaves it off.
   */
  CONTACT_TRAVEL_HALVINGS: number
  /** With BALL_COLLISIONS 'fixed': most sweeps per tick of the velocity solve and of the overlap projection. */
  CONTACT_ITERATIONS: number
  /**
   * With BALL_COLLISIONS 'fixed': the work one CONTACT_TICK of the clock may spend on contacts, in visits to
   * every pair of its balls (n·(n − 1)/2 pairs of the n balls on the panel, n counted as at least 64): past
   * it, the span's remaining ticks are solved by a cheaper rule (docs/fixed-tick.md). Ordinary
   * scenes stay far within it; a pumped elastic crowd does not.
   */
  CONTACT_WORK_BUDGET: number
  /**
   * With BALL_COLLISIONS 'fixed' and CONTACT_WORK_BUDGET 0: a budget of the same kind that counts only the
   * work of pairs whose masses are UNLIKE_MASS_RATIO (1e4) or more apart, where a light ball squeezed between
   * heavy ones takes a number of meetings that grows with that ratio (docs/fixed-tick.md); 0 sets none. Its
   * unit is a visit to each pair the span's first try pairs (at least 64 balls' n·(n − 1)/2 = 2,016 pairs).
   * Scenes of like masses never spend it.
   */
  UNLIKE_MASS_BUDGET: number
  /** e between two balls, normal coefficient of restitution, [0, 1]. */
  BALL_RESTITUTION: number
  /**
   * With ball-ball contacts: px/s. A contact that would send a ball's velocity component beyond this (and
   * beyond what that component was before the contact) takes less restitution instead, down to none:
   * momentum is kept and kinetic energy falls further. Light balls between heavy ones gain speed at every
   * bounce (Fermi acceleration), without end in a closed elastic box; past this they gain no more, where
   * every px/s more costs ticks (the fixed tick) or events (the exact method). Never below what an inelastic
   * contact gives. At MAX_SPEED (1e7) only the commands' own speed limit bounds a contact, as before 0.3.0.
   */
  CONTACT_SPEED_LIMIT: number
  /**
   * Approach speed below which a ball-ball contact is perfectly inelastic (the two leave together), and,
   * with contacts on, normal speed below which a wall hit stops instead of bouncing, px/s. Ends the
   * ever-faster runs of ever-smaller contacts of balls pressed together (inelastic collapse).
   */
  BALL_SETTLE_SPEED: number
}

/** Rim models (config.RIM_MODEL). */
export const RIM_MODELS = Object.freeze(['stages', 'tabulated'] as const)
export type RimModel = (typeof RIM_MODELS)[number]

/** Capture window shapes (config.CAPTURE_WINDOW). */
export const CAPTURE_WINDOW_SHAPES = Object.freeze(['ellipse', 'quadratic'] as const)
export type CaptureWindowShape = (typeof CAPTURE_WINDOW_SHAPES)[number]

const HOLE_RADIUS = 18
const BALL_RADIUS = 11
const V_SKIP_MAX = 640

/** g implied by V_SKIP_MAX = R·√(2g/r): g = V_SKIP_MAX²·r / (2R²). */
export function gravityFromSkip(vSkipMax: number, holeRadius: number, ballRadius: number): number {
  return (vSkipMax * vSkipMax * ballRadius) / (2 * holeRadius * holeRadius)
}

/** V_SKIP_MAX implied by g: the dead-centre speed whose chord time equals the time to fall by r. */
export function skipFromGravity(gravity: number, holeRadius: number, ballRadius: number): number {
  return holeRadius * Math.sqrt((2 * gravity) / ballRadius)
}

export const DEFAULT_CONFIG: Readonly<BallPhysicsConfig> = Object.freeze({
  HOLE_RADIUS,
  BALL_RADIUS,
  V_MAX: 600,
  V_SKIP_MAX,
  GRAVITY: gravityFromSkip(V_SKIP_MAX, HOLE_RADIUS, BALL_RADIUS),
  RIM_RESTITUTION: 0.3,
  RIM_FRICTION: 0.3,
  RIM_ROLL_RATIO: 1.4,
  RIM_ROLL_FRICTION: 5.0,
  RIM_ROLL_DROP_SPEED: 110,
  RIM_ROLL_MAX_TURNS: 0.565,
  MIN_VY: 175,
  MAX_VY: 700,
  ROLLING_DECEL: 300,
  CAPTURE_WINDOW: 'ellipse',
  RIM_MODEL: 'stages',
  BALL_INERTIA: 2 / 5,
  MAX_STEP: 0.25,
  MAX_EVENT_PASSES: 256,
  METHOD: 'exact',
  SUBSTEPS: 1,
  BALL_COLLISIONS: 'off',
  PREDICTION_HORIZON: 0.1,
  CONTACT_TICK: 1 / 120,
  CONTACT_TIMING: 'auto',
  CONTACT_TRAVEL_HALVINGS: 4,
  CONTACT_ITERATIONS: 32,
  CONTACT_WORK_BUDGET: 0,
  UNLIKE_MASS_BUDGET: 16,
  BALL_RESTITUTION: 0.9,
  CONTACT_SPEED_LIMIT: 2e5,
  BALL_SETTLE_SPEED: 1,
})

/** Any keys of the config; a key given as undefined is as if it were absent. */
export type ConfigOverrides = { [K in keyof BallPhysicsConfig]?: BallPhysicsConfig[K] | undefined }

interface Range {
  min: number
  max: number
  minOpen?: boolean
  integer?: boolean
}

/** Keys whose value is one of a list of names. */
export type ChoiceKey = 'CAPTURE_WINDOW' | 'RIM_MODEL' | 'METHOD' | 'BALL_COLLISIONS' | 'CONTACT_TIMING'
type NumericKey = Exclude<keyof BallPhysicsConfig, ChoiceKey>

/** Allowed values of every key that names a choice. */
export const CONFIG_CHOICES: Readonly<Record<ChoiceKey, readonly string[]>> = Object.freeze({
  CAPTURE_WINDOW: CAPTURE_WINDOW_SHAPES,
  RIM_MODEL: RIM_MODELS,
  METHOD: METHODS,
  BALL_COLLISIONS: COLLISION_MODES,
  CONTACT_TIMING: CONTACT_TIMINGS,
})

/** Allowed range of every numeric key. Open lower bounds are for values that divide or must be positive. */
export const CONFIG_RANGES: Readonly<Record<NumericKey, Readonly<Range>>> = Object.freeze({
  HOLE_RADIUS: Object.freeze({ min: 0, max: 1e4, minOpen: true }),
  BALL_RADIUS: Object.freeze({ min: 0, max: 1e4, minOpen: true }),
  V_MAX: Object.freeze({ min: 0, max: 1e6, minOpen: true }),
  V_SKIP_MAX: Object.freeze({ min: 0, max: 1e6, minOpen: true }),
  GRAVITY: Object.freeze({ min: 0, max: 1e9, minOpen: true }),
  RIM_RESTITUTION: Object.freeze({ min: 0, max: 1 }),
  RIM_FRICTION: Object.freeze({ min: 0, max: 1 }),
  RIM_ROLL_RATIO: Object.freeze({ min: 0, max: 1e6 }),
  RIM_ROLL_FRICTION: Object.freeze({ min: 0, max: 1e6 }),
  RIM_ROLL_DROP_SPEED: Object.freeze({ min: 0, max: 1e6, minOpen: true }),
  RIM_ROLL_MAX_TURNS: Object.freeze({ min: 0, max: 100, minOpen: true }),
  MIN_VY: Object.freeze({ min: 0, max: 1e6 }),
  MAX_VY: Object.freeze({ min: 0, max: 1e6 }),
  ROLLING_DECEL: Object.freeze({ min: 0, max: 1e6 }),
  BALL_INERTIA: Object.freeze({ min: 0, max: 2 / 3, minOpen: true }),
  MAX_STEP: Object.freeze({ min: 0, max: 10, minOpen: true }),
  MAX_EVENT_PASSES: Object.freeze({ min: 1, max: 1e6, integer: true }),
  SUBSTEPS: Object.freeze({ min: 1, max: 64, integer: true }),
  PREDICTION_HORIZON: Object.freeze({ min: 0, max: 1 }),
  CONTACT_TICK: Object.freeze({ min: 1e-4, max: 0.1 }),
  CONTACT_TRAVEL_HALVINGS: Object.freeze({ min: 0, max: 10, integer: true }),
  CONTACT_ITERATIONS: Object.freeze({ min: 1, max: 64, integer: true }),
  CONTACT_WORK_BUDGET: Object.freeze({ min: 0, max: 1e6, integer: true }),
  UNLIKE_MASS_BUDGET: Object.freeze({ min: 0, max: 1e6, integer: true }),
  BALL_RESTITUTION: Object.freeze({ min: 0, max: 1 }),
  CONTACT_SPEED_LIMIT: Object.freeze({ min: 0, max: MAX_SPEED, minOpen: true }),
  BALL_SETTLE_SPEED: Object.freeze({ min: 0, max: 1e6 }),
})

export function describeRange(r: Range): string {
  return `${r.minOpen ? '(' : '['}${r.min}, ${r.max}]${r.integer ? ' (an integer)' : ''}`
}

function checkChoice(key: ChoiceKey, value: unknown): string {
  const allowed = CONFIG_CHOICES[key]
  const choices = allowed.map((a) => `'${a}'`).join(', ')
  // the wrong type (not a string) is a TypeError, a string not among the choices a RangeError, as for the numbers
  if (typeof value !== 'string') throw new TypeError(`config.${key} must be one of ${choices}, got ${describe(value)}`)
  if (!allowed.includes(value)) throw new RangeError(`config.${key} must be one of ${choices}, got '${value}'`)
  return value
}

function checkKey(key: NumericKey, value: unknown): number {
  const range = CONFIG_RANGES[key]
  if (typeof value !== 'number') {
    throw new TypeError(`config.${key} must be a number in ${describeRange(range)}, got ${describe(value)}`)
  }
  const ok =
    Number.isFinite(value) &&
    (range.minOpen ? value > range.min : value >= range.min) &&
    value <= range.max &&
    (!range.integer || Number.isInteger(value))
  if (!ok) throw new RangeError(`config.${key} must be in ${describeRange(range)}, got ${value}`)
  return value
}

/** A key derived from the others (GRAVITY from V_SKIP_MAX or the reverse, with the two radii): out of range, it says where it came from. */
function checkDerived(key: 'GRAVITY' | 'V_SKIP_MAX', value: number, from: string): void {
  try {
    checkKey(key, value)
  } catch (e) {
    if (!(e instanceof RangeError)) throw e
    throw new RangeError(`${e.message} (derived from config.${from}, HOLE_RADIUS and BALL_RADIUS: V_SKIP_MAX = HOLE_RADIUS·√(2·GRAVITY/BALL_RADIUS); change one of them)`)
  }
}

/**
 * Validates overrides and returns a complete, frozen config. Unknown keys, non-finite or out-of-range
 * values throw an error naming the key and its allowed range. GRAVITY and V_SKIP_MAX: give either and
 * the other is derived; give both and they must agree; give neither and V_SKIP_MAX (the design's number)
 * is kept while GRAVITY follows the radii.
 */
export function resolveConfig(overrides: ConfigOverrides = {}): Readonly<BallPhysicsConfig> {
  if (overrides === null || typeof overrides !== 'object' || Array.isArray(overrides)) {
    const got = overrides === null ? 'null' : Array.isArray(overrides) ? 'an array' : typeof overrides
    throw new TypeError(`config overrides must be an object of DEFAULT_CONFIG keys, got ${got}`)
  }
  // each key read once: what is validated is what is used
  const given: Record<string, unknown> = {}
  for (const key of Object.keys(overrides)) given[key] = (overrides as Record<string, unknown>)[key]
  const out = { ...DEFAULT_CONFIG } as BallPhysicsConfig
  for (const key of Object.keys(given)) {
    if (!(key in CONFIG_RANGES) && !(key in CONFIG_CHOICES)) {
      const known = [...Object.keys(CONFIG_RANGES), ...Object.keys(CONFIG_CHOICES)]
      throw new RangeError(`config.${key} is not a known key; known keys: ${known.join(', ')}`)
    }
    const value = given[key]
    if (value === undefined) continue
    if (key in CONFIG_CHOICES) {
      ;(out as unknown as Record<string, unknown>)[key] = checkChoice(key as ChoiceKey, value)
      continue
    }
    out[key as NumericKey] = checkKey(key as NumericKey, value)
  }
  if (out.RIM_MODEL !== 'stages' && out.METHOD !== 'exact') {
    throw new RangeError(`config.RIM_MODEL '${out.RIM_MODEL}' needs config.METHOD 'exact', got '${out.METHOD}'`)
  }
  if (out.BALL_COLLISIONS !== 'off' && out.METHOD !== 'exact') {
    throw new RangeError(`config.BALL_COLLISIONS '${out.BALL_COLLISIONS}' needs config.METHOD 'exact', got '${out.METHOD}'`)
  }
  if (out.RIM_MODEL === 'tabulated' && !(out.HOLE_RADIUS >= MIN_TABLE_RATIO * out.BALL_RADIUS)) {
    throw new RangeError(
      `config.BALL_RADIUS must be at most HOLE_RADIUS / ${MIN_TABLE_RATIO} = ${out.HOLE_RADIUS / MIN_TABLE_RATIO} with RIM_MODEL 'tabulated' ` +
        `(its table's rows take minutes closer to the hole's size), got ${out.BALL_RADIUS}`,
    )
  }
  if (out.MAX_VY < out.MIN_VY) {
    throw new RangeError(`config.MAX_VY must be in [MIN_VY = ${out.MIN_VY}, 1000000], got ${out.MAX_VY}`)
  }
  const hasG = given.GRAVITY !== undefined
  const hasSkip = given.V_SKIP_MAX !== undefined
  if (hasG && hasSkip) {
    const implied = skipFromGravity(out.GRAVITY, out.HOLE_RADIUS, out.BALL_RADIUS)
    if (Math.abs(implied - out.V_SKIP_MAX) > CONSISTENCY_TOLERANCE * out.V_SKIP_MAX) {
      throw new RangeError(
        `config.GRAVITY = ${out.GRAVITY} implies V_SKIP_MAX = ${implied}, but config.V_SKIP_MAX = ${out.V_SKIP_MAX}; ` +
          'give one of them (the other is derived) or values with V_SKIP_MAX = HOLE_RADIUS·√(2·GRAVITY/BALL_RADIUS); ' +
          'a config spread from DEFAULT_CONFIG or a world.config holds both: leave one out (const { GRAVITY, ...rest } = DEFAULT_CONFIG)',
      )
    }
  } else if (hasG) {
    out.V_SKIP_MAX = skipFromGravity(out.GRAVITY, out.HOLE_RADIUS, out.BALL_RADIUS)
    checkDerived('V_SKIP_MAX', out.V_SKIP_MAX, 'GRAVITY')
  } else {
    out.GRAVITY = gravityFromSkip(out.V_SKIP_MAX, out.HOLE_RADIUS, out.BALL_RADIUS)
    checkDerived('GRAVITY', out.GRAVITY, 'V_SKIP_MAX')
  }
  return Object.freeze(out)
}
