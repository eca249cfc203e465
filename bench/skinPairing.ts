// Neighbour lists kept from tick to tick, set beside the bare pairing grid of bench/barePairing.ts on the
// same recorded frames: whether keeping pairs across ticks can pair the moving balls of a tick for less than
// a grid built anew at each tick. Both lists give each ball a skin: at its entry's time it is listed with
// position p0 and list radius R = radius + skin + TOUCH_GAP, skin = speed · K ticks, and two balls are listed
// together when |p0_a − p0_b| < R_a + R_b. At each tick a ball whose travel since its entry plus one tick's
// travel is within its skin (|p − p0| + speed · tick ≤ skin) keeps its entry; then every pair within reach
// at the tick (|p_a − p_b| < reach_a + reach_b, reach = radius + speed · tick + TOUCH_GAP, as the grid's) is
// a listed pair, because |p0_a − p0_b| ≤ |p_a − p_b| + |p_a − p0_a| + |p_b − p0_b|. The tick then tests
// the listed pairs only.
//   rebuild: the whole list is built again (the grid of bench/barePairing.ts over the R's) when any ball
//            has spent its skin, is new, or was away when the list was last built;
//   per ball: a ball that has spent its skin (or is new, or back after a step away) alone gets a new entry
//            and is queried against the entries of the rest through a hashed grid kept from tick to tick;
//            its old pairs drop out of the list when the tick's pass meets them.
// Both count exactly the pairs the grid counts at every frame (tests/barePairing.test.ts), so the time is
// the only difference.
import { TOUCH_GAP } from '../src/config/tolerances'
import { cellPairs, type Frame, type PairSink } from './barePairing'

/** A neighbour list's state over a run of frames: `frame` counts the pairs within reach at the next frame. */
export interface SkinList {
  frame(f: Frame): number
  /** Entries made since the start (the rebuild variant: balls × builds). */
  entries(): number
}

/** A copy of a in a new array of length n, the rest filled with `fill`. */
function grown<T extends Float64Array | Int32Array>(a: T, n: number, fill = 0): T {
  const m = new (a.constructor as new (n: number) => T)(n)
  if (fill !== 0) m.fill(fill)
  m.set(a)
  return m
}

/** Per-entity scratch shared by both lists, grown to the largest id seen. */
class Entries {
  x0 = new Float64Array(0)
  y0 = new Float64Array(0)
  R = new Float64Array(0)
  skin = new Float64Array(0)
  seen = new Int32Array(0)
  slot = new Int32Array(0)
  made = 0

  fit(f: Frame): void {
    let top = 0
    for (let i = 0; i < f.n; i++) if (f.id[i]! > top) top = f.id[i]!
    if (top < this.x0.length) return
    const n = 2 * top + 64
    this.x0 = grown(this.x0, n)
    this.y0 = grown(this.y0, n)
    this.R = grown(this.R, n)
    this.skin = grown(this.skin, n)
    this.seen = grown(this.seen, n)
    this.slot = grown(this.slot, n)
  }

  /** A new entry for the ball at slot i of f: its position now, its skin K ticks of its present speed. */
  enter(f: Frame, i: number, K: number, tick: number, speed: number): void {
    const e = f.id[i]!
    const s = speed * K * tick
    this.x0[e] = f.x[i]!
    this.y0[e] = f.y[i]!
    this.skin[e] = s
    this.R[e] = f.r[i]! + s + TOUCH_GAP
    this.made++
  }

  /** Whether the ball at slot i keeps its entry for the next tick. */
  keeps(f: Frame, i: number, speed: number, tick: number): boolean {
    const e = f.id[i]!
    const dx = f.x[i]! - this.x0[e]!
    const dy = f.y[i]! - this.y0[e]!
    return Math.sqrt(dx * dx + dy * dy) + speed * tick <= this.skin[e]!
  }
}

/** The listed pairs (entity ids, and for the per-ball list the entries' versions they were made with). */
class Pairs {
  a: Int32Array = new Int32Array(1024)
  b: Int32Array = new Int32Array(1024)
  va: Int32Array = new Int32Array(1024)
  vb: Int32Array = new Int32Array(1024)
  count = 0

