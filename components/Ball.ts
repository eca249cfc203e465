// Ball: the physical state a game reads. Position and velocity are the ball's state at the end of the
// last step. Indexed by entity id: a ball is a bitECS entity carrying this component (src/world/balls.ts);
// `live` says which ids are balls.
import { createStore } from './store.js'

export const BallMode = Object.freeze({
  Rolling: 0,
  RimRoll: 1,
  Captured: 2,
  Resting: 3,
  /** left the panel through an open edge of the walls */
  Out: 4,
  /**
   * put down (with ball-ball contacts on) where another ball is: it waits at its spot, out of the
   * simulation, with the velocity it was given, until the spot is clear (systems/launcher.ts)
   */
  Held: 5,
} as const)
export type BallModeCode = (typeof BallMode)[keyof typeof BallMode]
export const BALL_MODE_NAMES = Object.freeze(['rolling', 'rimRoll', 'captured', 'resting', 'out', 'held'] as const)
export type BallModeName = (typeof BALL_MODE_NAMES)[number]

export const BallSchema = Object.freeze({
  /** centre, px */
  x: Float64Array,
  y: Float64Array,
  /** velocity, px/s */
  vx: Float64Array,
  vy: Float64Array,
  /** r, px */
  radius: Float64Array,
  /** BallMode */
  mode: Uint8Array,
  /** 1: a hero ball, whose lip crossings the physical reference decides (systems/heroReference.ts) */
  hero: Uint8Array,
  /** 1 while the id is a live ball (0: a free id, a hole or the walls) */
  live: Uint8Array,
  /** the ball's RimContact slot, 0 when it has none (components/RimContact.ts) */
  rim: Uint32Array,
})

export const createBallStore = (capacity: number) => createStore(BallSchema, capacity)
export type BallStore = ReturnType<typeof createBallStore>

/**
 * Zeroes ball eid's row, every field written out beside the schema (clearSlot's generic loop writes arrays
 * of every type from one site, which V8 makes slow; balls are added and removed in numbers).
 */
export function clearBallRow(B: BallStore, eid: number): void {
  B.x[eid] = 0
  B.y[eid] = 0
  B.vx[eid] = 0
  B.vy[eid] = 0
  B.radius[eid] = 0
  B.mode[eid] = 0
  B.hero[eid] = 0
  B.live[eid] = 0
  B.rim[eid] = 0
}
