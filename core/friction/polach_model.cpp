#include "friction/polach_model.hpp"

#include <cmath>

namespace creepwork {

PolachResult polach_forces(const PolachInput& in)
{
    constexpr double pi = 3.14159265358979323846;
    PolachResult r;
    const double s = std::hypot(in.xi_x, in.xi_y);
    r.mu = friction_value(in.law, s * in.V).mu;
    // Polach's reduced lateral creepage: the spin adds to xi_y only where
    // it enlarges it.
    const double with_spin = in.xi_y + in.phi * in.a;
    const double s_yc = std::fabs(with_spin) > std::fabs(in.xi_y) ? with_spin : in.xi_y;
    const double s_c = std::hypot(in.xi_x, s_yc);
    if (s_c == 0.0 || in.Q == 0.0 || r.mu == 0.0) return r;

    const double Qmu = in.Q * r.mu;
    double F = 0.0;
    if (s > 0.0) {
        const double c_jj = std::hypot(in.C11 * in.xi_x, in.C22 * in.xi_y) / s;
        r.epsilon = in.G * pi * in.a * in.b * c_jj * s_c / (4.0 * Qmu);
        const double eA = in.k_A * r.epsilon;
        F = 2.0 * Qmu / pi * (eA / (1.0 + eA * eA) + std::atan(in.k_S * r.epsilon));
    }
    double F_ys = 0.0; // Polach 1999's spin term, a length times mu
    if (in.phi != 0.0) {
        const double K_M = 1.0 + 6.3 * (1.0 - std::exp(-in.a / in.b));
        const double eM = 8.0 * in.b * std::sqrt(in.a * in.b) * in.G * in.C23 * std::fabs(s_yc) /
                          (3.0 * K_M * Qmu);
        const double d = (eM * eM - 1.0) / (eM * eM + 1.0);
        const double root = 1.0 - d * d;
        F_ys = 9.0 / 16.0 * in.a * r.mu * K_M *
               (eM * (-d * d * d / 3.0 + d * d / 2.0 - 1.0 / 6.0) + root * std::sqrt(root) / 3.0);
    }
    r.Fx = -F * in.xi_x / s_c;
    r.Fy = -(F * in.xi_y + in.Q * F_ys * in.phi) / s_c;
    return r;
}

} // namespace creepwork
