// Reading events: drainEvents (objects) and drainEventsWith (one reused view, nothing allocated).
import { readdirSync, readFileSync, statSync } from 'node:fs'
import { join, relative, resolve } from 'node:path'
import { PerformanceObserver } from 'node:perf_hooks'
import { describe, expect, it } from 'vitest'
import { DEFAULT_PANEL, addPanel, createBallPhysics, type BallEvent, type BallPhysics, type EventView } from '../src/index'
import { EventType, pushEvent } from '../src/ecs'

/** The default panel with walls open at the bottom and `n` balls thrown at once from the launch band. */
function burst(n: number, contacts: 'off' | 'fixed' = 'fixed'): BallPhysics {
  const sim = createBallPhysics({ BALL_COLLISIONS: contacts })
  addPanel(sim, DEFAULT_PANEL)
  for (let i = 0; i < n; i++) {
    sim.addBall({ x: 30 + 36 * (i % 10), y: 440 - 24 * Math.floor(i / 10), vx: 40 * Math.sin(i), vy: -250 - (i % 7) * 60 })
  }
  return sim
}

/** The view as the object drainEvents gives for the same event. */
function asEvent(e: EventView): BallEvent {
  const out: Record<string, unknown> = { type: e.type, ball: e.ball, time: e.time }
  if (e.code === EventType.Collision) return { ...out, other: e.other, speed: e.speed, impulse: e.impulse } as BallEvent
  if (e.hole !== 0) out.hole = e.hole
  if (e.hasLip) {
    out.delta = e.delta
    out.speed = e.speed
  }
  if (e.via !== undefined) out.via = e.via
  return out as unknown as BallEvent
}

