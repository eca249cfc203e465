// The cross-engine bundles: a test entry bundled by esbuild into one script with no imports (an IIFE), the
// way every engine can run it (a shell, a runtime, a browser page). Read by tests/engines.test.ts and
// tests/browser/engines.test.ts.
import { resolve } from 'node:path'
import { build } from 'esbuild'

const root = resolve(import.meta.dirname, '../..')

/** The entry's bundle as one script's text; `define` replaces globals by JSON values (esbuild's define). */
export async function bundleText(entry: string, define: Record<string, string> = {}): Promise<string> {
  const out = await build({
    absWorkingDir: root,
    entryPoints: [entry],
    bundle: true,
    format: 'iife',
    platform: 'neutral',
    mainFields: ['module', 'main'],
    target: 'es2022',
    define,
    write: false,
    logLevel: 'silent',
  })
  return out.outputFiles[0]!.text
}
