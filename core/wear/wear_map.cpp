#include "wear/wear_map.hpp"

#include <algorithm>
#include <cmath>

#include "contact/error.hpp"
#include "contact/fp_safe.hpp"

namespace creepwork::wear {

namespace {

// |(x, y)|: a plain square root for ordinary magnitudes (glibc's hypot costs
// more than the rest of an element's wear), hypot where the squares could
// overflow or underflow.
inline double magnitude(double x, double y)
{
    const double m = std::max(std::fabs(x), std::fabs(y));
    if (m < 1e150 && m > 1e-150) return std::sqrt(x * x + y * y);
    return std::hypot(x, y);
}

} // namespace

double parabola_strip_average(double V, double b, double lo, double hi)
{
    const double width = hi - lo;
    lo = std::max(lo, -b);
    hi = std::min(hi, b);
    if (!(hi > lo) || !(width > 0.0)) return 0.0;
    const double u = lo / b, v = hi / b;
    // integral of (1 - y^2/b^2) dy over [lo, hi] = b (v - u - (v^3 - u^3)/3)
    const double integral = b * ((v - u) - (v * v * v - u * u * u) / 3.0);
    return quotient_if_positive(0.75 * V / b * integral, width);
}

namespace {

// The element loop, one instance per law and source (no per-element
// dispatch). Two divisions per element: T/A = W/A and s = (T/A)/|p|.
template <Law L, bool SlipSource>
void element_loop(const ContactFields& in, const WearLaw& law, const WearFields& out,
                  WearTotals& t, double& volume_section)
{
    const double rho = law.density;
    for (int j = 0; j < in.ny; ++j) {
        const double dy = in.strip_width[j];
        const double to_depth = quotient_if_positive(1.0, rho * dy); // per unit mass per metre
        double strip = 0.0;
        for (int i = 0; i < in.nx; ++i) {
            const long e = i + static_cast<long>(j) * in.nx;
            const double A = in.area[e];
            double W = 0.0, tga = 0.0, s = 0.0, rate = 0.0;
            int regime = kRegimeNone;
            if (A > 0.0) {
                const double px = in.px[e], py = in.py[e];
                if constexpr (SlipSource) {
                    W = std::max(0.0, -(px * in.sx[e] + py * in.sy[e]) * A);
                    tga = quotient_if_positive(W, A); // fp_safe.hpp: never speculated
                    s = magnitude(in.sx[e], in.sy[e]);
                } else {
                    W = std::max(0.0, in.work[e]);
                    tga = quotient_if_positive(W, A); // fp_safe.hpp: never speculated
                    s = quotient_if_positive(tga, magnitude(px, py));
                }
                if constexpr (L == Law::usfd) {
                    rate = usfd_rate(law.usfd, tga, regime);
                } else {
                    const double pz = std::max(0.0, in.pz[e]);
                    const double k = kth_coefficient(law.kth, s * law.rolling_speed, pz, regime);
                    rate = rho * k * pz * s / law.kth.hardness;
                }
                if (regime != kRegimeNone) t.regime_area[regime - 1] += A;
            }
            const double mass_per_distance = rate * A;
            const double depth = mass_per_distance * to_depth;
            if (out.rate) out.rate[e] = rate;
            if (out.depth) out.depth[e] = depth;
            if (out.mass) out.mass[e] = mass_per_distance * law.pass_length;
            if (out.work_density) out.work_density[e] = tga;
            if (out.sliding) out.sliding[e] = s;
            if (out.regime) out.regime[e] = regime;
            t.mass_per_distance += mass_per_distance;
            t.work += W;
            strip += depth;
        }
        if (out.strip_depth) out.strip_depth[j] = strip;
        t.max_depth = std::max(t.max_depth, strip);
        volume_section += strip * dy;
    }
}

} // namespace

WearTotals wear_map(const ContactFields& in, const WearLaw& law, const WearFields& out)
{
    validate(law);
    WearTotals t;
    double volume_section = 0.0; // worn cross-section per pass [m^2]
    const bool slip = law.source == Source::slip;
    if (law.law == Law::usfd)
        slip ? element_loop<Law::usfd, true>(in, law, out, t, volume_section)
             : element_loop<Law::usfd, false>(in, law, out, t, volume_section);
    else
        slip ? element_loop<Law::archard_kth, true>(in, law, out, t, volume_section)
             : element_loop<Law::archard_kth, false>(in, law, out, t, volume_section);
    const double rho = law.density;
    t.mass_per_pass = t.mass_per_distance * law.pass_length;
    t.volume_per_distance = t.mass_per_distance / rho;
    if (out.strip_parabola)
        for (int j = 0; j < in.ny; ++j) {
            const double half = 0.5 * in.strip_width[j];
            out.strip_parabola[j] = parabola_strip_average(volume_section, in.b,
                                                           in.strip_y[j] - half,
                                                           in.strip_y[j] + half);
        }
    const double checks[] = {t.mass_per_distance, t.mass_per_pass, t.work, t.max_depth,
                             volume_section};
    for (double v : checks)
        if (!std::isfinite(v))
            throw Error(ErrorKind::numeric_failure,
                        "the wear of this contact overflowed: its work or coefficients are too "
                        "large for double precision");
    return t;
}

} // namespace creepwork::wear
