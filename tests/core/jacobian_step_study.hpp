// A Jacobian against central differences of the solver itself, with a step
// study: at each step (rel times each input's scale) the worst entry error,
// relative to its row's scale sum_c |J[r][c]| scale_c; truncation falls as
// h^2 and roundoff rises as eps/h, so the best step is what the derivative
// is worth. Steps that change some element's state (adhesion/slip) cross a
// kink and are marked, not counted. Shared by the FASTSIM, calibrated and
// exact Jacobian tests.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "contact/jacobian.hpp"
#include "contact/params.hpp"
#include "solver.hpp"

namespace cwtest {

using Totals4 = std::array<double, 4>;

// Fx, Fy, Mz, W_macro of a forces-only solve, and its slip count.
inline Totals4 forces_only_totals(creepwork::Solver& s, const creepwork::ContactInput& in,
                                  int& slips)
{
    const creepwork::SolveTotals& t = s.solve(in, creepwork::SolveMode::forces_only);
    slips = t.n_slip;
    return {t.Fx, t.Fy, t.Mz, t.W_macro};
}

// The input of Jacobian column c: xi_x, xi_y, phi, N.
inline double& jacobian_input(creepwork::ContactInput& in, int c)
{
    switch (c) {
    case 0: return in.xi_x;
    case 1: return in.xi_y;
    case 2: return in.phi;
    default: return in.normal_force;
    }
}

// Worst error of J at step rel; changed: some element's state differs from
// slips (the solution's slip count) at one of the steps.
inline double central_difference_error(creepwork::Solver& s, const creepwork::ContactInput& in,
                                       const creepwork::Jacobian& J,
                                       const std::array<double, 4>& scale, double rel,
                                       int slips, bool& changed)
{
    double worst = 0.0;
    changed = false;
    for (int c = 0; c < 4; ++c) {
        const double h = rel * scale[c];
        creepwork::ContactInput up = in, down = in;
        jacobian_input(up, c) += h;
        jacobian_input(down, c) -= h;
        int su = 0, sd = 0;
        const Totals4 fu = forces_only_totals(s, up, su), fd = forces_only_totals(s, down, sd);
        changed |= su != slips || sd != slips;
        for (int r = 0; r < 4; ++r) {
            double row = 0.0;
            for (int k = 0; k < 4; ++k) row += std::fabs(J.d[r][k]) * scale[k];
            const double fdiff = (fu[r] - fd[r]) / (2.0 * h);
            worst = std::max(worst, std::fabs(fdiff - J.d[r][c]) * scale[c] / row);
        }
    }
    return worst;
}

// Errors for rel = rel_first, rel_first/10, ... down to rel_last, printed on
// one line after label; returns the best among steps that changed no state.
inline double jacobian_step_study(const char* label, int label_width, creepwork::Solver& s,
                                  const creepwork::ContactInput& in, const creepwork::Jacobian& J,
                                  const std::array<double, 4>& scale, int slips,
                                  double rel_first, double rel_last)
{
    std::printf("  %-*s", label_width, label);
    double best = 1e300;
    for (double rel = rel_first; rel >= 0.5 * rel_last; rel /= 10) {
        bool changed = false;
        const double e = central_difference_error(s, in, J, scale, rel, slips, changed);
        std::printf(" %8.1e%s", e, changed ? "*" : " ");
        if (!changed) best = std::min(best, e);
    }
    std::printf("  best %.1e\n", best);
    return best;
}

} // namespace cwtest
