// The fixed-tick method on a row of balls with gaps between them, struck end on faster than the row's balls
// can pass each other in a tick. Each widening round carries the push one ball further along the row (a
// ball at rest is paired only with the balls it touches). The rounds stopped at MAX_WIDEN_ROUNDS, and the
// ball the push had reached then moved through the next one within the tick, unpaired: from a row of six,
// balls swapped places, and at 1e5 px/s one ball left through five others at rest. The rounds now go on
// while a ball could pass another (MAX_PASS_ROUNDS; MAX_CHAIN_ROUNDS along a row, where each sped-up ball
// is paired with the next ball its path meets: src/contacts/fixedCut.ts).
import { describe, expect, it } from 'vitest'
import { createBallPhysics, mulberry32 } from '../../src/index'
import { CHAIN_ROUNDS_PER_CANDIDATE, MAX_CHAIN_ROUNDS, MAX_PASS_ROUNDS, MAX_WIDEN_ROUNDS } from '../../src/config/tolerances'
import { callsContinued, callsKept, keepAcrossCalls } from '../../src/contacts/fixedCalls'
import { takeAsFound, takenAsFoundCount } from '../../src/contacts/fixedStamps'
import { jamsSettled } from '../../src/contacts/fixedJam'
import { useNearLists } from '../../src/contacts/fixedNear'
import { ticksRedone, ticksRedoneForRestitution } from '../../src/contacts/fixedRedo'
import { anchoredCount } from '../../src/contacts/fixedLayered'
import { strike } from '../../bench/rowScenes'

function row(radius: number, gap: number, speed: number, n: number, tick?: number, travel?: number) {
  const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 1, ROLLING_DECEL: 0, BALL_RADIUS: radius, CONTACT_TICK: tick, CONTACT_TRAVEL_HALVINGS: travel })
  const ids = [sim.addBall({ x: 0, y: 0, vx: speed, vy: 0 })]
  for (let i = 0; i < n; i++) ids.push(sim.addBall({ x: 4 * radius + i * (2 * radius + gap), y: 0, vx: 0, vy: 0 }))
  const F = sim.world.fixed!
  let swapped = false
  let collisions = 0
  let pairs = 0
  // long enough for the push to leave the row's end
  const frames = Math.ceil(((4 * radius + n * (2 * radius + gap)) / speed) * 60) + 2
  for (let f = 0; f < frames; f++) {
    // steps of half a contact tick: each tick's pairs are seen before the next tick gathers
    for (let s = 0; s < 4; s++) {
      sim.step(1 / 240)
      pairs = Math.max(pairs, F.pairCount)
    }
    for (const e of sim.drainEvents()) if (e.type === 'collision') collisions++
    const xs = ids.map((i) => sim.ballState(i).x)
    for (let k = 1; k < xs.length; k++) if (!(xs[k]! > xs[k - 1]!)) swapped = true
  }
  return { swapped, collisions, pairs, vx: ids.map((i) => sim.ballState(i).vx) }
}

