// Dormand–Prince 5(4) Butcher tableau (Dormand & Prince 1980; Hairer, Nørsett & Wanner, "Solving ODEs I",
// §II.5–II.6): nodes C, stage coefficients A, 5th-order weights B, error weights E, and the coefficients P of
// Hairer's 4th-order continuous extension (dense output, the same as SciPy's RK45).

export const C2 = 1 / 5
export const C3 = 3 / 10
export const C4 = 4 / 5
export const C5 = 8 / 9
export const A21 = 1 / 5
export const A31 = 3 / 40
export const A32 = 9 / 40
export const A41 = 44 / 45
export const A42 = -56 / 15
export const A43 = 32 / 9
export const A51 = 19372 / 6561
export const A52 = -25360 / 2187
export const A53 = 64448 / 6561
export const A54 = -212 / 729
export const A61 = 9017 / 3168
export const A62 = -355 / 33
export const A63 = 46732 / 5247
export const A64 = 49 / 176
export const A65 = -5103 / 18656
// 5th-order weights (also the 7th stage's row: first same as last)
export const B1 = 35 / 384
export const B3 = 500 / 1113
export const B4 = 125 / 192
export const B5 = -2187 / 6784
export const B6 = 11 / 84
// error weights: 5th-order minus embedded 4th-order weights
export const E1 = 71 / 57600
export const E3 = -71 / 16695
export const E4 = 71 / 1920
export const E5 = -17253 / 339200
export const E6 = 22 / 525
export const E7 = -1 / 40
// dense output: y(t + x·h) = y + h·Σ_k k_k·(P_k1·x + P_k2·x² + P_k3·x³ + P_k4·x⁴); row 2 is zero
export const P1 = [1, -8048581381 / 2820520608, 8663915743 / 2820520608, -12715105075 / 11282082432] as const
export const P3 = [0, 131558114200 / 32700410799, -68118460800 / 10900136933, 87487479700 / 32700410799] as const
export const P4 = [0, -1754552775 / 470086768, 14199869525 / 1410260304, -10690763975 / 1880347072] as const
export const P5 = [0, 127303824393 / 49829197408, -318862633887 / 49829197408, 701980252875 / 199316789632] as const
export const P6 = [0, -282668133 / 205662961, 2019193451 / 616988883, -1453857185 / 822651844] as const
export const P7 = [0, 40617522 / 29380423, -110615467 / 29380423, 69997945 / 29380423] as const
