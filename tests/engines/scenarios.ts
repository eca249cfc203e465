// Scenarios whose every bit must come out the same in every JavaScript engine (tests/engines.test.ts runs
// them in Node's V8, Bun's JavaScriptCore and the SpiderMonkey shell and compares the hashes).
//
// Each scenario throws 1,000 balls at the default panel from its launch point, with powers and aims drawn
// from a fixed-seed generator, a few of them hero balls (the live rigid-sphere reference: an ODE solver,
// sin, cos, atan2, pow), and steps 1/60 s frames until every ball is captured, out or at rest, or 20 s.
// The hash covers every event (type, ids, and the bits of every number) and, at the end, every ball's
// position, velocity and mode, and the snapshot of the final world is hashed too. Plain arithmetic only: no Math function that engines may round differently.
import {
  addPanel,
  BALL_MODE_NAMES,
  createBallPhysics,
  createReplayPlayer,
  DEFAULT_PANEL,
  replayFromJSON,
  replayToJSON,
  PHYSICAL_CONFIG,
  TABULATED_CONFIG,
  type ConfigOverrides,
  type EventView,
} from '../../src/index.js'

export interface ScenarioResult {
  /** 64-bit FNV-1a hash of the event stream and the final state, as 16 hex digits */
  hash: string
  events: number
  steps: number
  captured: number
  /** hash and length of the final world's snapshot */
  snapshot: string
  snapshotBytes: number
}

export const SCENARIOS: Readonly<Record<string, ConfigOverrides>> = {
  design: {},
  physical: PHYSICAL_CONFIG,
  tabulated: TABULATED_CONFIG,
  contactsExact: { BALL_COLLISIONS: 'on' },
  contactsFixed: { BALL_COLLISIONS: 'fixed' },
  // masses 1e-3 to 1e6 among the throws: the solve's mass-ratio rules (a light ball squeezed, solved with a
  // wall, met again past its restitution with heavier ones, its contacts counted)
  contactsFixedMasses: { BALL_COLLISIONS: 'fixed' },
}

/** each throw's mass in a scenario of unlike masses (undefined: the default) */
const MASSES: Readonly<Record<string, readonly (number | undefined)[]>> = {
  contactsFixedMasses: [1e6, 1e-3, undefined, 1e3, 1e-3, 1, 1e-3, 30],
}

const LITTLE = new Uint8Array(new Uint16Array([1]).buffer)[0] === 1

/** FNV-1a over 32-bit words, kept as two 32-bit halves (no BigInt: the same in every engine) */
export class Hash {
  private lo = 0x84222325
  private hi = 0xcbf29ce4
  private readonly f = new Float64Array(1)
  private readonly u = new Uint32Array(this.f.buffer)

  word(v: number): void {
    // h ^= v; h *= 0x100000001b3 (mod 2^64), in 16-bit limbs so every product is exact
    let lo = (this.lo ^ v) >>> 0
    let hi = this.hi
    const l0 = lo & 0xffff
    const l1 = lo >>> 16
    const h0 = hi & 0xffff
    const h1 = hi >>> 16
    // prime = 0x100_000001b3: low 32 bits 0x000001b3, high 32 bits 0x00000100
    const p0 = 0x1b3
    let c0 = l0 * p0
    let c1 = l1 * p0 + (c0 >>> 16)
    let c2 = h0 * p0 + (c1 >>> 16) + l0 * 0x100
    let c3 = h1 * p0 + (c2 >>> 16) + l1 * 0x100
    lo = ((c1 & 0xffff) << 16) | (c0 & 0xffff)
    hi = ((c3 & 0xffff) << 16) | (c2 & 0xffff)
    this.lo = lo >>> 0
    this.hi = hi >>> 0
  }

  num(x: number): void {
    this.f[0] = x
    // the same word order on every host: the low word of the float first
    this.word(this.u[LITTLE ? 0 : 1]!)
    this.word(this.u[LITTLE ? 1 : 0]!)
  }

  hex(): string {
    return this.hi.toString(16).padStart(8, '0') + this.lo.toString(16).padStart(8, '0')
  }
}

/** A visitor that hashes every field of an event */
export function eventHasher(h: Hash): (e: EventView) => void {
  return (e) => {
    h.word(e.code)
    h.word(e.ball)
    h.word(e.hole)
    h.word(e.other)
    h.num(e.time)
    h.num(e.delta)
    h.num(e.speed)
    h.num(e.impulse)
  }
}