describe('fixed tick: a push along a row with gaps', () => {
  it('the tolerances leave room beyond the widening rounds', () => {
    expect(MAX_PASS_ROUNDS).toBeGreaterThan(MAX_WIDEN_ROUNDS)
    expect(MAX_CHAIN_ROUNDS).toBeGreaterThan(MAX_PASS_ROUNDS)
    expect(CHAIN_ROUNDS_PER_CANDIDATE).toBeGreaterThanOrEqual(1)
  })

  const cases: Array<[radius: number, gap: number, speed: number, n: number]> = [
    [11, 2, 3000, 6], // a ball moves 25 px a tick: more than a diameter and a gap
    [11, 2, 3000, 10],
    [11, 5, 1e5, 30],
    [3, 1, 1000, 6],
    [0.5, 1, 1e4, 40],
    [11, 1, 1e5, 200],
    // rows of small balls longer than the pairs one ball's widening adds: a bound of 64 pairs a candidate
    // on the rounds let a ball through from the 82nd (5e4 px/s) or 161st (2e4 px/s)
    [0.5, 1, 2e4, 250],
    [0.5, 1, 5e4, 250],
    [3, 1, 2e5, 250],
    // longer than MAX_PASS_ROUNDS: at 256 rounds a tick the ball at index 258 went through its neighbour
    // (the push crosses about 830 gaps of 1 px in a 1/120 s tick at 1e5 px/s); and the radius-0.5 row
    // stopped earlier still at the pair bounds, every sped-up ball paired with all 416 balls along its path
    [0.5, 1, 1e5, 1000],
    [11, 1, 1e5, 1000],
    // longer than MAX_CHAIN_ROUNDS: at 4,096 rounds a tick the ball at index 4,098 went through its neighbour
    [0.5, 1, 1e5, 5000],
  ]
  for (const [radius, gap, speed, n] of cases) {
    it(`radius ${radius}, gap ${gap} px, ${speed} px/s into ${n} balls: no ball passes another, the last one leaves with the striker's speed`, () => {
      const r = row(radius, gap, speed, n)
      expect(r.swapped).toBe(false)
      // equal masses, restitution 1: the push goes through every ball, and only the last one moves on
      expect(r.collisions).toBe(n)
      expect(r.vx[n]).toBeCloseTo(speed, 6)
      for (let k = 0; k < n; k++) expect(Math.abs(r.vx[k]!)).toBeLessThan(1e-9 * speed)
      // each sped-up ball is paired with the next ball its path meets, not with all along it (n²/2 pairs:
      // 31,000 in a tick for the 250-ball rows)
      expect(r.pairs).toBeLessThan(4 * n + 8)
    })
  }

  it('radius 11, gap 1 px, 1e5 px/s into 1,000 balls at CONTACT_TICK 1/1920 s: rounds past MAX_PASS_ROUNDS that reach the chain bound with a ball that may pass solve the tick again finer, and no ball passes another', () => {
    // the rounds reached ball 802 of the row when the tick's pairs went one past CHAIN_PAIRS_PER_BALL a
    // candidate (4,005 for 1,001 candidates); the tick ended there as solved, ball 803 went on at 1e5 px/s
    // through 804 and 805 within the tick, and the two ended 44 px the wrong way round. Found with the tick
    // never halved for the balls' travel (CONTACT_TRAVEL_HALVINGS 0), which halves this one first; with it too
    for (const travel of [0, 4]) {
      const redone = ticksRedone()
      const r = row(11, 1, 1e5, 1000, 1 / 1920, travel)
      expect(r.swapped).toBe(false)
      expect(r.collisions).toBe(1000)
      expect(r.vx[1000]).toBeCloseTo(1e5, 6)
      if (travel === 0) expect(ticksRedone()).toBeGreaterThan(redone)
    }
  })

  // rows that stop the push (e = 0, the striker's mass given), at the default tick and at 1/240 s: the first
  // four met the same bound; the last two, a re-solve after the projection took the row out from one of its
  // balls that carried the push past the rounds' reach (systems/fixedContacts.ts). Each let a ball through its
  // neighbour before: 36 of 1,008 free rows of radii 0.5-11, gaps 0.05-5 px, 3,000-1e5 px/s, ticks
  // 1/120-1/7,680 s let one through, and none now (docs/known-failures.md)
  for (const [e, mass, radius, gap, speed, n, tick] of [
    [0, 1, 0.5, 0.05, 1e5, 1000, 1 / 120],
    [0, 100, 11, 1, 1e5, 1000, 1 / 120],
    [0, 100, 11, 0.05, 1e5, 1000, 1 / 240],
    [0, 100, 11, 1, 1e5, 1000, 1 / 240],
    [0, 100, 3, 1, 3000, 200, 1 / 120],
    [0, 100, 11, 5, 1e5, 1000, 1 / 120],
  ] as const) {
    it(`e = ${e}, a striker of mass ${mass} at ${speed} px/s into ${n} balls of radius ${radius} ${gap} px apart, tick 1/${Math.round(1 / tick)} s: no ball passes another`, () => {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: e, ROLLING_DECEL: 0, BALL_RADIUS: radius, CONTACT_TICK: tick })
      const ids = [sim.addBall({ x: 0, y: 0, vx: speed, vy: 0, mass })]
      for (let i = 0; i < n; i++) ids.push(sim.addBall({ x: 4 * radius + i * (2 * radius + gap), y: 0, vx: 0, vy: 0 }))
      const frames = Math.ceil(((4 * radius + n * (2 * radius + gap)) / speed) * 60) + 2
      let passed = -1
      for (let f = 0; f < frames * 4 && passed < 0; f++) {
        sim.step(1 / 240)
        const xs = ids.map((i) => sim.ballState(i).x)
        for (let k = 1; k < xs.length && passed < 0; k++) if (!(xs[k]! > xs[k - 1]!)) passed = k
      }
      expect(passed).toBe(-1)
    })
  }
})

/**
 * A ball of mass `mass` at 1e5 px/s along y = 0 into n balls of the given radius 1 px apart, stepped at hz
 * for `frames` frames; after every frame, momentum is kept to 1e-9 and kinetic energy never rises. Returns
 * the first index whose ball is not ahead of the one before (-1: none), the collisions, the balls' states
 * as bits and the ids.
 */
/** A striker of `mass` at `speed` px/s, `lead` px behind the first of a row of n balls `gap` px apart. */
function strikeRow(radius: number, n: number, mass: number, hz: number, frames: number, { speed = 1e5, gap = 1, e = 1, lead = 4 * radius, travel = undefined as number | undefined } = {}) {
  const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: e, ROLLING_DECEL: 0, BALL_RADIUS: radius, CONTACT_TRAVEL_HALVINGS: travel })
  const ids = [sim.addBall({ x: 0, y: 0, vx: speed, vy: 0, mass })]
  for (let i = 0; i < n; i++) ids.push(sim.addBall({ x: lead + i * (2 * radius + gap), y: 0, vx: 0, vy: 0 }))
  const masses = ids.map((_, k) => (k === 0 ? mass : 1))
  const p0 = mass * speed
  const e0 = 0.5 * mass * speed * speed
  let swapped = -1
  let collisions = 0
  // the deepest overlap of neighbours on the row after any frame
  let deepest = 0
  for (let f = 0; f < frames; f++) {
    sim.step(1 / hz)
    for (const e of sim.drainEvents()) if (e.type === 'collision') collisions++
    const st = ids.map((i) => sim.ballState(i))
    for (let k = 1; k < st.length && swapped < 0; k++) if (!(st[k]!.x > st[k - 1]!.x)) swapped = k
    for (let k = 1; k < st.length; k++) deepest = Math.max(deepest, 2 * radius - (st[k]!.x - st[k - 1]!.x))
    const p = st.reduce((acc, b, k) => acc + masses[k]! * b.vx, 0)
    const e = st.reduce((acc, b, k) => acc + 0.5 * masses[k]! * (b.vx * b.vx + b.vy * b.vy), 0)
    expect(Math.abs(p - p0)).toBeLessThan(1e-9 * p0)
    expect(e).toBeLessThanOrEqual(e0 * (1 + 1e-12))
  }
  const bits = ids.map((i) => { const b = sim.ballState(i); return `${b.x},${b.y},${b.vx},${b.vy}` }).join(';')
  return { sim, ids, swapped, collisions, bits, deepest }
}

