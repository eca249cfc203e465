// The world's memory layout: balls are lightweight entities of the world's bitECS entity index, RimContact
// rows are pooled, and each store is sized by its own component's use (the heap budget of a large world).
import { entityExists, hasComponent } from 'bitecs'
import { describe, expect, it } from 'vitest'
import { DEFAULT_PANEL, addPanel, createBallPhysics } from '../src/index'
import { isBall, rimSlot, RimMode } from '../src/ecs'
import { storeLength } from '../components/store'
import { rng, settle, shoot } from './helpers'

describe('balls are lightweight entities', () => {
  it('share the entity index with holes and walls: entityExists holds, ids never collide and are recycled both ways', () => {
    const sim = createBallPhysics()
    const w = sim.world
    const holes = addPanel(sim)
    const b = sim.addBall({ x: 10, y: 10, vx: 0, vy: 0 })
    expect(holes).toEqual(Array.from({ length: 25 }, (_, i) => i + 1))
    expect(b).toBe(26)
    expect(entityExists(w, b)).toBe(true)
    expect(isBall(w, b)).toBe(true)
    expect(hasComponent(w, b, w.IsHole)).toBe(false)
    expect(isBall(w, holes[0]!)).toBe(false)
    // a removed ball's id goes back to the index: bitECS's addEntity hands it to the next hole
    sim.removeBall(b)
    expect(entityExists(w, b)).toBe(false)
    expect(isBall(w, b)).toBe(false)
    const h = sim.addHole({ x: 1000, y: 1000 })
    expect(h).toBe(b)
    expect(sim.holeState(h).x).toBe(1000)
    expect(() => sim.ballState(h)).toThrow(/is not a live ball/)
    // and the walls' id, freed by bitECS's removeEntity, goes to the next ball
    sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480 })
    const wallsId = w.walls
    sim.clearWalls()
    expect(entityExists(w, wallsId)).toBe(false)
    const b2 = sim.addBall({ x: 20, y: 20, vx: 0, vy: 0 })
    expect(b2).toBe(wallsId)
    expect(entityExists(w, b2)).toBe(true)
    expect(sim.balls()).toEqual([b2])
  })

  it('keep every live id distinct and alive through random adds and removals of balls, holes and walls', () => {
    const sim = createBallPhysics({}, { capacity: 8 })
    const w = sim.world
    const rand = rng(5)
    const balls = new Set<number>()
    const holes = new Set<number>()
    for (let i = 0; i < 3000; i++) {
      const op = rand()
      if (op < 0.45) balls.add(sim.addBall({ x: rand() * 1e5, y: rand() * 1e5, vx: 0, vy: 0 }))
      else if (op < 0.8 && balls.size > 0) {
        const b = [...balls][Math.floor(rand() * balls.size)]!
        sim.removeBall(b)
        balls.delete(b)
      } else if (op < 0.9) holes.add(sim.addHole({ x: 2e5 + 100 * i, y: 0, radius: 5 }))
      else if (op < 0.95) sim.setWalls({ minX: -1e6, minY: -1e6, maxX: 1e6, maxY: 1e6 })
      else sim.clearWalls()
      for (const b of balls) expect(holes.has(b) || b === w.walls).toBe(false)
    }
    expect(sim.balls()).toEqual([...balls].sort((a, b) => a - b))
    expect(sim.holes().sort((a, b) => a - b)).toEqual([...holes].sort((a, b) => a - b))
    for (const b of balls) expect(entityExists(w, b) && isBall(w, b)).toBe(true)
    for (const h of holes) expect(entityExists(w, h) && hasComponent(w, h, w.IsHole) && !isBall(w, h)).toBe(true)
  })
})

