// The built-in ball-toss panel: 5 rows of 5 holes, the launch point below them. With ROLLING_DECEL =
// 300 px/s² a throw reaches the first row (80 px up) from power ≈ 0.04 and the top row (320 px up) from
// power ≈ 0.48: the top row's sweet spot is the middle of the meter, and the upper third arrives at the
// lower rows fast enough to skip them for most aims (docs/design.md §1).
import type { BallPhysics } from './api/createBallPhysics.js'
import { addHoles } from './commands/holes.js'
import { checkWorld, describe, readSpec } from './check.js'
import type { BallWorld } from './world/createWorld.js'

export interface PanelHole {
  x: number
  y: number
  value: number
}

export interface PanelLayout {
  /** px */
  width: number
  height: number
  /** where throws start, px */
  launch: { x: number; y: number }
  holes: readonly PanelHole[]
}

const ROW_Y = [370, 310, 250, 190, 130] as const
const ROW_VALUE = [10, 20, 30, 50, 100] as const
const COL_X = [50, 130, 210, 290, 370] as const

export const DEFAULT_PANEL: Readonly<PanelLayout> = Object.freeze({
  width: 420,
  height: 480,
  launch: Object.freeze({ x: 210, y: 450 }),
  holes: Object.freeze(
    ROW_Y.flatMap((y, row) => COL_X.map((x) => Object.freeze({ x, y, value: ROW_VALUE[row]! }))),
  ),
})

/**
 * Adds a layout's holes to a simulation (or a bare world), all or nothing: every hole is checked before the
 * first is added. Returns their entity ids in layout order.
 */
export function addPanel(target: BallPhysics | BallWorld, layout: PanelLayout = DEFAULT_PANEL): number[] {
  if (target === null || typeof target !== 'object') throw new TypeError(`addPanel: target must be a simulation or a world, got ${describe(target)}`)
  // a target that is neither is refused in addPanel's name (addHoles named itself)
  const world = checkWorld('addPanel', 'step' in target && 'world' in target ? target.world : target)
  if (layout === null || typeof layout !== 'object') throw new TypeError(`addPanel: layout must be a panel layout, got ${describe(layout)}`)
  const holes = readSpec('layout', layout, ['width', 'height', 'launch', 'holes'] as const).holes
  if (!Array.isArray(holes)) throw new TypeError(`layout.holes must be an array, got ${describe(holes)}`)
  return addHoles(world, holes as readonly PanelHole[])
}
