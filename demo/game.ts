// The game and its clock, without any drawing: one simulation of the built-in panel, the player's ten
// balls and score, the multi-ball bursts and the stress mode, a 120 Hz fixed-step loop with render
// interpolation, and the per-frame event feed. Everything that changes the physics goes through the
// public API (createBallPhysics, addPanel, throwBall, step, drainEvents, removeBall); the world's typed
// arrays are only read.
// Rounds: a throw or burst on a quiet panel starts recording a replay (sim.startRecording), and the
// panel falling quiet again ends it; "Replay" plays the last round back on a world of its own, step for
// step at the same 120 Hz, and then the live game resumes where it was. The demo's own per-ball state (whose ball, when it stopped) is a bitECS
// component of its own, DemoBall, on the simulation's ball entities: its balls are query([Ball, DemoBall]).
import { addComponent, hasComponent, query } from 'bitecs'
import { BALL_MODE_NAMES, DEFAULT_PANEL, EVENT_TYPE_NAMES, MIN_OUTCOME_STEP, addPanel, createBallPhysics, createFixedStepClock, createReplayPlayer, mulberry32, resolveConfig, solveThrow, type ThrowFailure, type ThrowSolution, type BallEvent, type BallPhysics, type BallPhysicsConfig, type ConfigOverrides, type FixedStepClock, type PanelLayout, type Replay, type ReplayPlayer } from '../src/index'
import { BallMode } from '../src/ecs'
import type { ThrowRequest } from './input'
import type { ShotCall } from './shotCall'
import { isHoleEvent } from './theme'

/** Mode code of a ball that left the panel through an open wall edge (-1 if the core has no such mode). */
const MODE_OUT = (BALL_MODE_NAMES as readonly string[]).indexOf('out')

/** Physics rate, Hz, and the most steps run for one displayed frame (the catch-up cap). */
export const PHYSICS_HZ = 120
export const MAX_STEPS_PER_FRAME = 8
/** the largest ball the demo draws (its static layer, the launch pad included, is cached as one texture) */
export const MAX_DEMO_RADIUS = 100
/** A frame longer than this (a tab that slept) counts as this long, s. */
export const MAX_FRAME_SECONDS = 0.25
export const BALLS_PER_GAME = 10
export const STRESS_BALLS = 10_000

export const Kind = { None: 0, Player: 1, Burst: 2, Stress: 3 } as const
export type KindCode = (typeof Kind)[keyof typeof Kind]

/** How long a resting ball stays before it fades out and is removed (it went back to the tray), s. */
export const REST_HOLD = 0.9
export const REST_FADE = 0.6
const STRESS_REST_HOLD = 0.25
const STRESS_CAPTURE_HOLD = 0.6
/** The least power of a ball a burst throws from the launch point. */
const LAUNCHER_MIN_POWER = 0.35
/** How long a burst's captured ball stays in its hole before it is taken out, s (burst after burst filled the holes with thousands of balls to draw). */
const BURST_CAPTURE_HOLD = 1.5

/** An event as the demo shows it: the core's event plus where and whose. */
export type DemoEvent = BallEvent & {
  /** index of the hole in the panel layout, -1 for none */
  holeIndex: number
  /** points of the hole (0 for none) */
  value: number
  /** the ball was one of the player's throws */
  player: boolean
}

export interface FrameResult {
  events: DemoEvent[]
  steps: number
  /** wall time spent in sim.step this frame, ms */
  physicsMs: number
}

export type Validation = { ok: true; config: Readonly<BallPhysicsConfig> } | { ok: false; error: string }

/** The walls spec. */
type WallsSpec = Parameters<BallPhysics['setWalls']>[0]

/** The demo's component on its balls: which kind of ball, and the demo time it stopped (0 while it moves). */
export interface DemoBallStore {
  kind: Uint8Array
  doneAt: Float64Array
}