describe('fixed tick: a slow push along a row at rest into a wall (e = 0)', () => {
  // a ball held like a wall (at rest, the impulse too weak to wake it) counted, with its partner, as a light
  // ball met again by a heavier one, and a sweep of only such meetings ended the solve call from half way:
  // 55 and 120 radius-0.5 balls 0.05 px apart struck at 100 px/s, a wall 5 px past the row, stayed up to
  // 5.4e-3 px deep from 0.5 s on (npm run bench:rows). Only the balls' own masses count there now
  for (const n of [55, 120]) {
    it(`${n} balls: no pair over 1e-3 px deep from 0.5 s on`, () => {
      const gap = 0.05
      const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 0, ROLLING_DECEL: 0, BALL_RADIUS: 0.5 })
      sim.setWalls({ minX: -50, minY: -20, maxX: n * (1 + gap) + 5, maxY: 20, restitution: 0 })
      const ids = [sim.addBall({ x: -1 - gap, y: 0, vx: 100, vy: 0 })]
      for (let i = 0; i < n; i++) ids.push(sim.addBall({ x: i * (1 + gap), y: 0, vx: 0, vy: 0 }))
      let deepest = 0
      for (let f = 0; f < 120; f++) {
        sim.step(1 / 120)
        if (f + 1 < 60) continue
        const x = sim.world.Ball.x
        for (let k = 1; k < ids.length; k++) deepest = Math.max(deepest, 1 - (x[ids[k]!]! - x[ids[k - 1]!]!))
      }
      expect(deepest).toBeLessThanOrEqual(1e-3)
    })
  }
})

describe('fixed tick: random rows struck by heavier balls into a wall, e = 0.9 and 1', () => {
  // npm run bench:rows strikes rows on a grid of settings; these are drawn between them: 20, 55 or 120
  // radius-0.5 balls 0.02–0.22 px apart, a striker of mass 3, 30 or 100 at 50–450 px/s, a closed wall 5 px
  // past the row, 1 s at 60 or 120 Hz. A first version of the rule that solves a small tick again finer when a
  // pair apart at its start closed past its restitution visits (docs/known-failures.md, "A heavier striker
  // into a resting pile") left 2 of these rows 2.8e-3 and 4.4e-3 px deep at a step after 0.5 s (a projection
  // that ran its sweeps out along a row pressed into the wall). The rule as kept (src/contacts/fixedRedo.ts,
  // finerForRestitution) acts in these rows, and none of 1,800 drawn so (two seeds) goes deeper than 1.0e-4 px
  it('240 rows: no ball passes another, no pair over 1e-3 px deep at a step from 0.5 s on', () => {
    const redone = ticksRedoneForRestitution()
    const r = mulberry32(1)
    const failing: string[] = []
    let deepest = 0
    for (let s = 0; s < 240; s++) {
      const n = [20, 55, 120][Math.floor(r() * 3)]!
      const gap = 0.02 + 0.2 * r()
      const mass = [3, 30, 100][Math.floor(r() * 3)]!
      const speed = 50 + 400 * r()
      const e = r() < 0.7 ? 1 : 0.9
      const hz = r() < 0.5 ? 60 : 120
      // on one line the deepest pair is a pair of neighbours (bench/rowScenes.ts looks at every pair)
      const { passed, deepest: deep } = strike({ n, gap, mass, speed, e, hz })
      deepest = Math.max(deepest, deep)
      if (passed >= 0 || deep > 1e-3) failing.push(JSON.stringify({ s, n, gap, mass, speed, e, hz, passed, deep }))
    }
    expect(failing).toEqual([])
    // the rows do press together: the projection's slop, not 0
    expect(deepest).toBeGreaterThan(1e-5)
    // and the rule solved ticks of theirs again finer
    expect(ticksRedoneForRestitution()).toBeGreaterThan(redone)
  })
})

describe('fixed tick: a heavy striker through a row (its capsule cut at the first ball, then lengthened)', () => {
  it('a ball of mass 1,000 at 1e5 px/s into 300 radius-3 balls 1 px apart: goes on past each cut, no ball passes another, momentum kept, energy never rises, every ball pushed ahead', () => {
    const { sim, ids, swapped } = strikeRow(3, 300, 1000, 60, 6)
    expect(swapped).toBe(-1)
    for (const i of ids) expect(sim.ballState(i).vx).toBeGreaterThan(0)
  })
})

/**
 * A ball 100 times heavier than the balls of a row sends each ahead at nearly twice its speed, and, their
 * positions frozen at the tick's start, every light ball then reaches every other within the tick: the
 * widening rounds stopped at PASS_PAIRS_PER_BALL with a ball that could still pass, and balls passed through
 * others (from index 501 of 520; 604 of 1,000). The tick is now solved again at a finer spacing
 * (src/contacts/fixedRedo.ts).
 */
