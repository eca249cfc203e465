// The throw solver (src/api/solveThrow.ts): every answer checked by simulating it in a world of its own.
import { describe, expect, it } from 'vitest'
import { addPanel, createBallPhysics, DEFAULT_PANEL, mulberry32, solveThrow, type BallPhysics, type ConfigOverrides, type ThrowOutcome, type ThrowSolution } from '../src/index.js'

const WALLS = { minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 0.5, open: { bottom: true } }

function panel(config: ConfigOverrides = {}): { sim: BallPhysics; holes: number[] } {
  const sim = createBallPhysics(config)
  const holes = addPanel(sim)
  sim.setWalls(WALLS)
  return { sim, holes }
}

/** The first decisive event (capture, skip, lipOut, bounce) of the thrown ball at `hole`, in a copy of `sim` made by snapshot. */
function outcomeOf(sim: BallPhysics, hole: number, s: { from: { x: number; y: number }; power: number; angle: number }, dt = 1 / 60, queue: 'back' | 'front' = 'back'): ThrowOutcome | null {
  const copy = createBallPhysics(sim.config)
  copy.restore(sim.snapshot())
  copy.drainEvents()
  const b = copy.throwBall({ x: s.from.x, y: s.from.y, power: s.power, angle: s.angle, queue })
  for (let t = 0; t < 20; t += dt) {
    copy.step(dt) // another step than the solver's: the outcome does not depend on it
    for (const e of copy.drainEvents()) {
      if (e.ball !== b || e.hole !== hole) continue
      if (e.type === 'capture' || e.type === 'skip' || e.type === 'lipOut' || e.type === 'bounce') return e.type
    }
    const m = copy.ballState(b).mode
    if (m === 'captured' || m === 'out' || m === 'resting') return null
  }
  return null
}

