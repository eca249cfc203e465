// Draws the panel: body, holes with rims and values, balls (one ParticleContainer, so 10,000+ balls are a
// single draw), velocity vectors, event flashes with their (δ, v), score pops, the aim arrow, the power
// meter and the tray of balls left. It only reads the game and the world's arrays.
import { Container, Graphics, Particle, ParticleContainer, Text, Texture } from 'pixi.js'
import { BALL_MODE_NAMES, cogRadius } from '../src/index'
import { BallMode } from '../src/ecs'
import { BALLS_PER_GAME, Kind, type DemoEvent, type Game } from './game'
import type { ThrowInput } from './input'
import { COLORS, FONT, MONO, PLAIN_BALL, PLAYER_BALL, eventColor, modeColor, valueColor } from './theme'

export interface InspectorOptions {
  modeColors: boolean
  vectors: boolean
  labels: boolean
}

/** Opacity of the player's ball while it waits at the launcher. */
export const HELD_PLAYER_ALPHA = 0.35
/** Most velocity vectors drawn per frame (the rest are skipped, so stress mode stays fast). */
const MAX_VECTORS = 2500
/** Seconds a velocity vector spans. */
const VECTOR_SECONDS = 0.12
const FLASH_SECONDS = 1.1
const PLAYER_FLASH_SECONDS = 2.2
const LABEL_MIN_INTERVAL = 0.12
const POP_SECONDS = 1.3
const TEXTURE_SIZE = 64
const TEXT_RES = 3

interface Flash {
  type: string
  at: number
  player: boolean
  label: string
  shownAt: number
}

function ballTexture(): Texture {
  const c = document.createElement('canvas')
  c.width = c.height = TEXTURE_SIZE
  const g = c.getContext('2d')!
  const h = TEXTURE_SIZE / 2
  const grad = g.createRadialGradient(h * 0.7, h * 0.62, h * 0.08, h, h, h)
  grad.addColorStop(0, '#ffffff')
  grad.addColorStop(0.45, '#e6e6e6')
  grad.addColorStop(0.9, '#8c8c8c')
  grad.addColorStop(1, '#6e6e6e')
  g.fillStyle = grad
  g.beginPath()
  g.arc(h, h, h - 1, 0, Math.PI * 2)
  g.fill()
  return Texture.from(c)
}

/** ABGR-packed particle colour, as Particle computes it from tint and alpha. */
function packColor(rgb: number, alpha: number): number {
  const bgr = ((rgb & 0xff) << 16) | (rgb & 0xff00) | ((rgb >> 16) & 0xff)
  return bgr + (((alpha * 255) | 0) << 24)
}

function text(s: string, size: number, fill: number, opts: { mono?: boolean; bold?: boolean; outline?: boolean } = {}): Text {
  return new Text({
    text: s,
    resolution: TEXT_RES,
    style: {
      fontFamily: opts.mono ? MONO : FONT,
      fontSize: size,
      fill,
      fontWeight: opts.bold ? '700' : '500',
      ...(opts.outline ? { stroke: { color: 0x070b14, width: 3, join: 'round' as const } } : {}),
    },
  })
}

export class PanelView {
  readonly root = new Container()
  /** body, holes and value labels: drawn once per config into a cached texture */
  private readonly staticLayer = new Container()
  private readonly body = new Graphics()
  private readonly holesG = new Graphics()
  private readonly inspectG = new Graphics()
  private readonly tallyG = new Graphics()
  private readonly labelsLayer = new Container()
  private readonly tallyLayer = new Container()
  private readonly balls: ParticleContainer
  /** held balls drawn visible in the last frame (the page's test hook reads it): the player's, faint; the others wait unseen in the launcher */
  heldVisible = 0
  private readonly vectors = new Graphics()
  private readonly flashG = new Graphics()
  private readonly flashLayer = new Container()
  private readonly popLayer = new Container()
  private readonly aimG = new Graphics()
  private readonly meterG = new Graphics()
  private readonly trayG = new Graphics()
  private readonly meterLabel = text('', 10, COLORS.textDim, { mono: true })
  private readonly hint = text('', 13, COLORS.text, { bold: true })
  private readonly subHint = text('', 10.5, COLORS.textDim)
  private readonly texture = ballTexture()
  private readonly pool: Particle[] = []
  private flashes: (Flash | null)[] = []
  private flashTexts: Text[] = []
  private tallyTexts: Text[] = []
  private pops: { t: Text; at: number; y: number }[] = []
  private built = -1
  /** the meter's rectangle in panel coordinates (for pointer hit tests) */
  readonly meter = { x: 0, y: 0, w: 16, h: 200 }

