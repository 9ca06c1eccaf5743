// The flexibility of the spin part of FASTSIM's longitudinal slip that makes
// the simplified theory's creep moment Kalker's C33 in the linear limit.
//
// Derivation (continuum, no slip; X = x/a, the march from the leading edge
// x = a(y) = a sqrt(1 - y^2/b^2)): the spin part of the x-traction is
// p_x = phi y (a(y) - x) / L_M, odd in y, so it adds nothing to Fx or Fy;
// the spin part of p_y is phi (a(y)^2 - x^2) / (2 L3), even in x, so its
// moment x p_y integrates to zero. The spin moment is therefore all from
// -y p_x: |Mz| = (phi / L_M) int y^2 2 a(y)^2 dy = (8/15) a^2 b^3 phi / L_M.
// Kalker's linear theory: |Mz| = G (ab)^2 C33 phi. Equal when
//   L_M = 8 b / (15 G C33).
// Plain FASTSIM uses L3 there, which gives C33_eff = (32/(15 pi)) (b/a)^(3/2)
// C23 (16 % below C33 at a/b = 1 and nu = 0.28, 23 % at a/b = 2).
// (A derivation, not a published method; tests/core/test_core_calibrated.cpp
// checks it on the grid against Kalker 1990, Table E.3.)
#pragma once

namespace creepwork {

// b [m], G [Pa], C33 [-] -> L_M [m/Pa].
double moment_consistent_flexibility(double b, double G, double C33);

} // namespace creepwork
