// A replay played through the game API: the world-level player (src/commands/replay.ts) with a
// BallPhysics over its world, so a game reads states and drains events as it does for a live run.
import { createReplayPlayer as createWorldPlayer, type Replay, type ReplayPlayer as WorldReplayPlayer } from '../commands/replay.js'
import { physicsFor, type BallPhysics } from './createBallPhysics.js'
import type { ScheduleEntry } from '../schedule.js'

export interface ReplayPlayer extends WorldReplayPlayer {
  /** the game API over the replayed world (read states, drain events; the player steps it) */
  readonly sim: BallPhysics
}

/**
 * A player for `replay` on a fresh world made from its config: `next()` runs the inputs up to and
 * including the next step (false when none are left); read `sim` between calls. `schedule`: the schedule
 * to step with (default: the config's). A game that put systems of its own into `sim.schedule` passes
 * such a schedule: the commands they give during a step are not in the replay, and they give them again.
 */
export function createReplayPlayer(replay: Replay, schedule?: readonly ScheduleEntry[]): ReplayPlayer {
  const p = createWorldPlayer(replay, schedule)
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
