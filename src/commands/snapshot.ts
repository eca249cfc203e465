// Snapshots: the whole simulation state of a world as bytes, and back.
//
// snapshotWorld(world) writes every field of the world's data — the component stores (Ball, Path,
// RimContact, Hole, Walls), the moving set, the hole table and grid, the contact state of either contact
// method, the event buffer (events not yet drained), the clock — and bitECS's entity index with which of
// this module's components each entity has. restoreWorld(world, bytes) gives a world made with the same
// config that state: stepping it then gives the same bits as stepping the original (tests/snapshot.test.ts).
//
// Format (all numbers little-endian): "PBSN", u16 format version, u32 length + the resolved config as
// JSON (keys sorted), u32 length + the body, u32 FNV-1a checksum of everything before it. The body is the
// world's data walked field by field: each value a tag byte, then a float64, a byte, a typed array (kind,
// length, how many leading elements follow: trailing zeros are left out, which keeps a snapshot of a world
// with spare capacity small), a list, an object (its keys, then its values), or a reference to an array or
// object met before (so arrays the world shares between two fields stay shared).
//
// Not in a snapshot: a game's own components and stores (its own to save), the schedule (made from the
// config), and the tabulated rim model's tables (named by their geometry, rebuilt or taken from the cache).
// Snapshots need METHOD 'exact': the tick-sampled comparison methods ('naive', 'v1') keep their sub-step
// state outside the world, and are refused.
import { addComponent, addEntity, hasComponent, removeEntity } from 'bitecs'
import type { BallWorld } from '../world/createWorld.js'
import { dropGoneHeld } from '../world/idLists.js'
import { MIN_TABLE_RATIO } from '../config/limits.js'
import { MAX_RATIO } from '../reference/tolerances.js'
import { rimTableFor } from '../reference/rimTables.js'
import { checkWorld } from './validate.js'
import { BALL_MODE_NAMES } from '../../components/Ball.js'
import { checksum, configText, kindOf, readValue, Reader, SnapshotError, writeValue, Writer } from './snapshotCodec.js'

/** Version of the byte format; restore refuses any other (2: the contact state keeps predictions across steps; 3: the path's origin and next event in world.pathHot; 4: the contact state keeps where each path may change next and what each prediction covered; 5: and the planner's distance to that change, with the path it was found for; the event heap as times and pool entries; 6: the fixed tick's halvings and its last tick's pairs; 7: and its coarsening back-off; 8: the exact method's contact counts per contact tick of the clock, not per step; 9: each buffered event's phase at its instant; 10: instead, the start of the window that recorded it; 11: the fixed tick's growth of its pairs over its last ticks; 12: the fixed tick's work meter; 13: and the spans whose last ticks it skipped; 14: the launcher's kick back-off; 15: that back-off per held ball, by id; 16: the held balls' grid; 17: the spot and held grids as two ball hashes, src/world/ballHash.ts; 18: the work meter's share of a try's work; 19: the hole grid's holes kept out of its cells; 20: the fixed tick's pairs that meet at their instant, world.meet). */
export const SNAPSHOT_VERSION = 20

const MAGIC = [0x50, 0x42, 0x53, 0x4e] // "PBSN"

/** World fields kept out of the walked body (see the top of this file; a failed world is not snapshotted) */
const SPECIAL = new Set(['config', 'entityIndex', 'rimTables', 'stepping', 'IsHole', 'recorder', 'holeCells', 'failed', 'heldGone'])

/** Component membership bits, per entity */
const BALL = 1
const PATH = 2
const RIM = 4
const HOLE = 8
const IS_HOLE = 16
const WALLS = 32

/** Snapshots hold the exact method's state; the tick-sampled variants keep theirs outside the world. */
function exactOnly(name: string, w: BallWorld): void {
  if (w.config.METHOD !== 'exact') {
    throw new RangeError(`${name}: snapshots need METHOD 'exact'; this world runs '${w.config.METHOD}' (a tick-sampled comparison method, whose sub-step state is not part of a snapshot)`)
  }
}

/** The world's data fields the body holds, in the order the world has them. */
function bodyKeys(w: BallWorld): string[] {
  return Object.keys(w).filter((k) => !SPECIAL.has(k))
}

