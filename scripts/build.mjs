// Bundles the library's three entry points with esbuild: `.` (src/index.ts → dist/index.js), `./ecs`
// (src/ecs.ts → dist/ecs.js) and `./reference` (src/reference/index.ts → dist/reference.js).
// Splitting is required, not an optimisation: a world made through `.` is handed to functions from
// `./ecs`, so every module with module-level state (e.g. the WeakMap of stores in components/store.ts)
// must exist once, in a shared chunk under dist/chunks/, not be copied into each entry.
// bitecs stays external: it is the package's one runtime dependency. The portable elementary functions
// (src/math.ts, from @stdlib packages written as CommonJS, hence the main field) are bundled in, so a
// user installs none of them. Declarations come from tsc
// (tsconfig.build.json → dist/types/).
import { build } from 'esbuild'
import { rm } from 'node:fs/promises'
import { fileURLToPath } from 'node:url'

const root = fileURLToPath(new URL('..', import.meta.url))

// stale chunks (their names carry content hashes) would otherwise pile up in the package
await rm(new URL('../dist', import.meta.url), { recursive: true, force: true })

await build({
  absWorkingDir: root,
  entryPoints: {
    index: 'src/index.ts',
    ecs: 'src/ecs.ts',
    reference: 'src/reference/index.ts',
  },
  entryNames: '[name]',
  chunkNames: 'chunks/[name]-[hash]',
  bundle: true,
  splitting: true,
  format: 'esm',
  platform: 'neutral',
  mainFields: ['module', 'main'],
  target: 'es2022',
  external: ['bitecs'],
  outdir: 'dist',
  sourcemap: true,
  logLevel: 'info',
})
