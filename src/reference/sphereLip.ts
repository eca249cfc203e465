// Physical reference model: a rigid sphere rolling into a circular hole with a sharp lip (described in
// docs/reference-model.md). Headless, deterministic, no dependency. This file runs one ball through the
// phases (referenceOutcome, referenceTrace); the phases themselves live in lipRoll.ts (2), flight.ts (3) and
// contact.ts (4), the settings in tolerances.ts, the public types in types.ts.
//
// Frame: the hole is centred at the origin, the lip is the circle of radius R in the plane z = 0, the surface
// is z = 0 outside it, gravity is −g ẑ. The ball (radius r, inertia j·m·r²) rolls along +x at y = δ.
//
// Internally everything is in units r = g = 1 (lengths in r, times in √(r/g), speeds in √(g·r)), so the
// outcome depends only on R/r, δ/r, v/√(g·r) and j, and the tolerances (tolerances.ts) mean the same thing for a golf
// ball and for a game sprite.
//
// Phases (docs/reference-model.md, "The model"):
//  1. rolling on the surface up to the instant the centre crosses the lip circle: closed form (a straight
//     line at constant speed), so the model starts at that instant;
//  2. rolling on the lip without slip: state y = [ψ, θ, ψ̇, θ̇, ω_n] integrated by DOPRI5 with three events
//     (θ rises through 0: rolled out; θ falls through −π/2: dropped in; N falls through 0: lift-off);
//  3. ballistic flight with constant spin: closed form; the landing (centre descends to z = r outside the
//     hole) and the drop (centre descends to z = 0 inside) are roots of quadratics; the lip contact (distance
//     from the centre to the lip circle back to r while approaching) is bracketed by conservative advancement
//     on the closed form and refined with Brent's method;
//  4. perfectly plastic, no-slip impact with the lip (angular momentum about the contact point kept), then
//     back to 2 (or straight back to 3 if the lip cannot hold the ball: N < 0 after the impact).
// One addition to these four phases, for a case they leave open: a "held" roll when, at N ≤ 0, the free path
// would run straight back into the lip (see HELD_EVENTS in lipRoll.ts).

import { impact, lipToCartesian } from './contact.js'
import { dopri5, type Dopri5Options } from './dopri5.js'
import { fly } from './flight.js'
import {
  EVENT_CLEAR,
  EVENT_DROPPED,
  EVENT_ROLLED_OUT,
  HELD_EVENTS,
  LIP_EVENTS,
  LIP_OPTIONS,
  lipEnergyScaled,
  lipRhs,
  normalForce,
  ws,
} from './lipRoll.js'
import { G, P, V, W, lip } from './state.js'
import { LIP_MAX_STEPS, MAX_PHASES, MAX_RATIO, MAX_SCALED_SPEED, MAX_TIME } from './tolerances.js'
import {
  validateReferenceInput,
  type PhaseEnd,
  type PhaseRecord,
  type ReferenceEnding,
  type ReferenceInput,
  type ReferenceOutcome,
  type ReferenceTrace,
} from './types.js'
import { atan2, hypot } from '../math.js'

/**
 * The lip phases' options, LIP_OPTIONS with maxSteps rewritten per phase under a step budget (one object, no
 * allocation; every phase passes it, so the integrator sees one shape of options)
 */
const BUDGETED: Dopri5Options & { maxSteps: number } = { rtol: LIP_OPTIONS.rtol, atol: LIP_OPTIONS.atol, hMax: LIP_OPTIONS.hMax, maxSteps: LIP_MAX_STEPS }

/**
 * Runs the model in scaled units (r = g = 1): rs = R/r, ds = δ/r, vs = v/√(g r). `trace` (optional) receives
 * the phases in scaled units; the caller converts. `stepBudget` (optional) bounds the integrator steps of all
 * lip phases together: a run that needs more ends 'integratorLimit' (the engine's live runs pass
 * LIVE_STEP_BUDGET; a run that decides takes far fewer, one that rolls round the lip to MAX_TIME far more).
 * Under the budget the run is the same, bit for bit.
 */
