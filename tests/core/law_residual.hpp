// How well the elements of a solve under a law of the slip speed meet it:
// over the slipping elements of a solver's last full solve, the worst
// | |p| - p_z mu(V |s|) | / (p_z mu_s) at each element's exported traction p,
// pressure p_z and micro-slip s, mu from CONTACT's formula
// (contact_friction_formula.hpp, libm's exp). Shared by the tests of
// FASTSIM with the law at every element.
#pragma once

#include "contact_friction_formula.hpp"
#include "core_test_support.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace cwtest {

// in: the input of the solver's last solve (full mode), a falling law;
// checked: incremented by the slipping elements seen.
inline double worst_law_residual(const creepwork::Solver& s, const creepwork::ContactInput& in,
                                 long& checked)
{
    // An absent second term's half speed is not read: 1 m/s keeps the formula finite.
    const double sh2 = in.mu_e2 > 0.0 ? in.s_h2 : 1.0;
    const double mu_s = in.mu + in.mu_e1 + in.mu_e2;
    const std::vector<double> px = field(s, creepwork::Field::px), py = field(s, creepwork::Field::py),
                              pz = field(s, creepwork::Field::pz), sx = field(s, creepwork::Field::sx),
                              sy = field(s, creepwork::Field::sy);
    const std::vector<int> state = states(s);
    double worst = 0.0;
    for (size_t k = 0; k < state.size(); ++k) {
        if (state[k] != 2) continue;
        const double speed = in.V * std::hypot(sx[k], sy[k]); // [m/s]
        const double mu = contact_mu_steady(int(in.friction_law), in.mu, in.mu_e1, 1e3 * in.s_h1,
                                            in.mu_e2, 1e3 * sh2, 1e3 * speed);
        worst = std::max(worst, std::fabs(std::hypot(px[k], py[k]) - pz[k] * mu) / (pz[k] * mu_s));
        ++checked;
    }
    return worst;
}

} // namespace cwtest
