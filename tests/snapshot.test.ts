// Snapshots (src/commands/snapshot.ts): a world restored from a snapshot taken mid-run continues with the
// same events and states, bit for bit, in every contact mode and rim model; bad bytes are refused with a
// message that says what is wrong, and the world they were given to is left as it was.
import { describe, expect, it } from 'vitest'
import { addPanel, createBallPhysics, DEFAULT_PANEL, PHYSICAL_CONFIG, prepareRimTable, SNAPSHOT_VERSION, SnapshotError, TABULATED_CONFIG, type BallPhysics, type ConfigOverrides } from '../src/index.js'
import { checksum } from '../src/commands/snapshotCodec.js'
import { SnapshotError as ecsSnapshotError } from '../src/ecs.js'

function random(seed: number): () => number {
  let s = seed
  return () => {
    s = (s * 16807) % 2147483647
    return (s - 1) / 2147483646
  }
}

/** A busy panel: walls open at the bottom, 300 balls thrown (a few hero balls), run for `steps` frames. */
function busy(config: ConfigOverrides, steps: number): BallPhysics {
  const sim = createBallPhysics(config)
  addPanel(sim)
  sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, open: { bottom: true } })
  const r = random(5)
  for (let i = 0; i < 300; i++) sim.throwBall({ x: 60 + 300 * r(), y: 450 - 30 * r(), power: r(), angle: (r() - 0.5) * 1.2, hero: i % 50 === 3 })
  for (let s = 0; s < steps; s++) sim.step(1 / 60)
  return sim
}

function everything(sim: BallPhysics) {
  return { time: sim.time, balls: sim.balls().map((b) => ({ id: b, ...sim.ballState(b) })), holes: sim.holes().map((h) => sim.holeState(h)) }
}

/** the same bytes, every one */
function same(a: Uint8Array, b: Uint8Array): boolean {
  return a.length === b.length && a.every((x, i) => x === b[i])
}

const MODES: Array<[string, ConfigOverrides]> = [
  ['the design, contacts off', {}],
  ['contacts on (exact)', { BALL_COLLISIONS: 'on' }],
  ['contacts fixed', { BALL_COLLISIONS: 'fixed' }],
  ['PHYSICAL_CONFIG', PHYSICAL_CONFIG],
  ['TABULATED_CONFIG, contacts on', { ...TABULATED_CONFIG, BALL_COLLISIONS: 'on' }],
]

