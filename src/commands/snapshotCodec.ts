// The byte codec of snapshots (src/commands/snapshot.ts): a growable little-endian writer, a reader that
// names what it was reading when the bytes ran out, a checksum, and a walk that writes a value — a number,
// a boolean, null, a typed array (trailing zeros left out), a list, a plain object — and reads it back,
// with references to arrays and objects already written, so that one the world holds at two places stays
// one. Anything else (a function, a class instance, a view into a larger buffer) is refused by name.
const enum Tag {
  Undefined = 0,
  Null = 1,
  Number = 2,
  True = 3,
  False = 4,
  Typed = 5,
  List = 6,
  Object = 7,
  Ref = 8,
}

/** Typed-array kinds, by constructor */
export const KINDS = [Float64Array, Float32Array, Int32Array, Uint32Array, Uint8Array, Int8Array, Uint16Array, Int16Array] as const
export type Typed = InstanceType<(typeof KINDS)[number]>
export const SIZES = [8, 4, 4, 4, 1, 1, 2, 2]

export class Writer {
  bytes = new Uint8Array(1 << 16)
  view = new DataView(this.bytes.buffer)
  at = 0

  room(n: number): void {
    if (this.at + n <= this.bytes.length) return
    let len = this.bytes.length * 2
    while (len < this.at + n) len *= 2
    const next = new Uint8Array(len)
    next.set(this.bytes.subarray(0, this.at))
    this.bytes = next
    this.view = new DataView(next.buffer)
  }
  u8(v: number): void {
    this.room(1)
    this.bytes[this.at++] = v
  }
  u16(v: number): void {
    this.room(2)
    this.view.setUint16(this.at, v, true)
    this.at += 2
  }
  u32(v: number): void {
    this.room(4)
    this.view.setUint32(this.at, v, true)
    this.at += 4
  }
  f64(v: number): void {
    this.room(8)
    this.view.setFloat64(this.at, v, true)
    this.at += 8
  }
  ascii(s: string): void {
    this.u32(s.length)
    this.room(s.length)
    for (let i = 0; i < s.length; i++) {
      const c = s.charCodeAt(i)
      if (c > 0x7e) throw new TypeError(`snapshot: only ASCII text can be stored, got ${JSON.stringify(s)}`)
      this.bytes[this.at++] = c
    }
  }
}

/** What restore throws for bytes it will not read (a RangeError, named so that a caller can tell it apart). */
export class SnapshotError extends RangeError {
  override name = 'SnapshotError'
}

export class Reader {
  view: DataView
  at = 0
  constructor(readonly bytes: Uint8Array) {
    this.view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength)
  }
  need(n: number, what: string): void {
    if (this.at + n > this.bytes.length) throw new SnapshotError(`restore: the bytes end inside ${what} (truncated at ${this.bytes.length} bytes)`)
  }
  u8(what: string): number {
    this.need(1, what)
    return this.bytes[this.at++]!
  }
  u16(what: string): number {
    this.need(2, what)
    const v = this.view.getUint16(this.at, true)
    this.at += 2
    return v
  }
  u32(what: string): number {
    this.need(4, what)
    const v = this.view.getUint32(this.at, true)
    this.at += 4
    return v
  }
  f64(what: string): number {
    this.need(8, what)
    const v = this.view.getFloat64(this.at, true)
    this.at += 8
    return v
  }
  ascii(what: string): string {
    const n = this.u32(what)
    this.need(n, what)
    let s = ''
    for (let i = 0; i < n; i++) s += String.fromCharCode(this.bytes[this.at++]!)
    return s
  }
}

/** FNV-1a, 32 bits, of bytes[0, n) */
export function checksum(bytes: Uint8Array, n: number): number {
  let h = 0x811c9dc5
  for (let i = 0; i < n; i++) h = Math.imul(h ^ bytes[i]!, 0x01000193) >>> 0
  return h
}

/** The config as JSON with sorted keys: the same text for the same config on every engine. */
export function configText(config: object): string {
  const c = config as Record<string, unknown>
  const out: Record<string, unknown> = {}
  for (const k of Object.keys(c).sort()) out[k] = c[k]
  return JSON.stringify(out)
}

export function isPlain(v: object): boolean {
  const p = Object.getPrototypeOf(v)
  return p === Object.prototype || p === null
}

export function kindOf(v: ArrayBufferView): number {
  for (let k = 0; k < KINDS.length; k++) if (v instanceof KINDS[k]!) return k
  return -1
}

