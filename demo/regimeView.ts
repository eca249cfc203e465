// The live regime map: the (δ, v) plane of a hole entry with the design's closed-form boundaries, drawn
// from the core's exported regime functions, and every hole entry of the game as a dot coloured by its
// outcome. δ runs from 0 to R along x, v from 0 to ~700 px/s up y.
import { Container, Graphics, Particle, ParticleContainer, Text, Texture } from 'pixi.js'
import { vSkip, type BallPhysicsConfig } from '../src/index'
import { regimeCurves } from './regimeCurves'
import type { DemoEvent } from './game'
import { COLORS, FONT, HOLE_EVENT_TYPES, MONO, eventColor, isHoleEvent } from './theme'

const DOTS = 1500
const DOT_TEXTURE = 16
const TEXT_RES = 3
const SKIP = 0xff5c7a
const WINDOW = 0x3ddc84
const COG = 0xfbd34d
const ROLL = 0x4cc9ff

function dotTexture(): Texture {
  const c = document.createElement('canvas')
  c.width = c.height = DOT_TEXTURE
  const g = c.getContext('2d')!
  g.fillStyle = '#fff'
  g.beginPath()
  g.arc(DOT_TEXTURE / 2, DOT_TEXTURE / 2, DOT_TEXTURE / 2 - 1, 0, Math.PI * 2)
  g.fill()
  return Texture.from(c)
}

function packColor(rgb: number, alpha: number): number {
  const bgr = ((rgb & 0xff) << 16) | (rgb & 0xff00) | ((rgb >> 16) & 0xff)
  return bgr + (((alpha * 255) | 0) << 24)
}

/** The least of 1, 2, 5 × 10^k at or above `at` and `least`: a grid step. */
function niceStep(at: number, least: number): number {
  let step = least
  while (step < at) step = step * (String(step)[0] === '2' ? 2.5 : 2)
  return step
}

function label(s: string, size: number, fill: number, mono = false): Text {
  return new Text({
    text: s,
    resolution: TEXT_RES,
    style: { fontFamily: mono ? MONO : FONT, fontSize: size, fill, fontWeight: '500' },
  })
}

export class RegimeView {
  readonly root = new Container()
  /** plot rectangle, local coordinates */
  readonly plot = { x: 44, y: 52, w: 330, h: 250 }
  private readonly staticLayer = new Container()
  private readonly frame = new Graphics()
  private readonly curves = new Graphics()
  private readonly texts = new Container()
  private readonly dots: ParticleContainer
  private readonly marker = new Graphics()
  private readonly markerText = label('', 10, COLORS.text, true)
  private readonly texture = dotTexture()
  private readonly particles: Particle[] = []
  private head = 0
  private count = 0
  private dirty = false
  private R = 18
  private vTop = 700
  private configKey = ''
  private lastPlayer: DemoEvent | null = null
  plotted = 0

  /** dots on the map now (at most DOTS; cleared for a new game or config) */
  get shown(): number {
    return this.count
  }

  constructor() {
    this.dots = new ParticleContainer({
      texture: this.texture,
      dynamicProperties: { position: true, color: true, vertex: false },
    })
    for (let i = 0; i < DOTS; i++) {
      this.particles.push(
        new Particle({ texture: this.texture, anchorX: 0.5, anchorY: 0.5, scaleX: 5 / DOT_TEXTURE, scaleY: 5 / DOT_TEXTURE }),
      )
    }
    this.staticLayer.addChild(this.frame, this.curves, this.texts)
    this.root.addChild(this.staticLayer, this.dots, this.marker, this.markerText)
  }

  private px(delta: number): number {
    return this.plot.x + (delta / this.R) * this.plot.w
  }

  private py(speed: number): number {
    return this.plot.y + this.plot.h - (Math.min(speed, this.vTop) / this.vTop) * this.plot.h
  }