describe('drainEventsWith', () => {
  it('gives the events drainEvents gives, in the same order (time, then ball id), with every field', () => {
    const a = burst(120)
    const b = burst(120)
    const kinds = new Set<string>()
    for (let i = 0; i < 90; i++) {
      a.step(1 / 60)
      b.step(1 / 60)
      const objects = a.drainEvents()
      const viewed: BallEvent[] = []
      expect(b.drainEventsWith((e) => viewed.push(asEvent(e)))).toBe(objects.length)
      expect(viewed).toEqual(objects)
      for (let k = 1; k < objects.length; k++) {
        const p = objects[k - 1]!
        const q = objects[k]!
        expect(p.time < q.time || (p.time === q.time && p.ball <= q.ball)).toBe(true)
      }
      for (const e of objects) kinds.add(e.type)
    }
    for (const k of ['collision', 'capture', 'skip', 'nearMiss', 'rest']) expect(kinds.has(k), k).toBe(true)
  })

  it('lets the callback remove the ball it is told was captured, and step: nothing is lost or reported twice', () => {
    const a = burst(120)
    const b = burst(120)
    const seenA: BallEvent[] = []
    const seenB: BallEvent[] = []
    for (let i = 0; i < 90; i++) {
      a.step(1 / 60)
      for (const e of a.drainEvents()) {
        seenA.push(e)
        if (e.type === 'capture') a.removeBall(e.ball)
      }
      b.step(1 / 60)
      b.drainEventsWith((e) => {
        seenB.push(asEvent(e))
        if (e.type === 'capture') b.removeBall(e.ball)
      })
    }
    expect(seenB).toEqual(seenA)
    expect(seenA.filter((e) => e.type === 'capture').length).toBeGreaterThan(5)
    expect(b.balls()).toEqual(a.balls())

    // stepping from the callback: that step's events wait for the next drain
    const c = burst(60)
    const d = burst(60)
    c.step(1 / 60)
    d.step(1 / 60)
    const first = c.drainEvents()
    const viewed: BallEvent[] = []
    d.drainEventsWith((e) => {
      if (viewed.length === 0) d.step(1 / 60)
      viewed.push(asEvent(e))
    })
    expect(viewed).toEqual(first)
    c.step(1 / 60)
    expect(d.drainEvents()).toEqual(c.drainEvents())
  })

  it('gives no event, after the callback removes an entity, that names it: not even when a new ball has its id', () => {
    for (const contacts of ['on', 'fixed'] as const) {
      // a comes to rest at t = 0.1 s; b strikes it later in the same step
      const sim = createBallPhysics({ BALL_COLLISIONS: contacts, ROLLING_DECEL: 300 })
      const a = sim.addBall({ x: 100, y: 100, vx: 30, vy: 0 })
      const b = sim.addBall({ x: 0, y: 100, vx: 400, vy: 0 })
      const twin = createBallPhysics({ BALL_COLLISIONS: contacts, ROLLING_DECEL: 300 })
      twin.addBall({ x: 100, y: 100, vx: 30, vy: 0 })
      twin.addBall({ x: 0, y: 100, vx: 400, vy: 0 })
      sim.step(0.5)
      twin.step(0.5)
      const all = twin.drainEvents()
      expect(all.map((e) => e.type)).toEqual(['rest', 'collision']) // without a removal, the collision is given
      const seen: BallEvent[] = []
      let added = 0
      const passed = sim.drainEventsWith((e) => {
        seen.push(asEvent(e))
        if (e.type === 'rest' && e.ball === a) {
          sim.removeBall(a)
          added = sim.addBall({ x: 300, y: 300, vx: 0, vy: 0 }) // bitECS hands the id straight back
        }
      })
      expect(added).toBe(a)
      expect(seen).toEqual([all[0]])
      expect(passed).toBe(1)
      // the marks are cleared: the next drains give the new ball's events and the struck ball's
      sim.setBallVelocity(added, 50, 0)
      sim.step(0.5)
      const next: BallEvent[] = []
      sim.drainEventsWith((e) => next.push(asEvent(e)))
      expect(next.some((e) => e.ball === added && e.type === 'rest')).toBe(true)
      expect(next.some((e) => e.ball === b)).toBe(true)
    }
  })

  it('refuses a drain from its callback, and a callback that is not a function; a callback that throws ends the drain', () => {
    const sim = burst(40)
    sim.step(0.5)
    const thrower = burst(40)
    thrower.step(0.5)
    let seen = 0
    expect(() =>
      thrower.drainEventsWith(() => {
        if (++seen === 2) throw new Error('game code failed')
      }),
    ).toThrow('game code failed')
    expect(seen).toBe(2)
    expect(thrower.drainEvents()).toEqual([]) // the rest went with the drain
    thrower.step(1 / 60)
    expect(() => thrower.drainEventsWith(() => {})).not.toThrow() // and the buffer is usable again
    expect(() => sim.drainEventsWith(() => sim.drainEvents())).toThrow(/drainEvents: called from a drainEventsWith callback/)
    expect(() => sim.drainEventsWith(null as never)).toThrow(TypeError)
    expect(() => sim.drainEventsWith(null as never)).toThrow(/visit must be a function/)
  })

  it('allocates nothing: draining 400,000 events runs no garbage collection (drainEvents runs several)', async () => {
    const sim = createBallPhysics()
    const ids: number[] = []
    for (let i = 0; i < 97; i++) ids.push(sim.addBall({ x: 20 + 30 * (i % 10), y: 20 + 30 * Math.floor(i / 10) }))
    sim.drainEvents()
    // a system of the game's pushes them in a step, at times spread over the step's window, out of order
    let pushing = false
    sim.schedule.push({
      name: 'pusher',
      run: (w) => {
        if (!pushing || w.pass !== 0) return
        const span = w.tickEnd - w.time
        for (let i = 0; i < 400_000; i++) pushEvent(w.events, EventType.Skip, ids[i % 97]!, 0, w.time + (((i * 7919) % 1000) / 1000) * span, true, 3, 400)
      },
    })
    const fill = () => {
      pushing = true
      sim.step(1 / 60)
      pushing = false
    }
    const gcsDuring = async (drain: () => void): Promise<number> => {
      let count = 0
      const obs = new PerformanceObserver((list) => {
        count += list.getEntries().length
      })
      fill()
      await new Promise((r) => setTimeout(r, 20)) // earlier collections reported before the count starts
      obs.observe({ entryTypes: ['gc'] })
      drain()
      await new Promise((r) => setTimeout(r, 20))
      obs.disconnect()
      return count
    }
    const kept = new Float64Array(2)
    // once to grow the buffer's order arrays, then measured
    await gcsDuring(() => sim.drainEventsWith(() => {}))
    const viewGcs = await gcsDuring(() => {
      sim.drainEventsWith((e) => {
        kept[0] += e.time
        kept[1] += e.speed
      })
    })
    let objects = 0
    const objectGcs = await gcsDuring(() => {
      objects = sim.drainEvents().length
    })
    expect(objects).toBe(400_000)
    expect(kept[1]).toBe(400 * 400_000)
    expect(viewGcs).toBe(0)
    expect(objectGcs).toBeGreaterThan(0)
  })
})