describe('RimContact is pooled', () => {
  it('a ball holds a row only while it has a hole lock, and reads hole 0 / mode None without one', () => {
    const { sim, ball, hole } = shoot(2, 900) // fast: skips over the hole
    const w = sim.world
    expect(rimSlot(w, ball)).toBe(0)
    expect(w.RimContact.hole[rimSlot(w, ball)]).toBe(0)
    let held = 0
    for (let i = 0; i < 600; i++) {
      sim.step(1 / 2000)
      const slot = rimSlot(w, ball)
      if (slot !== 0) {
        held++
        expect(w.RimContact.hole[slot]).toBe(hole)
        expect(w.RimContact.mode[slot]).toBe(RimMode.Skipping)
      }
    }
    expect(held).toBeGreaterThan(0)
    expect(rimSlot(w, ball)).toBe(0) // out of the lip circle: given back
    expect(sim.drainEvents().map((e) => e.type)).toContain('skip')
    // the freed row was zeroed, every field of it
    for (const [k, arr] of Object.entries(w.RimContact) as [string, Float64Array][]) expect(arr.every((v) => v === 0), k).toBe(true)
  })

  it('10,000 balls thrown at the panel: the pool grows with the concurrent contacts only, and every row comes back', () => {
    const sim = createBallPhysics({}, { capacity: 16384 })
    const w = sim.world
    addPanel(sim)
    const rand = rng(2024)
    for (let i = 0; i < 10000; i++) {
      sim.throwBall({ x: DEFAULT_PANEL.launch.x + (rand() - 0.5) * 300, y: DEFAULT_PANEL.launch.y, power: rand(), angle: (rand() - 0.5) * 1.4 })
    }
    let peak = 0
    for (let i = 0; i < 60 * 30 && w.moving.count > 0; i++) {
      sim.step(1 / 60)
      sim.drainEvents()
      peak = Math.max(peak, w.rimNext - 1 - w.rimFree.count)
    }
    expect(w.moving.count).toBe(0)
    expect(peak).toBeGreaterThan(0)
    expect(storeLength(w.RimContact)).toBeLessThanOrEqual(Math.max(64, 2 * (w.rimNext - 1) + 1))
    expect(w.rimNext - 1).toBeLessThan(10000 / 4) // slots ever handed out: far fewer than balls
    // captured and resting balls hold none: every slot is back in the pool
    expect(w.rimFree.count).toBe(w.rimNext - 1)
    for (const b of sim.balls()) expect(rimSlot(w, b)).toBe(0)
  })

  it('removing a ball on the rim gives its row back', () => {
    const { sim, ball } = shoot(11, 490) // rolls on the rim
    for (let i = 0; i < 400 && sim.ballState(ball).mode !== 'rimRoll'; i++) sim.step(1 / 2000)
    expect(sim.ballState(ball).mode).toBe('rimRoll')
    expect(rimSlot(sim.world, ball)).not.toBe(0)
    sim.drainEvents()
    const slot = rimSlot(sim.world, ball)
    for (const k of ['hole', 'mode', 'hasLip', 'delta', 'speed', 'lipTime', 'angle', 'arc', 'angle0', 'speed0', 'direction', 'time0'] as const) {
      expect(sim.world.RimContact[k][slot], k).not.toBe(0)
    }
    sim.removeBall(ball)
    expect(sim.world.rimFree.count).toBe(sim.world.rimNext - 1)
    // zeroed, every field of the schema (releaseRim lists them one by one)
    for (const [k, arr] of Object.entries(sim.world.RimContact) as [string, Float64Array][]) expect(arr[slot], k).toBe(0)
    expect(settle(sim)).toEqual([])
  })
})

describe('stores are sized per component', () => {
  it('holes and walls made before many balls keep their stores small; the per-ball stores fit the balls', () => {
    const n = 50_000
    const sim = createBallPhysics({}, { capacity: 1024 })
    const w = sim.world
    addPanel(sim)
    sim.setWalls({ minX: 0, minY: 0, maxX: 420, maxY: 480 })
    // resting balls beside the panel (a ball added inside a lip circle would take a RimContact row)
    for (let i = 0; i < n; i++) sim.addBall({ x: 500 + (i % 400), y: 5 + (i % 470), vx: 0, vy: 0 })
    expect(storeLength(w.Hole)).toBe(64)
    expect(storeLength(w.Walls)).toBe(64)
    expect(storeLength(w.RimContact)).toBeLessThanOrEqual(64)
    expect(storeLength(w.Ball)).toBeGreaterThan(n)
    expect(storeLength(w.Path)).toBe(storeLength(w.Ball))
    expect(w.capacity).toBe(storeLength(w.Ball))
  })

  it('typed arrays cost at most 160 bytes per ball id (the heap budget is 200 B per ball, bench/scale.ts)', () => {
    const cap = 1 << 16
    const sim = createBallPhysics({}, { capacity: cap })
    const w = sim.world
    let bytes = w.moving.sparse.byteLength + 4 * cap // the moving set's dense list, when every ball moves
    for (const store of [w.Ball, w.Path]) for (const arr of Object.values(store) as Float64Array[]) bytes += arr.byteLength
    bytes += w.pathHot.byteLength // the path's rows (src/world/pathHot.ts)
    expect(bytes / cap).toBeLessThanOrEqual(160)
  })
})

/**
 * The hole holeAt finds at each of 20,000 random points of the box [x, y, width, height] in `grid`, checked
 * against `scan` (a world of the same holes that scans them all).
 */
function holesAtRandomPoints<W>(grid: W, scan: W, holeAt: (w: W, x: number, y: number) => number, box: readonly number[], seed: number): number[] {
  const r = rng(seed)
  const hits: number[] = []
  for (let k = 0; k < 20000; k++) {
    const x = box[0]! + box[2]! * r()
    const y = box[1]! + box[3]! * r()
    const h = holeAt(scan, x, y)
    expect(holeAt(grid, x, y)).toBe(h)
    hits.push(h)
  }
  return hits
}