  constructor(private readonly game: Game) {
    this.balls = new ParticleContainer({
      texture: this.texture,
      dynamicProperties: { position: true, color: true, vertex: false, rotation: false, uvs: false },
    })
    this.hint.anchor.set(0.5, 0)
    this.subHint.anchor.set(0.5, 0)
    this.meterLabel.anchor.set(0.5, 0)
    this.staticLayer.addChild(this.body, this.holesG, this.labelsLayer)
    this.root.addChild(
      this.staticLayer,
      this.tallyG,
      this.inspectG,
      this.tallyLayer,
      this.flashG,
      this.vectors,
      this.balls,
      this.flashLayer,
      this.popLayer,
      this.aimG,
      this.meterG,
      this.meterLabel,
      this.trayG,
      this.hint,
      this.subHint,
    )
  }

  /** Redraws everything that depends on the simulation's config (after a rebuild). */
  private build(): void {
    const g = this.game
    const { width: W, height: H, launch } = g.panel
    const R = g.config.HOLE_RADIUS
    const r = g.config.BALL_RADIUS
    this.built = g.generation

    const b = this.body.clear()
    b.roundRect(-10, -10, W + 20, H + 20, 16).fill({ color: 0x070b14 })
    b.rect(0, 0, W, H).fill({ color: COLORS.panel })
    for (let x = 20; x < W; x += 20) b.moveTo(x, 2).lineTo(x, H - 2)
    for (let y = 20; y < H; y += 20) b.moveTo(2, y).lineTo(W - 2, y)
    b.stroke({ width: 1, color: COLORS.panelGrid, alpha: 0.55 })
    // a band behind each row, tinted by its value
    const rows = [...new Set(g.panel.holes.map((h) => h.y))]
    for (const y of rows) {
      const v = g.panel.holes.find((h) => h.y === y)!.value
      b.roundRect(8, y - R - 7, W - 16, 2 * R + 26, 8).fill({ color: valueColor(v), alpha: 0.045 })
    }
    // walls: rails left, top and right; the bottom edge is the open gutter
    b.moveTo(-2, H + 2).lineTo(-2, -2).lineTo(W + 2, -2).lineTo(W + 2, H + 2)
    b.stroke({ width: 5, color: 0x3b4f78, join: 'round' })
    b.moveTo(-2, H + 2).lineTo(-2, -2).lineTo(W + 2, -2).lineTo(W + 2, H + 2)
    b.stroke({ width: 1.5, color: 0x8aa2cf, alpha: 0.6, join: 'round' })
    b.rect(0, H - 3, W, 7).fill({ color: 0x03060c })
    for (let x = 4; x < W; x += 12) b.moveTo(x, H + 4).lineTo(x + 6, H - 3)
    b.stroke({ width: 1, color: 0x2c3d5e })
    // launch pad and foul line
    b.moveTo(12, launch.y - 22).lineTo(W - 12, launch.y - 22).stroke({ width: 1, color: COLORS.aim, alpha: 0.18 })
    b.circle(launch.x, launch.y, r + 7).fill({ color: 0x1b2740 }).stroke({ width: 1.5, color: COLORS.aim, alpha: 0.5 })

    const hg = this.holesG.clear()
    for (const h of g.panel.holes) {
      hg.circle(h.x, h.y + 1.5, R + 3).fill({ color: COLORS.lipShadow, alpha: 0.8 })
      hg.circle(h.x, h.y, R).fill({ color: COLORS.holeInside })
      hg.circle(h.x, h.y, R - 4).fill({ color: 0x000000 })
      hg.circle(h.x, h.y, R).stroke({ width: 2.5, color: COLORS.lip })
      hg.circle(h.x, h.y, R + 1.8).stroke({ width: 1, color: valueColor(h.value), alpha: 0.55 })
    }

    const ig = this.inspectG.clear()
    const rc = cogRadius(R, r)
    for (const h of g.panel.holes) {
      // COG gate circle, R − r/2: dashed
      const n = 24
      for (let i = 0; i < n; i += 2) {
        const a0 = (i / n) * Math.PI * 2
        const a1 = ((i + 1) / n) * Math.PI * 2
        ig.moveTo(h.x + rc * Math.cos(a0), h.y + rc * Math.sin(a0))
        ig.arc(h.x, h.y, rc, a0, a1)
      }
    }
    ig.stroke({ width: 1, color: COLORS.cog, alpha: 0.45 })

    for (const t of this.labelsLayer.removeChildren()) t.destroy()
    for (const t of this.flashTexts) t.destroy()
    for (const t of this.tallyTexts) t.destroy()
    this.flashTexts = []
    this.tallyTexts = []
    this.flashes = g.panel.holes.map(() => null)
    for (const h of g.panel.holes) {
      const v = text(String(h.value), 10.5, valueColor(h.value), { bold: true })
      v.anchor.set(0.5, 0)
      v.position.set(h.x, h.y + R + 1)
      this.labelsLayer.addChild(v)
      const f = text('', 9.5, COLORS.text, { mono: true, bold: true, outline: true })
      f.anchor.set(0.5, 1)
      f.position.set(h.x, h.y - R + 2)
      f.visible = false
      this.flashLayer.addChild(f)
      this.flashTexts.push(f)
      const tl = text('', 9, 0xfbd34d, { bold: true })
      tl.anchor.set(0, 0.5)
      tl.position.set(h.x + R + 2, h.y - R + 2)
      this.tallyTexts.push(tl)
    }

    this.meter.x = W + 14
    this.meter.h = 200
    this.meter.y = H - this.meter.h
    this.meterLabel.position.set(this.meter.x + this.meter.w / 2, H + 6)
    this.hint.position.set(W / 2, 30)
    this.subHint.position.set(W / 2, 52)
    this.balls.update()
    this.tallyLayer.addChild(...this.tallyTexts)
    // one textured quad instead of a few full-size fills per frame (software GL is fill-rate bound)
    this.staticLayer.cacheAsTexture(false)
    this.staticLayer.cacheAsTexture({ resolution: 2, antialias: true })
  }

