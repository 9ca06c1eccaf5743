// A shape of gap_shapes.hpp as CONTACT's case (contact_gap.h): the grid,
// the gap, the load, the materials and the shape's own creepages, EPS eps.
// Shared by make_contact_reference and creepwork_bench_nonhertz.
#pragma once

extern "C" {
#include "contact_gap.h"
}
#include "gap_shapes.hpp"

inline contact_gap_case contact_case_of(const gapshapes::Shape& s, double eps)
{
    contact_gap_case c{};
    c.nx = s.nx;
    c.ny = s.ny;
    c.x0 = s.x0;
    c.y0 = s.y0;
    c.dx = s.dx;
    c.dy = s.dy;
    c.h = s.h.data();
    c.approach_given = s.approach_given;
    c.normal_force = s.normal_force;
    c.approach = s.approach;
    c.G = s.G;
    c.nu = s.nu;
    c.mu = s.mu;
    c.xi_x = s.xi_x;
    c.xi_y = s.xi_y;
    c.phi = s.phi;
    c.rolling_direction = s.rolling_direction;
    c.eps = eps;
    return c;
}