// appendEvent and appendCollision may grow the buffer, which replaces its arrays: in
// `w.events.time[appendEvent(w.events, …)] = t` the old time array is taken before the call, so the event
// that grew the buffer kept time 0 (found by the long adversarial run; named tests in adversarial.test.ts)
describe('event buffer writes', () => {
  const root = resolve(import.meta.dirname, '..')
  const files = (dir: string): string[] =>
    readdirSync(dir).flatMap((name) => {
      const p = join(dir, name)
      return statSync(p).isDirectory() ? files(p) : p.endsWith('.ts') ? [p] : []
    })
  /** Lines that index an array with the append call itself, as "line: code". */
  const offences = (text: string): string[] =>
    text.split('\n').flatMap((line, i) => (/\[\s*append(Event|Collision)\(/.test(line) ? [`${i + 1}: ${line.trim()}`] : []))

  it('no file of the simulation writes an event field through an array read before the append (the append may grow the buffer)', () => {
    const bad: string[] = []
    for (const dir of ['src', 'systems']) for (const f of files(join(root, dir))) for (const o of offences(readFileSync(f, 'utf8'))) bad.push(`${relative(root, f)}:${o}`)
    expect(bad).toEqual([])
    expect(offences('w.events.time[appendEvent(w.events, EventType.Wall, e, 0, false)] = t')).toHaveLength(1)
    expect(offences('const i = appendEvent(w.events, EventType.Wall, e, 0, false)\nw.events.time[i] = t')).toEqual([])
  })
})

describe('events by kind', () => {
  // every drained event has exactly the fields of its kind's type (src/eventTypes.ts), so a check of
  // `type` narrows them: a capture its hole and via, a collision its other ball, speed and impulse
  it('each kind has the fields its type says, and no others', () => {
    const allowed: Record<string, { must: string[]; may: string[] }> = {
      capture: { must: ['type', 'ball', 'time', 'hole', 'via'], may: ['delta', 'speed'] },
      collision: { must: ['type', 'ball', 'time', 'other', 'speed', 'impulse'], may: [] },
      rest: { must: ['type', 'ball', 'time'], may: [] },
      wall: { must: ['type', 'ball', 'time'], may: [] },
      gutter: { must: ['type', 'ball', 'time'], may: [] },
    }
    for (const t of ['skip', 'bounce', 'rimRoll', 'lipOut', 'nearMiss']) allowed[t] = { must: ['type', 'ball', 'time', 'hole'], may: ['delta', 'speed'] }
    const sim = createBallPhysics({ BALL_COLLISIONS: 'on' })
    addPanel(sim, DEFAULT_PANEL)
    sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 0.5, open: { bottom: true } })
    for (let i = 0; i < 200; i++) sim.throwBall({ x: 20 + 1.9 * i, y: 450, power: (i * 0.618) % 1, angle: ((i * 0.377) % 1) - 0.5 })
    const seen = new Set<string>()
    for (let f = 0; f < 600; f++) {
      sim.step(1 / 60)
      for (const e of sim.drainEvents()) {
        const keys = Object.keys(e)
        const a = allowed[e.type]!
        for (const k of a.must) expect(keys, e.type).toContain(k)
        for (const k of keys) expect([...a.must, ...a.may], `${e.type}.${k}`).toContain(k)
        seen.add(e.type)
      }
    }
    expect([...seen].sort()).toEqual(expect.arrayContaining(['bounce', 'capture', 'collision', 'nearMiss', 'rest', 'skip', 'wall']))
  })
})
