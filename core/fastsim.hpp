// The FASTSIM march (Kalker 1982) in normalised units: tractions p' in units
// of mu*p0, bound = pressure shape (1 at the centre). All strips advance one
// step together, so the inner loop runs across strips and vectorises.
#pragma once

#include <Eigen/Core>

#include "contact_grid.hpp"
#include "model_setup.hpp"

namespace creepwork {

// Per-element state of one solve, march order (see contact_grid.hpp).
// The trial traction q' (elastic predictor) and the factor f that scales it
// onto the traction bound are kept: p' = f q', f = 1 in adhesion, f < 1 in
// slip. Slip, dissipation and every other field follow from (q', f).
struct MarchState {
    Eigen::ArrayXd qx, qy, factor;
    // Per strip: sums over the strip of p'_x, p'_y and X p'_y, and the
    // number of slip elements (a double so the march loop stays all-double).
    Eigen::ArrayXd sum_px, sum_py, sum_x_py, slip_count;
    // Per strip: running traction, the march's only carried state.
    Eigen::ArrayXd px, py;

    void resize(int n_elements, int ny);
};

// Advance every strip from the leading edge (m = 0) to the trailing edge.
// Writes state; allocates nothing.
void march(const ContactGrid& grid, const NormalisedKinematics& kin, PressureKind pressure,
           MarchState& state);

} // namespace creepwork
