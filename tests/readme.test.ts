// The README's TypeScript examples run as written (the package's names resolve to the sources here), so
// the docs cannot drift from the API. Each block is written to a module and imported; its console output
// is captured and checked for what the example promises.
import { execFileSync } from 'node:child_process'
import { existsSync, mkdirSync, readdirSync, readFileSync, writeFileSync } from 'node:fs'
import { dirname, resolve } from 'node:path'
import { describe, expect, it, vi } from 'vitest'

const root = resolve(import.meta.dirname, '..')
const readme = readFileSync(resolve(root, 'README.md'), 'utf8')
const blocks = [...readme.matchAll(/```ts\n([\s\S]*?)```/g)].map((m) => m[1]!).filter((b) => b.includes("from 'positron-ball-physics"))

async function run(code: string, name: string): Promise<unknown[][]> {
  const dir = resolve(root, 'test-artifacts/readme')
  mkdirSync(dir, { recursive: true })
  const file = resolve(dir, `${name}.ts`)
  writeFileSync(file, code)
  const logs: unknown[][] = []
  const spy = vi.spyOn(console, 'log').mockImplementation((...args: unknown[]) => void logs.push(args))
  try {
    await import(/* @vite-ignore */ `${file}?t=${Date.now()}`)
  } finally {
    spy.mockRestore()
  }
  return logs
}

describe('README examples', () => {
  it('has the four examples (the game API, snapshots and replays, the throw solver, the ecs entry)', () => {
    expect(blocks.length).toBe(4)
    expect(blocks[0]).toContain('createBallPhysics')
    expect(blocks[1]).toContain('createReplayPlayer')
    expect(blocks[2]).toContain('solveThrow')
    expect(blocks[3]).toContain("from 'positron-ball-physics/ecs'")
  })

  it('the throw solver example runs and finds a throw that captures at the middle hole', async () => {
    const logs = await run(blocks[2]!, 'solver')
    expect(logs).toHaveLength(1)
    expect(String(logs[0]![0])).toMatch(/^capture at hole 13: power 0\.\d{3}, angle -?\d\.\d{3}$/)
  })

  it('the snapshot and replay example runs: the replay and the restored copy give the recorded events', async () => {
    const logs = await run(blocks[1]!, 'replay')
    expect(logs).toHaveLength(1)
    const [events, replayedSame, bytes, copySame] = logs[0] as [number, boolean, number, boolean]
    expect(events).toBeGreaterThan(50)
    expect(replayedSame).toBe(true)
    expect(bytes).toBeGreaterThan(1000)
    expect(copySame).toBe(true)
  })

  it('the game API example runs and reports events', async () => {
    const logs = await run(blocks[0]!, 'use')
    expect(logs.length).toBeGreaterThan(0)
    for (const [type, ball, time] of logs) {
      expect(typeof type).toBe('string')
      expect(ball).toBe(26) // the first ball after the panel's 25 holes
      expect(time as number).toBeGreaterThan(0)
    }
  })

  it('the ecs example runs: its own system counts lip crossings, its own component is queried with Ball', async () => {
    const logs = await run(blocks[3]!, 'ecs')
    expect(logs).toHaveLength(1)
    const [lipCrossings, trail] = logs[0] as [number, number]
    expect(lipCrossings).toBeGreaterThan(0)
    expect(trail).toBeGreaterThan(50) // px rolled while it was a ball
  })

  it('the examples typecheck (strict, the names resolved to the sources)', async () => {
    await run(blocks[0]!, 'use')
    await run(blocks[1]!, 'replay')
    await run(blocks[2]!, 'solver')
    await run(blocks[3]!, 'ecs')
    const dir = resolve(root, 'test-artifacts/readme')
    writeFileSync(
      resolve(dir, 'tsconfig.json'),
      JSON.stringify({
        extends: '../../tsconfig.json',
        compilerOptions: {
          noEmit: true,
          // the examples name things to show them, not to use them all
          noUnusedLocals: false,
          rootDir: '../..',
          paths: {
            'positron-ball-physics': ['../../src/index.ts'],
            'positron-ball-physics/ecs': ['../../src/ecs.ts'],
            'positron-ball-physics/reference': ['../../src/reference/index.ts'],
          },
        },
        include: ['use.ts', 'replay.ts', 'solver.ts', 'ecs.ts'],
      }),
    )
    let out = ''
    try {
      execFileSync(resolve(root, 'node_modules/.bin/tsc'), ['-p', resolve(dir, 'tsconfig.json')], { encoding: 'utf8' })
    } catch (e) {
      out = String((e as { stdout?: string }).stdout ?? e)
    }
    expect(out).toBe('')
  })
})

