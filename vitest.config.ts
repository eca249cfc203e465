import { existsSync, mkdirSync, readdirSync, rmSync, writeFileSync } from 'node:fs'
import { dirname, join, relative, resolve, sep } from 'node:path'
import { buildSync } from 'esbuild'
import { configDefaults, defineConfig, type Plugin } from 'vitest/config'

const root = import.meta.dirname
/** the library's source folders, which the tests import as native modules (nativeSources) */
const LIBRARY = ['src', 'systems', 'components']
/** a TypeScript source file, not a declaration file */
const isSource = (name: string) => name.endsWith('.ts') && !name.endsWith('.d.ts')
/** the checkout's path as a glob of itself: forward slashes, glob characters escaped */
const globRoot = root.split(sep).join('/').replace(/[()[\]{}*?!+@]/g, '\\$&')

/**
 * The library's sources (src/, systems/, components/) run as plain ES modules compiled by esbuild, file by
 * file (the same transform the build gives them, unbundled), which Node imports itself: the tests import
 * them through this plugin, whatever the path they name them by, so every test and helper shares one copy.
 * Run through vitest's module runner instead, every imported name is read through a getter of the module's
 * exports object, which keeps V8 from inlining one module's functions into another's: the reference
 * workload of tests/helpers.ts took 112–122 ms a run that way against 16–17 ms bundled, and a fixed-tick
 * sequence of the adversarial suite 17.1 s against 8.5–9.5 s. The tests' time budgets then measured the
 * test runner, not the code that ships. In watch mode a changed or new source file is compiled again
 * before the tests re-run (`forceRerunTriggers` below re-runs the files being watched: a native module is
 * not in vite's module graph, so vite cannot tell which tests import it; each test file runs in a new worker
 * process, which imports the rebuilt modules afresh).
 */
function nativeSources(): Plugin {
  const folders = LIBRARY.map((f) => join(root, f))
  // one folder a vitest process (two may run at once in one checkout: the long adversarial run spawns its
  // own), removed when it exits; folders left by processes no longer alive are removed at the next build
  const cache = join(root, 'node_modules', '.cache', 'native-sources')
  const out = join(cache, String(process.pid))
  const inLibrary = (file: string) => folders.some((f) => file.startsWith(f + sep))
  const built = (file: string) => join(out, relative(root, file)).replace(/\.ts$/, '.js')
  const compile = (entryPoints: string[]) =>
    buildSync({ entryPoints, outdir: out, outbase: root, bundle: false, format: 'esm', platform: 'node', target: 'node20', sourcemap: 'inline', logLevel: 'warning' })
  let ready = false
  const build = () => {
    if (ready) return
    ready = true
    const sources = folders.flatMap((f) => readdirSync(f, { recursive: true, encoding: 'utf8' }).filter(isSource).map((n) => join(f, n)))
    mkdirSync(cache, { recursive: true })
    for (const name of readdirSync(cache)) if (!alive(Number(name))) rmSync(join(cache, name), { recursive: true, force: true })
    mkdirSync(out, { recursive: true })
    process.on('exit', () => rmSync(out, { recursive: true, force: true }))
    // ES modules by this folder's own package.json (node_modules/ holds no other)
    writeFileSync(join(out, 'package.json'), '{ "type": "module" }\n')
    compile(sources)
  }
  /** watch mode: a source changed or added after the first build is compiled again (a syntax error is
   * reported by esbuild and leaves the last good build in place) */
  const rebuild = (file: string) => {
    if (!ready || !inLibrary(file) || !isSource(file)) return
    try {
      compile([file])
    } catch {
      // esbuild has printed the error; the tests re-run against the previous build of the file
    }
  }
  return {
    name: 'native-sources',
    enforce: 'pre',
    configureServer(server) {
      // runs before vitest's own re-run (which waits out a short debounce after the same event)
      server.watcher.on('change', rebuild)
      server.watcher.on('add', rebuild)
    },
    resolveId(source, importer) {
      if (!source.startsWith('.') && !source.startsWith('/')) return null
      const base = source.startsWith('/') ? source : resolve(importer ? dirname(importer) : root, source)
      const candidates = [base, base.replace(/\.js$/, '.ts'), `${base}.ts`, join(base, 'index.ts')]
      const file = candidates.find((c) => c.endsWith('.ts') && inLibrary(c) && existsSync(c))
      if (file === undefined) return null
      build()
      return { id: built(file), external: true }
    },
  }
}

/** Whether a process with this id is running (not a number: no). */
function alive(pid: number): boolean {
  if (!Number.isInteger(pid) || pid <= 0) return false
  try {
    process.kill(pid, 0)
    return true
  } catch (e) {
    return (e as NodeJS.ErrnoException).code === 'EPERM'
  }
}

export default defineConfig({
  plugins: [nativeSources()],
  resolve: {
    // the package's own names, for tests that run the README's examples as a user would write them
    alias: [
      { find: /^positron-ball-physics$/, replacement: resolve(root, 'src/index.ts') },
      { find: /^positron-ball-physics\/ecs$/, replacement: resolve(root, 'src/ecs.ts') },
      { find: /^positron-ball-physics\/reference$/, replacement: resolve(root, 'src/reference/index.ts') },
    ],
  },
  test: {
    include: ['tests/**/*.test.ts'],
    environment: 'node',
    testTimeout: 60_000,
    // a change to the library re-runs the test files being watched (see nativeSources)
    forceRerunTriggers: [...configDefaults.forceRerunTriggers, ...LIBRARY.map((f) => `${globRoot}/${f}/**/*.ts`)],
  },
})