/**
 * A recorded session for the replay check: contacts on, walls, 300 throws over the first second, a few
 * velocity changes, a removal, a hole added and one removed, 4 s in all. Returns the replay's JSON and
 * the hash of every event of the recorded run.
 */
export function recordSession(): { text: string; hash: string; events: number } {
  const sim = createBallPhysics({ BALL_COLLISIONS: 'on' })
  sim.startRecording()
  addPanel(sim)
  sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480, restitution: 0.7, open: { bottom: true } })
  const r = random(4242)
  const h = new Hash()
  const visit = eventHasher(h)
  let events = 0
  for (let step = 0; step < 240; step++) {
    if (step < 60) for (let k = 0; k < 5; k++) sim.throwBall({ x: 60 + 300 * r(), y: 450 - 30 * r(), power: r(), angle: (r() - 0.5) * 1.2, hero: k === 0 && step % 20 === 0 })
    if (step === 30) {
      for (const b of sim.balls().slice(0, 10)) if (sim.ballState(b).mode === 'rolling') sim.setBallVelocity(b, -0, -200 * r())
    }
    if (step === 45) sim.removeBall(sim.balls()[3]!)
    if (step === 50) sim.addHole({ x: 30, y: 30, radius: 12 })
    if (step === 90) sim.removeHole(sim.holes()[7]!)
    sim.step(1 / 60)
    events += sim.drainEventsWith((e) => visit(e))
  }
  return { text: replayToJSON(sim.stopRecording()), hash: h.hex(), events }
}

/** Plays a replay's JSON and hashes every event, as recordSession did */
export function playSession(text: string): { hash: string; events: number } {
  const p = createReplayPlayer(replayFromJSON(text))
  const h = new Hash()
  const visit = eventHasher(h)
  let events = 0
  while (p.next()) events += p.sim.drainEventsWith((e) => visit(e))
  return { hash: h.hex(), events }
}

function random(seed: number): () => number {
  let s = seed
  return () => {
    s = (s * 16807) % 2147483647
    return (s - 1) / 2147483646
  }
}

export function runScenario(name: string, balls = 1000, seconds = 20): ScenarioResult {
  const config = SCENARIOS[name]
  if (config === undefined) throw new RangeError(`runScenario: unknown scenario ${name}`)
  const sim = createBallPhysics(config, { capacity: balls + 64 })
  addPanel(sim)
  const { x, y } = DEFAULT_PANEL.launch
  const r = random(20261123)
  for (let i = 0; i < balls; i++) {
    // spread across the launch band: the launch point ± 150 px, so throws do not start inside each other
    const masses = MASSES[name]
    sim.throwBall({ x: x - 150 + 300 * r(), y: y - 30 * r(), power: r(), angle: (r() - 0.5) * 1.2, hero: i % 100 === 7, mass: masses?.[i % masses.length] })
  }
  const h = new Hash()
  let events = 0
  const hashEvent = eventHasher(h)
  const visit = (e: EventView): void => {
    events++
    hashEvent(e)
  }
  let steps = 0
  const ids = sim.balls()
  for (; steps < seconds * 60; steps++) {
    sim.step(1 / 60)
    sim.drainEventsWith(visit)
    let moving = 0
    for (const b of ids) {
      const m = sim.ballState(b).mode
      if (m === 'rolling' || m === 'rimRoll') moving++
    }
    if (moving === 0) break
  }
  let captured = 0
  for (const b of ids) {
    const s = sim.ballState(b)
    if (s.mode === 'captured') captured++
    h.num(s.x)
    h.num(s.y)
    h.num(s.vx)
    h.num(s.vy)
    h.word(BALL_MODE_NAMES.indexOf(s.mode))
  }
  // the snapshot of the final world: the same bytes in every engine
  const bytes = sim.snapshot()
  const hs = new Hash()
  for (let i = 0; i + 4 <= bytes.length; i += 4) hs.word((bytes[i]! | (bytes[i + 1]! << 8) | (bytes[i + 2]! << 16) | (bytes[i + 3]! << 24)) >>> 0)
  for (let i = bytes.length & ~3; i < bytes.length; i++) hs.word(bytes[i]!)
  return { hash: h.hex(), events, steps, captured, snapshot: hs.hex(), snapshotBytes: bytes.length }
}

export function runAll(balls?: number): Record<string, ScenarioResult> {
  const out: Record<string, ScenarioResult> = {}
  for (const name of Object.keys(SCENARIOS)) out[name] = runScenario(name, balls)
  return out
}
