// The events a drain hands out, as objects: one type per kind of event, told apart by `type`, so that a
// check of `e.type` narrows the fields (a capture has its hole and `via`, a collision its other ball and
// impulse). A field a kind never has is typed `undefined`, so it can still be read from any event.

/** The kinds of event (`BallEvent['type']`), in the order of their codes (EventType, src/events.ts). */
export const EVENT_TYPE_NAMES = Object.freeze(['skip', 'capture', 'bounce', 'rimRoll', 'lipOut', 'nearMiss', 'rest', 'wall', 'gutter', 'collision'] as const)
export type BallEventType = (typeof EVENT_TYPE_NAMES)[number]
export type CaptureViaName = 'clean' | 'rimRoll' | 'rest'

interface EventOf<T extends BallEventType> {
  type: T
  ball: number
  /** simulation time of the event, s (exact: from the closed-form path, not the tick) */
  time: number
}

/** A ball's event at a hole: skip, bounce, rimRoll, lipOut, nearMiss */
export interface HoleEvent extends EventOf<'skip' | 'bounce' | 'rimRoll' | 'lipOut' | 'nearMiss'> {
  hole: number
  /**
   * δ at the lip crossing, px (for a nearMiss without a crossing: the closest approach); absent when the
   * ball met the hole without crossing its lip (put down inside it, say)
   */
  delta?: number
  /** v at the lip crossing, px/s (for a nearMiss without a crossing: the speed at closest approach); as delta */
  speed?: number
  via?: undefined
  other?: undefined
  impulse?: undefined
}

/** A ball captured by a hole */
export interface CaptureEvent extends EventOf<'capture'> {
  hole: number
  /** how: dropped in at the lip, after rolling round it, or stopped over the hole */
  via: CaptureViaName
  /** as HoleEvent's: absent for a ball that did not cross the lip (put down inside the hole, a hole added under it) */
  delta?: number
  speed?: number
  other?: undefined
  impulse?: undefined
}

/** Two balls touch (ball-ball contacts on): `ball` < `other` */
export interface CollisionEvent extends EventOf<'collision'> {
  other: number
  /** the speed at which they approached, px/s */
  speed: number
  /** normal impulse, mass·px/s (masses in units of a default ball) */
  impulse: number
  hole?: undefined
  delta?: undefined
  via?: undefined
}

/** A ball comes to rest, meets a closed wall, or leaves through an open edge */
export interface BallOnlyEvent extends EventOf<'rest' | 'wall' | 'gutter'> {
  hole?: undefined
  delta?: undefined
  speed?: undefined
  via?: undefined
  other?: undefined
  impulse?: undefined
}

export type BallEvent = HoleEvent | CaptureEvent | CollisionEvent | BallOnlyEvent