/**
 * Velocity sweeps even out a chain of touching balls in about the square of its length: a striker pressing
 * hundreds of them left the back of the chain faster than its front after every tick's sweeps, the chain
 * closed a little more each tick, and the projection could not open it again (0.25 px deep here, half a
 * radius; in a row of 1,000 struck by a mass-150 ball, until two balls passed). A chain the sweeps leave
 * closing now moves on as one body (src/contacts/fixedJam.ts).
 */
describe('fixed tick: a long chain the sweeps leave closing moves on as one body', () => {
  it('a ball of mass 10 at 1e4 px/s into 300 radius-0.5 balls 0.01 px apart, e = 0: the row leaves at the centre-of-mass speed, no overlap over 0.05 px, the same bits at 60 and 240 Hz', () => {
    const jams = jamsSettled()
    const a = strikeRow(0.5, 300, 10, 60, 6, { speed: 1e4, gap: 0.01, e: 0, lead: 1.01 })
    expect(jamsSettled()).toBeGreaterThan(jams)
    expect(a.swapped).toBe(-1)
    expect(a.deepest).toBeLessThan(0.05)
    // fully inelastic: all 301 balls at 10 · 1e4 / 310 (before, the striker at 557 px/s and the last ball at 101)
    for (const i of a.ids) expect(Math.abs(a.sim.ballState(i).vx - 1e5 / 310)).toBeLessThan(0.1)
    const b = strikeRow(0.5, 300, 10, 240, 24, { speed: 1e4, gap: 0.01, e: 0, lead: 1.01 })
    expect(b.bits).toBe(a.bits)
  })

  // the striker pairs with every ball within a tick's travel (83 px) ahead of it, so the row was no chain by
  // the count of each ball's closing pairs, and half way through the sweeps the striker was often slower than
  // the ball ahead (apart from the row's group); the row left its first tick 775 px/s faster at the back than
  // the front, closed on itself, and balls passed from the 4th (2.4 px deep; rows of 96 to 160: passes, up to
  // 47 px deep). A row is now told by its normals, and pairs met RESTITUTION_VISITS times join it
  it('a ball of mass 1e4 at 1e4 px/s into 120 touching radius-0.5 balls, e = 0: the whole row leaves its first tick at the inelastic speed, no overlap, the same bits at 60 and 240 Hz', () => {
    const a = strikeRow(0.5, 120, 1e4, 60, 6, { speed: 1e4, gap: 0, e: 0, lead: 1 })
    expect(a.swapped).toBe(-1)
    expect(a.deepest).toBeLessThan(1e-3)
    for (const i of a.ids) expect(Math.abs(a.sim.ballState(i).vx - 1e8 / 10_120)).toBeLessThan(0.1)
    const b = strikeRow(0.5, 120, 1e4, 240, 24, { speed: 1e4, gap: 0, e: 0, lead: 1 })
    expect(b.bits).toBe(a.bits)
  })
})

describe('fixed tick: a tick whose widening rounds stop with a ball that may pass is solved again, halved', () => {
  it('a ball of mass 100 at 1e5 px/s into 520 radius-0.5 balls 1 px apart: no ball passes another, the last leaves as the two-body law says, the same bits at 60 and 240 Hz', () => {
    // found with the tick never halved for the balls' travel (CONTACT_TRAVEL_HALVINGS 0), which halves this
    // one before its rounds stop; with it too
    for (const travel of [0, 4]) {
      const redone = ticksRedone()
      const a = strikeRow(0.5, 520, 100, 60, 3, { travel })
      expect(a.swapped).toBe(-1)
      // the last ball of the row, struck by the heavy one through a chain of equal balls: 2·100/101 · 1e5
      expect(a.sim.ballState(a.ids[520]!).vx).toBeCloseTo((2 * 100 * 1e5) / 101, 1)
      if (travel === 0) expect(ticksRedone()).toBeGreaterThan(redone)
      const b = strikeRow(0.5, 520, 100, 240, 12, { travel })
      expect(b.collisions).toBe(a.collisions)
      expect(b.bits).toBe(a.bits)
    }
  })
})

/**
 * Rows side by side, each struck end on: a ball widened by its whole travel in every direction was paired
 * with every ball of every row within 833 px, the rounds' pair bounds stopped the push after about five
 * balls and each striker went through its row (10 rows of 100: 310 contacts instead of 1,000). Widened
 * along its path only (src/contacts/fixedCapsule.ts), it meets only its own row.
 */
function lattice(rows: number, cols: number, speed: number, slant: number) {
  const radius = 0.5
  const pitch = 4
  const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 1, ROLLING_DECEL: 0, BALL_RADIUS: radius })
  const ids: number[] = []
  for (let r = 0; r < rows; r++) for (let c = 0; c < cols; c++) ids.push(sim.addBall({ x: 10 + c * pitch, y: r * pitch, vx: 0, vy: 0 }))
  for (let r = 0; r < rows; r++) ids.push(sim.addBall({ x: 10 - 4 * radius, y: r * pitch + slant * radius, vx: speed, vy: slant * speed * 0.05 }))
  let collisions = 0
  let deepest = 0
  const B = sim.world.Ball
  for (let f = 0; f < 6; f++) {
    sim.step(1 / 60)
    for (const e of sim.drainEvents()) if (e.type === 'collision') collisions++
    // no ball inside another (sorted by x, neighbours within a diameter)
    const order = [...ids].sort((a, b) => B.x[a]! - B.x[b]!)
    for (let a = 0; a < order.length; a++) {
      for (let b = a + 1; b < order.length && B.x[order[b]!]! - B.x[order[a]!]! < 2 * radius; b++) {
        const d = Math.hypot(B.x[order[b]!]! - B.x[order[a]!]!, B.y[order[b]!]! - B.y[order[a]!]!)
        deepest = Math.max(deepest, 2 * radius - d)
      }
    }
  }
  // the far end of each row: whether its last ball was struck
  let ends = 0
  for (let r = 0; r < rows; r++) if (B.x[ids[r * cols + cols - 1]!]! > 10 + (cols - 1) * pitch + 1) ends++
  return { collisions, deepest, ends }
}