export function writeValue(out: Writer, seen: Map<object, number>, path: string, v: unknown): void {
  if (v === undefined) return out.u8(Tag.Undefined)
  if (v === null) return out.u8(Tag.Null)
  if (typeof v === 'number') {
    out.u8(Tag.Number)
    return out.f64(v)
  }
  if (typeof v === 'boolean') return out.u8(v ? Tag.True : Tag.False)
  if (typeof v !== 'object') throw new TypeError(`snapshot: ${path} holds a ${typeof v}, which a snapshot cannot store`)
  const ref = seen.get(v)
  if (ref !== undefined) {
    out.u8(Tag.Ref)
    return out.u32(ref)
  }
  seen.set(v, seen.size)
  if (ArrayBuffer.isView(v)) {
    const kind = kindOf(v)
    const a = v as Typed
    if (kind < 0 || a.byteLength !== a.buffer.byteLength) {
      throw new TypeError(`snapshot: ${path} is a ${v.constructor.name} ${kind < 0 ? 'of a kind' : 'view into a larger buffer, which'} a snapshot cannot store`)
    }
    let used = a.length
    while (used > 0 && a[used - 1] === 0 && !Object.is(a[used - 1], -0)) used--
    out.u8(Tag.Typed)
    out.u8(kind)
    out.u32(a.length)
    out.u32(used)
    const size = SIZES[kind]!
    out.room(used * size)
    const view = out.view
    let at = out.at
    for (let i = 0; i < used; i++, at += size) {
      const x = a[i]!
      if (kind === 0) view.setFloat64(at, x, true)
      else if (kind === 1) view.setFloat32(at, x, true)
      else if (kind === 2) view.setInt32(at, x, true)
      else if (kind === 3) view.setUint32(at, x, true)
      else if (kind === 4) view.setUint8(at, x)
      else if (kind === 5) view.setInt8(at, x)
      else if (kind === 6) view.setUint16(at, x, true)
      else view.setInt16(at, x, true)
    }
    out.at = at
    return
  }
  if (Array.isArray(v)) {
    out.u8(Tag.List)
    out.u32(v.length)
    for (let i = 0; i < v.length; i++) writeValue(out, seen, `${path}[${i}]`, v[i])
    return
  }
  if (!isPlain(v)) throw new TypeError(`snapshot: ${path} holds a ${v.constructor?.name ?? 'object'}, which a snapshot cannot store`)
  const keys = Object.keys(v)
  out.u8(Tag.Object)
  out.u32(keys.length)
  for (const k of keys) {
    out.ascii(k)
    writeValue(out, seen, `${path}.${k}`, (v as Record<string, unknown>)[k])
  }
}

export function readValue(r: Reader, seen: unknown[], path: string): unknown {
  const tag = r.u8(path)
  switch (tag) {
    case Tag.Undefined:
      return undefined
    case Tag.Null:
      return null
    case Tag.Number:
      return r.f64(path)
    case Tag.True:
      return true
    case Tag.False:
      return false
    case Tag.Ref: {
      const i = r.u32(path)
      if (i >= seen.length) throw new SnapshotError(`restore: ${path} refers to value ${i}, of ${seen.length} read so far (malformed bytes)`)
      return seen[i]
    }
    case Tag.Typed: {
      const kind = r.u8(path)
      if (kind >= KINDS.length) throw new SnapshotError(`restore: ${path} has typed-array kind ${kind}, allowed 0–${KINDS.length - 1} (malformed bytes)`)
      const length = r.u32(path)
      const used = r.u32(path)
      if (used > length) throw new SnapshotError(`restore: ${path} lists ${used} elements of an array of ${length} (malformed bytes)`)
      const size = SIZES[kind]!
      r.need(used * size, path)
      const a = new KINDS[kind]!(length)
      seen.push(a)
      const view = r.view
      let at = r.at
      for (let i = 0; i < used; i++, at += size) {
        a[i] =
          kind === 0 ? view.getFloat64(at, true)
          : kind === 1 ? view.getFloat32(at, true)
          : kind === 2 ? view.getInt32(at, true)
          : kind === 3 ? view.getUint32(at, true)
          : kind === 4 ? view.getUint8(at)
          : kind === 5 ? view.getInt8(at)
          : kind === 6 ? view.getUint16(at, true)
          : view.getInt16(at, true)
      }
      r.at = at
      return a
    }
    case Tag.List: {
      const n = r.u32(path)
      r.need(n, path) // at least a tag byte each
      const list: unknown[] = []
      seen.push(list)
      for (let i = 0; i < n; i++) list.push(readValue(r, seen, `${path}[${i}]`))
      return list
    }
    case Tag.Object: {
      const n = r.u32(path)
      r.need(n * 5, path)
      const o: Record<string, unknown> = {}
      seen.push(o)
      for (let i = 0; i < n; i++) {
        const k = r.ascii(path)
        o[k] = readValue(r, seen, `${path}.${k}`)
      }
      return o
    }
    default:
      throw new SnapshotError(`restore: ${path} has tag ${tag}, allowed 0–8 (malformed bytes)`)
  }
}
