// Two builds of this module side by side in one process: the working tree against a commit (default HEAD),
// on a scene of the contacts benchmark (bench/contactScenes.ts). On this shared machine the same code's
// steps swing 1.5–2× between processes and between minutes, so a change's effect on speed is measured here
// as ratios within rounds: each round runs both builds REPEATS times in turn (their order alternating from
// round to round), each time with contacts off and on, a fresh scene of MEASURED_STEPS steps each (after a
// throwaway scene of WARM_STEPS steps per build and setting), and takes working ÷ base of the round's
// summed times: of the runs with contacts, and of their extra time over the runs with contacts off (the
// denominator: the base build's extra time in the same round). Prints the median and
// quartiles of the per-round ratios, and whether the two builds end every scene with the same bits (a hash
// of every ball's state and the event count). Writes nothing. With --work-config, a JSON object of config
// fields the working tree's build takes on top of the scene's (the base's is left as it is): with --base
// HEAD, two settings of the same code side by side.
//
//   npm run bench:ab -- [--base COMMIT] [--scene panel|gas] [--balls 1000] [--mode fixed|on] [--rounds 15] [--repeats 5]
//                       [--work-config '{"CONTACT_TIMING":"tick"}']
import { execFileSync } from 'node:child_process'
import { mkdirSync, rmSync } from 'node:fs'
import { join, resolve } from 'node:path'
import { pathToFileURL } from 'node:url'
import { build } from 'esbuild'
import type { BallPhysics, createBallPhysics } from '../src/index'
import { checksum } from '../src/commands/snapshotCodec'
import { DT, argValue, collectGarbage, median } from './lib'
import { gas, oursScene, panel, type Scene } from './contactScenes'

const MEASURED_STEPS = 120
const WARM_STEPS = 240

type Create = typeof createBallPhysics

/** The module's entry bundled from `root` (a checkout or an extracted commit) into `out`. */
async function bundle(root: string, out: string): Promise<Create> {
  await build({
    entryPoints: [join(root, 'src/index.ts')],
    outfile: out,
    bundle: true,
    format: 'esm',
    platform: 'node',
    target: 'node20',
    packages: 'external',
    logLevel: 'warning',
  })
  const mod = (await import(pathToFileURL(out).href)) as { createBallPhysics: Create }
  return mod.createBallPhysics
}

/** The sources of `commit` (src, components, systems) extracted under `dir`. */
function extract(commit: string, dir: string): void {
  rmSync(dir, { recursive: true, force: true })
  mkdirSync(dir, { recursive: true })
  const tar = execFileSync('git', ['archive', '--format=tar', commit, 'src', 'components', 'systems'], { maxBuffer: 1 << 28 })
  execFileSync('tar', ['-x', '-C', dir], { input: tar })
}

/** Every ball's state and the events, hashed (the snapshot codec's checksum over the doubles' bytes). */
function stateHash(sim: BallPhysics, events: number): string {
  const values: number[] = []
  for (const b of sim.balls()) {
    const st = sim.ballState(b)
    values.push(st.x, st.y, st.vx, st.vy)
    for (let i = 0; i < st.mode.length; i++) values.push(st.mode.charCodeAt(i))
  }
  values.push(events)
  const bytes = new Uint8Array(new Float64Array(values).buffer)
  return checksum(bytes, bytes.length).toString(16)
}

/** One run of MEASURED_STEPS steps of a fresh scene: ms for the whole run, and the final state's hash. */
function run(create: Create, sc: Scene, mode: 'off' | 'on' | 'fixed', steps: number): { ms: number; hash: string } {
  const sim = oursScene(sc, mode, DT, create)
  let events = 0
  collectGarbage()
  const t0 = performance.now()
  for (let i = 0; i < steps; i++) {
    sim.step(DT)
    events += sim.world.events.count
    sim.world.events.count = 0
  }
  const ms = performance.now() - t0
  return { ms, hash: stateHash(sim, events) }
}

function quartiles(a: readonly number[]): string {
  const s = [...a].sort((x, y) => x - y)
  const q = (f: number): number => s[Math.min(s.length - 1, Math.floor(f * (s.length - 1) + 0.5))]!
  return `${median(a).toFixed(3)} (quartiles ${q(0.25).toFixed(3)}–${q(0.75).toFixed(3)})`
}

