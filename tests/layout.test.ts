// The library's shape: imports go one way through the layers of .dependency-cruiser.cjs with no
// runtime cycles (checked by dependency-cruiser), no library file outgrows 420 lines, and nothing
// in the library or its docs cites a file that lives outside this repository.
//
// dependency-cruiser parses TypeScript with the `typescript` package's compiler API, which
// TypeScript 7 (this repo's compiler) no longer ships; handed .ts files it silently cruises
// nothing and reports no violations. So the test type-strips the tree with esbuild (honouring
// tsconfig.json, so verbatimModuleSyntax keeps exactly the imports that exist at run time) into a
// temporary copy with the same layout and cruises that copy with the same configuration. That is
// what dependency-cruiser itself does with `tsPreCompilationDeps: false`; the test checks that
// every library file was cruised and that each rule still catches a planted violation.
//
// `npm run depcruise` runs this file and also prints dependency-cruiser's full report (warnings
// included).
import { mkdirSync, mkdtempSync, readFileSync, readdirSync, rmSync, symlinkSync, writeFileSync } from 'node:fs'
import { tmpdir } from 'node:os'
import { dirname, join, relative, sep } from 'node:path'
import { fileURLToPath } from 'node:url'
import { cruise, format, type ICruiseResult, type IViolation } from 'dependency-cruiser'
import extractDepcruiseOptions from 'dependency-cruiser/config-utl/extract-depcruise-options'
import { transformSync } from 'esbuild'
import { afterAll, beforeAll, describe, expect, it } from 'vitest'

const ROOT = fileURLToPath(new URL('..', import.meta.url))
const LIBRARY = ['src', 'systems', 'components']
/** Copied too, so that an import from the library into tooling is named as such, not as unresolvable. */
const TOOLING = ['tests', 'demo', 'bench', 'scripts']
const MAX_LINES = 420
const OUTSIDE_CITATIONS = ['DECISIONS.md', 'ball-physics-iteration-2', 'shared/spec', 'STYLE.md', 'perf-anchors']
const PRINT_REPORT = process.env.npm_lifecycle_event === 'depcruise'

const posix = (p: string): string => p.split(sep).join('/')

function walk(dir: string): string[] {
  const out: string[] = []
  for (const entry of readdirSync(join(ROOT, dir), { withFileTypes: true })) {
    const rel = `${dir}/${entry.name}`
    if (entry.isDirectory()) out.push(...walk(rel))
    else if (entry.isFile()) out.push(rel)
  }
  return out.sort()
}

const isTs = (file: string): boolean => /\.[cm]?ts$/.test(file) && !/\.d\.[cm]?ts$/.test(file)
const jsName = (file: string): string => file.replace(/\.([cm]?)ts$/, '.$1js')
/** A path in the type-stripped copy, back to the source file's name. */
const sourceName = (file: string): string =>
  /^(src|systems|components|tests|demo|bench|scripts)\//.test(file) ? file.replace(/\.([cm]?)js$/, '.$1ts') : file
const sourceText = (text: string): string =>
  text.replace(/\b((?:src|systems|components|tests|demo|bench|scripts)\/[\w./-]*?)\.([cm]?)js\b/g, '$1.$2ts')

const TSCONFIG = readFileSync(join(ROOT, 'tsconfig.json'), 'utf8')

/** Writes `file` (repository-relative) into the copy at `dir`, type-stripped if it is TypeScript. */
function put(dir: string, file: string, text: string): void {
  const target = join(dir, isTs(file) ? jsName(file) : file)
  mkdirSync(dirname(target), { recursive: true })
  if (!isTs(file)) return writeFileSync(target, text)
  const { code } = transformSync(text, { loader: 'ts', format: 'esm', target: 'esnext', tsconfigRaw: TSCONFIG, sourcefile: file })
  writeFileSync(target, code)
}

async function cruiseCopy(dir: string, entries: string[]): Promise<ICruiseResult> {
  const options = await extractDepcruiseOptions(join(ROOT, '.dependency-cruiser.cjs'))
  delete options.tsConfig // the copy is JavaScript whose `.js` specifiers name real files
  const { output } = await cruise(entries, { ...options, baseDir: dir, preserveSymlinks: true, outputType: 'json' })
  return typeof output === 'string' ? (JSON.parse(output) as ICruiseResult) : output
}

function describeViolation(v: IViolation): string {
  const rule = `${v.rule.name} (${v.rule.severity})`
  if (v.cycle?.length) {
    const path = [v.from, ...v.cycle.map((step) => step.name)].map(sourceName).join(' → ')
    return `${rule}: ${path}`
  }
  if (v.from === v.to) return `${rule}: ${sourceName(v.from)}`
  return `${rule}: ${sourceName(v.from)} → ${sourceName(v.to)}`
}

let copy = ''
let result: ICruiseResult
let libraryFiles: string[] = []

beforeAll(async () => {
  copy = mkdtempSync(join(tmpdir(), 'layout-'))
  for (const dir of [...LIBRARY, ...TOOLING]) for (const file of walk(dir)) put(copy, file, readFileSync(join(ROOT, file), 'utf8'))
  writeFileSync(join(copy, 'package.json'), readFileSync(join(ROOT, 'package.json')))
  symlinkSync(join(ROOT, 'node_modules'), join(copy, 'node_modules'), 'junction')
  libraryFiles = LIBRARY.flatMap(walk).filter(isTs)
  result = await cruiseCopy(copy, LIBRARY)
  if (PRINT_REPORT) {
    const { output } = await format(result, { outputType: 'err-long' })
    console.log(sourceText(String(output)))
  }
}, 60_000)

