#include "normal/normal_problem.hpp"

#include <algorithm>
#include <cmath>

#include "contact/hertz.hpp"
#include "halfspace/cell_box.hpp"

namespace creepwork {
namespace {

constexpr double kPi = 3.14159265358979323846;

} // namespace

NormalProblem::NormalProblem(int nx, int ny)
    : n_(nx * ny), nx_(nx), h_(n_), q_(n_, 0.0), u_(n_), r_(n_), z_(n_), p_(n_), ap_(n_),
      box_in_(n_), box_out_(n_), dq_(n_, 0.0), active_(n_, 0)
{
}

void NormalProblem::fit_box(GridConvolution& conv)
{
    const int ny = n_ / nx_;
    const CellBox box = cell_box(nx_, ny, [&](std::size_t k) { return active_[k] != 0; });
    box_i0_ = box.i0;
    box_j0_ = box.j0;
    box_nx_ = box.nx;
    box_ny_ = box.ny;
    box_->set_size(box_nx_, box_ny_);
    box_->copy_coefficients(conv);
}

void NormalProblem::set_product(GridConvolution& conv, const std::vector<double>& in,
                                std::vector<double>& out, bool inverse)
{
    ++products_;
    if (!box_) {
        if (inverse)
            conv.apply_normal_inverse(in.data(), out.data());
        else
            conv.apply_normal(in.data(), out.data());
        return;
    }
    for (int j = 0; j < box_ny_; ++j)
        for (int i = 0; i < box_nx_; ++i)
            box_in_[i + static_cast<size_t>(box_nx_) * j] =
                in[box_i0_ + i + static_cast<size_t>(nx_) * (box_j0_ + j)];
    if (inverse)
        box_->apply_normal_inverse(box_in_.data(), box_out_.data());
    else
        box_->apply_normal(box_in_.data(), box_out_.data());
    // Outside the box (so outside the set) out is never read; zero keeps it tidy.
    std::fill(out.begin(), out.end(), 0.0);
    for (int j = 0; j < box_ny_; ++j)
        for (int i = 0; i < box_nx_; ++i)
            out[box_i0_ + i + static_cast<size_t>(nx_) * (box_j0_ + j)] =
                box_out_[i + static_cast<size_t>(box_nx_) * j];
}

void NormalProblem::grid_product(GridConvolution& conv)
{
    ++products_;
    conv.apply_normal(q_.data(), u_.data());
}

void NormalProblem::project(std::vector<double>& v) const
{
    double mean = 0.0;
    for (int k = 0; k < n_; ++k)
        if (active_[k]) mean += v[k];
    mean /= n_active_;
    for (int k = 0; k < n_; ++k) v[k] = active_[k] ? v[k] - mean : 0.0;
}

// Projected preconditioned CG for A q + h = pen on the active set, with
// sum q fixed (the mean of the residual is the approach's share) or with
// pen fixed (then the residual is only restricted to the set).
bool NormalProblem::conjugate_gradients(GridConvolution& conv, bool fixed_sum, bool u_current,
                                        double target, double tolerance, int max_iterations,
                                        NormalSolveInfo& info)
{
    auto restrict_to_set = [&](std::vector<double>& v) {
        if (fixed_sum)
            project(v);
        else
            for (int k = 0; k < n_; ++k)
                if (!active_[k]) v[k] = 0.0;
    };
    if (!u_current) set_product(conv, q_, u_, false);
    if (fixed_sum)
        for (int k = 0; k < n_; ++k) r_[k] = active_[k] ? -(h_[k] + u_[k]) : 0.0;
    else
        for (int k = 0; k < n_; ++k) r_[k] = active_[k] ? pen_ - h_[k] - u_[k] : 0.0;
    restrict_to_set(r_);
    auto precondition = [&] {
        set_product(conv, r_, z_, true);
        restrict_to_set(z_);
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
        set_product(conv, p_, ap_, false);
        restrict_to_set(ap_);
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
    active_set(conv, true, load, 0.0, tolerance, tolerance, max_iterations, info);
    return info;
}

NormalSolveInfo NormalProblem::solve_gap(GridConvolution& conv, const double* h,
                                         const double* start, bool force, double value,
                                         double tolerance, int max_iterations,
                                         double first_tolerance, const double* start_product)
{
    NormalSolveInfo info;
    double h_floor = h[0];
    start_product_ = start_product;
    for (int k = 0; k < n_; ++k) {
        h_[k] = h[k];
        q_[k] = start[k] > 0.0 ? start[k] : 0.0;
        h_floor = std::min(h_floor, h[k]);
        if (start[k] < 0.0) start_product_ = nullptr; // clipped: not A q
    }
    if (!force) {
        pen_ = value;
        if (!(value > h_floor)) { // the surfaces do not touch
            start_product_ = nullptr;
            std::fill(q_.begin(), q_.end(), 0.0);
            n_contact_ = 0;
            info.converged = true;
            return info;
        }
    }
    // An empty start: the elements the rigid surfaces overlap (approach), or
    // the lowest one (force).
    bool any = false;
    for (int k = 0; k < n_ && !any; ++k) any = q_[k] > 0.0;
    for (int k = 0; k < n_ && !any; ++k)
        if (force ? h_[k] == h_floor : h_[k] < pen_) q_[k] = 1.0;
    active_set(conv, force, value, h_floor, tolerance, std::max(tolerance, first_tolerance),
               max_iterations, info);
    return info;
}

void NormalProblem::active_set(GridConvolution& conv, bool fixed_sum, double load,
                               double h_floor, double tolerance, double first_tolerance,
                               int max_iterations, NormalSolveInfo& info)
{
    double pass_tolerance = first_tolerance; // until the contact set settles
    const double* start_product = start_product_; // solve_gap's, this solve's only
    start_product_ = nullptr;
    products_ = 0;
    n_active_ = 0;
    for (int k = 0; k < n_; ++k) {
        active_[k] = q_[k] > 0.0;
        n_active_ += active_[k];
    }

    const int max_passes = 50;
    double target = 1.0;
    while (info.active_set_passes < max_passes && n_active_ > 0) {
        ++info.active_set_passes;
        double pen = 0.0;
        if (fixed_sum) {
            double sum = 0.0;
            for (int k = 0; k < n_; ++k) sum += active_[k] ? q_[k] : 0.0;
            for (int k = 0; k < n_; ++k)
                q_[k] = !active_[k] ? 0.0 : sum > 0.0 ? q_[k] * (load / sum) : load / n_active_;
            // The approach sets the scale of the gap residual.
            if (box_) fit_box(conv);
            if (start_product && sum > 0.0) // the start's product, scaled as q
                for (int k = 0; k < n_; ++k) u_[k] = start_product[k] * (load / sum);
            else
                set_product(conv, q_, u_, false);
            for (int k = 0; k < n_; ++k)
                if (active_[k]) pen += h_[k] + u_[k];
            target = std::max(std::fabs(pen / n_active_ - h_floor), 1e-300);
        } else {
            for (int k = 0; k < n_; ++k)
                if (!active_[k]) q_[k] = 0.0;
            target = std::max(std::fabs(pen_ - h_floor), 1e-300);
            if (box_) fit_box(conv);
            if (start_product) std::copy(start_product, start_product + n_, u_.begin());
        }
        const bool u_current = fixed_sum || start_product;
        start_product = nullptr; // the first pass's only
        if (!conjugate_gradients(conv, fixed_sum, u_current, target, pass_tolerance,
                                 max_iterations, info))
            break;

        grid_product(conv);
        if (fixed_sum) {
            pen = 0.0;
            for (int k = 0; k < n_; ++k)
                if (active_[k]) pen += h_[k] + u_[k];
            pen_ = pen / n_active_;
        }
        const double depth = std::fabs(pen_ - h_floor);
        double worst = 0.0;
        for (int k = 0; k < n_; ++k)
            if (active_[k]) worst = std::max(worst, std::fabs(h_[k] - pen_ + u_[k]));
        info.residual = worst / std::max(depth, 1e-300);

        // Complementarity: drop tensile elements, add penetrating ones.
        bool changed = false;
        int kept = 0;
        for (int k = 0; k < n_; ++k) {
            if (active_[k] && q_[k] < 0.0) {
                active_[k] = 0;
                q_[k] = 0.0;
                changed = true;
            } else if (!active_[k] && h_[k] - pen_ + u_[k] < -pass_tolerance * depth) {
                active_[k] = 1;
                changed = true;
            }
            kept += active_[k];
        }
        n_active_ = kept;
        if (n_active_ == 0) break; // a positive load keeps one; an approach may lose all
        if (!changed) {
            if (pass_tolerance > tolerance) { // settled: once more at the tolerance
                pass_tolerance = tolerance;
                continue;
            }
            info.converged = true;
            break;
        }
    }
    // With the approach prescribed, an empty set is the solution when every
    // element under tension was dropped and none penetrates.
    if (!fixed_sum && n_active_ == 0 && info.active_set_passes > 0) {
        info.converged = true;
        for (int k = 0; k < n_ && info.converged; ++k)
            info.converged = h_[k] - pen_ >= -tolerance * std::fabs(pen_ - h_floor);
    }
    info.products = products_;
    // A failed solve leaves no start for the next one.
    n_contact_ = 0;
    for (int k = 0; k < n_; ++k) {
        if (!info.converged || q_[k] < 0.0) q_[k] = 0.0;
        n_contact_ += q_[k] > 0.0;
    }
}

} // namespace creepwork

namespace creepwork {

bool NormalProblem::load_derivative(GridConvolution& conv, double tolerance, int max_iterations)
{
    std::fill(dq_.begin(), dq_.end(), 0.0);
    load_by_approach_ = 0.0;
    if (n_contact_ == 0 || n_active_ == 0) return false;
    if (box_) fit_box(conv);
    // Preconditioned conjugate gradients for A_CC z = 1 from z = 0, in dq_
    // (q_, h_, pen_ stay the solution's).
    std::vector<double>& z = dq_;
    auto restrict_to_set = [&](std::vector<double>& v) {
        for (int k = 0; k < n_; ++k)
            if (!active_[k]) v[k] = 0.0;
    };
    auto largest = [&](const std::vector<double>& v) {
        double m = 0.0;
        for (double x : v) m = std::max(m, std::fabs(x));
        return m;
    };
    for (int k = 0; k < n_; ++k) r_[k] = active_[k] ? 1.0 : 0.0;
    set_product(conv, r_, z_, true);
    restrict_to_set(z_);
    p_ = z_;
    double rz = 0.0;
    for (int k = 0; k < n_; ++k) rz += r_[k] * z_[k];
    bool converged = false;
    for (int it = 0; it < max_iterations; ++it) {
        set_product(conv, p_, ap_, false);
        restrict_to_set(ap_);
        double pap = 0.0;
        for (int k = 0; k < n_; ++k) pap += p_[k] * ap_[k];
        if (!(pap > 0.0)) break;
        const double step = rz / pap;
        for (int k = 0; k < n_; ++k) {
            z[k] += step * p_[k];
            r_[k] -= step * ap_[k];
        }
        if (largest(r_) <= tolerance) {
            converged = true;
            break;
        }
        set_product(conv, r_, z_, true);
        restrict_to_set(z_);
        double rz_new = 0.0;
        for (int k = 0; k < n_; ++k) rz_new += r_[k] * z_[k];
        const double beta = rz_new / rz;
        rz = rz_new;
        for (int k = 0; k < n_; ++k) p_[k] = z_[k] + beta * p_[k];
    }
    double sum = 0.0;
    for (int k = 0; k < n_; ++k) sum += z[k];
    if (!converged || !(sum > 0.0)) {
        std::fill(dq_.begin(), dq_.end(), 0.0);
        return false;
    }
    for (int k = 0; k < n_; ++k) z[k] /= sum;
    load_by_approach_ = sum;
    return true;
}

} // namespace creepwork
