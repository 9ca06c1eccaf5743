#include "work/wear_map.hpp"

#include <algorithm>
#include <cmath>

#include "contact/error.hpp"
#include "contact/fp_safe.hpp"

namespace creepwork::wear {

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

WearTotals wear_map(const ContactFields& in, const WearLaw& law, const WearFields& out)
{
    validate(law);
    const bool slip_source = law.source == Source::slip;
    const double rho = law.density;
    WearTotals t;
    double volume_section = 0.0; // worn cross-section per pass [m^2]
    for (int j = 0; j < in.ny; ++j) {
        const double dy = in.strip_width[j];
        double strip = 0.0;
        for (int i = 0; i < in.nx; ++i) {
            const long e = i + static_cast<long>(j) * in.nx;
            const double A = in.area[e];
            double W = 0.0, s = 0.0, rate = 0.0;
            int regime = kRegimeNone;
            if (A > 0.0) {
                const double px = in.px[e], py = in.py[e];
                const double p = std::hypot(px, py);
                if (slip_source) {
                    W = std::max(0.0, -(px * in.sx[e] + py * in.sy[e]) * A);
                    s = std::hypot(in.sx[e], in.sy[e]);
                } else {
                    W = std::max(0.0, in.work[e]);
                    s = quotient_if_positive(W, p * A);
                }
                if (law.law == Law::usfd) {
                    rate = usfd_rate(law.usfd, W / A, regime);
                } else {
                    const double k = kth_coefficient(law.kth, s * law.rolling_speed, in.pz[e], regime);
                    rate = rho * k * std::max(0.0, in.pz[e]) * s / law.kth.hardness;
                }
                if (regime != kRegimeNone) t.regime_area[regime - 1] += A;
            }
            const double mass_per_distance = rate * A;
            const double depth = quotient_if_positive(mass_per_distance, rho * dy);
            if (out.rate) out.rate[e] = rate;
            if (out.depth) out.depth[e] = depth;
            if (out.mass) out.mass[e] = mass_per_distance * law.pass_length;
            if (out.work_density) out.work_density[e] = quotient_if_positive(W, A);
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
