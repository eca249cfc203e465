import { describe, expect, it } from 'vitest'
import fc from 'fast-check'
import { createCollisionState } from '../../src/world/contactState'
import { HeapKind, heapClear, heapPop, heapPush as pushAt, heapTopA, heapTopB, heapTopKind, heapTopLive, heapTopT, pushTime } from '../../src/contacts/eventHeap'
import type { CollisionState } from '../../src/world/contactState'

/** heapPush at time t (the heap reads its time from pushTime) */
function heapPush(C: CollisionState, t: number, kind: number, a: number, b: number): void {
  pushTime[0] = t
  pushAt(C, kind, a, b)
}

type Entry = { t: number; a: number; b: number; kind: number }
const order = (x: Entry, y: Entry) => x.t - y.t || x.a - y.a || x.b - y.b || x.kind - y.kind

/** A few distinct times so that ties (decided by a, b, kind) are common. */
const entry = fc.record({
  t: fc.constantFrom(0, 0.25, 0.5, 1, 1e-9, 3),
  a: fc.integer({ min: 1, max: 6 }),
  b: fc.integer({ min: 0, max: 6 }),
  kind: fc.constantFrom(HeapKind.Own, HeapKind.Contact, HeapKind.Resume),
})
/** a push, or (null) a pop of the top when there is one */
const op = fc.oneof(entry, fc.constant(null))

describe('event heap', () => {
  it('gives its entries back in (time, a, b, kind) order, whatever the pushes and pops between, and grows past its first size', () => {
    fc.assert(
      fc.property(fc.array(op, { maxLength: 3000 }), (ops) => {
        const C = createCollisionState(8, 11)
        const model: Entry[] = []
        const check = () => {
          model.sort(order)
          const want = model.shift()!
          expect({ t: heapTopT(C), a: heapTopA(C), b: heapTopB(C), kind: heapTopKind(C) }).toEqual(want)
          heapPop(C)
        }
        for (const o of ops) {
          if (o === null) {
            if (model.length > 0) check()
          } else {
            heapPush(C, o.t, o.kind, o.a, o.b)
            model.push(o)
          }
          expect(C.heapCount).toBe(model.length)
        }
        while (model.length > 0) check()
      }),
      { numRuns: 60 },
    )
  })

  it('marks an entry stale once either ball’s version moves on, and empties on clear', () => {
    const C = createCollisionState(8, 11)
    heapPush(C, 1, HeapKind.Contact, 2, 3)
    expect(heapTopLive(C)).toBe(true)
    C.ver[3]!++
    expect(heapTopLive(C)).toBe(false)
    heapPush(C, 0.5, HeapKind.Own, 4, 0)
    expect(heapTopA(C)).toBe(4)
    expect(heapTopLive(C)).toBe(true)
    C.ver[4]!++
    expect(heapTopLive(C)).toBe(false)
    heapClear(C)
    expect(C.heapCount).toBe(0)
    heapPush(C, 2, HeapKind.Own, 5, 0)
    expect([heapTopT(C), heapTopA(C), C.eCount]).toEqual([2, 5, 1])
  })
})
