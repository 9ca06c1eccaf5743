// Polach's creep-force model: the whole contact's forces in closed form,
// no grid (O. Polach, "A fast wheel-rail forces calculation computer code",
// Vehicle System Dynamics 33 suppl. (1999) 728-739, with spin; "Creep forces
// in simulations of traction vehicles running on adhesion limit", Wear 258
// (2005) 992-1000, with the reduction factors k_A, k_S and friction falling
// with the slip speed). Formulas and their variables: doc/theory/friction.md.
//
// With s = |(xi_x, xi_y)|, w = s V the slip speed and mu = mu(w) the law:
//   s_yc = xi_y + phi a  if |xi_y + phi a| > |xi_y|,  else xi_y;
//   s_c = |(xi_x, s_yc)|;  c_jj = |(C11 xi_x, C22 xi_y)| / s;
//   eps = G pi a b c_jj s_c / (4 Q mu);
//   F = (2 Q mu / pi) [k_A eps / (1 + (k_A eps)^2) + atan(k_S eps)];
//   K_M = 1 + 6.3 (1 - exp(-a/b));
//   eps_M = 8 b sqrt(ab) G C23 |s_yc| / (3 K_M Q mu);
//   delta = (eps_M^2 - 1) / (eps_M^2 + 1);
//   F_ys = (9/16) a mu K_M [eps_M (-delta^3/3 + delta^2/2 - 1/6)
//                          + (1 - delta^2)^(3/2) / 3];
//   Fx = -F xi_x / s_c,  Fy = -(F xi_y + Q F_ys phi) / s_c.
// k_A = k_S = 1 and a Coulomb law give Polach 1999. Forces on the wheel
// (body 1), creepwork's signs (Kalker's). The model has no moment Mz.
#pragma once

#include "friction/slip_speed_law.hpp"

namespace creepwork {

struct PolachInput {
    double Q = 0.0;                      // normal force [N] >= 0
    double a = 0.0, b = 0.0;             // semi-axes [m] > 0 (a along the rolling direction)
    double G = 0.0;                      // combined shear modulus [Pa] > 0
    double C11 = 0.0, C22 = 0.0, C23 = 0.0; // Kalker's coefficients [-]
    double xi_x = 0.0, xi_y = 0.0;       // creepages [-]
    double phi = 0.0;                    // spin creepage [1/m]
    double V = 0.0;                      // rolling speed [m/s] (read by a falling law)
    SlipSpeedLaw law;                     // mu of the slip speed w = s V
    double k_A = 1.0, k_S = 1.0;         // Polach 2005's reductions in adhesion and slip
};

struct PolachResult {
    double Fx = 0.0, Fy = 0.0; // [N]
    double mu = 0.0;           // the coefficient at the contact's slip speed
    double epsilon = 0.0;      // the gradient of the tangential stress, eps
};

PolachResult polach_forces(const PolachInput& in);

} // namespace creepwork
