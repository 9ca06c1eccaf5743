#include "wheelrail/hertz_patch.hpp"

#include <algorithm>
#include <cmath>

#include "contact/hertz.hpp"

namespace creepwork::wheelrail {

PatchForces HertzPatchEstimate::operator()(const ContactPatch& p) const
{
    PatchForces f;
    if (p.nx < 3 || p.ny < 3 || !(p.approach > 0.0)) return f;
    int k = 0;
    for (int m = 1; m < p.nx * p.ny; ++m)
        if (p.h[m] < p.h[k]) k = m;
    // keep the stencil inside the grid
    const int i = std::clamp(k % p.nx, 1, p.nx - 2), j = std::clamp(k / p.nx, 1, p.ny - 2);
    auto h = [&](int a, int b) { return p.h[a + b * p.nx]; };
    const double hxx = (h(i + 1, j) - 2.0 * h(i, j) + h(i - 1, j)) / (p.dx * p.dx);
    const double hss = (h(i, j + 1) - 2.0 * h(i, j) + h(i, j - 1)) / (p.ds * p.ds);
    // h = A x^2 + B y^2 with A, B > 0; a flat direction keeps a tiny curvature
    const double A = std::max(0.5 * hxx, 1e-6), B = std::max(0.5 * hss, 1e-6);
    const double e_star = G / (1.0 - nu);
    const double unit = hertz_from_curvatures(A, B, 1.0, e_star).approach; // approach at 1 N
    f.fn = std::pow(p.approach / unit, 1.5);                               // approach ~ N^(2/3)
    f.fn_by_approach = 1.5 * f.fn / p.approach;
    return f;
}

} // namespace creepwork::wheelrail
