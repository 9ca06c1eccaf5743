#include "calibration_metrics.hpp"

#include <algorithm>
#include <cmath>

namespace cwcal {

std::vector<double> summed_onto_coarse_grid(const std::vector<double>& fine, int n_fine,
                                            int n_coarse)
{
    const int f = n_fine / n_coarse;
    std::vector<double> map(size_t(n_coarse) * n_coarse, 0.0);
    for (int j = 0; j < n_fine; ++j)
        for (int i = 0; i < n_fine; ++i)
            map[size_t(i / f) + size_t(j / f) * n_coarse] += fine[size_t(i) + size_t(j) * n_fine];
    return map;
}

double unit_l1(const std::vector<double>& a, const std::vector<double>& b)
{
    double sa = 0, sb = 0;
    for (double v : a) sa += v;
    for (double v : b) sb += v;
    if (!(sa > 0) || !(sb > 0)) return 2.0;
    double d = 0;
    for (size_t k = 0; k < a.size(); ++k) d += std::fabs(a[k] / sa - b[k] / sb);
    return d;
}

double profile_l1(const std::vector<double>& a, const std::vector<double>& b, int nx, int ny)
{
    std::vector<double> pa(ny, 0.0), pb(ny, 0.0);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            pa[j] += a[i + j * nx];
            pb[j] += b[i + j * nx];
        }
    return unit_l1(pa, pb);
}

CaseErrors case_errors(const creepwork::ContactInput& in, const ModelResult& m,
                       const ModelResult& ref, const ModelResult& exact40, int nx, int ny)
{
    CaseErrors e;
    const double muN = in.mu * in.normal_force, c = std::sqrt(in.a * in.b);
    e.dFx = 100.0 * std::fabs(m.Fx - ref.Fx) / muN;
    e.dFy = 100.0 * std::fabs(m.Fy - ref.Fy) / muN;
    e.mz_relative = std::fabs(ref.Mz) >= 0.01 * muN * c;
    e.dMz = e.mz_relative ? 100.0 * std::fabs(m.Mz - ref.Mz) / std::fabs(ref.Mz)
                          : 100.0 * std::fabs(m.Mz - ref.Mz) / (muN * c);
    e.has_spin = in.phi != 0.0;
    e.dW = 100.0 * std::fabs(m.W - ref.W) / std::fabs(ref.W);
    e.partial_slip = exact40.adhesion_fraction >= 0.05 && exact40.adhesion_fraction <= 0.95;
    e.has_map = !m.work_map.empty();
    if (e.partial_slip && e.has_map) {
        e.map_L1 = unit_l1(m.work_map, exact40.work_map);
        e.profile_L1 = profile_l1(m.work_map, exact40.work_map, nx, ny);
    }
    return e;
}

} // namespace cwcal

namespace cwcal {

double median_of(std::vector<double> v)
{
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

} // namespace cwcal
