// The gap grid a shape of gap_shapes.hpp is given on, for the tests and the
// benchmark that solve the shapes through the C++ core.
#pragma once

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

} // namespace gapshapes
