#include "contact/surface_plausibility.hpp"

#include <cmath>

namespace creepwork {

namespace {

// A steel property's plausible range, and the unit mistake each side of it
// suggests. Steels' values at 0-600 deg C lie well inside (lambda 25-60,
// c 420-750, rho 7700-7900); the limits leave room for other metals.
struct Property {
    CheckRule rule;
    const char* unit;
    double lo, hi;
    const char* below;
    const char* above;
};

const Property kConductivity = {
    CheckRule::conductivity, "W/(m K)", 1.0, 1000.0,
    "steel's conductivity is about 50 W/(m K) (W/(mm K) typed as W/(m K)?)",
    "steel's conductivity is about 50 W/(m K), no metal's exceeds 430 (mW/(m K) typed as "
    "W/(m K)?)"};
const Property kHeatCapacity = {
    CheckRule::heat_capacity, "J/kg/K", 100.0, 5000.0, // J/(kg K) overflows cw_check.unit
    "steel's heat capacity is about 450 J/kg/K (kJ/kg/K or J/g/K typed as J/kg/K?)",
    "steel's heat capacity is about 450 J/kg/K, no metal's exceeds 3600 (mJ/kg/K typed as "
    "J/kg/K?)"};
const Property kDensity = {
    CheckRule::density, "kg/m^3", 1000.0, 25000.0,
    "steel's density is about 7850 kg/m^3 (g/cm^3 or t/m^3 typed as kg/m^3?)",
    "steel's density is about 7850 kg/m^3, no element's exceeds 22600 (g/m^3 typed as kg/m^3?)"};

void check_property(const Property& p, const char* input, double v, std::vector<Implausible>& out)
{
    if (!std::isfinite(v)) return;
    if (v < p.lo) out.push_back({p.rule, input, v, p.unit, p.below});
    if (v > p.hi) out.push_back({p.rule, input, v, p.unit, p.above});
}

} // namespace

std::vector<Implausible> check_temperature(const TemperaturePlausibility& t)
{
    std::vector<Implausible> out;
    const char* const conductivity[] = {"conductivity_1", "conductivity_2"};
    const char* const heat_capacity[] = {"heat_capacity_1", "heat_capacity_2"};
    const char* const density[] = {"density_1", "density_2"};
    for (int body = 0; body < 2; ++body) {
        check_property(kConductivity, conductivity[body], t.conductivity[body], out);
        check_property(kHeatCapacity, heat_capacity[body], t.heat_capacity[body], out);
        check_property(kDensity, density[body], t.density[body], out);
    }
    if (t.rolling_speed > kSpeedLimit && std::isfinite(t.rolling_speed))
        out.push_back({CheckRule::speed, "rolling_speed", t.rolling_speed, "m/s", kSpeedReason});
    return out;
}

std::vector<Implausible> check_damage(const DamagePlausibility& d)
{
    std::vector<Implausible> out;
    // Steels' shear yield stresses are 2-6e8 Pa; one in MPa typed as Pa
    // is below 1e4 Pa, 1e6 leaves room for soft metals.
    if (d.k_yield > 0.0 && d.k_yield < 1e6)
        out.push_back({CheckRule::yield_stress, "k_yield", d.k_yield, "Pa",
                       "steel's shear yield stress is 2-6e8 Pa (MPa or N/mm^2 typed as Pa?)"});
    // Burstow's thresholds are 15-175 N (J/m); the same in kN (or J/mm)
    // typed as N fall below 1.
    const struct {
        const char* input;
        double v;
    } thresholds[] = {
        {"wlrm_onset", d.wlrm_onset}, {"wlrm_peak", d.wlrm_peak}, {"wlrm_zero", d.wlrm_zero}};
    for (const auto& w : thresholds)
        if (w.v > 0.0 && w.v < 1.0)
            out.push_back({CheckRule::wlrm_threshold, w.input, w.v, "N",
                           "the Whole Life Rail Model's thresholds of T_gamma are 15-175 N "
                           "(kN or J/mm typed as N?)"});
    return out;
}

} // namespace creepwork
