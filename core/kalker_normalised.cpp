#include "kalker_normalised.hpp"

#include <cmath>
#include <string>

#include "contact_grid.hpp"
#include "error.hpp"
#include "fastsim.hpp"

namespace creepwork {
namespace {

void require_finite(const char* name, double v)
{
    if (!std::isfinite(v))
        throw Error(ErrorKind::invalid_input, std::string(name) + " must be a finite number");
}

// Strip boundaries: my equal strips; when the longitudinal rigid slip
// changes sign inside a strip (y0 = ux/fx) and tol asks for it, that strip
// is cut at y0 so that no strip straddles the sign change.
Eigen::ArrayXd strip_bounds(double ux, double fx, int my, double tol)
{
    Eigen::ArrayXd equal = Eigen::ArrayXd::LinSpaced(my + 1, -1.0, 1.0);
    if (fx == 0.0) return equal;
    const double y0 = ux / fx;
    for (int j = 0; j < my; ++j) {
        const double lo = equal[j], hi = equal[j + 1];
        const double width = hi - lo;
        if (!(y0 > lo && y0 < hi)) continue;
        if (std::fabs(y0 - 0.5 * (lo + hi)) > tol * width && tol < 1.0) continue;
        if (tol >= 1.0) break;
        Eigen::ArrayXd split(my + 2);
        split.head(j + 1) = equal.head(j + 1);
        split[j + 1] = y0;
        split.tail(my - j) = equal.tail(my - j);
        return split;
    }
    return equal;
}

} // namespace

NormalisedForces kalker_fastsim_normalised(double ux, double uy, double fx, double fy, int mx,
                                           int my, double tol)
{
    require_finite("ux", ux);
    require_finite("uy", uy);
    require_finite("fx", fx);
    require_finite("fy", fy);
    require_finite("tol", tol);
    const ContactGrid grid(mx, strip_bounds(ux, fx, my, tol));
    MarchState state;
    state.resize(grid.size(), grid.ny());
    NormalisedKinematics kin;
    kin.ux = ux;
    kin.uy = uy;
    kin.cx = fx;
    kin.cy = fy;
    march(grid, kin, PressureKind::parabolic, state);
    // Unit-disk forces divided by the load integral pi/2; the march computes
    // the traction on the wheel, so the rail's is its negative.
    double tx = 0.0, ty = 0.0;
    for (int j = 0; j < grid.ny(); ++j) {
        const double area = grid.x_length()[j] * grid.y_width()[j];
        tx += area * state.sum_px[j];
        ty += area * state.sum_py[j];
    }
    const double scale = -2.0 / 3.14159265358979323846;
    return {scale * tx, scale * ty};
}

} // namespace creepwork
