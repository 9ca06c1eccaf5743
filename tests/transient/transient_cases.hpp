// The contacts of CONTACT's transient examples as gap grids (SI units; the
// examples are in mm and N/mm^2): a sphere on a plane with the undeformed
// distance h = B (x^2 + y^2) on CONTACT's grid.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "contact/params.hpp"

namespace cwtest {

struct TransientCase {
    creepwork::GridSpec grid;
    creepwork::ContactInput input;
    std::vector<double> gap;
};

// nx x ny elements of size d [m] whose first centre is (x0, y0); h = B r^2.
inline TransientCase sphere_case(int nx, int ny, double x0, double y0, double d, double B,
                                 double N, double G, double nu, double mu)
{
    TransientCase c;
    c.grid.kind = creepwork::GridKind::gap;
    c.grid.nx = nx;
    c.grid.ny = ny;
    c.grid.x0 = x0;
    c.grid.y0 = y0;
    c.grid.dx = c.grid.dy = d;
    c.gap.resize(static_cast<size_t>(nx) * ny);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const double x = x0 + i * d, y = y0 + j * d;
            c.gap[i + static_cast<size_t>(nx) * j] = B * (x * x + y * y);
        }
    c.input.model = creepwork::ModelKind::exact;
    c.input.normal_force = N;
    c.input.G = G;
    c.input.nu = nu;
    c.input.mu = mu;
    c.input.gap = c.gap.data();
    c.input.gap_len = c.gap.size();
    return c;
}

// examples/catt_to_cart.inp: 34 x 33 elements of 0.25 mm from (-4.125, -4.125)
// mm, B = 0.002963 / mm, N = 0.4705 N, G = 1 N/mm^2, nu = 0.28, mu = 0.4013.
inline TransientCase catt_to_cart()
{
    return sphere_case(34, 33, -4.0e-3, -4.0e-3, 0.25e-3, 2.963, 0.4705, 1e6, 0.28, 0.4013);
}

// examples/cattaneo.inp: 19 x 19 elements of 0.13333 mm from -1.26667 mm,
// B = 0.01 / mm, N = 9.1954 N, G = 200 N/mm^2, nu = 0.42, mu = 0.4.
inline TransientCase cattaneo()
{
    const double d = 0.13333e-3;
    return sphere_case(19, 19, -1.26667e-3 + 0.5 * d, -1.26667e-3 + 0.5 * d, d, 10.0, 9.1954,
                       2e8, 0.42, 0.4);
}

// A number as CONTACT prints it (%.3E).
inline std::string printed(double v)
{
    char s[32];
    std::snprintf(s, sizeof s, "%.3E", v);
    return s;
}

} // namespace cwtest
