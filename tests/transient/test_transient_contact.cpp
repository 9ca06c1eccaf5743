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
#include "contact/hertz.hpp"
#include "exact/exact_model.hpp"
#include "gap/gap_exact_model.hpp"
#include "transient/transient_contact.hpp"
#include "transient_cases.hpp"
#include "wear/transient_wear.hpp"
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
        const double fric = -res.W_slip / (shift ? 1.0 : 2.5e-4);
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

// The work map of each step of catt_to_cart sums to W_step (to 1e-12,
// relative), is >= 0 and vanishes in adhesion and outside the contact.
void work_map_sums_to_w_step(void**)
{
    cwtest::TransientCase c = cwtest::catt_to_cart();
    TransientContact tc(c.grid, c.input);
    const size_t n = 34 * 33;
    std::vector<double> work(n);
    std::vector<int> state(n);
    double worst = 0.0;
    for (int k = 0; k < 12; ++k) {
        const TransientStepResult& r = tc.step(force_step(k == 0 ? 0.0 : c.grid.dx, -0.657, c));
        tc.copy_work(work.data());
        tc.copy_state(state.data());
        double sum = 0.0;
        for (size_t e = 0; e < n; ++e) {
            sum += work[e];
            assert_true(work[e] >= 0.0);
            if (state[e] != 2) assert_true(work[e] == 0.0);
        }
        assert_true(r.W_step > 0.0);
        worst = std::max(worst, std::fabs(sum / r.W_step - 1.0));
        tc.commit();
    }
    std::printf("work map: largest |sum / W_step - 1| %.2e\n", worst);
    assert_true(worst <= 1e-12);

    // A small shift from zero tractions (Fx = -0.01 mu N) sticks everywhere:
    // the rigid work -1/2 Fx delta goes into elastic energy and nothing is
    // dissipated: |W_step| <= 1e-9 of the rigid work (measured 1.4e-11).
    TransientContact fresh(c.grid, c.input);
    const TransientStepResult& r = fresh.step(force_step(0.0, -0.01, c));
    const double rigid = -0.5 * r.Fx * r.xi_x;
    std::printf("small shift: rigid work %.3e J, W_step %.3e J, W_slip %.3e J\n", rigid, r.W_step,
                r.W_slip);
    assert_int_equal(r.n_slip, 0);
    assert_true(r.W_slip == 0.0);
    assert_true(rigid > 0.0 && std::fabs(r.W_step) <= 1e-9 * rigid);
}

// In steady state (a step of dq = dx at the steady creepage of Fx = -0.657
// mu N, from the steady start) the work per rolled distance W_step / dq is
// the steady exact model's W_macro = -(Fx xi_x) on the same grid, and the
// same creepage 150 steps after a Cattaneo shift gives it too.
void steady_work_per_distance_is_w_macro(void**)
{
    cwtest::TransientCase c = cwtest::catt_to_cart();
    c.input.tolerance = 1e-12;
    TransientContact tc(c.grid, c.input);
    const TransientStepResult steady = tc.start_steady(force_step(0.0, -0.657, c));
    creepwork::GapExactModel model(c.grid);
    creepwork::ContactInput in = c.input;
    in.xi_x = steady.xi_x;
    const creepwork::SolveTotals t = model.solve(in, creepwork::SolveMode::full);
    TransientStepInput s;
    s.dq = c.grid.dx;
    s.xi_x = steady.xi_x;
    const double w = tc.step(s).W_step / c.grid.dx;
    std::printf("steady: W_step / dq %.9e J/m, W_macro %.9e J/m (%.2e); W_slip / dq %.9e, "
                "the model's W_micro_paper %.9e\n",
                w, t.W_macro, w / t.W_macro - 1.0, tc.last().W_slip / c.grid.dx, t.W_micro_paper);
    assert_true(std::fabs(w / t.W_macro - 1.0) <= 1e-9);
    // The dissipation of the slip itself is the steady model's paper map.
    assert_true(std::fabs(tc.last().W_slip / c.grid.dx / t.W_micro_paper - 1.0) <= 1e-9);
}