describe('fixed tick: rows side by side of tiny balls struck at 1e5 px/s', () => {
  it('10 rows of 100 balls of radius 0.5, 4 px apart, each struck end on: every ball struck once, every row pushed to its end', () => {
    const r = lattice(10, 100, 1e5, 0)
    expect(r.collisions).toBe(1000)
    expect(r.ends).toBe(10)
    expect(r.deepest).toBeLessThan(1e-3)
  })

  it('the same rows struck a little off their line and slanting across them: no ball left inside another', () => {
    const r = lattice(10, 100, 1e5, 0.3)
    expect(r.collisions).toBeGreaterThan(1000)
    expect(r.deepest).toBeLessThan(1e-3)
  })
})

describe('fixed tick: a row along a wall struck at 1e5 px/s', () => {
  it('every ball the rounds widen near a wall is kept in the near-wall list (it outgrew the candidates and later entries were dropped: no wall for those balls that tick)', () => {
    const n = 60
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 1, ROLLING_DECEL: 0, BALL_RADIUS: 0.5 })
    sim.setWalls({ minX: 0, minY: 0, maxX: 5 + 2 * n, maxY: 40, restitution: 1 })
    // lying on the floor (within the touch gap): listed at the gather and again at each widening
    const y = 0.5 + 1e-7
    for (let c = 0; c < n; c++) sim.addBall({ x: 4 + 2 * c, y, vx: 0, vy: 0 })
    sim.addBall({ x: 1, y, vx: 1e5, vy: 0 })
    const F = sim.world.fixed!
    let listed = 0
    for (let i = 0; i < 12; i++) {
      sim.step(1 / 120) // one contact tick a step: each tick's list is seen
      expect(F.nearWallCount).toBeLessThanOrEqual(F.nearWall.length)
      listed = Math.max(listed, F.nearWallCount)
      sim.drainEvents()
      for (const b of sim.balls()) {
        const s = sim.ballState(b)
        expect(s.x).toBeGreaterThanOrEqual(0)
        expect(s.x).toBeLessThanOrEqual(5 + 2 * n)
      }
    }
    expect(listed).toBeGreaterThan(n)
  })
})

describe('fixed tick: a resting ball an earlier widening round added', () => {
  it('is paired with a ball a later round widens: struck toward it, that ball meets it at the same tick (it moved into it, unpaired, and met it a tick late)', () => {
    // a random scene (two rows of 30 balls of radii 0.5–3, 7 px apart, a third of them thrown at
    // 1e4–1e5 px/s), seed 19: at the fourth tick ball 11 strikes ball 10 toward ball 9, 1.6 px away; ball 9
    // joined the tick's candidates through another ball's widening in an earlier round
    let s = (19 * 7919) >>> 0
    const R = () => {
      s = (s * 1664525 + 1013904223) >>> 0
      return s / 4294967296
    }
    // (found with the tick never halved for the balls' travel, CONTACT_TRAVEL_HALVINGS 0: at the finer ticks
    // of that rule the scene never comes to this)
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 1, ROLLING_DECEL: 0, BALL_RADIUS: 1, CONTACT_TRAVEL_HALVINGS: 0 })
    for (let i = 0; i < 60; i++) {
      const r = 0.5 + R() * 2.5
      R()
      R()
      const x = 10 + (i % 30) * 7
      const y = 20 + Math.floor(i / 30) * 9 + R() * 2
      const sp = R() < 0.3 ? 1e4 + R() * 9e4 : 0
      const a = R() * Math.PI * 2
      try {
        sim.addBall({ x, y, radius: r, vx: sp * Math.cos(a), vy: sp * Math.sin(a) })
      } catch {
        // put down where another ball already is: refused, as in the scene this reproduces
      }
    }
    const times = new Map<string, number>()
    for (let f = 0; f < 6; f++) {
      sim.step(1 / 120)
      for (const e of sim.drainEvents()) if (e.type === 'collision' && !times.has(`${e.ball}-${e.other}`)) times.set(`${e.ball}-${e.other}`, e.time)
    }
    expect(times.get('10-11')).toBe(4 / 120)
    expect(times.get('9-10')).toBe(times.get('10-11'))
  })
})

