// Reading the events the systems recorded.
import { drainEventBuffer, drainEventBufferWith, type BallEvent, type EventView } from '../events.js'
import type { BallWorld } from '../world/createWorld.js'
import { checkWorld } from './validate.js'

/**
 * The events since the last drain, in time order (ties: what a window starting on an instant recorded
 * there after what the window ending there recorded, then by ball id, then in the order they were recorded),
 * as new objects; the buffer is emptied. Events naming a ball or hole removed after they were recorded are
 * dropped (the id may already belong to a new entity).
 */
export function drainEvents(world: BallWorld): BallEvent[] {
  const buf = checkWorld('drainEvents', world, true).events
  if (buf.draining) throw new Error('drainEvents: called from a drainEventsWith callback (drain once, after it returns)')
  return drainEventBuffer(buf)
}

/**
 * The events since the last drain, in the same order as drainEvents, passed to `visit` one at a time
 * through one reused EventView (copy what you keep: its fields change with the next event); returns how
 * many it passed. Allocates nothing once the buffer has grown to the scene: for games with many balls.
 * `visit` may command or step the world; the events that records wait for the next drain. A ball or hole
 * it removes is named by none of the events the drain goes on to pass (its id may already be a new
 * ball's). If `visit` throws, the drain ends there and the events not yet given to it are dropped.
 */
export function drainEventsWith(world: BallWorld, visit: (e: EventView) => void): number {
  const buf = checkWorld('drainEventsWith', world, true).events
  if (typeof visit !== 'function') throw new TypeError(`drainEventsWith: visit must be a function (e: EventView) => void, got ${visit === null ? 'null' : typeof visit}`)
  if (buf.draining) throw new Error('drainEventsWith: called from a drainEventsWith callback (drain once, after it returns)')
  return drainEventBufferWith(buf, visit)
}
