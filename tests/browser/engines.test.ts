// The same bits in the browsers a game ships to as on its server: the cross-engine scenarios of
// tests/engines/scenarios.ts (six worlds of 1,000 balls: the design, PHYSICAL_CONFIG, TABULATED_CONFIG, both
// contact methods, the fixed tick with unlike masses) and a recorded replay, bundled as one script
// (tests/engines/bundle.ts) and run in a page of Debian's Chromium (V8, the browser's own version of it) and
// of Debian's Firefox ESR (SpiderMonkey, the browser's own version: the js102 shell of tests/engines.test.ts
// is an older one). Every scenario's hash, event count and captures must be the ones this Node process
// gives. Chromium is driven by playwright-core, Firefox by puppeteer-core over WebDriver BiDi.
import { existsSync } from 'node:fs'
import { chromium } from 'playwright-core'
import puppeteer from 'puppeteer-core'
import { afterAll, beforeAll, describe, expect, it } from 'vitest'
import { bundleText } from '../engines/bundle'
import { recordSession, runAll, SCENARIOS, type ScenarioResult } from '../engines/scenarios'

const CHROMIUM = process.env.CHROMIUM_PATH ?? '/usr/bin/chromium'
const FIREFOX = process.env.FIREFOX_PATH ?? '/usr/bin/firefox-esr'
const CHROMIUM_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync']

/** One page of a browser: evaluates a script's text there and returns what it computed. */
interface Browser {
  version: string
  evaluate(script: string): Promise<string>
  close(): Promise<void>
}

/**
 * A bundle's text wrapped to run as one expression in a page: the line it prints (console.log) is its
 * value, and the page's console is left as it was.
 */
function captured(bundle: string): string {
  return `(() => { let out = ''; const log = console.log; console.log = (s) => { out = String(s) }; try {\n${bundle}\n} finally { console.log = log } return out })()`
}

function installed(path: string, name: string, install: string): void {
  if (!existsSync(path)) throw new Error(`${name} is not installed at ${path} (install: ${install})`)
}

async function openChromium(): Promise<Browser> {
  installed(CHROMIUM, 'Chromium', 'apt-get install chromium')
  const browser = await chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS })
  const page = await (await browser.newContext()).newPage()
  return { version: `Chromium ${browser.version()}`, evaluate: (s) => page.evaluate(s) as Promise<string>, close: () => browser.close() }
}

async function openFirefox(): Promise<Browser> {
  installed(FIREFOX, 'Firefox ESR', 'apt-get install firefox-esr')
  const browser = await puppeteer.launch({ browser: 'firefox', executablePath: FIREFOX, headless: true, protocolTimeout: 300_000 })
  const page = await browser.newPage()
  return { version: (await browser.version()).replace('firefox/', 'Firefox '), evaluate: (s) => page.evaluate(s) as Promise<string>, close: () => browser.close() }
}

/** the session recorded in this process: its replay's JSON and the hash of its events */
const session = recordSession()
let node: Record<string, ScenarioResult>
let scenarios = ''
let replay = ''

beforeAll(async () => {
  node = runAll()
  scenarios = captured(await bundleText('tests/engines/main.ts'))
  replay = captured(await bundleText('tests/engines/replayMain.ts', { REPLAY_TEXT: JSON.stringify(session.text) }))
}, 120_000)

for (const [name, open] of [
  ['Chromium (V8)', openChromium],
  ['Firefox ESR (SpiderMonkey)', openFirefox],
] as const) {
  describe(`the same bits in a ${name} page`, () => {
    let browser: Browser | null = null
    beforeAll(async () => {
      browser = await open()
      console.info(`browser engines: ${browser.version}`)
    }, 120_000)
    afterAll(async () => {
      await browser?.close()
    })

    it('every scenario gives the hash, events and captures this Node process gives', async () => {
      const got = JSON.parse(await browser!.evaluate(scenarios)) as Record<string, ScenarioResult>
      expect(Object.keys(got).sort()).toEqual(Object.keys(SCENARIOS).sort())
      for (const key of Object.keys(SCENARIOS)) expect({ key, ...got[key] }).toEqual({ key, ...node[key] })
    }, 300_000)

    it('the comparison sees a change: with 999 balls a scenario instead of 1,000, no hash is Node\'s', async () => {
      const got = JSON.parse(await browser!.evaluate(`globalThis.ENGINE_BALLS = 999; ${scenarios}`)) as Record<string, ScenarioResult>
      for (const key of Object.keys(SCENARIOS)) expect(got[key]!.hash).not.toBe(node[key]!.hash)
    }, 300_000)

    it('a replay recorded in Node plays back there with every event bit-identical', async () => {
      expect(session.events).toBeGreaterThan(500)
      expect(JSON.parse(await browser!.evaluate(replay))).toEqual({ hash: session.hash, events: session.events })
    }, 300_000)
  })
}
