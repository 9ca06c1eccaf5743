// The semi-Hertzian method's derivative by the load, at the depth d the last
// solve found. Each row's pressure is p_i = P sqrt(d - beta g - alpha A x_i^2)
// with P the row's pressure factor (SemiHertz::Row::p_factor), constant in d
// between the depths where the curvature fit's half-width or an element's
// contact changes: so dp_i/dd = P^2 / (2 p_i) on the contact elements and
// dF/dd = dx dy sum dp_i/dd. With the approach prescribed, d = approach - h_min
// and dp/dN = (dp/dd) / (dF/dd); with the force prescribed the solve scales
// its pressure by N / F(d), F(d) = N to the iteration's 1e-13, and
// differentiating p = N p(d) / F(d) along F(d(N)) = N gives the same
// (dp/dd) / (dF/dd). The ratio does not depend on the scale of p, so the
// scaled pressure serves. dF/dd alone is the force's derivative by the
// approach (d = approach - h_min), to the scale N / F(d) = 1 + O(1e-13).
#include "normal/semi_hertz.hpp"

#include <cstddef>

namespace creepwork {

void SemiHertz::load_derivative(const double* pressure, double* dp_dN) const
{
    double total = 0.0;
    for (int j = 0; j < ny_; ++j) {
        const double P2 = rows_[j].p_factor * rows_[j].p_factor;
        for (int i = 0; i < nx_; ++i) {
            const std::size_t k = i + static_cast<std::size_t>(nx_) * j;
            const double p = pressure[k];
            dp_dN[k] = p > 0.0 ? 0.5 * P2 / p : 0.0;
            total += dp_dN[k];
        }
    }
    const double inv = total > 0.0 ? 1.0 / (total * dx_ * dy_) : 0.0;
    const std::size_t n = static_cast<std::size_t>(nx_) * ny_;
    for (std::size_t k = 0; k < n; ++k) dp_dN[k] *= inv;
}

double SemiHertz::force_by_depth(const double* pressure) const
{
    double total = 0.0;
    for (int j = 0; j < ny_; ++j) {
        const double P2 = rows_[j].p_factor * rows_[j].p_factor;
        const double* p = pressure + static_cast<std::size_t>(nx_) * j;
        for (int i = rows_[j].written_lo; i <= rows_[j].written_hi; ++i)
            if (p[i] > 0.0) total += 0.5 * P2 / p[i];
    }
    return total * dx_ * dy_;
}

} // namespace creepwork
