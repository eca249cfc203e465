// A worker of npm run outcomes (scripts/outcomes.ts, through tinypool): one chunk of a Monte Carlo run —
// throws first … first + count − 1 of the distribution — counted with sampleThrows.
import { sampleThrows, type OutcomeScene, type OutcomeTally, type ThrowDistribution } from '../src/index'

export default function chunk(task: { scene: OutcomeScene; dist: ThrowDistribution; count: number; seed: number; first: number }): OutcomeTally {
  return sampleThrows(task.scene, task.dist, task.count, task.seed, task.first)
}
