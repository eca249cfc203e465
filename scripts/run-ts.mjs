// Runs a TypeScript entry (a benchmark or a script) under plain Node: esbuild bundles it into
// node_modules/.cache and Node imports the result. Arguments after the entry are passed through.
import { build } from 'esbuild'
import { createHash } from 'node:crypto'
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
// named by the entry's full path too, so two checkouts sharing one node_modules never overwrite each other
const tag = createHash('sha1').update(resolve(entry)).digest('hex').slice(0, 8)
const outfile = resolve(outdir, basename(entry).replace(/\.ts$/, `-${tag}.mjs`))
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
