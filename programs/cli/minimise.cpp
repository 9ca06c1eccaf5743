#include "minimise.hpp"

#include <cmath>

namespace cwcli {

Minimum golden_section(const std::function<double(double)>& f, double lo, double hi, double rel_tol)
{
    const double g = (std::sqrt(5.0) - 1.0) / 2.0; // 0.618...
    double c = hi - g * (hi - lo), d = lo + g * (hi - lo);
    double fc = f(c), fd = f(d);
    // Each step keeps the bracket holding the lower interior point.
    for (int it = 0; it < 200 && (hi - lo) > rel_tol * std::fabs(c); ++it) {
        if (fc <= fd) {
            hi = d;
            d = c;
            fd = fc;
            c = hi - g * (hi - lo);
            fc = f(c);
        } else {
            lo = c;
            c = d;
            fc = fd;
            d = lo + g * (hi - lo);
            fd = f(d);
        }
    }
    return fc <= fd ? Minimum{c, fc} : Minimum{d, fd};
}

std::vector<Minimum> local_minima(const std::function<double(double)>& f, double lo, double hi,
                                  int samples, double rel_tol)
{
    std::vector<double> x(static_cast<size_t>(samples)), y(x.size());
    const double ratio = std::pow(hi / lo, 1.0 / (samples - 1));
    for (size_t k = 0; k < x.size(); ++k) {
        x[k] = lo * std::pow(ratio, static_cast<double>(k));
        y[k] = f(x[k]);
    }
    std::vector<Minimum> minima;
    for (size_t k = 1; k + 1 < x.size(); ++k)
        if (y[k] < y[k - 1] && y[k] <= y[k + 1])
            minima.push_back(golden_section(f, x[k - 1], x[k + 1], rel_tol));
    return minima;
}

} // namespace cwcli
