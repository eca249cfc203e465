// The README's TypeScript examples run as written (the package's names resolve to the sources here), so
// the docs cannot drift from the API. Each block is written to a module and imported; its console output
// is captured and checked for what the example promises.
import { execFileSync } from 'node:child_process'
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs'
import { resolve } from 'node:path'
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