describe('fixed tick: resting balls the rounds added one by one, touching each other', () => {
  // a push along a row of touching balls at rest adds them to the tick's candidates a round at a time; two of
  // them were never paired (each joined paired with the ball widened that round only), so a ball struck
  // in the row went on to the ball after the next, through the next: the push skipped every other ball and
  // the last one struck went through the row's last ball
  for (const hz of [60, 120]) {
    it(`20 touching radius-0.5 balls struck end on by an equal ball at 300 px/s, e = 1, a wall 5 px past the row, ${hz} Hz: every neighbour struck, no ball passes another for 1 s`, () => {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 1, ROLLING_DECEL: 0, BALL_RADIUS: 0.5 })
      sim.setWalls({ minX: -50, minY: -20, maxX: 25, maxY: 20, restitution: 1 })
      const ids = [sim.addBall({ x: -1, y: 0, vx: 300, vy: 0 })]
      for (let i = 0; i < 20; i++) ids.push(sim.addBall({ x: i, y: 0, vx: 0, vy: 0 }))
      const met = new Set<string>()
      let passed = -1
      for (let f = 0; f < hz; f++) {
        sim.step(1 / hz)
        for (const e of sim.drainEvents()) if (e.type === 'collision') met.add(`${e.ball}-${e.other}`)
        const xs = ids.map((i) => sim.ballState(i).x)
        for (let k = 1; k < xs.length && passed < 0; k++) if (!(xs[k]! > xs[k - 1]!)) passed = f
      }
      expect(passed).toBe(-1)
      for (let k = 1; k < ids.length; k++) expect(met.has(`${ids[k - 1]}-${ids[k]}`), `${ids[k - 1]}-${ids[k]}`).toBe(true)
    })
  }
})

/**
 * A row of n radius-0.5 balls `gap` px apart struck end on by a ball of mass `mass` at `speed` px/s,
 * restitution e, a closed wall 5 px past the row, stepped 1 s at `hz`: the first step at which a ball is not
 * ahead of the one before it (-1: none), and every ball's state at the end.
 */
function strikeRowAtWall(n: number, gap: number, mass: number, speed: number, hz: number, e = 1, travel?: number, tick?: number) {
  const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: e, ROLLING_DECEL: 0, BALL_RADIUS: 0.5, CONTACT_TRAVEL_HALVINGS: travel, CONTACT_TICK: tick })
  sim.setWalls({ minX: -50, minY: -20, maxX: n * (1 + gap) + 5, maxY: 20, restitution: e })
  const ids = [sim.addBall({ x: -1 - gap, y: 0, vx: speed, vy: 0, mass })]
  for (let i = 0; i < n; i++) ids.push(sim.addBall({ x: i * (1 + gap), y: 0, vx: 0, vy: 0 }))
  let passed = -1
  for (let f = 0; f < hz; f++) {
    sim.step(1 / hz)
    sim.drainEvents()
    const xs = ids.map((i) => sim.ballState(i).x)
    for (let k = 1; k < xs.length && passed < 0; k++) if (!(xs[k]! > xs[k - 1]!)) passed = f
  }
  return { passed, state: ids.map((i) => sim.ballState(i)) }
}

/**
 * The row above passes no ball at 60 Hz and ends with the same bits at 120 Hz: with the tick never halved for
 * the balls' travel (CONTACT_TRAVEL_HALVINGS 0, the default), solving a tick again; and with that rule at 4,
 * which halves these ticks before they need it.
 */
function holdsWithRedo(n: number, gap: number, mass: number, speed: number, redone = true): void {
  const before = ticksRedone()
  const a = strikeRowAtWall(n, gap, mass, speed, 60, 1, 0)
  expect(a.passed).toBe(-1)
  if (redone) expect(ticksRedone()).toBeGreaterThan(before)
  expect(strikeRowAtWall(n, gap, mass, speed, 120, 1, 0)).toEqual(a)
  const b = strikeRowAtWall(n, gap, mass, speed, 60, 1, 4)
  expect(b.passed).toBe(-1)
  expect(strikeRowAtWall(n, gap, mass, speed, 120, 1, 4)).toEqual(b)
}

describe('fixed tick: a tick that leaves a pair closing deep into itself is solved again, halved', () => {
  // struck at 1e4 px/s, a push runs the length of the row, off the wall and back within one tick of
  // 1/120 s: the sweeps end with a pair still closing through itself, or the row's last ball still moving
  // into the wall (it turned there between ticks and went back through the row); a finer tick resolves it
  for (const gap of [0, 0.3]) {
    it(`20 radius-0.5 balls ${gap} px apart struck end on by an equal ball at 1e4 px/s, e = 1, a wall 5 px past the row: no ball passes another for 1 s, the same bits at 60 and 120 Hz`, () => {
      holdsWithRedo(20, gap, 1, 1e4)
    })
  }
})

describe('fixed tick: a tick of many pairs a candidate that leaves a push front closing deep is solved again (DEEP_FRONTS)', () => {
  // a ball of mass 3 striking a row of radius-0.5 balls at 3,000–1e4 px/s: the first tick has 5–20 pairs a
  // candidate after its widening rounds, more than CHAIN_PAIRS_PER_BALL, and its sweeps leave one or two
  // pairs closing deep (the push's front, the wall ahead); left to the projection, a ball passed its
  // neighbour before the next tick
  // (the 120-ball row holds without a tick solved again since a ball only the wall turned in a tick keeps its
  // path to the wall, src/contacts/fixedWallTurn.ts; the 80-ball row still needs one)
  const cases: Array<[n: number, gap: number, speed: number, redone: boolean]> = [[55, 2, 3000, true], [55, 2, 1e4, true], [55, 0.05, 1e4, true], [80, 2, 3000, true], [120, 2, 3000, false]]
  for (const [n, gap, speed, redone] of cases) {
    it(`${n} radius-0.5 balls ${gap} px apart struck end on by a mass-3 ball at ${speed} px/s, e = 1, a wall 5 px past the row: no ball passes another for 1 s, the same bits at 60 and 120 Hz`, () => {
      holdsWithRedo(n, gap, 3, speed, redone)
    })
  }
})

