#include "exact/exact_work.hpp"

#include <cmath>

#include "contact/params.hpp"
#include "contact/solved_contact.hpp"

namespace creepwork {

ExactWorkTotals exact_work(const ExactWorkInput& in, double* paper, double* consistent,
                           double* profile, double* row_d, double* row_pool)
{
    ExactWorkTotals t;
    const int nx = in.nx, ny = in.ny;
    const double unit = in.traction_scale * in.slip_scale * in.area; // J/m per unit q.s
    double total_d = 0.0, total_pool = 0.0, total_signed = 0.0;
    int rows_with_slip = 0;
    for (int j = 0; j < ny; ++j) {
        double d_sum = 0.0, rigid = 0.0;
        for (int i = 0; i < nx; ++i) {
            const int k = i + nx * j;
            double d = 0.0;
            if (in.state[k] == 2) {
                d = -unit * (in.q[k].real() * in.s[k].real() + in.q[k].imag() * in.s[k].imag());
                if (!(d > 0.0)) d = 0.0; // q is antiparallel to s: only rounding gets here
            }
            paper[k] = d;
            d_sum += d;
            if (in.state[k] != 0)
                rigid -= unit * (in.q[k].real() * in.w[k].real() + in.q[k].imag() * in.w[k].imag());
        }
        row_d[j] = d_sum;
        const double pool = rigid - d_sum;
        row_pool[j] = pool > 0.0 ? pool : 0.0;
        total_d += d_sum;
        total_pool += row_pool[j];
        total_signed += pool;
        rows_with_slip += d_sum > 0.0;
    }
    t.W_micro_paper = total_d;
    // A row can end with a negative budget (the elastic field passes energy
    // between rows). The total is the numerical dissipation (>= 0); the rows
    // with a positive budget share it in proportion to their budgets.
    const double share = total_pool > 0.0 && total_signed > 0.0 ? total_signed / total_pool : 0.0;
    for (int j = 0; j < ny; ++j) row_pool[j] *= share;
    total_pool = total_signed > 0.0 ? total_signed : 0.0;

    // Each row's pool goes to its own slip elements, or to the nearest rows
    // with slip (split evenly between two at the same distance); with no slip
    // anywhere, to each row's trailing contact element.
    for (int k = 0; k < nx * ny; ++k) consistent[k] = paper[k];
    if (rows_with_slip == 0) {
        if (total_pool > 0.0) t.flags |= kWorkUnresolved;
        for (int j = 0; j < ny; ++j) {
            if (!(row_pool[j] > 0.0)) continue;
            for (int i = 0; i < nx; ++i)
                if (in.state[i + nx * j] != 0) {
                    consistent[i + nx * j] += row_pool[j];
                    break;
                }
        }
    } else {
        for (int j = 0; j < ny; ++j) {
            if (!(row_pool[j] > 0.0)) continue;
            int lo = -1, hi = -1;
            for (int dist = 0; dist < ny && lo < 0 && hi < 0; ++dist) {
                if (j - dist >= 0 && row_d[j - dist] > 0.0) lo = j - dist;
                if (j + dist < ny && row_d[j + dist] > 0.0) hi = j + dist;
            }
            const int targets[2] = {lo, hi == lo ? -1 : hi};
            const double share = row_pool[j] / ((targets[0] >= 0) + (targets[1] >= 0));
            for (int r : targets) {
                if (r < 0) continue;
                const double f = share / row_d[r];
                for (int i = 0; i < nx; ++i) consistent[i + nx * r] += f * paper[i + nx * r];
            }
        }
    }

    const double total = total_d + total_pool;
    // The map adds up to W_macro only when both are positive. Otherwise it is
    // zero and flagged, as in the march (march_work.cpp): W_macro <= 0 with
    // dissipation, or W_macro > 0 that rounding left with nothing to carry it
    // (extreme inputs, where every element product flushes to zero).
    if (!(total > 0.0 && in.W_macro > 0.0) && (total > 0.0 || in.W_macro != 0.0))
        t.flags |= kWorkNonPositive;
    t.balance = total > 0.0 && in.W_macro > 0.0 ? in.W_macro / total : 1.0;
    const double scale = (t.flags & kWorkNonPositive) ? 0.0 : t.balance;
    double sum = 0.0;
    double peak = 0.0;
    for (int j = 0; j < ny; ++j) {
        double row = 0.0;
        for (int i = 0; i < nx; ++i) {
            const int k = i + nx * j;
            consistent[k] *= scale;
            row += consistent[k];
        }
        sum += row;
        profile[j] = row / in.dy;
        peak = profile[j] > peak ? profile[j] : peak;
    }
    t.W_consistent = sum;

    if (peak > 0.0) {
        double max_diff = 0.0, sum_sq = 0.0;
        int count = 0;
        for (int j = 0; j < ny; ++j) {
            bool contact = false;
            for (int i = 0; i < nx && !contact; ++i) contact = in.state[i + nx * j] != 0;
            if (!contact) continue;
            const double y = in.y0 + j * in.dy;
            const double d = (profile[j] - lateral_parabola(sum, in.b, y)) / peak;
            max_diff = std::fabs(d) > max_diff ? std::fabs(d) : max_diff;
            sum_sq += d * d;
            ++count;
        }
        t.profile_max_diff = max_diff;
        t.profile_rms_diff = std::sqrt(sum_sq / count);
    }
    return t;
}

void set_work_totals(const ExactWorkTotals& work, SolveTotals& t)
{
    t.W_micro_paper = work.W_micro_paper;
    t.K = work.W_micro_paper != 0.0 ? t.W_macro / work.W_micro_paper : 0.0;
    t.W_consistent = work.W_consistent;
    t.balance_factor = work.balance;
    t.work_flags = work.flags;
    t.profile_max_diff = work.profile_max_diff;
    t.profile_rms_diff = work.profile_rms_diff;
}

} // namespace creepwork