/**
 * The whole simulation state of the world as bytes (see the top of this file). Not during a step. A game's
 * own components are not included.
 */
export function snapshotWorld(world: BallWorld): Uint8Array {
  const w = checkWorld('snapshotWorld', world)
  dropGoneHeld(w)
  if (w.stepping) throw new Error('snapshot (snapshotWorld): the world is in the middle of a step; take the snapshot between steps')
  // the events the callback has been handed are still in the buffer until the drain returns: a world restored
  // from such a snapshot would hand them out again (and refuse to drain, the drain's flag set)
  if (w.events.draining) throw new Error('snapshot (snapshotWorld): called from a drainEventsWith callback; take the snapshot after the drain returns')
  exactOnly('snapshotWorld', w)
  const out = new Writer()
  for (const b of MAGIC) out.u8(b)
  out.u16(SNAPSHOT_VERSION)
  out.ascii(configText(w.config))
  const bodyAt = out.at
  out.u32(0) // body length, filled in below
  // the entity index and which of this module's components each entity has
  const E = w.entityIndex
  out.u32(E.maxId)
  out.u32(E.aliveCount)
  out.u32(E.dense.length)
  for (let i = 0; i < E.dense.length; i++) out.u32(E.dense[i]!)
  for (let i = 0; i < E.aliveCount; i++) {
    const e = E.dense[i]!
    out.u8(
      (hasComponent(w, e, w.Ball) ? BALL : 0) |
        (hasComponent(w, e, w.Path) ? PATH : 0) |
        (hasComponent(w, e, w.RimContact) ? RIM : 0) |
        (hasComponent(w, e, w.Hole) ? HOLE : 0) |
        (hasComponent(w, e, w.IsHole) ? IS_HOLE : 0) |
        (hasComponent(w, e, w.Walls) ? WALLS : 0),
    )
  }
  // the rim tables, by geometry
  out.u32(w.rimTables.length)
  for (const t of w.rimTables) {
    out.f64(t.ratio)
    out.f64(t.inertia)
  }
  // every other field
  const seen = new Map<object, number>()
  const keys = bodyKeys(w)
  out.u32(keys.length)
  for (const k of keys) {
    out.ascii(k)
    writeValue(out, seen, k, (w as unknown as Record<string, unknown>)[k])
  }
  out.view.setUint32(bodyAt, out.at - bodyAt - 4, true)
  out.u32(checksum(out.bytes, out.at))
  return out.bytes.slice(0, out.at)
}

interface Decoded {
  maxId: number
  aliveCount: number
  dense: number[]
  members: Uint8Array
  tables: Array<[number, number]>
  fields: Record<string, unknown>
}

