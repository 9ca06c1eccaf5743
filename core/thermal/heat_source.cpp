#include "thermal/heat_source.hpp"

#include <algorithm>
#include <cmath>

#include "contact/fp_safe.hpp"

namespace creepwork::thermal {

void heat_from_work(long n, const double* work, const double* area, double rolling_speed,
                    double* q)
{
    for (long e = 0; e < n; ++e)
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