/** Rails on the left, top and right of the panel; the bottom edge is open (the gutter below the launch). */
export function wallsFor(panel: Readonly<PanelLayout>): WallsSpec {
  return { minX: 0, minY: 0, maxX: panel.width, maxY: panel.height, restitution: 0.5, open: { bottom: true } }
}

function grow<T extends Float64Array | Uint8Array | Int32Array>(a: T, n: number, fill = 0): T {
  if (a.length >= n) return a
  let cap = Math.max(1024, a.length)
  while (cap < n) cap *= 2
  const next = new (a.constructor as new (n: number) => T)(cap)
  if (fill !== 0) next.fill(fill)
  next.set(a)
  return next
}

export class Game {
  readonly panel: Readonly<PanelLayout> = DEFAULT_PANEL
  sim: BallPhysics
  /** hole ids in layout order */
  holes: number[] = []
  /** bumped whenever the simulation is recreated (views rebuild what depends on the config) */
  generation = 0
  /** overrides of the running simulation, and the validated ones waiting for the next throw */
  overrides: ConfigOverrides = {}
  pending: ConfigOverrides | null = null
  readonly clock: FixedStepClock = createFixedStepClock({ hz: PHYSICS_HZ, maxStepsPerFrame: MAX_STEPS_PER_FRAME })
  /** demo time, s (wall time of the frames, after the frame cap) */
  time = 0

  // per entity id; positions at the start of the last step, for interpolation
  prevX = new Float64Array(1024)
  prevY = new Float64Array(1024)
  /** the demo's component (indexed by entity id, grown as ids grow) */
  readonly DemoBall: DemoBallStore = { kind: new Uint8Array(1024), doneAt: new Float64Array(1024) }
  private holeIndexById = new Map<number, number>()

  score = 0
  ballsLeft = BALLS_PER_GAME
  /** captures of the player's balls per hole (layout order), this game */
  gameCaptures: number[] = []
  /** events seen this game (a new game starts them at 0), and by type */
  eventsSeen = 0
  readonly eventCounts: Record<string, number> = Object.fromEntries(EVENT_TYPE_NAMES.map((t) => [t, 0]))
  /** the last events (newest last), for the log and the test hook */
  readonly recent: DemoEvent[] = []
  throwsMade = 0
  lastThrow: (ThrowRequest & { speed: number }) | null = null
  stressTarget = 0
  /**
   * Where the multi-ball bursts come from: spread along the bottom edge, or all from the launch point (an
   * arcade launcher: with contacts on, the balls leave it one after another as each clears the spot)
   */
  burstFrom: 'edge' | 'launcher' = 'edge'
  private stressLive = 0
  private playerMoving = 0
  private random = mulberry32(0x5eed)

  /** the last finished round, and the kinds of its balls by id */
  lastRound: Replay | null = null
  private lastRoundKinds = new Map<number, number>()
  /** a round being recorded: the kinds of its balls by id */
  private roundKinds: Map<number, number> | null = null
  /** while a round plays back: the player, the live game set aside, and the round's events so far */
  replaying: { player: ReplayPlayer; live: BallPhysics; kinds: Map<number, number>; kind: Uint8Array; doneAt: Float64Array } | null = null
  /** (type, ball, time) of every event of the last recorded round, and of the last replay, for checks */
  roundEvents: Array<[string, number, number]> = []
  replayEvents: Array<[string, number, number]> = []
  private recordingEvents: Array<[string, number, number]> = []
  /** rounds finished since the page loaded */
  roundsRecorded = 0

  constructor(overrides: ConfigOverrides = {}) {
    this.overrides = { ...overrides }
    this.sim = this.rebuild()
  }

  get config(): Readonly<BallPhysicsConfig> {
    return this.sim.config
  }

  /** The demo's live balls: the entities with Ball and DemoBall (a live array: read it, don't keep it). */
  get live(): readonly number[] {
    const w = this.sim.world
    return query(w, [w.Ball, this.DemoBall]) as readonly number[]
  }

