// Stage 5, skip-over, decided at the tick: v > v_skip(δ) with v the speed at the overshot position.
// Reads the naive marks, RimContact (δ, v); writes RimContact.mode, Path.mark; emits 'skip'.
import { PathEvent } from '../../../components/Path.js'
import { RimMode } from '../../../components/RimContact.js'
import { EventType } from '../../../src/events.js'
import { vSkip } from '../../../src/geometry.js'
import { emitHoleEvent } from '../../../src/motion/ballFate.js'
import type { BallWorld } from '../../../src/world/createWorld.js'
import { naiveState } from './state.js'
import { outsideStep } from '../../../src/world/system.js'

export function naiveSkipOverSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('naiveSkipOverSystem', w)
  const st = naiveState(w)
  const P = w.Path
  const RC = w.RimContact
  const g = w.config.GRAVITY
  const list = st.marked
  for (let i = 0; i < list.count; i++) {
    const eid = list.ids[i]!
    if (P.mark[eid] !== PathEvent.Lip) continue
    const hole = P.markHole[eid]!
    const rim = w.Ball.rim[eid]!
    if (RC.speed[rim]! > vSkip(RC.delta[rim]!, w.Hole.radius[hole]!, w.Ball.radius[eid]!, g)) {
      RC.mode[rim] = RimMode.Skipping
      P.mark[eid] = PathEvent.None
      emitHoleEvent(w, EventType.Skip, eid, hole, st.t)
    }
  }
}