  /** Redraws the boundaries for a config (cheap; called when the simulation is recreated). */
  setConfig(c: Readonly<BallPhysicsConfig>): void {
    const key = JSON.stringify(c)
    if (key === this.configKey) return
    this.configKey = key
    const R = (this.R = c.HOLE_RADIUS)
    const r = c.BALL_RADIUS
    this.vTop = Math.max(700, Math.ceil(c.MAX_VY / 50) * 50)
    const { x, y, w, h } = this.plot
    const vt = this.vTop
    for (const t of this.texts.removeChildren()) t.destroy()
    const T = (s: string, tx: number, ty: number, size: number, fill: number, ax = 0, ay = 0, mono = false): Text => {
      const t = label(s, size, fill, mono)
      t.anchor.set(ax, ay)
      t.position.set(tx, ty)
      this.texts.addChild(t)
      return t
    }

    const f = this.frame.clear()
    f.roundRect(0, 0, x + w + 14, y + h + 112, 10).fill({ color: 0x0d1424 }).stroke({ width: 1, color: COLORS.panelEdge })
    f.rect(x, y, w, h).fill({ color: 0x0a101d })
    // grid: every 100 px/s and 5 px at the design's scale, coarser (1-2-5 steps) so a wide range keeps about
    // 7-14 lines a side (MAX_VY 1e6 drew 10,000 labels and took 3 s)
    const vStep = niceStep(vt / 14, 100)
    const dStep = niceStep(R / 7, 5)
    for (let v = vStep; v < vt; v += vStep) f.moveTo(x, this.py(v)).lineTo(x + w, this.py(v))
    for (let d = dStep; d < R; d += dStep) f.moveTo(this.px(d), y).lineTo(this.px(d), y + h)
    f.stroke({ width: 1, color: COLORS.panelGrid, alpha: 0.9 })
    f.rect(x, y, w, h).stroke({ width: 1, color: COLORS.axis })
    T('Regime map · hole entries (δ, v)', 12, 10, 12.5, COLORS.text)
    for (let v = 0; v <= vt; v += vStep) T(String(v), x - 5, this.py(v), 9, COLORS.textDim, 1, 0.5, true)
    for (let d = 0; d < R - dStep / 5; d += dStep) T(String(+d.toPrecision(6)), this.px(d), y + h + 4, 9, COLORS.textDim, 0.5, 0, true)
    T(`R=${+R.toFixed(2)}`, this.px(R), y + h + 4, 9, COLORS.textDim, 0.5, 0, true)
    T('δ  offset from hole centre, px', x + w / 2, y + h + 17, 10, COLORS.textDim, 0.5, 0)
    const vl = T('v at the lip, px/s', 12, y + h / 2, 10, COLORS.textDim, 0.5, 0.5)
    vl.rotation = -Math.PI / 2

    // regions: skip above v_skip(δ); clean capture inside the capture window δ ≤ δ_eff(v)
    const cv = this.curves.clear()
    const curves = regimeCurves(c, 80, vt)
    const skipPts: number[] = []
    for (const p of curves.skip) skipPts.push(this.px(p.delta), this.py(p.speed))
    cv.poly([this.px(0), this.py(vt), ...skipPts, this.px(R), this.py(vt)]).fill({ color: SKIP, alpha: 0.09 })
    const winPts: number[] = []
    for (const p of curves.window) winPts.push(this.px(p.delta), this.py(p.speed))
    cv.poly([this.px(0), this.py(0), ...winPts, this.px(0), this.py(Math.min(c.V_MAX, vt))]).fill({
      color: WINDOW,
      alpha: 0.08,
    })
    // the skip curve only where it is inside the plot (a larger g puts its top above the axis)
    const top = this.py(vt) + 0.5
    let pen = false
    for (let i = 0; i < skipPts.length; i += 2) {
      const inside = skipPts[i + 1]! > top
      if (inside && pen) cv.lineTo(skipPts[i]!, skipPts[i + 1]!)
      else if (inside) cv.moveTo(skipPts[i]!, skipPts[i + 1]!)
      pen = inside
    }
    cv.stroke({ width: 2, color: SKIP })
    cv.moveTo(winPts[0]!, winPts[1]!)
    for (let i = 2; i < winPts.length; i += 2) cv.lineTo(winPts[i]!, winPts[i + 1]!)
    cv.stroke({ width: 2, color: WINDOW })
    const dashed = (d: number, color: number, top: number): void => {
      if (!(d > 0 && d < R)) return
      const X = this.px(d)
      for (let yy = top; yy < y + h; yy += 8) cv.moveTo(X, yy).lineTo(X, Math.min(yy + 4, y + h))
      cv.stroke({ width: 1.5, color, alpha: 0.9 })
    }
    const dCog = curves.cog
    const dRoll = curves.roll
    dashed(dCog, COG, y - 12)
    dashed(dRoll, ROLL, y)

    // curve names
    const vs0 = vSkip(0, R, r, c.GRAVITY)
    T('skip', this.px(R * 0.8), this.py(Math.min(vt - 20, (vSkip(R * 0.8, R, r, c.GRAVITY) + vt) / 2)), 11, SKIP, 0.5, 0.5)
    T(`v_skip(δ)  ${Math.round(vs0)} at δ=0`, x + 6, this.py(vs0) - 3, 9, SKIP, 0, 1, true)
    T('clean capture', this.px(R * 0.3), this.py(c.V_MAX * 0.35), 11, WINDOW, 0.5, 0.5)
    T(`δ_eff(v), V_MAX ${Math.round(c.V_MAX)}`, this.px(R * 0.3), this.py(c.V_MAX * 0.35) + 14, 9, WINDOW, 0.5, 0.5, true)
    // line names above the plot, each starting at its line
    if (dCog > 0 && dCog < R) T(`COG gate R−r/2 = ${dCog.toFixed(1)}`, this.px(dCog), y - 14, 9, COG, dCog > R * 0.6 ? 0.8 : 0, 1, true)
    if (dRoll > 0 && dRoll < R) T(`roll ratio ${c.RIM_ROLL_RATIO}: δ = ${dRoll.toFixed(1)}`, this.px(dRoll), y - 3, 9, ROLL, 0.5, 1, true)

    // legend
    const ly = y + h + 40
    HOLE_EVENT_TYPES.forEach((type, i) => {
      const lx = x + (i % 3) * 112
      const row = ly + Math.floor(i / 3) * 16
      f.circle(lx + 4, row, 4).fill({ color: eventColor(type) })
      T(type, lx + 12, row, 10, COLORS.text, 0, 0.5)
    })
    T('lines: red v_skip(δ) · green capture window · dashed: roll ratio, COG gate', x - 30, ly + 34, 9, COLORS.textDim)
    this.staticLayer.cacheAsTexture(false)
    this.staticLayer.cacheAsTexture({ resolution: 2, antialias: true })
    this.clear()
  }

