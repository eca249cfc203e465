// Struct-of-arrays component stores for bitECS: a component is a plain object of typed arrays indexed by
// entity id. Stores start at a preallocated capacity and grow (doubling) when an entity id passes it;
// the arrays are then replaced, so systems fetch them from the store at each call, never across calls.

export type ArrayType =
  | Float64ArrayConstructor
  | Float32ArrayConstructor
  | Uint32ArrayConstructor
  | Int32ArrayConstructor
  | Uint8ArrayConstructor
  | Int8ArrayConstructor

export type Schema = Record<string, ArrayType>
export type Store<S extends Schema> = { [K in keyof S]: InstanceType<S[K]> }

const schemas = new WeakMap<object, Schema>()

/** Creates a store with one typed array per schema field, `capacity` entities long. */
export function createStore<S extends Schema>(schema: S, capacity: number): Store<S> {
  const store = {} as Record<string, unknown>
  for (const key of Object.keys(schema)) store[key] = new schema[key]!(capacity)
  schemas.set(store, schema)
  return store as Store<S>
}

/** Reallocates every array of the store to `capacity` entries, keeping the contents. */
export function growStore(store: object, capacity: number): void {
  const schema = schemas.get(store)
  if (!schema) throw new TypeError('growStore: not a store made by createStore')
  const fields = store as Record<string, Float64Array>
  for (const key of Object.keys(schema)) {
    const old = fields[key]!
    if (old.length >= capacity) continue
    const next = new schema[key]!(capacity) as Float64Array
    next.set(old)
    fields[key] = next
  }
}

/** Zeroes one entity's slot in every array of the store (a removed entity's slot is reused). */
export function clearSlot(store: object, eid: number): void {
  const schema = schemas.get(store)
  if (!schema) throw new TypeError('clearSlot: not a store made by createStore')
  const fields = store as Record<string, Float64Array>
  for (const key of Object.keys(schema)) fields[key]![eid] = 0
}
