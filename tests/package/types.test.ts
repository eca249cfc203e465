// The published package, as a consumer gets it: `npm pack` from a tree without `dist/` (as a fresh clone
// is: the `prepack` script builds it; without one the tarball held no code), the tarball unpacked into a
// fixture project's node_modules (bitecs, the one runtime dependency, symlinked from the repo), then
//  - a consumer importing from all three entry points (`.`, `./ecs`, `./reference`) typechecks with the
//    repo's tsc under NodeNext, Node16 and Bundler resolution, strict and with skipLibCheck off (so the
//    shipped .d.ts files themselves are checked); `@ts-expect-error` lines fail (TS2578) if the types
//    degrade to `any`; every file tsc loads is the package's own, bitecs's or tsc's lib (nothing from the
//    repo's node_modules: a declaration needing a devDependency's types fails);
//  - every declaration file the package's declarations import is in the tarball;
//  - at runtime, the three entries share one copy of the library (a world from `.` runs under `./ecs`);
//  - @arethetypeswrong/cli finds no problem in the tarball (see the one allowed kind below).
import { execFile } from 'node:child_process'
import { mkdir, mkdtemp, readFile, realpath, rm, symlink, writeFile } from 'node:fs/promises'
import { join, posix, resolve, sep } from 'node:path'
import { promisify } from 'node:util'
import { afterAll, beforeAll, describe, expect, it } from 'vitest'

const run = promisify(execFile)
const root = resolve(import.meta.dirname, '../..')
const PKG = 'positron-ball-physics'
const isWin = process.platform === 'win32'
const bin = (name: string) => join(root, 'node_modules', '.bin', isWin ? `${name}.cmd` : name)

interface Result {
  code: number
  stdout: string
  stderr: string
}

/** Runs a command; never throws on a non-zero exit (the caller asserts on the code and the output). */
async function sh(cmd: string, args: string[], cwd: string): Promise<Result> {
  try {
    const { stdout, stderr } = await run(cmd, args, { cwd, maxBuffer: 64 << 20, shell: isWin, env: { ...process.env, NO_COLOR: '1' } })
    return { code: 0, stdout, stderr }
  } catch (e) {
    const err = e as { code?: number | string; stdout?: string; stderr?: string; message: string }
    return { code: typeof err.code === 'number' ? err.code : 1, stdout: err.stdout ?? '', stderr: err.stderr ?? err.message }
  }
}

