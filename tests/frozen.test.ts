// The exported constant tables are frozen all the way down: a game cannot loosen a config range or rename
// an event type by writing into them (test files are modules, so such a write throws).
import { describe, expect, it } from 'vitest'
import * as main from '../src/index'
import * as ecs from '../src/ecs'
import * as reference from '../src/reference/index'
import { BALL_MODE_NAMES, CONFIG_RANGES, EVENT_TYPE_NAMES, addPanel, createBallPhysics } from '../src/index'

/** Paths under `value` to objects that are not frozen (functions and their properties are not data). */
function unfrozen(value: unknown, path: string, out: string[], seen = new Set<unknown>()): string[] {
  if (value === null || typeof value !== 'object' || seen.has(value)) return out
  seen.add(value)
  if (!Object.isFrozen(value)) out.push(path)
  for (const key of Object.keys(value)) unfrozen((value as Record<string, unknown>)[key], `${path}.${key}`, out, seen)
  return out
}

describe('exported constant tables', () => {
  it('every exported object of the three entries is frozen, and every object inside it', () => {
    const open: string[] = []
    const checked: string[] = []
    for (const [entry, mod] of [['index', main], ['ecs', ecs], ['reference', reference]] as const) {
      for (const [name, value] of Object.entries(mod)) {
        if (value === null || typeof value !== 'object') continue
        checked.push(name)
        unfrozen(value, `${entry}.${name}`, open)
      }
    }
    expect(checked).toEqual(expect.arrayContaining(['CONFIG_RANGES', 'CONFIG_CHOICES', 'EVENT_TYPE_NAMES', 'BALL_MODE_NAMES', 'RIM_MODE_NAMES', 'DEFAULT_CONFIG', 'DEFAULT_PANEL', 'DEFAULT_SCHEDULE', 'BallMode', 'EventType', 'PathEvent', 'BallSchema']))
    expect(open).toEqual([])
  })

  it('CONFIG_RANGES.ROLLING_DECEL.min = -1e9 throws, and a negative ROLLING_DECEL is still refused', () => {
    expect(() => {
      ;(CONFIG_RANGES.ROLLING_DECEL as { min: number }).min = -1e9
    }).toThrow(TypeError)
    expect(() => {
      ;(CONFIG_RANGES as Record<string, unknown>).ROLLING_DECEL = { min: -1e9, max: 1e6 }
    }).toThrow(TypeError)
    expect(CONFIG_RANGES.ROLLING_DECEL.min).toBe(0)
    expect(() => createBallPhysics({ ROLLING_DECEL: -1 })).toThrow(/config\.ROLLING_DECEL must be in \[0, 1000000\]/)
  })

  it("EVENT_TYPE_NAMES[1] = 'CAUGHT' and BALL_MODE_NAMES[2] = 'gone' throw; drained events and states keep their names", () => {
    expect(() => {
      ;(EVENT_TYPE_NAMES as unknown as string[])[1] = 'CAUGHT'
    }).toThrow(TypeError)
    expect(() => {
      ;(BALL_MODE_NAMES as unknown as string[])[2] = 'gone'
    }).toThrow(TypeError)
    expect(() => (EVENT_TYPE_NAMES as unknown as string[]).push('extra')).toThrow(TypeError)
    const sim = createBallPhysics()
    const [hole] = addPanel(sim)
    const ball = sim.addBall({ x: 50, y: 370, vx: 0, vy: 0 }) // at rest over a hole: falls in
    sim.step(1 / 60)
    expect(sim.drainEvents().map((e) => [e.type, e.ball, e.hole])).toEqual([['capture', ball, hole]])
    expect(sim.ballState(ball).mode).toBe('captured')
  })
})
