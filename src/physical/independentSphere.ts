// The independent rigid-sphere model's dynamics (docs/physical.md, "An independent model"): a sphere of
// radius r and inertia j·m·r² as a free body in 3D (centre G, velocity V, spin ω, all Cartesian vectors in
// the game's own units, px and s), held on the sharp lip circle (radius R, plane z = 0) by a contact force
// that is solved for at every evaluation, or flying under gravity. It shares no code with src/reference/,
// which writes the same idealisation as equations in the lip's angles (ψ, θ) and integrates them by DOPRI5;
// here nothing is written in angles and the integrator is a fixed-step RK4 (src/physical/independent.ts).

/** Geometry and physics of one run: hole and ball radii (px), g (px/s²), inertia ratio j. */
export interface SphereLip {
  R: number
  r: number
  g: number
  j: number
}

/** A state is 9 numbers: G (0..2), V (3..5), ω (6..8); z up, the lip in the plane z = 0. */
export const STATE_SIZE = 9

/**
 * Derivative of the state while the ball touches the lip without slipping; returns N/m, the normal part of
 * the contact force per mass (negative: the lip would have to pull).
 *
 * The contact point is the lip's point nearest G, P = R·e_ρ. The sphere's material point there is at rest:
 * c = V + ω × (P − G) = 0. Differentiating with Ṗ (the contact point running along the lip) and Newton–Euler
 * (a = f − g·ẑ, α = (P − G) × f / (j·r²) for the contact force f per mass, P − G = −r·n) gives
 * f + (f − (f·n)·n)/j = b with b = g·ẑ − ω × (Ṗ − V): the force's normal part is b·n, its tangential part
 * j/(1+j) of b's. A 3 × 3 solve in closed form, so nothing about the lip's angles enters.
 */
export function lipDerivative(p: SphereLip, y: Float64Array, out: Float64Array): number {
  const gx = y[0]!
  const gy = y[1]!
  const gz = y[2]!
  const vx = y[3]!
  const vy = y[4]!
  const vz = y[5]!
  const wx = y[6]!
  const wy = y[7]!
  const wz = y[8]!
  const rho = Math.sqrt(gx * gx + gy * gy)
  const ex = gx / rho
  const ey = gy / rho
  // n: unit vector from P to G
  const dx = (rho - p.R) * ex
  const dy = (rho - p.R) * ey
  const dl = Math.sqrt(dx * dx + dy * dy + gz * gz)
  const nx = dx / dl
  const ny = dy / dl
  const nz = gz / dl
  // Ṗ = R·ψ̇·e_ψ, with ψ̇ the turn rate of G about the hole's axis
  const psiDot = (gx * vy - gy * vx) / (rho * rho)
  const ux = -p.R * psiDot * ey - vx
  const uy = p.R * psiDot * ex - vy
  const uz = -vz
  // b = g·ẑ − ω × (Ṗ − V)
  const bx = -(wy * uz - wz * uy)
  const by = -(wz * ux - wx * uz)
  const bz = p.g - (wx * uy - wy * ux)
  const bn = bx * nx + by * ny + bz * nz
  const k = p.j / (1 + p.j)
  const fx = bn * nx + k * (bx - bn * nx)
  const fy = bn * ny + k * (by - bn * ny)
  const fz = bn * nz + k * (bz - bn * nz)
  out[0] = vx
  out[1] = vy
  out[2] = vz
  out[3] = fx
  out[4] = fy
  out[5] = fz - p.g
  // α = −(n × f)/(j·r)
  const s = -1 / (p.j * p.r)
  out[6] = s * (ny * fz - nz * fy)
  out[7] = s * (nz * fx - nx * fz)
  out[8] = s * (nx * fy - ny * fx)
  return bn
}

/** Derivative of the state in flight: gravity only, the spin unchanged. */
export function flightDerivative(p: SphereLip, y: Float64Array, out: Float64Array): void {
  out[0] = y[3]!
  out[1] = y[4]!
  out[2] = y[5]!
  out[3] = 0
  out[4] = 0
  out[5] = -p.g
  out[6] = 0
  out[7] = 0
  out[8] = 0
}

