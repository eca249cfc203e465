// Reading the events the systems recorded.
import { drainEventBuffer, type BallEvent } from '../events.js'
import type { BallWorld } from '../world/createWorld.js'
import { checkWorld } from './validate.js'

/**
 * The events since the last drain, in time order (ties: by ball id, then in the order they were recorded),
 * as new objects; the buffer is emptied. Events naming a ball or hole removed after they were recorded are
 * dropped (the id may already belong to a new entity).
 */
export function drainEvents(world: BallWorld): BallEvent[] {
  return drainEventBuffer(checkWorld('drainEvents', world).events)
}
