#include "normal/pressure_drift.hpp"

#include <algorithm>
#include <cmath>

namespace creepwork {

PressureDrift::PressureDrift(std::size_t n)
{
    for (int s = 0; s < kSolutions; ++s) {
        h_[s].assign(n, 0.0);
        p_[s].assign(n, 0.0);
        u_[s].assign(n, 0.0);
    }
}

void PressureDrift::predict(const double* h, bool force, double approach, double* start,
                            double* g_out) const
{
    const int m = count_ - 1; // differences available (0, 1 or 2)
    const std::vector<double>& h0 = h_[slot(0)];
    const std::vector<double>& p0 = p_[slot(0)];
    const std::size_t n = p0.size();
    auto in_contact = [&](std::size_t k) {
        for (int i = 0; i <= m; ++i)
            if (p_[slot(i)][k] > 0.0) return true;
        return false;
    };
    // The differences r = h - h_0 and d_i = h_i - h_0 on the contact, less
    // their means (force) or the approach's changes (approach).
    double shift_r = approach - approach_[slot(0)], shift[2] = {0.0, 0.0};
    for (int i = 0; i < m; ++i) shift[i] = approach_[slot(i + 1)] - approach_[slot(0)];
    if (force) {
        double sr = 0.0, sd[2] = {0.0, 0.0}, count = 0.0;
        for (std::size_t k = 0; k < n; ++k)
            if (in_contact(k)) {
                sr += h[k] - h0[k];
                for (int i = 0; i < m; ++i) sd[i] += h_[slot(i + 1)][k] - h0[k];
                count += 1.0;
            }
        shift_r = count > 0.0 ? sr / count : 0.0;
        for (int i = 0; i < m; ++i) shift[i] = count > 0.0 ? sd[i] / count : 0.0;
    }
    double a11 = 0.0, a12 = 0.0, a22 = 0.0, b1 = 0.0, b2 = 0.0, hh = 0.0;
    for (std::size_t k = 0; k < n; ++k)
        if (m > 0 && in_contact(k)) {
            const double r = h[k] - h0[k] - shift_r;
            const double d1 = h_[slot(1)][k] - h0[k] - shift[0];
            const double d2 = m > 1 ? h_[slot(2)][k] - h0[k] - shift[1] : 0.0;
            a11 += d1 * d1;
            a12 += d1 * d2;
            a22 += d2 * d2;
            b1 += d1 * r;
            b2 += d2 * r;
            hh += h0[k] * h0[k];
        }
    // A difference within rounding of the gaps (a height alone changed, with
    // the force prescribed) is no direction: its step would scale the
    // solutions' own rounding up.
    const double floor = kRoundingFloor * kRoundingFloor * hh;
    const bool use1 = a11 > floor, use2 = m > 1 && a22 > floor;
    double g[2] = {0.0, 0.0};
    const double det = a11 * a22 - a12 * a12;
    if (use1 && use2 && det > 1e-12 * a11 * a22) { // normal equations of the least squares
        g[0] = (b1 * a22 - b2 * a12) / det;
        g[1] = (a11 * b2 - a12 * b1) / det;
    } else if (use1) {
        g[0] = b1 / a11;
    } else if (use2) {
        g[1] = b2 / a22;
    }
    if (!std::isfinite(g[0] + g[1])) g[0] = g[1] = 0.0;
    if (g_out) std::copy(g, g + kSolutions - 1, g_out);
    if (g[0] == 0.0 && g[1] == 0.0) {
        std::copy(p0.begin(), p0.end(), start);
        return;
    }
    const std::vector<double>& p1 = p_[slot(1)];
    const std::vector<double>& p2 = p_[slot(m > 1 ? 2 : 1)];
    for (std::size_t k = 0; k < n; ++k)
        start[k] = p0[k] + g[0] * (p1[k] - p0[k]) + g[1] * (p2[k] - p0[k]);
}

bool PressureDrift::predict_product(const double* g, double* product) const
{
    const int m = count_ - 1;
    if (count_ == 0 || !u_valid_[slot(0)]) return false;
    const std::vector<double>& u0 = u_[slot(0)];
    if (g[0] == 0.0 && g[1] == 0.0) {
        std::copy(u0.begin(), u0.end(), product);
        return true;
    }
    const int s1 = slot(1), s2 = slot(m > 1 ? 2 : 1);
    if (!u_valid_[s1] || !u_valid_[s2]) return false;
    const std::vector<double>& u1 = u_[s1];
    const std::vector<double>& u2 = u_[s2];
    for (std::size_t k = 0; k < u0.size(); ++k)
        product[k] = u0[k] + g[0] * (u1[k] - u0[k]) + g[1] * (u2[k] - u0[k]);
    return true;
}

void PressureDrift::remember(const double* h, double approach, const std::vector<double>& p,
                             const double* product, double scale)
{
    newest_ = count_ == 0 ? 0 : (newest_ + 1) % kSolutions;
    std::copy(h, h + h_[newest_].size(), h_[newest_].begin());
    std::copy(p.begin(), p.end(), p_[newest_].begin());
    u_valid_[newest_] = product != nullptr;
    if (product)
        for (std::size_t k = 0; k < u_[newest_].size(); ++k) u_[newest_][k] = product[k] * scale;
    approach_[newest_] = approach;
    count_ = std::min(count_ + 1, kSolutions);
}

} // namespace creepwork