  /** Kind of ball by entity id. */
  get kind(): Uint8Array {
    return this.DemoBall.kind
  }

  get gameOver(): boolean {
    return this.ballsLeft === 0 && this.playerMoving === 0
  }

  /**
   * The player's ball waiting at its spot (held: contacts on, thrown where other balls are or wait), and how
   * many held balls on that spot are ahead of it in the queue; null when no ball of the player's waits.
   */
  get playerWaiting(): { id: number; ahead: number } | null {
    if (this.playerMoving === 0) return null // a held ball of the player's is one in play (cheap: most frames)
    const w = this.sim.world
    const q = w.held
    const B = w.Ball
    const D = this.DemoBall
    for (let i = 0; i < q.count; i++) {
      const p = q.ids[i]!
      if (B.live[p] !== 1 || B.mode[p] !== BallMode.Held || !hasComponent(w, p, D) || D.kind[p] !== Kind.Player) continue
      return { id: p, ahead: this.sim.heldAhead(p) }
    }
    return null
  }

  /** Balls of the player still rolling or on a rim. */
  get playerInPlay(): number {
    return this.playerMoving
  }

  /** Why a throw of the player's cannot be made now (no ball left, a replay playing), or null. */
  get throwBlocked(): string | null {
    if (this.ballsLeft <= 0) return 'No balls left: start a new game.'
    if (this.replaying !== null) return 'A replay is playing: throw when it ends.'
    return null
  }

  /** Why a call of a shot cannot be made now (no ball left, a replay playing, a method without snapshots), or null. */
  get callBlocked(): string | null {
    if (this.ballsLeft <= 0) return 'No balls left: start a new game.'
    if (this.replaying !== null) return 'A replay is playing: call your shot when it ends.'
    if (this.sim.config.METHOD !== 'exact') return `Call your shot needs METHOD 'exact' (the solver works on a snapshot of the world); this one runs '${this.sim.config.METHOD}'.`
    return null
  }

  /** Checks overrides the way a new simulation would use them (config and the panel's holes). */
  static validate(overrides: ConfigOverrides): Validation {
    try {
      // every rule of the config, the tabulated model's included, without building a rim table (a world of
      // that model finds every row of its table when it is made: seconds near the hole's size, and each value
      // typed into the panel on the way to one would have built its own)
      const c = resolveConfig(overrides)
      const probe = createBallPhysics({ ...overrides, RIM_MODEL: 'stages' })
      addPanel(probe, DEFAULT_PANEL)
      probe.setWalls(wallsFor(DEFAULT_PANEL))
      // what the demo itself needs beyond the core's ranges: its outcome map and Call your shot step each
      // throw at MAX_STEP for up to 30 s, and its panel is drawn at a fixed scale
      if (c.MAX_STEP < MIN_OUTCOME_STEP) return { ok: false, error: `RangeError: config.MAX_STEP must be at least ${MIN_OUTCOME_STEP} s in the demo (its outcome map and Call your shot step each throw at it), got ${c.MAX_STEP}` }
      if (c.BALL_RADIUS > MAX_DEMO_RADIUS) return { ok: false, error: `RangeError: config.BALL_RADIUS must be at most ${MAX_DEMO_RADIUS} px in the demo (its panel is ${DEFAULT_PANEL.width} px wide), got ${c.BALL_RADIUS}` }
      return { ok: true, config: c }
    } catch (e) {
      const err = e instanceof Error ? e : new Error(String(e))
      return { ok: false, error: `${err.name}: ${err.message}` }
    }
  }

  /** Sets the overrides used from the next throw or reset on. Throws the core's error if invalid. */
  setPending(overrides: ConfigOverrides): void {
    const v = Game.validate(overrides)
    if (!v.ok) throw new RangeError(v.error)
    const same = JSON.stringify(v.config) === JSON.stringify(this.sim.config)
    this.pending = same ? null : { ...overrides }
  }

