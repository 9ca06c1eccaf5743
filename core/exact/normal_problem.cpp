#include "exact/normal_problem.hpp"

#include <algorithm>
#include <cmath>

#include "contact/hertz.hpp"

namespace creepwork {
namespace {

constexpr double kPi = 3.14159265358979323846;

} // namespace

NormalProblem::NormalProblem(int nx, int ny)
    : n_(nx * ny), h_(n_), q_(n_, 0.0), u_(n_), r_(n_), z_(n_), p_(n_), ap_(n_), active_(n_, 0)
{
}

void NormalProblem::project(std::vector<double>& v) const
{
    double mean = 0.0;
    for (int k = 0; k < n_; ++k)
        if (active_[k]) mean += v[k];
    mean /= n_active_;
    for (int k = 0; k < n_; ++k) v[k] = active_[k] ? v[k] - mean : 0.0;
}

// Projected preconditioned CG for A q + h = pen on the active set with
// sum q fixed (the mean of the residual is the approach's share).
bool NormalProblem::conjugate_gradients(GridConvolution& conv, double target, double tolerance,
                                        int max_iterations, NormalSolveInfo& info)
{
    conv.apply_normal(q_.data(), u_.data());
    for (int k = 0; k < n_; ++k) r_[k] = active_[k] ? -(h_[k] + u_[k]) : 0.0;
    project(r_);
    auto precondition = [&] {
        conv.apply_normal_inverse(r_.data(), z_.data());
        project(z_);
    };
    auto largest = [&](const std::vector<double>& v) {
        double m = 0.0;
        for (double x : v) m = std::max(m, std::fabs(x));
        return m;
    };
    if (largest(r_) <= tolerance * target) return true;
    precondition();
    p_ = z_;
    double rz = 0.0;
    for (int k = 0; k < n_; ++k) rz += r_[k] * z_[k];
    while (info.iterations < max_iterations) {
        ++info.iterations;
        conv.apply_normal(p_.data(), ap_.data());
        project(ap_);
        double pap = 0.0;
        for (int k = 0; k < n_; ++k) pap += p_[k] * ap_[k];
        if (!(pap > 0.0)) return false; // lost positive definiteness: rounding
        const double step = rz / pap;
        for (int k = 0; k < n_; ++k) {
            q_[k] += step * p_[k];
            r_[k] -= step * ap_[k];
        }
        if (largest(r_) <= tolerance * target) return true;
        precondition();
        double rz_new = 0.0;
        for (int k = 0; k < n_; ++k) rz_new += r_[k] * z_[k];
        const double beta = rz_new / rz;
        rz = rz_new;
        for (int k = 0; k < n_; ++k) p_[k] = z_[k] + beta * p_[k];
    }
    return false;
}

NormalSolveInfo NormalProblem::solve(const ExactGeometry& g, GridConvolution& conv, bool start,
                                     double tolerance, int max_iterations)
{
    NormalSolveInfo info;
    // Gap and load in the normalised units: Hertz's curvatures for semi-axes
    // alpha, beta (in dx) with p0 = E* = 1, times 1 - nu (E* = G / (1 - nu)).
    const HertzCurvatures hz =
        hertz_from_semi_axes(g.alpha, g.beta, 2.0 * kPi * g.alpha * g.beta / 3.0, 1.0);
    const double one_minus_nu = 1.0 - conv.nu();
    const double load = 2.0 * kPi * g.alpha * g.beta / (3.0 * g.rho); // sum q = N/(p0 dx dy)
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const double X = g.X(i), Y = g.Y(j);
            h_[i + g.nx * j] = one_minus_nu * (hz.A * X * X + hz.B * Y * Y);
        }

    if (!(start && n_contact_ > 0)) {
        // Hertz's pressure on the elements whose centre is inside the ellipse;
        // if there is none (a box far too coarse), the element nearest the centre.
        int nearest = 0;
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                const int k = i + g.nx * j;
                const double X = g.X(i) / g.alpha, Y = g.Y(j) / g.beta;
                const double e = 1.0 - X * X - Y * Y;
                q_[k] = e > 0.0 ? std::sqrt(e) : 0.0;
                if (h_[k] < h_[nearest]) nearest = k;
            }
        bool any = false;
        for (int k = 0; k < n_; ++k) any = any || q_[k] > 0.0;
        if (!any) q_[nearest] = 1.0;
    }
    n_active_ = 0;
    for (int k = 0; k < n_; ++k) {
        active_[k] = q_[k] > 0.0;
        n_active_ += active_[k];
    }

    const int max_passes = 50;
    double target = 1.0;
    while (info.active_set_passes < max_passes) {
        ++info.active_set_passes;
        double sum = 0.0;
        for (int k = 0; k < n_; ++k) sum += active_[k] ? q_[k] : 0.0;
        for (int k = 0; k < n_; ++k)
            q_[k] = !active_[k] ? 0.0 : sum > 0.0 ? q_[k] * (load / sum) : load / n_active_;
        // The approach sets the scale of the gap residual.
        conv.apply_normal(q_.data(), u_.data());
        double pen = 0.0;
        for (int k = 0; k < n_; ++k)
            if (active_[k]) pen += h_[k] + u_[k];
        target = std::max(std::fabs(pen / n_active_), 1e-300);
        if (!conjugate_gradients(conv, target, tolerance, max_iterations, info)) break;

        conv.apply_normal(q_.data(), u_.data());
        pen = 0.0;
        for (int k = 0; k < n_; ++k)
            if (active_[k]) pen += h_[k] + u_[k];
        pen_ = pen / n_active_;
        double worst = 0.0;
        for (int k = 0; k < n_; ++k)
            if (active_[k]) worst = std::max(worst, std::fabs(h_[k] - pen_ + u_[k]));
        info.residual = worst / std::max(std::fabs(pen_), 1e-300);

        // Complementarity: drop tensile elements, add penetrating ones.
        bool changed = false;
        int kept = 0;
        for (int k = 0; k < n_; ++k) {
            if (active_[k] && q_[k] < 0.0) {
                active_[k] = 0;
                q_[k] = 0.0;
                changed = true;
            } else if (!active_[k] && h_[k] - pen_ + u_[k] < -tolerance * std::fabs(pen_)) {
                active_[k] = 1;
                changed = true;
            }
            kept += active_[k];
        }
        n_active_ = kept;
        if (n_active_ == 0) break; // cannot happen with a positive load; guarded
        if (!changed) {
            info.converged = true;
            break;
        }
    }
    // A failed solve leaves no start for the next one.
    n_contact_ = 0;
    for (int k = 0; k < n_; ++k) {
        if (!info.converged || q_[k] < 0.0) q_[k] = 0.0;
        n_contact_ += q_[k] > 0.0;
    }
    return info;
}

} // namespace creepwork