// Central differences of a step (h = 1e-5 of the input's scale) against
// jacobian().
double jacobian_difference(TransientContact& tc, const TransientStepInput& base,
                           const double scale[3])
{
    double J[9];
    tc.step(base);
    tc.jacobian(J);
    double worst = 0.0;
    for (int col = 0; col < 3; ++col) {
        const double h = 1e-5 * scale[col];
        double out[2][3];
        for (int side = 0; side < 2; ++side) {
            TransientStepInput s = base;
            const double d = side == 0 ? h : -h;
            if (col == 0) (s.prescribe_fx ? s.Fx : s.xi_x) += d;
            if (col == 1) (s.prescribe_fy ? s.Fy : s.xi_y) += d;
            if (col == 2) s.phi += d;
            const TransientStepResult& r = tc.step(s);
            tc.rewind();
            out[side][0] = s.prescribe_fx ? r.xi_x : r.Fx;
            out[side][1] = s.prescribe_fy ? r.xi_y : r.Fy;
            out[side][2] = r.Mz;
        }
        for (int row = 0; row < 3; ++row) {
            const double fd = (out[0][row] - out[1][row]) / (2 * h);
            double size = 0.0; // the row's largest entry
            for (int k = 0; k < 3; ++k) size = std::max(size, std::fabs(J[3 * row + k]));
            const double e = std::fabs(fd - J[3 * row + col]) / size;
            worst = std::max(worst, e);
        }
    }
    return worst;
}

// The step map's Jacobian (creepages given; Fx given; Fx and Fy given; a
// shift) equals central differences of the step to 1e-6 of each row's
// largest entry, after four steps of catt_to_cart with lateral creepage and
// spin added.
void step_jacobian_matches_differences(void**)
{
    cwtest::TransientCase c = cwtest::catt_to_cart();
    c.input.tolerance = 1e-12;
    TransientContact tc(c.grid, c.input);
    tc.step(force_step(0.0, -0.657, c));
    tc.commit();
    double xi[3] = {0.0, 1e-3, 20.0};
    for (int k = 0; k < 4; ++k) {
        TransientStepInput s = force_step(c.grid.dx, -0.5, c);
        s.xi_y = xi[1];
        s.phi = xi[2];
        xi[0] = tc.step(s).xi_x;
        tc.commit();
    }
    TransientStepInput s;
    s.dq = c.grid.dx;
    s.xi_x = xi[0];
    s.xi_y = xi[1];
    s.phi = xi[2];
    const double creep_scale[3] = {1e-3, 1e-3, 20.0};
    const double e_creep = jacobian_difference(tc, s, creep_scale);
    const double muN = c.input.mu * c.input.normal_force;
    TransientStepInput f = s;
    f.prescribe_fx = true;
    f.Fx = -0.5 * muN;
    const double force_scale[3] = {muN, muN, 20.0};
    const double e_fx = jacobian_difference(tc, f, force_scale);
    f.prescribe_fy = true;
    f.Fy = tc.step(s).Fy;
    const double e_forces = jacobian_difference(tc, f, force_scale);
    TransientStepInput shift;
    shift.xi_x = -2e-6;
    shift.xi_y = 1e-6;
    shift.phi = 1e-4;
    const double shift_scale[3] = {1e-6, 1e-6, 1e-4};
    const double e_shift = jacobian_difference(tc, shift, shift_scale);
    std::printf("step Jacobian vs central differences: creepages %.2e, Fx %.2e, Fx Fy %.2e, "
                "shift %.2e\n",
                e_creep, e_fx, e_forces, e_shift);
    assert_true(e_creep <= 1e-6);
    assert_true(e_fx <= 1e-6);
    assert_true(e_forces <= 1e-6);
    assert_true(e_shift <= 1e-6);
}

