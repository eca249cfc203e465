// The tuning panel (lil-gui): one field per key of DEFAULT_CONFIG. A change is checked by building a
// simulation with it (createBallPhysics + addPanel), so the message shown is the core's own RangeError;
// a valid set waits in game.pending and takes effect at the next throw, burst or new game.
import GUI, { type Controller } from 'lil-gui'
import { CONFIG_CHOICES, DEFAULT_CONFIG, PHYSICAL_CONFIG, TABULATED_CONFIG, resolveConfig, type BallPhysicsConfig, type ConfigOverrides } from '../src/index'
import { Game } from './game'

type Key = keyof BallPhysicsConfig

/** Decimals to show `v` with: `usual`, or more for a value below its last place (up to 20). */
function shownDecimals(v: number, usual: number): number {
  const a = Math.abs(v)
  if (a === 0 || a >= 10 ** -usual) return usual
  return Math.min(20, Math.ceil(-Math.log10(a)) + 2)
}

const DECIMALS: Partial<Record<Key, number>> = {
  GRAVITY: 1,
  V_SKIP_MAX: 1,
  RIM_RESTITUTION: 3,
  RIM_FRICTION: 3,
  RIM_ROLL_RATIO: 3,
  RIM_ROLL_FRICTION: 3,
  RIM_ROLL_MAX_TURNS: 3,
  MAX_STEP: 3,
  MAX_EVENT_PASSES: 0,
}

export interface Tuning {
  gui: GUI
  /** refreshes the status line (pending / applied) */
  update(): void
  /** sets one key as the panel would (validated; pending until the next throw, burst or new game) */
  set(key: Key, value: unknown): void
}

export function createTuning(container: HTMLElement, status: HTMLElement, game: Game): Tuning {
  const gui = new GUI({ container, title: 'Physics constants', width: 288 })
  const values = { ...DEFAULT_CONFIG } as BallPhysicsConfig
  let overrides: ConfigOverrides = {}
  let error = ''
  const controllers = new Map<Key, Controller>()

  const show = (): void => {
    status.classList.toggle('error', error !== '')
    status.classList.toggle('pending', error === '' && game.pending !== null)
    if (error) status.textContent = error
    else if (game.pending !== null) {
      status.textContent = 'Valid. Applies to the next throw (the panel is cleared then).'
      // a tabulated world of another ball or hole size or inertia finds its rim table's rows when it is made
      const c = resolveConfig(game.pending)
      const d = DEFAULT_CONFIG
      if (c.RIM_MODEL === 'tabulated' && (c.BALL_RADIUS !== d.BALL_RADIUS || c.HOLE_RADIUS !== d.HOLE_RADIUS || c.BALL_INERTIA !== d.BALL_INERTIA)) {
        status.textContent += ' The tabulated model builds its rim table for these sizes first: about a second for small balls, up to 15 s near the hole\'s size (once per page).'
      }
    }
    else if (Object.keys(game.overrides).length === 0) status.textContent = 'Design values.'
    else status.textContent = `Running with: ${Object.keys(game.overrides).join(', ')}.`
  }

  const sync = (config: Readonly<BallPhysicsConfig>): void => {
    for (const [k, c] of controllers) {
      ;(values as Record<Key, unknown>)[k] = config[k]
      // a value too small for the key's usual decimals shows three significant digits instead of 0.0
      const d = DECIMALS[k]
      const v = config[k]
      if (d !== undefined && typeof v === 'number') c.decimals(shownDecimals(v, d))
      c.updateDisplay()
      c.domElement.classList.remove('invalid')
    }
  }

  const change = (key: Key, value: unknown): void => {
    const next: ConfigOverrides = { ...overrides, [key]: value }
    // a key set back to its design value is no override
    if (Object.is(value, DEFAULT_CONFIG[key])) delete next[key]
    // GRAVITY and V_SKIP_MAX are one fact: the one edited last wins, the other is derived
    if (key === 'GRAVITY') delete next.V_SKIP_MAX
    if (key === 'V_SKIP_MAX') delete next.GRAVITY
    const result = Game.validate(next)
    if (!result.ok) {
      error = result.error
      const c = controllers.get(key)
      // the refused value stays readable in its field (a MAX_STEP of 1e-5 showed as 0.000)
      const d = DECIMALS[key]
      if (c !== undefined && d !== undefined && typeof value === 'number') {
        c.decimals(shownDecimals(value, d))
        c.updateDisplay()
      }
      c?.domElement.classList.add('invalid')
      show()
      return
    }
    error = ''
    overrides = next
    game.setPending(next)
    sync(result.config)
    show()
  }

  for (const key of Object.keys(DEFAULT_CONFIG) as Key[]) {
    // keys that name a choice get a drop-down of their allowed values
    const choices = (CONFIG_CHOICES as Record<string, readonly string[]>)[key]
    const c = (choices ? gui.add(values, key, [...choices]) : gui.add(values, key)).name(key)
    const d = DECIMALS[key]
    if (d !== undefined) c.decimals(d)
    c.domElement.dataset.key = key
    c.onFinishChange((v: unknown) => change(key, v))
    controllers.set(key, c)
  }
  const preset = (p: Readonly<ConfigOverrides>): void => {
    const result = Game.validate(p)
    if (!result.ok) return
    overrides = { ...p }
    error = ''
    game.setPending(overrides)
    sync(result.config)
    show()
  }
  const actions = {
    designValues: (): void => {
      overrides = {}
      error = ''
      game.setPending({})
      sync(DEFAULT_CONFIG)
      show()
    },
    /** a preset over the design values (pending like any change) */
    physicalPreset: (): void => preset(PHYSICAL_CONFIG),
    tabulatedPreset: (): void => preset(TABULATED_CONFIG),
    applyNow: (): void => {
      if (error) {
        // a field with a refused value goes back to the value in effect: what runs is what the panel shows
        error = ''
        const result = Game.validate(overrides)
        if (result.ok) sync(result.config)
      }
      game.reset()
      show()
    },
  }
  gui.add(actions, 'designValues').name('Reset to design values').domElement.dataset.key = 'designValues'
  gui.add(actions, 'physicalPreset').name('Physical preset (fitted stages)').domElement.dataset.key = 'physicalPreset'
  gui.add(actions, 'tabulatedPreset').name('Tabulated reference (rides the lip)').domElement.dataset.key = 'tabulatedPreset'
  gui.add(actions, 'applyNow').name('Apply now (new game)').domElement.dataset.key = 'applyNow'
  show()
  return { gui, update: show, set: change }
}
