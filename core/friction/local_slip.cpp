#include "friction/local_slip.hpp"

#include <algorithm>
#include <cmath>

namespace creepwork {

LocalSlip local_slip(const SlipSpeedLaw& law, double P, double pn, double c, double mu_guess)
{
    LocalSlip r;
    double lo = 0.0, hi = std::min(P, pn * static_friction(law));
    double t = mu_guess >= 0.0 ? std::min(hi, pn * mu_guess) : hi;
    // Safeguarded Newton on g(t) = t - pn mu(c (P - t)), g(lo) <= 0 <= g(hi):
    // a step that leaves the bracket is replaced by bisection. It stops at
    // the t whose law value it holds once the next step would be below
    // 1e-14 of the bracket (so |g(t)| is that small), keeping t, s and mu
    // of one evaluation.
    FrictionValue v;
    double dg = 1.0;
    for (int it = 0;; ++it) {
        v = friction_value(law, c * (P - t));
        const double g = t - pn * v.mu;
        dg = 1.0 + pn * c * v.dmu_ds; // dg/dt
        r.iterations = it + 1;
        if (g == 0.0 || it == 200) break; // 200: bisection alone halves the bracket to rounding
        (g < 0.0 ? lo : hi) = t;
        double next = dg > 0.0 ? t - g / dg : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::fabs(next - t) <= 1e-14 * hi) break;
        t = next;
    }
    r.t = t;
    r.s = c * (P - t);
    r.mu = v.mu;
    r.dt_dP = dg != 0.0 ? pn * c * v.dmu_ds / dg : 0.0;
    r.dt_dpn = dg != 0.0 ? v.mu / dg : 0.0;
    r.dt_dc = dg != 0.0 ? pn * v.dmu_ds * (P - t) / dg : 0.0;
    return r;
}

} // namespace creepwork
