// The uniform grid as the exact model sees it (CONTACT's potential contact
// area, doc/theory/exact-discretisation.md rule 1): nx x ny elements over the box
// [-S a, S a] x [-S b, S b], element (i, j) at [i + nx j], i along x in the
// rolling frame (leading edge at +x). Lengths are in units of the element
// length dx = 2 S a / nx, so the normalised problems depend only on the
// grid and a/b (exact/exact_model.hpp).
#pragma once

namespace creepwork {

struct ExactGeometry {
    int nx = 0, ny = 0;
    double box_scale = 1.0; // S
    double alpha = 0.0;     // a / dx = nx / (2 S)
    double beta = 0.0;      // b / dx
    double rho = 0.0;       // dy / dx

    ExactGeometry() = default;
    ExactGeometry(int nx_, int ny_, double S, double a_over_b)
        : nx(nx_), ny(ny_), box_scale(S), alpha(nx_ / (2.0 * S)), beta(alpha / a_over_b),
          rho(2.0 * S * beta / ny_)
    {
    }
    int size() const { return nx * ny; }
    // Element centre, in units of dx.
    double X(int i) const { return (i + 0.5) - 0.5 * nx; }
    double Y(int j) const { return ((j + 0.5) - 0.5 * ny) * rho; }
};

} // namespace creepwork
