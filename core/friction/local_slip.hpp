// One slipping element of FASTSIM's march under a law of the slip speed,
// scalar: the step the march with friction memory calls in place of
// Coulomb's projection (without memory the march is a SIMD kernel with the
// same method, fastsim/march_law.hpp). The element's
// elastic predictor has traction magnitude P (the traction it would carry
// if it adhered); slipping, it keeps the predictor's direction and a
// magnitude t < P, and slides at the slip speed s = c (P - t) [m/s], where
// c = V L / h (rolling speed, flexibility, step) turns lost traction into
// slip speed (CONTACT m_solvpt.f90: h s = u - u' + h w). The law closes it:
//   t = p_n mu(c (P - t)).
// Coulomb's law gives t = p_n mu at once. The root is sought in
// [0, min(P, p_n mu(0))], where g(t) = t - p_n mu(c (P - t)) changes sign
// (g(0) <= 0, g(top) >= 0) once the element slips (P > p_n mu(0)); a law that
// falls faster than 1/(c p_n) may have several roots there (the multiple
// solutions of instantaneous laws that friction memory removes): the one
// found is the bracket's safeguarded Newton root, the same for the same
// inputs.
#pragma once

#include <algorithm>
#include <cmath>

#include "friction/friction_memory.hpp"
#include "friction/slip_speed_law.hpp"

namespace creepwork {

struct LocalSlip {
    double t = 0.0;     // traction magnitude [Pa]
    double s = 0.0;     // slip speed c (P - t) [m/s]
    double mu = 0.0;    // mu(s)
    int iterations = 0; // Newton steps taken
};

// P > p_n mu(0) >= 0 (the element slips), c > 0. Newton starts from
// t = p_n mu_guess (clamped into the bracket): a march passes the previous
// element's mu, so that one or two steps suffice; a negative mu_guess starts
// from the bracket's top. Law: a SlipSpeedLaw, or a MemoryElement (the
// law with friction memory); static_friction(law) bounds its mu from above.
template <class Law>
LocalSlip local_slip(const Law& law, double P, double pn, double c, double mu_guess = -1.0)
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
    double s = c * (P - t);
    for (int it = 0;; ++it) {
        v = friction_value(law, s);
        const double g = t - pn * v.mu;
        const double dg = 1.0 + pn * c * v.dmu_ds; // dg/dt
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
    return r;
}

} // namespace creepwork