/**
 * Puts the ball on the lip without slipping, in place. G moves along n to distance r from the nearest lip
 * point P; then a plastic, no-slip impulse at P: the angular momentum about P, L = (G − P) × V + j·r²·ω, is
 * kept, and V = ω × (G − P). Its normal part gives ω·n = L·n/(j·r²), its tangential part (1+j)·r²·ω_t = L_t.
 * This is the impact at a re-touch, and after every step on the lip it is the projection back onto the
 * constraint (an impulse at P gives the state on the constraint nearest in the kinetic-energy norm).
 */
export function projectOntoLip(p: SphereLip, y: Float64Array): void {
  const rho = Math.sqrt(y[0]! * y[0]! + y[1]! * y[1]!)
  const ex = y[0]! / rho
  const ey = y[1]! / rho
  let dx = (rho - p.R) * ex
  let dy = (rho - p.R) * ey
  let dz = y[2]!
  const dl = Math.sqrt(dx * dx + dy * dy + dz * dz)
  dx *= p.r / dl
  dy *= p.r / dl
  dz *= p.r / dl
  y[0] = p.R * ex + dx
  y[1] = p.R * ey + dy
  y[2] = dz
  const jr2 = p.j * p.r * p.r
  const vx = y[3]!
  const vy = y[4]!
  const vz = y[5]!
  const lx = dy * vz - dz * vy + jr2 * y[6]!
  const ly = dz * vx - dx * vz + jr2 * y[7]!
  const lz = dx * vy - dy * vx + jr2 * y[8]!
  const nx = dx / p.r
  const ny = dy / p.r
  const nz = dz / p.r
  const ln = lx * nx + ly * ny + lz * nz
  const t = 1 / ((1 + p.j) * p.r * p.r)
  const wx = (ln * nx) / jr2 + (lx - ln * nx) * t
  const wy = (ln * ny) / jr2 + (ly - ln * ny) * t
  const wz = (ln * nz) / jr2 + (lz - ln * nz) * t
  y[6] = wx
  y[7] = wy
  y[8] = wz
  // V = ω × (G − P)
  y[3] = wy * dz - wz * dy
  y[4] = wz * dx - wx * dz
  y[5] = wx * dy - wy * dx
}

/** Mechanical energy per mass, ½|V|² + ½·j·r²·|ω|² + g·z: kept while the ball rolls on the lip or flies. */
export function energy(p: SphereLip, y: Float64Array): number {
  const v2 = y[3]! * y[3]! + y[4]! * y[4]! + y[5]! * y[5]!
  const w2 = y[6]! * y[6]! + y[7]! * y[7]! + y[8]! * y[8]!
  return 0.5 * v2 + 0.5 * p.j * p.r * p.r * w2 + p.g * y[2]!
}

/** Squared distance from G to the lip circle minus r²: negative when the sphere reaches through the lip. */
export function lipGap(p: SphereLip, gx: number, gy: number, gz: number): number {
  const e = Math.sqrt(gx * gx + gy * gy) - p.R
  return e * e + gz * gz - p.r * p.r
}

/** The rate of change of lipGap along the state's velocity. */
export function lipGapRate(p: SphereLip, y: Float64Array): number {
  const rho = Math.sqrt(y[0]! * y[0]! + y[1]! * y[1]!)
  const rhoDot = (y[0]! * y[3]! + y[1]! * y[4]!) / rho
  return 2 * ((rho - p.R) * rhoDot + y[2]! * y[5]!)
}

/**
 * Angular momentum about a lip point P = (px, py, 0), per mass: (G − P) × V + j·r²·ω, into out[0..2].
 * Kept by the impact at P (tests/independent.test.ts).
 */
export function momentAbout(p: SphereLip, y: Float64Array, px: number, py: number, out: Float64Array): void {
  const dx = y[0]! - px
  const dy = y[1]! - py
  const dz = y[2]!
  const jr2 = p.j * p.r * p.r
  out[0] = dy * y[5]! - dz * y[4]! + jr2 * y[6]!
  out[1] = dz * y[3]! - dx * y[5]! + jr2 * y[7]!
  out[2] = dx * y[4]! - dy * y[3]! + jr2 * y[8]!
}
