// Runs a TypeScript entry (a benchmark or a script) under plain Node: esbuild bundles it into
// node_modules/.cache and Node imports the result. Arguments after the entry are passed through.
import { build } from 'esbuild'
import { mkdirSync } from 'node:fs'
import { basename, resolve } from 'node:path'
import { pathToFileURL } from 'node:url'

const entry = process.argv[2]
if (!entry) {
  console.error('usage: node scripts/run-ts.mjs <entry.ts> [args...]')
  process.exit(2)
}
const outdir = resolve('node_modules/.cache/run-ts')
mkdirSync(outdir, { recursive: true })
const outfile = resolve(outdir, basename(entry).replace(/\.ts$/, '.mjs'))
await build({
  entryPoints: [entry],
  outfile,
  bundle: true,
  format: 'esm',
  platform: 'node',
  target: 'node20',
  packages: 'external',
  sourcemap: 'inline',
  logLevel: 'warning',
})
process.argv.splice(2, 1)
await import(pathToFileURL(outfile).href)
