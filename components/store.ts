// Struct-of-arrays component stores for bitECS: a component is a plain object of typed arrays indexed by
// entity id (or, for a pooled component such as RimContact, by a slot the entity holds). Each store has
// its own length: it starts at a preallocated size and grows (doubling) when an index used in it passes
// that length, so a component only some entities have stays as small as its use. Growing replaces the
// arrays, so systems fetch them from the store at each call, never across calls.

export type ArrayType =
  | Float64ArrayConstructor
  | Float32ArrayConstructor
  | Uint32ArrayConstructor
  | Int32ArrayConstructor
  | Uint8ArrayConstructor
  | Int8ArrayConstructor

export type Schema = Record<string, ArrayType>
export type Store<S extends Schema> = { [K in keyof S]: InstanceType<S[K]> }

interface StoreInfo {
  schema: Schema
  /** the schema's field names, listed once so that clearing a slot allocates nothing */
  keys: string[]
}

const stores = new WeakMap<object, StoreInfo>()

function info(store: object, caller: string): StoreInfo {
  const i = stores.get(store)
  if (!i) throw new TypeError(`${caller}: not a store made by createStore`)
  return i
}

/** Creates a store with one typed array per schema field, `capacity` entities long. */
export function createStore<S extends Schema>(schema: S, capacity: number): Store<S> {
  const store = {} as Record<string, unknown>
  const keys = Object.keys(schema)
  for (const key of keys) store[key] = new schema[key]!(capacity)
  stores.set(store, { schema, keys })
  return store as Store<S>
}

/** Reallocates every array of the store to `capacity` entries, keeping the contents. */
export function growStore(store: object, capacity: number): void {
  const { schema, keys } = info(store, 'growStore')
  const fields = store as Record<string, Float64Array>
  for (const key of keys) {
    const old = fields[key]!
    if (old.length >= capacity) continue
    const next = new schema[key]!(capacity) as Float64Array
    next.set(old)
    fields[key] = next
  }
}

/** Number of entries in each array of the store. */
export function storeLength(store: object): number {
  const { keys } = info(store, 'storeLength')
  return (store as Record<string, Float64Array>)[keys[0]!]!.length
}

/** Grows the store (doubling its length) until `index` fits; does nothing when it already does. */
export function fitStore(store: object, index: number): void {
  const length = storeLength(store)
  if (index < length) return
  let next = Math.max(length, 1)
  while (next <= index) next *= 2
  growStore(store, next)
}

/** Zeroes one entity's (or slot's) entry in every array of the store, for reuse. Allocates nothing. */
export function clearSlot(store: object, eid: number): void {
  const { keys } = info(store, 'clearSlot')
  const fields = store as Record<string, Float64Array>
  for (let i = 0; i < keys.length; i++) fields[keys[i]!]![eid] = 0
}
