// Contact kinematics between the lip coordinates (ψ, θ, ψ̇, θ̇, ω_n) and the Cartesian centre, velocity and
// spin (G, V, W): the rolling ball's Cartesian state at a lift-off or a roll-out, and the plastic no-slip
// impact that turns a flying ball back into a lip state. Scaled units (r = g = 1).

import { G, V, W } from './state.js'
import { atan2, cos, hypot, sin } from '../math.js'

/** Writes the centre, velocity and spin of the ball rolling on the lip in state y into G, V, W. */
export function lipToCartesian(y: Float64Array, rs: number): void {
  const psi = y[0]!
  const th = y[1]!
  const pd = y[2]!
  const td = y[3]!
  const wn = y[4]!
  const cp = cos(psi)
  const sp = sin(psi)
  const st = sin(th)
  const ct = cos(th)
  const rho = rs + st
  // n = sinθ e_ρ + cosθ e_z, t_θ = cosθ e_ρ − sinθ e_z, e_ρ = (cp, sp, 0), e_ψ = (−sp, cp, 0)
  const nx = st * cp
  const ny = st * sp
  const nz = ct
  G[0] = rho * cp
  G[1] = rho * sp
  G[2] = ct
  // V = ρ ψ̇ e_ψ + r θ̇ t_θ
  V[0] = -rho * pd * sp + td * ct * cp
  V[1] = rho * pd * cp + td * ct * sp
  V[2] = -td * st
  // ω = ω_n n + n × V / r
  W[0] = wn * nx + (ny * V[2]! - nz * V[1]!)
  W[1] = wn * ny + (nz * V[0]! - nx * V[2]!)
  W[2] = wn * nz + (nx * V[1]! - ny * V[0]!)
}

/**
 * Plastic no-slip impact at the lip point nearest to the centre G (|G − P| = r): keeps the angular momentum
 * about P, L = (G − P) × V + j r² ω; ω⁺ = (L·n) n / (j r²) + (L − (L·n) n) / ((1+j) r²), V⁺ = ω⁺ × (G − P).
 * Writes the lip state into y.
 */
export function impact(y: Float64Array, rs: number, j: number): void {
  const gx = G[0]!
  const gy = G[1]!
  const gz = G[2]!
  const rhoG = hypot(gx, gy)
  const psi = atan2(gy, gx)
  const cp = gx / rhoG
  const sp = gy / rhoG
  // n = (G − P)/|G − P|, with P = R e_ρ (|G − P| = r up to the rounding of the contact search)
  const ex = gx - rs * cp
  const ey = gy - rs * sp
  const en = Math.sqrt(ex * ex + ey * ey + gz * gz)
  const nx = ex / en
  const ny = ey / en
  const nz = gz / en
  const vx = V[0]!
  const vy = V[1]!
  const vz = V[2]!
  // L/(m r²) = n × V + j ω (units r = 1)
  const lx = ny * vz - nz * vy + j * W[0]!
  const ly = nz * vx - nx * vz + j * W[1]!
  const lz = nx * vy - ny * vx + j * W[2]!
  const ln = lx * nx + ly * ny + lz * nz
  const wx = (ln * nx) / j + (lx - ln * nx) / (1 + j)
  const wy = (ln * ny) / j + (ly - ln * ny) / (1 + j)
  const wz = (ln * nz) / j + (lz - ln * nz) / (1 + j)
  const ux = wy * nz - wz * ny
  const uy = wz * nx - wx * nz
  const uz = wx * ny - wy * nx
  // tilt from n = sinθ e_ρ + cosθ e_z; θ̇ and ψ̇ from V⁺ = ρψ̇ e_ψ + r θ̇ t_θ
  const sinTh = nx * cp + ny * sp
  const th = atan2(sinTh, nz)
  const st = sin(th)
  const ct = cos(th)
  const rho = rs + st
  y[0] = psi
  y[1] = th
  y[2] = (-ux * sp + uy * cp) / rho
  y[3] = (ux * cp + uy * sp) * ct - uz * st
  y[4] = ln / j
  W[0] = wx
  W[1] = wy
  W[2] = wz
  V[0] = ux
  V[1] = uy
  V[2] = uz
}
