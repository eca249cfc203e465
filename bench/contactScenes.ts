// The two scenes of the contacts benchmark (bench/contacts.ts), also read by bench/horizon.ts:
//   gas:   a walled square, balls at area fraction 0.2, restitution 0.9 (balls and walls), no holes, no
//          rolling deceleration, 150–350 px/s in random directions;
//   panel: the multi-ball panel: tiles of the default 5 × 5 panel side by side in one walled field (bottom
//          open), 40 balls a tile thrown up the panel at once from a launch band (powers 0.2–0.9, aims
//          ±0.4 rad), the design's deceleration.
// Every ball is put down apart from the others.
import { DEFAULT_PANEL, createBallPhysics, type BallPhysics } from '../src/index'
import { random } from './lib'

/** the balls' radius (the default) */
export const R = 11

export interface Scene {
  name: 'gas' | 'panel'
  width: number
  height: number
  /** open bottom edge */
  open: boolean
  restitution: number
  decel: number
  balls: { x: number; y: number; vx: number; vy: number }[]
  holes: { x: number; y: number }[]
}

export function gas(n: number): Scene {
  const r = random(12345)
  const side = Math.sqrt((n * Math.PI * R * R) / 0.2)
  const k = Math.ceil(Math.sqrt(n))
  const pitch = side / k
  const balls: Scene['balls'] = []
  for (let i = 0; i < n; i++) {
    const a = r() * 2 * Math.PI
    const v = 150 + 200 * r()
    const jitter = pitch - 2 * R - 0.01
    balls.push({ x: pitch * ((i % k) + 0.5) + (r() - 0.5) * jitter, y: pitch * (Math.floor(i / k) + 0.5) + (r() - 0.5) * jitter, vx: v * Math.cos(a), vy: v * Math.sin(a) })
  }
  return { name: 'gas', width: side, height: side, open: false, restitution: 0.9, decel: 0, balls, holes: [] }
}

export function panel(n: number): Scene {
  const r = random(777)
  const perTile = 40
  const tiles = Math.ceil(n / perTile)
  const cols = Math.ceil(Math.sqrt(tiles))
  const rows = Math.ceil(tiles / cols)
  const W = DEFAULT_PANEL.width
  const H = DEFAULT_PANEL.height
  const holes: Scene['holes'] = []
  for (let ty = 0; ty < rows; ty++) for (let tx = 0; tx < cols; tx++) for (const h of DEFAULT_PANEL.holes) holes.push({ x: h.x + tx * W, y: h.y + ty * H })
  const balls: Scene['balls'] = []
  // launch band: 10 columns × 4 rows a tile, 40 px apart, jittered, below the lowest row of holes
  for (let i = 0; i < n; i++) {
    const t = Math.floor(i / perTile)
    const j = i % perTile
    const x = (t % cols) * W + 30 + 40 * (j % 10) + (r() - 0.5) * 16
    const y = Math.floor(t / cols) * H + H - 150 + 40 * Math.floor(j / 10) + (r() - 0.5) * 16
    const speed = 175 + (0.2 + 0.7 * r()) * (700 - 175)
    const angle = (r() - 0.5) * 0.8
    balls.push({ x, y, vx: speed * Math.sin(angle), vy: -speed * Math.cos(angle) })
  }
  return { name: 'panel', width: cols * W, height: rows * H, open: true, restitution: 0.9, decel: 300, balls, holes }
}

/** This module's world for scene sc (`create`: another build's createBallPhysics, as bench/ab.ts passes). */
export function oursScene(sc: Scene, mode: 'off' | 'on' | 'fixed', tick: number, create: typeof createBallPhysics = createBallPhysics): BallPhysics {
  const sim: BallPhysics = create(
    { ROLLING_DECEL: sc.decel, BALL_COLLISIONS: mode, BALL_RESTITUTION: sc.restitution, CONTACT_TICK: tick },
    { capacity: sc.balls.length + sc.holes.length + 64 },
  )
  sim.setWalls({ minX: 0, minY: 0, maxX: sc.width, maxY: sc.height, restitution: sc.restitution, open: { bottom: sc.open } })
  for (const h of sc.holes) sim.addHole(h)
  for (const b of sc.balls) sim.addBall(b)
  return sim
}
