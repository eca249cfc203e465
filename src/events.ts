// Hole and ball events. Systems write them into a growable struct-of-arrays buffer (no object per event
// on the hot path); drainEvents turns them into objects, in time order, once per frame.

export const EventType = {
  Skip: 0,
  Capture: 1,
  Bounce: 2,
  RimRoll: 3,
  LipOut: 4,
  NearMiss: 5,
  Rest: 6,
  Wall: 7,
  Gutter: 8,
  /** two balls touch (ball-ball contacts on): `ball` and `other` */
  Collision: 9,
} as const
export type EventTypeCode = (typeof EventType)[keyof typeof EventType]
export const EVENT_TYPE_NAMES = ['skip', 'capture', 'bounce', 'rimRoll', 'lipOut', 'nearMiss', 'rest', 'wall', 'gutter', 'collision'] as const
export type BallEventType = (typeof EVENT_TYPE_NAMES)[number]

export const CaptureVia = { None: 0, Clean: 1, RimRoll: 2, Rest: 3 } as const
export type CaptureViaCode = (typeof CaptureVia)[keyof typeof CaptureVia]
const VIA_NAMES = [undefined, 'clean', 'rimRoll', 'rest'] as const
export type CaptureViaName = 'clean' | 'rimRoll' | 'rest'

export interface BallEvent {
  type: BallEventType
  ball: number
  /** the hole, for hole events */
  hole?: number
  /** simulation time of the event, s (exact: from the closed-form path, not the tick) */
  time: number
  /** δ at the lip crossing, px (for a nearMiss without a crossing: the closest approach) */
  delta?: number
  /** v at the lip crossing, px/s (for a nearMiss without a crossing: the speed at closest approach) */
  speed?: number
  /** how a capture happened */
  via?: CaptureViaName
  /** the other ball of a collision */
  other?: number
  /** normal impulse of a collision, mass·px/s (masses in units of a default ball) */
  impulse?: number
}

export interface EventBuffer {
  count: number
  type: Uint8Array
  ball: Uint32Array
  hole: Uint32Array
  time: Float64Array
  delta: Float64Array
  speed: Float64Array
  /** 1 when delta and speed are set */
  hasDV: Uint8Array
  via: Uint8Array
  /** the other ball of a collision (0 otherwise) */
  other: Uint32Array
  /** the normal impulse of a collision (0 otherwise) */
  impulse: Float64Array
  /**
   * Entities removed since the last drain: `cutIds[k]` was removed when `cutAt[k]` events were buffered.
   * Buffered events that name one of them (as ball, other or hole) are dropped at the drain, so no event
   * ever names a new entity that reuses a removed one's id.
   */
  cutCount: number
  cutIds: Uint32Array
  cutAt: Uint32Array
}

export function createEventBuffer(capacity = 1024): EventBuffer {
  return {
    count: 0,
    type: new Uint8Array(capacity),
    ball: new Uint32Array(capacity),
    hole: new Uint32Array(capacity),
    time: new Float64Array(capacity),
    delta: new Float64Array(capacity),
    speed: new Float64Array(capacity),
    hasDV: new Uint8Array(capacity),
    via: new Uint8Array(capacity),
    other: new Uint32Array(capacity),
    impulse: new Float64Array(capacity),
    cutCount: 0,
    cutIds: new Uint32Array(16),
    cutAt: new Uint32Array(16),
  }
}

function grow(buf: EventBuffer): void {
  const cap = buf.type.length * 2
  const next = createEventBuffer(cap)
  next.type.set(buf.type)
  next.ball.set(buf.ball)
  next.hole.set(buf.hole)
  next.time.set(buf.time)
  next.delta.set(buf.delta)
  next.speed.set(buf.speed)
  next.hasDV.set(buf.hasDV)
  next.via.set(buf.via)
  next.other.set(buf.other)
  next.impulse.set(buf.impulse)
  buf.type = next.type
  buf.ball = next.ball
  buf.hole = next.hole
  buf.time = next.time
  buf.delta = next.delta
  buf.speed = next.speed
  buf.hasDV = next.hasDV
  buf.via = next.via
  buf.other = next.other
  buf.impulse = next.impulse
}

