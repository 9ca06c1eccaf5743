// FASTSIM with a law of the slip speed at every element (FastsimLawModel):
// Coulomb's law gives FASTSIM's forces; a falling law in full sliding gives
// the closed form mu(xi V) N; a vanishing rolling speed gives Coulomb's
// forces at the static coefficient; bad inputs are named.
#include "contact_friction_formula.hpp"
#include "core_test_support.hpp"
#include "law_residual.hpp"
#include "tractcurv_contact.hpp"
#include "test_support.h"

#include "contact/error.hpp"
#include "fastsim/fastsim_law_model.hpp"
#include "fastsim/fastsim_model.hpp"
#include "friction/slip_speed_law.hpp"
#include "solver.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace cw = creepwork;

namespace {

using cwtest::tractcurv_grid;

cw::ContactInput eurosprinter(double xi_x, double xi_y = 0.0, double phi = 0.0)
{
    return cwtest::tractcurv_contact(xi_x, xi_y, phi);
}

// Coulomb's law through the law's march: FASTSIM's forces and slip counts,
// with creepage and spin, on both grids, both rolling directions.
void coulomb_law_is_fastsim(void**)
{
    for (const cw::GridSpec& g : {tractcurv_grid(), cwtest::kalker_grid(30, 25)}) {
        cw::FastsimModel plain(g);
        cw::FastsimLawModel law(g);
        law.set_law(cw::coulomb_law(0.33), 10.0);
        for (double xi : {1e-5, 1e-3, 4e-3, 0.05}) {
            cw::ContactInput in = eurosprinter(xi, -0.5 * xi, 2.0 * xi);
            in.mu = 0.33;
            in.rolling_direction = xi > 1e-3 ? -1 : 1;
            const cw::SolveTotals a = plain.solve(in, cw::SolveMode::forces_only);
            const cw::SolveTotals b = law.solve(in, cw::SolveMode::forces_only);
            assert_close(b.Fx, a.Fx, 1e-13, 0.0);
            assert_close(b.Fy, a.Fy, 1e-13, 0.0);
            assert_close(b.Mz, a.Mz, 1e-13, 1e-16);
            assert_int_equal(b.n_slip, a.n_slip);
        }
    }
}

// Polach's mu0 = 0.36, A = 0.38, B = 0.7 s/m at V = 10 m/s: in full sliding
// every element slides at nearly xi V, so |Fx|/(mu_s N) -> A + (1 - A)
// exp(-B xi V), within 2e-4 from xi = 10 % on.
void full_sliding_closed_form(void**)
{
    cw::FastsimLawModel m(tractcurv_grid());
    m.set_law(cw::polach_law(0.36, 0.38, 0.7), 10.0);
    for (double xi : {0.10, 0.15, 0.25, 0.5}) {
        const cw::SolveTotals t = m.solve(eurosprinter(xi), cw::SolveMode::forces_only);
        assert_int_equal(t.n_slip, t.n_contact);
        const double closed = 0.38 + 0.62 * std::exp(-0.7 * xi * 10.0);
        assert_close(-t.Fx / (0.36 * 106.7e3), closed, 0.0, 2e-4);
        assert_true(m.mu_min() < m.mu_max() && m.mu_max() < 0.36);
    }
}

// Every form of the law, two terms each (mu_kin 0.14, mu_e1 0.19 at
// 1.25 m/s, mu_e2 0.05 at 0.3 m/s): in full sliding at 10 and 15 % (1 and
// 1.5 m/s, short of the linear law's kink at 2.5 m/s) |Fx|/(mu_s N) ->
// mu(xi V)/mu_s within 2e-4, mu from CONTACT's formula.
void every_form_in_full_sliding(void**)
{
    cw::FastsimLawModel m(tractcurv_grid());
    for (const auto kind : {cw::SlipSpeedLawKind::linear, cw::SlipSpeedLawKind::rational,
                            cw::SlipSpeedLawKind::exponential}) {
        cw::SlipSpeedLaw law;
        law.kind = kind;
        law.mu_kin = 0.14;
        law.mu_e1 = 0.19;
        law.s_h1 = 1.25;
        law.mu_e2 = 0.05;
        law.s_h2 = 0.3;
        m.set_law(law, 10.0);
        for (double xi : {0.10, 0.15}) {
            const cw::SolveTotals t = m.solve(eurosprinter(xi), cw::SolveMode::forces_only);
            assert_int_equal(t.n_slip, t.n_contact);
            // CONTACT's formula in its mm/s (contact_friction_formula.hpp).
            const double mu = cwtest::contact_mu_steady(int(kind), 0.14, 0.19, 1250.0, 0.05,
                                                        300.0, 1e4 * xi);
            assert_close(-t.Fx / 106.7e3, mu, 0.0, 2e-4 * (0.14 + 0.19 + 0.05));
        }
    }
}

// Every slipping element meets its law, |p| = p_z mu(V |s|) with the
// element's exported micro-slip s and mu from CONTACT's formula
// (law_residual.hpp): within 1e-12 of p_z mu_s,
// where the march's Halley step stops (fastsim/march_law.hpp), over the
// creepage range from the first slip to full sliding, with lateral creepage
// and spin, Polach's law and every form with two terms (mu_kin 0.14,
// mu_e1 0.19 at 1.25 m/s, mu_e2 0.05 at 0.3 m/s), on the tractcurv grid and
// Kalker's 40 x 40 strips.
void every_element_meets_its_law(void**)
{
    double worst = 0.0;
    long checked = 0;
    for (const cw::GridSpec& g : {tractcurv_grid(), cwtest::kalker_grid(40, 40)}) {
        cw::Solver s(g);
        for (int form = 0; form < 4; ++form)
            for (double xi : {5e-4, 1e-3, 2e-3, 4e-3, 1e-2, 2e-2, 5e-2, 0.1, 0.3})
                for (double lateral : {0.0, 1.0}) {
                    cw::ContactInput in =
                        eurosprinter(xi, 0.3 * lateral * xi, 0.2 * lateral * xi / 6.304e-3);
                    in.V = 10.0;
                    if (form == 0) { // Polach's mu0 = 0.36, A = 0.38, B = 0.7 s/m
                        in.friction_law = cw::FrictionLaw::exponential;
                        in.mu = 0.36 * 0.38;
                        in.mu_e1 = 0.36 * 0.62;
                        in.s_h1 = std::log(2.0) / 0.7;
                    } else {
                        in.friction_law = form == 1   ? cw::FrictionLaw::linear
                                          : form == 2 ? cw::FrictionLaw::rational
                                                      : cw::FrictionLaw::exponential;
                        in.mu = 0.14;
                        in.mu_e1 = 0.19;
                        in.s_h1 = 1.25;
                        in.mu_e2 = 0.05;
                        in.s_h2 = 0.3;
                    }
                    s.solve(in, cw::SolveMode::full);
                    worst = std::max(worst, cwtest::worst_law_residual(s, in, checked));
                }
    }
    print_message("%ld slipping elements: worst |p - p_z mu(s)| / (p_z mu_s) %.3g\n", checked,
                  worst);
    assert_true(checked > 100000);
    assert_true(worst <= 1e-12);
}

// Full mode under a law (the law at every element, friction memory): the
// work map sums to W_macro within 1e-12 relative, is >= 0 everywhere and
// exactly 0 in adhesion and outside the contact (the march's energy
// identity, march_work.hpp), before and past the peak, with lateral
// creepage and spin; the forces are forces mode's, bitwise.
void work_map_under_the_law(void**)
{
    cw::Solver s(tractcurv_grid());
    for (double memory : {0.0, 3e-6})
        for (double xi : {0.002, 0.004, 0.02, 0.1})
            for (double lateral : {0.0, 1.0}) {
                cw::ContactInput in =
                    eurosprinter(xi, 0.3 * lateral * xi, 0.2 * lateral * xi / 6.304e-3);
                in.mu = 0.36 * 0.38; // Polach's mu0 = 0.36, A = 0.38, B = 0.7 s/m
                in.friction_law = cw::FrictionLaw::exponential;
                in.mu_e1 = 0.36 * 0.62;
                in.s_h1 = std::log(2.0) / 0.7;
                in.V = 10.0;
                in.memory_distance = memory;
                in.memory_s0 = 1e-3;
                const cw::SolveTotals forces = s.solve(in, cw::SolveMode::forces_only);
                const cw::SolveTotals t = s.solve(in, cw::SolveMode::full);
                assert_true(t.Fx == forces.Fx && t.Fy == forces.Fy && t.Mz == forces.Mz);
                assert_true(t.W_macro > 0.0 && t.n_slip > 0);
                const std::vector<double> w = cwtest::field(s, cw::Field::work_consistent);
                const std::vector<int> state = cwtest::states(s);
                double sum = 0.0;
                for (size_t k = 0; k < w.size(); ++k) {
                    assert_true(w[k] >= 0.0);
                    if (state[k] != 2) assert_true(w[k] == 0.0);
                    sum += w[k];
                }
                assert_close(sum, t.W_macro, 1e-12, 0.0);
                assert_close(t.W_consistent, t.W_macro, 1e-12, 0.0);
            }
}

// Friction memory (d_c, s0): a vanishing distance is the law without it, a
// huge one keeps every element at mu_s (Coulomb's FASTSIM at mu_s); between,
// tractcurv's 3 um and 1 mm/s lifts the force above the law's, below
// Coulomb's. No Jacobian with memory.
void memory_limits(void**)
{
    cw::FastsimModel plain(tractcurv_grid());
    cw::FastsimLawModel m(tractcurv_grid()), none(tractcurv_grid());
    const cw::SlipSpeedLaw law = cw::polach_law(0.36, 0.38, 0.7);
    m.set_law(law, 10.0);
    none.set_law(law, 10.0);
    for (double xi : {0.002, 0.01, 0.1}) {
        cw::ContactInput in = eurosprinter(xi, 0.2 * xi);
        in.mu = 0.36;
        const cw::SolveTotals coulomb = plain.solve(in, cw::SolveMode::forces_only);
        const cw::SolveTotals without = none.solve(in, cw::SolveMode::forces_only);
        m.set_memory({1e-15, 1e-3});
        const cw::SolveTotals tiny = m.solve(in, cw::SolveMode::forces_only);
        assert_close(tiny.Fx, without.Fx, 1e-9, 0.0);
        assert_close(tiny.Fy, without.Fy, 1e-9, 0.0);
        m.set_memory({1e6, 1e-3});
        const cw::SolveTotals huge = m.solve(in, cw::SolveMode::forces_only);
        assert_close(huge.Fx, coulomb.Fx, 1e-9, 0.0);
        assert_close(huge.Fy, coulomb.Fy, 1e-9, 0.0);
        m.set_memory({3e-6, 1e-3});
        const cw::SolveTotals some = m.solve(in, cw::SolveMode::forces_only);
        assert_true(-some.Fx > -without.Fx && -some.Fx < -coulomb.Fx);
    }
    cw::Jacobian J;
    try {
        m.solve_jacobian(eurosprinter(0.01), cw::SolveMode::forces_only, J);
        fail_msg("memory's Jacobian given");
    } catch (const cw::Error& e) {
        assert_true(std::string(e.what()).rfind("memory_distance", 0) == 0);
    }
    try {
        m.set_memory({-1.0, 0.0});
        fail_msg("negative memory distance accepted");
    } catch (const cw::Error& e) {
        assert_true(std::string(e.what()).rfind("memory_distance", 0) == 0);
    }
}

// V -> 0: every slip speed is ~0, mu = mu_s: Coulomb's forces at 0.36.
void slow_rolling_is_coulomb(void**)
{
    cw::FastsimModel plain(tractcurv_grid());
    cw::FastsimLawModel law(tractcurv_grid());
    law.set_law(cw::polach_law(0.36, 0.38, 0.7), 1e-12);
    cw::ContactInput in = eurosprinter(2e-3, 1e-3);
    in.mu = 0.36;
    const cw::SolveTotals a = plain.solve(in, cw::SolveMode::forces_only);
    const cw::SolveTotals b = law.solve(in, cw::SolveMode::forces_only);
    assert_close(b.Fx, a.Fx, 1e-10, 0.0);
    assert_close(b.Fy, a.Fy, 1e-10, 0.0);
}

// A falling law lowers the force below Coulomb's at mu_s in partial slip,
// and the curve falls past its peak.
void falling_law_peaks(void**)
{
    cw::FastsimLawModel m(tractcurv_grid());
    m.set_law(cw::polach_law(0.36, 0.38, 0.7), 10.0);
    cw::FastsimModel plain(tractcurv_grid());
    double previous = 0.0, peak = 0.0;
    bool fell = false;
    for (double xi = 0.001; xi < 0.1; xi *= 1.3) {
        cw::ContactInput in = eurosprinter(xi);
        in.mu = 0.36;
        const double f = -m.solve(in, cw::SolveMode::forces_only).Fx;
        assert_true(f <= -plain.solve(in, cw::SolveMode::forces_only).Fx);
        peak = std::max(peak, f);
        fell = fell || f < previous;
        previous = f;
    }
    assert_true(fell && peak < 0.36 * 106.7e3);
}

void inputs_named(void**)
{
    cw::FastsimLawModel m(tractcurv_grid());
    const auto expect = [&](auto&& call, const char* name) {
        try {
            call();
            fail_msg("accepted, expected an error naming %s", name);
        } catch (const cw::Error& e) {
            assert_true(std::string(e.what()).rfind(name, 0) == 0);
        }
    };
    expect([&] { m.solve(eurosprinter(1e-3), cw::SolveMode::forces_only); }, "V");
    expect([&] { m.set_law(cw::coulomb_law(0.3), 0.0); }, "V");
    expect([&] { m.set_law(cw::coulomb_law(0.3), NAN); }, "V");
    cw::SlipSpeedLaw bad = cw::polach_law(0.36, 0.38, 0.7);
    bad.s_h1 = -1.0;
    expect([&] { m.set_law(bad, 10.0); }, "s_h1");
}

// The Jacobian of Fx, Fy, Mz by xi_x, xi_y, phi, N against central
// differences of the model itself, before the peak (0.4 %) and past it
// (2 %, where dFx/dxi_x has changed sign), alone and with lateral creepage
// and spin (rolling towards -x at 2 %): the
// worst entry, relative to its row's scale sum_c |J_rc| scale_c, over the
// best of four steps that change no element's state, within 1e-4.
double jacobian_error(cw::FastsimLawModel& m, const cw::ContactInput& in, const cw::Jacobian& J,
                      int slips)
{
    const double scale[4] = {std::fabs(in.xi_x), std::fabs(in.xi_x), std::fabs(in.xi_x) / in.a,
                             in.normal_force};
    double best = INFINITY;
    for (double rel : {1e-3, 1e-4, 1e-5, 1e-6}) {
        double worst = 0.0;
        bool changed = false;
        double fd[3][4];
        for (int c = 0; c < 4; ++c) {
            cw::ContactInput up = in, down = in;
            double* u[4] = {&up.xi_x, &up.xi_y, &up.phi, &up.normal_force};
            double* d[4] = {&down.xi_x, &down.xi_y, &down.phi, &down.normal_force};
            *u[c] += rel * scale[c];
            *d[c] -= rel * scale[c];
            const cw::SolveTotals a = m.solve(up, cw::SolveMode::forces_only);
            const cw::SolveTotals b = m.solve(down, cw::SolveMode::forces_only);
            changed |= a.n_slip != slips || b.n_slip != slips;
            const double h2 = 2 * rel * scale[c];
            fd[0][c] = (a.Fx - b.Fx) / h2;
            fd[1][c] = (a.Fy - b.Fy) / h2;
            fd[2][c] = (a.Mz - b.Mz) / h2;
        }
        for (int r = 0; r < 3; ++r) {
            double row = 0.0;
            for (int c = 0; c < 4; ++c) row += std::fabs(J.d[r][c]) * scale[c];
            for (int c = 0; c < 4; ++c)
                worst = std::max(worst, std::fabs(J.d[r][c] - fd[r][c]) * scale[c] / row);
        }
        if (!changed) best = std::min(best, worst);
    }
    return best;
}

void jacobian_across_the_peak(void**)
{
    cw::FastsimLawModel m(tractcurv_grid());
    m.set_law(cw::polach_law(0.36, 0.38, 0.7), 10.0);
    for (double xi : {0.004, 0.02})
        for (double lateral : {0.0, 1.0}) {
            cw::ContactInput in =
                eurosprinter(xi, 0.3 * lateral * xi, 0.2 * lateral * xi / 6.304e-3);
            in.rolling_direction = lateral > 0.0 && xi > 0.01 ? -1 : 1;
            cw::Jacobian J;
            const cw::SolveTotals t = m.solve_jacobian(in, cw::SolveMode::forces_only, J);
            const cw::SolveTotals plain = m.solve(in, cw::SolveMode::forces_only);
            assert_true(t.Fx == plain.Fx && t.Fy == plain.Fy && t.Mz == plain.Mz);
            const double err = jacobian_error(m, in, J, t.n_slip);
            print_message("xi_x %.3f (%s): dFx/dxi_x %.6g N, worst relative error %.2e\n", xi,
                          lateral > 0 ? "with xi_y, phi" : "alone", J.d[0][0], err);
            assert_true(err <= 1e-4);
            // Pure rolling creepage: the force on the wheel opposes it, so
            // dFx/dxi_x < 0 before the peak (about 0.5 % here) and > 0 past
            // it, where |Fx| falls.
            if (lateral == 0.0) assert_true(xi < 0.01 ? J.d[0][0] < 0.0 : J.d[0][0] > 0.0);
        }
}
} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(coulomb_law_is_fastsim),
        cmocka_unit_test(full_sliding_closed_form),
        cmocka_unit_test(every_form_in_full_sliding),
        cmocka_unit_test(slow_rolling_is_coulomb),
        cmocka_unit_test(memory_limits),
        cmocka_unit_test(work_map_under_the_law),
        cmocka_unit_test(every_element_meets_its_law),
        cmocka_unit_test(falling_law_peaks),
        cmocka_unit_test(inputs_named),
        cmocka_unit_test(jacobian_across_the_peak),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
