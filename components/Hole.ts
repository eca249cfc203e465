// Hole: a circular hole in the panel. Holes are static; their lip circles may not overlap.
// Indexed by entity id; the store grows only when a hole's id passes its length, so holes made before the
// balls (the usual order) keep it small however many balls follow.
import { createStore } from './store.js'

export const HoleSchema = Object.freeze({
  /** centre, px */
  x: Float64Array,
  y: Float64Array,
  /** R, px */
  radius: Float64Array,
  /** points scored by a capture */
  value: Float64Array,
})

export const createHoleStore = (capacity: number) => createStore(HoleSchema, capacity)
export type HoleStore = ReturnType<typeof createHoleStore>
