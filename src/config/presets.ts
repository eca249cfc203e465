// The physical preset: the same six systems, with the capture window's shape and the constants fitted to
// the rigid-sphere reference at the game's geometry (R = 18 px, r = 11 px, g from the design's constants,
// solid ball j = 2/5). `npm run physical` refits them on the fine (δ, v) grid and says whether these
// values are still the best; docs/physical.md gives the fit and the numbers.
//
//   createBallPhysics(PHYSICAL_CONFIG)                 // or { ...PHYSICAL_CONFIG, ROLLING_DECEL: 200 }
//
// The design's constants stay the default (DEFAULT_CONFIG): this is a choice a game makes, not a fix.
import type { ConfigOverrides } from './design.js'

export const PHYSICAL_CONFIG: Readonly<ConfigOverrides> = Object.freeze({
  /** Penner's quadratic window v_c(δ) = V_MAX·(1 − δ²/R²) instead of the design's ellipse */
  CAPTURE_WINDOW: 'quadratic',
  /** fitted: best agreement with the reference's capture map (not its dead-centre limit, 655 px/s) */
  V_MAX: 507,
  /**
   * fitted: rim rolls above the reference's capture speed pop off instead of dropping in; the agreement is
   * flat below 0.25, and the fit keeps the longest roll within 0.1 point of the best so rolls stay visible
   */
  RIM_ROLL_MAX_TURNS: 0.25,
})

/**
 * The reference-tabulated rim model: every lip crossing decided by a table of the rigid-sphere reference at
 * the crossing's geometry (src/reference/rimTable.ts, systems/tabulatedRim.ts) instead of the six stages; a
 * ball that rolls round the lip rides it for the reference's time. Agrees with the live reference on
 * capture against escape on 99.98 % of the 180 × 200 (δ, v) grid (docs/physical.md).
 *
 *   createBallPhysics(TABULATED_CONFIG)                // or { ...TABULATED_CONFIG, BALL_COLLISIONS: 'on' }
 */
export const TABULATED_CONFIG: Readonly<ConfigOverrides> = Object.freeze({
  RIM_MODEL: 'tabulated',
})