describe('fixed tick: a push that leaves three fronts closing deep at a fine tick is solved again (DEEP_ROW_FRONTS)', () => {
  // a ball of mass 100 at 3,000 px/s into 120 radius-0.5 balls 0.3 px apart, at a tick of 1/1,920 s (the
  // default tick halved 4 times, as CONTACT_TRAVEL_HALVINGS 4 does here): the second tick's sweeps leave the
  // push part-way along the row, three balls at 3,000-3,600 px/s 0.3 px behind balls at rest, on a tick of
  // more than CHAIN_PAIRS_PER_BALL pairs a candidate; at most DEEP_FRONTS (2) such fronts were solved again,
  // and ball 95 ended on the far side of ball 94 (npm run bench:rows, its fine set)
  for (const [travel, tick] of [[0, 1 / 1920], [4, undefined]] as const) {
    it(`CONTACT_TRAVEL_HALVINGS ${travel}, CONTACT_TICK ${tick === undefined ? 'default' : '1/1920 s'}: no ball passes another for 1 s, the same bits at 60 and 120 Hz`, () => {
      const before = ticksRedone()
      const a = strikeRowAtWall(120, 0.3, 100, 3000, 60, 1, travel, tick)
      expect(a.passed).toBe(-1)
      expect(ticksRedone()).toBeGreaterThan(before)
      expect(strikeRowAtWall(120, 0.3, 100, 3000, 120, 1, travel, tick)).toEqual(a)
    })
  }
})

describe('fixed tick: a long row the projection takes out from one of its balls has its velocities solved again', () => {
  // a ball of mass 100 striking 120 radius-0.5 balls: the sweeps leave the row pressed within itself, off
  // the wall; the projection takes it out from one of its balls (src/contacts/fixedLayered.ts), and the push
  // it carries along the row moves balls up to others closing on them, by more than the gaps the tick's
  // velocities were solved at; without solving them again where the balls are now (systems/fixedContacts.ts)
  // each of these rows let a ball pass another; before the rows were taken out from a ball, the one at
  // 1e4 px/s did too
  const cases: Array<[gap: number, speed: number, e: number]> = [[0, 3000, 1], [0, 1e4, 1], [0.3, 300, 0]]
  for (const [gap, speed, e] of cases) {
    it(`120 radius-0.5 balls ${gap} px apart struck end on by a mass-100 ball at ${speed} px/s, e = ${e}, a wall 5 px past the row: a row taken from one of its balls, no ball passes another for 1 s, the same bits at 60 and 120 Hz`, () => {
      const before = anchoredCount()
      const a = strikeRowAtWall(120, gap, 100, speed, 60, e)
      expect(anchoredCount()).toBeGreaterThan(before)
      expect(a.passed).toBe(-1)
      expect(strikeRowAtWall(120, gap, 100, speed, 120, e)).toEqual(a)
    })
  }
})

