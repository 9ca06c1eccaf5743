// The gap grid a shape of gap_shapes.hpp is given on, for the tests and the
// benchmark that solve the shapes through the C++ core.
#pragma once

#include <vector>

#include "contact/hertz.hpp"
#include "contact/params.hpp"
#include "gap_shapes.hpp"

namespace gapshapes {

inline creepwork::GridSpec grid_of(const Shape& s)
{
    creepwork::GridSpec g;
    g.kind = creepwork::GridKind::gap;
    g.nx = s.nx;
    g.ny = s.ny;
    g.x0 = s.x0;
    g.y0 = s.y0;
    g.dx = s.dx;
    g.dy = s.dy;
    return g;
}

// The contact of a shape: its gap (borrowed: s must outlive the input),
// load, material and rolling direction; model, normal method and creepages
// are the caller's (the defaults: exact, exact, none).
inline creepwork::ContactInput contact_input(const Shape& s)
{
    creepwork::ContactInput in;
    in.gap = s.h.data();
    in.gap_len = s.h.size();
    in.normal_load = s.approach_given ? creepwork::NormalLoad::approach
                                      : creepwork::NormalLoad::force;
    in.normal_force = s.normal_force;
    in.approach = s.approach;
    in.G = s.G;
    in.nu = s.nu;
    in.mu = s.mu;
    in.rolling_direction = s.rolling_direction;
    return in;
}

// The Hertzian gap of an elliptic contact on the cells of the elliptic exact
// model's uniform n x n grid of box scale S (cell centres): the grid, and
// the gap in h. On it the exact model on a gap solves the elliptic model's
// discrete problem.
inline creepwork::GridSpec hertzian_gap(const creepwork::ContactInput& e, int n, double S,
                                        std::vector<double>& h)
{
    creepwork::GridSpec g;
    g.kind = creepwork::GridKind::gap;
    g.nx = g.ny = n;
    g.dx = 2 * S * e.a / n;
    g.dy = 2 * S * e.b / n;
    g.x0 = -S * e.a + 0.5 * g.dx;
    g.y0 = -S * e.b + 0.5 * g.dy;
    const creepwork::HertzCurvatures hz =
        creepwork::hertz_from_semi_axes(e.a, e.b, e.normal_force, e.G / (1.0 - e.nu));
    h.assign(static_cast<size_t>(n) * n, 0.0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double x = g.x0 + i * g.dx, y = g.y0 + j * g.dy;
            h[i + static_cast<size_t>(n) * j] = hz.A * x * x + hz.B * y * y;
        }
    return g;
}

} // namespace gapshapes