function decode(bytes: Uint8Array, config: string): Decoded {
  const r = new Reader(bytes)
  for (let i = 0; i < MAGIC.length; i++) {
    if (r.u8('the header') !== MAGIC[i]) throw new SnapshotError('restore: these bytes are not a snapshot (they do not start with "PBSN")')
  }
  const version = r.u16('the header')
  if (version !== SNAPSHOT_VERSION) throw new SnapshotError(`restore: snapshot format version ${version}; this module reads version ${SNAPSHOT_VERSION}`)
  // the lengths and the checksum before anything is read from the rest: a changed byte is reported as
  // such, never as what it happened to turn into (another config, a malformed body)
  const configAt = r.at
  const configLength = r.u32('the header')
  if (r.at + configLength + 8 > bytes.length) {
    throw new SnapshotError(`restore: the config should be ${configLength} bytes, followed by the body's length; the snapshot has ${bytes.length} bytes (truncated or altered)`)
  }
  r.at += configLength
  const bodyLength = r.u32('the header')
  if (r.at + bodyLength + 4 !== bytes.length) {
    throw new SnapshotError(`restore: the body should be ${bodyLength} bytes and end the snapshot with a 4-byte checksum; the snapshot has ${bytes.length} bytes (truncated, padded or altered)`)
  }
  const sum = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength).getUint32(bytes.length - 4, true)
  if (sum !== checksum(bytes, bytes.length - 4)) throw new SnapshotError('restore: checksum mismatch (the bytes were changed after the snapshot was taken)')
  const bodyAt = r.at
  r.at = configAt
  const theirs = r.ascii('the config')
  r.at = bodyAt
  if (theirs !== config) {
    let key = '(unreadable)'
    try {
      const a = JSON.parse(theirs) as Record<string, unknown>
      const b = JSON.parse(config) as Record<string, unknown>
      key = [...new Set([...Object.keys(a), ...Object.keys(b)])].sort().find((k) => JSON.stringify(a[k]) !== JSON.stringify(b[k])) ?? key
      if (key !== '(unreadable)') key = `${key}: the snapshot's is ${JSON.stringify(a[key])}, this world's ${JSON.stringify(b[key])}`
    } catch {
      // fall through with the generic message
    }
    throw new SnapshotError(`restore: the snapshot was taken with another config (${key}); make the world with the snapshot's config`)
  }
  const maxId = r.u32('the entity index')
  const aliveCount = r.u32('the entity index')
  const n = r.u32('the entity index')
  if (aliveCount > n || n !== maxId) throw new SnapshotError(`restore: entity index with ${aliveCount} alive of ${n} ids, largest ${maxId} (malformed bytes)`)
  r.need(4 * n, 'the entity index')
  const dense: number[] = []
  for (let i = 0; i < n; i++) {
    const id = r.u32('the entity index')
    if (id < 1 || id > maxId) throw new SnapshotError(`restore: entity id ${id} outside 1–${maxId} (malformed bytes)`)
    dense.push(id)
  }
  if (new Set(dense).size !== n) throw new SnapshotError('restore: an entity id is listed twice (malformed bytes)')
  r.need(aliveCount, 'the entity index')
  const members = new Uint8Array(aliveCount)
  for (let i = 0; i < aliveCount; i++) members[i] = r.u8('the entity index')
  const tableCount = r.u32('the rim tables')
  r.need(16 * tableCount, 'the rim tables')
  const tables: Array<[number, number]> = []
  for (let i = 0; i < tableCount; i++) {
    const ratio = r.f64('the rim tables')
    const inertia = r.f64('the rim tables')
    // the geometry prepareRimTable accepts (src/reference/rimTables.ts): no table is built outside it
    if (!(ratio >= MIN_TABLE_RATIO && ratio <= MAX_RATIO) || !(inertia > 0 && inertia <= 2 / 3)) {
      throw new SnapshotError(`restore: rim table ${ratio}:${inertia} outside the geometry a table can have (R/r in [${MIN_TABLE_RATIO}, ${MAX_RATIO}], j in (0, 2/3])`)
    }
    tables.push([ratio, inertia])
  }
  const count = r.u32('the body')
  const fields: Record<string, unknown> = {}
  const seen: unknown[] = []
  for (let i = 0; i < count; i++) {
    const k = r.ascii('the body')
    fields[k] = readValue(r, seen, k)
  }
  if (r.at !== bytes.length - 4) throw new SnapshotError(`restore: ${bytes.length - 4 - r.at} bytes left over after the body (malformed bytes)`)
  return { maxId, aliveCount, dense, members, tables, fields }
}

/** Throws unless value `v` from the snapshot fits field `path` of the world, `t` (the same shape). */
function checkShape(path: string, t: unknown, v: unknown): void {
  if (t !== null && typeof t === 'object' && !ArrayBuffer.isView(t) && !Array.isArray(t)) {
    if (v === null || typeof v !== 'object' || ArrayBuffer.isView(v) || Array.isArray(v)) {
      throw new SnapshotError(`restore: ${path} is an object in this world, not in the snapshot (another version of the module?)`)
    }
    const tk = Object.keys(t)
    const vk = Object.keys(v)
    if (tk.length !== vk.length || tk.some((k, i) => k !== vk[i])) {
      throw new SnapshotError(`restore: ${path} has fields ${tk.join(', ')} in this world and ${vk.join(', ')} in the snapshot (another version of the module?)`)
    }
    for (const k of tk) checkShape(`${path}.${k}`, (t as Record<string, unknown>)[k], (v as Record<string, unknown>)[k])
    return
  }
  if (ArrayBuffer.isView(t)) {
    if (!ArrayBuffer.isView(v) || kindOf(v) !== kindOf(t)) throw new SnapshotError(`restore: ${path} is a ${t.constructor.name} in this world, not in the snapshot`)
    return
  }
  if (Array.isArray(t)) {
    if (!Array.isArray(v)) throw new SnapshotError(`restore: ${path} is a list in this world, not in the snapshot`)
    // lists of objects (the registered per-ball stores) keep their objects: the same count is needed
    if (t.some((x) => x !== null && typeof x === 'object') || v.some((x) => x !== null && typeof x === 'object')) {
      if (t.length !== v.length) throw new SnapshotError(`restore: ${path} has ${t.length} entries in this world and ${v.length} in the snapshot`)
      for (let i = 0; i < t.length; i++) checkShape(`${path}[${i}]`, t[i], v[i])
    }
    return
  }
  if (t === null ? v !== null : typeof v !== typeof t) {
    throw new SnapshotError(`restore: ${path} is ${t === null ? 'null' : `a ${typeof t}`} in this world and ${v === null ? 'null' : `a ${typeof v}`} in the snapshot`)
  }
}

