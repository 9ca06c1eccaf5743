// Transient rolling (core/transient) against CONTACT's transient examples
// (tests/data/transient, eve70a/CONTACT commit d431cdb), against the steady
// exact model on the same gap grid, and the handle's step / commit / rewind /
// save / restore.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "../core/core_test_support.hpp"
#include "contact/error.hpp"
#include "gap/gap_exact_model.hpp"
#include "transient/transient_contact.hpp"
#include "transient_cases.hpp"
#include "test_support.h"

using creepwork::TransientContact;
using creepwork::TransientStepInput;
using creepwork::TransientStepResult;

namespace {

void expect_commit_refused(TransientContact& tc)
{
    bool refused = false;
    try {
        tc.commit();
    } catch (const creepwork::Error& e) {
        refused = std::strstr(e.what(), "no step to commit") != nullptr;
    }
    assert_true(refused);
}

// Fx prescribed as a fraction of mu N.
TransientStepInput force_step(double dq, double fx_over_mu_n, const cwtest::TransientCase& c)
{
    TransientStepInput s;
    s.dq = dq;
    s.prescribe_fx = true;
    s.Fx = fx_over_mu_n * c.input.mu * c.input.normal_force;
    return s;
}

// catt_to_cart.inp: the Cattaneo shift to Fx = -0.657 mu N (case 1), then
// 56 steps of dq = dx at that force (cases 2 ... 57), each printed digit of
// the shift [mm], the creepages and the frictional work as CONTACT prints
// them (%.3E), and its element division (adhesion, slip) per case.
void catt_to_cart_history(void**)
{
    const cwtest::CsvTable ref =
        cwtest::read_csv(cwtest::test_data_path("transient/catt_to_cart.csv"));
    assert_int_equal(ref.rows.size(), 57);
    cwtest::TransientCase c = cwtest::catt_to_cart();
    TransientContact tc(c.grid, c.input);
    int mismatches = 0;
    double max_rel = 0.0, max_division = 0.0, max_fric = 0.0;
    for (size_t r = 0; r < ref.rows.size(); ++r) {
        const bool shift = ref.text(r, "kind") == "shift";
        const TransientStepResult& res = tc.step(force_step(shift ? 0.0 : c.grid.dx, -0.657, c));
        tc.commit();
        const double value = shift ? res.xi_x * 1e3 : res.xi_x; // CONTACT's shift is in mm
        const std::string got = cwtest::printed(value), want = cwtest::printed(ref.number(r, "value"));
        max_rel = std::max(max_rel, std::fabs(value / ref.number(r, "value") - 1.0));
        if (got != want) {
            ++mismatches;
            std::printf("case %s: %s, CONTACT %s\n", ref.text(r, "case").c_str(), got.c_str(),
                        want.c_str());
        }
        // The element division, and the frictional work: CONTACT prints the
        // shift's work [N m] and a step's power [N m/s] at V = 1000 mm/s (dt =
        // dq / V = 2.5e-4 s), negative.
        const double adh = ref.number(r, "n_adhesion"), slip = ref.number(r, "n_slip");
        max_division = std::max({max_division, std::fabs(res.n_adhesion - adh),
                                 std::fabs(res.n_slip - slip)});
        const double fric = -res.W_step / (shift ? 1.0 : 2.5e-4);
        max_fric = std::max(max_fric, std::fabs(fric / ref.number(r, "fric") - 1.0));
        if (cwtest::printed(fric) != cwtest::printed(ref.number(r, "fric"))) {
            ++mismatches;
            std::printf("case %s: frictional work %s, CONTACT %s\n", ref.text(r, "case").c_str(),
                        cwtest::printed(fric).c_str(), cwtest::printed(ref.number(r, "fric")).c_str());
        }
        // The force is met.
        assert_true(std::fabs(res.Fx + 0.657 * c.input.mu * c.input.normal_force) <=
                    1e-8 * c.input.mu * c.input.normal_force);
    }
    std::printf("catt_to_cart: %d of 57 printed values differ; largest relative difference %.2e\n",
                mismatches, max_rel);
    std::printf("largest difference of adhesion or slip elements %.0f; frictional work / power "
                "largest relative difference %.2e\n",
                max_division, max_fric);
    assert_int_equal(mismatches, 0);
    assert_true(max_division == 0.0);
}

// cattaneo.inp: the shift at Fx = -7/8 mu N from zero tractions is 8.155e-3
// mm on CONTACT's grid (Mindlin's continuum value 8.172e-3 mm); the stick
// zone has radius 0.5 a: 45 elements of 177, 7 across on the centre row.
void cattaneo_shift(void**)
{
    cwtest::TransientCase c = cwtest::cattaneo();
    TransientContact tc(c.grid, c.input);
    const TransientStepResult& r = tc.step(force_step(0.0, -0.875, c));
    std::printf("cattaneo: shift %.4e mm, contact %d, adhesion %d, slip %d\n", r.xi_x * 1e3,
                r.n_contact, r.n_adhesion, r.n_slip);
    assert_string_equal(cwtest::printed(r.xi_x * 1e3).c_str(), "8.155E-03");
    assert_int_equal(r.n_contact, 177);
    assert_int_equal(r.n_adhesion, 45);
    assert_int_equal(r.n_slip, 132);
    std::vector<int> state(19 * 19);
    tc.copy_state(state.data());
    int across = 0;
    for (int i = 0; i < 19; ++i) across += state[i + 19 * 9] == 1;
    assert_int_equal(across, 7);
}

// The steady solution at Fx is a fixed point of a step of dq = dx at its
// creepage, and the transient history tends to it: after 150 steps the
// creepage equals the steady one to 1e-6 (relative). The steady creepage
// is that of the steady exact model on the same grid (gap/gap_exact_model)
// within 1e-6: it gives Fx at that creepage to 1e-6 mu N.
void asymptote_is_steady(void**)
{
    cwtest::TransientCase c = cwtest::catt_to_cart();
    TransientContact tc(c.grid, c.input);
    const TransientStepResult steady = tc.start_steady(force_step(0.0, -0.657, c));
    std::printf("steady creepage at Fx: %.7e\n", steady.xi_x);

    creepwork::GapExactModel model(c.grid);
    creepwork::ContactInput in = c.input;
    in.xi_x = steady.xi_x;
    const creepwork::SolveTotals t = model.solve(in, creepwork::SolveMode::forces_only);
    const double muN = c.input.mu * c.input.normal_force;
    std::printf("steady model Fx / mu N at it: %.9f\n", t.Fx / muN);
    assert_true(std::fabs(t.Fx / muN + 0.657) <= 1e-6);

    // Fixed point: one step at the steady creepage keeps the tractions.
    TransientStepInput s;
    s.dq = c.grid.dx;
    s.xi_x = steady.xi_x;
    const TransientStepResult& r = tc.step(s);
    assert_true(std::fabs(r.Fx / muN + 0.657) <= 1e-7);

    tc.start_zero();
    tc.step(force_step(0.0, -0.657, c));
    tc.commit();
    double last = 0.0;
    for (int k = 0; k < 150; ++k) {
        last = tc.step(force_step(c.grid.dx, -0.657, c)).xi_x;
        tc.commit();
    }
    std::printf("transient creepage after 150 steps: %.7e (steady %.7e)\n", last, steady.xi_x);
    assert_true(std::fabs(last / steady.xi_x - 1.0) <= 1e-6);
}

// A trial repeated after rewind, or after save and restore, gives the same
// bits; commit without a trial and foreign bytes are refused.
void rewind_and_restore_repeat_bits(void**)
{
    cwtest::TransientCase c = cwtest::catt_to_cart();
    TransientContact tc(c.grid, c.input);
    tc.step(force_step(0.0, -0.657, c));
    tc.commit();
    for (int k = 0; k < 3; ++k) {
        tc.step(force_step(c.grid.dx, -0.657, c));
        tc.commit();
    }
    const std::vector<unsigned char> saved = tc.save();
    const size_t n = 34 * 33;
    std::vector<double> px1(n), py1(n), px2(n), py2(n);
    const TransientStepResult a = tc.step(force_step(c.grid.dx, -0.5, c));
    tc.copy_traction(px1.data(), py1.data());
    tc.rewind();
    expect_commit_refused(tc);
    // A different trial in between, dropped.
    tc.step(force_step(c.grid.dx, -0.2, c));
    tc.rewind();
    const TransientStepResult b = tc.step(force_step(c.grid.dx, -0.5, c));
    tc.copy_traction(px2.data(), py2.data());
    assert_memory_equal(&a, &b, sizeof a);
    assert_memory_equal(px1.data(), px2.data(), n * sizeof(double));
    assert_memory_equal(py1.data(), py2.data(), n * sizeof(double));
    // Commit it, move on, restore the saved state: the same trial again.
    tc.commit();
    tc.step(force_step(c.grid.dx, -0.1, c));
    tc.commit();
    assert_int_equal(tc.steps_committed(), 6);
    tc.restore(saved.data(), saved.size());
    assert_int_equal(tc.steps_committed(), 4);
    const TransientStepResult d = tc.step(force_step(c.grid.dx, -0.5, c));
    assert_memory_equal(&a, &d, sizeof a);
    // A restored state in a second handle of the same contact.
    TransientContact other(c.grid, c.input);
    other.restore(saved.data(), saved.size());
    const TransientStepResult e = other.step(force_step(c.grid.dx, -0.5, c));
    assert_memory_equal(&a, &e, sizeof a);
    // Bytes cut short, or of another contact.
    bool refused = false;
    try {
        tc.restore(saved.data(), saved.size() - 1);
    } catch (const creepwork::Error&) {
        refused = true;
    }
    assert_true(refused);
    cwtest::TransientCase heavier = cwtest::catt_to_cart();
    heavier.input.normal_force = 0.5;
    TransientContact h(heavier.grid, heavier.input);
    refused = false;
    try {
        h.restore(saved.data(), saved.size());
    } catch (const creepwork::Error& e) {
        refused = std::strstr(e.what(), "another contact") != nullptr;
    }
    assert_true(refused);
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(catt_to_cart_history),
        cmocka_unit_test(cattaneo_shift),
        cmocka_unit_test(asymptote_is_steady),
        cmocka_unit_test(rewind_and_restore_repeat_bits),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
