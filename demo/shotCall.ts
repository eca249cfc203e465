// Call your shot off the main thread: what the page sends the solver worker (demo/solveWorker.ts) and what
// it gets back. The worker restores the snapshot into a world of its own made with the same config, so the
// hole's entity id is the same there, and runs solveThrow on it.
import type { BallPhysicsConfig, ThrowFailure, ThrowRequest, ThrowSolution } from '../src/index'

/** A call to solve: the world's config and snapshot when it was made, and the solver's request. */
export interface ShotCall {
  token: number
  config: BallPhysicsConfig
  snapshot: Uint8Array
  request: ThrowRequest
}

/** The worker's reply to the call `token`: the solver's answer and its time, ms; or the error it threw. */
export type ShotReply =
  | { token: number; answer: ThrowSolution | ThrowFailure; ms: number }
  | { token: number; error: string }
