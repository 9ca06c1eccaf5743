// Plausibility of the surface post-processors' inputs (cw_temperature_params_check,
// cw_damage_params_check): thermal properties far from any steel's, a
// rolling speed in km/h, a yield stress in MPa, WLRM thresholds in kN --
// each with its likely unit mistake, in the rule table's message style
// (contact/plausibility.hpp). Nothing here warns by itself.
#pragma once

#include <vector>

#include "contact/plausibility.hpp"

namespace creepwork {

// The numbers of cw_temperature_params the rules read (SI); index 0 is body
// 1 (the rail), 1 body 2 (the wheel).
struct TemperaturePlausibility {
    double conductivity[2] = {0, 0};
    double heat_capacity[2] = {0, 0};
    double density[2] = {0, 0};
    double rolling_speed = 0;
};

// The numbers of cw_damage_params the rules read (SI).
struct DamagePlausibility {
    double k_yield = 0;
    double wlrm_onset = 0, wlrm_peak = 0, wlrm_zero = 0;
};

// The rules each set of parameters breaks, in a fixed order (one entry per
// rule and input). NaN breaks no rule: the compute refuses it.
std::vector<Implausible> check_temperature(const TemperaturePlausibility& t);
std::vector<Implausible> check_damage(const DamagePlausibility& d);

} // namespace creepwork