  private rebuild(): BallPhysics {
    this.cancelCall()
    this.endReplay()
    this.roundKinds = null
    const sim = createBallPhysics(this.overrides)
    // a method without snapshots records no rounds: the last one (of another method) is not offered either
    if (sim.config.METHOD !== 'exact') this.lastRound = null
    this.holes = addPanel(sim, this.panel)
    sim.setWalls(wallsFor(this.panel))
    this.holeIndexById = new Map(this.holes.map((id, i) => [id, i]))
    this.sim = sim
    this.DemoBall.kind.fill(0)
    this.DemoBall.doneAt.fill(0)
    this.stressLive = 0
    this.playerMoving = 0
    this.generation++
    return sim
  }

  /** Recreates the simulation with the pending overrides, if any (balls on the panel are cleared). */
  applyPending(): boolean {
    if (this.pending === null) return false
    this.overrides = this.pending
    this.pending = null
    this.rebuild()
    return true
  }

  /** A new game: pending overrides applied, panel cleared, score 0, ten balls, the event counts at 0. */
  reset(): void {
    if (!this.applyPending()) this.rebuild()
    this.score = 0
    this.ballsLeft = BALLS_PER_GAME
    this.gameCaptures = this.holes.map(() => 0)
    this.stressTarget = 0
    this.recent.length = 0
    this.lastThrow = null
    this.eventsSeen = 0
    for (const t of EVENT_TYPE_NAMES) this.eventCounts[t] = 0
  }

  holeIndex(hole: number | undefined): number {
    return hole === undefined ? -1 : (this.holeIndexById.get(hole) ?? -1)
  }

  /** Throw speed for a meter power, px/s (the mapping throwBall uses). */
  speedFor(power: number): number {
    const c = this.sim.config
    return c.MIN_VY + power * (c.MAX_VY - c.MIN_VY)
  }

  /**
   * One of the player's throws from the launch point (or `from`), with the pending settings applied first
   * (unless `apply` is false). Returns false when no balls are left.
   */
  throwPlayer(request: ThrowRequest, from: { x: number; y: number } = this.panel.launch, apply = true): boolean {
    if (this.ballsLeft <= 0 || this.replaying !== null) return false
    this.cancelCall()
    if (apply) this.applyPending()
    this.beginRound()
    if (this.gameCaptures.length !== this.holes.length) this.gameCaptures = this.holes.map(() => 0)
    this.spawn(Kind.Player, from.x, from.y, request.power, request.angle)
    this.ballsLeft--
    this.throwsMade++
    this.lastThrow = { ...request, speed: this.speedFor(request.power) }
    return true
  }

  /**
   * n balls thrown at once toward random points of the hole field: from along the bottom edge, or (burstFrom
   * 'launcher') all from the launch point.
   */
  burst(n: number): void {
    if (this.replaying !== null) return
    this.cancelCall()
    this.applyPending()
    this.beginRound()
    for (let i = 0; i < n; i++) this.spawnRandom(Kind.Burst, this.burstFrom === 'launcher')
  }

  /** Keeps `n` balls in play (0 = off): finished ones are removed and thrown again. */
  setStress(n: number): void {
    if (this.replaying !== null) return
    this.cancelCall()
    this.applyPending()
    // the stress mode's endless recycling is no round: a recording under way is dropped
    if (n > 0) this.dropRound()
    this.stressTarget = n
    if (n === 0) this.removeWhere((k) => k === Kind.Stress)
  }

  /**
   * Removes every ball that is not the player's, and stops the stress mode. Not while a replay plays (its
   * world's balls are the recorded ones, and the recording removes them itself).
   */
  clearExtra(): void {
    if (this.replaying !== null) return
    this.cancelCall()
    this.stressTarget = 0
    this.removeWhere((k) => k !== Kind.Player)
  }

