#include "calibration_limit.hpp"

#include <cmath>

namespace cwcal {

ContinuumLimit continuum_limit(const double h[3], const double q[3], double scale)
{
    ContinuumLimit L;
    L.value = q[2];
    const double d1 = q[1] - q[0], d2 = q[2] - q[1];
    if (std::fabs(d1) + std::fabs(d2) <= 1e-10 * scale) {
        L.resolved = true;
        return L;
    }
    if (!(d1 * d2 > 0.0) || !(std::fabs(d2) < std::fabs(d1))) return L;
    const double ratio = d2 / d1;
    // (h1^p - h2^p)/(h0^p - h1^p) falls as p grows: bisection on [0.5, 4].
    const auto model_ratio = [&](double p) {
        return (std::pow(h[1], p) - std::pow(h[2], p)) / (std::pow(h[0], p) - std::pow(h[1], p));
    };
    double lo = 0.5, hi = 4.0;
    if (ratio > model_ratio(lo) || ratio < model_ratio(hi)) return L;
    for (int it = 0; it < 100; ++it) {
        const double mid = 0.5 * (lo + hi);
        (model_ratio(mid) > ratio ? lo : hi) = mid;
    }
    L.order = 0.5 * (lo + hi);
    L.value = q[2] + d2 * std::pow(h[2], L.order) /
                         (std::pow(h[1], L.order) - std::pow(h[2], L.order));
    L.richardson = true;
    return L;
}

} // namespace cwcal
