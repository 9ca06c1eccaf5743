#include "normal/gap_grid.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "contact/contact_input.hpp"
#include "contact/error.hpp"
#include "contact/number_text.hpp"
#include "halfspace/grid_convolution.hpp"
#include "normal/gap_normal.hpp"
#include "simd/simd.hpp"

namespace creepwork {
namespace {

// Whether every one of n values lies within [-1, 1] (false for NaN and
// infinities too), by a branch-free pass: a select per value, so that the
// loop vectorises. A kernel of simd/kernel_isa.hpp (W unused: the compiler
// vectorises the loop for the copy's ISA); a yes or no, the same in every
// copy.
struct AllWithinOne : KernelWidths {
    template <int W>
    CREEPWORK_INLINE static void run(const double* const& v, const size_t& n, bool* const& yes)
    {
        double bad = 0.0;
        for (size_t k = 0; k < n; ++k) bad = std::fabs(v[k]) <= 1.0 ? bad : 1.0;
        *yes = bad == 0.0;
    }
};

} // namespace

const GridSpec& checked_gap_grid(const GridSpec& g)
{
    if (g.kind != GridKind::gap)
        throw Error(ErrorKind::invalid_input, "the gap model needs a gap grid");
    for (const auto& [name, v] : {std::pair<const char*, int>{"nx", g.nx}, {"ny", g.ny}})
        if (v < kMinGapCells || v > kMaxExactCells)
            throw Error(ErrorKind::grid_out_of_range,
                        std::string(name) + " = " + std::to_string(v) + " is outside " +
                            std::to_string(kMinGapCells) + " ... " +
                            std::to_string(kMaxExactCells) + " for a gap grid");
    for (const auto& [name, v] : {std::pair<const char*, double>{"x0", g.x0}, {"y0", g.y0}})
        if (!std::isfinite(v) || std::fabs(v) > 1e6)
            throw Error(ErrorKind::invalid_input,
                        std::string(name) + " = " + number_text(v) +
                            " is invalid: the gap grid's origin must be finite, within 1e6");
    for (const auto& [name, v] : {std::pair<const char*, double>{"dx", g.dx}, {"dy", g.dy}})
        if (!(v > 0.0 && v <= 1e3))
            throw Error(ErrorKind::invalid_input,
                        std::string(name) + " = " + number_text(v) +
                            " is invalid: the gap grid's spacing must be > 0 (and <= 1e3)");
    const double ratio = g.dy / g.dx;
    if (!(ratio >= 0.05 && ratio <= 20.0))
        throw Error(ErrorKind::invalid_input,
                    "dy/dx = " + number_text(ratio) +
                        " is invalid: the gap grid's cells must have dy/dx in [0.05, 20]");
    return g;
}

void copy_gap_rows(const GridSpec& grid, double* y, double* width)
{
    for (int j = 0; j < grid.ny; ++j) {
        y[j] = grid.y0 + j * grid.dy;
        width[j] = grid.dy;
    }
}

void gap_centres(const GridSpec& grid, std::vector<double>& x, std::vector<double>& y)
{
    x.resize(grid.nx);
    y.resize(grid.ny);
    for (int i = 0; i < grid.nx; ++i) x[i] = grid.x0 + i * grid.dx;
    for (int j = 0; j < grid.ny; ++j) y[j] = grid.y0 + j * grid.dy;
}

void validate_gap_input(const ContactInput& in, size_t n, KernelIsa isa)
{
    if (!in.gap)
        throw Error(ErrorKind::invalid_input, "gap is NULL: a gap grid needs the undeformed "
                                              "distance of every element");
    if (in.gap_len < n)
        throw Error(ErrorKind::invalid_input,
                    "gap_len = " + std::to_string(in.gap_len) + " is invalid: the gap grid has " +
                        std::to_string(n) + " elements");
    // The values by one branch-free pass; when one is bad, the first is named.
    bool within = false;
    run_kernel<AllWithinOne>(isa, in.gap, n, &within);
    for (size_t k = 0; !within && k < n; ++k)
        if (!std::isfinite(in.gap[k]) || std::fabs(in.gap[k]) > 1.0)
            throw Error(ErrorKind::invalid_input,
                        "gap[" + std::to_string(k) + "] = " + number_text(in.gap[k]) +
                            " is invalid: the undeformed distance must be finite, within 1 m");
    if (in.normal_load == NormalLoad::force)
        require_non_negative("normal_force", in.normal_force);
    else if (in.normal_load == NormalLoad::approach) {
        require_finite("approach", in.approach);
        if (std::fabs(in.approach) > 1.0)
            reject_input("approach", in.approach, "must lie within 1 m of the gap's datum");
    } else
        reject_input("normal_load", static_cast<double>(in.normal_load), "unknown normal load");
    if (!normal_method_known(in.normal_method))
        reject_input("normal_method", static_cast<double>(in.normal_method),
                     "unknown normal method");
    validate_friction_input(in);
    require_positive("G", in.G);
    require_finite("nu", in.nu);
    if (!(in.nu >= 0.0 && in.nu <= 0.5)) reject_input("nu", in.nu, "must lie in [0, 0.5]");
    require_finite("xi_x", in.xi_x);
    require_finite("xi_y", in.xi_y);
    require_finite("phi", in.phi);
    if (in.rolling_direction != 1 && in.rolling_direction != -1)
        reject_input("rolling_direction", in.rolling_direction, "must be +1 or -1");
    require_finite("spin_offset", in.spin_offset);
    if (in.spin_offset > 1.0)
        reject_input("spin_offset", in.spin_offset,
                     "must lie in [0, 1] (a fraction of the element length), or be negative "
                     "for the model's default");
}

} // namespace creepwork
