// The exact model with friction memory (ExactModel::set_friction_memory:
// CONTACT's mu_k = theta_k mu_prev,k + (1 - theta_k) mu_s(s_k) along each
// row, exact/steady_memory.cpp) against independent numbers:
//  - CONTACT's exact theory on its tractcurv grid (48 x 44) with the
//    exponential law and MEMDST 3 um, MEM_S0 1 mm/s, no interface layer
//    (tests/data/contact_tractcurv_memory.csv, its input beside it): every
//    printed digit of Fx / (mu_s N), the contact and slip areas;
//  - the recurrence itself, element by element, from the exported fields:
//    mu = |traction| / pressure of a slipping element and of the slipping
//    element ahead of it, theta from its exported slip speed;
//  - d_c -> 0 tends to the law without memory, d_c = 0 is the law's bits.
// Its Jacobian: test_core_exact_law_jacobian.
#include "core_test_support.hpp"
#include "tractcurv_exact.hpp"
#include "test_support.h"

#include "contact/error.hpp"
#include "contact/solved_contact.hpp"
#include "exact/exact_model.hpp"
#include "friction/slip_speed_law.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

namespace cw = creepwork;

namespace {

const double kN = cwtest::kTractcurvN, kV = cwtest::kTractcurvV;
const double kMuStatic = 0.33;           // 0.14 + 0.19
const double kDistance = 3e-6, kS0 = 1e-3; // CONTACT's MEMDST 0.003 mm, MEM_S0 1 mm/s
using cwtest::tractcurv_exact;

// Half a unit of the printed value's last digit.
double half_digit(const std::string& text)
{
    const auto e = text.find_first_of("Ee");
    const std::string mant = text.substr(0, e);
    const auto dot = mant.find('.');
    const int decimals = dot == std::string::npos ? 0 : int(mant.size() - dot - 1);
    const int exponent = e == std::string::npos ? 0 : std::stoi(text.substr(e + 1));
    return 0.5 * std::pow(10.0, exponent - decimals);
}

cw::ExactModel& with_memory(cw::ExactModel& m, double distance = kDistance)
{
    m.set_law(cwtest::tractcurv_exponential_law(), kV);
    m.set_friction_memory(distance, kS0);
    return m;
}

void contact_memory_rows(void**)
{
    const cwtest::CsvTable t =
        cwtest::read_csv(cwtest::test_data_path("contact_tractcurv_memory.csv"));
    cw::ExactModel m(cwtest::tractcurv_grid());
    with_memory(m);
    double worst = 0.0;
    int rounds = 0, most = 0, newton = 0;
    for (size_t r = 0; r < t.rows.size(); ++r) {
        const cw::SolveTotals tot =
            m.solve(tractcurv_exact(t.number(r, "CKSI")), cw::SolveMode::forces_only);
        const double fx = tot.Fx / (kMuStatic * kN);
        const double d = std::fabs(fx - t.number(r, "FX_over_FSTAT_FN")) /
                         half_digit(t.text(r, "FX_over_FSTAT_FN"));
        printf("  CKSI %-6s Fx/(mu_s N) %.6f, CONTACT %s (%.2f of half a digit); slip %d "
               "(CONTACT %d); %d memory rounds, %d Newton steps\n",
               t.text(r, "CKSI").c_str(), fx, t.text(r, "FX_over_FSTAT_FN").c_str(), d,
               tot.n_slip, int(t.number(r, "NSLIP")), m.info().memory_iterations,
               m.info().newton_steps);
        worst = std::max(worst, d);
        assert_int_equal(tot.n_contact, int(t.number(r, "NCON")));
        assert_true(std::abs(tot.n_slip - int(t.number(r, "NSLIP"))) <= 2);
        assert_true(m.info().memory_iterations >= 2); // the fixed point was iterated
        rounds += m.info().memory_iterations;
        most = std::max(most, m.info().memory_iterations);
        newton += m.info().newton_steps;
    }
    printf("  memory, %zu rows: worst %.3f of half a printed digit; %.1f memory rounds per "
           "solve (at most %d), %.1f Newton steps per solve\n",
           t.rows.size(), worst, double(rounds) / double(t.rows.size()), most,
           double(newton) / double(t.rows.size()));
    assert_int_equal(int(t.rows.size()), 6);
    assert_true(worst <= 1.0);
}

// CONTACT's tractcurv series 2 (examples/tractcurv.ref_out: the exact
// theory with the interface layer G3 = 8200 N/mm^2, h = 1.25 mm, the
// exponential law and the memory above): all 30 creepages within two units
// of the last printed digit, as series 1 (test_core_exact_law: tractcurv
// runs CONTACT at EPS 1e-6 and from A1 and a/b, not from the printed
// semi-axes); the layer's and the memory's own rows above, run from the
// printed semi-axes, meet every digit. Measured: 3.3 of half a digit
// (1.7e-4 at 0.4 %).
void series2_layer_law_memory(void**)
{
    const cwtest::CsvTable t = cwtest::read_csv(cwtest::test_data_path("contact_tractcurv.csv"));
    cw::ExactModel m(cwtest::tractcurv_grid());
    with_memory(m);
    double worst = 0.0;
    int rows = 0;
    for (size_t r = 0; r < t.rows.size(); ++r) {
        if (t.number(r, "series") != 2) continue;
        cw::ContactInput in = tractcurv_exact(t.number(r, "CKSI"));
        in.layer_h = 1.25e-3;
        in.layer_G = 8.2e9;
        const cw::SolveTotals tot = m.solve(in, cw::SolveMode::forces_only);
        const double fx = tot.Fx / (kMuStatic * kN);
        worst = std::max(worst, std::fabs(fx - t.number(r, "FX_over_FSTAT_FN")) /
                                    half_digit(t.text(r, "FX_over_FSTAT_FN")));
        ++rows;
    }
    printf("  series 2 (layer, law, memory): worst |Fx/(mu_s N) - CONTACT| = %.3f of half a "
           "printed digit\n",
           worst);
    assert_int_equal(rows, 30);
    assert_true(worst <= 4.0);
}

// From the exported fields: along each row the coefficient |t| / p of a
// slipping element is theta mu_ahead + (1 - theta) mu_s(s), mu_ahead that
// of the slipping element ahead of it, s = |micro-slip| V its slip speed,
// theta = d_c / (d_c + (dx / V) max(s, s0)). Elements with p > 0.2 p0
// (the tractions converge relative to mu_s p0).
void recurrence_holds_element_by_element(void**)
{
    cw::ExactModel m(cwtest::tractcurv_grid());
    with_memory(m);
    const cw::SlipSpeedLaw law = cwtest::tractcurv_exponential_law();
    for (double xi : {2e-3, 5e-3, 0.02}) {
        cw::ContactInput in = tractcurv_exact(xi, 1e-4, 0.05);
        in.tolerance = 1e-11;
        m.solve(in, cw::SolveMode::full);
        const cw::SolvedContact c = m.solved();
        const double dt = std::fabs(c.x_column[1] - c.x_column[0]) / kV;
        double p0 = 0.0;
        for (long k = 0; k < long(c.nx) * c.ny; ++k)
            p0 = std::max(p0, c.pressure_scale * c.pressure[k]);
        double worst = 0.0, memory = 0.0;
        int checked = 0;
        for (int j = 0; j < c.ny; ++j)
            for (int i = 0; i + 1 < c.nx; ++i) {
                const long k = i + long(c.nx) * j, up = k + 1; // the model's frame: ahead at i + 1
                if (c.state[k] != 2 || c.state[up] != 2) continue;
                const double pk = c.pressure_scale * c.pressure[k];
                const double pu = c.pressure_scale * c.pressure[up];
                if (!(pk > 0.2 * p0 && pu > 0.2 * p0)) continue;
                const double mu_k = c.traction_scale * std::abs(c.traction[k]) / pk;
                const double mu_up = c.traction_scale * std::abs(c.traction[up]) / pu;
                const double s = c.slip_scale * std::abs(c.slip[k]) * kV;
                const double theta = kDistance / (kDistance + dt * std::max(s, kS0));
                const double mu_s = law.mu_kin + law.mu_e1 * std::exp(-std::log(2.0) * s / law.s_h1);
                worst = std::max(worst, std::fabs(mu_k - (theta * mu_up + (1 - theta) * mu_s)));
                memory = std::max(memory, std::fabs(mu_k - mu_s));
                ++checked;
            }
        printf("  xi %.3g: %d slipping pairs, recurrence off by %.2g, mu - mu_s(s) up to %.3g\n",
               xi, checked, worst, memory);
        assert_true(checked > 50);
        assert_true(memory > 1e-3); // the memory matters here
        assert_true(worst <= 1e-10);
    }
}

// d_c = 0 is the law alone, to the bit; a tiny d_c (theta ~ 1e-6) tends to
// it within the solves' tolerance.
void vanishing_distance_is_the_law(void**)
{
    cw::ExactModel law(cwtest::tractcurv_grid()), zero(cwtest::tractcurv_grid()),
        tiny(cwtest::tractcurv_grid());
    law.set_law(cwtest::tractcurv_exponential_law(), kV);
    with_memory(zero, 0.0);
    with_memory(tiny, 1e-14);
    for (double xi : {1e-3, 4e-3, 0.05}) {
        cw::ContactInput in = tractcurv_exact(xi, 2e-4, 0.1);
        in.tolerance = 1e-11;
        const cw::SolveTotals a = law.solve(in, cw::SolveMode::forces_only);
        const cw::SolveTotals b = zero.solve(in, cw::SolveMode::forces_only);
        const cw::SolveTotals c = tiny.solve(in, cw::SolveMode::forces_only);
        assert_memory_equal(&a.Fx, &b.Fx, sizeof a.Fx);
        assert_memory_equal(&a.Fy, &b.Fy, sizeof a.Fy);
        assert_memory_equal(&a.Mz, &b.Mz, sizeof a.Mz);
        assert_int_equal(zero.info().memory_iterations, 0);
        const double muN = kMuStatic * kN;
        assert_close(c.Fx, a.Fx, 0.0, 1e-6 * muN);
        assert_close(c.Fy, a.Fy, 0.0, 1e-6 * muN);
        assert_true(tiny.info().memory_iterations >= 1);
    }
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(contact_memory_rows),
        cmocka_unit_test(series2_layer_law_memory),
        cmocka_unit_test(recurrence_holds_element_by_element),
        cmocka_unit_test(vanishing_distance_is_the_law),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