// catt_to_cart's second sequence (cases 58-114): the same contact in
// world-fixed coordinates (T = 1) on 90 x 33 elements, the geometry moved by
// dq = dx per step. Against the contact-fixed history on 34 x 33 (the same
// discrete problem seen from the ground: creepage and W_step to 1e-6,
// relative, asserted) and CONTACT's own T = 1 results
// (tests/data/transient/catt_to_cart_world.csv: the shift of each step
// [mm], element division, frictional work as printed): the shift and work
// to 5e-4 (relative) from case 60 on, as far as CONTACT's T = 1 is from
// its own T = 2 (3e-4 on the creepage; its work 1e-4 below), the element
// division equal. CONTACT's T = 1 differs from its own T = 2 (which
// creepwork reproduces digit by digit) in case 59, the first rolling step,
// by 2.6e-3 (4.548e-4 mm: xi_x = 1.819e-3 against 1.824e-3), and in the
// division of case 69 (350/271 against 352/269): there the test asserts
// CONTACT's T = 2 values.
void world_fixed_matches_contact_fixed(void**)
{
    const cwtest::CsvTable ref =
        cwtest::read_csv(cwtest::test_data_path("transient/catt_to_cart_world.csv"));
    const cwtest::CsvTable t2 = cwtest::read_csv(cwtest::test_data_path("transient/catt_to_cart.csv"));
    assert_int_equal(ref.rows.size(), 57);
    cwtest::TransientCase c = cwtest::catt_to_cart();
    cwtest::TransientCase w = cwtest::sphere_case(90, 33, -4e-3, -4e-3, 0.25e-3, 2.963, 0.4705,
                                                  1e6, 0.28, 0.4013);
    TransientContact tc(c.grid, c.input), tw(w.grid, w.input);
    tw.set_frame(creepwork::TransientFrame::world);
    double worst = 0.0, worst_work = 0.0, worst_contact = 0.0;
    for (size_t r = 0; r < ref.rows.size(); ++r) {
        const double dq = r == 0 ? 0.0 : c.grid.dx;
        const TransientStepResult a = tc.step(force_step(dq, -0.657, c));
        const TransientStepResult& b = tw.step(force_step(dq, -0.657, w));
        tc.commit();
        tw.commit();
        worst = std::max(worst, std::fabs(b.xi_x / a.xi_x - 1.0));
        worst_work = std::max(worst_work, std::fabs(b.W_step / a.W_step - 1.0));
        // CONTACT prints the world-fixed step's shift [mm]: xi_x dq.
        const double shift_mm = (r == 0 ? b.xi_x : b.xi_x * dq) * 1e3;
        const bool own = r == 1 || r == 11; // cases 59 and 69: CONTACT's T = 2
        const double want = own ? (r == 0 ? 1.0 : dq * 1e3) * t2.number(r, "value")
                                : ref.number(r, "value");
        const double e = std::max(std::fabs(shift_mm / want - 1.0),
                                  std::fabs(-b.W_slip / ref.number(r, "fric") - 1.0));
        if (r != 1) worst_contact = std::max(worst_contact, e);
        const cwtest::CsvTable& division = own ? t2 : ref;
        assert_int_equal(b.n_adhesion, static_cast<int>(division.number(r, "n_adhesion")));
        assert_int_equal(b.n_slip, static_cast<int>(division.number(r, "n_slip")));
    }
    std::printf("world- vs contact-fixed: creepage %.2e, W_step %.2e; against CONTACT's T = 1 "
                "(cases 60-114) shift and work %.2e (largest relative differences)\n",
                worst, worst_work, worst_contact);
    assert_true(worst <= 1e-6);
    assert_true(worst_work <= 1e-6);
    assert_true(worst_contact <= 5e-4);

    // A world-fixed trial repeats bitwise after another (whose normal problem
    // moved the geometry elsewhere) and after restore; a contact-fixed
    // handle's state is refused.
    const TransientStepResult first = tw.step(force_step(0.5 * c.grid.dx, -0.6, w));
    tw.rewind();
    tw.step(force_step(c.grid.dx, -0.3, w));
    tw.rewind();
    const TransientStepResult again = tw.step(force_step(0.5 * c.grid.dx, -0.6, w));
    assert_memory_equal(&first, &again, sizeof first);
    const std::vector<unsigned char> saved = tw.save();
    tw.commit();
    assert_true(std::fabs(tw.position() - 56.5 * c.grid.dx) <= 1e-12 * c.grid.dx);
    tw.restore(saved.data(), saved.size());
    assert_true(std::fabs(tw.position() - 56 * c.grid.dx) <= 1e-12 * c.grid.dx);
    const TransientStepResult restored = tw.step(force_step(0.5 * c.grid.dx, -0.6, w));
    assert_memory_equal(&first, &restored, sizeof first);
    TransientContact cw(w.grid, w.input);
    bool refused = false;
    try {
        cw.restore(saved.data(), saved.size());
    } catch (const creepwork::Error&) {
        refused = true;
    }
    assert_true(refused);
}

