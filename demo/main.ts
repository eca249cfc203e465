// The Positron Stakes ball-toss demo: a playable panel on the headless physics core, with an inspector
// (mode colours, velocity vectors, event flashes, a live regime map), multi-ball and stress modes and a
// tuning panel. Physics runs at a fixed 120 Hz; drawing interpolates between the last two steps.
import { Application, Container } from 'pixi.js'
import { Game, STRESS_BALLS, type DemoEvent } from './game'
import { ThrowInput } from './input'
import { PanelView, type InspectorOptions } from './panelView'
import { RegimeView } from './regimeView'
import { MAP_SPEC, OutcomeView } from './outcomeView'
import { BALL_MODE_NAMES, EVENT_TYPE_NAMES, type ThrowFailure, type ThrowSolution } from '../src/index'
import { BallMode } from '../src/ecs'
import type { ShotReply } from './shotCall'
import { PLAIN_BALL, PLAYER_BALL, eventColor, hex, modeColor } from './theme'
import { createTuning } from './tuning'

/** Logical size of the drawing; it is scaled to fit the stage element. */
const STAGE_W = 900
const STAGE_H = 545
const PANEL_AT = { x: 22, y: 22 }
const REGIME_AT = { x: 500, y: 12 }

function el<T extends HTMLElement = HTMLElement>(id: string): T {
  const e = document.getElementById(id)
  if (!e) throw new Error(`demo: missing element #${id}`)
  return e as T
}

/** True when WebGL is rendered in software (no GPU). */
function softwareGL(): boolean {
  try {
    const gl = document.createElement('canvas').getContext('webgl')
    if (!gl) return true
    const info = gl.getExtension('WEBGL_debug_renderer_info')
    const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER))
    gl.getExtension('WEBGL_lose_context')?.loseContext()
    return /swiftshader|llvmpipe|softpipe|software/i.test(name)
  } catch {
    return true
  }
}

/** fps and physics time, averaged over windows of at least half a second. */
class Meter {
  fps = 0
  physicsMs = 0
  /** JS time per frame: physics plus preparing the drawing (not the GPU's rasterising), ms */
  frameMs = 0
  stepsPerFrame = 0
  private frames = 0
  private ms = 0
  private js = 0
  private steps = 0
  private since = performance.now()

  frame(now: number, physicsMs: number, steps: number, jsMs: number): boolean {
    this.frames++
    this.ms += physicsMs
    this.js += jsMs
    this.steps += steps
    const span = now - this.since
    if (span < 500) return false
    this.fps = (this.frames * 1000) / span
    this.physicsMs = this.ms / this.frames
    this.frameMs = this.js / this.frames
    this.stepsPerFrame = this.steps / this.frames
    this.frames = 0
    this.ms = 0
    this.js = 0
    this.steps = 0
    this.since = now
    return true
  }
}

