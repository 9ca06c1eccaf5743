// Kalker's linear-theory creepage and spin coefficients and the flexibilities
// of the simplified theory derived from them.
#pragma once

namespace creepwork {

struct CreepCoefficients {
    double C11, C22, C23, C33;
};

struct Flexibilities {
    double L1, L2, L3;
};

// C11, C22, C23, C33 for semi-axis ratio a/b (1e-3 .. 1e3) and Poisson's
// ratio nu (0 .. 0.5): Kalker 1990, Table E.3, interpolated linearly in
// g = min(a/b, b/a) and quadratically in 1/C through nu = 0, 0.25, 0.5;
// Kalker's asymptotes below g = 0.1 (see the .cpp for C33).
CreepCoefficients kalker_coefficients(double a_over_b, double nu);

// Kalker 1982: L1 = 8a/(3 C11 G), L2 = 8a/(3 C22 G),
// L3 = pi a sqrt(a/b) / (4 C23 G).
Flexibilities kalker_flexibilities(double a, double b, double G, const CreepCoefficients& c);

} // namespace creepwork
