// FASTSIM's transient form (core/transient/transient_fastsim.hpp) on
// CONTACT's transient examples (tests/data/transient, eve70a/CONTACT
// d431cdb):
//   - its steady start equals creepwork's steady FASTSIM on the same gap
//     grid (gap/gap_fastsim_model: another implementation of the march) to
//     1e-12 mu N, and a step of dq = dx at the steady creepage keeps it
//     (the steady state is a fixed point); from zero tractions, the
//     contact's length in steps of dx at a constant creepage reach it: the
//     memory leaves the contact;
//   - its accuracy against the exact transient solution of catt_to_cart,
//     pinned at the numbers doc/validation/transient.md states (CONTACT's
//     printed creepages, the exact model's): the shift within 7 %, every
//     rolling creepage within 16 %, the overshoot's step 15 +- 1 and value
//     within 1 %, the asymptote within 7.5 %;
//   - a trial repeated after rewind and after restore gives the same bits;
//     both forces prescribed are met; errors name their input.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "../core/core_test_support.hpp"
#include "contact/error.hpp"
#include "gap/gap_fastsim_model.hpp"
#include "transient/transient_fastsim.hpp"
#include "transient_cases.hpp"
#include "test_support.h"

using creepwork::TransientFastsim;
using creepwork::TransientStepInput;
using creepwork::TransientStepResult;

