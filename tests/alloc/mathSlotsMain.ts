// Bundled and run in a Node process of its own by tests/mathSlots.test.ts (the test runner's transform of
// a test file boxes doubles in its loops, whatever the functions they call): the heap's growth per call of
// the allocation-free sin/cos, exp and expm1, and of @stdlib's, after a collection, each once optimised.
// Prints one line of JSON: { ours, theirs } in bytes per call.
import { ARG, COS, RESULT, SIN, expSlot, expm1Slot, mathSlot, sinCosSlot } from '../../src/math.js'

declare const gc: () => void

// the sums in an array: a double local summed over a loop may be boxed before the loop is optimised
const acc = new Float64Array(1)

function ours(n: number): void {
  for (let i = 0; i < n; i++) {
    mathSlot[ARG] = (i % 1000) * 0.0123 - 6
    sinCosSlot()
    acc[0] += mathSlot[SIN]! + mathSlot[COS]!
    mathSlot[ARG] = (i % 997) * -0.002
    expSlot()
    acc[0] += mathSlot[RESULT]!
    mathSlot[ARG] = (i % 997) * -0.002
    expm1Slot()
    acc[0] += mathSlot[RESULT]!
  }
}

/** the control: every double stored into an array of objects is a heap number of its own */
const tagged: unknown[] = [{}]
function control(n: number): void {
  for (let i = 0; i < n; i++) {
    for (let k = 0; k < 3; k++) tagged[1 + (i % 1000)] = (i % 1000) * 0.0123 - k
  }
}

/**
 * Bytes the heap grows by per call (three calls an iteration), over 300,000 calls after a collection: at
 * most 4.8 MB, which the young generation the test gives the process (32 MB) holds without collecting.
 */
function perCall(run: (n: number) => void): number {
  for (let k = 0; k < 20; k++) run(10_000)
  gc()
  const before = process.memoryUsage().heapUsed
  run(100_000)
  return (process.memoryUsage().heapUsed - before) / 3e5
}

const result = { ours: perCall(ours), control: perCall(control), sum: acc[0] }
console.log(JSON.stringify(result))
