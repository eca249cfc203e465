// Input checks for every entry point. A spec is read once, field by field, into a plain record (a getter
// runs once; what is validated is what is used), then checked; errors name the field, the allowed range and
// what was given, and are thrown before anything in the world changes.
import type { BallWorld } from './world/createWorld.js'

/** A value as an error message shows it: numbers as they are, anything else with its kind. */
export function describe(value: unknown): string {
  switch (typeof value) {
    case 'number':
      return String(value)
    case 'string':
      return `the string ${JSON.stringify(value)}`
    case 'symbol':
      return `a symbol (${value.toString()})`
    case 'bigint':
      return `a bigint (${value.toString()}n)`
    case 'boolean':
      return `the boolean ${value}`
    case 'undefined':
      return 'undefined'
    case 'function':
      return 'a function'
    default:
      return value === null ? 'null' : Array.isArray(value) ? 'an array' : 'an object'
  }
}

/**
 * Reads the named fields of a spec object once each. Throws a TypeError when it is not a plain object, and
 * a RangeError naming the first own key that is not one of `keys` (a misspelt optional field would
 * otherwise be ignored); `field` names the spec in that message (default `name`).
 */
export function readSpec<K extends string>(name: string, spec: unknown, keys: readonly K[], field = name): Record<K, unknown> {
  const source = specObject(name, spec, keys, field)
  const out = {} as Record<K, unknown>
  for (const key of keys) out[key] = source[key]
  return out
}

/**
 * The spec as a record to read fields from (for entry points that read them into locals, allocating
 * nothing). Throws a TypeError when it is not a plain object, and a RangeError naming the first own key that
 * is not one of `keys`; `field` names the spec in that message (default `name`).
 */
export function specObject(name: string, spec: unknown, keys: readonly string[], field = name): Record<string, unknown> {
  if (spec === null || typeof spec !== 'object' || Array.isArray(spec)) {
    throw new TypeError(`${name} must be an object, got ${describe(spec)}`)
  }
  const source = spec as Record<string, unknown>
  for (const key in source) {
    if (!Object.prototype.hasOwnProperty.call(source, key) || keys.includes(key)) continue
    throw new RangeError(`${field}.${key} is not a known key; known keys: ${keys.join(', ')}`)
  }
  return source
}

/** A finite number in [−limit, limit]. */
export function finite(field: string, value: unknown, limit: number): number {
  if (typeof value !== 'number') throw new TypeError(`${field} must be a number in [${-limit}, ${limit}], got ${describe(value)}`)
  if (!Number.isFinite(value) || Math.abs(value) > limit) {
    throw new RangeError(`${field} must be a finite number in [${-limit}, ${limit}], got ${value}`)
  }
  return value
}

/** A number in (0, limit]. */
export function positive(field: string, value: unknown, limit: number): number {
  if (typeof value !== 'number') throw new TypeError(`${field} must be a number in (0, ${limit}], got ${describe(value)}`)
  if (!Number.isFinite(value) || value <= 0 || value > limit) {
    throw new RangeError(`${field} must be in (0, ${limit}], got ${value}`)
  }
  return value
}

/** A number in [lo, hi]. */
export function within(field: string, value: unknown, lo: number, hi: number): number {
  if (typeof value !== 'number') throw new TypeError(`${field} must be a number in [${lo}, ${hi}], got ${describe(value)}`)
  if (!(value >= lo && value <= hi)) throw new RangeError(`${field} must be in [${lo}, ${hi}], got ${value}`)
  return value
}

/** An optional choice among `allowed` (undefined: the first of them). */
export function choice<T extends string>(field: string, value: unknown, allowed: readonly T[]): T {
  if (value === undefined) return allowed[0]!
  const names = allowed.map((a) => `'${a}'`).join(' or ')
  if (typeof value !== 'string') throw new TypeError(`${field} must be ${names}, got ${describe(value)}`)
  if (!(allowed as readonly string[]).includes(value)) throw new RangeError(`${field} must be ${names}, got ${describe(value)}`)
  return value as T
}

/** An optional boolean (undefined: false). */
export function flag(field: string, value: unknown): boolean {
  if (value === undefined) return false
  if (typeof value !== 'boolean') throw new TypeError(`${field} must be a boolean, got ${describe(value)}`)
  return value
}

/** bitECS's key for a world's own data (a registered symbol), which its deleteWorld removes */
const BITECS_INTERNAL = Symbol.for('bitecs_internal')

/**
 * `world` as a BallWorld, checked: one made by createBallWorld (or createBallPhysics().world), not deleted or
 * reset by bitECS. A world whose last step an error ended part-done (world.failed) is refused unless the
 * caller only reads it (`reads`): its state cannot go on.
 */
export function checkWorld(caller: string, world: unknown, reads = false): BallWorld {
  const w = world as BallWorld | null
  if (w === null || typeof w !== 'object' || !('Ball' in w) || !('holes' in w) || !('config' in w)) {
    throw new TypeError(`${caller}: world must be a world made by createBallWorld, got ${describe(world)}`)
  }
  const internal = (w as unknown as Record<symbol, { entityIndex?: unknown } | undefined>)[BITECS_INTERNAL]
  if (internal === undefined) {
    throw new Error(
      `${caller}: this is not a live world: it was deleted (bitECS deleteWorld), which is not supported (make a new one), or it is a copy of one (such as { ...world }), which has the stores but not bitECS's entities (pass the world createBallWorld returned)`,
    )
  }
  // bitECS's resetWorld gives the world a fresh entity index and forgets every entity and component, while
  // the simulation's stores still hold its balls, holes and walls: new ids would be handed out over them
  if (internal.entityIndex !== w.entityIndex) {
    throw new Error(`${caller}: the world was reset (bitECS resetWorld), which is not supported: bitECS forgot its balls, holes and walls but the simulation did not; make a new world (createBallWorld) instead`)
  }
  if (w.failed !== null && !reads) {
    throw new Error(
      `${caller}: the world's step at t = ${w.time} was ended part-done by an error (${w.failed}), and the world cannot go on ` +
        '(a ball may sit at an event no system handled); read it, or restore a snapshot taken before that step into a new world',
    )
  }
  return w
}