describe('snapshot and restore', () => {
  for (const [name, config] of MODES) {
    it(`${name}: a restored world continues with every event and state bit-identical`, () => {
      const a = busy(config, 25)
      a.drainEvents()
      a.step(1 / 60) // events left undrained: they are part of the state
      const bytes = a.snapshot()
      const b = createBallPhysics(config)
      b.restore(bytes)
      expect(same(b.snapshot(), bytes)).toBe(true)
      expect(everything(b)).toEqual(everything(a))
      for (let s = 0; s < 240; s++) {
        a.step(1 / 60)
        b.step(1 / 60)
        expect(b.drainEvents()).toEqual(a.drainEvents())
      }
      expect(everything(b)).toEqual(everything(a))
      // the run did something after the snapshot
      expect(a.balls().filter((x) => a.ballState(x).mode === 'captured').length).toBeGreaterThan(10)
    })
  }

  /** Commands between steps, from the step's own seed: launcher throws (a hero among them), a ball put
   * down anywhere, a velocity set, a removal. */
  function commands(sim: BallPhysics, step: number): void {
    const r = random(1000 + step)
    if (step % 7 === 0) for (let i = 0; i < 6; i++) sim.throwBall({ ...DEFAULT_PANEL.launch, power: r(), angle: (r() - 0.5) * 1.2, hero: i === 2 })
    if (step % 11 === 0) sim.addBall({ x: 40 + 340 * r(), y: 40 + 400 * r(), vx: (r() - 0.5) * 800, vy: (r() - 0.5) * 800, radius: 6 + 12 * r() })
    const live = sim.balls()
    if (step % 13 === 0 && live.length > 0) {
      const b = live[Math.floor(r() * live.length)]!
      const mode = sim.ballState(b).mode
      if (mode === 'rolling' || mode === 'resting') sim.setBallVelocity(b, (r() - 0.5) * 500, -300 * r())
    }
    if (step % 17 === 0 && live.length > 0) sim.removeBall(live[Math.floor(r() * live.length)]!)
  }

  for (const [name, config] of [...MODES, ['TABULATED_CONFIG, contacts fixed', { ...TABULATED_CONFIG, BALL_COLLISIONS: 'fixed' }]] as Array<[string, ConfigOverrides]>) {
    it(`${name}: a snapshot taken before any of 50 steps of a run with commands, restored and stepped at 240 Hz, gives the 60 Hz run's events and states for 40 steps on`, () => {
      const N = 150
      const M = 40
      const ref = createBallPhysics(config)
      addPanel(ref)
      ref.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 0.8, open: { bottom: true } })
      const snaps: Uint8Array[] = []
      const events: string[] = []
      const states: string[] = []
      let held = 0
      let riding = 0
      for (let k = 0; k < N + M; k++) {
        if (k < N && k % 3 === 0) {
          snaps[k] = ref.snapshot()
          if (ref.heldCount() > 0) held++
          if (ref.balls().some((b) => ref.ballState(b).mode === 'rimRoll')) riding++
        }
        commands(ref, k)
        ref.step(1 / 60)
        events.push(JSON.stringify(ref.drainEvents()))
        states.push(JSON.stringify(everything(ref)))
      }
      // the snapshots caught the states this test is for: balls held at the launcher, balls on a rim
      if (config.BALL_COLLISIONS !== undefined) expect(held).toBeGreaterThan(10)
      // (with the stages and contacts, the launcher lets out few balls in 2.5 s and none was on a rim at a snapshot)
      if (config.BALL_COLLISIONS === undefined || config.RIM_MODEL === 'tabulated') expect(riding).toBeGreaterThan(10)
      for (let k = 0; k < N; k += 3) {
        const b = createBallPhysics(config)
        b.restore(snaps[k]!)
        for (let j = k; j < k + M; j++) {
          commands(b, j)
          const got = []
          for (let q = 0; q < 4; q++) {
            b.step(1 / 240)
            got.push(...b.drainEvents())
          }
          expect(JSON.stringify(got), `snapshot before step ${k}, step ${j}`).toBe(events[j])
          expect(JSON.stringify(everything(b)), `snapshot before step ${k}, step ${j}`).toBe(states[j])
        }
      }
    })
  }

  it('new balls and holes after a restore get the ids the original world would give them', () => {
    const a = busy({ BALL_COLLISIONS: 'on' }, 10)
    for (const x of a.balls().slice(0, 20)) a.removeBall(x)
    const b = createBallPhysics({ BALL_COLLISIONS: 'on' })
    b.restore(a.snapshot())
    expect(b.addBall({ x: 100, y: 100, vx: 10, vy: -300 })).toBe(a.addBall({ x: 100, y: 100, vx: 10, vy: -300 }))
    expect(b.addHole({ x: 1000, y: 1000 })).toBe(a.addHole({ x: 1000, y: 1000 }))
    for (let s = 0; s < 60; s++) {
      a.step(1 / 60)
      b.step(1 / 60)
    }
    expect(b.drainEvents()).toEqual(a.drainEvents())
  })

  it('a ball removed between steps, then a step of one pass: the snapshot restores and runs on the same (every contact mode)', () => {
    // the list of balls the last pass continued outlived the step; a ball the game removed was still named
    // in it, and a step of one pass (nothing to continue) left it there for the snapshot: restore refused
    // it ("the list todo holds 41, which is not a ball")
    for (const config of [{}, { BALL_COLLISIONS: 'on' }, { BALL_COLLISIONS: 'fixed' }] as ConfigOverrides[]) {
      const a = busy(config, 5)
      const r = random(9)
      let restored = 0
      for (let s = 0; s < 40; s++) {
        a.step(1 / 60)
        const live = a.balls().filter((x) => a.ballState(x).mode === 'rolling')
        if (live.length === 0) break
        a.removeBall(live[Math.floor(r() * live.length)]!)
        a.step(1e-9)
        const b = createBallPhysics(config)
        b.restore(a.snapshot())
        restored++
        if (s % 10 === 0) {
          b.step(1 / 60)
          const c = createBallPhysics(config)
          c.restore(a.snapshot())
          c.step(1 / 60)
          expect(everything(b)).toEqual(everything(c))
        }
      }
      expect(restored).toBeGreaterThan(20)
    }
  })

  it('is compact: a 300-ball world in a world made for 1,024 balls takes under 200 kB, and an empty one under 4 kB', () => {
    expect(busy({}, 20).snapshot().length).toBeLessThan(200_000)
    expect(createBallPhysics().snapshot().length).toBeLessThan(4_000)
  })

  describe('bad bytes are refused, and the world is left as it was', () => {
    const good = busy({ BALL_COLLISIONS: 'on' }, 15).snapshot()
    const fresh = createBallPhysics({ BALL_COLLISIONS: 'on' }).snapshot()

    function refused(bytes: unknown, message: RegExp, config: ConfigOverrides = { BALL_COLLISIONS: 'on' }): void {
      const sim = createBallPhysics(config)
      const before = sim.snapshot()
      expect(() => sim.restore(bytes as Uint8Array)).toThrow(message)
      expect(same(sim.snapshot(), before)).toBe(true)
      expect(sim.balls()).toEqual([])
      // and it can still take a good snapshot afterwards
      if (config.BALL_COLLISIONS === 'on' && Object.keys(config).length === 1) {
        sim.restore(good)
        expect(same(sim.snapshot(), good)).toBe(true)
      }
    }

    it('not bytes', () => {
      refused([1, 2, 3], /bytes must be a Uint8Array/)
      refused(null, /bytes must be a Uint8Array/)
    })

    it('not a snapshot', () => {
      refused(new TextEncoder().encode('hello world, not a snapshot'), /not a snapshot/)
      refused(new Uint8Array(0), /end inside the header/)
      // a SnapshotError (a RangeError) that a caller can tell apart, from either entry
      let caught: unknown
      try {
        createBallPhysics().restore(new TextEncoder().encode('hello world, not a snapshot'))
      } catch (e) {
        caught = e
      }
      expect(caught).toBeInstanceOf(SnapshotError)
      expect(caught).toBeInstanceOf(RangeError)
      expect((caught as Error).name).toBe('SnapshotError')
      expect(String(caught)).toMatch(/^SnapshotError: restore: these bytes are not a snapshot/)
      expect(SnapshotError).toBe(ecsSnapshotError)
    })

    it('truncated anywhere', () => {
      const r = random(3)
      for (let k = 0; k < 40; k++) {
        const cut = 1 + Math.floor(r() * (good.length - 2))
        refused(good.slice(0, cut), /truncated|end inside/)
      }
    })

    it('a changed byte (the checksum)', () => {
      for (const at of [20, Math.floor(good.length / 2), good.length - 5]) {
        const bad = good.slice()
        bad[at] = bad[at]! ^ 0x10
        refused(bad, /checksum|config|malformed|truncated/)
      }
      const bad = good.slice()
      bad[Math.floor(good.length / 2)] ^= 1
      refused(bad, /checksum mismatch/)
    })

    it('a changed byte anywhere after the format version is reported as a changed or cut snapshot, never as another config or a malformed body', () => {
      // bytes 0–3 ("PBSN") and 4–5 (the format version) are read first by design: a change there says the
      // bytes are not a snapshot, or of another version. Every later byte, config included, is covered by
      // the lengths and the checksum, checked before anything else is read.
      const small = (() => {
        const sim = createBallPhysics({ BALL_COLLISIONS: 'on' }, { capacity: 4 })
        sim.addHole({ x: 100, y: 100 })
        sim.addBall({ x: 100, y: 300, vx: 0, vy: -200 })
        sim.step(1 / 60)
        return sim.snapshot()
      })()
      const corrupt = /checksum mismatch|\(truncated, padded or altered\)|\(truncated or altered\)/
      const heads: string[] = []
      const wrong: string[] = []
      const target = createBallPhysics({ BALL_COLLISIONS: 'on' }, { capacity: 4 }) // a refused restore changes nothing
      for (let at = 0; at < small.length; at++) {
        for (const flip of [1, 0x80]) {
          const bad = small.slice()
          bad[at] ^= flip
          let message = ''
          try {
            target.restore(bad)
          } catch (e) {
            message = (e as Error).message
          }
          if (at < 6) heads.push(message)
          else if (!corrupt.test(message)) wrong.push(`byte ${at} ^ ${flip}: ${message}`)
        }
      }
      expect(wrong).toEqual([])
      expect(target.balls()).toEqual([])
      target.restore(small)
      expect(same(target.snapshot(), small)).toBe(true)
      expect(heads.slice(0, 8).every((m) => /not a snapshot/.test(m))).toBe(true)
      expect(heads.slice(8).every((m) => /format version/.test(m))).toBe(true)
      // the reported case: a byte of the config changed
      const bad = good.slice()
      bad[100] ^= 1
      refused(bad, /checksum mismatch/)
    })

    it('another format version', () => {
      const bad = good.slice()
      new DataView(bad.buffer).setUint16(4, SNAPSHOT_VERSION + 1, true)
      refused(bad, new RegExp(`format version ${SNAPSHOT_VERSION + 1}; this module reads version ${SNAPSHOT_VERSION}`))
    })

    it('another config, naming the setting that differs', () => {
      refused(good, /another config \(BALL_COLLISIONS: the snapshot's is "on", this world's "off"\)/, {})
      refused(good, /another config \(BALL_RESTITUTION/, { BALL_COLLISIONS: 'on', BALL_RESTITUTION: 0.5 })
    })

    it('a world that already has entities', () => {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'on' })
      sim.addHole({ x: 10, y: 10 })
      const before = sim.snapshot()
      expect(() => sim.restore(good)).toThrow(/the world has had entities/)
      expect(same(sim.snapshot(), before)).toBe(true)
    })

    it('a world whose entities were all removed: the message says why emptying it does not do', () => {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'on' })
      sim.removeHole(sim.addHole({ x: 10, y: 10 }))
      sim.removeBall(sim.addBall({ x: 100, y: 100 }))
      expect(sim.balls().length + sim.holes().length).toBe(0)
      expect(() => sim.restore(good)).toThrow(/the world has had entities \(bitECS has handed out ids up to \d+, removed or not\), and a snapshot restores the ids too/)
    })

    it('the tick-sampled comparison methods, whose sub-step state is outside the world', () => {
      for (const METHOD of ['naive', 'v1'] as const) {
        const sim = createBallPhysics({ METHOD })
        sim.addBall({ x: 0, y: 0, vx: 10, vy: 0 })
        sim.step(1 / 60)
        expect(() => sim.snapshot()).toThrow(new RegExp(`snapshots need METHOD 'exact'; this world runs '${METHOD}'`))
        expect(() => createBallPhysics({ METHOD }).restore(good)).toThrow(/snapshots need METHOD 'exact'/)
      }
    })

    it('an empty world restores an empty world', () => {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'on' })
      sim.restore(fresh)
      expect(same(sim.snapshot(), fresh)).toBe(true)
    })
  })
})