  push(a: number, b: number, va: number, vb: number): void {
    if (this.count === this.a.length) {
      const n = 2 * this.count
      this.a = grown(this.a, n)
      this.b = grown(this.b, n)
      this.va = grown(this.va, n)
      this.vb = grown(this.vb, n)
    }
    const k = this.count++
    this.a[k] = a
    this.b[k] = b
    this.va[k] = va
    this.vb[k] = vb
  }
}

/** Whether the balls at slots ia and ib of f are within reach at the tick (reaches precomputed by slot). */
function withinReach(f: Frame, reach: Float64Array, ia: number, ib: number): number {
  const dx = f.x[ib]! - f.x[ia]!
  const dy = f.y[ib]! - f.y[ia]!
  const s = reach[ia]! + reach[ib]!
  return dx * dx + dy * dy < s * s ? 1 : 0
}

/** Speeds and reaches of f's balls by slot, in `speed` and `reach`, and list radii (grown as needed). */
class Reaches {
  speed = new Float64Array(0)
  reach = new Float64Array(0)
  list = new Float64Array(0)

  of(f: Frame, tick: number): void {
    if (this.speed.length < f.n) {
      this.speed = new Float64Array(2 * f.n)
      this.reach = new Float64Array(2 * f.n)
      this.list = new Float64Array(2 * f.n)
    }
    for (let i = 0; i < f.n; i++) {
      const v = Math.sqrt(f.vx[i]! * f.vx[i]! + f.vy[i]! * f.vy[i]!)
      this.speed[i] = v
      this.reach[i] = f.r[i]! + v * tick + TOUCH_GAP
    }
  }
}

/** The rebuild variant: skins of K ticks, the whole list built again when any ball needs a new entry. */
export function skinRebuild(K: number, tick: number): SkinList {
  const E = new Entries()
  const P = new Pairs()
  const S = new Reaches()
  let built = 0
  let stamp = 0
  let cur: Frame | null = null
  // the grid's pairs are slots of the frame; the list keeps entity ids
  const sink: PairSink = { push: (sa, sb) => P.push(cur!.id[sa]!, cur!.id[sb]!, 0, 0) }
  return {
    entries: () => E.made,
    frame(f: Frame): number {
      E.fit(f)
      S.of(f, tick)
      stamp++
      let stale = false
      for (let i = 0; i < f.n; i++) {
        const e = f.id[i]!
        E.slot[e] = i
        if (!stale && (E.seen[e]! < built || E.seen[e] === 0 || !E.keeps(f, i, S.speed[i]!, tick))) stale = true
      }
      for (let i = 0; i < f.n; i++) E.seen[f.id[i]!] = stamp
      if (stale) {
        built = stamp
        for (let i = 0; i < f.n; i++) {
          E.enter(f, i, K, tick, S.speed[i]!)
          S.list[i] = E.R[f.id[i]!]!
        }
        P.count = 0
        cur = f
        cellPairs(f.n, f.x, f.y, S.list, sink)
      }
      let found = 0
      for (let p = 0; p < P.count; p++) {
        const a = P.a[p]!
        const b = P.b[p]!
        if (E.seen[a] !== stamp || E.seen[b] !== stamp) continue
        found += withinReach(f, S.reach, E.slot[a]!, E.slot[b]!)
      }
      return found
    },
  }
}

/**
 * The per-ball variant: skins of K ticks, an entry renewed ball by ball, the entries in a hashed grid of
 * cells `cell` px (the first frame's largest list radius when 0) kept from tick to tick.
 */
