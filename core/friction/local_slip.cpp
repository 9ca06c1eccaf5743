#include "friction/local_slip.hpp"

#include <algorithm>
#include <cmath>

namespace creepwork {

LocalSlip local_slip(const FrictionLaw& law, double P, double pn, double c)
{
    LocalSlip r;
    double lo = 0.0, hi = std::min(P, pn * static_friction(law));
    double t = hi;
    // Safeguarded Newton on g(t) = t - pn mu(c (P - t)), g(lo) <= 0 <= g(hi):
    // a step that leaves the bracket is replaced by bisection.
    for (int it = 0; it < 100; ++it) {
        const FrictionValue v = friction_value(law, c * (P - t));
        const double g = t - pn * v.mu;
        const double dg = 1.0 + pn * c * v.dmu_ds; // dg/dt
        if (g == 0.0) break;
        (g < 0.0 ? lo : hi) = t;
        double next = dg > 0.0 ? t - g / dg : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        r.iterations = it + 1;
        const bool done = std::fabs(next - t) <= 1e-15 * std::max(hi, 1e-300);
        t = next;
        if (done) break;
    }
    const FrictionValue v = friction_value(law, c * (P - t));
    r.t = t;
    r.s = c * (P - t);
    r.mu = v.mu;
    const double dg = 1.0 + pn * c * v.dmu_ds;
    r.dt_dP = dg != 0.0 ? pn * c * v.dmu_ds / dg : 0.0;
    r.dt_dpn = dg != 0.0 ? v.mu / dg : 0.0;
    return r;
}

} // namespace creepwork
