// The training and evaluation sets of the calibrated model (doc/theory/calibrated.md):
// contacts spanning a/b 0.2-5, nu 0-0.5, creepages from
// 1 % to 300 % of saturation, each creepage alone and combined, both signs.
// Both sets are drawn by a fixed pseudo-random generator with different
// seeds and different stratifications, so they share no case (checked when
// they are made).
#pragma once

#include <string>
#include <vector>

#include "contact/params.hpp"

namespace cwcal {

enum class CaseSet { training, evaluation };

struct CalibrationCase {
    std::string id;
    double a_over_b = 1, nu = 0.28;
    double level = 0.1;       // creepage as a fraction of saturation (1e-2 .. 3)
    int combo = 0;            // which creepages: bit 0 xi_x, bit 1 xi_y, bit 2 phi
    creepwork::ContactInput input; // model and pressure set by the caller
};

std::vector<CalibrationCase> make_cases(CaseSet set);
const char* set_name(CaseSet set);

} // namespace cwcal