export function skinPerBall(K: number, tick: number, cell = 0): SkinList {
  const E = new Entries()
  const P = new Pairs()
  const S = new Reaches()
  const HB = 1 << 14
  const head = new Int32Array(HB).fill(-1)
  let bucket: Int32Array = new Int32Array(0)
  let next: Int32Array = new Int32Array(0)
  let prev: Int32Array = new Int32Array(0)
  let ver: Int32Array = new Int32Array(0)
  let visit: Int32Array = new Int32Array(0)
  let size = cell
  let inv = cell > 0 ? 1 / cell : 0
  let maxR = 0
  let stamp = 0
  let queries = 0
  let last: Frame | null = null
  const hash = (cx: number, cy: number): number => (Math.imul(cx, 73856093) ^ Math.imul(cy, 19349663)) & (HB - 1)
  const fitLinks = (): void => {
    if (bucket.length >= E.x0.length) return
    const n = E.x0.length
    bucket = grown(bucket, n, -1)
    next = grown(next, n, -1)
    prev = grown(prev, n, -1)
    ver = grown(ver, n)
    visit = grown(visit, n)
  }
  const unlink = (e: number): void => {
    const c = bucket[e]!
    if (c < 0) return
    const p = prev[e]!
    const q = next[e]!
    if (p >= 0) next[p] = q
    else head[c] = q
    if (q >= 0) prev[q] = p
    bucket[e] = -1
  }
  const link = (e: number): void => {
    const c = hash(Math.floor(E.x0[e]! * inv), Math.floor(E.y0[e]! * inv))
    bucket[e] = c
    prev[e] = -1
    const h = head[c]!
    next[e] = h
    if (h >= 0) prev[h] = e
    head[c] = e
  }
  // pairs ball e's new entry with every entry of a ball present at this tick that its list radius meets
  const query = (e: number): void => {
    queries++
    const span = Math.ceil((E.R[e]! + maxR) * inv)
    const cx = Math.floor(E.x0[e]! * inv)
    const cy = Math.floor(E.y0[e]! * inv)
    for (let gy = cy - span; gy <= cy + span; gy++) {
      for (let gx = cx - span; gx <= cx + span; gx++) {
        // two cells of the span can share a bucket: each ball is met once per query
        for (let o = head[hash(gx, gy)]!; o >= 0; o = next[o]!) {
          if (o === e || E.seen[o] !== stamp || visit[o] === queries) continue
          visit[o] = queries
          const dx = E.x0[o]! - E.x0[e]!
          const dy = E.y0[o]! - E.y0[e]!
          const s = E.R[e]! + E.R[o]!
          if (dx * dx + dy * dy < s * s) P.push(e, o, ver[e]!, ver[o]!)
        }
      }
    }
  }
  return {
    entries: () => E.made,
    frame(f: Frame): number {
      E.fit(f)
      fitLinks()
      S.of(f, tick)
      stamp++
      if (size === 0) {
        for (let i = 0; i < f.n; i++) size = Math.max(size, f.r[i]! + S.speed[i]! * K * tick + TOUCH_GAP)
        inv = size > 0 ? 1 / size : 1
      }
      for (let i = 0; i < f.n; i++) {
        const e = f.id[i]!
        E.slot[e] = i
        E.seen[e] = stamp
      }
      // balls of the last tick gone from this one leave the grid; one that comes back (or is new) is out
      // of it (no bucket), missed the queries made meanwhile, and is entered again
      if (last !== null) for (let i = 0; i < last.n; i++) if (E.seen[last.id[i]!] !== stamp) unlink(last.id[i]!)
      last = f
      for (let i = 0; i < f.n; i++) {
        const e = f.id[i]!
        if (bucket[e]! >= 0 && E.keeps(f, i, S.speed[i]!, tick)) continue
        unlink(e)
        ver[e]!++
        E.enter(f, i, K, tick, S.speed[i]!)
        if (E.R[e]! > maxR) maxR = E.R[e]!
        link(e)
        query(e)
      }
      let found = 0
      let q = 0
      for (let p = 0; p < P.count; p++) {
        const a = P.a[p]!
        const b = P.b[p]!
        if (ver[a] !== P.va[p] || ver[b] !== P.vb[p] || E.seen[a] !== stamp || E.seen[b] !== stamp) continue
        // kept (compacted in place)
        P.a[q] = a
        P.b[q] = b
        P.va[q] = P.va[p]!
        P.vb[q] = P.vb[p]!
        q++
        found += withinReach(f, S.reach, E.slot[a]!, E.slot[b]!)
      }
      P.count = q
      return found
    },
  }
}
