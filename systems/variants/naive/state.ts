// Per-world state of the tick-sampled methods ('naive', 'v1'): the sub-step clock, the balls marked in
// this sub-step, and a small per-ball store for what a tick-sampled port has to remember between ticks
// (its current rim-roll speed, the near miss being tracked). Kept beside the world, not in it, so the
// exact core's world and stores are unchanged; created on first use, grown with the world's per-ball
// capacity (its stores are indexed by ball id).
import { createStore, growStore } from '../../../components/store.js'
import { createIdList } from '../../../src/world/idLists.js'
import { type BallWorld, type IdList } from '../../../src/world/createWorld.js'

export const NaiveBallSchema = {
  /** current rim-roll speed, px/s (v ← v·(1 − μ·dt): may turn negative) */
  rollSpeed: Float64Array,
  /** hole whose footprint overlap is being tracked for a near miss, 0 when none */
  nearHole: Uint32Array,
  /** smallest sampled centre distance to nearHole so far, px, and the speed there */
  nearD: Float64Array,
  nearV: Float64Array,
  /** hole whose near miss was reported, until the footprint leaves it */
  nearDone: Uint32Array,
  /** hole the ball bounced or popped off last: no near miss for it */
  fromHole: Uint32Array,
  /** 1 when the speed ran out in this sub-step */
  stopped: Uint8Array,
}

const createNaiveBallStore = (capacity: number) => createStore(NaiveBallSchema, capacity)
export type NaiveBallStore = ReturnType<typeof createNaiveBallStore>

export interface NaiveState {
  /** sub-steps per step (config.SUBSTEPS) */
  substeps: number
  /** index of the current sub-step within the step, and the step it belongs to */
  index: number
  stepEnd: number
  /** sub-step length and its end time, s */
  h: number
  t: number
  /** balls stopped at something in this sub-step, for the decision systems */
  marked: IdList
  store: NaiveBallStore
  capacity: number
}

const states = new WeakMap<BallWorld, NaiveState>()

/** The world's tick-sampled state, created on first use and grown to the world's per-ball capacity. */
export function naiveState(w: BallWorld): NaiveState {
  let st = states.get(w)
  if (st === undefined) {
    st = {
      substeps: w.config.SUBSTEPS,
      index: 0,
      stepEnd: Number.NaN,
      h: 0,
      t: w.time,
      marked: createIdList(),
      store: createNaiveBallStore(w.capacity),
      capacity: w.capacity,
    }
    states.set(w, st)
    w.ballStores.push(st.store)
  } else if (st.capacity < w.capacity) {
    growStore(st.store, w.capacity)
    st.capacity = w.capacity
  }
  return st
}