/** The component stores: they hold finite numbers only, in a snapshot as in a world */
const STORES = ['Ball', 'Path', 'RimContact', 'Hole', 'Walls']

function checkFinite(name: string, store: Record<string, unknown>): void {
  for (const k of Object.keys(store)) {
    const a = store[k]
    if (!(a instanceof Float64Array || a instanceof Float32Array)) continue
    for (let i = 0; i < a.length; i++) {
      if (!Number.isFinite(a[i]!)) throw new SnapshotError(`restore: ${name}.${k}[${i}] is ${a[i]}; a store holds finite numbers only (malformed bytes)`)
    }
  }
}

/**
 * Throws unless the snapshot's lists of balls name balls: every ball's mode is one of BALL_MODE_NAMES; the
 * moving set's ids are live balls, each once (its index the inverse of its list); the event pass's lists and
 * the launcher's queue hold live balls. The checksum catches accidents, not changes made on purpose (it
 * can be recomputed); a ball id that was not a ball in the moving set once made a step that never returned.
 */
function checkLists(d: Decoded): void {
  const balls = new Set<number>()
  for (let i = 0; i < d.aliveCount; i++) if ((d.members[i]! & BALL) !== 0) balls.add(d.dense[i]!)
  const f = d.fields as Record<string, Record<string, unknown>>
  const mode = f['Ball']!['mode'] as ArrayLike<number>
  for (const b of balls) {
    if (!(b < mode.length && mode[b]! >= 0 && mode[b]! < BALL_MODE_NAMES.length)) throw new SnapshotError(`restore: ball ${b} has no mode a ball can have (malformed bytes)`)
  }
  const moving = f['moving']!
  const count = moving['count'] as number
  const dense = moving['dense'] as Uint32Array
  const sparse = moving['sparse'] as Uint32Array
  if (!(Number.isInteger(count) && count >= 0 && count <= dense.length)) throw new SnapshotError(`restore: the moving set's count ${count} does not fit its list (malformed bytes)`)
  for (let i = 0; i < count; i++) {
    const b = dense[i]!
    if (!balls.has(b) || b >= sparse.length || sparse[b] !== i) throw new SnapshotError(`restore: the moving set lists ${b}, which is not a ball of it (malformed bytes)`)
  }
  for (const k of ['marked', 'todo', 'held']) {
    const list = f[k]!
    const n = list['count'] as number
    const ids = list['ids'] as Uint32Array
    if (!(Number.isInteger(n) && n >= 0 && n <= ids.length)) throw new SnapshotError(`restore: the list ${k} has a count ${n} that does not fit it (malformed bytes)`)
    for (let i = 0; i < n; i++) if (!balls.has(ids[i]!)) throw new SnapshotError(`restore: the list ${k} holds ${ids[i]}, which is not a ball (malformed bytes)`)
  }
}