describe('snapshots and recordings inside a drainEventsWith callback', () => {
  // the events the callback had been handed were still in the buffer, and so was the drain's flag: a world
  // restored from such a snapshot refused every drain, and handed the same captures out again once it could
  it('are refused, and the world drains as usual after the callback', () => {
    const sim = createBallPhysics()
    addPanel(sim)
    for (let i = 0; i < 20; i++) sim.throwBall({ x: 150 + 6 * i, y: 450, power: 0.4, angle: 0.2 - 0.02 * i })
    const errors: string[] = []
    let captures = 0
    for (let f = 0; f < 240 && captures === 0; f++) {
      sim.step(1 / 60)
      sim.drainEventsWith((e) => {
        if (e.type !== 'capture') return
        captures++
        for (const call of [() => sim.snapshot(), () => sim.startRecording()]) {
          try {
            call()
          } catch (err) {
            errors.push((err as Error).message)
          }
        }
      })
    }
    expect(captures).toBeGreaterThan(0)
    expect(errors.length).toBe(2 * captures)
    expect(errors[0]).toMatch(/snapshot \(snapshotWorld\): called from a drainEventsWith callback/)
    expect(errors[1]).toMatch(/startRecording \(startReplay\): called from a drainEventsWith callback/)
    // after the callback: a snapshot restores into a world that drains, and hands out nothing twice
    const copy = createBallPhysics(sim.config)
    copy.restore(sim.snapshot())
    expect(copy.drainEvents()).toEqual([])
    sim.step(1 / 60)
    copy.step(1 / 60)
    expect(copy.drainEvents()).toEqual(sim.drainEvents())
  })
})

