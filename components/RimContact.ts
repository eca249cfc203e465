// RimContact: a ball's business with the one hole whose lip circle its centre is inside (holes do not
// overlap, so there is at most one). While `hole` is set, that hole makes no new decision for the ball:
// this is the transit lock of Stage 5, used also after a bounce or a pop-off (docs/decisions.md §6).
//
// Pooled: the store is indexed by slot, not by ball id. A ball takes a slot (Ball.rim) when it gets a
// hole lock and gives it back when the lock ends (it leaves the lip circle, falls in, leaves the panel or
// is removed); the freed row is zeroed. Slot 0 is never handed out and stays zero, so a ball without a
// slot reads hole 0, mode None. At any moment only the balls inside a lip circle hold a slot, a small
// share of a large scene, so the store grows with the peak number of concurrent contacts instead of
// costing its 120 bytes for every ball. Read a ball's row as RimContact.x[rimSlot(world, ball)]; write
// only through acquireRim (src/world/rimSlots.ts). A row says nothing once its lock has ended.
//
// As a bitECS component, RimContact marks the balls a hole holds on its rim (mode rimRoll): query or
// observe it for rim contacts (src/world/ballMode.ts). Balls inside a lip circle without touching the rim
// (skipping, entering, in transit) hold a row but not the component.
import { createStore } from './store.js'

export const RimMode = Object.freeze({
  /** not inside any lip circle */
  None: 0,
  /** inside, decided, leaving (after a bounce or a pop-off, or added inside) */
  Transit: 1,
  /** inside, flying over (Stage 5) */
  Skipping: 2,
  /** inside, heading for the contact circle ρ_c = R − r/2 (passed the COG gate) */
  Entering: 3,
  /** rolling on the rim (Stage 3), or riding it (a tabulated roll) */
  Rolling: 4,
  /** carried across by the tabulated model: a bounce or skip on its way to the reference's exit point */
  Crossing: 5,
} as const)
export type RimModeCode = (typeof RimMode)[keyof typeof RimMode]
/** RimContact.ride: a tabulated ride round the lip that leaves at its end ('lipOut'), or drops in */
export const RIDE_LEAVES = 1
export const RIDE_DROPS = 2

export const RIM_MODE_NAMES = Object.freeze(['none', 'transit', 'skipping', 'entering', 'rolling', 'crossing'] as const)

export const RimContactSchema = Object.freeze({
  /** entity id of the hole, 0 when none */
  hole: Uint32Array,
  /** RimMode */
  mode: Uint8Array,
  /** 1 when delta/speed/lipTime describe a lip crossing (0 for a ball added inside a hole) */
  hasLip: Uint8Array,
  /** δ at the lip crossing, px */
  delta: Float64Array,
  /** v at the lip crossing, px/s */
  speed: Float64Array,
  /** simulation time of the lip crossing, s */
  lipTime: Float64Array,
  /** rim roll: angle of the ball centre about the hole centre, rad (atan2 convention, y down) */
  angle: Float64Array,
  /** rim roll: arc length rolled so far, px */
  arc: Float64Array,
  /** rim roll: angle at the start, rad */
  angle0: Float64Array,
  /** rim roll: tangential speed at the start, px/s */
  speed0: Float64Array,
  /** rim roll: +1 counter-clockwise in angle, −1 clockwise */
  direction: Int8Array,
  /** rim roll: start time, s */
  time0: Float64Array,
  /**
   * RIDE_LEAVES or RIDE_DROPS: a tabulated ride (RIM_MODEL 'tabulated'): over rideTime seconds the centre
   * turns rideTurn radians at a steady rate while its distance from the hole centre goes from rideFrom to
   * rideTo, then the ball leaves with (exitVx, exitVy) or drops in; 0: the design's Stage 3 roll
   */
  ride: Uint8Array,
  /** tabulated ride: turn of the centre about the hole, rad (≥ 0; the sense is `direction`) */
  rideTurn: Float64Array,
  /** tabulated ride: duration, s */
  rideTime: Float64Array,
  /**
   * tabulated ride: distance of the centre from the hole centre at the start and at the end, px; a crossing
   * (RimMode.Crossing): rideTo is the distance along its path to the exit point, and time0 and speed0 the
   * path's start time and speed (a path started since, by a wall or a strike, ends the crossing)
   */
  rideFrom: Float64Array,
  rideTo: Float64Array,
  /** tabulated ride or crossing that escapes: velocity it leaves with, px/s */
  exitVx: Float64Array,
  exitVy: Float64Array,
})

export const createRimContactStore = (capacity: number) => createStore(RimContactSchema, capacity)
export type RimContactStore = ReturnType<typeof createRimContactStore>