afterAll(() => {
  if (copy) rmSync(copy, { recursive: true, force: true })
})

describe('import layering (dependency-cruiser, .dependency-cruiser.cjs)', () => {
  it('cruises every library file', () => {
    const cruised = new Set(result.modules.map((m) => sourceName(m.source)))
    expect(libraryFiles.length).toBeGreaterThan(0)
    expect(libraryFiles.filter((f) => !cruised.has(f))).toEqual([])
    expect(result.summary.totalDependenciesCruised).toBeGreaterThan(libraryFiles.length)
  })

  it('has no upward imports, runtime cycles, imports of tooling, or unresolvable imports', () => {
    const errors = result.summary.violations.filter((v) => v.rule.severity === 'error')
    const listed = errors.map(describeViolation)
    expect(errors.length, `${errors.length} dependency violation(s):\n  ${listed.join('\n  ')}\n`).toBe(0)
  })

  it('catches each kind of violation when one is planted', async () => {
    const planted: Record<string, string> = {
      'src/api/__layoutCanaryTop.ts': 'export const top = 1\n',
      'src/world/__layoutCanaryUp.ts': "import { top } from '../api/__layoutCanaryTop.js'\nexport const up = top\n",
      'src/world/__layoutCanaryTypeOnly.ts':
        "import type { top } from '../api/__layoutCanaryTop.js'\nexport type T = typeof top\nexport const n = 1\n",
      'src/contacts/__layoutCanaryA.ts': "import { b } from './__layoutCanaryB.js'\nexport const a = () => b()\n",
      'src/contacts/__layoutCanaryB.ts': "import { a } from './__layoutCanaryA.js'\nexport const b = () => a\n",
      'tests/__layoutCanaryTool.ts': 'export const tool = 1\n',
      'src/motion/__layoutCanaryTooling.ts': "import { tool } from '../../tests/__layoutCanaryTool.js'\nexport const t = tool\n",
      'src/motion/__layoutCanaryMissing.ts': "import { gone } from './__layoutCanaryGone.js'\nexport const m = gone\n",
      'src/__layoutCanaryNew/x.ts': "import { top } from '../api/__layoutCanaryTop.js'\nexport const x = top\n",
    }
    for (const [file, text] of Object.entries(planted)) put(copy, file, text)
    const canary = await cruiseCopy(copy, Object.keys(planted).filter((f) => f.startsWith('src/')).map(jsName))
    const found = canary.summary.violations.filter((v) => v.rule.severity === 'error').map(describeViolation).sort()
    expect(found).toEqual(
      [
        'layer-unassigned (error): src/__layoutCanaryNew/x.ts → src/api/__layoutCanaryTop.ts',
        'library-not-tooling (error): src/motion/__layoutCanaryTooling.ts → tests/__layoutCanaryTool.ts',
        'no-circular (error): src/contacts/__layoutCanaryA.ts → src/contacts/__layoutCanaryB.ts → src/contacts/__layoutCanaryA.ts',
        'not-to-unresolvable (error): src/motion/__layoutCanaryMissing.ts → ./__layoutCanaryGone.js',
        'world-not-up (error): src/world/__layoutCanaryUp.ts → src/api/__layoutCanaryTop.ts',
      ].sort(),
    )
    // the upward `import type` was cruised, and is not an edge
    const typeOnly = canary.modules.find((m) => m.source === 'src/world/__layoutCanaryTypeOnly.js')
    expect(typeOnly?.dependencies).toEqual([])
  })
})

describe('library files', () => {
  it(`are at most ${MAX_LINES} lines`, () => {
    const over = LIBRARY.flatMap(walk)
      .map((file) => {
        const text = readFileSync(join(ROOT, file), 'utf8')
        const lines = text === '' ? 0 : text.split('\n').length - (text.endsWith('\n') ? 1 : 0)
        return { file, lines }
      })
      .filter(({ lines }) => lines > MAX_LINES)
      .map(({ file, lines }) => `${file}: ${lines} lines`)
    expect(over, `files over ${MAX_LINES} lines:\n  ${over.join('\n  ')}\n`).toEqual([])
  })

  it('cite no file outside the repository (library, docs/, README.md)', () => {
    const files = [...LIBRARY.flatMap(walk), ...walk('docs'), 'README.md']
    const hits: string[] = []
    for (const file of files) {
      const bytes = readFileSync(join(ROOT, file))
      if (bytes.includes(0)) continue // images and other binaries
      bytes
        .toString('utf8')
        .split('\n')
        .forEach((line, i) => {
          for (const needle of OUTSIDE_CITATIONS) {
            if (line.includes(needle)) hits.push(`${posix(relative(ROOT, join(ROOT, file)))}:${i + 1}: ${needle}: ${line.trim()}`)
          }
        })
    }
    expect(hits, `citations of files outside the repository:\n  ${hits.join('\n  ')}\n`).toEqual([])
  })
})
