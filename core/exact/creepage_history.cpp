#include "exact/creepage_history.hpp"

#include <algorithm>
#include <cmath>

namespace creepwork {

void CreepageHistory::resize(std::size_t n)
{
    for (auto& q : q_) q.assign(n, Complex(0.0, 0.0));
    predicted_.assign(n, Complex(0.0, 0.0));
    error_.assign(n, Complex(0.0, 0.0));
    error_before_.assign(n, Complex(0.0, 0.0));
    state_.assign(n, 0);
    clear();
}

bool CreepageHistory::same(const double key[kKey]) const
{
    if (count_ == 0) return false;
    for (int k = 0; k < kKey; ++k)
        if (key[k] != key_[k]) return false;
    return true;
}

bool CreepageHistory::predict(const double key[kKey], const double c[3], std::vector<Complex>& q,
                              double scale)
{
    predicted_valid_ = false;
    if (!same(key)) {
        clear();
        return false;
    }
    const int m = count_ - 1; // differences available (0, 1 or 2)
    double d[2][3], r[3];
    for (int k = 0; k < 3; ++k) r[k] = c[k] - c_[0][k];
    for (int i = 0; i < m; ++i)
        for (int k = 0; k < 3; ++k) d[i][k] = c_[i + 1][k] - c_[0][k];
    double g[2] = {0.0, 0.0};
    auto dot3 = [](const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    if (m == 1) {
        const double dd = dot3(d[0], d[0]);
        if (dd > 0.0) g[0] = dot3(d[0], r) / dd;
    } else if (m == 2) { // normal equations of the 3 x 2 least-squares problem
        const double a11 = dot3(d[0], d[0]), a12 = dot3(d[0], d[1]), a22 = dot3(d[1], d[1]);
        const double b1 = dot3(d[0], r), b2 = dot3(d[1], r);
        const double det = a11 * a22 - a12 * a12;
        if (det > 1e-12 * a11 * a22) {
            g[0] = (b1 * a22 - b2 * a12) / det;
            g[1] = (a11 * b2 - a12 * b1) / det;
        } else if (a11 > 0.0) {
            g[0] = b1 / a11;
        }
    }
    for (double& v : g)
        if (!(std::fabs(v) <= 4.0)) v = 0.0; // extrapolate, do not leap
    const std::vector<Complex>& q0 = q_[0];
    // The error of the last secant step when it and this one see the same
    // states: the newest four solutions (this step's three and the one
    // before them) share them. With the newest five, the last two errors
    // share them too, and the error is extrapolated linearly from them.
    const bool correct = m == 2 && error_valid_ && same_states_ >= 4;
    const bool linear = correct && error_before_valid_ && same_states_ >= 5;
    for (size_t k = 0; k < q.size(); ++k) {
        Complex v = q0[k];
        for (int i = 0; i < m; ++i) v += g[i] * (q_[i + 1][k] - q0[k]);
        predicted_[k] = v;
        if (linear)
            v += 2.0 * error_[k] - error_before_[k];
        else if (correct)
            v += error_[k];
        q[k] = scale == 1.0 ? v : v * scale;
    }
    predicted_valid_ = m == 2;
    return true;
}

void CreepageHistory::remember(const double key[kKey], const double c[3],
                               const std::vector<Complex>& q, double scale,
                               const signed char* state)
{
    if (!same(key)) clear();
    for (int k = 0; k < kKey; ++k) key_[k] = key[k];
    const size_t n = q.size();
    if (state) {
        const bool same_states =
            same_states_ > 0 && std::equal(state, state + n, state_.begin());
        same_states_ = same_states ? same_states_ + 1 : 1;
        std::copy(state, state + n, state_.begin());
    } else {
        same_states_ = 0;
    }
    // Shift: [0] is the newest.
    for (int i = std::min(count_, 2); i > 0; --i) {
        q_[i].swap(q_[i - 1]);
        for (int k = 0; k < 3; ++k) c_[i][k] = c_[i - 1][k];
    }
    if (scale == 1.0)
        q_[0] = q;
    else
        for (size_t k = 0; k < n; ++k) q_[0][k] = scale * q[k];
    for (int k = 0; k < 3; ++k) c_[0][k] = c[k];
    error_before_.swap(error_);
    error_before_valid_ = error_valid_;
    error_valid_ = predicted_valid_;
    if (error_valid_)
        for (size_t k = 0; k < n; ++k) error_[k] = q_[0][k] - predicted_[k];
    predicted_valid_ = false;
    count_ = std::min(count_ + 1, 3);
}

} // namespace creepwork
