// Hole: a circular hole in the panel. Holes are static; their lip circles may not overlap.
import { createStore } from '../src/store'

export const HoleSchema = {
  /** centre, px */
  x: Float64Array,
  y: Float64Array,
  /** R, px */
  radius: Float64Array,
  /** points scored by a capture */
  value: Float64Array,
}

export const createHoleStore = (capacity: number) => createStore(HoleSchema, capacity)
export type HoleStore = ReturnType<typeof createHoleStore>