/** Writes value `v` into field `key` of `parent` (objects kept and filled in, arrays and values replaced). */
function apply(parent: Record<string, unknown>, key: string, v: unknown): void {
  const t = parent[key]
  if (t !== null && typeof t === 'object' && !ArrayBuffer.isView(t) && !Array.isArray(t)) {
    const o = t as Record<string, unknown>
    for (const k of Object.keys(o)) apply(o, k, (v as Record<string, unknown>)[k])
    return
  }
  if (Array.isArray(t) && t.some((x) => x !== null && typeof x === 'object')) {
    const list = v as unknown[]
    for (let i = 0; i < t.length; i++) apply(t as unknown as Record<string, unknown>, String(i), list[i])
    return
  }
  parent[key] = v
}

/**
 * Gives `world` — made with the same config, and never given an entity — the state in `bytes` (from
 * snapshotWorld). Bytes that are not a snapshot, are truncated or changed, or come from another config
 * or format version throw a RangeError that says which, and leave the world as it was.
 */
export function restoreWorld(world: BallWorld, bytes: Uint8Array): void {
  const w = checkWorld('restoreWorld', world, true)
  if (!(bytes instanceof Uint8Array)) throw new TypeError(`restore: bytes must be a Uint8Array (from snapshot()), got ${bytes === null ? 'null' : typeof bytes}`)
  if (w.stepping) throw new Error('restore: the world is in the middle of a step')
  // a recording holds the state it started from and the inputs since; a restore is neither
  if (w.recorder !== null) throw new Error('restore: the world is recording; restore first, then start the recording (a replay starts from the state its recording started in)')
  exactOnly('restore', w)
  if (w.entityIndex.maxId !== 0) {
    // (removing them does not do: bitECS's entity index, which the snapshot sets, has handed ids out)
    throw new Error(`restore: the world has had entities (bitECS has handed out ids up to ${w.entityIndex.maxId}, removed or not), and a snapshot restores the ids too; restore into a world just made with the snapshot's config (createBallPhysics(config)), then add the game's own components`)
  }
  const d = decode(bytes, configText(w.config))
  const keys = bodyKeys(w)
  const theirs = Object.keys(d.fields)
  if (keys.length !== theirs.length || keys.some((k, i) => k !== theirs[i])) {
    throw new SnapshotError(`restore: the world has fields ${keys.join(', ')}, the snapshot ${theirs.join(', ')} (another version of the module?)`)
  }
  for (const k of keys) checkShape(k, (w as unknown as Record<string, unknown>)[k], d.fields[k])
  for (const k of STORES) checkFinite(k, d.fields[k] as Record<string, unknown>)
  checkFinite('world', { pathHot: d.fields['pathHot'] })
  checkLists(d)
  const tables = d.tables.map(([ratio, inertia]) => rimTableFor(ratio, inertia))
  // nothing below throws: the world changes only now
  // ids 1..maxId made through bitECS, the ones not alive removed again; then the index's order (which id
  // a new entity gets next) set to the snapshot's
  for (let i = 0; i < d.maxId; i++) addEntity(w)
  for (let i = d.aliveCount; i < d.dense.length; i++) removeEntity(w, d.dense[i]!)
  const E = w.entityIndex
  for (let i = 0; i < d.dense.length; i++) {
    E.dense[i] = d.dense[i]!
    E.sparse[d.dense[i]!] = i
  }
  for (let i = 0; i < d.aliveCount; i++) {
    const e = d.dense[i]!
    const m = d.members[i]!
    if ((m & IS_HOLE) !== 0) addComponent(w, e, w.IsHole)
    if ((m & HOLE) !== 0) addComponent(w, e, w.Hole)
    if ((m & WALLS) !== 0) addComponent(w, e, w.Walls)
    if ((m & BALL) !== 0) addComponent(w, e, w.Ball) // adoptBall runs (and adds Path); its rows are overwritten below
    if ((m & PATH) !== 0 && !hasComponent(w, e, w.Path)) addComponent(w, e, w.Path)
    if ((m & RIM) !== 0) addComponent(w, e, w.RimContact)
  }
  w.rimTables.length = 0
  for (const t of tables) w.rimTables.push(t)
  for (const k of keys) apply(w as unknown as Record<string, unknown>, k, d.fields[k])
  // (a world that failed with no entity given yet: the snapshot's state replaces its own)
  w.failed = null
  // the snapshot's queue replaced the world's, removed balls and all
  w.heldGone = 0
}
