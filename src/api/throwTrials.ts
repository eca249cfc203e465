// The throw solver's simulations (src/api/solveThrow.ts): a trial world for the grid's throws, and the
// exact copy of the world that checks the chosen one.
import type { BallWorld } from '../world/createWorld.js'
import { createBallPhysics, type BallPhysics } from './createBallPhysics.js'
import { snapshotWorld } from '../commands/snapshot.js'
import { openSpec } from '../commands/walls.js'
import { EventType } from '../events.js'
import { BallMode } from '../../components/Ball.js'
import { forEachBall } from '../world/balls.js'

export type ThrowOutcome = 'capture' | 'skip' | 'lipOut' | 'bounce'

/** simulated time after which a throw that has not met the hole counts as missing it, s */
export const HORIZON = 20

/** What the ball's first decisive event at the hole was: an outcome, or null (it never met the hole, or another hole took it). */
function outcomeAt(type: number, eventHole: number, hole: number): ThrowOutcome | null {
  if (eventHole !== hole) return null
  if (type === EventType.Capture) return 'capture'
  if (type === EventType.Skip) return 'skip'
  if (type === EventType.LipOut) return 'lipOut'
  if (type === EventType.Bounce) return 'bounce'
  return null
}

/**
 * Steps `sim` (MAX_STEP at a time, up to HORIZON) until ball `b` meets `hole` decisively or stops; the
 * outcome there (null: none), its time after `t0`, s, and whether the ball was still held at its spot at
 * the end (queued at a launcher the whole time).
 */
function follow(sim: BallPhysics, b: number, hole: number, t0: number, dt: number): { outcome: ThrowOutcome | null; at: number; held: boolean } {
  const found = { outcome: null as ThrowOutcome | null, at: -1, held: false }
  const visit = (e: { code: number; ball: number; hole: number; time: number }): void => {
    if (found.outcome !== null || e.ball !== b) return
    found.outcome = outcomeAt(e.code, e.hole, hole)
    if (found.outcome !== null) found.at = e.time - t0
  }
  const mode = sim.world.Ball.mode
  for (let t = 0; t < HORIZON && found.outcome === null; t += dt) {
    sim.step(dt)
    sim.drainEventsWith(visit)
    const m = mode[b]
    if (m === BallMode.Captured || m === BallMode.Out || m === BallMode.Resting) break
  }
  found.held = mode[b] === BallMode.Held
  return found
}

/**
 * A world with the config, holes and walls of the solved one, for one throw at a time. With contacts off
 * the thrown ball is alone (the others cannot touch it); with contacts on, the balls on the panel are put
 * down again for each throw where they are now, with their velocities, radii and masses.
 */
export class Trial {
  readonly sim: BallPhysics
  readonly hole: number
  count = 0
  /** x, y, vx, vy, radius, mass of each ball on the panel (contacts on) */
  private readonly others: number[] = []

  constructor(world: BallWorld, hole: number) {
    const contacts = world.collide !== null || world.fixed !== null
    this.sim = createBallPhysics(contacts ? world.config : { ...world.config, BALL_COLLISIONS: 'off' }, { capacity: 64 })
    const ids = copyPanel(world, this.sim)
    this.hole = ids.get(hole)!
    if (!contacts) return
    const B = world.Ball
    const mass = world.collide !== null ? world.collide.mass : world.fixed!.mass
    forEachBall(world, (b) => {
      const m = B.mode[b]
      if (m !== BallMode.Rolling && m !== BallMode.RimRoll && m !== BallMode.Resting) return
      this.others.push(B.x[b]!, B.y[b]!, m === BallMode.Resting ? 0 : B.vx[b]!, m === BallMode.Resting ? 0 : B.vy[b]!, B.radius[b]!, mass[b]!)
    })
  }

  run(x: number, y: number, power: number, angle: number): ThrowOutcome | null {
    this.count++
    const sim = this.sim
    const o = this.others
    for (let i = 0; i < o.length; i += 6) sim.addBall({ x: o[i]!, y: o[i + 1]!, vx: o[i + 2]!, vy: o[i + 3]!, radius: o[i + 4]!, mass: o[i + 5]! })
    const { outcome } = follow(sim, sim.throwBall({ x, y, power, angle }), this.hole, sim.time, sim.config.MAX_STEP)
    for (const id of sim.balls()) sim.removeBall(id)
    sim.drainEvents()
    return outcome
  }
}

/** The throw simulated in an exact copy of the world (a snapshot restored into a fresh one). */
export class ExactCheck {
  count = 0
  /** runs whose ball was still held at its spot when the check stopped following it (HORIZON s) */
  heldThrough = 0
  private readonly bytes: Uint8Array
  constructor(
    private readonly world: BallWorld,
    private readonly hole: number,
    /** the step the copy is stepped at (the outcome is the same at every step; the cost is not) */
    private readonly dt: number,
    /** where the throw waits if it is held (throwBall's queue) */
    private readonly queue: 'back' | 'front',
  ) {
    this.bytes = snapshotWorld(world)
  }

  /** The time from the throw to the outcome, s, or −1 when this run does not give it. */
  run(x: number, y: number, power: number, angle: number, outcome: ThrowOutcome): number {
    this.count++
    const copy = createBallPhysics(this.world.config)
    copy.restore(this.bytes)
    copy.drainEvents()
    const found = follow(copy, copy.throwBall({ x, y, power, angle, queue: this.queue }), this.hole, copy.time, this.dt)
    if (found.held) this.heldThrough++
    return found.outcome === outcome ? found.at : -1
  }
}

/** Copies the world's holes and walls into `sim`; returns the map from the world's hole ids to the copies'. */
function copyPanel(world: BallWorld, sim: BallPhysics): Map<number, number> {
  const ids = new Map<number, number>()
  const H = world.Hole
  const holes = world.holes
  for (let i = 0; i < holes.count; i++) {
    const h = holes.ids[i]!
    ids.set(h, sim.addHole({ x: H.x[h]!, y: H.y[h]!, radius: H.radius[h]!, value: H.value[h]! }))
  }
  if (world.walls !== 0) {
    const W = world.Walls
    const e = world.walls
    sim.setWalls({ minX: W.minX[e]!, minY: W.minY[e]!, maxX: W.maxX[e]!, maxY: W.maxY[e]!, restitution: W.restitution[e]!, open: openSpec(W.open[e]!) })
  }
  return ids
}
