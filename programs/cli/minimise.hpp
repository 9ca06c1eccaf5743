// One-dimensional minimisation for fitting a semi-axis: a scan that finds
// every local minimum (FASTSIM's forces are not monotonic in a, so the
// misfit can have several), each refined by golden-section search.
#pragma once

#include <functional>
#include <vector>

namespace cwcli {

struct Minimum {
    double x = 0, f = 0;
};

// Golden-section search for a minimum of f in [lo, hi], to |hi - lo| <=
// rel_tol * x.
Minimum golden_section(const std::function<double(double)>& f, double lo, double hi,
                       double rel_tol);

// f on `samples` geometrically spaced points over [lo, hi] (lo > 0); every
// interior sample lower than both neighbours brackets a local minimum, which
// golden_section refines. Sorted by x.
std::vector<Minimum> local_minima(const std::function<double(double)>& f, double lo, double hi,
                                  int samples, double rel_tol);

} // namespace cwcli