describe('fixed tick: what a solve call keeps for the next within a tick (src/contacts/fixedCalls.ts)', () => {
  // each widening round solves again; a call after one that converged looks only at its new pairs and the
  // balls it changes (sweeps from a heap of pairs, rounds that look at the balls changed or cut), where a
  // whole sweep walked every pair and every round every ball the tick changed; and a round finds the
  // resting balls the rounds added and the balls with a capsule through lists and a hash
  // (src/contacts/fixedNear.ts), where it walked them all
  type Sim = ReturnType<typeof createBallPhysics>
  function run(radius: number, setup: (sim: Sim) => void, keep: boolean): { hash: string; kept: number; continued: number; found: number } {
    keepAcrossCalls(keep)
    useNearLists(keep)
    takeAsFound(keep)
    const before = callsKept()
    const continued = callsContinued()
    const found = takenAsFoundCount()
    try {
      const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 1, ROLLING_DECEL: 0, BALL_RADIUS: radius })
      setup(sim)
      let h = ''
      for (let f = 0; f < 12; f++) {
        sim.step(1 / 60)
        for (const e of sim.drainEvents()) h += `${e.type}${e.ball}:${e.time};`
      }
      const B = sim.world.Ball
      for (const b of sim.balls()) h += `${B.x[b]},${B.y[b]},${B.vx[b]},${B.vy[b]};`
      return { hash: h, kept: callsKept() - before, continued: callsContinued() - continued, found: takenAsFoundCount() - found }
    } finally {
      keepAcrossCalls(true)
      useNearLists(true)
      takeAsFound(true)
    }
  }
  const scenes: Array<[name: string, radius: number, least: number, setup: (sim: Sim) => void]> = [
    ['a row of 300 radius-0.5 balls 1 px apart', 0.5, 250, (sim) => {
      sim.addBall({ x: 0, y: 0, vx: 1e5, vy: 0 })
      for (let i = 0; i < 300; i++) sim.addBall({ x: 2 + i * 2, y: 0, vx: 0, vy: 0 })
    }],
    ['the same row in walls it lies along', 0.5, 250, (sim) => {
      sim.setWalls({ minX: -5, minY: -0.5, maxX: 700, maxY: 50, restitution: 1 })
      sim.addBall({ x: 0, y: 0, vx: 1e5, vy: 0 })
      for (let i = 0; i < 300; i++) sim.addBall({ x: 2 + i * 2, y: 0, vx: 0, vy: 0 })
    }],
    ['a row of 200 radius-11 balls', 11, 150, (sim) => {
      sim.addBall({ x: 0, y: 0, vx: 1e5, vy: 0 })
      for (let i = 0; i < 200; i++) sim.addBall({ x: 44 + i * 23, y: 0, vx: 0, vy: 0 })
    }],
    ['8 rows of 60 side by side', 0.5, 40, (sim) => {
      for (let r = 0; r < 8; r++) {
        sim.addBall({ x: 0, y: r * 4, vx: 1e5, vy: 0 })
        for (let i = 0; i < 60; i++) sim.addBall({ x: 2 + i * 4, y: r * 4, vx: 0, vy: 0 })
      }
    }],
    ['a mass-100 striker through 300', 0.5, 1, (sim) => {
      sim.addBall({ x: 0, y: 0, vx: 1e5, vy: 0, mass: 100 })
      for (let i = 0; i < 300; i++) sim.addBall({ x: 2 + i * 2, y: 0, vx: 0, vy: 0 })
    }],
  ]
  for (const [name, radius, least, setup] of scenes) {
    it(`${name}, struck at 1e5 px/s: calls keep, and give the same events and states as calls that keep nothing`, () => {
      const a = run(radius, setup, true)
      const b = run(radius, setup, false)
      expect(b.kept).toBe(0)
      expect(a.kept).toBeGreaterThanOrEqual(least)
      expect(a.hash.length).toBeGreaterThan(1000)
      expect(a.hash === b.hash).toBe(true)
    })
  }

  // 30 heavy balls (mass 700) thrown from one point at 3e4 px/s into a closed elastic box of 60 light ones
  // (mass 0.25): the heavy balls pump the light ones between them, and the calls seldom converge. A widening
  // round's call after one that did not converge keeps its stamps too (its first sweep walks every pair but
  // tests only those with a ball changed since), and the jam and wall rules half way through a call take a
  // pair whose balls have not changed since the sweeps found it refused or parting as found
  // (src/contacts/fixedStamps.ts). In the long adversarial run's 1,348th sequence, such a crowd, a third
  // of the sweeps' swept tests were in those first sweeps
  it('heavy balls pumping light ones in a closed box: calls continue with their stamps, the rules take pairs as found, and give the same events and states as calls that keep nothing', () => {
    const setup = (sim: Sim): void => {
      sim.setWalls({ minX: 0, minY: 0, maxX: 200, maxY: 160, restitution: 1 })
      for (let i = 0; i < 60; i++) sim.addBall({ x: 10 + (i % 10) * 18, y: 10 + Math.floor(i / 10) * 20, vx: 0, vy: 0, radius: 0.7, mass: 0.25 })
      for (let i = 0; i < 30; i++) {
        const a = (2 * Math.PI * i) / 30
        sim.addBall({ x: 100 + 0.3 * Math.cos(3 * a), y: 140 + 0.3 * Math.sin(5 * a), vx: 3e4 * Math.cos(a), vy: 3e4 * Math.sin(a), mass: 700 })
      }
    }
    const a = run(11, setup, true)
    const b = run(11, setup, false)
    expect(b.continued + b.kept + b.found).toBe(0)
    expect(a.continued).toBeGreaterThan(0)
    expect(a.found).toBeGreaterThan(0)
    expect(a.hash.length).toBeGreaterThan(1000)
    expect(a.hash === b.hash).toBe(true)
  })
})

describe('fixed tick: a push the projection carries along a row at rest', () => {
  // 55 touching radius-0.5 balls struck by a ball of mass 100 at 100 px/s, e = 1, a closed wall 5 px past
  // the row: by 0.5 s the row lies at rest against the wall and a slow push runs back along it. The
  // projection pushed ball after ball of it into the next, each round pairing one more ball at rest that the
  // tick had not gathered; the rounds stopped at MAX_WIDEN_ROUNDS with the fourth ball 1.7e-3 px deep in the
  // fifth (at 0.533 s). They now go on while each round pairs one ball more (systems/fixedContacts.ts).
  it('55 touching radius-0.5 balls struck by a ball of mass 100 at 100 px/s, e = 1, at 120 Hz: from 0.5 s no two balls more than 1e-3 px deep', () => {
    const n = 55
    const sim = createBallPhysics({ BALL_COLLISIONS: 'fixed', BALL_RESTITUTION: 1, ROLLING_DECEL: 0, BALL_RADIUS: 0.5 })
    sim.setWalls({ minX: -50, minY: -20, maxX: n + 5, maxY: 20, restitution: 1 })
    const ids = [sim.addBall({ x: -1, y: 0, vx: 100, vy: 0, mass: 100 })]
    for (let i = 0; i < n; i++) ids.push(sim.addBall({ x: i, y: 0, vx: 0, vy: 0 }))
    let deepest = 0
    for (let f = 0; f < 120; f++) {
      sim.step(1 / 120)
      sim.drainEvents()
      if (f + 1 < 60) continue
      const st = ids.map((i) => sim.ballState(i))
      for (let k = 1; k < st.length; k++) deepest = Math.max(deepest, 1 - Math.hypot(st[k]!.x - st[k - 1]!.x, st[k]!.y - st[k - 1]!.y))
    }
    expect(deepest).toBeLessThan(1e-3)
  })
})
