// The smallest box of a grid's cells that holds every cell a predicate
// picks (the contact, the active set): the exact model's products run on it
// (tractions and pressures vanish outside). Without such a cell the box is
// the whole grid.
#pragma once

#include <algorithm>
#include <cstddef>

namespace creepwork {

struct CellBox {
    int i0 = 0, j0 = 0; // first cell along x, y
    int nx = 0, ny = 0; // cells along x, y
};

// in(k) for cell k = i + nx j of an nx x ny grid.
template <class In>
CellBox cell_box(int nx, int ny, In in)
{
    int i0 = nx, i1 = -1, j0 = ny, j1 = -1;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            if (in(i + static_cast<std::size_t>(nx) * j)) {
                i0 = std::min(i0, i);
                i1 = std::max(i1, i);
                j0 = std::min(j0, j);
                j1 = std::max(j1, j);
            }
    if (i1 < 0) return {0, 0, nx, ny};
    return {i0, j0, i1 - i0 + 1, j1 - j0 + 1};
}

} // namespace creepwork
