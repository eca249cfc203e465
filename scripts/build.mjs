// Bundles the library (src/index.ts and everything it imports) into dist/index.js with esbuild.
// bitecs stays external: it is the package's one runtime dependency. Declarations come from tsc.
import { build } from 'esbuild'

await build({
  entryPoints: ['src/index.ts'],
  outfile: 'dist/index.js',
  bundle: true,
  format: 'esm',
  platform: 'neutral',
  target: 'es2022',
  external: ['bitecs'],
  sourcemap: true,
  logLevel: 'info',
})
