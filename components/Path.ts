// Path: the closed-form trajectory a ball follows since its last event, and its next event. Positions are
// always evaluated from the path's origin, never accumulated tick by tick, so event times and (δ, v)
// depend only on earlier events, not on where ticks fell (docs/decisions.md §1).
import { createStore } from './store.js'

/** What a ball meets next. Decision events stop the ball for the systems; the others are bookkeeping. */
export const PathEvent = Object.freeze({
  None: 0,
  /** centre crosses a hole's lip circle inward (decided by skip-over, capture, COG gate) */
  Lip: 1,
  /** centre reaches the contact circle ρ_c (decided by the COG gate: roll or bounce) */
  Contact: 2,
  /** speed reaches 0 (decided by capture: over a hole or not) */
  Stop: 3,
  /** rim roll ends: drop or pop (rim-roll system); a reference-decided ride's end (integration, or the tabulated rim system with exact contacts) */
  RollEnd: 4,
  /** centre leaves the locked hole's lip circle (integration unlocks it) */
  Exit: 5,
  /** closest approach to a hole the footprint overlaps without the centre entering (integration reports it) */
  Near: 6,
  /** marks set by the COG gate for the bounce and rim-roll systems */
  Bounce: 7,
  Roll: 8,
  /** centre reaches a closed wall, one radius in (walls system) */
  Wall: 9,
  /** centre crosses an open edge of the walls (walls system) */
  Gutter: 10,
  /** touches another ball (collisions system; markOther holds the other ball) */
  Collide: 11,
  /** a tabulated bounce or skip reaches the reference's exit point (integration, or the tabulated rim system with exact contacts) */
  Landing: 12,
  /** touches another ball alone at a fixed contact tick, at its instant (src/contacts/fixedMeet.ts; nextHole holds the other ball) */
  Meet: 13,
} as const)
export type PathEventCode = (typeof PathEvent)[keyof typeof PathEvent]

// The path itself (origin, direction, speed v0 and time t0 at the origin) and the next event's time and
// distance live in the world's interleaved rows, world.pathHot (src/world/pathHot.ts); the rest is here.
export const PathSchema = Object.freeze({
  /** speed at the ball's last event, from the closed form (so (δ, v) at an event is exact, not a hypot of components) */
  speed: Float64Array,
  /**
   * Distance along the path, and hole, of the last event handled on it. Events are ordered by
   * (distance, hole id); the next one must come after this key, so none is lost or handled twice.
   */
  s: Float64Array,
  sHole: Uint32Array,
  /** hole this path leaves after a bounce or a pop-off: its near miss is already reported */
  fromHole: Uint32Array,
  /** kind and hole of the next event on the current path (its time and distance: world.pathHot) */
  nextKind: Uint8Array,
  nextHole: Uint32Array,
  /** the WallEdge bit of a Wall or Gutter event (0 for other kinds) */
  nextEdge: Uint8Array,
  /** the event the ball is stopped at in this pass, for the systems (PathEvent.None when none) */
  mark: Uint8Array,
  markHole: Uint32Array,
  /** the WallEdge bit of a marked Wall or Gutter event */
  markEdge: Uint8Array,
  /** the other ball of a marked Collide event */
  markOther: Uint32Array,
})

export const createPathStore = (capacity: number) => createStore(PathSchema, capacity)
export type PathStore = ReturnType<typeof createPathStore>

/** Zeroes ball eid's row, every field written out beside the schema (as clearBallRow in Ball.ts). */
export function clearPathRow(P: PathStore, eid: number): void {
  P.speed[eid] = 0
  P.s[eid] = 0
  P.sHole[eid] = 0
  P.fromHole[eid] = 0
  P.nextKind[eid] = 0
  P.nextHole[eid] = 0
  P.nextEdge[eid] = 0
  P.mark[eid] = 0
  P.markHole[eid] = 0
  P.markEdge[eid] = 0
  P.markOther[eid] = 0
}
