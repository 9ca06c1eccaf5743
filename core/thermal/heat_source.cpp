#include "thermal/heat_source.hpp"

#include <algorithm>
#include <cmath>

#include "contact/fp_safe.hpp"
#include "simd/simd.hpp"

namespace creepwork::thermal {

void heat_from_work(long n, const double* work, const double* area, double rolling_speed,
                    double* q)
{
    // Two elements a step: one packed division instead of two.
    typedef simd::Vec<2> Pair;
    const Pair zero = {0.0, 0.0};
    long e = 0;
    for (; e + 2 <= n; e += 2) {
        const Pair w = simd::load<2>(work + e);
        simd::store<2>(q + e, rolling_speed * quotient_if_positive(zero < w ? w : zero,
                                                                   simd::load<2>(area + e)));
    }
    for (; e < n; ++e)
        q[e] = rolling_speed * quotient_if_positive(std::max(0.0, work[e]), area[e]);
}

void heat_from_slip(long n, const double* px, const double* py, const double* sx,
                    const double* sy, double rolling_speed, double* q)
{
    // Plain roots: a solver's tractions and slips are far from the squares'
    // overflow (glibc's hypot costs more than the rest).
    for (long e = 0; e < n; ++e)
        q[e] = std::sqrt(px[e] * px[e] + py[e] * py[e]) * std::sqrt(sx[e] * sx[e] + sy[e] * sy[e]) *
               rolling_speed;
}

} // namespace creepwork::thermal
