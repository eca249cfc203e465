// A replay played through the game API: the world-level player (src/commands/replay.ts) with a
// BallPhysics over its world, so a game reads states and drains events as it does for a live run.
import { createReplayPlayer as createWorldPlayer, type Replay, type ReplayPlayer as WorldReplayPlayer } from '../commands/replay.js'
import { physicsFor, type BallPhysics } from './createBallPhysics.js'

export interface ReplayPlayer extends WorldReplayPlayer {
  /** the game API over the replayed world (its schedule is the config's) */
  readonly sim: BallPhysics
}

/**
 * A player for `replay` on a fresh world made from its config: `next()` runs the inputs up to and
 * including the next step (false when none are left); read `sim` between calls.
 */
export function createReplayPlayer(replay: Replay): ReplayPlayer {
  const p = createWorldPlayer(replay)
  const sim = physicsFor(p.world)
  return {
    sim,
    world: p.world,
    get at() {
      return p.at
    },
    total: p.total,
    get steps() {
      return p.steps
    },
    next: () => p.next(),
  }
}
