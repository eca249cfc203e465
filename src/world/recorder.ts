// Replay recording (src/commands/replay.ts): while a world records, every command that changes it between
// steps appends one input — its name and its checked arguments — after its checks pass, and every step its
// dt (a command a game's system gives during a step is the system's, and is not recorded). Callers
// test w.recorder before they build the input, so a world that does not record pays one null test per
// command and allocates nothing for it.
import type { BallWorld } from './createWorld.js'

/** One recorded input: the command's name, then its arguments (plain numbers, booleans and objects) */
export type ReplayInput = [string, ...unknown[]]

export interface Recorder {
  inputs: ReplayInput[]
  /** the world when recording started, as a base64 snapshot; undefined when it had no entities */
  start: string | undefined
}

/** Appends an input (the caller has checked that the world records). */
export function record(w: BallWorld, input: ReplayInput): void {
  // a command a game's system gives during a step is part of that system, which the replay does not hold:
  // played with the same schedule, the system gives it again at the same instant (recorded, it came after the
  // step, for a ball the playback's system had already removed)
  if (w.stepping) return
  w.recorder?.inputs.push(input)
}

/** The fields of a checked spec that are set (undefined ones left out), as a plain object */
export function specOf(s: Record<string, unknown>): Record<string, unknown> {
  const out: Record<string, unknown> = {}
  for (const k of Object.keys(s)) if (s[k] !== undefined) out[k] = s[k]
  return out
}
