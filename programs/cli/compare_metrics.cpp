#include "compare_metrics.hpp"

#include <cmath>
#include <vector>

#include "cli_error.hpp"

namespace cwcli {

namespace {

double work_sum(const std::vector<double>& v)
{
    double s = 0.0;
    for (double x : v) s += x;
    return s;
}

// sum_k |a_k/A - b_k/B|, NaN when either total is not positive.
double l1_of_shapes(const std::vector<double>& a, const std::vector<double>& b)
{
    const double ta = work_sum(a), tb = work_sum(b);
    if (!(ta > 0.0 && tb > 0.0)) return NAN;
    double d = 0.0;
    for (size_t k = 0; k < a.size(); ++k) d += std::fabs(a[k] / ta - b[k] / tb);
    return d;
}

// Share of the total of w in the elements whose state in `states` is adhesion.
double share_in_adhesion(const std::vector<double>& w, const std::vector<int>& states)
{
    const double total = work_sum(w);
    if (!(total > 0.0)) return NAN;
    double in = 0.0;
    for (size_t k = 0; k < w.size(); ++k)
        if (states[k] == CW_STATE_ADHESION) in += w[k];
    return in / total;
}

double centroid(const Solution& s)
{
    const double total = work_sum(s.work_consistent);
    if (!(total > 0.0)) return NAN;
    double m = 0.0;
    for (size_t k = 0; k < s.size(); ++k) m += s.work_consistent[k] * s.x[k];
    return s.params.rolling_direction * m / (total * s.result.a);
}

} // namespace

WorkComparison compare_work(const Solution& f, const Solution& e)
{
    if (f.nx != e.nx || f.ny != e.ny || f.grid.kind != e.grid.kind ||
        f.grid.box_scale != e.grid.box_scale)
        throw CliError(kExitFailure, "internal error: compare_work needs one grid for both models");
    WorkComparison c;
    c.map_l1_consistent = l1_of_shapes(f.work_consistent, e.work_consistent);
    c.map_l1_paper = l1_of_shapes(f.work_paper, e.work_paper);
    c.profile_l1 = l1_of_shapes(f.profile_w, e.profile_w);
    c.exact_power_in_fastsim_adhesion = share_in_adhesion(e.work_paper, f.state);
    c.fastsim_work_in_exact_adhesion = share_in_adhesion(f.work_consistent, e.state);
    for (size_t k = 0; k < f.size(); ++k)
        if (f.state[k] != CW_STATE_EXTERIOR && e.state[k] != CW_STATE_EXTERIOR &&
            f.state[k] != e.state[k])
            ++c.state_differences;
    c.centroid_fastsim = centroid(f);
    c.centroid_exact = centroid(e);
    return c;
}

} // namespace cwcli
