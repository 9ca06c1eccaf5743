// cw_temperature_params_check, cw_damage_params_check: the surface
// post-processors' implausible inputs (core/contact/surface_plausibility.hpp)
// as cw_check entries.
#include "capi_check.hpp"
#include "contact/surface_plausibility.hpp"

namespace {

// The findings w as cw_check entries into out (capi_check.hpp's rules).
void write_findings(const std::vector<cw::Implausible>& w, cw_check* out, size_t len,
                    size_t* found)
{
    std::vector<cw_check> checks(w.size());
    for (size_t k = 0; k < w.size(); ++k) creepwork::capi::fill_check(w[k], 1, 0, "", checks[k]);
    creepwork::capi::write_checks(checks, out, len, found);
}

} // namespace

extern "C" {

int cw_temperature_params_check(const cw_temperature_params* params, cw_check* out, size_t len,
                                size_t* found)
{
    std::string ignored;
    return guarded(&ignored, [&] {
        require(params, "params");
        require(found, "found");
        cw_temperature_params defaults;
        cw_temperature_params_init(&defaults);
        const cw_temperature_params p = read_struct(params, defaults, "params");
        cw::TemperaturePlausibility t;
        t.conductivity[0] = p.conductivity_1;
        t.conductivity[1] = p.conductivity_2;
        t.heat_capacity[0] = p.heat_capacity_1;
        t.heat_capacity[1] = p.heat_capacity_2;
        t.density[0] = p.density_1;
        t.density[1] = p.density_2;
        t.rolling_speed = p.rolling_speed;
        write_findings(cw::check_temperature(t), out, len, found);
        return CW_OK;
    });
}

int cw_damage_params_check(const cw_damage_params* params, cw_check* out, size_t len,
                           size_t* found)
{
    std::string ignored;
    return guarded(&ignored, [&] {
        require(params, "params");
        require(found, "found");
        cw_damage_params defaults;
        cw_damage_params_init(&defaults);
        const cw_damage_params p = read_struct(params, defaults, "params");
        cw::DamagePlausibility d;
        d.k_yield = p.k_yield;
        d.wlrm_onset = p.wlrm_onset;
        d.wlrm_peak = p.wlrm_peak;
        d.wlrm_zero = p.wlrm_zero;
        write_findings(cw::check_damage(d), out, len, found);
        return CW_OK;
    });
}

} // extern "C"