const CONSUMER = `
import { createBallPhysics, DEFAULT_CONFIG, addPanel, DEFAULT_PANEL, solveThrow, createReplayPlayer, replayFromJSON, replayToJSON, sampleThrows, type BallEvent, type BallPhysics, type EventView, type Replay, type ThrowSolution, type ThrowFailure } from '${PKG}'
import { createBallWorld, runSchedule, DEFAULT_SCHEDULE, BallMode, type BallWorld } from '${PKG}/ecs'
import { referenceOutcome, type ReferenceOutcome } from '${PKG}/reference'

const sim: BallPhysics = createBallPhysics({ ROLLING_DECEL: DEFAULT_CONFIG.ROLLING_DECEL * 2 })
const holes: number[] = addPanel(sim, DEFAULT_PANEL)
// a world made through the main entry is the one ./ecs works on
const world: BallWorld = sim.world
runSchedule(world, DEFAULT_SCHEDULE, 1 / 60)
const own: BallWorld = createBallWorld({}, { capacity: 64 })
runSchedule(own, DEFAULT_SCHEDULE, 1 / 60)
const events: BallEvent[] = sim.drainEvents()
const kinds: string[] = events.map((e) => e.type)
let latest = 0
const drained: number = sim.drainEventsWith((e: EventView) => {
  latest = e.time
})
const rolling: 0 = BallMode.Rolling
const outcome: ReferenceOutcome = referenceOutcome({ delta: 5, speed: 300, holeRadius: 18, ballRadius: 11, gravity: 6953, inertia: 0.4 })
const captured: boolean = outcome.captured
const shot: ThrowSolution | ThrowFailure = solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[0]!, outcome: 'skip' })
const power: number | null = shot.power
const bytes: Uint8Array = sim.snapshot()
sim.startRecording()
const replay: Replay = sim.stopRecording()
const player = createReplayPlayer(replayFromJSON(replayToJSON(replay)))
const more: boolean = player.next()
const tally = sampleThrows({ holes: DEFAULT_PANEL.holes }, { power: { mean: 0.5 }, angle: { mean: 0 }, from: DEFAULT_PANEL.launch }, 10, 1)
export const used: unknown[] = [holes, kinds, rolling, captured, drained, latest, power, bytes, more, tally.throws]
// a check of an event's type narrows its fields
for (const e of events) {
  if (e.type === 'capture') {
    const h: number = e.hole
    const via: 'clean' | 'rimRoll' | 'rest' = e.via
    used.push(h, via)
  } else if (e.type === 'collision') {
    const pair: [number, number, number, number] = [e.ball, e.other, e.speed, e.impulse]
    used.push(pair)
  } else if (e.type === 'skip' || e.type === 'nearMiss') {
    const h: number = e.hole
    const d: number | undefined = e.delta
    used.push(h, d)
  }
  // fields a kind never has read as undefined on any event
  const other: number | undefined = e.other
  used.push(other)
}

// Each line below is an error only while the types are real: were any of them \`any\`, the directive would
// be unused (TS2578) and the check would fail.
// @ts-expect-error ROLLING_DECEL is a number
createBallPhysics({ ROLLING_DECEL: 'fast' })
// @ts-expect-error dt is a number
runSchedule(world, DEFAULT_SCHEDULE, '1/60')
// @ts-expect-error the reference needs all of its input
referenceOutcome({ delta: 5 })
// @ts-expect-error an event's type is one of the event names
export const never: BallEvent['type'] = 'explosion'
// @ts-expect-error BallMode is a readonly object of codes
BallMode.Rolling = 1
// @ts-expect-error the outcome is not a number
export const notNumber: number = outcome
// @ts-expect-error an outcome is one of capture, skip, lipOut, bounce
solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: 1, outcome: 'drop' })
// @ts-expect-error a snapshot is restored from bytes
sim.restore('snapshot')
// @ts-expect-error a wall event has no hole
export const noHole = (e: BallEvent): number => (e.type === 'wall' ? e.hole : 0)
// @ts-expect-error a skip has no via
export const noVia = (e: BallEvent): string => (e.type === 'skip' ? e.via : '')
// @ts-expect-error an event view's hole is a number (0: none), not optional
sim.drainEventsWith((e) => { const h: undefined = e.hole })
`

/**
 * A consumer under exactOptionalPropertyTypes that passes optional values through (each may be undefined,
 * which the library takes as absent): every optional field of the public input types must accept undefined.
 */
