// Builds the demo and serves it on localhost with a tiny static server (node:http, no dependencies).
//
//   PORT=5173 node scripts/demo-serve.mjs [--outdir demo-dist] [--no-watch] [--no-build]
//
// PORT defaults to 5173; PORT=0 picks a free port. The first line printed is "Demo: <url>" (the browser
// test reads it). By default esbuild watches demo/ and src/ and rebuilds on change: reload the page.
import { createReadStream, statSync } from 'node:fs'
import { createServer } from 'node:http'
import { extname, join, normalize, resolve, sep } from 'node:path'
import { pathToFileURL } from 'node:url'
import { DEFAULT_OUTDIR, buildDemo, watchDemo } from './demo-build.mjs'

const MIME = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.map': 'application/json; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.png': 'image/png',
  '.svg': 'image/svg+xml',
  '.ico': 'image/x-icon',
  '.txt': 'text/plain; charset=utf-8',
}

/** Serves the files under `root`; resolves to the listening server and its URL. */
export function serveStatic(root, port = 5173, host = '127.0.0.1') {
  const base = resolve(root)
  const server = createServer((req, res) => {
    let path
    try {
      path = decodeURIComponent(new URL(req.url ?? '/', 'http://x').pathname)
    } catch {
      res.writeHead(400).end('bad request')
      return
    }
    if (path.endsWith('/')) path += 'index.html'
    const file = normalize(join(base, path))
    if (file !== base && !file.startsWith(base + sep)) {
      res.writeHead(403).end('forbidden')
      return
    }
    let st
    try {
      st = statSync(file)
    } catch {
      st = undefined
    }
    if (!st || !st.isFile()) {
      res.writeHead(404, { 'content-type': 'text/plain; charset=utf-8' }).end(`not found: ${path}`)
      return
    }
    res.writeHead(200, {
      'content-type': MIME[extname(file)] ?? 'application/octet-stream',
      'content-length': st.size,
      'cache-control': 'no-cache',
    })
    if (req.method === 'HEAD') res.end()
    else createReadStream(file).pipe(res)
  })
  return new Promise((resolvePromise, reject) => {
    server.once('error', reject)
    server.listen(port, host, () => {
      const addr = server.address()
      const actual = typeof addr === 'object' && addr ? addr.port : port
      resolvePromise({ server, url: `http://localhost:${actual}/` })
    })
  })
}

if (import.meta.url === pathToFileURL(process.argv[1] ?? '').href) {
  const i = process.argv.indexOf('--outdir')
  const outdir = i >= 0 && process.argv[i + 1] ? resolve(process.argv[i + 1]) : DEFAULT_OUTDIR
  const watch = !process.argv.includes('--no-watch')
  const raw = process.env.PORT ?? '5173'
  const port = Number(raw)
  if (!Number.isInteger(port) || port < 0 || port > 65535) {
    console.error(`PORT must be an integer in [0, 65535], got ${raw}`)
    process.exit(2)
  }
  let ctx
  if (process.argv.includes('--no-build')) {
    // serve what is there
  } else if (watch) {
    ctx = await watchDemo({ outdir })
  } else {
    await buildDemo({ outdir, dev: true })
  }
  const { server, url } = await serveStatic(outdir, port)
  console.log(`Demo: ${url}`)
  if (watch) console.log('watching demo/ and src/ for changes (Ctrl+C to stop)')
  const stop = async () => {
    server.close()
    await ctx?.dispose()
    process.exit(0)
  }
  process.on('SIGINT', stop)
  process.on('SIGTERM', stop)
}
