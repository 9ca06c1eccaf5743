#include "wear_setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "../cli/cli_error.hpp"
#include "wire.hpp"

namespace cwcampaign {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

cw_wear_params row_wear_params(const WearSetup& setup, const RowWear& row)
{
    cw_wear_params p = setup.params;
    if (row.speed > 0.0) p.rolling_speed = row.speed;
    p.pass_length = row.body == kWheel && setup.wheel_radius > 0.0
                        ? 2.0 * kPi * setup.wheel_radius
                        : 1.0;
    return p;
}

std::vector<double> profile_nodes(const WearSetup& setup, const std::vector<ContactCase>& rows)
{
    double lo = 1e300, hi = -1e300, step = 1e300;
    for (const ContactCase& c : rows) {
        if (!c.rejected.empty()) continue;
        const double box = c.grid.kind == CW_GRID_UNIFORM ? c.grid.box_scale : 1.0;
        const double b = c.params.b * box;
        lo = std::min(lo, c.wear.s0 - b);
        hi = std::max(hi, c.wear.s0 + b);
        if (c.grid.ny > 0) step = std::min(step, 0.25 * 2.0 * b / c.grid.ny);
    }
    if (!(hi > lo)) { // no readable row: any small grid will do
        lo = -0.01;
        hi = 0.01;
        step = 1e-4;
    }
    const double margin = 0.2 * (hi - lo);
    lo -= margin;
    hi += margin;
    step = std::max(step, (hi - lo) / 20000.0);
    if (!std::isnan(setup.profile_from)) lo = setup.profile_from;
    if (!std::isnan(setup.profile_to)) hi = setup.profile_to;
    if (!std::isnan(setup.profile_step)) step = setup.profile_step;
    if (!(step > 0)) throw cwcli::usage_error("--profile-step", "must be > 0 (metres)");
    if (!(hi > lo))
        throw cwcli::usage_error("--profile-to", "must be greater than --profile-from");
    const double n = std::floor((hi - lo) / step + 1e-9) + 1;
    if (n < 2)
        throw cwcli::usage_error("--profile-step", "leaves fewer than 2 nodes between "
                                                   "--profile-from and --profile-to");
    if (n > 1e6) throw cwcli::usage_error("--profile-step", "gives more than 1e6 nodes");
    std::vector<double> nodes(static_cast<size_t>(n));
    for (size_t k = 0; k < nodes.size(); ++k) nodes[k] = lo + step * static_cast<double>(k);
    return nodes;
}

std::string nodes_to_bytes(const std::vector<double>& nodes)
{
    std::string bytes(nodes.size() * sizeof(double), '\0');
    if (!nodes.empty()) std::memcpy(bytes.data(), nodes.data(), bytes.size());
    return bytes;
}

std::vector<double> nodes_from_bytes(const std::string& bytes)
{
    std::vector<double> nodes(bytes.size() / sizeof(double));
    if (!nodes.empty()) std::memcpy(nodes.data(), bytes.data(), nodes.size() * sizeof(double));
    return nodes;
}

uint64_t wear_identity(const WearSetup& setup, uint64_t seed)
{
    // Field by field: the struct's padding is not part of its value.
    const cw_wear_params& p = setup.params;
    const double reals[] = {p.density,  p.rolling_speed, p.usfd_k1,      p.usfd_t1,
                            p.usfd_k2,  p.usfd_t2,       p.usfd_k3,      p.usfd_c3,
                            p.hardness, p.kth_v1,        p.kth_v2,       p.kth_seizure_ratio,
                            p.kth_k_seizure, p.kth_k_slow, p.kth_k_severe, p.kth_k_fast,
                            setup.wheel_radius};
    const int32_t ints[] = {1, p.law, p.source, setup.orientation, setup.default_body};
    uint64_t h = fnv1a(ints, sizeof ints, seed);
    h = fnv1a(reals, sizeof reals, h);
    return fnv1a(setup.nodes.data(), setup.nodes.size() * sizeof(double), h);
}

} // namespace cwcampaign
