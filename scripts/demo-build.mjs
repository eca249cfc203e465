// Builds the pixi.js demo (demo/main.ts and the static files next to it) into a directory that any static
// web server can host: index.html, style.css, main.js and solveWorker.js (+ maps). pixi.js and lil-gui are bundled here only;
// the library bundle (scripts/build.mjs) never sees them.
//
//   node scripts/demo-build.mjs [--outdir demo-dist] [--dev]
//
// Also imported by scripts/demo-serve.mjs (buildDemo, demoBuildOptions).
import { build, context } from 'esbuild'
import { copyFileSync, mkdirSync } from 'node:fs'
import { dirname, resolve } from 'node:path'
import { fileURLToPath, pathToFileURL } from 'node:url'

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..')
export const DEMO_DIR = resolve(root, 'demo')
export const DEFAULT_OUTDIR = resolve(root, 'demo-dist')
const STATIC_FILES = ['index.html', 'style.css']

/** esbuild options for the demo bundle. `dev`: readable output with inline-able source maps. */
export function demoBuildOptions(outdir = DEFAULT_OUTDIR, dev = false) {
  return {
    // the page, and the throw solver's worker (Call your shot), which the page loads from next to it
    entryPoints: { main: resolve(DEMO_DIR, 'main.ts'), solveWorker: resolve(DEMO_DIR, 'solveWorker.ts') },
    outdir,
    bundle: true,
    format: 'esm',
    platform: 'browser',
    target: 'es2022',
    minify: !dev,
    sourcemap: true,
    legalComments: 'linked',
    define: { 'process.env.NODE_ENV': dev ? '"development"' : '"production"' },
    logLevel: 'warning',
    metafile: true,
  }
}

export function copyStatic(outdir = DEFAULT_OUTDIR) {
  mkdirSync(outdir, { recursive: true })
  for (const f of STATIC_FILES) copyFileSync(resolve(DEMO_DIR, f), resolve(outdir, f))
}

/** One build into `outdir`; returns esbuild's result (with metafile). */
export async function buildDemo({ outdir = DEFAULT_OUTDIR, dev = false } = {}) {
  mkdirSync(outdir, { recursive: true })
  const result = await build(demoBuildOptions(outdir, dev))
  copyStatic(outdir)
  return result
}

/** A watching build (for `npm run demo`): rebuilds main.js and solveWorker.js and recopies the static files on change. */
export async function watchDemo({ outdir = DEFAULT_OUTDIR } = {}) {
  mkdirSync(outdir, { recursive: true })
  copyStatic(outdir)
  const ctx = await context({
    ...demoBuildOptions(outdir, true),
    plugins: [{ name: 'copy-static', setup: (b) => b.onEnd(() => copyStatic(outdir)) }],
  })
  await ctx.watch()
  return ctx
}

function argValue(name, fallback) {
  const i = process.argv.indexOf(name)
  return i >= 0 && process.argv[i + 1] ? resolve(process.argv[i + 1]) : fallback
}

if (import.meta.url === pathToFileURL(process.argv[1] ?? '').href) {
  const outdir = argValue('--outdir', DEFAULT_OUTDIR)
  const dev = process.argv.includes('--dev')
  const t0 = performance.now()
  const result = await buildDemo({ outdir, dev })
  const bytes = Object.values(result.metafile.outputs).reduce((s, o) => s + o.bytes, 0)
  console.log(
    `demo built into ${outdir} (${(bytes / 1024).toFixed(0)} KiB with maps, ${(performance.now() - t0).toFixed(0)} ms)`,
  )
}