describe('solveThrow', () => {
  it('finds a capture for every hole of the default panel from the launch line, and each one captures when thrown', () => {
    const { sim, holes } = panel()
    for (const hole of holes) {
      const s = solveThrow(sim, { from: DEFAULT_PANEL.launch, hole, along: 160 })
      expect(s.found, `hole ${hole}`).toBe(true)
      const t = s as ThrowSolution
      expect(outcomeOf(sim, hole, t), `hole ${hole}`).toBe('capture')
      expect(t.power).toBeGreaterThanOrEqual(0)
      expect(t.power).toBeLessThanOrEqual(1)
      expect(t.time).toBeGreaterThan(0)
      // the margin is a margin: half of it either way still captures
      expect(t.margin.power + t.margin.angle).toBeGreaterThan(0)
      for (const k of [-0.5, 0.5]) {
        const p = Math.min(1, Math.max(0, t.power + k * t.margin.power))
        expect(outcomeOf(sim, hole, { ...t, power: p }), `hole ${hole} power ${k}`).toBe('capture')
        expect(outcomeOf(sim, hole, { ...t, angle: t.angle + k * t.margin.angle }), `hole ${hole} angle ${k}`).toBe('capture')
      }
    }
  })

  it('from the launch point alone: the holes straight behind the first row cannot be reached, and it says why', () => {
    const { sim, holes } = panel()
    const behind = holes[12]! // the middle of the middle row, behind two holes in line
    const s = solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: behind })
    expect(s.found).toBe(false)
    if (!s.found) {
      expect(s.reason).toMatch(new RegExp(`no throw from \\(210, 450\\) gives capture at hole ${behind}`))
      expect(s.trials).toBeGreaterThan(1000)
      expect(s.power).toBeNull()
    }
    // the reason names the ways tried: with walls, bank shots off them too; without, direct throws only
    if (!s.found) expect(s.reason).toMatch(/throws tried, (direct and off the closed walls|direct only \(no bank shot off the walls toward it\)), over/)
    const bare = createBallPhysics()
    const bareHoles = addPanel(bare)
    const none = solveThrow(bare, { from: DEFAULT_PANEL.launch, hole: bareHoles[12]! })
    expect(none.found).toBe(false)
    if (!none.found) expect(none.reason).toMatch(/throws tried, direct only \(no walls\), over the powers and aims that reach it/)
    // and a hole of the first row is
    const first = solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[1]! })
    expect(first.found).toBe(true)
    expect((first as ThrowSolution).from).toEqual(DEFAULT_PANEL.launch)
  })

  for (const outcome of ['skip', 'lipOut', 'bounce'] as const) {
    it(`${outcome}: found for holes of each row, and each one gives ${outcome} there when thrown`, () => {
      const { sim, holes } = panel()
      for (const i of [0, 6, 12, 18, 24]) {
        const s = solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[i]!, outcome, along: 160 })
        expect(s.found, `hole ${holes[i]}`).toBe(true)
        expect(outcomeOf(sim, holes[i]!, s as ThrowSolution), `hole ${holes[i]}`).toBe(outcome)
      }
    })
  }

  it('solves from the world as it is: its time, and with contacts on, the balls already on the panel', () => {
    const { sim, holes } = panel({ BALL_COLLISIONS: 'on' })
    // balls resting in the launch lane, and time on the clock
    for (let i = 0; i < 6; i++) sim.addBall({ x: 150 + 24 * i, y: 405, vx: 0, vy: 0 })
    for (let i = 0; i < 30; i++) sim.step(1 / 60)
    for (const i of [2, 7, 11, 22]) {
      const s = solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[i]!, along: 160 })
      expect(s.found, `hole ${holes[i]}`).toBe(true)
      expect(outcomeOf(sim, holes[i]!, s as ThrowSolution), `hole ${holes[i]}`).toBe('capture')
    }
  })

  it('is deterministic, and leaves the world untouched', () => {
    const { sim, holes } = panel()
    const before = sim.snapshot()
    const a = solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[17]!, along: 160 })
    const b = solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[17]!, along: 160 })
    expect(b).toEqual(a)
    expect(sim.snapshot()).toEqual(before)
  })

  it('refuses bad requests by name', () => {
    const { sim, holes } = panel()
    expect(() => solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: 9999 })).toThrow(/request\.hole 9999 is not a live hole/)
    expect(() => solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[0]!, outcome: 'drop' as ThrowOutcome })).toThrow(/request\.outcome must be one of capture, skip, lipOut, bounce/)
    expect(() => solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[0]!, outcome: 'drop' as ThrowOutcome })).toThrow(RangeError)
    expect(() => solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[0]!, outcome: 5 as never })).toThrow(TypeError)
    expect(() => solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[0]!, outcome: 5 as never })).toThrow(/request\.outcome must be one of capture, skip, lipOut, bounce, got 5/)
    expect(() => solveThrow(sim, { from: { x: Number.NaN, y: 450 }, hole: holes[0]! })).toThrow(/request\.from\.x/)
    expect(() => solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[0]!, along: -1 })).toThrow(/request\.along/)
    // along keeps the segment within the coordinates; a step too short to simulate 20 s of throws is refused, by name
    expect(() => solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[0]!, along: 1e9 })).toThrow(/request\.along must be in \[0, 999999790\]/)
    expect(() => solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[0]!, step: 5e-324 })).toThrow(/request\.step must be in \[0\.0001, 0\.25\], got 5e-324/)
    expect(() => solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[0]!, step: '1' as never })).toThrow(TypeError)
    const fine = panel({ MAX_STEP: 1e-6 })
    expect(() => solveThrow(fine.sim, { from: DEFAULT_PANEL.launch, hole: fine.holes[0]! })).toThrow(/solveThrow: the world's MAX_STEP must be at least 0\.0001 s/)
    // inside a drain's callback: refused in its own name (the snapshot it takes named snapshotWorld)
    sim.throwBall({ x: 210, y: 450, power: 0.5, angle: 0 })
    let inDrain = ''
    for (let i = 0; i < 60 && inDrain === ''; i++) {
      sim.step(1 / 60)
      sim.drainEventsWith(() => {
        try {
          solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[0]! })
        } catch (e) {
          inDrain = (e as Error).message
        }
      })
    }
    expect(inDrain).toMatch(/^solveThrow: called from a drainEventsWith callback/)
    const inside = solveThrow(sim, { from: { x: 50, y: 370 }, hole: holes[0]! })
    expect(inside.found).toBe(false)
    for (const step of [0, -1, 1, Number.NaN]) expect(() => solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[0]!, step })).toThrow(/request\.step must be in \[0\.0001, 0\.25\]/)
    expect(() => solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[0]!, step: '0.1' as unknown as number })).toThrow(TypeError)
  })

  it('with balls held at the launcher (contacts on), every answer holds at any step: 1/60, 1/240 and 0.25 s (when held balls left at step starts, answers checked at 0.25 s missed at 1/60 s: 11 of 24)', () => {
    // a burst from the launch point: all but one held, released as the spot clears, at launch instants
    const { sim, holes } = panel({ BALL_COLLISIONS: 'on' })
    for (let i = 0; i < 12; i++) sim.throwBall({ x: 210, y: 450, power: 0.3 + 0.05 * i, angle: -0.5 + 0.09 * i })
    for (let i = 0; i < 12; i++) sim.step(1 / 60)
    sim.drainEvents()
    expect(sim.balls().filter((b) => sim.ballState(b).mode === 'held').length).toBeGreaterThan(5)
    let found = 0
    for (let i = 0; i < holes.length; i++) {
      const shot = solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[i]!, outcome: 'capture', along: 160 })
      if (!shot.found) continue
      found++
      // the solver checked it at MAX_STEP (0.25 s)
      for (const dt of [1 / 60, 1 / 240, 0.25]) expect(outcomeOf(sim, holes[i]!, shot, dt), `hole ${i}, step ${dt}`).toBe('capture')
    }
    expect(found).toBeGreaterThanOrEqual(12)
  })

  it('a throw that would wait at a busy launcher past the 20 s it is followed: the reason says so (it said the other balls spoil the throw); with fewer queued it leaves in time and solves', () => {
    for (const method of ['on', 'fixed'] as const) {
      const busyPanel = (n: number) => {
        const { sim, holes } = panel({ BALL_COLLISIONS: method })
        const rand = mulberry32(3)
        const L = DEFAULT_PANEL.launch
        for (let i = 0; i < n; i++) sim.throwBall({ x: L.x, y: L.y, power: 0.5 + 0.5 * rand(), angle: (rand() - 0.5) * 2 })
        sim.step(1 / 60)
        return { sim, holes }
      }
      const solve = (n: number, hole: number) => {
        const { sim, holes } = busyPanel(n)
        return solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[hole]!, outcome: 'capture' })
      }
      for (const hole of [0, 5, 20]) {
        const busy = solve(600, hole)
        expect(busy.found, `${method}, hole ${hole}`).toBe(false)
        if (!busy.found) expect(busy.reason, method).toMatch(/^a ball thrown from \(210, 450\) now waits held at its spot behind the balls queued there \(599 held\) for longer than the 20 s a throw is followed: try again when the launcher has room, or ask for a throw at the front of the queue \(request.queue 'front'\)$/)
      }
      // asked for at the front of the queue, the throw waits only for the spot: found, and it captures when
      // thrown so (thrown at the back, it would wait behind the 599)
      const { sim, holes } = busyPanel(600)
      const front = solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[5]!, outcome: 'capture', queue: 'front' })
      expect(front.found, method).toBe(true)
      if (front.found) {
        expect(outcomeOf(sim, holes[5]!, front, 1 / 60, 'front'), method).toBe('capture')
        expect(outcomeOf(sim, holes[5]!, front, 1 / 60, 'back'), method).toBe(null)
      }
      expect(() => solveThrow(sim, { from: DEFAULT_PANEL.launch, hole: holes[5]!, queue: 'first' as 'front' })).toThrow(/request\.queue must be 'back' or 'front', got the string "first"/)
      // behind 99 balls it waits too, but leaves within the 20 s
      expect(solve(100, 5).found, method).toBe(true)
    }
  })
})
