#include "sweep_series.hpp"

#include <cmath>

namespace cwcli {

Saturation saturation_creepages(const cw_params& p, const cw_result& r)
{
    const double pi = 3.14159265358979323846;
    const double p0 = p.pressure == CW_PRESSURE_ELLIPTIC ? 1.5 * p.normal_force / (pi * r.a * r.b)
                                                         : 2.0 * p.normal_force / (pi * r.a * r.b);
    const double t = 2.0 * p.mu * p0;
    return {t * r.L1 / r.a, t * r.L2 / r.a, t * r.L3 / (r.a * r.a)};
}

namespace {

SweepCase make(const Saturation& s, double sx, double sy, double sphi)
{
    return {sx, sy, sphi, sx * s.xi_c, sy * s.eta_c, sphi * s.phi_c};
}

} // namespace

std::vector<SweepFigure> paper_sweep_figures(const Saturation& s)
{
    std::vector<SweepFigure> figs;
    // Fig. 2: zero spin, xi_x = xi_y growing until the whole patch slips.
    SweepFigure f2{"fig2", "Fig. 2: zero spin, ξ_x = ξ_y increasing", 2, 4, {}};
    for (double m : {0.02, 0.05, 0.1, 0.2, 0.3, 0.4, 0.55, 0.75}) {
        SweepCase c = make(s, m, m * s.xi_c / s.eta_c, 0.0);
        c.xi_y = c.xi_x; // equal exactly, not just to rounding
        f2.cases.push_back(c);
    }
    figs.push_back(f2);
    // Fig. 3: zero lateral creepage; small spin (top row), large spin (bottom).
    SweepFigure f3{
        "fig3",
        "Fig. 3: zero lateral creepage, ξ_x increasing; small spin (top), large spin (bottom)",
        2,
        4,
        {}};
    for (double spin : {0.1, 2.0})
        for (double m : {0.05, 0.15, 0.35, 0.7}) f3.cases.push_back(make(s, m, 0.0, spin));
    figs.push_back(f3);
    // Fig. 4: zero longitudinal creepage, lateral from negative to positive.
    SweepFigure f4{"fig4",
                   "Fig. 4: zero longitudinal creepage, ξ_y from negative to positive; small spin "
                   "(top), large spin (bottom)",
                   2,
                   5,
                   {}};
    for (double spin : {0.1, 2.0})
        for (double m : {-0.8, -0.4, 0.0, 0.4, 0.8}) f4.cases.push_back(make(s, 0.0, m, spin));
    figs.push_back(f4);
    // Fig. 5: pure spin, increasing.
    SweepFigure f5{"fig5", "Fig. 5: pure spin, increasing", 2, 3, {}};
    for (double spin : {0.1, 0.3, 0.6, 1.5, 3.0, 6.0}) f5.cases.push_back(make(s, 0.0, 0.0, spin));
    figs.push_back(f5);
    return figs;
}

} // namespace cwcli
