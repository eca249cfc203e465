// The moving balls are walked in id order again once many have come and gone (src/world/idLists.ts,
// orderMoving; src/schedule.ts): with contacts off or exact that order changes no result.
import { describe, expect, it } from 'vitest'
import { createBallPhysics, type BallEvent } from '../src/index'
import { isMoving, orderMoving } from '../src/world/idLists'

function run(order: 'always' | 'never') {
  let s = 5
  const r = () => ((s = (s * 16807) % 2147483647) - 1) / 2147483646
  const sim = createBallPhysics({ ROLLING_DECEL: 300 }, { capacity: 6000 })
  for (let i = 0; i < 5; i++) for (let j = 0; j < 5; j++) sim.addHole({ x: 40 + 80 * i, y: 40 + 80 * j })
  const spawn = () => {
    const a = r() * 2 * Math.PI
    const v = 200 + 400 * r()
    sim.addBall({ x: r() * 400, y: r() * 400, vx: v * Math.cos(a), vy: v * Math.sin(a) })
  }
  for (let i = 0; i < 5000; i++) spawn()
  const w = sim.world
  const events: BallEvent[] = []
  let scattered = 0
  for (let step = 0; step < 60; step++) {
    const m = w.moving
    let sorted = true
    for (let k = 1; k < m.count; k++) if (m.dense[k]! < m.dense[k - 1]!) sorted = false
    if (!sorted) scattered++
    if (order === 'always') orderMoving(w)
    else m.churn = 0 // the schedule's own ordering never triggers
    sim.step(1 / 60)
    events.push(...sim.drainEvents())
    if (step % 5 === 4) {
      const gone = sim.balls().filter((b) => w.Ball.mode[b] === 2 || w.Ball.mode[b] === 3)
      for (const b of gone) sim.removeBall(b)
      for (let i = 0; i < gone.length; i++) spawn()
    }
  }
  const state = sim.balls().map((b) => [b, w.Ball.x[b], w.Ball.y[b], w.Ball.vx[b], w.Ball.vy[b], w.Ball.mode[b]])
  return { sim, events, state, scattered }
}

describe('the order the moving balls are walked in', () => {
  it('contacts off: walking them in id order gives the same events and states, bit for bit, as a scattered order', () => {
    const ordered = run('always')
    const scattered = run('never')
    expect(scattered.scattered).toBeGreaterThan(30) // the other run really walked them out of order
    expect(ordered.events.length).toBeGreaterThan(5000)
    expect(ordered.events).toEqual(scattered.events)
    expect(ordered.state).toEqual(scattered.state)
  })

  it('exact contacts: walking them in id order gives the same events and states, bit for bit, as a scattered order', () => {
    // 1,200 balls thrown up 30 panels side by side at once (the contacts bench's panel scene)
    const go = (order: 'always' | 'never') => {
      let s = 777
      const r = () => ((s = (s * 16807) % 2147483647) - 1) / 2147483646
      const sim = createBallPhysics({ BALL_COLLISIONS: 'on' }, { capacity: 2048 })
      const cols = 6
      sim.setWalls({ minX: 0, minY: 0, maxX: cols * 400, maxY: 5 * 600, restitution: 0.9, open: { bottom: true } })
      for (let t = 0; t < 30; t++) for (let i = 0; i < 5; i++) for (let j = 0; j < 5; j++) sim.addHole({ x: (t % cols) * 400 + 40 + 80 * i, y: Math.floor(t / cols) * 600 + 40 + 80 * j })
      for (let i = 0; i < 1200; i++) {
        const t = Math.floor(i / 40)
        const j = i % 40
        const speed = 175 + (0.2 + 0.7 * r()) * 525
        const angle = (r() - 0.5) * 0.8
        sim.addBall({ x: (t % cols) * 400 + 30 + 34 * (j % 10), y: Math.floor(t / cols) * 600 + 450 + 35 * Math.floor(j / 10), vx: speed * Math.sin(angle), vy: -speed * Math.cos(angle) })
      }
      const w = sim.world
      const events: BallEvent[] = []
      let scattered = 0
      for (let step = 0; step < 90; step++) {
        const m = w.moving
        for (let k = 1; k < m.count; k++) {
          if (m.dense[k]! < m.dense[k - 1]!) {
            scattered++
            break
          }
        }
        if (order === 'always') orderMoving(w)
        else m.churn = 0
        sim.step(1 / 60)
        events.push(...sim.drainEvents())
      }
      const state = sim.balls().map((b) => [b, w.Ball.x[b], w.Ball.y[b], w.Ball.vx[b], w.Ball.vy[b], w.Ball.mode[b]])
      return { events, state, scattered }
    }
    const ordered = go('always')
    const scattered = go('never')
    expect(scattered.scattered).toBeGreaterThan(30)
    expect(ordered.events.filter((e) => e.type === 'collision').length).toBeGreaterThan(100)
    expect(ordered.events).toEqual(scattered.events)
    expect(ordered.state).toEqual(scattered.state)
  })

  it('orderMoving keeps the set whole: the same balls, ascending, each found by isMoving', () => {
    const { sim } = run('never')
    const w = sim.world
    const before = Array.from(w.moving.dense.subarray(0, w.moving.count)).sort((a, b) => a - b)
    orderMoving(w)
    const after = Array.from(w.moving.dense.subarray(0, w.moving.count))
    expect(after).toEqual(before)
    for (const b of after) expect(isMoving(w, b)).toBe(true)
    expect(w.moving.churn).toBe(0)
  })
})
