#include "damage/damage_indices.hpp"

#include <algorithm>
#include <cmath>

#include "contact/contact_input.hpp"
#include "contact/fp_safe.hpp"

namespace creepwork::damage {

void validate(const DamageParams& p)
{
    require_positive("k_yield", p.k_yield);
    if (!(p.k_yield <= 1e12)) reject_input("k_yield", p.k_yield, "must be <= 1e12 Pa");
    validate(p.wlrm);
}

double rcf_index(double px, double py, double pz, bool contact, double k_yield)
{
    if (!contact) return kRcfNoRisk;
    // A plain root: the solver's tractions are far from the squares' overflow
    // (glibc's hypot would cost more than the rest of the element).
    const double pt = std::sqrt(px * px + py * py);
    const double r = quotient_if_positive(pt - k_yield, pz); // fp_safe.hpp
    return pz > 0.0 ? std::max(kRcfNoRisk, r) : kRcfNoRisk;
}

DamageTotals damage_indices(const DamageInput& in, const DamageParams& p,
                            const DamageFields& out)
{
    validate(p);
    DamageTotals t;
    const long n = static_cast<long>(in.nx) * in.ny;
    for (long e = 0; e < n; ++e) {
        const bool contact = in.state[e] >= 1;
        const double r = rcf_index(in.px[e], in.py[e], in.pz[e], contact, p.k_yield);
        if (out.rcf_index) out.rcf_index[e] = r;
        if (contact && (t.rcf_element < 0 || r > t.rcf_index_max)) {
            t.rcf_index_max = r;
            t.rcf_element = e;
        }
        if (out.t_gamma_density)
            out.t_gamma_density[e] = quotient_if_positive(std::max(0.0, in.work[e]), in.area[e]);
    }
    if (in.normal_force > 0.0 && in.contact_area > 0.0) {
        // fp_safe.hpp: divisions the compiler cannot hoist above the test
        t.mu_eff = quotient_if_positive(std::hypot(in.Fx, in.Fy), in.normal_force);
        t.FI_surf = t.mu_eff - 2.0 * in.contact_area * p.k_yield / (3.0 * in.normal_force);
    }
    t.T_gamma = in.W_macro;
    t.wlrm_damage = wlrm_damage(t.T_gamma, p.wlrm);
    return t;
}

} // namespace creepwork::damage
