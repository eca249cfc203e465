// Hole and ball events. Systems write them into a growable struct-of-arrays buffer (no object per event
// on the hot path); drainEvents turns them into objects, in time order, once per frame.

export const EventType = Object.freeze({
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
} as const)
export type EventTypeCode = (typeof EventType)[keyof typeof EventType]
import { EVENT_TYPE_NAMES, type BallEvent, type BallEventType, type CaptureViaName } from './eventTypes.js'
export { EVENT_TYPE_NAMES }
export type { BallEvent, BallEventType, BallOnlyEvent, CaptureEvent, CaptureViaName, CollisionEvent, HoleEvent } from './eventTypes.js'

export const CaptureVia = Object.freeze({ None: 0, Clean: 1, RimRoll: 2, Rest: 3 } as const)
export type CaptureViaCode = (typeof CaptureVia)[keyof typeof CaptureVia]
const VIA_NAMES = Object.freeze([undefined, 'clean', 'rimRoll', 'rest'] as const)

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
   * The world's time when the window that recorded the event began (src/schedule.ts sets windowFrom at each
   * window's start): an event at that instant (a solve or a launch there, and what follows from them) comes
   * after the events at that instant of the windows that end there, whichever drain each falls in (before()).
   */
  from: Float64Array
  windowFrom: number
  /**
   * Entities removed since the last drain: `cutIds[k]` was removed when `cutAt[k]` events were buffered.
   * Buffered events that name one of them (as ball, other or hole) are dropped at the drain, so no event
   * ever names a new entity that reuses a removed one's id.
   */
  cutCount: number
  cutIds: Uint32Array
  cutAt: Uint32Array
  /** true while drainEventBufferWith is calling back (a drain then is refused) */
  draining: boolean
  /** at a drain: for each cut id, the event count when it was last cut (by entity id; 0 otherwise); while a
   * drainEventsWith callback runs, 1 for each id it has removed */
  cutMark: Uint32Array
  /** at a drain: the kept events' indices in time order, and the merge sort's scratch */
  order: Uint32Array
  scratch: Uint32Array
}

/**
 * One event as drainEventsWith passes it to its callback: one object, rewritten for every event (copy what
 * you keep). The fields a BallEvent may leave out are always here: 0 (or false, or undefined for via)
 * where they do not apply.
 */
export interface EventView {
  type: BallEventType
  /** the EventType code of type */
  code: EventTypeCode
  ball: number
  /** simulation time of the event, s */
  time: number
  /** the hole, for hole events (0: none) */
  hole: number
  /** true when delta and speed are the lip crossing's (hole events that carry them) */
  hasLip: boolean
  /** δ at the lip crossing, px */
  delta: number
  /** v at the lip crossing, px/s; for a collision, the approach speed */
  speed: number
  /** how a capture happened */
  via: CaptureViaName | undefined
  /** the other ball of a collision (0 otherwise) */
  other: number
  /** normal impulse of a collision (0 otherwise) */
  impulse: number
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
    from: new Float64Array(capacity),
    windowFrom: 0,
    cutCount: 0,
    cutIds: new Uint32Array(16),
    cutAt: new Uint32Array(16),
    draining: false,
    cutMark: new Uint32Array(64),
    order: new Uint32Array(capacity),
    scratch: new Uint32Array(capacity),
  }
}

/** The per-event arrays (grown and shifted together). */
const PER_EVENT = ['type', 'ball', 'hole', 'time', 'delta', 'speed', 'hasDV', 'via', 'other', 'impulse', 'from'] as const

function grow(buf: EventBuffer): void {
  const next = createEventBuffer(buf.type.length * 2)
  const from = buf as unknown as Record<string, Float64Array>
  const to = next as unknown as Record<string, Float64Array>
  for (let f = 0; f < PER_EVENT.length; f++) {
    const k = PER_EVENT[f]!
    to[k]!.set(from[k]!)
    from[k] = to[k]!
  }
  buf.order = next.order
  buf.scratch = next.scratch
}

/**
 * Appends one event and returns its index: the caller writes its time into buf.time[i], and with `hasDV` its
 * delta and speed into buf.delta[i], buf.speed[i]. The module's systems append events so: V8 boxes every
 * double passed to a function it does not inline, three heap numbers an event through pushEvent.
 */
export function appendEvent(buf: EventBuffer, type: EventTypeCode, ball: number, hole: number, hasDV: boolean, via: CaptureViaCode = CaptureVia.None): number {
  if (buf.count === buf.type.length) grow(buf)
  const i = buf.count++
  buf.type[i] = type
  buf.ball[i] = ball
  buf.hole[i] = hole
  buf.time[i] = 0
  buf.hasDV[i] = hasDV ? 1 : 0
  buf.delta[i] = 0
  buf.speed[i] = 0
  buf.via[i] = via
  buf.other[i] = 0
  buf.impulse[i] = 0
  buf.from[i] = buf.windowFrom
  return i
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
  const i = appendEvent(buf, type, ball, hole, hasDV, via)
  buf.time[i] = time
  if (hasDV) {
    buf.delta[i] = delta
    buf.speed[i] = speed
  }
}

