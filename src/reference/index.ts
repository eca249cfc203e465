// Physical reference model of a rigid sphere meeting a sharp circular lip: the ground truth the game's
// six-stage model is charted against. See docs/reference-model.md.
export { referenceOutcome, referenceTrace } from './sphereLip.js'
export { referenceCaptureSpeed, referenceCaptureOffset } from './captureSearch.js'
export { singleImpactDeadCentreLimit } from './singleImpact.js'
export { brentRoot, dopri5, singleImpactEscapes } from './checked.js'
export { lipEnergy, rollOnLip } from './lipRoll.js'
export { validateReferenceInput } from './types.js'
export { LIP_RTOL, LIP_ATOL, MAX_PHASES, MAX_RATIO, MAX_SCALED_SPEED, MAX_TIME, LIVE_STEP_BUDGET } from './tolerances.js'
export type {
  ReferenceInput,
  ReferenceOutcome,
  ReferenceEnding,
  ReferenceTrace,
  PhaseRecord,
  PhaseEnd,
  LipState,
} from './types.js'
export {
  dopri5Interpolate,
  dopri5DenseOutput,
  createDopri5Workspace,
  DOPRI5_SAFETY,
  DOPRI5_MIN_FACTOR,
  DOPRI5_MAX_FACTOR,
  DOPRI5_PI_BETA,
  DOPRI5_DEFAULT_MAX_STEPS,
} from './dopri5.js'
export type { OdeRhs, EventFunction, OdeEvent, Dopri5Options, Dopri5Result, Dopri5Status, Dopri5Workspace } from './dopri5.js'
