// "Where your throw goes": the outcome map of the running config — which hole every (power, aim) from the
// launch point ends in (outcomeMap, the engine's own exact simulation) — drawn into a canvas of the side
// panel, with the player's current power and aim marked. It is computed a few rows a frame (a full map is
// 120 × 160 throws, about 60 ms), again whenever the config changes.
import { DEFAULT_PANEL, outcomeMap, type OutcomeMapSpec, type OutcomeScene } from '../src/index'
import { wallsFor, type Game } from './game'

export const MAP_SPEC: OutcomeMapSpec = {
  from: DEFAULT_PANEL.launch,
  power: { min: 0, max: 1, steps: 120 },
  angle: { min: -1.3, max: 1.3, steps: 160 },
}
/** rows computed per frame */
const ROWS_PER_FRAME = 12
const HUES = [210, 30, 120, 280, 0]

/** The colour of hole h (layout order): hue by column, darker toward the top rows (which score more). */
function colour(h: number): [number, number, number] {
  if (h < 0) return [22, 28, 42]
  const hue = HUES[h % 5]!
  const light = (72 - 9 * Math.floor(h / 5)) / 100
  // hsl → rgb at 65 % saturation
  const c = (1 - Math.abs(2 * light - 1)) * 0.65
  const x = c * (1 - Math.abs(((hue / 60) % 2) - 1))
  const m = light - c / 2
  const [r, g, b] = hue < 60 ? [c, x, 0] : hue < 120 ? [x, c, 0] : hue < 180 ? [0, c, x] : hue < 240 ? [0, x, c] : hue < 300 ? [x, 0, c] : [c, 0, x]
  return [Math.round(255 * (r + m)), Math.round(255 * (g + m)), Math.round(255 * (b + m))]
}

export class OutcomeView {
  /** hole index (layout order, −1 none) of each cell, row-major by power (row 0 = power 0) then aim */
  readonly cells = new Int16Array(MAP_SPEC.power.steps * MAP_SPEC.angle.steps)
  /** rows computed for the current config */
  rows = 0
  private generation = -1
  private readonly image: ImageData
  private readonly ctx: CanvasRenderingContext2D

  constructor(
    canvas: HTMLCanvasElement,
    private readonly game: Game,
  ) {
    canvas.width = MAP_SPEC.angle.steps
    canvas.height = MAP_SPEC.power.steps
    this.ctx = canvas.getContext('2d')!
    this.image = this.ctx.createImageData(canvas.width, canvas.height)
  }

  get done(): boolean {
    return this.rows === MAP_SPEC.power.steps
  }

  private scene(): OutcomeScene {
    const panel = this.game.panel
    return { config: this.game.overrides, holes: panel.holes.map((h) => ({ x: h.x, y: h.y, value: h.value })), walls: wallsFor(panel) }
  }

  /** Computes a few more rows (a new config starts over), then draws the map and the marker. */
  frame(power: number, angle: number): void {
    if (this.generation !== this.game.generation) {
      this.generation = this.game.generation
      this.rows = 0
      this.cells.fill(-1)
    }
    if (!this.done) {
      const to = Math.min(MAP_SPEC.power.steps, this.rows + ROWS_PER_FRAME)
      try {
        this.cells.set(outcomeMap(this.scene(), MAP_SPEC, { from: this.rows, to }), this.rows * MAP_SPEC.angle.steps)
        this.rows = to
      } catch (e) {
        // a config the map cannot be computed for: the map stops (grey) and says why; the game goes on
        console.warn(`outcome map: ${e instanceof Error ? e.message : String(e)}`)
        this.rows = MAP_SPEC.power.steps
      }
    }
    this.draw(power, angle)
  }

  private draw(power: number, angle: number): void {
    const W = MAP_SPEC.angle.steps
    const H = MAP_SPEC.power.steps
    const px = this.image.data
    for (let row = 0; row < H; row++) {
      // power grows upward
      const y = H - 1 - row
      for (let col = 0; col < W; col++) {
        const [r, g, b] = row < this.rows ? colour(this.cells[row * W + col]!) : [70, 76, 90]
        const o = 4 * (y * W + col)
        px[o] = r
        px[o + 1] = g
        px[o + 2] = b
        px[o + 3] = 255
      }
    }
    this.ctx.putImageData(this.image, 0, 0)
    // the player's power and aim
    const A = MAP_SPEC.angle
    const x = ((angle - A.min) / (A.max - A.min)) * (W - 1)
    const y = H - 1 - power * (H - 1)
    this.ctx.strokeStyle = '#111'
    this.ctx.lineWidth = 1
    this.ctx.beginPath()
    this.ctx.moveTo(x, 0)
    this.ctx.lineTo(x, H)
    this.ctx.moveTo(0, y)
    this.ctx.lineTo(W, y)
    this.ctx.stroke()
  }
}