// Steps shorter than an element: world-fixed (the gap interpolated between
// the elements) against contact-fixed (the displacement interpolated): the
// same continuum problem, discretised differently. 112 steps of dq = dx / 2
// at Fx = -0.657 mu N after the Cattaneo shift on 90 x 33 elements: the
// creepages agree to 7e-2 (relative; the overshoot comes a step or two
// apart) and the asymptotes to 2e-2 (world-fixed 1.6 % higher: its contact
// area alternates between two discrete shapes).
void world_fixed_half_steps(void**)
{
    cwtest::TransientCase c = cwtest::catt_to_cart();
    cwtest::TransientCase w = cwtest::sphere_case(90, 33, -4e-3, -4e-3, 0.25e-3, 2.963, 0.4705,
                                                  1e6, 0.28, 0.4013);
    TransientContact tc(c.grid, c.input), tw(w.grid, w.input);
    tw.set_frame(creepwork::TransientFrame::world);
    double worst = 0.0, last_c = 0.0, last_w = 0.0;
    for (int k = 0; k <= 112; ++k) {
        const double dq = k == 0 ? 0.0 : 0.5 * c.grid.dx;
        last_c = tc.step(force_step(dq, -0.657, c)).xi_x;
        last_w = tw.step(force_step(dq, -0.657, w)).xi_x;
        tc.commit();
        tw.commit();
        if (k > 0) worst = std::max(worst, std::fabs(last_w / last_c - 1.0));
    }
    std::printf("half steps: world- vs contact-fixed creepage %.2e (largest relative "
                "difference); after 56 elements %.6e, %.6e\n",
                worst, last_w, last_c);
    assert_true(worst <= 7e-2);
    assert_true(std::fabs(last_w / last_c - 1.0) <= 2e-2);
}

// An elliptic contact (a = 4 mm, b = 2.5 mm, catt_to_cart's load and
// material) on the exact model's uniform grid (32 x 24, box scale 1.1),
// given by its semi-axes, and the same contact given as its Hertzian gap on
// a gap grid of the same elements: the history of a Cattaneo shift to Fx =
// -0.5 mu N and 20 steps at that force agree to 1e-6 (relative; the
// solver's tolerance is 1e-8). The steady start at xi_x = 1e-3, xi_y =
// 5e-4 equals the steady exact model on the uniform grid (cw_solver's
// elliptic exact model) to 1e-6 mu N.
void ellipse_matches_gap(void**)
{
    creepwork::GridSpec u;
    u.kind = creepwork::GridKind::uniform;
    u.nx = 32;
    u.ny = 24;
    u.box_scale = 1.1;
    creepwork::ContactInput in;
    in.model = creepwork::ModelKind::exact;
    in.a = 4e-3;
    in.b = 2.5e-3;
    in.normal_force = 0.4705;
    in.G = 1e6;
    in.nu = 0.28;
    in.mu = 0.4013;
    TransientContact te(u, in);

    creepwork::GridSpec g;
    g.kind = creepwork::GridKind::gap;
    g.nx = u.nx;
    g.ny = u.ny;
    g.dx = 2.0 * 1.1 * in.a / u.nx;
    g.dy = 2.0 * 1.1 * in.b / u.ny;
    g.x0 = -1.1 * in.a + 0.5 * g.dx;
    g.y0 = -1.1 * in.b + 0.5 * g.dy;
    const creepwork::HertzCurvatures hz =
        creepwork::hertz_from_semi_axes(in.a, in.b, in.normal_force, in.G / (1.0 - in.nu));
    std::vector<double> h(static_cast<size_t>(g.nx) * g.ny);
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const double x = g.x0 + i * g.dx, y = g.y0 + j * g.dy;
            h[i + static_cast<size_t>(g.nx) * j] = hz.A * x * x + hz.B * y * y;
        }
    creepwork::ContactInput ig = in;
    ig.a = ig.b = 0.0;
    ig.gap = h.data();
    ig.gap_len = h.size();
    TransientContact tg(g, ig);

    const double muN = in.mu * in.normal_force;
    double worst = 0.0;
    for (int k = 0; k <= 20; ++k) {
        TransientStepInput s;
        s.dq = k == 0 ? 0.0 : g.dx;
        s.prescribe_fx = true;
        s.Fx = -0.5 * muN;
        const TransientStepResult a = te.step(s);
        const TransientStepResult& b = tg.step(s);
        te.commit();
        tg.commit();
        worst = std::max(worst, std::fabs(a.xi_x / b.xi_x - 1.0));
        assert_int_equal(a.n_slip, b.n_slip);
    }
    TransientStepInput s;
    s.xi_x = 1e-3;
    s.xi_y = 5e-4;
    const TransientStepResult steady = te.start_steady(s);
    creepwork::ExactModel model(u);
    creepwork::ContactInput m = in;
    m.xi_x = s.xi_x;
    m.xi_y = s.xi_y;
    const creepwork::SolveTotals t = model.solve(m, creepwork::SolveMode::forces_only);
    const double dF = std::max(std::fabs(steady.Fx - t.Fx), std::fabs(steady.Fy - t.Fy)) / muN;
    std::printf("ellipse vs gap: creepage history %.2e (largest relative difference); steady "
                "start vs the uniform grid's exact model: %.2e mu N (Fx %.6e, %.6e)\n",
                worst, dF, steady.Fx, t.Fx);
    assert_true(worst <= 1e-6);
    assert_true(dF <= 1e-6);
}

