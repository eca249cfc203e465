// Physical reference model of a rigid sphere meeting a sharp circular lip (shared/spec/reference-model.md):
// the ground truth the game's six-stage model is charted against. See docs/reference-model.md.
export {
  referenceOutcome,
  referenceTrace,
  referenceCaptureSpeed,
  referenceCaptureOffset,
  singleImpactDeadCentreLimit,
  singleImpactEscapes,
  lipEnergy,
  rollOnLip,
  validateReferenceInput,
  LIP_RTOL,
  LIP_ATOL,
  MAX_PHASES,
  MAX_TIME,
} from './sphereLip.js'
export type {
  ReferenceInput,
  ReferenceOutcome,
  ReferenceEnding,
  ReferenceTrace,
  PhaseRecord,
  PhaseEnd,
  LipState,
} from './sphereLip.js'
export {
  dopri5,
  dopri5Interpolate,
  dopri5DenseOutput,
  createDopri5Workspace,
  brentRoot,
  DOPRI5_SAFETY,
  DOPRI5_MIN_FACTOR,
  DOPRI5_MAX_FACTOR,
  DOPRI5_PI_BETA,
  DOPRI5_DEFAULT_MAX_STEPS,
} from './dopri5.js'
export type { OdeRhs, EventFunction, OdeEvent, Dopri5Options, Dopri5Result, Dopri5Status, Dopri5Workspace } from './dopri5.js'