/** Appends one event. `delta`/`speed` are recorded only when `hasDV` is true; `hole` 0 means none. */
export function pushEvent(
  buf: EventBuffer,
  type: EventTypeCode,
  ball: number,
  hole: number,
  time: number,
  hasDV: boolean,
  delta: number,
  speed: number,
  via: CaptureViaCode = CaptureVia.None,
): void {
  if (buf.count === buf.type.length) grow(buf)
  const i = buf.count++
  buf.type[i] = type
  buf.ball[i] = ball
  buf.hole[i] = hole
  buf.time[i] = time
  buf.hasDV[i] = hasDV ? 1 : 0
  buf.delta[i] = hasDV ? delta : 0
  buf.speed[i] = hasDV ? speed : 0
  buf.via[i] = via
  buf.other[i] = 0
  buf.impulse[i] = 0
}

/** Appends a collision of balls `ball` and `other` at `time`: approach speed and normal impulse. */
export function pushCollisionEvent(buf: EventBuffer, ball: number, other: number, time: number, speed: number, impulse: number): void {
  if (buf.count === buf.type.length) grow(buf)
  const i = buf.count++
  buf.type[i] = EventType.Collision
  buf.ball[i] = ball
  buf.hole[i] = 0
  buf.time[i] = time
  buf.hasDV[i] = 0
  buf.delta[i] = 0
  buf.speed[i] = speed
  buf.via[i] = CaptureVia.None
  buf.other[i] = other
  buf.impulse[i] = impulse
}

/**
 * Records that entity `id` (a ball or a hole) is removed now: the events buffered so far that name it are
 * dropped at the next drain (its id may be reused by a new entity before then).
 */
export function cutEvents(buf: EventBuffer, id: number): void {
  if (buf.count === 0) return
  if (buf.cutCount === buf.cutIds.length) {
    const ids = new Uint32Array(buf.cutCount * 2)
    ids.set(buf.cutIds)
    const at = new Uint32Array(buf.cutCount * 2)
    at.set(buf.cutAt)
    buf.cutIds = ids
    buf.cutAt = at
  }
  buf.cutIds[buf.cutCount] = id
  buf.cutAt[buf.cutCount++] = buf.count
}

/**
 * Returns the buffered events as objects sorted by time (ties: by ball id, then by the order they were
 * recorded, so the order is deterministic) and empties the buffer.
 */
export function drainEventBuffer(buf: EventBuffer): BallEvent[] {
  // events that name an entity removed after they were buffered are dropped
  let cut: Map<number, number> | null = null
  if (buf.cutCount > 0) {
    cut = new Map()
    for (let k = 0; k < buf.cutCount; k++) cut.set(buf.cutIds[k]!, buf.cutAt[k]!) // later cuts overwrite
    buf.cutCount = 0
  }
  const order: number[] = []
  for (let i = 0, n = buf.count; i < n; i++) {
    if (cut !== null && (i < (cut.get(buf.ball[i]!) ?? 0) || i < (cut.get(buf.hole[i]!) ?? 0) || i < (cut.get(buf.other[i]!) ?? 0))) continue
    order.push(i)
  }
  const n = order.length
  order.sort((a, b) => buf.time[a]! - buf.time[b]! || buf.ball[a]! - buf.ball[b]! || a - b)
  const out = new Array<BallEvent>(n)
  for (let k = 0; k < n; k++) {
    const i = order[k]!
    const e: BallEvent = { type: EVENT_TYPE_NAMES[buf.type[i]!]!, ball: buf.ball[i]!, time: buf.time[i]! }
    if (buf.type[i] === EventType.Collision) {
      e.other = buf.other[i]!
      e.speed = buf.speed[i]!
      e.impulse = buf.impulse[i]!
      out[k] = e
      continue
    }
    if (buf.hole[i] !== 0) e.hole = buf.hole[i]!
    if (buf.hasDV[i] === 1) {
      e.delta = buf.delta[i]!
      e.speed = buf.speed[i]!
    }
    const via = VIA_NAMES[buf.via[i]!]
    if (via !== undefined) e.via = via
    out[k] = e
  }
  buf.count = 0
  return out
}
