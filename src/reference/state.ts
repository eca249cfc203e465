// Module-level state shared by the phases of a run, in scaled units (r = g = 1): the run's non-dimensional
// parameters (read by the lip equations and events), the lip state vector and the flying ball's centre,
// velocity and spin. Preallocated once; a run is synchronous, so runs never overlap.

/** Non-dimensional parameters of a run: hole radius in ball radii and the inertia factor. */
export interface Params {
  rs: number
  j: number
}

export const P: Params = { rs: 2, j: 0.4 }
/** lip state y = [ψ, θ, ψ̇, θ̇, ω_n] (scaled) */
export const lip = new Float64Array(5)
// flight state: centre, velocity, spin (scaled)
export const G = new Float64Array(3)
export const V = new Float64Array(3)
export const W = new Float64Array(3)