async function main(): Promise<void> {
  const stageEl = el('stage')
  const params = new URLSearchParams(location.search)
  const stressN = Math.max(1000, Math.min(100_000, Number(params.get('stress')) || STRESS_BALLS))
  el('stress').textContent = `Stress ${stressN % 1000 === 0 ? `${stressN / 1000}k` : stressN.toLocaleString('en-US')}`

  // software GL (SwiftShader, llvmpipe: headless browsers, no GPU) is fill-rate bound: skip MSAA there
  const software = softwareGL()
  const aa = params.get('aa')
  const app = new Application()
  await app.init({
    background: 0x0a0f1a,
    resizeTo: stageEl,
    antialias: aa === null ? !software : aa !== '0',
    autoDensity: true,
    resolution: Math.min(2, window.devicePixelRatio || 1),
    preference: 'webgl',
  })
  stageEl.appendChild(app.canvas)

  const game = new Game()
  game.reset()
  const panel = new PanelView(game)
  const regime = new RegimeView()
  const outcomes = new OutcomeView(el<HTMLCanvasElement>('outcome-map'), game)
  const world = new Container()
  panel.root.position.set(PANEL_AT.x, PANEL_AT.y)
  regime.root.position.set(REGIME_AT.x, REGIME_AT.y)
  world.addChild(panel.root, regime.root)
  app.stage.addChild(world)

  // Two arrangements of the drawing: side by side (the regime map right of the panel), or stacked (the map
  // under the panel) where that draws the panel larger: a portrait phone drew the panel side by side at
  // about 185 px wide. The stacked size is measured from the two views once they are first drawn.
  let stackedAt: { x: number; y: number; W: number; H: number } | null = null
  const measureStacked = (): void => {
    const box = (c: Container): { x: number; y: number; width: number; height: number } => {
      const b = c.getLocalBounds() // a bounds object pixi reuses: copied at once
      return { x: b.x, y: b.y, width: b.width, height: b.height }
    }
    const pb = box(panel.root)
    const rb = box(regime.root)
    const x = PANEL_AT.x + pb.x + Math.max(0, (pb.width - rb.width) / 2) - rb.x
    const y = PANEL_AT.y + pb.y + pb.height + 16 - rb.y
    const W = Math.ceil(Math.max(PANEL_AT.x + pb.x + pb.width, x + rb.x + rb.width) + PANEL_AT.x + pb.x)
    stackedAt = { x, y, W, H: Math.ceil(y + rb.y + rb.height + 12) }
  }
  let stacked = false
  const layout = (): void => {
    const w = app.screen.width
    const h = app.screen.height
    const side = Math.min(w / STAGE_W, h / STAGE_H)
    const S = stackedAt
    const tall = S === null ? 0 : Math.min(w / S.W, h / S.H)
    stacked = S !== null && tall > side * 1.1
    const [W, H, s] = S !== null && stacked ? [S.W, S.H, tall] : [STAGE_W, STAGE_H, side]
    if (S !== null && stacked) regime.root.position.set(S.x, S.y)
    else regime.root.position.set(REGIME_AT.x, REGIME_AT.y)
    world.scale.set(s)
    world.position.set(Math.round((w - W * s) / 2), Math.round(Math.min(12 * s, (h - H * s) / 2)))
  }
  app.renderer.on('resize', layout)
  layout()

  const opts: InspectorOptions = { modeColors: true, vectors: false, labels: true }
  const showModes = el<HTMLInputElement>('show-modes')
  const showVectors = el<HTMLInputElement>('show-vectors')
  const showLabels = el<HTMLInputElement>('show-labels')
  const syncOpts = (): void => {
    opts.modeColors = showModes.checked
    opts.vectors = showVectors.checked
    opts.labels = showLabels.checked
  }
  for (const c of [showModes, showVectors, showLabels]) {
    c.addEventListener('change', () => {
      syncOpts()
      c.blur() // Space charges a throw, not the checkbox
    })
  }
  syncOpts()

  // the legend names the colours the balls are drawn in: by mode, or (colouring off) the player's and the rest
  const legend = (): void => {
    const keys: Array<[string, number]> = showModes.checked
      ? (BALL_MODE_NAMES as readonly string[]).filter((m) => m !== 'out' && m !== 'held').map((m) => [m, modeColor(m)]) // held balls wait unseen in the launcher
      : [['your ball', PLAYER_BALL], ['other balls', PLAIN_BALL]]
    el('mode-legend').innerHTML = keys.map(([m, c]) => `<span><i style="background:${hex(c)}"></i>${m}</span>`).join('')
  }
  showModes.addEventListener('change', legend)
  legend()

  // ---- input: pointer, keyboard and the test hook all drive the same ThrowInput ----
  const now = (): number => performance.now() / 1000
  const input = new ThrowInput((request) => {
    // a throw that cannot be made says why on the status line (it was dropped without a word)
    const blocked = game.throwBlocked
    if (!game.throwPlayer(request)) {
      if (blocked !== null) callStatus.textContent = blocked
    } else if (!calling && awaiting < 0) {
      callStatus.textContent = '' // a refusal shown before is stale now
      syncWaiting() // the ball waits at the launcher: say so now, not a frame later
    }
  })
  const canvas = app.canvas
  const launch = game.panel.launch
  let dragging = false
  const local = (e: PointerEvent): { x: number; y: number } => {
    const r = canvas.getBoundingClientRect()
    return panel.root.toLocal({ x: e.clientX - r.left, y: e.clientY - r.top })
  }
  const inPanel = (p: { x: number; y: number }): boolean =>
    p.x >= 0 && p.y >= 0 && p.x <= game.panel.width && p.y <= game.panel.height
  const inMeter = (p: { x: number; y: number }): boolean => {
    const m = panel.meter
    return p.x >= m.x - 8 && p.x <= m.x + m.w + 8 && p.y >= m.y - 8 && p.y <= m.y + m.h + 24
  }
  // call your shot: while on, a click on a hole throws the player's next ball into it (the throw solver)
  let calling = false
  const callBtn = el<HTMLButtonElement>('call-shot')
  const callStatus = el('call-status')
  /** what the status line says to a burst, Clear or Stress while a replay plays (they do nothing then) */
  const REPLAY_WAITS = 'A replay is playing: bursts, Clear and Stress wait until it ends (press them then).'
  const setCalling = (on: boolean): void => {
    calling = on
    callBtn.setAttribute('aria-pressed', String(on))
    callStatus.textContent = on ? 'Click a hole: your next ball is thrown to drop in it.' : ''
  }
  const holeAt = (p: { x: number; y: number }): number => {
    const r = game.config.HOLE_RADIUS + 8
    return game.panel.holes.findIndex((h) => (h.x - p.x) ** 2 + (h.y - p.y) ** 2 <= r * r)
  }
  const showAnswer = (i: number, answer: ThrowSolution | ThrowFailure | null): void => {
    const ms = game.lastCall?.ms ?? 0
    const value = game.panel.holes[i]!.value
    if (answer === null) callStatus.textContent = game.callBlocked ?? ''
    else if (answer.found) {
      const deg = (answer.angle * 180) / Math.PI
      callStatus.textContent = `Hole ${value}: power ${answer.power.toFixed(3)}, aim ${deg.toFixed(1)}°, from x = ${answer.from.x.toFixed(0)}; margin ±${answer.margin.power.toFixed(3)} power, ±${((answer.margin.angle * 180) / Math.PI).toFixed(2)}° (solved in ${ms.toFixed(0)} ms)`
    } else {
      // the solver names holes by entity id; the player knows them by value
      const reason = answer.reason.replace(/hole (\d+)/g, (_m, id: string) => `hole ${game.panel.holes[game.holeIndex(Number(id))]?.value ?? id}`)
      callStatus.textContent = `Hole ${value}: no throw found (${reason})`
    }
  }
  // the hole of the call whose answer the status line waits for (-1: none): a call cancelled meanwhile (a
  // throw, a burst, a reset) says so at once, not when its answer comes
  let awaiting = -1
  // the solver runs in a worker when the page can start one (the panel waits for its answer, the page
  // does not); here otherwise, or when the worker fails
  let solver: Worker | null = null
  try {
    solver = new Worker(new URL('./solveWorker.js', import.meta.url), { type: 'module' })
  } catch {
    solver = null
  }
  const solveHere = (i: number): void => showAnswer(i, game.callShot(i))
  if (solver !== null) {
    solver.onmessage = (e: MessageEvent<ShotReply>) => {
      const reply = e.data
      const s = game.solving
      if (s === null || s.token !== reply.token) return // cancelled meanwhile: a throw, a burst, a reset
      awaiting = -1
      if ('error' in reply) {
        game.cancelCall()
        callStatus.textContent = `The solver failed: ${reply.error}`
        return
      }
      showAnswer(s.holeIndex, game.finishCall(reply.token, reply.answer, reply.ms))
    }
    solver.onerror = (e) => {
      e.preventDefault()
      solver?.terminate()
      solver = null
      const s = game.solving
      awaiting = -1
      game.cancelCall()
      // solved here instead, this time and from now on
      if (s !== null) solveHere(s.holeIndex)
    }
  }
  const syncCall = (): void => {
    if (awaiting < 0 || game.solving !== null) return
    callStatus.textContent = `Hole ${game.panel.holes[awaiting]!.value}: call cancelled (a throw, a burst, a clear, the stress mode, a replay or a new game came first)`
    awaiting = -1
  }
  const callAt = (p: { x: number; y: number }): boolean => {
    const i = holeAt(p)
    if (i < 0) return false
    if (game.solving !== null) return true // one call at a time
    if (solver === null) {
      solveHere(i)
      return true
    }
    const call = game.beginCall(i)
    if (call === null) showAnswer(i, null)
    else {
      callStatus.textContent = `Hole ${game.panel.holes[i]!.value}: solving… (the panel waits for the answer)`
      awaiting = i
      solver.postMessage(call)
    }
    return true
  }
  canvas.addEventListener('pointerdown', (e) => {
    if (e.button !== 0) return
    const p = local(e)
    if (calling && inPanel(p)) {
      // a click off the holes while calling throws nothing (a quick click there threw a weak ball and used up
      // one of the ten); the meter and the keys still throw
      e.preventDefault()
      if (!callAt(p)) callStatus.textContent = 'Not on a hole: click a hole to call your shot (or turn Call your shot off to throw with the pointer).'
      return
    }
    if (!inPanel(p) && !inMeter(p)) return
    e.preventDefault()
    canvas.setPointerCapture(e.pointerId)
    dragging = true
    if (inPanel(p) && p.y < launch.y - 4) input.aimAt(p.x, p.y, launch.x, launch.y)
    input.beginCharge(now())
  })
  canvas.addEventListener('pointermove', (e) => {
    const p = local(e)
    if ((dragging || inPanel(p)) && p.y < launch.y - 4) input.aimAt(p.x, p.y, launch.x, launch.y)
  })
  const endDrag = (e: PointerEvent): void => {
    if (!dragging) return
    dragging = false
    if (canvas.hasPointerCapture(e.pointerId)) canvas.releasePointerCapture(e.pointerId)
    if (e.type === 'pointercancel') input.cancel()
    else input.release(now())
  }
  canvas.addEventListener('pointerup', endDrag)
  canvas.addEventListener('pointercancel', endDrag)

  const stressBtn = el('stress')
  // the button shows what the game does, however it changed (a replay refuses the change; Clear and a new
  // game end it)
  const syncStress = (): void => {
    const on = String(game.stressTarget > 0)
    if (stressBtn.getAttribute('aria-pressed') !== on) stressBtn.setAttribute('aria-pressed', on)
  }
  const setStress = (on: boolean): void => {
    if (game.replaying !== null) {
      callStatus.textContent = REPLAY_WAITS
      return
    }
    game.setStress(on ? stressN : 0)
    syncStress()
  }
  // the player's ball held at its spot (contacts on: thrown where other balls are or wait) says so, and how
  // many wait there ahead of it; the line clears when it leaves (it waited unseen behind a burst)
  const WAITING = 'Your ball waits at the launcher'
  const syncWaiting = (): void => {
    const waiting = game.playerWaiting
    const text = callStatus.textContent ?? ''
    const shown = text.startsWith(WAITING)
    if (waiting === null) {
      if (shown) callStatus.textContent = ''
    } else if (text === '' || shown) {
      setText(callStatus, waiting.ahead === 0 ? `${WAITING} until its spot is clear.` : `${WAITING} behind ${waiting.ahead.toLocaleString('en-US')} ${waiting.ahead === 1 ? 'ball' : 'balls'}: it leaves after them.`)
    }
  }
  const newGame = (): void => {
    input.cancel()
    game.reset()
    regime.clear() // the regime map's dots are of the game before
    syncStress()
    if (!calling) callStatus.textContent = '' // a refusal or an answer of the game before
  }
  const typing = (t: EventTarget | null): boolean =>
    t instanceof HTMLElement && (t.tagName === 'INPUT' || t.tagName === 'TEXTAREA' || t.tagName === 'SELECT')
  const onKey = (down: boolean) => (e: KeyboardEvent) => {
    if (typing(e.target) || e.ctrlKey || e.metaKey || e.altKey) return
    if (input.key(e.code, down, e.repeat, now())) {
      e.preventDefault()
      return
    }
    if (!down || e.repeat) return
    switch (e.code) {
      case 'KeyR':
        newGame()
        break
      case 'Digit1':
        burst(10)
        break
      case 'Digit2':
        burst(100)
        break
      case 'Digit3':
        burst(1000)
        break
      case 'KeyS':
        setStress(game.stressTarget === 0)
        break
      case 'KeyL':
        setBurstFrom(game.burstFrom === 'edge' ? 'launcher' : 'edge')
        break
      case 'KeyP':
        game.replayLastRound()
        break
      case 'KeyC':
        setCalling(!calling)
        break
      case 'KeyV':
        showVectors.checked = !showVectors.checked
        syncOpts()
        break
      default:
        return
    }
    e.preventDefault()
  }
  window.addEventListener('keydown', onKey(true))
  window.addEventListener('keyup', onKey(false))
  window.addEventListener('blur', () => input.blur())

  // a burst after the game is over plays for show: the score stands (the status line says so)
  function burst(n: number): void {
    if (game.replaying !== null) callStatus.textContent = REPLAY_WAITS
    else if (game.gameOver) callStatus.textContent = 'Game over: the score stands, and bursts play for show. Start a new game to score.'
    game.burst(n)
  }
  const button = (id: string, fn: () => void): void => {
    const b = el<HTMLButtonElement>(id)
    b.addEventListener('click', () => {
      fn()
      b.blur() // so that Space charges a throw instead of pressing the button again
    })
  }
  button('reset', newGame)
  for (const n of [10, 100, 1000]) button(`multi-${n}`, () => burst(n))
  button('stress', () => setStress(game.stressTarget === 0))
  button('clear-balls', () => {
    if (game.replaying !== null) callStatus.textContent = REPLAY_WAITS
    game.clearExtra()
    syncStress()
  })
  button('call-shot', () => setCalling(!calling))
  const replayBtn = el<HTMLButtonElement>('replay')
  button('replay', () => game.replayLastRound())
  const syncReplay = (): void => {
    // the refusals a replay gave go with it
    if (game.replaying === null && callStatus.textContent?.startsWith('A replay is playing')) callStatus.textContent = ''
    const can = game.lastRound !== null && game.replaying === null
    if (replayBtn.disabled === can) replayBtn.disabled = !can
    const pressed = String(game.replaying !== null)
    if (replayBtn.getAttribute('aria-pressed') !== pressed) replayBtn.setAttribute('aria-pressed', pressed)
    const label = game.replaying !== null ? 'Replaying…' : 'Replay round'
    if (replayBtn.textContent !== label) replayBtn.textContent = label
  }

  const tuning = createTuning(el('gui'), el('tuning-status'), game)
  // ball-ball contacts, beside the multi-ball buttons: the same key as the tuning panel's drop-down
  // cycles off → exact ('on') → fixed tick → off
  const contactsBtn = el<HTMLButtonElement>('contacts')
  const contactsMode = () => (game.pending ?? game.overrides).BALL_COLLISIONS ?? 'off'
  const CONTACT_LABEL = { off: 'off', on: 'on · exact', fixed: 'fixed · tick' } as const // the config's values first, as the tuning panel names them
  // the label follows the key, however it was set (this button, the drop-down, a preset, a reset)
  const syncContacts = (): void => {
    const mode = contactsMode()
    const pressed = String(mode !== 'off')
    if (contactsBtn.getAttribute('aria-pressed') !== pressed) contactsBtn.setAttribute('aria-pressed', pressed)
    const label = `Contacts: ${CONTACT_LABEL[mode]}`
    if (contactsBtn.textContent !== label) contactsBtn.textContent = label
  }
  button('contacts', () => {
    const now = contactsMode()
    tuning.set('BALL_COLLISIONS', now === 'off' ? 'on' : now === 'on' ? 'fixed' : 'off')
    syncContacts()
  })
  // where the multi-ball bursts come from: the bottom edge, or the launch point (an arcade launcher)
  const fromBtn = el<HTMLButtonElement>('burst-from')
  const setBurstFrom = (from: 'edge' | 'launcher'): void => {
    game.burstFrom = from
    fromBtn.setAttribute('aria-pressed', String(from === 'launcher'))
    fromBtn.textContent = from === 'launcher' ? 'From: launcher' : 'From: bottom edge'
  }
  button('burst-from', () => setBurstFrom(game.burstFrom === 'edge' ? 'launcher' : 'edge'))
  // a button whose label changes keeps the width of its widest label, so the row never reflows (a press
  // of Contacts or From moved the buttons after it, to another line at some widths)
  const steadyWidth = (b: HTMLButtonElement, labels: readonly string[]): void => {
    const shown = b.textContent
    b.style.minWidth = ''
    b.style.boxSizing = 'border-box'
    let widest = 0
    for (const l of labels) {
      b.textContent = l
      widest = Math.max(widest, b.getBoundingClientRect().width)
    }
    b.textContent = shown
    if (widest > 0) b.style.minWidth = `${Math.ceil(widest)}px`
  }
  const steadyButtons = (): void => {
    steadyWidth(contactsBtn, Object.values(CONTACT_LABEL).map((l) => `Contacts: ${l}`))
    steadyWidth(fromBtn, ['From: bottom edge', 'From: launcher'])
    steadyWidth(replayBtn, ['Replay round', 'Replaying…'])
  }
  steadyButtons()
  void document.fonts.ready.then(steadyButtons)
  // lil-gui keeps key events from leaving its controls: a tuning button keeps no focus, so the keys go on
  // working after it (as after the demo's own buttons)
  el('gui').addEventListener('click', (e) => {
    if (e.target instanceof HTMLElement && e.target.closest('button') !== null) e.target.closest('button')!.blur()
  })

  // ---- HUD ----
  const hud = {
    score: el('score'),
    ballsLeft: el('balls-left'),
    ballCount: el('ball-count'),
    fps: el('fps'),
    physicsMs: el('physics-ms'),
    frameMs: el('frame-ms'),
    events: el('events-seen'),
    log: el('event-log'),
    counts: el('event-counts'),
  }
  const ballCountLabel = document.querySelector<HTMLElement>('label[for="ball-count"]')!
  const setText = (e: HTMLElement, s: string): void => {
    if (e.textContent !== s) e.textContent = s
  }
  const describe = (e: DemoEvent): string => {
    const where = e.holeIndex >= 0 ? ` ${e.value}` : ''
    const dv = e.delta !== undefined && e.speed !== undefined ? ` δ${e.delta.toFixed(1)} v${Math.round(e.speed)}` : ''
    return `${e.type}${where}${dv}${e.via ? ` (${e.via})` : ''}`
  }
  let lastLog = ''
  const slowHud = (meter: Meter): void => {
    setText(hud.fps, meter.fps.toFixed(0))
    setText(hud.physicsMs, meter.physicsMs.toFixed(2))
    setText(hud.frameMs, meter.frameMs.toFixed(2))
    setText(hud.events, game.eventsSeen.toLocaleString('en-US'))
    const log = game.recent
      .slice(-8)
      .reverse()
      .map(
        (e) =>
          `<li class="${e.player ? 'player' : ''}"><i style="color:${hex(eventColor(e.type))}">●</i> ${describe(e)}</li>`,
      )
      .join('')
    if (log !== lastLog) {
      hud.log.innerHTML = log
      lastLog = log
    }
    hud.counts.innerHTML = EVENT_TYPE_NAMES.concat()
      .map(
        (t) =>
          `<tr><td><i style="background:${hex(eventColor(t))}"></i>${t}</td><td class="n">${(game.eventCounts[t] ?? 0).toLocaleString('en-US')}</td></tr>`,
      )
      .join('')
    tuning.update()
  }

  // ---- the loop ----
  const meter = new Meter()
  let last = performance.now()
  let shownGeneration = -1
  let frames = 0
  app.ticker.add(() => {
    const t = performance.now()
    const dt = (t - last) / 1000
    last = t
    input.update(t / 1000, Math.min(dt, 0.1))
    const result = game.frame(dt)
    if (shownGeneration !== game.generation) {
      shownGeneration = game.generation
      regime.setConfig(game.config)
    }
    panel.onEvents(result.events)
    regime.onEvents(result.events)
    panel.draw(game.clock.alpha, input, opts)
    regime.draw()
    if (stackedAt === null) {
      measureStacked()
      layout()
    }
    outcomes.frame(input.power, input.angle)
    frames++
    setText(hud.score, String(game.score))
    setText(hud.ballsLeft, String(game.ballsLeft))
    setText(hud.ballCount, game.live.length.toLocaleString('en-US'))
    // balls the launcher holds until their spot is clear (contacts on) are in play but not yet out: say how many
    const held = game.sim.heldCount()
    setText(ballCountLabel, held > 0 ? `Balls in play · ${held.toLocaleString('en-US')} waiting` : 'Balls in play')
    syncReplay()
    syncWaiting()
    syncCall()
    syncContacts()
    syncStress()
    if (meter.frame(t, result.physicsMs, result.steps, performance.now() - t)) slowHud(meter)
  })

  // ---- read-only debug hook for the browser test (and the console) ----
  const hook = {
    get ready() {
      return frames > 0
    },
    get frames() {
      return frames
    },
    get score() {
      return game.score
    },
    get ballsLeft() {
      return game.ballsLeft
    },
    get eventsSeen() {
      return game.eventsSeen
    },
    /** balls riding or rolling on a lip now: distance of the centre from the hole's, and angle about it */
    get lipRiders() {
      const w = game.sim.world
      const out: Array<{ ball: number; distance: number; angle: number }> = []
      for (const b of game.sim.balls()) {
        if (game.sim.ballState(b).mode !== 'rimRoll') continue
        const hole = w.RimContact.hole[w.Ball.rim[b]!]!
        const dx = w.Ball.x[b]! - w.Hole.x[hole]!
        const dy = w.Ball.y[b]! - w.Hole.y[hole]!
        out.push({ ball: b, distance: Math.hypot(dx, dy), angle: Math.atan2(dy, dx) })
      }
      return out
    },
    get eventCounts() {
      return { ...game.eventCounts }
    },
    get recent() {
      return game.recent.map((e) => ({ ...e }))
    },
    get liveBalls() {
      return game.live.length
    },
    /** the deepest overlap of two balls on the panel (rolling, on a rim or resting), px; 0 when none */
    /** where the bursts come from ('edge' or 'launcher') */
    get burstFrom() {
      return game.burstFrom
    },
    /** balls waiting at their spots to be launched (mode 'held': contacts on, thrown onto another ball) */
    get heldBalls() {
      const B = game.sim.world.Ball
      return game.live.filter((b) => B.mode[b] === BallMode.Held).length
    },
    /** the player's ball waiting at the launcher (its id, and the held balls ahead of it), or null */
    get playerWaiting() {
      return game.playerWaiting
    },
    /** held balls drawn visible in the last frame (they wait unseen in the launcher) */
    get heldDrawn() {
      return panel.heldVisible
    },
    /** the balls on the panel (rolling, on a rim or resting) whose centres are over 30 px from the launch point */
    get awayFromLauncher() {
      const B = game.sim.world.Ball
      const { x, y } = game.panel.launch
      return game.live.filter((b) => (B.mode[b] === BallMode.Rolling || B.mode[b] === BallMode.RimRoll || B.mode[b] === BallMode.Resting) && Math.hypot(B.x[b]! - x, B.y[b]! - y) > 30).length
    },
    get worstOverlap() {
      const B = game.sim.world.Ball
      const on = game.live.filter((b) => B.mode[b] === 0 || B.mode[b] === 1 || B.mode[b] === 3)
      let worst = 0
      for (let i = 0; i < on.length; i++) {
        for (let j = i + 1; j < on.length; j++) {
          const p = on[i]!
          const q = on[j]!
          worst = Math.max(worst, B.radius[p]! + B.radius[q]! - Math.hypot(B.x[p]! - B.x[q]!, B.y[p]! - B.y[q]!))
        }
      }
      return worst
    },
    get simTime() {
      return game.sim.time
    },
    /** the round replay: steps of the last round, whether one plays now, and (type, ball, time) of every
     * event of the recorded round and of the last replay */
    get lastRoundSteps() {
      return game.lastRoundSteps
    },
    /** the last called shot: the hole (layout order), the solver's answer, ms */
    get lastCall() {
      return game.lastCall === null ? null : JSON.parse(JSON.stringify(game.lastCall))
    },
    /** the outcome map view: rows computed, its grid, and the hole (layout order, −1 none) of a cell */
    get outcomeMap() {
      return { rows: outcomes.rows, done: outcomes.done, spec: MAP_SPEC }
    },
    outcomeCell(row: number, col: number): number {
      return outcomes.cells[row * MAP_SPEC.angle.steps + col]!
    },
    get roundsRecorded() {
      return game.roundsRecorded
    },
    get replaying() {
      return game.replaying !== null
    },
    get roundEvents() {
      return game.roundEvents.map((e) => [...e])
    },
    get replayEvents() {
      return game.replayEvents.map((e) => [...e])
    },
    get playerInPlay() {
      return game.playerInPlay
    },
    get gameOver() {
      return game.gameOver
    },
    /** the called shot being solved in the worker (the panel waits), or null */
    get solving() {
      return game.solving === null ? null : { ...game.solving }
    },
    /** true while the solver runs in a worker (false once it has failed, or where workers cannot start) */
    get solverInWorker() {
      return solver !== null
    },
    get throwsMade() {
      return game.throwsMade
    },
    get fps() {
      return meter.fps
    },
    get physicsMs() {
      return meter.physicsMs
    },
    get frameMs() {
      return meter.frameMs
    },
    get stepsPerFrame() {
      return meter.stepsPerFrame
    },
    get config() {
      return { ...game.config }
    },
    get pending() {
      return game.pending === null ? null : { ...game.pending }
    },
    get input() {
      return { angle: input.angle, power: input.power, charging: input.charging }
    },
    get renderer() {
      return { type: app.renderer.name, software, antialias: aa === null ? !software : aa !== '0' }
    },
    /** how the drawing is arranged: the regime map beside the panel, or under it (narrow, tall stages) */
    get stageLayout() {
      return stacked ? 'stacked' : 'side by side'
    },
    /** dots on the regime map now */
    get regimeDots() {
      return regime.shown
    },
    get plotted() {
      return regime.plotted
    },
    /** page coordinates (CSS px) of a point of the panel, for driving the pointer */
    toPage(x: number, y: number): { x: number; y: number } {
      const r = canvas.getBoundingClientRect()
      const g = panel.root.toGlobal({ x, y })
      return { x: r.left + g.x, y: r.top + g.y }
    },
    /** the same calls the pointer and keyboard make */
    aim(angle: number): void {
      input.setAim(angle)
    },
    charge(power: number): void {
      input.beginCharge(now())
      input.holdPower(power)
    },
    release(): void {
      input.release(now())
    },
  }
  Object.defineProperty(window, '__demo', { value: Object.freeze(hook), enumerable: false })
}

main().catch((e: unknown) => {
  console.error(e)
  const msg = document.createElement('pre')
  msg.style.cssText = 'color:#ff5c7a;padding:16px;white-space:pre-wrap'
  msg.textContent = `The demo failed to start: ${e instanceof Error ? e.message : String(e)}`
  document.body.prepend(msg)
})
