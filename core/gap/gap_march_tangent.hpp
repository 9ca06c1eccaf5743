// Forward-mode derivatives of the march on a gap grid (gap_march.hpp): the
// march again, each element carrying the derivative of its traction by the
// rolling-frame creepages xi, eta, phi and by the normal force N. Per
// element q = p_prev - dx omega with omega linear in (xi, eta, phi), so
//   adhesion: dp = dq,
//   slip:     p = g q / |q| (g = mu pz), dp = (g / |q|) (I - e e^T) dq + e dg,
//             e = q / |q|,
// with dg = mu dpz/dN in the N column (the normal method's derivative) and
// dq = dp_prev - dx domega. The patches' flexibilities and spin centres
// depend on their sizes in whole elements, piecewise constant in N: held
// fixed. An element exactly on the bound takes the state the march found.
//
// Under a law of the slip speed, in slip p = f q with f = t / P, P = |q|,
// t = pz mu(s), s = c (P - t), c = V Lq / (P dx), Lq = |(L1 q_x, L2 q_y)|:
//   dt = (mu dpz + pz mu' (c dP + (P - t) dc)) / (1 + pz c mu'),
//   dc = c (dLq / Lq - dP / P),  dp = (dt - f dP) / P q + f dq
// (derivative 0 where 1 + pz c mu' = 0), as the ellipse's march under a law
// (fastsim/march_law.hpp).
#pragma once

#include "gap/gap_march.hpp"

namespace creepwork {

// dF[r][c]: r = Fx, Fy, Mz (rolling frame, Mz about its origin; N, N m),
// c = xi, eta, phi (rolling frame), N. dpressure: the bound's pressure's
// derivative by N [1/m^2] per element [i + nx j] (rolling frame: dpz/dN, times
// the friction factors with in.bound_pressure), or null (N column zero).
// Allocates nothing.
void gap_march_tangent(const GapMarchInput& in, const double* dpressure, double dF[3][4]);

} // namespace creepwork
