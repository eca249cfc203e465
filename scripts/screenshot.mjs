// Regenerates docs/demo.png: the demo mid-game with the inspector on (mode colours, velocity vectors,
// event labels, the regime map). Builds the demo into a temporary directory, serves it, and drives
// headless Chromium (playwright-core) through the demo's own hook.
//
//   node scripts/screenshot.mjs [--out docs/demo.png]      (CHROMIUM_PATH overrides /usr/bin/chromium)
import { existsSync, mkdirSync, mkdtempSync, rmSync } from 'node:fs'
import { tmpdir } from 'node:os'
import { dirname, join, resolve } from 'node:path'
import { fileURLToPath } from 'node:url'
import { chromium } from 'playwright-core'
import { buildDemo } from './demo-build.mjs'
import { serveStatic } from './demo-serve.mjs'

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..')
const i = process.argv.indexOf('--out')
const out = resolve(root, i >= 0 && process.argv[i + 1] ? process.argv[i + 1] : 'docs/demo.png')
const executablePath = process.env.CHROMIUM_PATH ?? '/usr/bin/chromium'
if (!existsSync(executablePath)) {
  console.error(`Chromium not found at ${executablePath}: apt-get install -y chromium (or set CHROMIUM_PATH)`)
  process.exit(1)
}

const dir = mkdtempSync(join(tmpdir(), 'demo-shot-'))
await buildDemo({ outdir: dir })
const { server, url } = await serveStatic(dir, 0)
const browser = await chromium.launch({
  executablePath,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking',
    '--disable-component-update', '--disable-sync', '--disable-quic'],
})
const errors = []
try {
  const page = await browser.newPage({ viewport: { width: 1400, height: 860 } })
  page.on('console', (m) => m.type() === 'error' && errors.push(m.text()))
  page.on('pageerror', (e) => errors.push(e.message))
  await page.goto(url)
  await page.waitForFunction(() => window.__demo?.ready && window.__demo.frames > 5, null, { timeout: 30_000 })
  await page.check('#show-vectors')
  const toss = async (angle, power, wait) => {
    await page.evaluate(([a, p]) => {
      window.__demo.aim(a)
      window.__demo.charge(p)
      window.__demo.release()
    }, [angle, power])
    await page.waitForTimeout(wait)
  }
  // a game under way: a few of the player's throws (one into a 100), then a burst for the inspector
  await toss(-0.22, 0.5, 1500)
  await toss(0.27, 0.56, 1200)
  await toss(-0.32, 0.42, 1200)
  await toss(0.12, 0.3, 1200)
  await toss(0.05, 0.47, 100)
  // a burst in flight (velocity vectors) and the next throw being charged and aimed
  await page.evaluate(() => {
    window.__demo.aim(-0.18)
    window.__demo.charge(0.62)
  })
  await page.click('#multi-100')
  await page.waitForFunction(() => window.__demo.eventsSeen > 0 && window.__demo.frames > 0)
  await page.waitForTimeout(200)
  mkdirSync(dirname(out), { recursive: true })
  await page.screenshot({ path: out })
  if (errors.length) throw new Error(`console errors:\n${errors.join('\n')}`)
  console.log(`wrote ${out}`)
} finally {
  await browser.close()
  server.close()
  rmSync(dir, { recursive: true, force: true })
}
