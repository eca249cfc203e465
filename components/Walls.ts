// Walls: an optional rectangle around the panel (one per world), with restitution. An edge may be open:
// a ball whose centre crosses it leaves the panel (the gutter). A world without walls never reads this.
// Indexed by entity id; the store grows only when the walls entity's id passes its length (set the walls
// before adding many balls, as for holes, and it stays small).
import { createStore } from './store.js'

export const WallEdge = Object.freeze({ Left: 1, Top: 2, Right: 4, Bottom: 8 } as const)

export const WallsSchema = Object.freeze({
  /** inner faces of the rectangle, px (y down: top = minY) */
  minX: Float64Array,
  minY: Float64Array,
  maxX: Float64Array,
  maxY: Float64Array,
  /** normal coefficient of restitution at a wall, [0, 1] */
  restitution: Float64Array,
  /** open edges, a WallEdge bit mask */
  open: Uint8Array,
})

export const createWallsStore = (capacity: number) => createStore(WallsSchema, capacity)
export type WallsStore = ReturnType<typeof createWallsStore>
