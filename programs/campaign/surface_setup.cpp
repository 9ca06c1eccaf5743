#include "surface_setup.hpp"

#include <cmath>

#include "../cli/options.hpp"
#include "wire.hpp"

namespace cwcampaign {

cw_temperature_params row_temperature_params(const SurfaceSetup& setup, const ContactCase& row)
{
    cw_temperature_params p = setup.temperature_params;
    p.rolling_direction = 0; // the solve's
    p.rolling_speed = row.params.V > 0.0 ? 0.0 // the solve's V
                      : row.wear.speed > 0.0 ? row.wear.speed
                                             : setup.speed;
    return p;
}

std::string surface_row_problem(const SurfaceSetup& setup, const ContactCase& row, long line)
{
    if (!setup.temperature || !row.rejected.empty()) return "";
    const std::string where = "line " + std::to_string(line) + ", column V: ";
    const double V = row.params.V;
    if (V > 0.0 && setup.speed > 0.0 && std::fabs(setup.speed - V) > 1e-9 * V)
        return where + cwcli::round_trip_text(V) + " m/s differs from --speed " +
               cwcli::round_trip_text(setup.speed) +
               " m/s: give the rolling speed once, or the same in both";
    if (!(V > 0.0) && !(row.wear.speed > 0.0) && !(setup.speed > 0.0))
        return where + "empty: --temperature needs the rolling speed (a V column, or --speed)";
    return "";
}

uint64_t surface_identity(const SurfaceSetup& setup, uint64_t seed)
{
    // Field by field: the structs' padding is not part of their value.
    const cw_temperature_params& t = setup.temperature_params;
    const cw_damage_params& d = setup.damage_params;
    const double reals[] = {t.T0_1,           t.heat_capacity_1, t.conductivity_1, t.density_1,
                            t.T0_2,           t.heat_capacity_2, t.conductivity_2, t.density_2,
                            setup.speed,      d.k_yield,         d.wlrm_onset,     d.wlrm_peak,
                            d.wlrm_zero,      d.wlrm_peak_damage};
    const int32_t ints[] = {2, setup.temperature, setup.damage, t.discretisation,
                            static_cast<int32_t>(setup.mu_T_temperature.size())};
    uint64_t h = fnv1a(ints, sizeof ints, seed);
    h = fnv1a(reals, sizeof reals, h);
    h = fnv1a(setup.mu_T_temperature.data(), setup.mu_T_temperature.size() * sizeof(double), h);
    return fnv1a(setup.mu_T_mu.data(), setup.mu_T_mu.size() * sizeof(double), h);
}

} // namespace cwcampaign