describe('bytes changed on purpose (the checksum recomputed)', () => {
  // the checksum catches accidents; a moving set naming an id that is not a ball once made a world whose
  // fourth step never returned
  it('a moving set, an event list or the launcher queue naming what is not a ball, or a ball with no mode, is refused', () => {
    const src = createBallPhysics({ BALL_COLLISIONS: 'on' })
    addPanel(src)
    for (let i = 0; i < 40; i++) src.throwBall({ x: 60 + 7 * i, y: 450 - (i % 5) * 6, power: 0.2 + 0.02 * i, angle: -0.6 + 0.03 * i })
    for (let i = 0; i < 20; i++) src.step(1 / 60)
    const moving = src.world.moving
    expect(moving.count).toBeGreaterThan(3)
    const bytes = src.snapshot()
    const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength)
    const want = Array.from(moving.dense.subarray(0, moving.count))
    let at = -1
    for (let i = 0; i + 4 * want.length <= bytes.length && at < 0; i++) if (want.every((v, k) => dv.getUint32(i + 4 * k, true) === v)) at = i
    expect(at).toBeGreaterThan(0)
    const altered = (edit: (v: DataView) => void): Uint8Array => {
      const b = bytes.slice()
      const v = new DataView(b.buffer)
      edit(v)
      v.setUint32(b.length - 4, checksum(b, b.length - 4), true)
      return b
    }
    const last = at + 4 * (want.length - 1)
    for (const id of [want[want.length - 1]! + 200, 0, src.holes()[0]!]) {
      const w = createBallPhysics({ BALL_COLLISIONS: 'on' })
      expect(() => w.restore(altered((v) => v.setUint32(last, id, true)))).toThrow(/restore: the moving set lists \d+, which is not a ball of it/)
      expect(w.balls()).toEqual([])
    }
    // the same ball twice
    const twice = createBallPhysics({ BALL_COLLISIONS: 'on' })
    expect(() => twice.restore(altered((v) => v.setUint32(last, want[0]!, true)))).toThrow(/moving set lists/)
    // unchanged bytes still restore
    createBallPhysics({ BALL_COLLISIONS: 'on' }).restore(bytes)
  })
})

