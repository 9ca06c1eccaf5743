// What both exact models (the ellipse's, exact_model.hpp, and any gap's,
// gap/gap_exact_model.hpp) share of their tangential problem: a hierarchy of
// grids over the same box, each about half the elements of the next finer
// one per direction while both directions keep kMinCoarseCells, and the one
// way a solve's tangential problem starts:
//  - no load or no friction: the contact slides with the rigid slip
//    (SteadyRolling::slide_freely);
//  - no creepage: zero traction, confirmed by one sweep;
//  - warm: from the last solution as the model predicts it; retried cold
//    when it does not converge;
//  - cold: the coarsest grid from a march of Kalker's simplified theory,
//    each finer one from the one below it, interpolated.
// Every solve ends with a result within the tolerance, or with
// Error(not_converged). The models differ in their grids' geometry, bounds
// and first guesses, which they give as the Steps of solve_tangential.
// Their Jacobians share the rigid slip's derivatives and the moments of the
// tractions' (creepage_tangent, traction_moments).
#pragma once

#include <algorithm>
#include <complex>
#include <vector>

#include "exact/steady_rolling.hpp"
#include "halfspace/grid_convolution.hpp"

namespace creepwork {

constexpr int kKrylovDimension = 40;
// Coarse grids: each about half the elements of the next finer one per
// direction, while both directions keep at least this many.
constexpr int kMinCoarseCells = 10;
// Coarse grids only give the next one a start (where the slip zone lies):
// solved this far. Measured on the benchmark contact: 1e-1 needs fewer FFT
// products in all than 1e-2 ... 1e-6 (72 against 80 ... 114 at N = 40).
constexpr double kCoarseTolerance = 1e-1;
// GMRES iterations per derivative of the Jacobians (each one FFT product);
// the linear systems are those of a Newton step near convergence, which
// take 10-40.
constexpr int kMaxJacobianIterations = 2000;

// The next coarser grid of nx x ny (about half per direction); false, with
// nx and ny unchanged, when either would fall below kMinCoarseCells.
inline bool coarser(int& nx, int& ny)
{
    if (!((nx + 1) / 2 >= kMinCoarseCells && (ny + 1) / 2 >= kMinCoarseCells)) return false;
    nx = (nx + 1) / 2;
    ny = (ny + 1) / 2;
    return true;
}

// One grid of the hierarchy: its products and its steady-rolling solver.
struct TangentialLevel {
    TangentialLevel(int nx_, int ny_, ConvolutionUse use)
        : nx(nx_), ny(ny_), conv(nx_, ny_, use), tangential(nx_, ny_, kKrylovDimension)
    {
    }
    int nx, ny;
    GridConvolution conv;
    SteadyRolling tangential;
};

// What the tangential solve did (the exact models' diagnostics).
struct TangentialInfo {
    int levels_used = 0;  // grids solved (1 for a warm start)
    int newton_steps = 0; // on the finest grid
    int products = 0;     // FFT products, all grids (each ~ the cost of one)
    bool warm = false;    // started from the last solution
    bool retried_cold = false;
    // Under a law of the slip speed (exact_law.hpp): the local equations'
    // Newton steps (every sweep of every grid solved), their mean per
    // slipping element in the final sweep, and the coefficient's range over
    // the slipping elements (mu(0) when none slips).
    long friction_iterations = 0;
    double friction_steps_per_element = 0;
    double mu_min = 0, mu_max = 0;
    // Under friction memory: the fine grid's rounds of the fixed point on
    // mu_prev (exact/steady_memory.cpp).
    int memory_iterations = 0;
};

enum class TangentialStart { slide, zero_creepage, warm, cold };

// trivial: no load or no friction; rolling_freely: no creepage; warm: a warm
// solve after a successful one.
inline TangentialStart tangential_start(bool trivial, bool rolling_freely, bool warm)
{
    if (trivial) return TangentialStart::slide;
    if (rolling_freely) return TangentialStart::zero_creepage;
    return warm ? TangentialStart::warm : TangentialStart::cold;
}

// The normalised rigid slip (xi, eta, phi) scaled down together when its
// largest part max(|xi|, |eta|, |phi| reach) exceeds 1e100 (slip_scale, the
// unit of the normalised slip, grows as much): beyond it every element
// slides. Throws Error(invalid_input) when it overflows.
void limit_rigid_slip(double& xi, double& eta, double& phi, double reach, double& slip_scale);

// The tangential problem on level 0 (its bound and rigid slip set) from the
// start given. Steps, the model's: TangentialLevel& level(int l);
// prepare(l): coarse level l's size, coefficients, bound and rigid slip;
// first_guess(l): the coarsest level's start; interpolate(l): level l's
// start from level l + 1; predict(): level 0's warm start. Throws
// Error(not_converged).
template <class Steps>
SteadyRollingInfo solve_tangential(Steps& steps, int n_levels, TangentialStart start,
                                   double tolerance, int max_steps, TangentialInfo& info)
{
    TangentialLevel& fine = steps.level(0);
    SteadyRollingInfo ti;
    auto cold = [&] {
        const int coarsest = n_levels - 1;
        for (int l = coarsest; l >= 0; --l) {
            TangentialLevel& L = steps.level(l);
            if (l > 0) steps.prepare(l);
            if (l == coarsest)
                steps.first_guess(l);
            else
                steps.interpolate(l);
            ti = L.tangential.solve(L.conv, l == 0 ? tolerance : std::max(tolerance,
                                                                           kCoarseTolerance),
                                    max_steps);
            info.products += ti.products;
            ++info.levels_used;
        }
    };
    switch (start) {
    case TangentialStart::slide:
        fine.tangential.slide_freely(fine.tangential.bound());
        ti.converged = true;
        info.levels_used = 1;
        break;
    case TangentialStart::zero_creepage:
        std::fill(fine.tangential.traction().begin(), fine.tangential.traction().end(), 0.0);
        ti = fine.tangential.solve(fine.conv, tolerance, max_steps); // one sweep
        info.products += ti.products;
        info.levels_used = 1;
        break;
    case TangentialStart::warm:
        info.warm = true;
        steps.predict();
        ti = fine.tangential.solve(fine.conv, tolerance, max_steps, true);
        info.products += ti.products;
        info.levels_used = 1;
        if (!ti.converged) {
            info.retried_cold = true;
            cold();
        }
        break;
    case TangentialStart::cold: cold(); break;
    }
    info.newton_steps = ti.newton_steps;
    require_converged(ti, tolerance);
    return ti;
}

// Kalker's simplified theory as a first guess on a level: each row marched
// from its leading edge (i = nx - 1), q += -dx w / (L G) per element with
// l1, l2, l3 = dx / (L1 G), dx / (L2 G), dx / (L3 G) and the rigid slip
// w = (xi - phi y, eta + phi x) at element (x(i), y(j)), clipped to the
// bound; an element outside the contact (bound 0) restarts the march.
template <class X, class Y>
void simplified_march(TangentialLevel& L, double l1, double l2, double l3, double xi,
                      double eta, double phi, X x, Y y)
{
    using Complex = SteadyRolling::Complex;
    const std::vector<double>& g = L.tangential.bound();
    std::vector<Complex>& q = L.tangential.traction();
    for (int j = 0; j < L.ny; ++j) {
        const double yj = y(j);
        Complex prev(0.0, 0.0);
        for (int i = L.nx - 1; i >= 0; --i) {
            const int k = i + L.nx * j;
            if (!(g[k] > 0.0)) {
                q[k] = prev = 0.0;
                continue;
            }
            Complex next = prev - Complex(l1 * xi - l3 * phi * yj, l2 * eta + l3 * phi * x(i));
            const double m = std::abs(next);
            if (m > g[k]) next *= g[k] / m;
            q[k] = prev = next;
        }
    }
}

// The coarse level's traction interpolated bilinearly at fractional element
// positions of it, (tx(i), ty(j)) in coarse elements, for each fine element
// (i, j) (clamped at the coarse grid's edges), into the fine level's.
template <class TX, class TY>
void interpolate_traction(const TangentialLevel& C, TangentialLevel& F, TX tx, TY ty)
{
    const std::vector<SteadyRolling::Complex>& qc = C.tangential.traction();
    std::vector<SteadyRolling::Complex>& qf = F.tangential.traction();
    for (int j = 0; j < F.ny; ++j) {
        const double tj = ty(j);
        const int j0 = static_cast<int>(std::floor(tj));
        const double fy = tj - j0;
        for (int i = 0; i < F.nx; ++i) {
            const double ti = tx(i);
            const int i0 = static_cast<int>(std::floor(ti));
            const double fx = ti - i0;
            SteadyRolling::Complex v(0.0, 0.0);
            for (int dj = 0; dj < 2; ++dj)
                for (int di = 0; di < 2; ++di) {
                    const int ii = std::min(std::max(i0 + di, 0), C.nx - 1);
                    const int jj = std::min(std::max(j0 + dj, 0), C.ny - 1);
                    v += (di ? fx : 1.0 - fx) * (dj ? fy : 1.0 - fy) * qc[ii + C.nx * jj];
                }
            qf[i + F.nx * j] = v;
        }
    }
}

// The rigid slip's derivative by the normalised creepage k (0: xi, 1: eta,
// 2: phi) at element (x(i), y(j)) of an nx x ny grid, [i + nx j]: (1, 0),
// (0, 1), or (-y, x + offset) with the spin centre's offset along x.
template <class X, class Y>
void creepage_tangent(std::vector<SteadyRolling::Complex>& w, int nx, int ny, int k, X x, Y y,
                      double offset)
{
    using Complex = SteadyRolling::Complex;
    for (int j = 0; j < ny; ++j) {
        const double yj = y(j);
        for (int i = 0; i < nx; ++i)
            w[i + static_cast<size_t>(nx) * j] = k == 0   ? Complex(1.0, 0.0)
                                                 : k == 1 ? Complex(0.0, 1.0)
                                                          : Complex(-yj, x(i) + offset);
    }
}

// The moments of a traction field dq on an nx x ny grid [i + nx j] with
// element centres (x(i), y(j)): sum dq_x, sum dq_y and sum (x dq_y - y dq_x),
// summed in the layout's order.
struct TractionMoments {
    double x = 0, y = 0, z = 0;
};
template <class X, class Y>
TractionMoments traction_moments(const std::vector<SteadyRolling::Complex>& dq, int nx, int ny,
                                 X x, Y y)
{
    TractionMoments m;
    for (int j = 0; j < ny; ++j) {
        const double yj = y(j);
        for (int i = 0; i < nx; ++i) {
            const SteadyRolling::Complex v = dq[i + static_cast<size_t>(nx) * j];
            const double xi = x(i);
            m.x += v.real();
            m.y += v.imag();
            m.z += xi * v.imag() - yj * v.real();
        }
    }
    return m;
}

} // namespace creepwork
