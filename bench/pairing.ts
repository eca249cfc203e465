// Whether pairs kept from tick to tick can pair a tick's moving balls for less than the bare grid that the
// contacts benchmark divides by (bench/barePairing.ts): the two neighbour lists of bench/skinPairing.ts, at
// skins of 2, 4 and 8 ticks, timed over the same recorded frames as the grid (the moving balls after each of
// 120 steps of a fixed-tick run of the contacts benchmark's scenes, at CONTACT_TICK = dt = 1/120 s), in
// turn in one process, ROUNDS rounds, the median kept. Every list is checked to count the grid's pairs at
// every frame before it is timed. Printed as µs a step, µs per contact of the run (the step's time over the
// run's contacts a step, the measure of the floor) and the ratio to the grid (the denominator: the
// grid, same frames, same process, measured in the same rounds). Writes docs/results/pairing.json.
//
//   npm run bench:pairing                      (panel and gas, 1,000 and 10,000 balls)
//   npm run bench:pairing -- --sizes 1000
import { pairFrame, recordFrames, type Frame } from './barePairing'
import { gas, oursScene, panel } from './contactScenes'
import { skinPerBall, skinRebuild, type SkinList } from './skinPairing'
import { DT, argValue, collectGarbage, median, writeResult } from './lib'

const TICK = 1 / 120
const STEPS = 120
const ROUNDS = 9
const SKINS = [2, 4, 8]

/** µs a step of one pass of `pass` over the frames (the pass returns the pairs it counted). */
function timePass(frames: readonly Frame[], pass: () => number, pairs: number, what: string): number {
  const t = process.hrtime.bigint()
  const got = pass()
  const us = Number(process.hrtime.bigint() - t) / 1000 / frames.length
  if (got !== pairs) throw new Error(`${what}: ${got} pairs in a pass, the grid ${pairs}`)
  return us
}

function listPass(frames: readonly Frame[], make: () => SkinList): () => number {
  return () => {
    const L = make()
    let n = 0
    for (const f of frames) n += L.frame(f)
    return n
  }
}

const sizes = (argValue('--sizes') ?? '1000,10000').split(',').map(Number)
const rows = []
for (const [scene, make] of [['panel', panel], ['gas', gas]] as const) {
  for (const n of sizes) {
    const sim = oursScene(make(n), 'fixed', TICK)
    const frames = recordFrames(sim, STEPS, DT)
    const contactsPerStep = (sim.world.fixed?.contacts ?? 0) / STEPS
    let moving = 0
    for (const f of frames) moving += f.n
    // the grid's pairs frame by frame, which every list must count too
    const each = frames.map((f) => pairFrame(f, TICK))
    const pairs = each.reduce((a, b) => a + b, 0)
    for (const K of SKINS) {
      for (const [name, mk] of [['rebuild', () => skinRebuild(K, TICK)], ['per ball', () => skinPerBall(K, TICK)]] as const) {
        const L = mk()
        frames.forEach((f, k) => {
          if (L.frame(f) !== each[k]) throw new Error(`${scene} ${n}, ${name} K ${K}: frame ${k} counts other pairs than the grid`)
        })
      }
    }
    const passes: [string, () => number][] = [['grid', () => frames.reduce((a, f) => a + pairFrame(f, TICK), 0)]]
    for (const K of SKINS) {
      passes.push([`rebuild K${K}`, listPass(frames, () => skinRebuild(K, TICK))])
      passes.push([`per ball K${K}`, listPass(frames, () => skinPerBall(K, TICK))])
    }
    const times = new Map<string, number[]>(passes.map(([k]) => [k, []]))
    for (const [k, pass] of passes) timePass(frames, pass, pairs, k) // warm every pass once
    for (let r = 0; r < ROUNDS; r++) {
      collectGarbage()
      for (const [k, pass] of passes) times.get(k)!.push(timePass(frames, pass, pairs, k))
    }
    const grid = median(times.get('grid')!)
    const row = {
      scene,
      balls: n,
      movingPerStep: moving / STEPS,
      contactsPerStep,
      pairsPerStep: pairs / STEPS,
      usPerStep: Object.fromEntries(passes.map(([k]) => [k, median(times.get(k)!)])),
      usPerContact: Object.fromEntries(passes.map(([k]) => [k, median(times.get(k)!) / contactsPerStep])),
      overGrid: Object.fromEntries(passes.map(([k]) => [k, median(times.get(k)!) / grid])),
    }
    rows.push(row)
    console.log(`\n${scene}, ${n} balls: ${row.movingPerStep.toFixed(0)} moving, ${contactsPerStep.toFixed(2)} contacts and ${row.pairsPerStep.toFixed(1)} pairs within reach a step`)
    console.log('  pairing            µs a step   µs per contact   ÷ grid')
    for (const [k] of passes) {
      console.log(`  ${k.padEnd(17)} ${row.usPerStep[k]!.toFixed(1).padStart(10)} ${row.usPerContact[k]!.toFixed(2).padStart(16)} ${row.overGrid[k]!.toFixed(2).padStart(8)}`)
    }
  }
}
const file = writeResult('pairing', {
  tick: TICK,
  steps: STEPS,
  rounds: ROUNDS,
  skins: SKINS,
  method: 'bench/skinPairing.ts: neighbour lists with a skin of K ticks of each ball\'s speed (rebuild: the whole list again when any ball spends its skin; per ball: that ball alone, through a hashed grid kept from tick to tick), against the bare grid of bench/barePairing.ts, over the moving balls after each step of a fixed-tick run; each checked to count the grid\'s pairs at every frame; median of the rounds, all in one process, in turn',
  rows,
})
console.log(`\nwrote ${file}`)