// Wear over steps (USFD, energy-consistent work): catt_to_cart's work
// densities are all in the law's mild regime, where the mass is k1 times the
// work, so each step's mass is k1 W_step (to 1e-12, relative) through the
// shift and 20 rolling steps (the shift adds none: no rolled distance), the
// accumulated map sums to the accumulated mass, and ten steady steps from
// the steady start wear 10 dx k1 W_macro of the steady exact model (1e-9).
void wear_accumulates_over_steps(void**)
{
    cwtest::TransientCase c = cwtest::catt_to_cart();
    TransientContact tc(c.grid, c.input);
    creepwork::TransientWear wear(tc);
    creepwork::wear::WearLaw law; // USFD
    const double k1 = law.usfd.k1;
    double worst = 0.0, total = 0.0;
    for (int k = 0; k <= 20; ++k) {
        const double dq = k == 0 ? 0.0 : c.grid.dx;
        const TransientStepResult& r = tc.step(force_step(dq, -0.657, c));
        const creepwork::wear::WearTotals t = wear.add(tc, dq, law);
        tc.commit();
        if (k == 0) {
            assert_true(t.mass_per_pass == 0.0);
            continue;
        }
        assert_true(t.regime_area[1] == 0.0 && t.regime_area[2] == 0.0);
        worst = std::max(worst, std::fabs(t.mass_per_pass / (k1 * r.W_step) - 1.0));
        total += k1 * r.W_step;
    }
    double map_sum = 0.0;
    for (double m : wear.mass_map()) map_sum += m;
    std::printf("wear: step mass / (k1 W_step) - 1 at most %.2e; accumulated %.6e kg, map sum "
                "%.2e off\n",
                worst, wear.mass(), map_sum / wear.mass() - 1.0);
    assert_true(worst <= 1e-12);
    assert_true(std::fabs(wear.mass() / total - 1.0) <= 1e-12);
    assert_true(std::fabs(map_sum / wear.mass() - 1.0) <= 1e-12);
    assert_int_equal(wear.steps(), 21);

    const TransientStepResult steady = tc.start_steady(force_step(0.0, -0.657, c));
    creepwork::GapExactModel model(c.grid);
    creepwork::ContactInput in = c.input;
    in.xi_x = steady.xi_x;
    const creepwork::SolveTotals t = model.solve(in, creepwork::SolveMode::full);
    wear.reset();
    TransientStepInput s;
    s.dq = c.grid.dx;
    s.xi_x = steady.xi_x;
    for (int k = 0; k < 10; ++k) {
        tc.step(s);
        wear.add(tc, s.dq, law);
        tc.commit();
    }
    const double want = 10 * c.grid.dx * k1 * t.W_macro;
    std::printf("ten steady steps: %.9e kg, 10 dx k1 W_macro %.9e kg\n", wear.mass(), want);
    assert_true(std::fabs(wear.mass() / want - 1.0) <= 1e-9);
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(catt_to_cart_history),
        cmocka_unit_test(cattaneo_shift),
        cmocka_unit_test(asymptote_is_steady),
        cmocka_unit_test(rewind_and_restore_repeat_bits),
        cmocka_unit_test(work_map_sums_to_w_step),
        cmocka_unit_test(steady_work_per_distance_is_w_macro),
        cmocka_unit_test(step_jacobian_matches_differences),
        cmocka_unit_test(world_fixed_matches_contact_fixed),
        cmocka_unit_test(world_fixed_half_steps),
        cmocka_unit_test(ellipse_matches_gap),
        cmocka_unit_test(wear_accumulates_over_steps),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