  private removeWhere(test: (kind: number) => boolean): void {
    // bitECS applies removals at the next query, so the live array does not change under the loop
    const live = this.live
    for (let i = live.length - 1; i >= 0; i--) {
      const id = live[i]!
      if (test(this.DemoBall.kind[id]!)) this.remove(id)
    }
  }

  private spawnRandom(kind: KindCode, fromLauncher = false): number {
    const r = this.random
    const W = this.panel.width
    if (fromLauncher) {
      // from the launch point: aimed at a random point of the hole field, with at least LAUNCHER_MIN_POWER (a
      // ball too slow to clear the spot would hold the ones behind it until it rolls back off)
      const { x, y } = this.panel.launch
      const tx = 20 + r() * (W - 40)
      const ty = 100 + r() * 300
      const angle = Math.max(-1.4, Math.min(1.4, Math.atan2(tx - x, -(ty - y))))
      return this.spawn(kind, x, y, LAUNCHER_MIN_POWER + (1 - LAUNCHER_MIN_POWER) * r(), angle)
    }
    const x = 40 + r() * (W - 80)
    const y = this.panel.launch.y + (r() - 0.5) * 20
    const tx = 20 + r() * (W - 40)
    const ty = 100 + r() * 300
    const angle = Math.max(-1.4, Math.min(1.4, Math.atan2(tx - x, -(ty - y))))
    return this.spawn(kind, x, y, r(), angle)
  }

  private spawn(kind: KindCode, x: number, y: number, power: number, angle: number): number {
    // the player's ball goes ahead of the balls a burst left waiting at the launcher: it waits only for the spot
    const id = this.sim.throwBall({ x, y, power, angle, queue: kind === Kind.Player ? 'front' : 'back' })
    const D = this.DemoBall
    if (D.kind.length < id + 1) {
      D.kind = grow(D.kind, id + 1)
      D.doneAt = grow(D.doneAt, id + 1)
    }
    addComponent(this.sim.world, id, D)
    this.ensurePrev()
    const B = this.sim.world.Ball
    this.prevX[id] = B.x[id]!
    this.prevY[id] = B.y[id]!
    D.kind[id] = kind
    D.doneAt[id] = 0
    this.roundKinds?.set(id, kind)
    if (kind === Kind.Stress) this.stressLive++
    if (kind === Kind.Player) this.playerMoving++
    return id
  }

  private remove(id: number): void {
    const D = this.DemoBall
    const k = D.kind[id]!
    if (k === Kind.Stress) this.stressLive--
    if (k === Kind.Player && D.doneAt[id] === 0) this.playerMoving--
    // the simulation forgets the ball, and DemoBall goes with the entity (removeBall: a replay records it)
    this.sim.removeBall(id)
    D.kind[id] = 0
    D.doneAt[id] = 0
  }

  private ensurePrev(): void {
    const n = this.sim.world.Ball.x.length
    if (this.prevX.length < n) {
      this.prevX = grow(this.prevX, n)
      this.prevY = grow(this.prevY, n)
    }
  }

  /**
   * One displayed frame: runs the due 120 Hz steps (at most MAX_STEPS_PER_FRAME; a longer frame is cut),
   * drains the events, scores the player's captures and retires finished balls. Afterwards draw each ball
   * at prev + (current − prev)·clock.alpha.
   */
  frame(frameSeconds: number): FrameResult {
    const dt = Number.isFinite(frameSeconds) && frameSeconds > 0 ? Math.min(frameSeconds, MAX_FRAME_SECONDS) : 0
    // a called shot being solved: the world waits for its answer (nothing steps, nothing fades)
    if (this.solving !== null) return { events: [], steps: 0, physicsMs: 0 }
    this.time += dt
    if (this.replaying !== null) return this.replayFrame(dt)
    let physicsMs = 0
    const sim = this.sim
    this.clock.advance(dt, (h) => {
      // positions at the start of this step: the interpolation's "previous" state
      this.ensurePrev()
      const B = sim.world.Ball
      this.prevX.set(B.x)
      this.prevY.set(B.y)
      const t0 = performance.now()
      sim.step(h)
      physicsMs += performance.now() - t0
    })
    const events = this.takeEvents()
    this.retire()
    this.endRoundIfQuiet()
    if (this.stressTarget > this.stressLive) {
      const n = this.stressTarget - this.stressLive
      for (let i = 0; i < n; i++) this.spawnRandom(Kind.Stress)
    }
    return { events, steps: this.clock.steps, physicsMs }
  }

