// Hero ball: the physical reference decides its lip crossings ("model no more than a scene needs"; see
// docs/physical.md). Covers the whole (δ, v) plane, for the balls flagged Ball.hero only.
//   at the exact lip crossing (δ, v): the reference (referenceOutcome's run, in its scaled units) → captured,
//   or the exit (point, speed, direction, time) of a rigid sphere rolling on and flying over a sharp lip
// Runs ahead of skipOver; a hero crossing it decides is unmarked, so the six stages never see it. Other
// balls, a hero whose radius is not below the hole's (the reference needs r < R), and a run the
// reference's guards stop (a steady roll round the rim that never decides) are left to the six stages.
// The outcome is applied as the tabulated model applies its table's (src/motion/rimOutcome.ts): a roll round
// the lip is ridden for the reference's time to its exit or drop ('rimRoll', then 'lipOut' or 'capture' via
// 'rimRoll'), a bounce or a skip is carried to the reference's exit point ('bounce' + 'nearMiss' or 'skip'
// at the crossing), a clean drop is captured at the crossing; no jump. Costs one reference run (~40 µs on
// average, at most LIVE_STEP_BUDGET lip steps: about 10 ms) per hero lip crossing; allocates only the
// reference's result object, once per crossing.
// Reads Path, Ball, Hole, config; writes Ball, Path, RimContact (takes the ball's slot); emits the events above.
import { PathEvent } from '../components/Path.js'
import { decideByReference } from '../src/motion/rimOutcome.js'
import { ROLL_TURN } from '../src/reference/rimTable.js'
import { type BallWorld } from '../src/world/createWorld.js'
import { outsideStep } from '../src/world/system.js'

/** Turn on the lip (rad) from which a hero's outcome counts as a rim roll (docs/reference-model.md: about 20°). */
export const HERO_ROLL_TURN = ROLL_TURN

export function heroReferenceSystem(w: BallWorld): void {
  if (!w.stepping) outsideStep('heroReferenceSystem', w)
  const P = w.Path
  const B = w.Ball
  const list = w.marked
  for (let i = 0; i < list.count; i++) {
    const eid = list.ids[i]!
    if (B.hero[eid] !== 1 || P.mark[eid] !== PathEvent.Lip) continue
    decideByReference(w, eid, false)
  }
}
