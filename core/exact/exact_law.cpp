#include "exact/exact_law.hpp"

#include <algorithm>
#include <cmath>

#include "contact/contact_input.hpp"
#include "contact/friction_law.hpp"

namespace creepwork {

bool ExactLaw::set(const SlipSpeedLaw& law, double V)
{
    check_slip_speed_law(law);
    if (!(std::isfinite(V) && V > 0.0))
        reject_input("V", V,
                     "must be finite and > 0 [m/s] (the rolling speed) for a law of the slip speed");
    const bool same = active_ && law.kind == law_.kind && law.mu_kin == law_.mu_kin &&
                      law.mu_e1 == law_.mu_e1 && law.s_h1 == law_.s_h1 &&
                      law.mu_e2 == law_.mu_e2 && law.s_h2 == law_.s_h2 && V == V_;
    law_ = law;
    V_ = V;
    active_ = true;
    return !same;
}

double ExactLaw::coefficient(const ContactInput& in) const
{
    return active_ ? law_.coefficient(0.0) : in.mu;
}

double ExactLaw::traction_scale(const ContactInput& in, double pressure) const
{
    return active_ ? traction_bound(law_, pressure, 0.0) : traction_bound(friction_law(in), pressure);
}

void ExactLaw::set_local_memory(LocalLaw& local, double dx) const
{
    local.memory = memory_;
    local.dt = dx / V_;
    local.mu_prev = static_friction(law_);
}

void ExactLaw::range(const SteadyRolling& fine, TangentialInfo& info) const
{
    const double mu0 = law_.coefficient(0.0);
    info.mu_min = info.mu_max = mu0;
    const std::vector<signed char>& state = fine.state();
    const std::vector<ElementSlip>& slip = fine.element_slip();
    if (slip.size() != state.size()) return;
    long slipping = 0, steps = 0;
    for (size_t k = 0; k < state.size(); ++k) {
        if (state[k] != 2) continue;
        const double mu = mu0 * slip[k].m;
        info.mu_min = slipping ? std::min(info.mu_min, mu) : mu;
        info.mu_max = slipping ? std::max(info.mu_max, mu) : mu;
        ++slipping;
        steps += slip[k].iterations;
    }
    info.friction_steps_per_element = slipping ? double(steps) / double(slipping) : 0.0;
}

} // namespace creepwork