describe('README benchmark tables', () => {
  it('are the figures of docs/results/*.json (scripts/readme-tables.mjs regenerates them; a table edited by hand or left behind a new run fails here)', async () => {
    const { regenerate, tables } = (await import(/* @vite-ignore */ resolve(root, 'scripts/readme-tables.mjs'))) as {
      regenerate: (text: string) => string
      tables: () => Map<string, string[]>
    }
    expect(tables().size).toBe(8)
    const again = regenerate(readme)
    const differing = readme.split('\n').filter((line, i) => line !== again.split('\n')[i])
    expect(differing).toEqual([])
    // and the check can fail: a changed figure is caught
    expect(regenerate(readme.replace(/\| 100,000 \| ([0-9.]+) \(/, '| 100,000 | 999.9 ('))).not.toBe(readme.replace(/\| 100,000 \| ([0-9.]+) \(/, '| 100,000 | 999.9 ('))
  })
})

/** GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens, repeats numbered. */
function anchorsOf(text: string): Set<string> {
  const out = new Set<string>()
  const seen = new Map<string, number>()
  for (const line of text.split('\n')) {
    const m = /^#{1,6}\s+(.*)$/.exec(line)
    if (!m) continue
    const slug = m[1]!.trim().toLowerCase().replace(/[^\p{L}\p{N}\s_-]/gu, '').replace(/\s/g, '-')
    const n = seen.get(slug) ?? 0
    seen.set(slug, n + 1)
    out.add(n === 0 ? slug : `${slug}-${n}`)
  }
  return out
}

/** The links of a markdown file (outside code blocks) that point at no file of the repository, or at no heading of it. */
function brokenLinks(file: string, text: string): string[] {
  const bad: string[] = []
  for (const m of text.replace(/```[\s\S]*?```/g, '').matchAll(/\]\(([^)\s]+)\)/g)) {
    const link = m[1]!
    if (/^(https?:|mailto:)/.test(link)) continue
    const [path, anchor] = link.split('#') as [string, string | undefined]
    const target = path === '' ? file : resolve(dirname(file), path)
    if (!existsSync(target)) bad.push(`${link}: no such file`)
    else if (anchor && target.endsWith('.md') && !anchorsOf(readFileSync(target, 'utf8')).has(anchor)) bad.push(`${link}: no such heading`)
  }
  return bad
}

describe('README and docs links', () => {
  it('every relative link in README.md and docs/*.md names a file of the repository, and a heading of it where it names one', () => {
    const files = [resolve(root, 'README.md'), ...readdirSync(resolve(root, 'docs')).filter((f) => f.endsWith('.md')).map((f) => resolve(root, 'docs', f))]
    const bad = files.flatMap((f) => brokenLinks(f, readFileSync(f, 'utf8')).map((b) => `${f.slice(root.length + 1)}: ${b}`))
    expect(bad).toEqual([])
    // and the check can fail: a moved file and a renamed heading are caught
    const readmePath = resolve(root, 'README.md')
    expect(brokenLinks(readmePath, '[a](docs/no-such-page.md) [b](docs/benchmarks.md#no-such-heading) [c](docs/benchmarks.md#peers-npm-run-benchpeers)')).toEqual([
      'docs/no-such-page.md: no such file',
      'docs/benchmarks.md#no-such-heading: no such heading',
    ])
  })
})
