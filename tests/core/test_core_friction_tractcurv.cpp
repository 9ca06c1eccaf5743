// CONTACT's FASTSIM with a law of the slip speed, as CONTACT's tractcurv
// example runs it (its series 3 and 4: Coulomb 0.33, and the exponential
// law with Spiryagin's slope reduction, mu at the contact's rigid slip
// speed): creepwork's FASTSIM on the same 48 x 44 grid against CONTACT's
// printed |Fx|/(mu_s N) (tests/data/contact_tractcurv.csv), and the
// full-sliding closed form A + (1 - A) exp(-B xi V), B in s/m.
#include "core_test_support.hpp"
#include "law_residual.hpp"
#include "tractcurv_contact.hpp"
#include "test_support.h"

#include "contact/contact_grid.hpp"
#include "contact/error.hpp"
#include "fastsim/fastsim_law_model.hpp"
#include "friction/global_slip.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace cw = creepwork;

namespace {

const double kN = cwtest::kTractcurvN, kV = cwtest::kTractcurvV;
using cwtest::tractcurv_grid;

cw::ContactInput eurosprinter(double xi) { return cwtest::tractcurv_contact(xi); }

// Series 4: Polach's mu0 = 0.36, A = 0.38, B = 0.7 s/m (CONTACT's FKIN
// 0.1368, FEXP1 0.2232, SABSH1 990 mm/s), k0 = 0.54, alpha_inf = 0.02,
// beta = 0.62.
const cw::SlopeReduction kSpiryagin{0.54, 0.02, 0.62};
cw::SlipSpeedLaw series4_law()
{
    cw::SlipSpeedLaw law;
    law.kind = cw::SlipSpeedLawKind::exponential;
    law.mu_kin = 0.1368;
    law.mu_e1 = 0.2232;
    law.s_h1 = 0.990;
    return law;
}

// |ours - CONTACT| within half a unit of the printed last digit plus 6e-5:
// creepwork's FASTSIM and CONTACT's modified FASTSIM differ by up to 5e-5
// on this grid with Coulomb's law already (series 3).
double printed_tolerance(const std::string& text)
{
    const auto e = text.find_first_of("Ee");
    const std::string mant = text.substr(0, e);
    const auto dot = mant.find('.');
    const int decimals = dot == std::string::npos ? 0 : int(mant.size() - dot - 1);
    const int exponent = e == std::string::npos ? 0 : std::stoi(text.substr(e + 1));
    return 0.5 * std::pow(10.0, exponent - decimals) + 6e-5;
}

void series3_coulomb_fastsim(void**)
{
    const cwtest::CsvTable t = cwtest::read_csv(cwtest::test_data_path("contact_tractcurv.csv"));
    cw::Solver s(tractcurv_grid());
    int rows = 0;
    for (size_t r = 0; r < t.rows.size(); ++r) {
        if (t.number(r, "series") != 3) continue;
        cw::ContactInput in = eurosprinter(t.number(r, "CKSI"));
        in.mu = 0.33;
        const cw::SolveTotals& tot = s.solve(in);
        const std::string ref = t.text(r, "FX_over_FSTAT_FN");
        assert_close(tot.Fx / (0.33 * kN), std::stod(ref), 0.0, printed_tolerance(ref));
        assert_int_equal(tot.n_contact, int(t.number(r, "NCON")));
        // The slip area: CONTACT's count in 29 of 30 rows, 864 against 862
        // at 0.24 %.
        assert_true(std::abs(tot.n_slip - int(t.number(r, "NSLIP"))) <= 2);
        ++rows;
    }
    assert_int_equal(rows, 30);
}

void series4_falling_friction_fastsim(void**)
{
    const cwtest::CsvTable t = cwtest::read_csv(cwtest::test_data_path("contact_tractcurv.csv"));
    const cw::GridSpec spec = tractcurv_grid();
    const cw::ContactGrid grid(spec);
    cw::Solver s(spec);
    int rows = 0;
    for (size_t r = 0; r < t.rows.size(); ++r) {
        if (t.number(r, "series") != 4) continue;
        const double xi = t.number(r, "CKSI");
        cw::GlobalSlip g;
        const cw::ContactInput in =
            cw::global_slip_input(eurosprinter(xi), grid, series4_law(), kSpiryagin, kV, &g);
        const cw::SolveTotals& tot = s.solve(in);
        const std::string ref = t.text(r, "FX_over_FSTAT_FN");
        assert_close(tot.Fx / (0.36 * kN), std::stod(ref), 0.0, printed_tolerance(ref));
        // CONTACT prints its slope reduction k where it prints the inputs.
        if (!t.text(r, "K_EFF").empty())
            assert_close(g.k, t.number(r, "K_EFF"), 0.0, 0.5e-4);
        // The slip area is CONTACT's, element for element count.
        assert_int_equal(tot.n_slip, int(t.number(r, "NSLIP")));
        // Full sliding (from 12.5 % on; at 10 % 62 elements still adhere,
        // in CONTACT too): F = mu(xi V) N, mu(w)/mu_s = A + (1 - A) exp(-B w).
        if (tot.n_slip == tot.n_contact) {
            const double closed = 0.38 + 0.62 * std::exp(-0.7 * xi * kV);
            assert_close(-tot.Fx / (0.36 * kN), closed, 0.0, 2e-4);
        }
        ++rows;
    }
    assert_int_equal(rows, 30);
}

// The global-slip FASTSIM's Jacobian (chain rule through mu(w) and k)
// against central differences of the whole set-up and solve, before the
// peak of series 4 (0.4 %) and past it (5 %; the peak is at 2.2 %), alone
// and with lateral creepage and spin: the worst entry relative to its row's
// scale, best of three steps that change no element's state, within 1e-4.
void global_slip_jacobian_across_the_peak(void**)
{
    const cw::GridSpec spec = tractcurv_grid();
    const cw::ContactGrid grid(spec);
    cw::Solver s(spec);
    for (double xi : {0.004, 0.05})
        for (double lateral : {0.0, 1.0}) {
            cw::ContactInput in = cwtest::tractcurv_contact(xi, 0.3 * lateral * xi,
                                                            0.2 * lateral * xi / 6.304e-3);
            const auto forces = [&](const cw::ContactInput& x, int& slips) {
                const cw::SolveTotals& t = s.solve(
                    cw::global_slip_input(x, grid, series4_law(), kSpiryagin, kV),
                    cw::SolveMode::forces_only);
                slips = t.n_slip;
                return std::array<double, 3>{t.Fx, t.Fy, t.Mz};
            };
            cw::Jacobian Jf;
            const cw::SolveTotals t =
                s.solve_jacobian(cw::global_slip_input(in, grid, series4_law(), kSpiryagin, kV),
                                 cw::SolveMode::forces_only, Jf);
            const double F[3] = {t.Fx, t.Fy, t.Mz};
            const int slips = t.n_slip;
            const cw::Jacobian J =
                cw::global_slip_jacobian(in, grid, series4_law(), kSpiryagin, kV, Jf, F);
            const double scale[4] = {xi, xi, xi / in.a, in.normal_force};
            double best = INFINITY;
            for (double rel : {1e-4, 1e-5, 1e-6}) {
                double worst = 0.0;
                bool changed = false;
                double fd[3][4];
                for (int c = 0; c < 4; ++c) {
                    cw::ContactInput up = in, down = in;
                    double* u[4] = {&up.xi_x, &up.xi_y, &up.phi, &up.normal_force};
                    double* d[4] = {&down.xi_x, &down.xi_y, &down.phi, &down.normal_force};
                    *u[c] += rel * scale[c];
                    *d[c] -= rel * scale[c];
                    int su = 0, sd = 0;
                    const auto a = forces(up, su), b = forces(down, sd);
                    changed |= su != slips || sd != slips;
                    for (int r = 0; r < 3; ++r) fd[r][c] = (a[r] - b[r]) / (2 * rel * scale[c]);
                }
                for (int r = 0; r < 3; ++r) {
                    double row = 0.0;
                    for (int c = 0; c < 4; ++c) row += std::fabs(J.d[r][c]) * scale[c];
                    for (int c = 0; c < 4; ++c)
                        if (row > 0.0)
                            worst = std::max(worst, std::fabs(J.d[r][c] - fd[r][c]) * scale[c] / row);
                }
                if (!changed) best = std::min(best, worst);
            }
            print_message("xi_x %.3f (%s): dFx/dxi_x %.6g N, worst relative error %.2e\n", xi,
                          lateral > 0 ? "with xi_y, phi" : "alone", J.d[0][0], best);
            assert_true(best <= 1e-4);
            if (lateral == 0.0) assert_true(xi < 0.022 ? J.d[0][0] < 0.0 : J.d[0][0] > 0.0);
        }
    // Blending breaks the identity the chain rule uses: refused by name.
    cw::ContactInput in = cwtest::tractcurv_contact(0.004);
    in.flexibility_blending = true;
    const double F[3] = {0, 0, 0};
    try {
        cw::global_slip_jacobian(in, grid, series4_law(), kSpiryagin, kV, cw::Jacobian{}, F);
        fail_msg("blending accepted");
    } catch (const cw::Error& e) {
        assert_true(std::string(e.what()).rfind("flexibility_blending", 0) == 0);
    }
}

// The law at every element (FastsimLawModel, no slope reduction: it does
// not matter where every element slides) against CONTACT's series 4 in
// full sliding, from 12.5 % on: within 2e-4 of the printed value.
void local_law_meets_series4_in_full_sliding(void**)
{
    const cwtest::CsvTable t = cwtest::read_csv(cwtest::test_data_path("contact_tractcurv.csv"));
    cw::FastsimLawModel m(tractcurv_grid());
    m.set_law(series4_law(), kV);
    int rows = 0;
    for (size_t r = 0; r < t.rows.size(); ++r) {
        if (t.number(r, "series") != 4 || t.number(r, "NADH") != 0) continue;
        const cw::SolveTotals tot = m.solve(eurosprinter(t.number(r, "CKSI")),
                                            cw::SolveMode::forces_only);
        assert_close(tot.Fx / (0.36 * kN), t.number(r, "FX_over_FSTAT_FN"), 0.0, 2e-4);
        ++rows;
    }
    assert_int_equal(rows, 6);
}

// The law at every element on series 4's contact and law (Polach's, as
// CONTACT's FKIN, FEXP1, SABSH1), through the solver, at every creepage of
// the series, partial slip to full sliding: every slipping element meets
// its law within 1e-12 of p_z mu_s (law_residual.hpp; the root's accuracy,
// fastsim/march_law.hpp).
void local_law_holds_at_every_element(void**)
{
    const cwtest::CsvTable t = cwtest::read_csv(cwtest::test_data_path("contact_tractcurv.csv"));
    cw::Solver s(tractcurv_grid());
    double worst = 0.0;
    long checked = 0;
    int rows = 0;
    for (size_t r = 0; r < t.rows.size(); ++r) {
        if (t.number(r, "series") != 4) continue;
        cw::ContactInput in = eurosprinter(t.number(r, "CKSI"));
        const cw::SlipSpeedLaw law = series4_law();
        in.friction_law = cw::FrictionLaw::exponential;
        in.mu = law.mu_kin;
        in.mu_e1 = law.mu_e1;
        in.s_h1 = law.s_h1;
        in.V = kV;
        s.solve(in, cw::SolveMode::full);
        worst = std::max(worst, cwtest::worst_law_residual(s, in, checked));
        ++rows;
    }
    print_message("series 4, %d creepages, %ld slipping elements: worst %.3g\n", rows, checked,
                  worst);
    assert_true(rows >= 10 && checked > 5000);
    assert_true(worst <= 1e-12);
}

// The equivalent ellipse of CONTACT's discrete contact on this grid: 1376
// elements spanning 44 x 40 of them (CONTACT's picture of series 3 and 4).
void equivalent_ellipse_of_the_grid(void**)
{
    const cw::ContactGrid grid(tractcurv_grid());
    const cw::SemiAxes e = cw::equivalent_ellipse(grid, 6.304e-3, 12.61e-3);
    const double dx = 2.2 * 6.304e-3 / 48, dy = 2.2 * 12.61e-3 / 44;
    const double r = std::sqrt(1376 * dx * dy / M_PI);
    assert_close(e.a, r * std::sqrt(44 * dx / (40 * dy)), 1e-14, 0.0);
    assert_close(e.b, r * std::sqrt(40 * dy / (44 * dx)), 1e-14, 0.0);
    // The strip grid has no box: the nominal semi-axes.
    cw::GridSpec strips;
    const cw::SemiAxes n = cw::equivalent_ellipse(cw::ContactGrid(strips), 6e-3, 7e-3);
    assert_true(n.a == 6e-3 && n.b == 7e-3);
}

// k0 = alpha_inf = 1 and Coulomb's law leave the input as it is: the
// flexibilities Kalker's, mu the same.
void no_reduction_is_fastsim(void**)
{
    const cw::GridSpec spec = tractcurv_grid();
    const cw::ContactGrid grid(spec);
    const cw::ContactInput base = eurosprinter(0.002);
    cw::ContactInput coulomb = base;
    coulomb.mu = 0.33;
    const cw::ContactInput in =
        cw::global_slip_input(base, grid, cw::coulomb_law(0.33), cw::SlopeReduction{}, kV);
    cw::Solver s1(spec), s2(spec);
    assert_true(s1.solve(in).Fx == s2.solve(coulomb).Fx);
}

// Bad inputs of the set-up are named: V for a law of the slip speed, the
// law's parameters, Spiryagin's.
void setup_inputs_named(void**)
{
    const cw::ContactGrid grid(tractcurv_grid());
    const auto expect = [&](const cw::SlipSpeedLaw& law, const cw::SlopeReduction& sr, double V,
                            const char* name) {
        try {
            cw::global_slip_input(eurosprinter(0.01), grid, law, sr, V);
            fail_msg("accepted, expected an error naming %s", name);
        } catch (const cw::Error& e) {
            assert_true(std::string(e.what()).rfind(name, 0) == 0);
        }
    };
    expect(series4_law(), kSpiryagin, 0.0, "V");
    expect(series4_law(), kSpiryagin, NAN, "V");
    cw::SlipSpeedLaw bad = series4_law();
    bad.s_h1 = 0.0;
    expect(bad, kSpiryagin, kV, "s_h1");
    expect(series4_law(), {0.0, 0.02, 0.62}, kV, "k0");
    expect(series4_law(), {0.54, 1.5, 0.62}, kV, "alpha_inf");
    expect(series4_law(), {0.54, 0.02, -1.0}, kV, "beta");
    // Coulomb's law needs no V.
    cw::global_slip_input(eurosprinter(0.01), grid, cw::coulomb_law(0.3), {}, 0.0);
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(series3_coulomb_fastsim),
        cmocka_unit_test(series4_falling_friction_fastsim),
        cmocka_unit_test(global_slip_jacobian_across_the_peak),
        cmocka_unit_test(local_law_meets_series4_in_full_sliding),
        cmocka_unit_test(local_law_holds_at_every_element),
        cmocka_unit_test(equivalent_ellipse_of_the_grid),
        cmocka_unit_test(no_reduction_is_fastsim),
        cmocka_unit_test(setup_inputs_named),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
