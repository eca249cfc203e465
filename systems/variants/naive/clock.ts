// Sub-step clock of the tick-sampled methods: splits the step [time, tickEnd] into SUBSTEPS equal
// sub-steps of length h and sets the current one's end time. The schedule lists the stage systems once per
// sub-step, each list headed by this system, so substeps are configuration, not code.
// Reads world.time, world.tickEnd; writes the naive state's h, t, index; clears its marked list.
import type { BallWorld } from '../../../src/world/createWorld.js'
import { naiveState } from './state.js'
import { outsideStep } from '../../../src/world/system.js'

export function naiveClockSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('naiveClockSystem', w)
  const st = naiveState(w)
  if (st.stepEnd !== w.tickEnd || st.index >= st.substeps) {
    st.stepEnd = w.tickEnd
    st.index = 0
  }
  const k = st.substeps
  st.h = (w.tickEnd - w.time) / k
  st.index++
  st.t = st.index === k ? w.tickEnd : w.time + st.index * st.h
  st.marked.count = 0
}
