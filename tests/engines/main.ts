// Entry of the cross-engine bundle (tests/engines.test.ts builds it with esbuild and runs it in each
// engine): runs every scenario and prints one JSON line of results.
import { runAll } from './scenarios.js'

const balls = Number((globalThis as { ENGINE_BALLS?: number }).ENGINE_BALLS ?? 1000)
console.log(JSON.stringify(runAll(balls)))