  /** Feeds a frame's events to the flashes and the score pops. */
  onEvents(events: DemoEvent[]): void {
    const now = this.game.time
    for (const e of events) {
      if (e.holeIndex < 0 || e.type === 'rest') continue
      const cur = this.flashes[e.holeIndex]
      // a burst's events do not hide the player's for a moment
      if (cur && cur.player && !e.player && now - cur.at < 0.8) continue
      const label =
        e.delta !== undefined && e.speed !== undefined ? `δ${e.delta.toFixed(1)} v${Math.round(e.speed)}` : e.type
      this.flashes[e.holeIndex] = { type: e.type, at: now, player: e.player, label, shownAt: cur?.shownAt ?? -1 }
      if (e.type === 'capture' && e.player) this.pop(e.holeIndex, e.value)
    }
  }

  private pop(holeIndex: number, value: number): void {
    const h = this.game.panel.holes[holeIndex]!
    const t = text(`+${value}`, 16, valueColor(value), { bold: true, outline: true })
    t.anchor.set(0.5, 1)
    t.position.set(h.x, h.y - this.game.config.HOLE_RADIUS - 12)
    this.popLayer.addChild(t)
    this.pops.push({ t, at: this.game.time, y: t.y })
  }

  draw(alpha: number, input: ThrowInput, opt: InspectorOptions): void {
    const g = this.game
    if (this.built !== g.generation) this.build()
    const now = g.time
    const B = g.sim.world.Ball
    const X = B.x
    const Y = B.y
    const M = B.mode
    const PX = g.prevX
    const PY = g.prevY
    const live = g.live
    const n = live.length
    const r = g.config.BALL_RADIUS

    // balls: one particle per live ball, interpolated between the last two physics states
    const pc = this.balls
    const kids = pc.particleChildren
    while (this.pool.length < n) {
      this.pool.push(new Particle({ texture: this.texture, anchorX: 0.5, anchorY: 0.5 }))
    }
    if (kids.length !== n) {
      if (kids.length > n) kids.length = n
      else for (let i = kids.length; i < n; i++) kids.push(this.pool[i]!)
      pc.update()
    }
    const scale = (2 * r) / TEXTURE_SIZE
    const modeColors = BALL_MODE_NAMES.map(modeColor)
    let heldVisible = 0
    for (let i = 0; i < n; i++) {
      const id = live[i]!
      const p = kids[i]!
      const px = PX[id]!
      const py = PY[id]!
      p.x = px + (X[id]! - px) * alpha
      p.y = py + (Y[id]! - py) * alpha
      const s = (B.radius[id]! / r) * scale
      if (p.scaleX !== s) {
        p.scaleX = p.scaleY = s
        pc.update()
      }
      const m = M[id]!
      // a held ball waits inside the launcher (the stats count it as waiting): drawn, a queue of them stacked
      // on the launch spot looked like balls inside one another. The player's own is drawn faint, so that a
      // throw queued behind a burst is seen waiting (the status line says how many are ahead of it)
      const a = m === BallMode.Held ? (g.kind[id] === Kind.Player ? HELD_PLAYER_ALPHA : 0) : g.opacity(id) * (m === BallMode.Captured ? 0.9 : 1)
      p.color = packColor(opt.modeColors ? (modeColors[m] ?? PLAIN_BALL) : g.kind[id] === Kind.Player ? PLAYER_BALL : PLAIN_BALL, a)
      if (m === BallMode.Held && p.color >>> 24 !== 0) heldVisible++
    }
    this.heldVisible = heldVisible

    // velocity vectors for moving balls, grouped by mode (one stroke per colour)
    const vg = this.vectors.clear()
    if (opt.vectors) {
      const VX = B.vx
      const VY = B.vy
      for (const mode of [BallMode.Rolling, BallMode.RimRoll]) {
        let drawn = 0
        for (let i = 0; i < n && drawn < MAX_VECTORS; i++) {
          const id = live[i]!
          if (M[id] !== mode) continue
          const x = kids[i]!.x
          const y = kids[i]!.y
          vg.moveTo(x, y).lineTo(x + VX[id]! * VECTOR_SECONDS, y + VY[id]! * VECTOR_SECONDS)
          drawn++
        }
        if (drawn > 0) vg.stroke({ width: 1.4, color: modeColor(BALL_MODE_NAMES[mode]), alpha: 0.85 })
      }
    }
    this.inspectG.visible = opt.labels

    // event flashes: a ring at the hole, fading, and the (δ, v) of the entry above it
    const fg = this.flashG.clear()
    const R = g.config.HOLE_RADIUS
    for (let i = 0; i < this.flashes.length; i++) {
      const f = this.flashes[i]
      const label = this.flashTexts[i]!
      if (!f) {
        label.visible = false
        continue
      }
      const life = f.player ? PLAYER_FLASH_SECONDS : FLASH_SECONDS
      const age = now - f.at
      if (age > life) {
        this.flashes[i] = null
        label.visible = false
        continue
      }
      const h = g.panel.holes[i]!
      const k = 1 - age / life
      const color = eventColor(f.type)
      fg.circle(h.x, h.y, R + 2 + (1 - k) * 7).stroke({ width: f.player ? 3 : 2, color, alpha: k })
      if (f.player) fg.circle(h.x, h.y, R).fill({ color, alpha: 0.18 * k })
      if (opt.labels && label.text !== f.label && now - f.shownAt >= LABEL_MIN_INTERVAL) {
        label.text = f.label
        f.shownAt = now
      }
      if (label.style.fill !== color) label.style.fill = color
      label.visible = opt.labels
      label.alpha = Math.min(1, 0.25 + k)
    }

    // captures this game, per hole: a gold ring and a count
    const tg = this.tallyG.clear()
    for (let i = 0; i < g.panel.holes.length; i++) {
      const c = g.gameCaptures[i] ?? 0
      const t = this.tallyTexts[i]!
      const want = c > 1 ? `×${c}` : ''
      if (t.text !== want) t.text = want
      if (c > 0) {
        const h = g.panel.holes[i]!
        tg.circle(h.x, h.y, R + 5).fill({ color: 0xfbd34d, alpha: 0.16 }).stroke({ width: 1.5, color: 0xfbd34d, alpha: 0.7 })
      }
    }

    for (let i = this.pops.length - 1; i >= 0; i--) {
      const p = this.pops[i]!
      const age = now - p.at
      if (age > POP_SECONDS) {
        p.t.destroy()
        this.pops.splice(i, 1)
        continue
      }
      p.t.y = p.y - age * 22
      p.t.alpha = Math.min(1, 2 * (1 - age / POP_SECONDS))
    }

    this.drawControls(input)
  }

