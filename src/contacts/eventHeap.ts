// The event heap of a contacts-on step: every event (a ball's own, a pair's contact, a search to resume)
// in global time order, keyed by (time, a, b, kind); entries carry their balls' path versions and are
// stale once a version moves on.
//
// A 4-ary heap of (time, entry) pairs: sifting moves two numbers a level, and the four children of a node
// sit side by side. An entry's balls, versions and kind live in a pool (eA, eB, eVA, eVB, eKind), read only
// when two times tie and when the top is taken; the pool's free entries are kept on a stack.
import { grown, type CollisionState } from '../world/contactState.js'

export const HeapKind = { Own: 0, Contact: 1, Resume: 2 } as const

/**
 * Entry e1 before entry e2 at the same time: by a, b, kind (the callers compare the times, and call this on a
 * tie only: times passed to a call V8 does not inline were boxed, two heap numbers a tie, and a pile's
 * settled clusters tie by the hundred)
 */
function tieBefore(C: CollisionState, e1: number, e2: number): boolean {
  if (C.eA[e1] !== C.eA[e2]) return C.eA[e1]! < C.eA[e2]!
  if (C.eB[e1] !== C.eB[e2]) return C.eB[e1]! < C.eB[e2]!
  return C.eKind[e1]! < C.eKind[e2]!
}

/**
 * heapPush's time, written by the caller just before the call: a double passed to a function V8 does not
 * inline is boxed, a heap number at every prediction
 */
export const pushTime = new Float64Array(1)

/** Pushes an entry of this kind for balls a and b (b = 0: a's own event) at time pushTime[0]. */
export function heapPush(C: CollisionState, kind: number, a: number, b: number): void {
  const t = pushTime[0]!
  let e: number
  if (C.eFreeCount > 0) e = C.eFree[--C.eFreeCount]!
  else {
    if (C.eCount === C.eA.length) growPool(C, C.eCount * 2)
    e = C.eCount++
  }
  C.eA[e] = a
  C.eB[e] = b
  C.eVA[e] = C.ver[a]!
  C.eVB[e] = b === 0 ? 0 : C.ver[b]!
  C.eKind[e] = kind
  if (C.heapCount === C.hT.length) {
    C.hT = grown(C.hT, C.hT.length * 2)
    C.hE = grown(C.hE, C.hE.length * 2)
  }
  const hT = C.hT
  const hE = C.hE
  let i = C.heapCount++
  while (i > 0) {
    const p = (i - 1) >> 2
    const tp = hT[p]!
    if (!(t < tp || (t === tp && tieBefore(C, e, hE[p]!)))) break
    hT[i] = tp
    hE[i] = hE[p]!
    i = p
  }
  hT[i] = t
  hE[i] = e
}

/** Removes the top entry (read it first: heapTopT, heapTopKind, heapTopA, heapTopB, heapTopLive). */
export function heapPop(C: CollisionState): void {
  const hT = C.hT
  const hE = C.hE
  C.eFree[C.eFreeCount++] = hE[0]!
  const n = --C.heapCount
  if (n === 0) return
  const t = hT[n]!
  const e = hE[n]!
  let i = 0
  for (;;) {
    const c = 4 * i + 1
    if (c >= n) break
    let m = c
    let tm = hT[c]!
    const last = c + 3 < n ? c + 3 : n - 1
    for (let k = c + 1; k <= last; k++) {
      const tk = hT[k]!
      if (tk < tm || (tk === tm && tieBefore(C, hE[k]!, hE[m]!))) {
        m = k
        tm = tk
      }
    }
    if (!(tm < t || (tm === t && tieBefore(C, hE[m]!, e)))) break
    hT[i] = tm
    hE[i] = hE[m]!
    i = m
  }
  hT[i] = t
  hE[i] = e
}

/** Empties the heap and its pool. */
export function heapClear(C: CollisionState): void {
  C.heapCount = 0
  C.eCount = 0
  C.eFreeCount = 0
}

export function heapTopT(C: CollisionState): number {
  return C.hT[0]!
}

export function heapTopKind(C: CollisionState): number {
  return C.eKind[C.hE[0]!]!
}

export function heapTopA(C: CollisionState): number {
  return C.eA[C.hE[0]!]!
}

export function heapTopB(C: CollisionState): number {
  return C.eB[C.hE[0]!]!
}

/** True when the top entry was made with its balls' current versions. */
export function heapTopLive(C: CollisionState): boolean {
  const e = C.hE[0]!
  const a = C.eA[e]!
  const b = C.eB[e]!
  return C.ver[a] === C.eVA[e] && (b === 0 || C.ver[b] === C.eVB[e])
}

function growPool(C: CollisionState, n: number): void {
  C.eA = grown(C.eA, n)
  C.eB = grown(C.eB, n)
  C.eVA = grown(C.eVA, n)
  C.eVB = grown(C.eVB, n)
  C.eKind = grown(C.eKind, n)
  C.eFree = grown(C.eFree, n)
}