  private takeEvents(raw: BallEvent[] = this.sim.drainEvents()): DemoEvent[] {
    const out = new Array<DemoEvent>(raw.length)
    for (let i = 0; i < raw.length; i++) {
      const e = raw[i]!
      // wall events carry no hole (whatever is in their hole slot): only hole events are mapped
      const holeIndex = isHoleEvent(e.type) ? this.holeIndex(e.hole) : -1
      const value = holeIndex >= 0 ? this.panel.holes[holeIndex]!.value : 0
      const player = this.DemoBall.kind[e.ball] === Kind.Player
      const d: DemoEvent = { ...e, holeIndex, value, player }
      out[i] = d
      if (this.replaying !== null) {
        this.replayEvents.push([e.type, e.ball, e.time])
        continue
      }
      if (this.roundKinds !== null) this.recordingEvents.push([e.type, e.ball, e.time])
      this.eventsSeen++
      this.eventCounts[e.type] = (this.eventCounts[e.type] ?? 0) + 1
      // the player's throws and the multi-ball bursts score (the stress mode's recycled balls do not), until
      // the game is over: then the score stands, and bursts play for show
      const scores = (player || this.DemoBall.kind[e.ball] === Kind.Burst) && !this.gameOver
      if (e.type === 'capture' && scores && holeIndex >= 0) {
        this.score += this.sim.holeState(e.hole!).value
        if (player) this.gameCaptures[holeIndex] = (this.gameCaptures[holeIndex] ?? 0) + 1
      }
    }
    // keep the newest few for the log (in stress mode thousands arrive per frame)
    const keep = 12
    for (let i = Math.max(0, out.length - keep); i < out.length; i++) this.recent.push(out[i]!)
    if (this.recent.length > keep) this.recent.splice(0, this.recent.length - keep)
    return out
  }

  /** Balls that rest fade out and go; balls that leave the panel go; a burst's captured balls go; stress balls are recycled. */
  private retire(): void {
    const B = this.sim.world.Ball
    const X = B.x
    const Y = B.y
    const M = B.mode
    const W = this.panel.width
    const H = this.panel.height
    const now = this.time
    const D = this.DemoBall
    const live = this.live
    for (let i = live.length - 1; i >= 0; i--) {
      const id = live[i]!
      const r = B.radius[id]!
      const x = X[id]!
      const y = Y[id]!
      const mode = M[id]!
      if (mode === MODE_OUT || x < -r || x > W + r || y < -r || y > H + r) {
        this.remove(id)
        continue
      }
      const stopped = mode === BallMode.Resting || mode === BallMode.Captured
      if (!stopped) continue
      if (D.doneAt[id] === 0) {
        D.doneAt[id] = Math.max(now, 1e-9)
        if (D.kind[id] === Kind.Player) this.playerMoving--
        continue
      }
      const age = now - D.doneAt[id]!
      const k = D.kind[id]
      if (k === Kind.Stress) {
        if (age > (mode === BallMode.Captured ? STRESS_CAPTURE_HOLD : STRESS_REST_HOLD)) this.remove(id)
      } else if (mode === BallMode.Resting && age > REST_HOLD + REST_FADE) {
        this.remove(id)
      } else if (k === Kind.Burst && mode === BallMode.Captured && age > BURST_CAPTURE_HOLD) {
        this.remove(id)
      }
    }
  }

