// The same simulation, bit for bit, in every JavaScript engine: the scenarios of tests/engines/scenarios.ts
// (the design, PHYSICAL_CONFIG, TABULATED_CONFIG, both contact methods, the fixed tick with unlike masses;
// 1,000 balls each, hero balls among them) bundled once and run in Node (V8), Bun (JavaScriptCore, the
// @oven/bun-linux-x64 package) and the
// SpiderMonkey shell (js102, from Debian's libmozjs-102-dev); every hash must match Node's, and the run
// inside this test process.
import { execFileSync } from 'node:child_process'
import { existsSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs'
import { tmpdir } from 'node:os'
import { join, resolve } from 'node:path'
import { afterAll, beforeAll, describe, expect, it } from 'vitest'
import { bundleText } from './engines/bundle.js'
import { Hash, playSession, recordSession, runAll, SCENARIOS, type ScenarioResult } from './engines/scenarios.js'

const root = resolve(import.meta.dirname, '..')
const ENGINES: Record<string, { path: string; install: string }> = {
  'node (V8)': { path: process.execPath, install: 'Node itself' },
  'bun (JavaScriptCore)': { path: join(root, 'node_modules/@oven/bun-linux-x64/bin/bun'), install: 'npm ci (devDependency @oven/bun-linux-x64)' },
  'js102 (SpiderMonkey)': { path: '/usr/bin/js102', install: 'apt-get install libmozjs-102-dev' },
}

let dir = ''
let bundle = ''
let replayBundle = ''
/** the session recorded in this process: its replay's JSON and the hash of its events */
const session = recordSession()

/** Writes the bundle of a test entry (tests/engines/bundle.ts) into the test's folder. */
async function bundleFile(entry: string, name: string, define: Record<string, string> = {}): Promise<string> {
  const file = join(dir, name)
  writeFileSync(file, await bundleText(entry, define))
  return file
}

beforeAll(async () => {
  dir = mkdtempSync(join(tmpdir(), 'engines-'))
  bundle = await bundleFile('tests/engines/main.ts', 'engines.js')
  replayBundle = await bundleFile('tests/engines/replayMain.ts', 'replay.js', { REPLAY_TEXT: JSON.stringify(session.text) })
})

afterAll(() => {
  if (dir !== '') rmSync(dir, { recursive: true, force: true })
})

function runIn<T = Record<string, ScenarioResult>>(engine: string, file = bundle): T {
  const { path, install } = ENGINES[engine]!
  if (!existsSync(path)) throw new Error(`${engine} is not installed at ${path} (install: ${install})`)
  const text = execFileSync(path, [file], { encoding: 'utf8', timeout: 120_000 })
  return JSON.parse(text.trim().split('\n').pop()!) as T
}

describe('the same bits in every engine', () => {
  let node: Record<string, ScenarioResult>
  beforeAll(() => {
    node = runIn('node (V8)')
  })

  it('covers every scenario, and the scenarios do something (events, captures, distinct hashes)', () => {
    expect(Object.keys(node).sort()).toEqual(Object.keys(SCENARIOS).sort())
    for (const r of Object.values(node)) {
      expect(r.events).toBeGreaterThan(1000)
      expect(r.captured).toBeGreaterThan(100)
    }
    expect(new Set(Object.values(node).map((r) => r.hash)).size).toBe(Object.keys(SCENARIOS).length)
  })

  it('this process (vitest, the source through its transform) gives Node its bits', () => {
    expect(runAll()).toEqual(node)
  })

  for (const engine of ['bun (JavaScriptCore)', 'js102 (SpiderMonkey)']) {
    it(`${engine} gives Node its bits in every scenario`, () => {
      const other = runIn(engine)
      for (const name of Object.keys(SCENARIOS)) expect({ name, ...other[name] }).toEqual({ name, ...node[name] })
    })
  }

  it('a replay recorded here plays back with every event bit-identical, here and in every engine', () => {
    expect(session.events).toBeGreaterThan(500)
    expect(playSession(session.text)).toEqual({ hash: session.hash, events: session.events })
    for (const engine of Object.keys(ENGINES)) {
      expect({ engine, ...runIn<{ hash: string; events: number }>(engine, replayBundle) }).toEqual({ engine, hash: session.hash, events: session.events })
    }
  })

  it('a hash changes with the last bit of one number', () => {
    const a = new Hash()
    const b = new Hash()
    a.num(0.1)
    b.num(0.1 + 2 ** -56) // the next double after 0.1
    expect(0.1 + 2 ** -56).not.toBe(0.1)
    expect(a.hex()).not.toBe(b.hex())
  })
})