/** Copies event `from` over event `to`, in every per-event array: for a system that drops events it appended. */
export function moveEvent(buf: EventBuffer, to: number, from: number): void {
  const arrays = buf as unknown as Record<string, Float64Array>
  for (let f = 0; f < PER_EVENT.length; f++) arrays[PER_EVENT[f]!]![to] = arrays[PER_EVENT[f]!]![from]!
}

/**
 * Appends a collision of balls `ball` and `other` and returns its index: the caller writes its time, approach
 * speed and normal impulse into buf.time[i], buf.speed[i], buf.impulse[i] (as appendEvent, no double passed).
 */
export function appendCollision(buf: EventBuffer, ball: number, other: number): number {
  const i = appendEvent(buf, EventType.Collision, ball, 0, false)
  buf.other[i] = other
  return i
}

/**
 * Records that entity `id` (a ball or a hole) is removed now: the events buffered so far that name it are
 * dropped at the next drain (its id may be reused by a new entity before then).
 */
export function cutEvents(buf: EventBuffer, id: number): void {
  if (buf.count === 0) return
  // removed by a drainEventsWith callback: the drain gives none of its remaining events that name it
  if (buf.draining) cutMarkFor(buf, id)[id] = 1
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

/** buf.cutMark, grown (its marks kept) to index `id` */
function cutMarkFor(buf: EventBuffer, id: number): Uint32Array {
  if (buf.cutMark.length <= id) {
    let len = buf.cutMark.length
    while (len <= id) len *= 2
    const mark = new Uint32Array(len)
    mark.set(buf.cutMark)
    buf.cutMark = mark
  }
  return buf.cutMark
}

/**
 * Puts the indices of the buffered events to report into buf.order, sorted by time (ties: by window, ball id, then
 * by the order they were recorded, so the order is deterministic); returns how many. Events that name an
 * entity removed after they were buffered are left out. Allocates nothing once the arrays have grown.
 */
function orderEvents(buf: EventBuffer): number {
  const cuts = buf.cutCount
  if (cuts > 0) {
    let top = 0
    for (let k = 0; k < cuts; k++) if (buf.cutIds[k]! > top) top = buf.cutIds[k]!
    const grown = cutMarkFor(buf, top)
    for (let k = 0; k < cuts; k++) grown[buf.cutIds[k]!] = buf.cutAt[k]! // later cuts overwrite
  }
  const mark = buf.cutMark
  const order = buf.order
  let n = 0
  for (let i = 0, count = buf.count; i < count; i++) {
    if (cuts > 0) {
      const b = buf.ball[i]!
      const h = buf.hole[i]!
      const o = buf.other[i]!
      if ((b < mark.length && i < mark[b]!) || (h < mark.length && i < mark[h]!) || (o < mark.length && i < mark[o]!)) continue
    }
    order[n++] = i
  }
  if (cuts > 0) {
    for (let k = 0; k < cuts; k++) mark[buf.cutIds[k]!] = 0
    buf.cutCount = 0
  }
  sortOrder(buf, n)
  return n
}

/**
 * a before b in the drain order: time, then whether the window that recorded it began at that instant (a
 * window starting on an instant where another ended comes after it: the two fall in one drain or in two,
 * as the steps end, and a tie broken by ball id across them gave another order at another frame rate),
 * then ball id, then record order
 */
function before(buf: EventBuffer, a: number, b: number): boolean {
  const ta = buf.time[a]!
  const tb = buf.time[b]!
  if (ta !== tb) return ta < tb
  const pa = buf.from[a] === ta
  const pb = buf.from[b] === tb
  if (pa !== pb) return pb
  const ba = buf.ball[a]!
  const bb = buf.ball[b]!
  return ba !== bb ? ba < bb : a < b
}

/** Sorts buf.order[0..n): runs already in order are common (one ball's events), so a bottom-up merge sort. */
function sortOrder(buf: EventBuffer, n: number): void {
  let src = buf.order
  let dst = buf.scratch
  // runs of 8 by insertion, then merges of doubling width
  for (let lo = 0; lo < n; lo += 8) {
    const hi = Math.min(lo + 8, n)
    for (let i = lo + 1; i < hi; i++) {
      const v = src[i]!
      let j = i - 1
      while (j >= lo && before(buf, v, src[j]!)) {
        src[j + 1] = src[j]!
        j--
      }
      src[j + 1] = v
    }
  }
  for (let width = 8; width < n; width *= 2) {
    for (let lo = 0; lo < n; lo += 2 * width) {
      const mid = Math.min(lo + width, n)
      const hi = Math.min(lo + 2 * width, n)
      let i = lo
      let j = mid
      let k = lo
      while (i < mid && j < hi) dst[k++] = before(buf, src[j]!, src[i]!) ? src[j++]! : src[i++]!
      while (i < mid) dst[k++] = src[i++]!
      while (j < hi) dst[k++] = src[j++]!
    }
    const t = src
    src = dst
    dst = t
  }
  if (src !== buf.order) {
    buf.scratch = buf.order
    buf.order = src
  }
}

/**
 * Returns the buffered events as objects sorted by time (ties: by window, ball id, then the order they were
 * recorded, so the order is deterministic) and empties the buffer.
 */
export function drainEventBuffer(buf: EventBuffer): BallEvent[] {
  const n = orderEvents(buf)
  const order = buf.order
  const out = new Array<BallEvent>(n)
  for (let k = 0; k < n; k++) {
    const i = order[k]!
    // built field by field (a hole event's delta and speed only when it crossed the lip); each kind has
    // exactly the fields of its type in src/eventTypes.ts
    const e: Loose = { type: EVENT_TYPE_NAMES[buf.type[i]!]!, ball: buf.ball[i]!, time: buf.time[i]! }
    if (buf.type[i] === EventType.Collision) {
      e.other = buf.other[i]!
      e.speed = buf.speed[i]!
      e.impulse = buf.impulse[i]!
      out[k] = e as BallEvent
      continue
    }
    if (buf.hole[i] !== 0) e.hole = buf.hole[i]!
    if (buf.hasDV[i] === 1) {
      e.delta = buf.delta[i]!
      e.speed = buf.speed[i]!
    }
    const via = VIA_NAMES[buf.via[i]!]
    if (via !== undefined) e.via = via
    out[k] = e as BallEvent
  }
  buf.count = 0
  return out
}

/** An event being built by drainEventBuffer: every field a kind can have, each optional */
interface Loose {
  type: BallEvent['type']
  ball: number
  time: number
  hole?: number
  delta?: number
  speed?: number
  via?: CaptureViaName
  other?: number
  impulse?: number
}

const view: EventView = { type: 'skip', code: EventType.Skip, ball: 0, time: 0, hole: 0, hasLip: false, delta: 0, speed: 0, via: undefined, other: 0, impulse: 0 }

/**
 * Passes the buffered events, in drainEventBuffer's order, to `visit` one at a time through one reused view,
 * and empties the buffer of them; returns how many it passed. Allocates nothing once the buffer has grown to
 * the scene. `visit` may command or step the world (remove the ball it is told was captured, say): the
 * events that records wait for the next drain. An entity it removes is named by none of the events the
 * drain goes on to pass (its id may already belong to a ball added since). It may not drain again (an
 * Error). If it throws, the drain ends there: the events it had not yet been given are dropped with the
 * others.
 */
export function drainEventBufferWith(buf: EventBuffer, visit: (e: EventView) => void): number {
  const n = orderEvents(buf)
  const drained = buf.count
  const order = buf.order
  let passed = 0
  buf.draining = true
  try {
    for (let k = 0; k < n; k++) {
      const i = order[k]!
      if (buf.cutCount > 0) {
        // the callback has removed an entity (cutEvents marked it, orderEvents having cleared the marks)
        const mark = buf.cutMark
        const b = buf.ball[i]!
        const h = buf.hole[i]!
        const o = buf.other[i]!
        if ((b < mark.length && mark[b] !== 0) || (h < mark.length && mark[h] !== 0) || (o < mark.length && mark[o] !== 0)) continue
      }
      const code = buf.type[i]! as EventTypeCode
      view.type = EVENT_TYPE_NAMES[code]!
      view.code = code
      view.ball = buf.ball[i]!
      view.time = buf.time[i]!
      view.hole = buf.hole[i]!
      view.hasLip = buf.hasDV[i] === 1
      view.delta = buf.delta[i]!
      view.speed = buf.speed[i]!
      view.via = VIA_NAMES[buf.via[i]!]
      view.other = buf.other[i]!
      view.impulse = buf.impulse[i]!
      passed++
      visit(view)
    }
  } finally {
    buf.draining = false
    for (let c = 0; c < buf.cutCount; c++) buf.cutMark[buf.cutIds[c]!] = 0
    dropFirst(buf, drained)
  }
  return passed
}

/** Drops the first `k` buffered events: the ones recorded after them (and the cuts made since) move down. */
function dropFirst(buf: EventBuffer, k: number): void {
  const rest = buf.count - k
  if (rest > 0) {
    const arrays = buf as unknown as Record<string, Float64Array>
    for (let f = 0; f < PER_EVENT.length; f++) arrays[PER_EVENT[f]!]!.copyWithin(0, k, buf.count)
  }
  buf.count = rest
  for (let c = 0; c < buf.cutCount; c++) buf.cutAt[c] = Math.max(0, buf.cutAt[c]! - k)
}
