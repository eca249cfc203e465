// A ball's mode changes in one place: here the RimContact component follows it. A ball carries RimContact
// exactly while a hole holds it on its rim (mode rimRoll), so a game can query or observe rim contacts.
// (The pooled RimContact row, at Ball.rim, also carries the hole lock of a ball that is inside a lip circle
// without touching the rim: skipping, entering, in transit. Adding the bitECS component at every lip
// crossing cost about a fifth of a dense panel's step: bitECS updates a Set per entity.)
import { addComponent, removeComponent } from 'bitecs'
import { BallMode, type BallModeCode } from '../../components/Ball.js'
import type { BallWorld } from './createWorld.js'

/** Sets a ball's mode, adding or removing its RimContact component when it starts or stops rolling on a rim. */
export function setBallMode(world: BallWorld, eid: number, mode: BallModeCode): void {
  const B = world.Ball
  const was = B.mode[eid]
  if (was === mode) return
  B.mode[eid] = mode
  if (mode === BallMode.RimRoll) addComponent(world, eid, world.RimContact)
  else if (was === BallMode.RimRoll) removeComponent(world, eid, world.RimContact)
}