const OPTIONAL = `
import { createBallPhysics, createFixedStepClock, outcomeMap, prepareRimTable, sampleThrows, solveThrow, DEFAULT_PANEL, type BallSpec, type ConfigOverrides, type HoleSpec, type ThrowSpec, type WallsSpec } from '${PKG}'
import { createBallWorld } from '${PKG}/ecs'

export function pass(o: { decel?: number; capacity?: number; radius?: number; hero?: boolean; mass?: number; value?: number; e?: number; bottom?: boolean; hz?: number; along?: number; sd?: number; window?: 'ellipse' | 'quadratic'; queue?: 'back' | 'front' }): void {
  const overrides: ConfigOverrides = { ROLLING_DECEL: o.decel, CAPTURE_WINDOW: o.window }
  const sim = createBallPhysics({ ROLLING_DECEL: o.decel }, { capacity: o.capacity, broadphase: undefined })
  createBallWorld(overrides, { capacity: o.capacity })
  const ball: BallSpec = { x: 0, y: 0, vx: 0, vy: 0, radius: o.radius, hero: o.hero, mass: o.mass, queue: o.queue }
  sim.addBall(ball)
  const thrown: ThrowSpec = { x: 0, y: 0, power: 0.5, angle: 0, radius: o.radius, hero: o.hero, mass: o.mass, queue: o.queue }
  sim.throwBall(thrown)
  const hole: HoleSpec = { x: 100, y: 100, radius: o.radius, value: o.value }
  const id = sim.addHole(hole)
  const walls: WallsSpec = { minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: o.e, open: { bottom: o.bottom, left: undefined } }
  sim.setWalls(walls)
  sim.setWalls({ ...walls, open: undefined })
  createFixedStepClock({ hz: o.hz, maxStepsPerFrame: undefined })
  solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: id, along: o.along, outcome: undefined, queue: o.queue })
  prepareRimTable(sim, 18, 11, { inertia: undefined, rows: undefined })
  const scene = { config: o.decel === undefined ? undefined : overrides, holes: DEFAULT_PANEL.holes, walls: undefined }
  sampleThrows(scene, { power: { mean: 0.5, sd: o.sd }, angle: { mean: 0, sd: o.sd }, from: { x: 210, y: 450, sdX: o.sd, sdY: o.sd } }, 1, 1)
  outcomeMap(scene, { from: DEFAULT_PANEL.launch, power: { min: 0, max: 1, steps: 1 }, angle: { min: 0, max: 0, steps: 1 } })
}
`

const RESOLUTIONS = [
  { name: 'nodenext', module: 'NodeNext', moduleResolution: 'NodeNext' },
  { name: 'node16', module: 'Node16', moduleResolution: 'Node16' },
  { name: 'bundler', module: 'ESNext', moduleResolution: 'Bundler' },
] as const

const RUNTIME = `
import * as main from '${PKG}'
import * as ecs from '${PKG}/ecs'
import * as reference from '${PKG}/reference'

// a world made through the main entry, grown by the ecs entry's commands: with two copies of the library
// the stores (registered in a module-level WeakMap) would be foreign to the second and growing them would throw
const sim = main.createBallPhysics({}, { capacity: 8 })
main.addPanel(sim, main.DEFAULT_PANEL)
sim.throwBall({ x: 200, y: 600, power: 0.5, angle: 0 })
for (let i = 0; i < 40; i++) ecs.addBall(sim.world, { x: 1000 + 30 * i, y: 1000, vx: 0, vy: -10 })
ecs.runSchedule(sim.world, ecs.DEFAULT_SCHEDULE, 1 / 60)
const own = ecs.createBallWorld()
ecs.runSchedule(own, ecs.DEFAULT_SCHEDULE, 1 / 60)
const out = reference.referenceOutcome({ delta: 5, speed: 300, holeRadius: 18, ballRadius: 11, gravity: 6953, inertia: 0.4 })
console.log(JSON.stringify({
  time: sim.time,
  ownTime: own.time,
  balls: sim.balls().length,
  sameModeNames: main.BALL_MODE_NAMES === ecs.BALL_MODE_NAMES,
  mainHasNoEcsInternals: !('createBallWorld' in main) && !('runSchedule' in main),
  captured: typeof out.captured,
  // the portable functions are bundled in: a snapshot restores in a copy, and the solver runs
  restored: (() => { const c = main.createBallPhysics(sim.config, { capacity: 8 }); c.restore(sim.snapshot()); return c.balls().length })(),
  solved: main.solveThrow(sim, { from: main.DEFAULT_PANEL.launch, hole: sim.holes()[0], outcome: 'skip' }).found,
}))
`

