// Ball-ball contacts by the fixed-tick method (not a design stage; opt-in with config.BALL_COLLISIONS =
// 'fixed'). Contacts are solved at the times k·CONTACT_TICK of the world's clock, whatever the frame rate:
// the step is split at those times, and at the first pass after each one this system pairs the balls that
// can touch within a tick (src/contacts/fixedGrid.ts), solves their velocities (src/contacts/fixedSolve.ts)
// and separates overlaps (src/contacts/fixedProject.ts), pairing again the balls the solve sped up
// (src/contacts/fixedReach.ts). Between ticks the balls follow their closed-form paths through the holes
// and walls exactly, as in every other mode. Cheaper than the exact method in dense scenes, at a cost in
// timing: a contact acts at the tick, up to one tick early (docs/decisions.md §12).
// Reads Ball, the walls, the fixed state; writes Ball, Path, RimContact; emits 'collision' and 'wall'.
import { findPairs, gatherCandidates } from '../src/contacts/fixedGrid.js'
import { applyChanges, solveVelocities } from '../src/contacts/fixedSolve.js'
import { solvePositions } from '../src/contacts/fixedProject.js'
import { widenReach } from '../src/contacts/fixedReach.js'
import { MAX_WIDEN_ROUNDS } from '../src/config/tolerances.js'
import type { BallWorld } from '../src/world/createWorld.js'

export function fixedContactsSystem(w: BallWorld): void {
  const F = w.fixed
  if (F === null || !F.due || w.pass !== 0) return
  F.due = false
  const t = w.time
  F.ticks++
  gatherCandidates(w, F)
  if (F.n < 2) return
  findPairs(F)
  if (F.pairCount === 0) return
  const iterations = w.config.CONTACT_ITERATIONS
  F.hitCount = 0
  F.overlap = false
  solveVelocities(w, F, t, iterations)
  for (let round = 0; round < MAX_WIDEN_ROUNDS && widenReach(w, F); round++) solveVelocities(w, F, t, iterations)
  solvePositions(w, F)
  applyChanges(w, F, t)
}
