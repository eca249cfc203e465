// The event heap of a contacts-on step: every event (a ball's own, a pair's contact, a search to resume)
// in global time order, keyed by (time, a, b, kind); entries carry their balls' path versions and are
// stale once a version moves on.
import { grown, type CollisionState } from '../world/contactState.js'

export const HeapKind = { Own: 0, Contact: 1, Resume: 2 } as const

function heapLess(C: CollisionState, i: number, j: number): boolean {
  const ti = C.hT[i]!
  const tj = C.hT[j]!
  if (ti !== tj) return ti < tj
  if (C.hA[i] !== C.hA[j]) return C.hA[i]! < C.hA[j]!
  if (C.hB[i] !== C.hB[j]) return C.hB[i]! < C.hB[j]!
  return C.hKind[i]! < C.hKind[j]!
}

function heapSwap(C: CollisionState, i: number, j: number): void {
  const f = C.hT[i]!
  C.hT[i] = C.hT[j]!
  C.hT[j] = f
  let u = C.hA[i]!
  C.hA[i] = C.hA[j]!
  C.hA[j] = u
  u = C.hB[i]!
  C.hB[i] = C.hB[j]!
  C.hB[j] = u
  u = C.hVA[i]!
  C.hVA[i] = C.hVA[j]!
  C.hVA[j] = u
  u = C.hVB[i]!
  C.hVB[i] = C.hVB[j]!
  C.hVB[j] = u
  u = C.hKind[i]!
  C.hKind[i] = C.hKind[j]!
  C.hKind[j] = u
}

export function heapPush(C: CollisionState, t: number, kind: number, a: number, b: number): void {
  if (C.heapCount === C.hT.length) {
    const n = C.hT.length * 2
    C.hT = grown(C.hT, n)
    C.hA = grown(C.hA, n)
    C.hB = grown(C.hB, n)
    C.hVA = grown(C.hVA, n)
    C.hVB = grown(C.hVB, n)
    C.hKind = grown(C.hKind, n)
  }
  let i = C.heapCount++
  C.hT[i] = t
  C.hA[i] = a
  C.hB[i] = b
  C.hVA[i] = C.ver[a]!
  C.hVB[i] = b === 0 ? 0 : C.ver[b]!
  C.hKind[i] = kind
  while (i > 0) {
    const p = (i - 1) >> 1
    if (!heapLess(C, i, p)) break
    heapSwap(C, i, p)
    i = p
  }
}

/** Removes the top entry (read it from index 0 first). */
export function heapPop(C: CollisionState): void {
  const n = --C.heapCount
  if (n === 0) return
  heapSwap(C, 0, n)
  let i = 0
  for (;;) {
    const l = 2 * i + 1
    if (l >= n) break
    const r = l + 1
    const m = r < n && heapLess(C, r, l) ? r : l
    if (!heapLess(C, m, i)) break
    heapSwap(C, i, m)
    i = m
  }
}

/** True when the top entry was made with its balls' current versions. */
export function heapTopLive(C: CollisionState): boolean {
  const a = C.hA[0]!
  const b = C.hB[0]!
  return C.ver[a] === C.hVA[0] && (b === 0 || C.ver[b] === C.hVB[0])
}
