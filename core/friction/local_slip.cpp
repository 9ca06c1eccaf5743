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
    // a step that leaves the bracket is replaced by bisection. Once a step
    // is below 1e-8 of the bracket the root is within rounding of t + step
    // (Newton's error squares), so it takes that step without another
    // evaluation of the law and moves s and mu with it to first order.
    FrictionValue v;
    double dg = 1.0;
    double s = c * (P - t);
    for (int it = 0;; ++it) {
        v = friction_value(law, s);
        const double g = t - pn * v.mu;
        dg = 1.0 + pn * c * v.dmu_ds; // dg/dt
        r.iterations = it + 1;
        if (g == 0.0 || it == 200) break; // 200: bisection alone halves the bracket to rounding
        (g < 0.0 ? lo : hi) = t;
        double next = dg > 0.0 ? t - g / dg : 0.5 * (lo + hi);
        const bool inside = next > lo && next < hi;
        if (!inside) next = 0.5 * (lo + hi);
        if (inside && std::fabs(next - t) <= 1e-8 * hi) {
            const double s_next = c * (P - next);
            v.mu += v.dmu_ds * (s_next - s);
            t = next;
            s = s_next;
            break;
        }
        t = next;
        s = c * (P - t);
    }
    r.t = t;
    r.s = s;
    r.mu = v.mu;
    r.dt_dP = dg != 0.0 ? pn * c * v.dmu_ds / dg : 0.0;
    r.dt_dpn = dg != 0.0 ? v.mu / dg : 0.0;
    r.dt_dc = dg != 0.0 ? pn * v.dmu_ds * (P - t) / dg : 0.0;
    return r;
}

} // namespace creepwork