  /** A throw or burst on a quiet panel starts recording a round. */
  private beginRound(): void {
    // a replay starts from a snapshot, which only the exact method has: other methods play without rounds
    if (this.roundKinds !== null || this.stressTarget > 0 || this.sim.config.METHOD !== 'exact') return
    this.sim.startRecording()
    this.roundKinds = new Map()
    this.recordingEvents = []
    for (const id of this.live) this.roundKinds.set(id, this.DemoBall.kind[id]!)
  }

  private dropRound(): void {
    if (this.roundKinds === null) return
    this.sim.stopRecording()
    this.roundKinds = null
  }

  /** The round ends when no ball is rolling, on a rim or held. */
  private endRoundIfQuiet(): void {
    if (this.roundKinds === null) return
    const M = this.sim.world.Ball.mode
    for (const id of this.live) {
      const m = M[id]
      if (m === BallMode.Rolling || m === BallMode.RimRoll || m === BallMode.Held) return
    }
    this.lastRound = this.sim.stopRecording()
    this.roundsRecorded++
    this.lastRoundKinds = this.roundKinds
    this.roundKinds = null
    this.roundEvents = this.recordingEvents
    this.recordingEvents = []
  }

  /** The last called shot: the hole (layout index), and the solver's answer */
  lastCall: { holeIndex: number; answer: ThrowSolution | ThrowFailure; ms: number } | null = null
  /**
   * A called shot being solved elsewhere (a worker): the hole (layout index) and the call's token. The
   * physics waits while it is set (frame() runs no step), so the answer is exact for the world it gets
   * back; a throw, a burst, a clear, a reset or a replay cancels the call.
   */
  solving: { holeIndex: number; token: number } | null = null
  private calls = 0

  /**
   * Call your shot, first half: what the solver needs to find a throw from the launch line (±160 px) that
   * drops the player's next ball into the hole at `holeIndex` (layout order), in this world as it is: its
   * config and a snapshot (a world restored from them has the same entity ids, so `hole` holds there). The
   * physics waits until finishCall or cancelCall. Null when no ball is left, a replay plays, or a call is
   * already being solved.
   */
  beginCall(holeIndex: number): ShotCall | null {
    if (this.ballsLeft <= 0 || this.replaying !== null || this.solving !== null) return null
    const hole = this.holes[holeIndex]
    if (hole === undefined) return null
    this.applyPending()
    if (this.callBlocked !== null) return null
    const token = ++this.calls
    this.solving = { holeIndex, token }
    // checked at the demo's own step (the outcome is the same at every step; the cost is not)
    const request = { from: { ...this.panel.launch }, hole: this.holes[holeIndex]!, outcome: 'capture' as const, along: 160, step: Math.min(1 / PHYSICS_HZ, this.sim.config.MAX_STEP), queue: 'front' as const }
    return { token, config: { ...this.sim.config }, snapshot: this.sim.snapshot(), request }
  }

  /**
   * Call your shot, second half: the solver's answer for the call `token` (and the time it took, ms). Throws
   * the player's ball when a throw was found, and lets the physics go on. Returns the answer, or null when
   * the call was cancelled in the meantime (then nothing happens).
   */
  finishCall(token: number, answer: ThrowSolution | ThrowFailure, ms: number): ThrowSolution | ThrowFailure | null {
    const s = this.solving
    if (s === null || s.token !== token) return null
    this.solving = null
    this.lastCall = { holeIndex: s.holeIndex, answer, ms }
    // thrown into the world it was solved in: settings changed meanwhile wait for the next throw (applied
    // now, they would rebuild the world, and the solved throw would go into another)
    if (answer.found) this.throwPlayer({ power: answer.power, angle: answer.angle }, answer.from, false)
    return answer
  }

  /** Drops the call being solved, if any (its answer, when it comes, is ignored); the physics goes on. */
  cancelCall(): void {
    this.solving = null
  }

