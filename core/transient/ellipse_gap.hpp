// A Hertzian contact given by its semi-axes, as the gap grid transient
// rolling runs on: the uniform grid of the exact model (GridKind::uniform,
// the box [-S a, S a] x [-S b, S b] of nx x ny elements, element (i, j) at
// [i + nx j]) with Hertz's undeformed distance h = A x^2 + B y^2 of the
// semi-axes a, b under N (contact/hertz.hpp; E* = G / (1 - nu)) and the
// normal force prescribed: the discrete normal problem the exact model
// solves on that grid, in the gap grid's units.
#pragma once

#include <vector>

#include "contact/params.hpp"

namespace creepwork {

struct EllipseGap {
    GridSpec grid;          // GridKind::gap, the uniform grid's elements
    std::vector<double> h;  // [i + nx j] [m]
};

// Throws Error(invalid_input) naming a bad semi-axis, load or material, or
// Error(grid_out_of_range).
EllipseGap ellipse_gap(const GridSpec& uniform, const ContactInput& in);

} // namespace creepwork
