#include "contact/flexibility_blending.hpp"

#include <algorithm>
#include <cmath>

#include "contact/fp_safe.hpp"

namespace creepwork {
namespace {

constexpr double kPi = 3.14159265358979323846;

// v / scale, with magnitudes below 1e-100 read as 0: their squares are below
// the rounding of a sum that holds a 1, and they would underflow.
double scaled(double v, double scale)
{
    const double r = v / scale;
    return std::fabs(r) < 1e-100 ? 0.0 : r;
}

} // namespace

Flexibilities blend_flexibilities(const Flexibilities& L, double a, double b, double mu,
                                  double normal_force, double xi, double eta, double phi)
{
    // CONTACT: f3 = 8a/3, f4 = pi a^2/4, t = phi f4/f3.
    const double t = phi * (3.0 * kPi * a / 32.0);
    const double largest = std::max({std::fabs(xi), std::fabs(eta), std::fabs(t)});

    // L_crss, the creepage-weighted harmonic mean of L1, L2, L3 (0 at zero
    // creepage, as in CONTACT).
    double L_crss = 0.0;
    if (largest > 0.0) {
        const double rx = scaled(xi, largest), ry = scaled(eta, largest), rt = scaled(t, largest);
        const double numer = rx * rx + ry * ry + rt * rt; // in [1, 3]
        const double denom = rx * rx / L.L1 + ry * ry / L.L2 + rt * rt / L.L3;
        L_crss = quotient_if_positive(numer, denom);
    }

    // Weight: the creepage over its characteristic (saturation) value.
    const double ch_scale = 3.0 * mu * normal_force / (8.0 * a * a * b);
    const double ch = std::hypot(ch_scale * L.L1, ch_scale * L.L2);
    const double creepage = std::hypot(xi, eta);
    double f_crp = 1e-10;
    if (creepage > 0.0) f_crp = ch > 0.0 ? std::max(f_crp, quotient_if_positive(creepage, ch)) : 3.0;
    const double w = std::min(1.0, f_crp / 3.0);

    // Zero creepage: CONTACT's L_crss is 0, so its L's are Kalker's times
    // (1 - 3.3e-11). Extreme inputs whose combined flexibility is not a
    // positive number keep the L's as they are.
    if (largest == 0.0) return {(1.0 - w) * L.L1, (1.0 - w) * L.L2, (1.0 - w) * L.L3};
    if (!(L_crss > 0.0) || !std::isfinite(L_crss)) return L;
    return {(1.0 - w) * L.L1 + w * L_crss, (1.0 - w) * L.L2 + w * L_crss,
            (1.0 - w) * L.L3 + w * L_crss};
}

void blend_flexibilities_derivatives(const Flexibilities& L, double a, double b, double mu,
                                     double normal_force, double xi, double eta, double phi,
                                     double d[3][4])
{
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 4; ++k) d[i][k] = 0.0;
    const double dt_dphi = 3.0 * kPi * a / 32.0;
    const double t = phi * dt_dphi;
    const double largest = std::max({std::fabs(xi), std::fabs(eta), std::fabs(t)});
    if (largest == 0.0) return;

    // L_crss = S / D in scaled variables r = v / largest (the scale cancels):
    // dL_crss/dv = 2 r (1 - L_crss/L_v) / (D largest).
    const double rx = scaled(xi, largest), ry = scaled(eta, largest), rt = scaled(t, largest);
    const double numer = rx * rx + ry * ry + rt * rt;
    const double denom = rx * rx / L.L1 + ry * ry / L.L2 + rt * rt / L.L3;
    const double L_crss = quotient_if_positive(numer, denom);
    if (!(L_crss > 0.0) || !std::isfinite(L_crss)) return; // L's returned unblended
    const double per = 2.0 / (denom * largest);
    double dLc[4] = {per * rx * (1.0 - L_crss / L.L1), per * ry * (1.0 - L_crss / L.L2),
                     per * rt * (1.0 - L_crss / L.L3) * dt_dphi, 0.0};

    // w = min(1, f/3), f = max(1e-10, creepage/ch), ch proportional to N.
    const double ch_scale = 3.0 * mu * normal_force / (8.0 * a * a * b);
    const double ch = std::hypot(ch_scale * L.L1, ch_scale * L.L2);
    const double creepage = std::hypot(xi, eta);
    double f_crp = 1e-10;
    double df[4] = {0, 0, 0, 0};
    if (creepage > 0.0) {
        if (ch > 0.0) {
            const double ratio = quotient_if_positive(creepage, ch);
            if (ratio > f_crp) {
                f_crp = ratio;
                df[0] = xi / (creepage * ch);
                df[1] = eta / (creepage * ch);
                df[3] = quotient_if_positive(-ratio, normal_force);
            }
        } else {
            f_crp = 3.0;
        }
    }
    const double w = std::min(1.0, f_crp / 3.0);
    const bool w_varies = f_crp / 3.0 < 1.0; // std::min takes f/3 only when it is smaller
    const double Lv[3] = {L.L1, L.L2, L.L3};
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 4; ++k) {
            const double dw = w_varies ? df[k] / 3.0 : 0.0;
            d[i][k] = dw * (L_crss - Lv[i]) + w * dLc[k];
        }
}

} // namespace creepwork