/** Module specifiers of a declaration file (imports, exports, `import('…')` types, `/// <reference types>`), relative and bare. */
function specifiers(text: string): { relative: string[]; bare: string[] } {
  const all = [...text.matchAll(/(?:from\s+|import\s*\(\s*|import\s+)['"]([^'"]+)['"]/g)].map((m) => m[1]!)
  const refTypes = [...text.matchAll(/\/\/\/\s*<reference\s+types\s*=\s*['"]([^'"]+)['"]/g)].map((m) => m[1]!)
  return { relative: all.filter((s) => s.startsWith('.')), bare: [...all.filter((s) => !s.startsWith('.')), ...refTypes] }
}

describe('published package', () => {
  let work: string
  let fixture: string
  let tarball: string
  let packed: string[]
  let pkgJson: { dependencies?: Record<string, string> }

  beforeAll(async () => {
    // no build of a run before: what `npm pack` packs, it builds
    await rm(join(root, 'dist'), { recursive: true, force: true })
    await mkdir(join(root, 'test-artifacts'), { recursive: true })
    work = await mkdtemp(join(root, 'test-artifacts', 'package-types-'))
    const pack = await sh('npm', ['pack', '--pack-destination', work, '--json'], root)
    if (pack.code !== 0) throw new Error(`npm pack failed:\n${pack.stderr}`)
    const info = JSON.parse(pack.stdout) as { filename: string; files: { path: string }[] }[]
    tarball = join(work, info[0]!.filename)
    packed = info[0]!.files.map((f) => f.path)

    fixture = join(work, 'fixture')
    const installed = join(fixture, 'node_modules', PKG)
    await mkdir(installed, { recursive: true })
    const untar = await sh('tar', ['-xzf', tarball, '-C', installed, '--strip-components=1'], work)
    if (untar.code !== 0) throw new Error(`tar failed:\n${untar.stderr}`)
    await symlink(join(root, 'node_modules', 'bitecs'), join(fixture, 'node_modules', 'bitecs'), 'junction')
    pkgJson = JSON.parse(await readFile(join(installed, 'package.json'), 'utf8'))
    await writeFile(join(fixture, 'package.json'), JSON.stringify({ name: 'fixture', private: true, type: 'module' }, null, 2))
    await writeFile(join(fixture, 'consumer.ts'), CONSUMER)
    await writeFile(join(fixture, 'runtime.mjs'), RUNTIME)
    await writeFile(join(fixture, 'optional.ts'), OPTIONAL)
    const exact = { module: 'ESNext', moduleResolution: 'Bundler', target: 'ES2022', lib: ['ES2022'], strict: true, exactOptionalPropertyTypes: true, skipLibCheck: false, noEmit: true, types: [] }
    await writeFile(join(fixture, 'tsconfig.optional.json'), JSON.stringify({ compilerOptions: exact, files: ['optional.ts'] }, null, 2))
    for (const r of RESOLUTIONS) {
      const compilerOptions = {
        module: r.module,
        moduleResolution: r.moduleResolution,
        target: 'ES2022',
        lib: ['ES2022'],
        strict: true,
        skipLibCheck: false,
        noEmit: true,
        types: [],
      }
      await writeFile(join(fixture, `tsconfig.${r.name}.json`), JSON.stringify({ compilerOptions, files: ['consumer.ts'] }, null, 2))
    }
  }, 120_000)

  afterAll(async () => {
    // KEEP_PACKAGE_FIXTURE=1 keeps test-artifacts/package-types-*/ (tarball and fixture) to look into
    if (work && !process.env.KEEP_PACKAGE_FIXTURE) await rm(work, { recursive: true, force: true })
  })

  it('packs the three bundles, their shared chunks and the declarations of the three entries', () => {
    for (const f of ['package.json', 'README.md', 'LICENSE', 'dist/index.js', 'dist/ecs.js', 'dist/reference.js']) expect(packed).toContain(f)
    expect(packed.some((f) => f.startsWith('dist/chunks/') && f.endsWith('.js'))).toBe(true)
    const dts = new Set(packed.filter((f) => f.endsWith('.d.ts')))
    for (const f of ['dist/types/src/index.d.ts', 'dist/types/src/ecs.d.ts', 'dist/types/src/reference/index.d.ts']) expect(dts).toContain(f)
  })

  it('declarations import only files in the tarball and runtime dependencies', async () => {
    const deps = new Set(Object.keys(pkgJson.dependencies ?? {}))
    const missing: string[] = []
    const foreign: string[] = []
    const installed = join(fixture, 'node_modules', PKG)
    for (const f of packed.filter((p) => p.endsWith('.d.ts'))) {
      const { relative: rel, bare } = specifiers(await readFile(join(installed, f), 'utf8'))
      for (const s of rel) {
        const target = posix.join(posix.dirname(f), s).replace(/\.js$/, '.d.ts')
        if (!packed.includes(target)) missing.push(`${f}: ${s}`)
      }
      for (const s of bare) {
        const name = s.startsWith('@') ? s.split('/').slice(0, 2).join('/') : s.split('/')[0]!
        if (!deps.has(name)) foreign.push(`${f}: ${s}`)
      }
    }
    expect(missing).toEqual([])
    expect(foreign).toEqual([])
  })

  it.each(RESOLUTIONS)('typechecks a consumer of all three entries under $module/$moduleResolution', async (r) => {
    const res = await sh(bin('tsc'), ['-p', `tsconfig.${r.name}.json`, '--pretty', 'false', '--listFiles'], fixture)
    const lines = res.stdout.split(/\r?\n/).filter((l) => l.trim() !== '')
    const diagnostics = lines.filter((l) => /error TS\d+|warning TS\d+/.test(l))
    expect(diagnostics).toEqual([])
    expect(res.stderr.trim()).toBe('')
    expect(res.code).toBe(0)
    // the files tsc loaded: the consumer, the package's declarations, bitecs's, and tsc's own lib files.
    // A declaration that reached for a devDependency's types (pixi.js, @types/node, …) would still pass the
    // check above, found by walking up into the repo's node_modules; this is what catches it.
    const files = lines.map((l) => resolve(fixture, l.trim()))
    const consumer = await realpath(join(fixture, 'consumer.ts'))
    const installed = await realpath(join(fixture, 'node_modules', PKG))
    const bitecs = await realpath(join(root, 'node_modules', 'bitecs'))
    const inside = (dir: string, f: string) => f.startsWith(dir + sep)
    const tscLib = (f: string) => /[\\/]node_modules[\\/](typescript|@typescript[\\/][^\\/]+)[\\/]lib[\\/]lib\.[\w.]+\.d\.ts$/.test(f)
    const stray = files.filter((f) => f !== consumer && !inside(installed, f) && !inside(bitecs, f) && !tscLib(f))
    expect(stray).toEqual([])
    for (const entry of ['src/index.d.ts', 'src/ecs.d.ts', 'src/reference/index.d.ts']) {
      expect(files).toContain(join(installed, 'dist', 'types', ...entry.split('/')))
    }
    expect(files.some((f) => inside(bitecs, f))).toBe(true)
  })

  it('under exactOptionalPropertyTypes, every optional input field accepts a value that may be undefined', async () => {
    const res = await sh(bin('tsc'), ['-p', 'tsconfig.optional.json', '--pretty', 'false'], fixture)
    expect(res.stdout.split(/\r?\n/).filter((l) => /error TS\d+/.test(l))).toEqual([])
    expect(res.code).toBe(0)
  })

  it('runs: the three entries share one copy of the library', async () => {
    const res = await sh(process.execPath, ['runtime.mjs'], fixture)
    expect(res.stderr).toBe('')
    expect(res.code).toBe(0)
    const out = JSON.parse(res.stdout.trim())
    expect(out.time).toBeGreaterThan(0)
    expect(out.ownTime).toBeGreaterThan(0)
    expect(out.balls).toBe(41)
    expect(out).toMatchObject({ sameModeNames: true, mainHasNoEcsInternals: true, captured: 'boolean', restored: 41, solved: true })
  })

  it('a CommonJS consumer: a .cts file typechecks under NodeNext and, where Node can require an ES module, runs', async () => {
    // tsc lets a .cts file import the ES module (Node 20.19+ and 22.12+ load it with require); the exports
    // carried only \`import\` conditions, so require() failed with ERR_PACKAGE_PATH_NOT_EXPORTED on every Node
    // while the same code passed the type check. The \`default\` condition now points require() at it too.
    const dir = join(fixture, 'cjs')
    await mkdir(dir, { recursive: true })
    await writeFile(join(dir, 'package.json'), JSON.stringify({ name: 'cjs-fixture', private: true, type: 'commonjs' }, null, 2))
    await writeFile(
      join(dir, 'consumer.cts'),
      [
        "import { createBallPhysics } from 'positron-ball-physics'",
        "import { createBallWorld } from 'positron-ball-physics/ecs'",
        "import { referenceOutcome } from 'positron-ball-physics/reference'",
        'declare const console: { log(message: string): void } // no @types/node in the fixture',
        'const sim = createBallPhysics()',
        'sim.addHole({ x: 0, y: 0 })',
        'sim.addBall({ x: -50, y: 0, vx: 200, vy: 0 })',
        'sim.step(1)',
        "console.log(JSON.stringify({ events: sim.drainEvents().map((e) => e.type), ecs: typeof createBallWorld, reference: typeof referenceOutcome }))",
        '',
      ].join('\n'),
    )
    const compilerOptions = { module: 'NodeNext', moduleResolution: 'NodeNext', target: 'ES2022', lib: ['ES2022'], strict: true, skipLibCheck: false, outDir: 'out', types: [] }
    await writeFile(join(dir, 'tsconfig.json'), JSON.stringify({ compilerOptions, files: ['consumer.cts'] }, null, 2))
    const tsc = await sh(bin('tsc'), ['-p', 'tsconfig.json', '--pretty', 'false'], dir)
    expect(tsc.stdout.split(/\r?\n/).filter((l) => /error TS\d+/.test(l))).toEqual([])
    expect(tsc.code).toBe(0)
    if (!(process.features as { require_module?: boolean }).require_module) return
    const res = await sh(process.execPath, [join('out', 'consumer.cjs')], dir)
    expect(res.stderr).toBe('')
    expect(JSON.parse(res.stdout.trim())).toEqual({ events: ['capture'], ecs: 'function', reference: 'function' })
  })

  it('@arethetypeswrong/cli finds no problem in the tarball', async () => {
    // Default (strict) profile: node10, node16 from ESM, node16 from CJS and bundler resolution, for every
    // subpath in `exports`. The package is ESM-only (`import` conditions, no `require`), so a CommonJS
    // consumer under node16 resolves to ESM: attw reports that as CJSResolvesToESM, which is what ESM-only
    // means, not a fault of the types. Exactly that kind, for node16-cjs only, is allowed; anything else fails.
    const res = await sh(bin('attw'), [tarball, '--format', 'json'], work)
    const report = JSON.parse(res.stdout) as { analysis: { problems: { kind: string; entrypoint?: string; resolutionKind?: string }[] } }
    const problems = report.analysis.problems
    const allowed = (p: (typeof problems)[number]) => p.kind === 'CJSResolvesToESM' && p.resolutionKind === 'node16-cjs'
    expect(problems.filter((p) => !allowed(p))).toEqual([])
    // the same verdict from attw itself: with the esm-only profile (which ignores node16-cjs, and node10,
    // checked above) it exits 0; its JSON still lists the ignored problems, so only the exit code tells
    const esm = await sh(bin('attw'), [tarball, '--format', 'json', '--profile', 'esm-only'], work)
    expect(esm.code).toBe(0)
  })
})