describe('rim tables in a snapshot', () => {
  it('a table prepared for any geometry prepareRimTable takes restores (R/r 1e7 was refused as malformed bytes); one outside it is refused by name', () => {
    const src = createBallPhysics(TABULATED_CONFIG)
    prepareRimTable(src, 1e4, 1e-3, { rows: 'lazy' })
    const bytes = src.snapshot()
    const dst = createBallPhysics(TABULATED_CONFIG)
    dst.restore(bytes)
    expect(dst.world.rimTables.map((t) => t.ratio)).toEqual([18 / 11, 1e7])
    // the ratio 1e7 written as 1.05 (no table is built that close to the hole's size), the checksum recomputed
    const b = bytes.slice()
    const v = new DataView(b.buffer)
    let at = -1
    for (let i = 0; i + 8 <= b.length && at < 0; i++) if (v.getFloat64(i, true) === 1e7) at = i
    expect(at).toBeGreaterThan(0)
    v.setFloat64(at, 1.05, true)
    v.setUint32(b.length - 4, checksum(b, b.length - 4), true)
    expect(() => createBallPhysics(TABULATED_CONFIG).restore(b)).toThrow(/restore: rim table 1\.05:0\.4 outside the geometry a table can have \(R\/r in \[1\.08, 100000000\]/)
  })
})
