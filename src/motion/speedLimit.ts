// The largest velocity a ball may have: MAX_SPEED a component (src/config/limits.ts), the most a command
// accepts, so that every velocity the world reports (ballState, the Ball store) can be given back
// (setBallVelocity). Contacts keep to it by taking less restitution (src/contacts/law.ts); every new path
// keeps to it too (startPath, src/motion/rolling.ts): a rim's exit turns a ball's velocity, and one of
// MAX_SPEED on both axes (√2·MAX_SPEED long) turned onto one axis would have that axis beyond it.
import { MAX_SPEED } from '../config/limits.js'

/** Whether a velocity has a component beyond MAX_SPEED (the largest a command accepts). */
export function overSpeed(vx: number, vy: number): boolean {
  return vx > MAX_SPEED || vx < -MAX_SPEED || vy > MAX_SPEED || vy < -MAX_SPEED
}

/**
 * Whether a contact takes a velocity component from c to o beyond `limit` (CONTACT_SPEED_LIMIT) and beyond
 * |c|: it would pump the ball past the limit (src/contacts/law.ts, capImpulse).
 */
export function pumpedPast(c: number, o: number, limit: number): boolean {
  return (o > limit || o < -limit) && o * o > c * c
}

/** capVelocity's answer: the capped velocity (slots, not a returned pair) */
export const capped = new Float64Array(2)

/**
 * A velocity with no component beyond MAX_SPEED (into `capped`): scaled down along itself when it has one
 * (its larger component then exactly ±MAX_SPEED), else as it is. A contact slows a ball this way only when
 * even an inelastic impulse sends it beyond (capImpulse, src/contacts/law.ts), and only there does a
 * contact not keep momentum.
 */
export function capVelocity(vx: number, vy: number): void {
  const ax = Math.abs(vx)
  const ay = Math.abs(vy)
  if (ax <= MAX_SPEED && ay <= MAX_SPEED) {
    capped[0] = vx
    capped[1] = vy
    return
  }
  if (ax >= ay) {
    const y = vy * (MAX_SPEED / ax)
    capped[0] = vx > 0 ? MAX_SPEED : -MAX_SPEED
    capped[1] = y > MAX_SPEED ? MAX_SPEED : y < -MAX_SPEED ? -MAX_SPEED : y
  } else {
    const x = vx * (MAX_SPEED / ay)
    capped[0] = x > MAX_SPEED ? MAX_SPEED : x < -MAX_SPEED ? -MAX_SPEED : x
    capped[1] = vy > 0 ? MAX_SPEED : -MAX_SPEED
  }
}

/**
 * largestShare's rows: for velocity component k, [3k] its value before a contact block (src/contacts/
 * fixedWallPair.ts, fixedSqueeze.ts), [3k + 1] after it at the block's full restitution, [3k + 2] after it
 * at none; its limit in share[1] and its answer in share[0]. Slots, not arguments or a returned double, which
 * V8 boxes when it does not take the call inline. Room for the most components a block changes (two heavy
 * balls and a row of 8).
 */
export const shareRows = new Float64Array(3 * 20)
export const share = new Float64Array(2)

/**
 * Whether any of the first n components of shareRows goes, at the block's full restitution, beyond the larger
 * of share[1] (CONTACT_SPEED_LIMIT) and its size before, at most MAX_SPEED: pumpedPast for each (velocities
 * and the limit are within MAX_SPEED), read from the rows, where the calls' doubles would be boxed.
 */
export function pastLimit(n: number): boolean {
  const limit = share[1]!
  for (let k = 0; k < n; k++) {
    const c = shareRows[3 * k]!
    const full = shareRows[3 * k + 1]!
    const size = c < 0 ? -c : c
    let M = limit > size ? limit : size
    if (M > MAX_SPEED) M = MAX_SPEED
    if (full > M || full < -M) return true
  }
  return false
}

/**
 * The largest share σ in [0, 1] of a block's restitution that keeps each of the first n components of
 * shareRows within the larger of share[1] (CONTACT_SPEED_LIMIT) and its size before, at most MAX_SPEED (as
 * capImpulse, src/contacts/law.ts, keeps a two-body contact): each component is linear in σ, from its value
 * at none to its value at full. 0 when a component is beyond it at none already: down to none, never below.
 * Into share[0].
 */
export function largestShare(n: number): void {
  const limit = share[1]!
  let s = 1
  for (let k = 0; k < n; k++) {
    const c = shareRows[3 * k]!
    const full = shareRows[3 * k + 1]!
    const none = shareRows[3 * k + 2]!
    const size = c < 0 ? -c : c
    let M = limit > size ? limit : size
    if (M > MAX_SPEED) M = MAX_SPEED
    if (!(full > M || full < -M)) continue
    if (none > M || none < -M) {
      s = 0
      break
    }
    const g = ((full > 0 ? M : -M) - none) / (full - none)
    if (g < s) s = g
  }
  share[0] = s > 0 ? s : 0
}