  clear(): void {
    this.head = 0
    this.count = 0
    this.dots.particleChildren.length = 0
    this.dots.update()
    this.lastPlayer = null
    this.marker.clear()
    this.markerText.text = ''
  }

  /** Plots the frame's hole entries (events that carry δ and v). */
  onEvents(events: DemoEvent[]): void {
    for (const e of events) {
      if (e.delta === undefined || e.speed === undefined || e.holeIndex < 0 || !isHoleEvent(e.type)) continue
      if (e.delta > this.R || e.delta < 0) continue
      const p = this.particles[this.head]!
      p.x = this.px(e.delta)
      p.y = this.py(e.speed)
      p.tint = eventColor(e.type)
      this.head = (this.head + 1) % DOTS
      if (this.count < DOTS) {
        this.count++
        this.dots.particleChildren.push(p)
        this.dots.update()
      }
      this.dirty = true
      this.plotted++
      if (e.player) this.lastPlayer = e
    }
  }

  draw(): void {
    if (!this.dirty) return
    this.dirty = false
    // older dots fade: the newest is opaque, the oldest of the buffer at 30 %
    for (let k = 0; k < this.count; k++) {
      const i = (this.head - 1 - k + DOTS) % DOTS
      const p = this.particles[i]!
      const a = 1 - (0.7 * k) / DOTS
      p.color = packColor(((p.tint as number) & 0xffffff) >>> 0, a)
    }
    const e = this.lastPlayer
    const m = this.marker.clear()
    if (e && e.delta !== undefined && e.speed !== undefined) {
      const X = this.px(e.delta)
      const Y = this.py(e.speed)
      m.circle(X, Y, 7).stroke({ width: 2, color: eventColor(e.type) })
      m.circle(X, Y, 10).stroke({ width: 1, color: 0xffffff, alpha: 0.5 })
      const s = `your throw: ${e.type}  δ ${e.delta.toFixed(1)}  v ${Math.round(e.speed)}`
      if (this.markerText.text !== s) this.markerText.text = s
      if (this.markerText.style.fill !== eventColor(e.type)) this.markerText.style.fill = eventColor(e.type)
      this.markerText.position.set(this.plot.x - 30, this.plot.y + this.plot.h + 92)
    }
  }
}