namespace {

cwtest::TransientCase fastsim_case(cwtest::TransientCase c)
{
    c.input.model = creepwork::ModelKind::fastsim;
    return c;
}

TransientStepInput force_step(double dq, double fx_over_mu_n, const cwtest::TransientCase& c)
{
    TransientStepInput s;
    s.dq = dq;
    s.prescribe_fx = true;
    s.Fx = fx_over_mu_n * c.input.mu * c.input.normal_force;
    return s;
}

TransientStepInput creep_step(double dq, double xi, double eta, double phi)
{
    TransientStepInput s;
    s.dq = dq;
    s.xi_x = xi;
    s.xi_y = eta;
    s.phi = phi;
    return s;
}

void steady_is_the_steady_fastsim(void**)
{
    cwtest::TransientCase c = fastsim_case(cwtest::catt_to_cart());
    const double mu_n = c.input.mu * c.input.normal_force;
    TransientFastsim tf(c.grid, c.input);
    const double xi = 1.5e-3, eta = -1e-3, phi = 40.0;
    const TransientStepResult st = tf.start_steady(creep_step(0.0, xi, eta, phi));
    creepwork::GapFastsimModel steady(c.grid);
    creepwork::ContactInput in = c.input;
    in.xi_x = xi;
    in.xi_y = eta;
    in.phi = phi;
    const creepwork::SolveTotals t = steady.solve(in, creepwork::SolveMode::forces_only);
    std::printf("steady: Fx %.9e / %.9e, Fy %.9e / %.9e, Mz %.9e / %.9e\n", st.Fx, t.Fx, st.Fy,
                t.Fy, st.Mz, t.Mz);
    assert_close(st.Fx, t.Fx, 0.0, 1e-12 * mu_n);
    assert_close(st.Fy, t.Fy, 0.0, 1e-12 * mu_n);
    assert_close(st.Mz, t.Mz, 0.0, 1e-12 * mu_n * 3.5e-3);
    assert_int_equal(st.n_slip, t.n_slip);
    // A step of dx at the same creepages keeps the steady state.
    const int n = c.grid.nx * c.grid.ny;
    std::vector<double> px0(n), py0(n), px(n), py(n);
    tf.copy_traction(px0.data(), py0.data());
    const TransientStepResult r = tf.step(creep_step(c.grid.dx, xi, eta, phi));
    tf.copy_traction(px.data(), py.data());
    for (int k = 0; k < n; ++k) {
        assert_close(px[k], px0[k], 0.0, 1e-12 * mu_n / (c.grid.dx * c.grid.dy));
        assert_close(py[k], py0[k], 0.0, 1e-12 * mu_n / (c.grid.dx * c.grid.dy));
    }
    assert_close(r.Fx, st.Fx, 0.0, 1e-12 * mu_n);
    // From zero: after nx steps of dx every particle in contact entered
    // since the start, so the tractions are the steady ones.
    tf.start_zero();
    TransientStepResult last;
    for (int k = 0; k < c.grid.nx; ++k) {
        last = tf.step(creep_step(c.grid.dx, xi, eta, phi));
        tf.commit();
    }
    assert_close(last.Fx, st.Fx, 0.0, 1e-12 * mu_n);
    assert_close(last.Fy, st.Fy, 0.0, 1e-12 * mu_n);
    assert_int_equal(tf.steps_committed(), c.grid.nx);
}

void catt_to_cart_accuracy(void**)
{
    const cwtest::CsvTable ref =
        cwtest::read_csv(cwtest::test_data_path("transient/catt_to_cart.csv"));
    cwtest::TransientCase c = fastsim_case(cwtest::catt_to_cart());
    TransientFastsim tf(c.grid, c.input);
    double max_rolling = 0.0, peak = 0.0, last = 0.0, exact_last = 0.0;
    size_t peak_case = 0;
    for (size_t r = 0; r < ref.rows.size(); ++r) {
        const bool shift = ref.text(r, "kind") == "shift";
        const TransientStepResult& res = tf.step(force_step(shift ? 0.0 : c.grid.dx, -0.657, c));
        tf.commit();
        assert_close(res.Fx, -0.657 * c.input.mu * c.input.normal_force, 0.0,
                     1e-8 * c.input.mu * c.input.normal_force);
        // CONTACT prints the shift in mm.
        const double exact = ref.number(r, "value") * (shift ? 1e-3 : 1.0);
        const double rel = (res.xi_x - exact) / exact;
        if (shift) {
            std::printf("shift %.4e m, exact %.4e m: %+.4f\n", res.xi_x, exact, rel);
            assert_true(std::fabs(rel) < 0.07);
            continue;
        }
        max_rolling = std::max(max_rolling, std::fabs(rel));
        if (r < 20 && res.xi_x > peak) peak = res.xi_x, peak_case = r + 1;
        last = res.xi_x;
        exact_last = exact;
    }
    std::printf("rolling: max |error| %.4f, peak %.4e at case %zu (exact 3.403e-3 at 15), "
                "asymptote %.4e (exact %.4e, %+.4f)\n",
                max_rolling, peak, peak_case, last, exact_last, (last - exact_last) / exact_last);
    assert_true(max_rolling < 0.16);
    assert_true(peak_case >= 14 && peak_case <= 16);
    assert_true(std::fabs(peak / 3.403e-3 - 1.0) < 0.01);
    assert_true(std::fabs(last / exact_last - 1.0) < 0.075);
}

void trial_repeats_and_forces(void**)
{
    cwtest::TransientCase c = fastsim_case(cwtest::catt_to_cart());
    const double mu_n = c.input.mu * c.input.normal_force;
    TransientFastsim tf(c.grid, c.input);
    tf.step(force_step(0.0, -0.5, c));
    tf.commit();
    const std::vector<unsigned char> saved = tf.save();
    assert_int_equal(saved.size() % 8, 0);
    TransientStepInput both = force_step(c.grid.dx, -0.4, c);
    both.prescribe_fy = true;
    both.Fy = 0.3 * mu_n;
    const TransientStepResult a = tf.step(both);
    assert_close(a.Fx, -0.4 * mu_n, 0.0, 1e-8 * mu_n);
    assert_close(a.Fy, 0.3 * mu_n, 0.0, 1e-8 * mu_n);
    tf.rewind();
    tf.step(creep_step(c.grid.dx, 1e-3, 0.0, 0.0));
    tf.rewind();
    const TransientStepResult b = tf.step(both);
    assert_memory_equal(&a, &b, sizeof a);
    tf.commit();
    tf.step(both);
    tf.commit();
    tf.restore(saved.data(), saved.size());
    assert_int_equal(tf.steps_committed(), 1);
    const TransientStepResult d = tf.step(both);
    assert_memory_equal(&a, &d, sizeof a);
    // Work of the step: >= 0, zero without slip.
    assert_true(a.W_step > 0.0 && a.n_slip > 0);
}

void errors_name_their_input(void**)
{
    cwtest::TransientCase c = fastsim_case(cwtest::catt_to_cart());
    TransientFastsim tf(c.grid, c.input);
    const auto refused = [&](const TransientStepInput& s, const char* name) {
        try {
            tf.step(s);
        } catch (const creepwork::Error& e) {
            if (std::strstr(e.what(), name)) return;
            fail_msg("message without %s: %s", name, e.what());
        }
        fail_msg("not refused: %s", name);
    };
    refused(creep_step(2 * c.grid.dx, 1e-3, 0.0, 0.0), "dq");
    refused(force_step(c.grid.dx, -1.0, c), "mu N");
    refused(creep_step(c.grid.dx, NAN, 0.0, 0.0), "xi_x");
    unsigned char junk[16] = {0};
    bool restore_refused = false;
    try {
        tf.restore(junk, sizeof junk);
    } catch (const creepwork::Error&) {
        restore_refused = true;
    }
    assert_true(restore_refused);
    cwtest::TransientCase given = c;
    given.input.flexibility = creepwork::FlexibilitySource::given;
    bool flexibility_refused = false;
    try {
        TransientFastsim bad(given.grid, given.input);
    } catch (const creepwork::Error& e) {
        flexibility_refused = std::strstr(e.what(), "flexibility") != nullptr;
    }
    assert_true(flexibility_refused);
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(steady_is_the_steady_fastsim),
        cmocka_unit_test(catt_to_cart_accuracy),
        cmocka_unit_test(trial_repeats_and_forces),
        cmocka_unit_test(errors_name_their_input),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
