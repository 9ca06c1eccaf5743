#include "fastsim/kalker_normalised.hpp"

#include <cmath>
#include <string>

#include "contact/contact_grid.hpp"
#include "contact/error.hpp"
#include "march/march.hpp"
#include "march/march_setup.hpp"

namespace creepwork {
namespace {

void require_finite(const char* name, double v)
{
    if (!std::isfinite(v))
        throw Error(ErrorKind::invalid_input, std::string(name) + " must be a finite number");
}

// Kalker's 1982 strip layout, reconstructed from his published check values
// (tests/data/kalker1982_checks.csv: all five rows to 4 decimals;
// the rules below were identified by reproducing them, see doc/migrating.md):
//  1. The spin pole (x0, y0) = (-uy/fy, ux/fx) is where the rigid slip
//     (ux - y fx, uy + x fy) vanishes. If it lies inside the unit disk, the
//     strips are cut at ys = y0 (the x-slip changes sign there); otherwise
//     at ys = 0.
//  2. [-1, ys] and [ys, 1] get ceil(my (1 + ys)/2) and ceil(my (1 - ys)/2)
//     equal strips (so my odd gives my + 1 strips even without spin).
//  3. With the pole inside, the strip next to ys on each side is bisected
//     towards ys while it is wider than 2 tol, i.e. while its centre lies
//     more than tol from y0 (tol >= 1 never bisects; the cut stays).
// At most kMaxGridCells strips: the bisections, then the strip counts, are
// capped so that the grid limits of the C ABI (mx, my <= 1000) always hold.
constexpr int kMaxBisections = 40; // 2^-40 of a strip: far below any useful tol

int strips_over(double length, int my)
{
    // The tolerance keeps exact products (my even, ys = 0) from rounding up.
    const double n = std::ceil(0.5 * my * length - 1e-9);
    return n < 1.0 ? 1 : static_cast<int>(n);
}

Eigen::ArrayXd strip_bounds(double ux, double uy, double fx, double fy, int my, double tol)
{
    double ys = 0.0;
    bool pole_inside = false;
    if (fx != 0.0 && fy != 0.0) {
        const double x0 = -uy / fy, y0 = ux / fx;
        if (x0 * x0 + y0 * y0 < 1.0) {
            ys = y0;
            pole_inside = true;
        }
    }
    int lower = strips_over(1.0 + ys, my), upper = strips_over(1.0 - ys, my);
    while (lower + upper > kMaxGridCells) (lower > upper ? lower : upper) -= 1;

    // Bisections next to ys: the new boundaries approach ys geometrically.
    int cut_lower = 0, cut_upper = 0;
    if (pole_inside) {
        double width = (1.0 + ys) / lower;
        while (width > 2.0 * tol && cut_lower < kMaxBisections) {
            width *= 0.5;
            ++cut_lower;
        }
        width = (1.0 - ys) / upper;
        while (width > 2.0 * tol && cut_upper < kMaxBisections) {
            width *= 0.5;
            ++cut_upper;
        }
        while (lower + upper + cut_lower + cut_upper > kMaxGridCells)
            (cut_lower > cut_upper ? cut_lower : cut_upper) -= 1;
    }

    Eigen::ArrayXd b(lower + upper + cut_lower + cut_upper + 1);
    Eigen::Index k = 0;
    for (int i = 0; i < lower; ++i) b[k++] = -1.0 + (1.0 + ys) * i / lower;
    // The last equal lower strip [ys - w, ys] becomes [ys - w, ys - w/2, ...].
    const double w_lower = (1.0 + ys) / lower;
    for (int c = 1; c <= cut_lower; ++c) b[k++] = ys - std::ldexp(w_lower, -c);
    b[k++] = ys;
    const double w_upper = (1.0 - ys) / upper;
    for (int c = cut_upper; c >= 1; --c) b[k++] = ys + std::ldexp(w_upper, -c);
    for (int i = 1; i <= upper; ++i) b[k++] = i == upper ? 1.0 : ys + (1.0 - ys) * i / upper;
    return b;
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
    // As in make_model_setup: huge creepages (full sliding) are scaled down
    // together so that |q|^2 in the march cannot overflow to Inf (which
    // gave zero traction) and ux - fx*y cannot become Inf - Inf.
    const double largest =
        std::fmax(std::fmax(std::fabs(ux), std::fabs(uy)), std::fmax(std::fabs(fx), std::fabs(fy)));
    if (largest > kMaxNormalisedCreepage) {
        const double scale = kMaxNormalisedCreepage / largest;
        ux *= scale;
        uy *= scale;
        fx *= scale;
        fy *= scale;
    }
    const ContactGrid grid(mx, strip_bounds(ux, uy, fx, fy, my, tol));
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
    // Unit-disk load integral pi/2; signs as Kalker's program printed them
    // (kalker_normalised.hpp): the march gives the wheel's traction.
    const double scale = 2.0 / 3.14159265358979323846;
    // + 0.0 turns a -0 (no force) into 0, as Kalker's program printed it.
    return {-scale * tx + 0.0, scale * ty + 0.0};
}

} // namespace creepwork