describe('holeAt', () => {
  it('the hole grid gives the same hole for a point as the scan of every hole', async () => {
    const { createBallWorld, addHoles } = await import('../src/ecs.js')
    const { holeAt } = await import('../src/world/holeTable.js')
    const specs = []
    for (let i = 0; i < 30; i++) for (let j = 0; j < 20; j++) specs.push({ x: 40 * i + (j % 3), y: 41 * j, radius: 12 + ((i * 7 + j) % 8) })
    const grid = createBallWorld({}, { broadphase: 'grid' })
    const scan = createBallWorld({}, { broadphase: 'scan' })
    addHoles(grid, specs)
    addHoles(scan, specs)
    const hits = holesAtRandomPoints(grid, scan, holeAt, [-50, -50, 1300, 900], 7)
    expect(hits.filter((h) => h !== 0).length).toBeGreaterThan(2000)
  })

  it('holes far wider than the rest stay out of the grid, and the grid gives the same holes and events as the scan (one of radius 1e4 sized its cells, and every hole shared a cell)', async () => {
    const { createBallWorld, addHoles, addBall, drainEvents, runSchedule, DEFAULT_SCHEDULE } = await import('../src/ecs.js')
    const { holeAt } = await import('../src/world/holeTable.js')
    const specs: { x: number; y: number; radius?: number }[] = []
    for (let i = 0; i < 30; i++) for (let j = 0; j < 20; j++) specs.push({ x: 40 * i, y: 41 * j, radius: 12 + ((i * 7 + j) % 8) })
    specs.push({ x: 600, y: -700, radius: 600 }, { x: -11000, y: 400, radius: 1e4 }, { x: 1500, y: 400, radius: 150 })
    const worlds = [createBallWorld({}, { broadphase: 'grid' }), createBallWorld({}, { broadphase: 'scan' })] as const
    for (const w of worlds) addHoles(w, specs)
    const hits = holesAtRandomPoints(worlds[0], worlds[1], holeAt, [-1500, -1400, 3500, 2400], 11)
    expect(hits.filter((h) => h > 600).length).toBeGreaterThan(1000)
    // balls rolling over the small holes and into the big ones: the same events, bit for bit
    const events = worlds.map((w) => {
      const r = rng(99)
      for (let k = 0; k < 300; k++) {
        const a = 6.2832 * r()
        addBall(w, { x: 1200 * r(), y: 800 * r(), vx: 900 * Math.cos(a), vy: 900 * Math.sin(a) })
      }
      for (let f = 0; f < 240; f++) runSchedule(w, DEFAULT_SCHEDULE, 1 / 60)
      return drainEvents(w)
    })
    expect(JSON.stringify(events[0])).toBe(JSON.stringify(events[1]))
    expect(events[0]!.filter((e) => e.type === 'capture' && (e.hole ?? 0) > 600).length).toBeGreaterThan(0)
    const g = worlds[0].holeGrid
    expect(g.bigCount).toBe(3)
    expect(g.maxRadius).toBe(19)
  })

  it('a ball of any radius leaves the cells no wider than twice the widest hole in them, and balls wider and narrower than the holes give the same events as the scan (one ball of radius 1e4, added and removed, sized the cells for it for good)', async () => {
    const { createBallWorld, addHoles, addBall, removeBall, drainEvents, runSchedule, DEFAULT_SCHEDULE } = await import('../src/ecs.js')
    const specs: { x: number; y: number; radius?: number }[] = []
    for (let i = 0; i < 30; i++) for (let j = 0; j < 20; j++) specs.push({ x: 40 * i, y: 41 * j, radius: 12 + ((i * 7 + j) % 8) })
    const worlds = [createBallWorld({}, { broadphase: 'grid' }), createBallWorld({}, { broadphase: 'scan' })] as const
    const radii = [1e4, 40, 16, 3, 11, 19.5, 0.5]
    const events = worlds.map((w) => {
      addHoles(w, specs)
      const wide = addBall(w, { x: 600, y: 400, radius: 1e4, vx: 5, vy: 1 })
      runSchedule(w, DEFAULT_SCHEDULE, 1 / 60)
      removeBall(w, wide)
      const r = rng(5)
      for (let k = 0; k < 300; k++) {
        const a = 6.2832 * r()
        addBall(w, { x: 1200 * r(), y: 800 * r(), radius: radii[k % radii.length]!, vx: 700 * Math.cos(a), vy: 700 * Math.sin(a) })
      }
      for (let f = 0; f < 180; f++) runSchedule(w, DEFAULT_SCHEDULE, 1 / 60)
      return drainEvents(w)
    })
    expect(JSON.stringify(events[0])).toBe(JSON.stringify(events[1]))
    // balls narrower than the holes meet them (the 16-px ones some holes only), wider ones bridge them
    const holeEvents = events[0]!.filter((e) => e.hole !== undefined)
    expect(holeEvents.length).toBeGreaterThan(300)
    const g = worlds[0].holeGrid
    expect(g.maxRadius).toBe(19)
    // sized for the widest ball narrower than the widest hole: the 16-px ones (1e4, 40 and 19.5 bridge every hole)
    expect(g.ballRadius).toBe(16)
    expect(g.cell).toBe(19 + 16)
  })
})
