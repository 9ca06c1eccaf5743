// Friction memory in the steady-rolling solve, as CONTACT solves it (its
// m_stang.f90, the outer loop of the TANG algorithm; user guide, "friction
// memory"): every element's coefficient is
//   mu_k = theta_k mu_prev,k + (1 - theta_k) mu_s(s_k),
//   theta_k = d_c / (d_c + dt max(s_k, s0)),  dt = dx / V,
// with mu_prev,k the coefficient of the element ahead of it in the rolling
// direction (the static coefficient before the row's first element) and s_k
// its slip speed (0 in adhesion and outside the contact, where the
// coefficient relaxes towards mu_s(0)). Newton's method solves with every
// mu_prev held and each slipping element's mu_k at its own slip speed
// inside the system (local_friction.hpp); mu_prev is then taken again from
// the solution, row by row from the leading edge, until it moves by no more
// than the tolerance (over the static coefficient).
#include "exact/steady_rolling.hpp"

#include <algorithm>
#include <cmath>

namespace creepwork {

namespace {

// Bound on the fixed point's rounds. Each is one Newton solve from the last
// round's traction (a few products); on CONTACT's tractcurv contact they
// take at most a dozen or so (doc/theory/friction.md).
constexpr int kMaxMemoryRounds = 200;

} // namespace

double SteadyRolling::memory_pass()
{
    const double mu_static = static_friction(law_.law);
    double change = 0.0;
    for (int j = 0; j < ny_; ++j) {
        double ahead = mu_static;
        for (int i = nx_ - 1; i >= 0; --i) {
            const int k = i + nx_ * j;
            change = std::max(change, std::fabs(ahead - mu_prev_[k]));
            mu_prev_[k] = ahead;
            law_.mu_prev = ahead;
            const double sigma = state_[k] == 2 ? std::abs(s_[k]) : 0.0;
            mu_[k] = law_.mu_ref * law_.value(sigma).mu;
            ahead = mu_[k];
        }
    }
    return change / mu_static;
}

void SteadyRolling::link_memory(int k, Complex c, Complex qk)
{
    // The element's slip s = c + B0 q (local_friction.hpp) at its solution.
    const Complex s(c.real() + b0x_ * qk.real(), c.imag() + b0y_ * qk.imag());
    const double sigma = std::abs(s);
    const double d_c = law_.memory.distance;
    MemoryLink& l = links_[k];
    l.theta = d_c / (d_c + law_.dt * std::max(law_.kappa * sigma, law_.memory.s0));
    l.sigma = sigma;
    l.e = sigma > 0.0 ? s / sigma : Complex(0.0, 0.0);
    l.dmu_dsigma = law_.mu_ref * law_.value(sigma).dmu_ds;
    l.bound = g_[k] * l.theta / law_.mu_ref;
}

void SteadyRolling::memory_link(int k, double cx, double cy, Complex& d, double& dmu,
                                bool speed) const
{
    // mu_k = theta mu_ahead + (1 - theta) mu_s: at rest (adhesion) theta0
    // alone; in slip the bound g mu_k / mu_ref moves q by u per unit (u of
    // local_friction.hpp), and mu_k moves with sigma = |c + B0 q| too.
    if (state_[k] != 2) {
        dmu *= theta0_;
        return;
    }
    const MemoryLink& l = links_[k];
    d += slip_info_[k].u * (l.bound * dmu);
    const double dsigma =
        l.e.real() * (cx + b0x_ * d.real()) + l.e.imag() * (cy + b0y_ * d.imag());
    dmu = l.theta * dmu + l.dmu_dsigma * (dsigma + (speed ? l.sigma : 0.0));
}

SteadyRollingInfo SteadyRolling::solve_with_memory(GridConvolution& conv, double tolerance,
                                                   int max_steps, bool warm)
{
    // The first round's mu_prev from the first guess's slip (CONTACT's start
    // from the last solution's), itself found with mu_prev static.
    std::fill(mu_prev_.begin(), mu_prev_.end(), static_friction(law_.law));
    products_ = 0;
    project(q_);
    sweep(conv, q_, gq_);
    memory_pass();
    SteadyRollingInfo info;
    int products = products_;
    long local_steps = 0;
    for (;;) {
        const bool close = warm || info.memory_iterations > 0;
        const SteadyRollingInfo round = newton(conv, tolerance, max_steps - info.newton_steps, close);
        ++info.memory_iterations;
        info.newton_steps += round.newton_steps;
        products += round.products;
        local_steps += friction_iterations_;
        info.residual = round.residual;
        if (!round.converged) break;
        // The largest change of mu_prev counts as a residual: the traction
        // was solved with the last round's.
        const double change = memory_pass();
        info.residual = std::max(round.residual, change);
        if (change <= tolerance) {
            // The states, local Jacobians and chain at the traction with
            // the mu_prev just found: a warm solve from this traction
            // linearises at the same point (its Jacobian has these bits).
            const long before = friction_iterations_;
            sweep(conv, q_, gq_);
            ++products;
            local_steps += friction_iterations_ - before;
            info.converged = true;
            break;
        }
        if (info.newton_steps >= max_steps || info.memory_iterations >= kMaxMemoryRounds) break;
    }
    products_ = products;
    friction_iterations_ = local_steps;
    info.products = products;
    memory_iterations_ = info.memory_iterations;
    return info;
}

} // namespace creepwork
