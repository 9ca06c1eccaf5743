// The exact model under a friction law of the slip speed
// (ExactModel::set_law: mu(s) at each element's own slip speed, inside the
// Newton system) against independent numbers:
//  - CONTACT's exact theory on its tractcurv grid (48 x 44): series 1 of
//    examples/tractcurv.ref_out (Coulomb 0.33) and CONTACT's runs of the
//    same contact with the exponential law alone
//    (tests/data/contact_tractcurv_exponential.csv, its input beside it):
//    every printed digit of Fx, Fy / (mu_s N) and Mz;
//  - the law written as Coulomb's (a constant coefficient through the
//    law's path) against the Coulomb model;
//  - the full-sliding limit mu_kin + mu_e1 exp(-ln2 xi V / s_h1);
//  - the Jacobian against central differences of the solver on both sides
//    of the adhesion peak, and the work map's energy balance.
#include "core_test_support.hpp"
#include "tractcurv_exact.hpp"
#include "test_support.h"
#include "error_naming.hpp"

#include "contact/error.hpp"
#include "exact/exact_model.hpp"
#include "friction/slip_speed_law.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace cw = creepwork;

namespace {

using cwtest::expect_error_naming;

const double kN = cwtest::kTractcurvN, kV = cwtest::kTractcurvV;
using cwtest::tractcurv_exact;
cw::SlipSpeedLaw exponential_law() { return cwtest::tractcurv_exponential_law(); }

// |ours - printed| against half a unit of the last printed digit; returns
// the worst ratio (<= 1: every digit).
double digits_ratio(double ours, const std::string& printed)
{
    return std::fabs(ours - std::stod(printed)) / cwtest::printed_half_digit(printed);
}

void series1_coulomb(void**)
{
    const cwtest::CsvTable t = cwtest::read_csv(cwtest::test_data_path("contact_tractcurv.csv"));
    cw::ExactModel m(cwtest::tractcurv_grid());
    double worst = 0.0;
    int rows = 0;
    for (size_t r = 0; r < t.rows.size(); ++r) {
        if (t.number(r, "series") != 1) continue;
        const cw::SolveTotals tot = m.solve(tractcurv_exact(t.number(r, "CKSI")), cw::SolveMode::forces_only);
        worst = std::max(worst, digits_ratio(tot.Fx / (0.33 * kN), t.text(r, "FX_over_FSTAT_FN")));
        assert_int_equal(tot.n_contact, int(t.number(r, "NCON")));
        assert_true(std::abs(tot.n_slip - int(t.number(r, "NSLIP"))) <= 2);
        ++rows;
    }
    printf("  series 1 (Coulomb): worst |Fx/(mu N) - CONTACT| = %.3f of half a printed digit\n", worst);
    assert_int_equal(rows, 30);
    // Two units of the last digit (measured 1.8 at 1e-5): tractcurv runs
    // CONTACT at EPS 1e-6 (creepwork 1e-8) and from A1 and a/b, not from the
    // semi-axes it prints to 4 digits (the rows of the exponential law below,
    // run at EPS 1e-10 from those semi-axes, meet every digit).
    assert_true(worst <= 4.0);
}

void exponential_law_rows(void**)
{
    const cwtest::CsvTable t =
        cwtest::read_csv(cwtest::test_data_path("contact_tractcurv_exponential.csv"));
    cw::ExactModel m(cwtest::tractcurv_grid());
    m.set_law(exponential_law(), kV);
    const double mu_s = 0.33;
    double worst = 0.0;
    double local = 0.0;
    int slipping = 0, newton = 0;
    for (size_t r = 0; r < t.rows.size(); ++r) {
        const double phi = 1e3 * t.number(r, "CPHI_per_mm");
        const cw::SolveTotals tot =
            m.solve(tractcurv_exact(t.number(r, "CKSI"), t.number(r, "CETA"), phi),
                    cw::SolveMode::forces_only);
        const double fx = digits_ratio(tot.Fx / (mu_s * kN), t.text(r, "FX_over_FSTAT_FN"));
        const double fy = digits_ratio(tot.Fy / (mu_s * kN), t.text(r, "FY_over_FSTAT_FN"));
        const double mz = digits_ratio(1e3 * tot.Mz, t.text(r, "MZ_Nmm"));
        worst = std::max({worst, fx, fy, mz});
        assert_int_equal(tot.n_contact, int(t.number(r, "NCON")));
        assert_int_equal(tot.n_slip, int(t.number(r, "NSLIP")));
        // mu(s) within the law's range, below mu(0) where elements slip.
        assert_true(m.info().mu_min >= 0.14 && m.info().mu_max <= mu_s);
        if (tot.n_slip > 0) assert_true(m.info().mu_min < mu_s);
        if (tot.n_slip > 0) {
            local += m.info().friction_steps_per_element;
            ++slipping;
        }
        newton += m.info().newton_steps;
    }
    printf("  exponential law, %zu rows: worst difference %.3f of half a printed digit; "
           "%.1f Newton steps per solve, %.2f local Newton steps per slipping element\n",
           t.rows.size(), worst, double(newton) / double(t.rows.size()), local / slipping);
    assert_int_equal(int(t.rows.size()), 36);
    assert_true(worst <= 1.0);
}

// Full sliding: every element slides at about xi V, so F/(mu_s N) tends to
// (mu_kin + mu_e1 exp(-ln2 xi V / s_h1)) / mu_s (within 2e-4 from 10 %).
void full_sliding_limit(void**)
{
    cw::ExactModel m(cwtest::tractcurv_grid());
    const cw::SlipSpeedLaw law = exponential_law();
    m.set_law(law, kV);
    for (double xi : {0.1, 0.15, 0.2, 0.25}) {
        const cw::SolveTotals t = m.solve(tractcurv_exact(xi), cw::SolveMode::forces_only);
        const double limit =
            (law.mu_kin + law.mu_e1 * std::exp(-std::log(2.0) * xi * kV / law.s_h1)) / 0.33;
        assert_close(-t.Fx / (0.33 * kN), limit, 0.0, 2e-4);
        assert_int_equal(t.n_slip, t.n_contact);
    }
}

// The law written as a constant coefficient takes the law's path (its own
// scalar Newton method) and solves Coulomb's discrete problem: the same
// forces within the solves' tolerance.
void constant_law_is_coulomb(void**)
{
    cw::GridSpec g = cwtest::tractcurv_grid();
    g.nx = 24;
    g.ny = 22;
    cw::ExactModel coulomb(g), law(g);
    law.set_law(cw::coulomb_law(0.33), kV);
    const double c[][3] = {{1e-3, 0, 0}, {2e-3, 1e-3, 0}, {0, 1e-3, 0.2}, {0.05, -0.01, 1.0}};
    for (const auto& k : c) {
        cw::ContactInput in = tractcurv_exact(k[0], k[1], k[2]);
        in.tolerance = 1e-12;
        const cw::SolveTotals a = coulomb.solve(in, cw::SolveMode::full);
        in.mu = 0.7; // not read under a law
        const cw::SolveTotals b = law.solve(in, cw::SolveMode::full);
        const double muN = 0.33 * kN, r = std::sqrt(in.a * in.b);
        assert_close(b.Fx, a.Fx, 0.0, 1e-10 * muN);
        assert_close(b.Fy, a.Fy, 0.0, 1e-10 * muN);
        assert_close(b.Mz, a.Mz, 0.0, 1e-10 * muN * r);
        assert_close(b.W_consistent, a.W_consistent, 1e-8, 1e-300);
        assert_int_equal(b.n_slip, a.n_slip);
        assert_true(law.info().friction_iterations > 0);
        assert_true(law.info().mu_min == 0.33 && law.info().mu_max == 0.33);
    }
}

// The work map under the law: the local work uses the local mu (the
// traction it holds), the energy-consistent map sums to W_macro, the
// paper's map to no more, and nothing is negative.
void work_map_balances(void**)
{
    cw::ExactModel m(cwtest::tractcurv_grid());
    m.set_law(exponential_law(), kV);
    for (double xi : {1e-3, 3e-3, 0.02}) {
        const cw::SolveTotals t = m.solve(tractcurv_exact(xi, 2e-4, 0.3), cw::SolveMode::full);
        assert_true(t.W_macro > 0.0);
        assert_int_equal(t.work_flags, 0);
        assert_close(t.W_consistent, t.W_macro, 1e-9, 1e-300);
        assert_true(t.W_micro_paper > 0.0 && t.W_micro_paper <= t.W_macro * (1.0 + 1e-12));
    }
}

// The N column against the law's scaling: the slip speed's unit V mu(0) p0
// / G grows with N as with V, so (forces homogeneous of degree 1 in the
// creepages and N otherwise) N dF/dN + sum_c xi_c dF/dxi_c - F = V dF/dV;
// dF/dV by central differences of the solver in V.
void n_column_scales_with_V(void**)
{
    cw::ExactModel m(cwtest::tractcurv_grid());
    for (double xi : {2e-3, 2e-2}) {
        cw::ContactInput in = tractcurv_exact(xi, 3e-4, 0.1);
        in.tolerance = 1e-13;
        in.warm_start = false;
        m.set_law(exponential_law(), kV);
        cw::Jacobian J;
        const cw::SolveTotals t = m.solve_jacobian(in, cw::SolveMode::forces_only, J);
        const double h = 1e-4 * kV;
        m.set_law(exponential_law(), kV + h);
        const cw::SolveTotals a = m.solve(in, cw::SolveMode::forces_only);
        m.set_law(exponential_law(), kV - h);
        const cw::SolveTotals b = m.solve(in, cw::SolveMode::forces_only);
        const double F[3] = {t.Fx, t.Fy, t.Mz}, Fa[3] = {a.Fx, a.Fy, a.Mz}, Fb[3] = {b.Fx, b.Fy, b.Mz};
        const double r = std::sqrt(in.a * in.b), scale[3] = {1.0, 1.0, 1.0 / r};
        double worst = 0.0, size = 0.0;
        for (int i = 0; i < 3; ++i) {
            const double lhs = in.normal_force * J.d[i][3] + in.xi_x * J.d[i][0] +
                               in.xi_y * J.d[i][1] + in.phi * J.d[i][2] - F[i];
            const double rhs = kV * (Fa[i] - Fb[i]) / (2 * h);
            worst = std::max(worst, std::fabs(lhs - rhs) * scale[i]);
            size = std::max(size, std::fabs(rhs) * scale[i]);
        }
        printf("  xi %.3g: V dF/dV = %.4g mu N, the N column's identity off by %.2g of it\n", xi,
               size / (0.33 * kN), worst / size);
        assert_true(size > 1e-3 * 0.33 * kN); // the law matters here
        assert_true(worst <= 1e-5 * size);
    }
}

void inputs_named(void**)
{
    cw::ExactModel m(cwtest::tractcurv_grid());
    expect_error_naming([&] { m.set_law(exponential_law(), 0.0); }, "V");
    expect_error_naming([&] { m.set_law(exponential_law(), NAN); }, "V");
    cw::SlipSpeedLaw bad = exponential_law();
    bad.s_h1 = 0.0;
    expect_error_naming([&] { m.set_law(bad, kV); }, "s_h1");
    bad = exponential_law();
    bad.mu_kin = -0.1;
    expect_error_naming([&] { m.set_law(bad, kV); }, "mu_kin");
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(series1_coulomb),
        cmocka_unit_test(exponential_law_rows),
        cmocka_unit_test(full_sliding_limit),
        cmocka_unit_test(constant_law_is_coulomb),
        cmocka_unit_test(work_map_balances),
        cmocka_unit_test(n_column_scales_with_V),
        cmocka_unit_test(inputs_named),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
