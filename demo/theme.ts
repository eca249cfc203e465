// Colours and sizes shared by the views. Event and mode colours are also used by the DOM legend.

export const COLORS = {
  page: 0x0a0f1a,
  panel: 0x111a2c,
  panelEdge: 0x2c3d5e,
  panelGrid: 0x1a2640,
  lip: 0xc9d4e8,
  lipShadow: 0x05080f,
  holeInside: 0x020409,
  cog: 0x7f8ea8,
  text: 0xe6ecf5,
  textDim: 0x8a97ad,
  axis: 0x3a4a6a,
  meterBack: 0x1a2438,
  aim: 0xfbd34d,
} as const

// keyed by name (not by the core's union types) so that event types or modes added to the core later
// still draw, in grey, until they get a colour here
export const EVENT_COLORS: Readonly<Record<string, number>> = {
  capture: 0x3ddc84,
  skip: 0xff5c7a,
  bounce: 0xffa24c,
  rimRoll: 0x4cc9ff,
  lipOut: 0xc77dff,
  nearMiss: 0x8a94a6,
  rest: 0x5b6578,
  wall: 0x9fb4d8,
  gutter: 0x6b7890,
  collision: 0xffe066,
}
export function eventColor(type: string): number {
  return EVENT_COLORS[type] ?? 0x8a94a6
}

/** Hole events (the ones flashed at holes and plotted on the regime map), in legend order. */
export const HOLE_EVENT_TYPES = ['capture', 'skip', 'bounce', 'rimRoll', 'lipOut', 'nearMiss'] as const
const HOLE_EVENTS: ReadonlySet<string> = new Set(HOLE_EVENT_TYPES)
export function isHoleEvent(type: string): boolean {
  return HOLE_EVENTS.has(type)
}

export const MODE_COLORS: Readonly<Record<string, number>> = {
  rolling: 0xf4f7fb,
  rimRoll: 0x4cc9ff,
  captured: 0x3ddc84,
  resting: 0x7d879a,
  held: 0xd9b36c,
  out: 0x4a5878,
}
export function modeColor(mode: string): number {
  return MODE_COLORS[mode] ?? 0x7d879a
}
/** Ball colour when "colour by mode" is off. */
export const PLAIN_BALL = 0xd8dee9
/** The player's balls when "colour by mode" is off, and the tray of balls left. */
export const PLAYER_BALL = 0xfbe7a1

/** Colour of a hole's value label by points. */
export function valueColor(value: number): number {
  if (value >= 100) return 0xf472b6
  if (value >= 50) return 0xfbbf24
  if (value >= 30) return 0x4ade80
  if (value >= 20) return 0x5cc8ff
  return 0x9aa7bd
}

export const FONT = 'ui-sans-serif, system-ui, "Segoe UI", Roboto, "Helvetica Neue", Arial, sans-serif'
export const MONO = 'ui-monospace, "SFMono-Regular", Menlo, Consolas, "DejaVu Sans Mono", monospace'

export function hex(c: number): string {
  return `#${c.toString(16).padStart(6, '0')}`
}