export function simulateScaled(rs: number, ds: number, vs: number, j: number, trace: PhaseRecord[] | null, stepBudget = Infinity): ReferenceOutcome {
  if (!(rs <= MAX_RATIO) || !(vs <= MAX_SCALED_SPEED)) {
    return { captured: false, turnAngle: 0, ending: 'outOfDomain', impacts: 0, phases: 0, duration: 0 }
  }
  P.rs = rs
  P.j = j
  const k = Math.sqrt(1 - (ds * ds) / (rs * rs))
  let t = 0
  let phases = 0
  let impacts = 0
  let turn = 0
  let used = 0
  let mode: 'lip' | 'held' | 'flight'
  const y = lip
  // lip state at the crossing (also the state a held roll starts from if the flight below cannot clear)
  y[0] = atan2(ds, -rs * k)
  y[1] = 0
  y[2] = (-vs * ds) / (rs * rs)
  y[3] = -vs * k
  y[4] = 0
  if (vs * vs * k * k > 1) {
    // too fast for the lip to hold it (N < 0 at θ = 0): flight from the crossing, rolling spin ω = ẑ × V / r
    G[0] = -rs * k
    G[1] = ds
    G[2] = 1
    V[0] = vs
    V[1] = 0
    V[2] = 0
    W[0] = 0
    W[1] = vs
    W[2] = 0
    mode = 'flight'
  } else {
    mode = 'lip'
  }
  const result = (ending: ReferenceEnding, captured: boolean, exit?: { vx: number; vy: number }): ReferenceOutcome => {
    const out: ReferenceOutcome = { captured, turnAngle: Math.abs(turn), ending, impacts, phases, duration: t }
    if (exit !== undefined) {
      out.exitSpeed = hypot(exit.vx, exit.vy)
      out.exitAngle = atan2(exit.vy, exit.vx)
      out.exitX = G[0]!
      out.exitY = G[1]!
    }
    return out
  }

  while (true) {
    if (phases >= MAX_PHASES) return result('phaseLimit', false)
    phases++
    if (mode === 'lip' || mode === 'held') {
      const held = mode === 'held'
      const psi0 = y[0]!
      const th0 = y[1]!
      const e0 = trace ? lipEnergyScaled(y, rs, j) : 0
      const t0 = t
      const left = stepBudget - used
      if (!(left >= 1)) return result('integratorLimit', false)
      BUDGETED.maxSteps = left < LIP_MAX_STEPS ? left : LIP_MAX_STEPS
      const res = dopri5(ws, lipRhs, t, y, MAX_TIME, BUDGETED, held ? HELD_EVENTS : LIP_EVENTS)
      used += res.accepted + res.rejected
      t = res.t
      turn += y[0]! - psi0
      let end: PhaseEnd
      if (res.status === 'event') {
        if (res.event === EVENT_ROLLED_OUT) end = 'rolledOut'
        else if (res.event === EVENT_DROPPED) end = 'droppedFromLip'
        else if (!held) end = 'liftOff'
        else end = res.event === EVENT_CLEAR ? 'clear' : 'pressing'
      } else {
        end = res.status === 'reachedEnd' ? 'timeLimit' : 'integratorLimit'
      }
      if (trace) {
        const rec: PhaseRecord = {
          kind: 'lip',
          tStart: t0,
          tEnd: t,
          end,
          psiStart: psi0,
          psiEnd: y[0]!,
          thetaStart: th0,
          thetaEnd: y[1]!,
          energyStart: e0,
          energyEnd: lipEnergyScaled(y, rs, j),
          steps: res.accepted + res.rejected,
        }
        if (held) rec.held = true
        trace.push(rec)
      }
      if (end === 'rolledOut') {
        lipToCartesian(y, rs)
        return result('rolledOut', false, { vx: V[0]!, vy: V[1]! })
      }
      if (end === 'droppedFromLip') return result('droppedFromLip', true)
      if (end === 'timeLimit' || end === 'integratorLimit') return result(end, false)
      if (end === 'pressing') {
        mode = 'lip'
      } else {
        lipToCartesian(y, rs)
        mode = 'flight'
      }
    } else {
      const t0 = t
      const { end, dt } = fly(rs)
      t += dt
      if (trace) trace.push({ kind: 'flight', tStart: t0, tEnd: t, end })
      if (end === 'sampleLimit') return result('flightLimit', false)
      if (end === 'landed') return result('hoppedOut', false, { vx: V[0]!, vy: V[1]! })
      if (end === 'droppedInFlight') return result('droppedInFlight', true)
      if (end === 'noClearance') {
        // N ≤ 0 but the free path runs into the lip at once (see HELD_EVENTS in lipRoll.ts): the lip keeps the ball
        // (y still holds the lip state the flight started from)
        mode = 'held'
        continue
      }
      if (t >= MAX_TIME) return result('timeLimit', false)
      impacts++
      impact(y, rs, j)
      // the lip holds the ball only if it presses on it; otherwise it flies off again at once
      mode = normalForce(y, rs) >= 0 ? 'lip' : 'flight'
    }
  }
}

function scaleOutcome(out: ReferenceOutcome, speedScale: number, timeScale: number, lengthScale: number): ReferenceOutcome {
  out.duration *= timeScale
  if (out.exitSpeed !== undefined) out.exitSpeed *= speedScale
  if (out.exitX !== undefined) out.exitX *= lengthScale
  if (out.exitY !== undefined) out.exitY *= lengthScale
  return out
}

/** Outcome of one ball (see ReferenceOutcome). Deterministic: the same input gives the same output. */
export function referenceOutcome(input: ReferenceInput): ReferenceOutcome {
  validateReferenceInput(input)
  const { delta, speed, holeRadius: R, ballRadius: r, gravity: g, inertia: j } = input
  const vScale = Math.sqrt(g * r)
  const out = simulateScaled(R / r, delta / r, speed / vScale, j, null)
  return scaleOutcome(out, vScale, Math.sqrt(r / g), r)
}

/** Outcome plus the phase sequence (times, tilts, contact angles, energies), in the input's units. */
export function referenceTrace(input: ReferenceInput): ReferenceTrace {
  validateReferenceInput(input)
  const { delta, speed, holeRadius: R, ballRadius: r, gravity: g, inertia: j } = input
  const vScale = Math.sqrt(g * r)
  const timeScale = Math.sqrt(r / g)
  const phases: PhaseRecord[] = []
  const outcome = scaleOutcome(simulateScaled(R / r, delta / r, speed / vScale, j, phases), vScale, timeScale, r)
  const eScale = g * r
  for (const p of phases) {
    p.tStart *= timeScale
    p.tEnd *= timeScale
    if (p.energyStart !== undefined) p.energyStart *= eScale
    if (p.energyEnd !== undefined) p.energyEnd *= eScale
  }
  return { outcome, phases }
}