  /**
   * Call your shot, solved here and now (the page without workers, and the tests): beginCall, solveThrow on
   * this world, finishCall. Returns the solver's answer (null when no ball is left or a replay plays).
   */
  callShot(holeIndex: number): ThrowSolution | ThrowFailure | null {
    const call = this.beginCall(holeIndex)
    if (call === null) return null
    const t0 = performance.now()
    const answer = solveThrow(this.sim, call.request)
    return this.finishCall(call.token, answer, performance.now() - t0)
  }

  /** Steps of the last round (0 when there is none). */
  get lastRoundSteps(): number {
    return this.lastRound === null ? 0 : this.lastRound.inputs.filter((i) => i[0] === 'step').length
  }

  /**
   * Plays the last round back from its start on a world of its own; the live game waits (no throws) and
   * resumes when the replay ends. Returns false when there is no round to play.
   */
  replayLastRound(): boolean {
    if (this.lastRound === null || this.replaying !== null) return false
    this.cancelCall()
    // a round under way keeps its recording: the live world waits (nothing of it steps or changes) and the
    // round goes on, and ends, after the replay
    const player = createReplayPlayer(this.lastRound)
    const D = this.DemoBall
    this.replaying = { player, live: this.sim, kinds: this.lastRoundKinds, kind: D.kind.slice(), doneAt: D.doneAt.slice() }
    this.replayEvents = []
    this.sim = player.sim
    D.doneAt.fill(0)
    this.tagReplayBalls()
    this.generation++
    return true
  }

  /** The replayed world's balls of the round get the demo's component (their ids are the recorded ones). */
  private tagReplayBalls(): void {
    const R = this.replaying!
    const w = this.sim.world
    const D = this.DemoBall
    for (const [id, kind] of R.kinds) {
      if (w.Ball.live[id] !== 1 || hasComponent(w, id, D)) continue
      if (D.kind.length < id + 1) {
        D.kind = grow(D.kind, id + 1)
        D.doneAt = grow(D.doneAt, id + 1)
      }
      addComponent(w, id, D)
      D.kind[id] = kind
      D.doneAt[id] = 0
      this.ensurePrev()
      this.prevX[id] = w.Ball.x[id]!
      this.prevY[id] = w.Ball.y[id]!
    }
  }

  private replayFrame(dt: number): FrameResult {
    const R = this.replaying!
    let physicsMs = 0
    let more = true
    // drained after every step: the round's removals come between steps, and removing a ball drops its
    // undrained events (the live game drained them at the end of the frame, before it removed the ball)
    const raw: BallEvent[] = []
    this.clock.advance(dt, () => {
      if (!more) return
      this.ensurePrev()
      const B = this.sim.world.Ball
      this.prevX.set(B.x)
      this.prevY.set(B.y)
      const t0 = performance.now()
      more = R.player.next()
      physicsMs += performance.now() - t0
      for (const e of this.sim.drainEvents()) raw.push(e)
      this.tagReplayBalls()
    })
    const events = this.takeEvents(raw)
    if (!more) this.endReplay()
    return { events, steps: this.clock.steps, physicsMs }
  }

  /** Back to the live game, as it was when the replay began. */
  endReplay(): void {
    const R = this.replaying
    if (R === null) return
    this.replaying = null
    this.sim = R.live
    this.DemoBall.kind = R.kind
    this.DemoBall.doneAt = R.doneAt
    this.ensurePrev()
    this.prevX.set(R.live.world.Ball.x)
    this.prevY.set(R.live.world.Ball.y)
    this.generation++
  }

  /** Opacity of a live ball (resting balls fade before they are removed). */
  opacity(id: number): number {
    const t = this.DemoBall.doneAt[id]!
    if (t === 0 || this.sim.world.Ball.mode[id] !== BallMode.Resting) return 1
    const hold = this.DemoBall.kind[id] === Kind.Stress ? STRESS_REST_HOLD : REST_HOLD
    const age = this.time - t - hold
    return age <= 0 ? 1 : Math.max(0, 1 - age / REST_FADE)
  }
}
