// pixi.js and lil-gui are the demo's dependencies only: the library bundle (src/index.ts, built the way
// scripts/build.mjs builds dist/index.js) must not pull in any of their code. The demo bundle is built
// too, as a control that the check can see pixi when it is there.
import { build, type Metafile } from 'esbuild'
import { resolve } from 'node:path'
import { describe, expect, it } from 'vitest'

const root = resolve(import.meta.dirname, '../..')
const DEMO_ONLY = /node_modules[\\/](pixi\.js|@pixi|lil-gui|earcut|eventemitter3|parse-svg-path|ismobilejs|gifuct-js|tiny-lru|@xmldom|@webgpu)[\\/]/

function inputsMatching(meta: Metafile, re: RegExp): string[] {
  return Object.keys(meta.inputs).filter((p) => re.test(p))
}

describe('core bundle', () => {
  it('contains no pixi.js or lil-gui code', async () => {
    const result = await build({
      absWorkingDir: root,
      entryPoints: ['src/index.ts'],
      bundle: true,
      format: 'esm',
      platform: 'neutral',
      mainFields: ['module', 'main'],
      target: 'es2022',
      external: ['bitecs'],
      write: false,
      metafile: true,
      logLevel: 'silent',
    })
    const text = result.outputFiles.map((f) => f.text).join('\n')
    expect(text.length).toBeGreaterThan(1000)
    // from node_modules, only the portable elementary functions of src/math.ts (and what they build on)
    const fromPackages = inputsMatching(result.metafile, /node_modules/)
    expect(fromPackages.length).toBeGreaterThan(0)
    expect(fromPackages.filter((p) => !/node_modules[\\/]@stdlib[\\/]/.test(p))).toEqual([])
    expect(text).not.toMatch(/pixi/i)
    expect(text).not.toMatch(/lil-gui|lil_gui/i)
    // no demo module leaks in either
    expect(Object.keys(result.metafile.inputs).filter((p) => p.startsWith('demo/'))).toEqual([])
    // its only bare import is bitecs
    const imports = new Set<string>()
    for (const out of Object.values(result.metafile.outputs)) for (const i of out.imports) imports.add(i.path)
    expect([...imports]).toEqual(['bitecs'])
  })

  it('the check sees pixi.js and lil-gui in the demo bundle (control)', async () => {
    const result = await build({
      absWorkingDir: root,
      entryPoints: ['demo/main.ts'],
      bundle: true,
      format: 'esm',
      platform: 'browser',
      target: 'es2022',
      write: false,
      metafile: true,
      logLevel: 'silent',
    })
    const inputs = inputsMatching(result.metafile, DEMO_ONLY)
    expect(inputs.some((p) => p.includes('pixi.js'))).toBe(true)
    expect(inputs.some((p) => p.includes('lil-gui'))).toBe(true)
  })
})