  private drawControls(input: ThrowInput): void {
    const g = this.game
    const { launch, width: W } = g.panel
    const ag = this.aimG.clear()
    const canThrow = g.ballsLeft > 0
    const dirX = Math.sin(input.angle)
    const dirY = -Math.cos(input.angle)
    if (canThrow) {
      // dotted guide
      for (let s = 26; s < 170; s += 10) {
        ag.circle(launch.x + dirX * s, launch.y + dirY * s, 1.3)
      }
      ag.fill({ color: COLORS.aim, alpha: 0.45 })
      const len = 24 + 70 * (input.charging ? input.power : 0.25)
      const tipX = launch.x + dirX * len
      const tipY = launch.y + dirY * len
      ag.moveTo(launch.x + dirX * 10, launch.y + dirY * 10).lineTo(tipX, tipY)
      ag.stroke({ width: 3, color: COLORS.aim, alpha: input.charging ? 1 : 0.7, cap: 'round' })
      const px = -dirY
      const py = dirX
      ag.poly([
        tipX + dirX * 9,
        tipY + dirY * 9,
        tipX + px * 6,
        tipY + py * 6,
        tipX - px * 6,
        tipY - py * 6,
      ]).fill({ color: COLORS.aim, alpha: input.charging ? 1 : 0.7 })
    }

    // power meter: press and hold to charge, release to throw
    const m = this.meter
    const mg = this.meterG.clear()
    mg.roundRect(m.x - 3, m.y - 3, m.w + 6, m.h + 6, 6).fill({ color: 0x070b14 }).stroke({ width: 1, color: COLORS.panelEdge })
    mg.roundRect(m.x, m.y, m.w, m.h, 4).fill({ color: COLORS.meterBack })
    const p = input.charging ? input.power : 0
    if (p > 0) {
      const hh = p * m.h
      const color = p < 0.5 ? 0x4ade80 : p < 0.8 ? 0xfbbf24 : 0xff5c7a
      mg.roundRect(m.x, m.y + m.h - hh, m.w, hh, 4).fill({ color })
    }
    for (let i = 1; i < 10; i++) {
      const y = m.y + m.h - (i / 10) * m.h
      mg.moveTo(m.x, y).lineTo(m.x + (i === 5 ? m.w : 5), y)
    }
    mg.stroke({ width: 1, color: 0x8a97ad, alpha: 0.6 })
    const last = g.lastThrow
    if (last) {
      const y = m.y + m.h - last.power * m.h
      mg.poly([m.x - 7, y - 4, m.x - 1, y, m.x - 7, y + 4]).fill({ color: COLORS.aim, alpha: 0.8 })
    }
    const shown = input.charging ? input.power : (last?.power ?? 0)
    const ml = `${Math.round(shown * 100)}%\n${Math.round(g.speedFor(shown))}`
    if (this.meterLabel.text !== ml) this.meterLabel.text = ml

    // tray: balls left in this game
    const tg = this.trayG.clear()
    const trayY = g.panel.height + 16
    for (let i = 0; i < BALLS_PER_GAME; i++) {
      const x = 12 + i * 15
      if (i < g.ballsLeft) tg.circle(x, trayY, 5.5).fill({ color: PLAYER_BALL })
      else tg.circle(x, trayY, 5).stroke({ width: 1, color: 0x4a5878 })
    }

    let hint = ''
    let sub = ''
    if (g.gameOver) {
      hint = `Game over — ${g.score} points`
      sub = 'New game: the button or R'
    } else if (g.throwsMade === 0 && g.ballsLeft === BALLS_PER_GAME) {
      hint = 'Press and hold to charge · drag to aim · release'
      sub = 'or ← → to aim and hold Space'
    } else if (input.charging) {
      hint = `${Math.round(input.power * 100)}% · ${Math.round(g.speedFor(input.power))} px/s`
    }
    if (this.hint.text !== hint) this.hint.text = hint
    if (this.subHint.text !== sub) this.subHint.text = sub
    void W
  }
}