const base = argValue('--base') ?? 'HEAD'
const sceneName = argValue('--scene') ?? 'panel'
const balls = Number(argValue('--balls') ?? 1000)
const mode = (argValue('--mode') ?? 'fixed') as 'fixed' | 'on'
const rounds = Number(argValue('--rounds') ?? 15)
const repeats = Number(argValue('--repeats') ?? 5)
const workConfigText = argValue('--work-config')
let workConfig: Record<string, unknown> = {}
if (workConfigText !== undefined) {
  try {
    workConfig = JSON.parse(workConfigText) as Record<string, unknown>
  } catch {
    throw new Error(`--work-config must be a JSON object of config fields, got ${workConfigText}`)
  }
  if (workConfig === null || typeof workConfig !== 'object' || Array.isArray(workConfig)) throw new Error(`--work-config must be a JSON object of config fields, got ${workConfigText}`)
}
if (sceneName !== 'panel' && sceneName !== 'gas') throw new Error(`--scene must be panel or gas, got ${sceneName}`)
if (mode !== 'fixed' && mode !== 'on') throw new Error(`--mode must be fixed or on, got ${mode}`)
if (!(Number.isInteger(balls) && balls >= 2)) throw new Error(`--balls must be a whole number of at least 2, got ${balls}`)
if (!(Number.isInteger(rounds) && rounds >= 1)) throw new Error(`--rounds must be a whole number of at least 1, got ${rounds}`)
if (!(Number.isInteger(repeats) && repeats >= 1)) throw new Error(`--repeats must be a whole number of at least 1, got ${repeats}`)

let commit: string
try {
  commit = execFileSync('git', ['rev-parse', '--verify', '--quiet', `${base}^{commit}`], { encoding: 'utf8' }).trim()
} catch {
  throw new Error(`--base must name a commit of this repository, got ${base}`)
}
const cache = resolve('node_modules/.cache/ab')
const baseDir = join(cache, commit)
extract(commit, baseDir)
const builds: Record<'base' | 'work', Create> = {
  base: await bundle(baseDir, join(cache, `base-${process.pid}.mjs`)),
  work: await bundle(resolve('.'), join(cache, `work-${process.pid}.mjs`)),
}
if (workConfigText !== undefined) {
  const work = builds.work
  builds.work = ((config, options) => work({ ...config, ...workConfig }, options)) as Create
}
// loaded: the bundles and the extracted sources are not needed any more
for (const f of [`base-${process.pid}.mjs`, `work-${process.pid}.mjs`]) rmSync(join(cache, f), { force: true })
rmSync(baseDir, { recursive: true, force: true })
const sc = sceneName === 'panel' ? panel(balls) : gas(balls)
console.log(`bench:ab: working tree${workConfigText === undefined ? '' : ` with ${workConfigText}`} against ${commit.slice(0, 12)} (${base}), ${sceneName} ${balls} balls, contacts '${mode}', ${rounds} rounds of ${repeats}`)

// warm each build and setting on a throwaway scene first
for (const k of ['base', 'work'] as const) for (const m of ['off', mode] as const) run(builds[k], sc, m, WARM_STEPS)

const stepRatio: number[] = []
const extraRatio: number[] = []
const offRatio: number[] = []
const hashes = { base: new Set<string>(), work: new Set<string>() }
for (let r = 0; r < rounds; r++) {
  const order = r % 2 === 0 ? (['base', 'work'] as const) : (['work', 'base'] as const)
  const ms = { base: { off: 0, on: 0 }, work: { off: 0, on: 0 } }
  for (let rep = 0; rep < repeats; rep++) {
    for (const k of order) {
      const off = run(builds[k], sc, 'off', MEASURED_STEPS)
      const on = run(builds[k], sc, mode, MEASURED_STEPS)
      ms[k].off += off.ms
      ms[k].on += on.ms
      hashes[k].add(on.hash)
    }
  }
  stepRatio.push(ms.work.on / ms.base.on)
  offRatio.push(ms.work.off / ms.base.off)
  extraRatio.push((ms.work.on - ms.work.off) / (ms.base.on - ms.base.off))
}
const same = hashes.base.size === 1 && hashes.work.size === 1 && [...hashes.base][0] === [...hashes.work][0]
console.log(`  whole run with contacts, working ÷ base:        ${quartiles(stepRatio)}`)
console.log(`  extra time of contacts, working ÷ base:         ${quartiles(extraRatio)}`)
console.log(`  run with contacts off, working ÷ base (noise):  ${quartiles(offRatio)}`)
console.log(`  final states: ${same ? 'the same bits' : `differ (base ${[...hashes.base].join(',')}, working ${[...hashes.work].join(',')})`}`)
