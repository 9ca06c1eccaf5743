#include "damage/damage_indices.hpp"

#include <algorithm>
#include <cmath>

#include "contact/contact_input.hpp"
#include "contact/fp_safe.hpp"
#include "simd/simd.hpp"

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

namespace {

typedef simd::Vec<2> Pair; // the type of contact/fp_safe.hpp's DoublePair

// rcf_index() and the T_gamma density of elements e and e + 1, two lanes at
// a time and without a branch: the same operations, so the same bits.
inline void pair_indices(const DamageInput& in, long e, double k_yield, double* rcf,
                         double* density)
{
    const Pair px = simd::load<2>(in.px + e), py = simd::load<2>(in.py + e),
               pz = simd::load<2>(in.pz + e);
    const Pair pt = simd::sqrt<2>(px * px + py * py);
    const Pair none = Pair{} + kRcfNoRisk, zero = Pair{};
    const auto loaded = pz > zero;
    const Pair q = quotient_if_positive(pt - k_yield, pz);
    const Pair contact = {in.state[e] >= 1 ? 1.0 : 0.0, in.state[e + 1] >= 1 ? 1.0 : 0.0};
    const Pair r = loaded ? (none < q ? q : none) : none;
    simd::store<2>(rcf, contact > zero ? r : none);
    const Pair work = simd::load<2>(in.work + e);
    simd::store<2>(density,
                   quotient_if_positive(zero < work ? work : zero, simd::load<2>(in.area + e)));
}

// The first contact element holding the largest RCF index; -1 without contact.
// Outside the contact the index is -0.5, the floor of every contact element's,
// so a maximum above it can only be a contact element's.
long rcf_maximum(const double* rcf, const int* state, long n)
{
    double m[4] = {kRcfNoRisk, kRcfNoRisk, kRcfNoRisk, kRcfNoRisk};
    long e = 0;
    for (; e + 4 <= n; e += 4)
        for (int k = 0; k < 4; ++k) m[k] = rcf[e + k] > m[k] ? rcf[e + k] : m[k];
    for (; e < n; ++e) m[0] = rcf[e] > m[0] ? rcf[e] : m[0];
    const double top = std::max(std::max(m[0], m[1]), std::max(m[2], m[3]));
    for (e = 0; e < n; ++e)
        if (state[e] >= 1 && rcf[e] == top) return e;
    return -1;
}

} // namespace

DamageTotals damage_indices(const DamageInput& in, const DamageParams& p,
                            const DamageFields& out)
{
    validate(p);
    DamageTotals t;
    const long n = static_cast<long>(in.nx) * in.ny;
    // Blocks of elements into the caller's fields, or into scratch when a
    // field is not asked for.
    constexpr long kBlock = 256;
    double rcf_scratch[kBlock], density_scratch[kBlock];
    for (long e0 = 0; e0 < n; e0 += kBlock) {
        const long m = std::min(kBlock, n - e0);
        double* rcf = out.rcf_index ? out.rcf_index + e0 : rcf_scratch;
        double* density = out.t_gamma_density ? out.t_gamma_density + e0 : density_scratch;
        long i = 0;
        for (; i + 2 <= m; i += 2) pair_indices(in, e0 + i, p.k_yield, rcf + i, density + i);
        for (; i < m; ++i) {
            const long e = e0 + i;
            rcf[i] = rcf_index(in.px[e], in.py[e], in.pz[e], in.state[e] >= 1, p.k_yield);
            density[i] = quotient_if_positive(std::max(0.0, in.work[e]), in.area[e]);
        }
        const long at = rcf_maximum(rcf, in.state + e0, m);
        if (at >= 0 && (t.rcf_element < 0 || rcf[at] > t.rcf_index_max)) {
            t.rcf_index_max = rcf[at];
            t.rcf_element = e0 + at;
        }
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
