// The throw solver in a worker, for Call your shot (demo/main.ts): solving in the page's own thread stops
// the page while it runs (seconds with a 1,000-ball burst and contacts on, since the solver simulates its
// throws among the other balls). Each call gets a fresh world: the page's config, its snapshot restored.
import { createBallPhysics, solveThrow } from '../src/index'
import type { ShotCall, ShotReply } from './shotCall'

const scope = self as unknown as { onmessage: ((e: MessageEvent<ShotCall>) => void) | null; postMessage(m: ShotReply): void }

scope.onmessage = (e) => {
  const call = e.data
  try {
    const t0 = performance.now()
    const sim = createBallPhysics(call.config)
    sim.restore(call.snapshot)
    const answer = solveThrow(sim, call.request)
    scope.postMessage({ token: call.token, answer, ms: performance.now() - t0 })
  } catch (err) {
    scope.postMessage({ token: call.token, error: err instanceof Error ? `${err.name}: ${err.message}` : String(err) })
  }
}
