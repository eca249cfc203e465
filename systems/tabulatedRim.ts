// The reference-tabulated rim model (RIM_MODEL 'tabulated', TABULATED_CONFIG): a lip crossing decided by the
// rigid-sphere reference's table at the crossing's geometry (src/reference/rimTable.ts) instead of the six
// closed-form stages. Runs after the hero ball's system and ahead of skipOver; a crossing it decides is
// unmarked, so the stages never see it. With exact contacts it also ends every ride round the lip and every
// carry across (the hero ball's too), whatever RIM_MODEL says; otherwise the integration system ends them
// in its pass (their outcome was decided at the crossing).
//   capture  v ≤ v_c(δ), the reference's capture speed per δ row, linear between rows
//   outcome  the table's kind, exit point, direction and speed, time and turn on the lip (interpolated)
// What the ball does then (a ride round the lip, a carry across, a clean drop): src/motion/rimOutcome.ts.
// A ball faster than the table's top (2,000 px/s at the design's geometry), or of a size whose table was not
// given to the world (it has its config's; prepareRimTable adds others), is decided by the live reference; a
// ball not smaller than the hole, or a node where a guard stopped the reference, is left to the stages.
// Reads Path, Ball, Hole, RimContact, config; writes Ball, Path, RimContact; emits the events above.
import { PathEvent } from '../components/Path.js'
import { decideByReference, endRide, landCrossing } from '../src/motion/rimOutcome.js'
import { type BallWorld } from '../src/world/createWorld.js'
import { outsideStep } from '../src/world/system.js'

export function tabulatedRimSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('tabulatedRimSystem', w)
  // (rides and carries also end here for hero balls, whose crossings the reference decided live)
  const tabulated = w.config.RIM_MODEL === 'tabulated'
  const P = w.Path
  const B = w.Ball
  const RC = w.RimContact
  const list = w.marked
  for (let i = 0; i < list.count; i++) {
    const eid = list.ids[i]!
    const mark = P.mark[eid]
    if (mark === PathEvent.Lip) {
      if (tabulated) decideByReference(w, eid, true)
    } else if (mark === PathEvent.RollEnd && RC.ride[B.rim[eid]!] !== 0) endRide(w, eid)
    else if (mark === PathEvent.Landing) landCrossing(w, eid)
  }
}
