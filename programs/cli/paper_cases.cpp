#include "paper_cases.hpp"

#include <cmath>

#include "cli_error.hpp"
#include "units.hpp"

namespace cwcli {

PaperCase paper_fig6()
{
    return {"Fig. 6", 0.0019,   0.0011, 0.144, 2.0,   0.6,           10000.0,
            2780.880, 3789.320, 2.385,  9.795, 1.602, "partial slip"};
}

PaperCase paper_fig7()
{
    return {"Fig. 7", 0.0,      0.0022, 0.576,  1.8,   0.6,        6345.8,
            0.0,      3255.332, 9.971,  12.905, 1.424, "full slip"};
}

std::vector<Table1Row> paper_table1()
{
    return {{0.050, 0.050, 0.1, 1.001, "full slip", false},
            {0.050, 0.010, 0.1, 1.008, "full slip", false},
            {0.010, 0.010, 0.1, 1.031, "full slip", false},
            {0.100, 0.100, 0.1, 1.003, "full slip", false},
            {0.000, 0.0022, 0.576, 1.424, "full slip", true},
            {0.0019, 0.0011, 0.144, 1.602, "partial slip", false},
            {0.001, 0.001, 0.1, 2.397, "partial slip", false}};
}

cw_params paper_params(const PaperCase& c, double a, const FitChoices& choices)
{
    cw_params p;
    cw_params_init(&p);
    p.a = a;
    p.b = a / c.a_over_b;
    p.normal_force = c.N_lbf * kNewtonPerLbf;
    p.mu = c.mu;
    p.G = choices.G;
    p.nu = choices.nu;
    p.pressure = CW_PRESSURE_PARABOLIC; // paper eq. 16
    p.xi_x = c.xi_x;
    p.xi_y = c.xi_y;
    p.phi = c.spin_per_ft / kMetrePerFoot;
    return p;
}

namespace {

// RMS of the differences to the printed forces, in lbf; the library's
// forces act on the wheel, the paper's on the rail.
double force_misfit(const PaperCase& c, const cw_result& r)
{
    const double dx = -r.Fx / kNewtonPerLbf - c.Fx_lbf;
    const double dy = -r.Fy / kNewtonPerLbf - c.Fy_lbf;
    return std::sqrt(0.5 * (dx * dx + dy * dy));
}

} // namespace

SemiAxisFit fit_semi_axis(const PaperCase& c, ContactSolver& solver, const FitChoices& choices)
{
    const auto misfit = [&](double a) {
        return force_misfit(c, solver.solve_totals(paper_params(c, a, choices)));
    };
    // 1 mm .. 40 mm spans every plausible wheel-rail contact; 400 samples
    // (1 % apart) resolve the separate branches.
    const std::vector<Minimum> minima = local_minima(misfit, 1e-3, 40e-3, 400, 1e-10);
    if (minima.empty())
        throw CliError(kExitFailure,
                       c.name + ": no local minimum of the force misfit in a = 1..40 mm");

    SemiAxisFit fit;
    const double force = std::hypot(c.Fx_lbf, c.Fy_lbf);
    double best_mz = INFINITY, best_rms = INFINITY;
    size_t best_any = 0;
    for (const Minimum& m : minima) {
        const cw_result r = solver.solve_totals(paper_params(c, m.x, choices));
        fit.candidates.push_back({m.x, m.f, r});
        const size_t k = fit.candidates.size() - 1;
        const double mz_error = std::fabs(-r.Mz / (kNewtonPerLbf * kMetrePerFoot) - c.Mz_lbf_ft);
        if (m.f < 0.01 * force && mz_error < best_mz) {
            best_mz = mz_error;
            fit.chosen = k;
        }
        if (m.f < best_rms) {
            best_rms = m.f;
            best_any = k;
        }
    }
    if (!std::isfinite(best_mz)) fit.chosen = best_any; // nothing reproduces the forces well
    return fit;
}

} // namespace cwcli
