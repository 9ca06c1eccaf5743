// The exact model's behaviour as a solver: named
// errors, the iteration bound, warm start = cold start to the tolerance
// (across failed solves, changes of a/b and extreme creepage jumps),
// degenerate contacts, consistency of totals and fields, determinism.
#include "exact_test_support.hpp"
#include "test_support.h"

#include <algorithm>
#include <cstring>

#include "contact/error.hpp"

namespace cw = creepwork;

namespace {

// Runs f, which must throw Error of the given kind with `needle` in its message.
template <class F>
void expect_error(F f, cw::ErrorKind kind, const char* needle)
{
    try {
        f();
    } catch (const cw::Error& e) {
        if (e.kind() != kind || !std::strstr(e.what(), needle))
            fail_msg("wrong error (kind %d): %s (expected '%s')", int(e.kind()), e.what(), needle);
        return;
    }
    fail_msg("no error (expected '%s')", needle);
}

cw::ContactInput partial_slip()
{
    cw::ContactInput in = cwtest::bench_contact(); // SI units, 75 % adhesion
    in.xi_x = 1e-3;
    in.xi_y = -4e-4;
    in.phi = 0.8;
    return in;
}

struct Snapshot {
    cw::SolveTotals t;
    std::vector<double> px, py;
    std::vector<int> state;
};

Snapshot solve(cw::Solver& s, const cw::ContactInput& in)
{
    Snapshot r;
    r.t = s.solve(in, cw::SolveMode::full);
    r.px = cwtest::field(s, cw::Field::px);
    r.py = cwtest::field(s, cw::Field::py);
    r.state = cwtest::states(s);
    return r;
}

// Two solutions of the same problem to a tolerance: forces within 100 tol of
// |F| (Mz of |F| c) and every traction within 100 tol of mu p_max. The
// residual bound tol is on the fixed-point map; its error can be that
// times the problem's condition, measured at most ~20 here.
void expect_same(const Snapshot& a, const Snapshot& b, const cw::ContactInput& in, double tol,
                 const char* what)
{
    const double F = std::max(std::hypot(b.t.Fx, b.t.Fy), 1e-300);
    const double c = std::sqrt(in.a * in.b);
    const double dF = std::max(std::fabs(a.t.Fx - b.t.Fx), std::fabs(a.t.Fy - b.t.Fy)) / F;
    const double dM = std::fabs(a.t.Mz - b.t.Mz) / (F * c);
    double dp = 0.0;
    for (size_t k = 0; k < a.px.size(); ++k)
        dp = std::max({dp, std::fabs(a.px[k] - b.px[k]), std::fabs(a.py[k] - b.py[k])});
    dp /= in.mu * b.t.p_max;
    if (getenv("CW_VERBOSE")) printf("  %s: dF %.2g dMz %.2g dp %.2g\n", what, dF, dM, dp);
    if (dF > 100 * tol || dM > 100 * tol || dp > 100 * tol)
        fail_msg("%s: warm and cold differ: dF %.3g, dMz %.3g, dp %.3g (tolerance %.3g)", what,
                 dF, dM, dp, tol);
}

void errors_name_the_input(void**)
{
    cw::ContactInput in = partial_slip();
    {
        cw::Solver strips(cwtest::kalker_grid(20, 20));
        expect_error([&] { strips.solve(in); }, cw::ErrorKind::invalid_input, "grid kind");
        expect_error([&] { strips.prepare(cw::ModelKind::exact); },
                     cw::ErrorKind::invalid_input, "uniform");
        assert_false(strips.has_solution());
        in.model = cw::ModelKind::fastsim; // the handle still solves FASTSIM
        strips.solve(in);
        assert_true(strips.has_solution());
        in.model = cw::ModelKind::exact;
    }
    {
        cw::Solver big(cwtest::uniform_grid(300, 20, 1.1));
        expect_error([&] { big.solve(in); }, cw::ErrorKind::grid_out_of_range, "nx = 300");
    }
    cw::Solver s(cwtest::guarded_grid(12));
    cw::ContactInput bad = in;
    bad.flexibility = cw::FlexibilitySource::given;
    bad.L1 = bad.L2 = bad.L3 = 1e-11;
    expect_error([&] { s.solve(bad); }, cw::ErrorKind::invalid_input, "flexibility");
    bad = in;
    bad.tolerance = 1e-20;
    expect_error([&] { s.solve(bad); }, cw::ErrorKind::invalid_input, "tolerance = 1e-20");
    bad.tolerance = 2.0;
    expect_error([&] { s.solve(bad); }, cw::ErrorKind::invalid_input, "tolerance = 2");
    bad = in;
    bad.max_iterations = -3;
    expect_error([&] { s.solve(bad); }, cw::ErrorKind::invalid_input, "max_iterations = -3");
    bad = in;
    bad.nu = 0.7;
    expect_error([&] { s.solve(bad); }, cw::ErrorKind::invalid_input, "nu = 0.7 is invalid");
    bad = in;
    bad.xi_x = 1e308;
    bad.mu = 1e-300;
    expect_error([&] { s.solve(bad); }, cw::ErrorKind::invalid_input, "rigid slip overflows");
    assert_false(s.has_solution());
    // The handle is usable after all that, and gives a fresh solver's answer.
    cw::Solver fresh(cwtest::guarded_grid(12));
    in.warm_start = false;
    const cw::SolveTotals a = s.solve(in), b = fresh.solve(in);
    assert_true(a.Fx == b.Fx && a.Fy == b.Fy && a.Mz == b.Mz);
}

// One Newton step cannot solve partial slip: CW_ERR_NOT_CONVERGED, never an
// unconverged answer; the next solve starts cold and succeeds.
void iteration_bound_is_an_error(void**)
{
    cw::Solver s(cwtest::guarded_grid(20));
    cw::ContactInput in = partial_slip();
    in.max_iterations = 1;
    expect_error([&] { s.solve(in); }, cw::ErrorKind::not_converged, "max_iterations");
    assert_false(s.has_solution());
    in.max_iterations = 0;
    const Snapshot after = solve(s, in);
    cw::Solver fresh(cwtest::guarded_grid(20));
    in.warm_start = false;
    const Snapshot cold = solve(fresh, in);
    assert_true(after.t.Fx == cold.t.Fx && after.t.Mz == cold.t.Mz); // it did start cold
    assert_true(after.t.residual <= 1e-8);
    assert_true(after.t.iterations > 1);
}

void warm_start_equals_cold_start(void**)
{
    const double tol = 1e-8;
    cw::Solver warm(cwtest::guarded_grid(20));
    cw::ContactInput in = partial_slip();
    // A drifting sequence, jumps between full adhesion and full sliding,
    // changes of a/b, load and sign, and a failed solve in between.
    struct Step {
        double xi, eta, phi, a_scale, N_scale;
        int max_iterations;
    };
    const Step steps[] = {{1e-3, -4e-4, 0.8, 1, 1, 0},     {1.01e-3, -4.1e-4, 0.79, 1, 1, 0},
                          {1e-9, 0, 0, 1, 1, 0},           {0.5, 0.3, 300, 1, 1, 0},
                          {-1e-3, 4e-4, -0.8, 1, 1, 0},    {1e-3, -4e-4, 0.8, 1.3, 1, 0},
                          {1e-3, -4e-4, 0.8, 0.6, 0.2, 0}, {2e-3, 1e-3, 1.0, 1, 1, 1},
                          {2e-3, 1e-3, 1.0, 1, 1, 0},      {0, 0, 0, 1, 1, 0},
                          {1e-3, -4e-4, 0.8, 1, 1, 0}};
    int k = 0;
    for (const Step& st : steps) {
        cw::ContactInput x = in;
        x.xi_x = st.xi;
        x.xi_y = st.eta;
        x.phi = st.phi;
        x.a = in.a * st.a_scale;
        x.normal_force = in.normal_force * st.N_scale;
        x.max_iterations = st.max_iterations;
        x.warm_start = true;
        char what[64];
        std::snprintf(what, sizeof what, "step %d", k++);
        if (st.max_iterations == 1) {
            expect_error([&] { warm.solve(x); }, cw::ErrorKind::not_converged, "did not converge");
            continue;
        }
        const Snapshot w = solve(warm, x);
        cw::Solver fresh(cwtest::guarded_grid(20));
        x.warm_start = false;
        const Snapshot c = solve(fresh, x);
        assert_true(w.t.residual <= tol && c.t.residual <= tol);
        if (c.t.Fx == 0.0 && c.t.Fy == 0.0) { // zero creepage: exact zeros either way
            assert_true(w.t.Fx == 0.0 && w.t.Fy == 0.0 && w.t.Mz == 0.0);
            continue;
        }
        expect_same(w, c, x, tol, what);
    }
}

// A vehicle loop's warm steps: the benchmark's drift (each creepage times
// 1 + 0.1 sin(2 pi k / 100 + offset), at most 1 % a step) on the benchmark
// contact in partial slip. Every step is within the tolerance of a fresh
// cold solve; the same calls on another handle give the same bits; and the
// start predicted along the drift (exact/creepage_history.hpp) and the
// coarse correction of the Newton steps' GMRES (exact/coarse_correction.hpp)
// keep the steps short: measured 11.70 FFT products per step over these 40
// steps, 16.7 without the correction (17.9 without it and with the last
// error added but not extrapolated); the bound is 7 % above.
void warm_drift_repeats_and_stays_short(void**)
{
    const double tol = 1e-8;
    const cw::GridSpec g = cwtest::guarded_grid(20);
    cw::Solver a(g), b(g);
    cw::ContactInput in = cwtest::bench_contact();
    in.xi_x = 6e-4;
    in.xi_y = 3e-4;
    in.phi = 0.2;
    in.warm_start = true;
    a.solve(in);
    // The cold solve: 38 FFT products with the coarse correction on its
    // finest grid's Newton steps (51 without); bounded 5 % above.
    assert_true(a.exact_model()->info().products <= 39);
    b.solve(in);
    const int steps = 40;
    long products = 0;
    for (int k = 1; k <= steps; ++k) {
        const double t = 2.0 * 3.14159265358979323846 * k / 100.0;
        cw::ContactInput x = in;
        x.xi_x = in.xi_x * (1.0 + 0.1 * std::sin(t));
        x.xi_y = in.xi_y * (1.0 + 0.1 * std::sin(t + 2.0));
        x.phi = in.phi * (1.0 + 0.1 * std::sin(t + 4.0));
        const Snapshot wa = solve(a, x), wb = solve(b, x);
        const cw::ExactSolveInfo& info = a.exact_model()->info();
        assert_true(info.warm && !info.retried_cold);
        products += info.products;
        assert_memory_equal(&wa.t.Fx, &wb.t.Fx, sizeof(double));
        assert_memory_equal(&wa.t.Fy, &wb.t.Fy, sizeof(double));
        assert_memory_equal(&wa.t.Mz, &wb.t.Mz, sizeof(double));
        assert_memory_equal(wa.px.data(), wb.px.data(), wa.px.size() * sizeof(double));
        assert_memory_equal(wa.py.data(), wb.py.data(), wa.py.size() * sizeof(double));
        if (k % 8 == 0) {
            cw::Solver fresh(g);
            x.warm_start = false;
            const Snapshot c = solve(fresh, x);
            char what[64];
            std::snprintf(what, sizeof what, "warm step %d", k);
            assert_true(wa.t.residual <= tol);
            expect_same(wa, c, x, tol, what);
        }
    }
    if (getenv("CW_VERBOSE")) printf("  FFT products per warm step: %.2f\n", double(products) / steps);
    assert_true(double(products) / steps <= 12.5);
}

// No load: no contact and exact zeros. No friction: no traction; every
// contact element slips with the rigid slip.
void degenerate_contacts(void**)
{
    cw::Solver s(cwtest::guarded_grid(16));
    cw::ContactInput in = partial_slip();
    in.normal_force = 0.0;
    const cw::SolveTotals t0 = s.solve(in);
    assert_true(t0.Fx == 0.0 && t0.Fy == 0.0 && t0.Mz == 0.0 && t0.W_macro == 0.0);
    assert_int_equal(t0.n_contact, 0);
    assert_true(t0.p_max == 0.0 && t0.approach == 0.0);
    for (int v : cwtest::states(s)) assert_int_equal(v, 0);

    in = partial_slip();
    in.mu = 0.0;
    const cw::SolveTotals t1 = s.solve(in);
    assert_true(t1.Fx == 0.0 && t1.Fy == 0.0 && t1.Mz == 0.0);
    assert_true(t1.n_contact > 0 && t1.n_slip == t1.n_contact);
    assert_true(t1.p_max > 0.0);
    const auto sx = cwtest::field(s, cw::Field::sx), sy = cwtest::field(s, cw::Field::sy);
    const auto x = cwtest::field(s, cw::Field::x), y = cwtest::field(s, cw::Field::y);
    const auto pz = cwtest::field(s, cw::Field::pz);
    const double dx = x[1] - x[0];
    for (size_t k = 0; k < sx.size(); ++k) {
        if (!(pz[k] > 0.0)) continue;
        // CONTACT's rigid slip with the spin centre dx/6 ahead.
        assert_close(sx[k], in.xi_x - in.phi * y[k], 1e-14, 1e-18);
        assert_close(sy[k], in.xi_y + in.phi * (x[k] + dx / 6.0), 1e-14, 1e-18);
    }
}

// Totals are the sums of the fields; Coulomb's law holds element by element;
// pure longitudinal creepage on a/b = 1 gives no lateral force or moment.
void fields_and_totals_agree(void**)
{
    for (const cwtest::ExactRow& row : cwtest::exact_rows(20)) {
        if (row.case_id != "ab2_cmb" && row.case_id != "ab1_lonM") continue;
        cw::Solver s(row.grid);
        const cw::SolveTotals t = s.solve(row.input);
        const auto px = cwtest::field(s, cw::Field::px), py = cwtest::field(s, cw::Field::py);
        const auto pz = cwtest::field(s, cw::Field::pz), mz = cwtest::field(s, cw::Field::mz);
        const auto sx = cwtest::field(s, cw::Field::sx), sy = cwtest::field(s, cw::Field::sy);
        const auto area = cwtest::field(s, cw::Field::area);
        const std::vector<int> st = cwtest::states(s);
        double fx = 0, fy = 0, m = 0, n = 0;
        int slips = 0;
        for (size_t k = 0; k < px.size(); ++k) {
            fx += px[k] * area[k];
            fy += py[k] * area[k];
            m += mz[k];
            n += pz[k] * area[k];
            const double p = std::hypot(px[k], py[k]), bound = row.input.mu * pz[k];
            assert_true(p <= bound * (1 + 1e-12));
            if (st[k] == 2) {
                ++slips;
                assert_close(p, bound, 1e-7, 0.0); // within the tolerance
                // traction against the slip
                assert_true(px[k] * sx[k] + py[k] * sy[k] <= 0.0);
            } else {
                assert_true(sx[k] == 0.0 && sy[k] == 0.0);
            }
            if (st[k] == 0) assert_true(pz[k] == 0.0 && px[k] == 0.0 && py[k] == 0.0);
        }
        assert_int_equal(slips, t.n_slip);
        const double F = std::hypot(t.Fx, t.Fy);
        assert_close(fx, t.Fx, 1e-12, 1e-12 * F);
        assert_close(fy, t.Fy, 1e-12, 1e-12 * F);
        assert_close(m, t.Mz, 1e-12, 1e-12 * F * row.input.a);
        assert_close(n, row.input.normal_force, 1e-12, 0.0); // dx dy sum pn = N exactly
        if (row.case_id == "ab1_lonM") {
            assert_true(std::fabs(t.Fy) < 1e-12 * F);
            assert_true(std::fabs(t.Mz) < 1e-12 * F * row.input.a);
        }
    }
}

// Rolling towards -x mirrors x: (xi, eta, phi) rolling -x gives what
// (-xi, eta, -phi) gives rolling +x with Fx, Mz negated and x mirrored.
void rolling_direction_mirrors(void**)
{
    const cw::GridSpec g = cwtest::guarded_grid(16);
    cw::Solver a(g), b(g);
    cw::ContactInput in = partial_slip();
    in.rolling_direction = -1;
    const cw::SolveTotals ta = a.solve(in);
    cw::ContactInput m = in;
    m.rolling_direction = 1;
    m.xi_x = -in.xi_x;
    m.phi = -in.phi;
    const cw::SolveTotals tb = b.solve(m);
    assert_true(ta.Fx == -tb.Fx && ta.Fy == tb.Fy && ta.Mz == -tb.Mz);
    const auto pa = cwtest::field(a, cw::Field::px), pb = cwtest::field(b, cw::Field::px);
    const auto qa = cwtest::field(a, cw::Field::py), qb = cwtest::field(b, cw::Field::py);
    const int nx = g.nx;
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < nx; ++i) {
            assert_true(pa[i + nx * j] == -pb[nx - 1 - i + nx * j]);
            assert_true(qa[i + nx * j] == qb[nx - 1 - i + nx * j]);
        }
}

// Bitwise: a fresh solver and a solver that solved other contacts (cold
// starts) give the same bits; prepare changes nothing.
void cold_solves_are_bitwise_reproducible(void**)
{
    const cw::GridSpec g = cwtest::guarded_grid(20);
    cw::ContactInput in = partial_slip();
    in.warm_start = false;
    cw::Solver fresh(g);
    const Snapshot a = solve(fresh, in);
    cw::Solver used(g);
    used.prepare(cw::ModelKind::exact);
    cw::ContactInput other = in;
    other.a *= 1.5;
    other.xi_x = 5e-3;
    used.solve(other);
    other.mu = 0.0;
    used.solve(other);
    const Snapshot b = solve(used, in);
    assert_memory_equal(&a.t.Fx, &b.t.Fx, sizeof(double));
    assert_memory_equal(&a.t.Mz, &b.t.Mz, sizeof(double));
    assert_memory_equal(&a.t.W_consistent, &b.t.W_consistent, sizeof(double));
    assert_memory_equal(a.px.data(), b.px.data(), a.px.size() * sizeof(double));
    assert_memory_equal(a.py.data(), b.py.data(), a.py.size() * sizeof(double));
    assert_true(a.state == b.state);
}

// Bitwise: a cold solve (warm_start off) on a solver whose earlier solves
// were warm and of another a/b gives a fresh solver's bits. The normal
// problem of a/b is then solved again from scratch: neither started from
// the other a/b's pressure, nor taken from a warm solve of the same a/b
// made after it.
void cold_solve_after_warm_solves_of_another_shape(void**)
{
    const cw::GridSpec g = cwtest::guarded_grid(20);
    cw::ContactInput cold = partial_slip();
    cold.warm_start = false;
    cw::Solver fresh(g);
    const Snapshot a = solve(fresh, cold);
    cw::ContactInput other = partial_slip();
    other.a *= 1.5;
    other.xi_x = 5e-3;
    cw::ContactInput warm = partial_slip();
    warm.xi_y = 1e-4;
    for (int same_shape_first = 0; same_shape_first < 2; ++same_shape_first) {
        cw::Solver used(g);
        used.solve(other);                     // warm, another a/b
        if (same_shape_first) used.solve(warm); // warm, this a/b, from the other's pressure
        const Snapshot b = solve(used, cold);
        assert_memory_equal(&a.t.Fx, &b.t.Fx, sizeof(double));
        assert_memory_equal(&a.t.Fy, &b.t.Fy, sizeof(double));
        assert_memory_equal(&a.t.Mz, &b.t.Mz, sizeof(double));
        assert_memory_equal(&a.t.approach, &b.t.approach, sizeof(double));
        assert_memory_equal(&a.t.W_consistent, &b.t.W_consistent, sizeof(double));
        assert_memory_equal(a.px.data(), b.px.data(), a.px.size() * sizeof(double));
        assert_memory_equal(a.py.data(), b.py.data(), a.py.size() * sizeof(double));
        assert_true(a.state == b.state);
    }
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(errors_name_the_input),
        cmocka_unit_test(iteration_bound_is_an_error),
        cmocka_unit_test(warm_start_equals_cold_start),
        cmocka_unit_test(warm_drift_repeats_and_stays_short),
        cmocka_unit_test(degenerate_contacts),
        cmocka_unit_test(fields_and_totals_agree),
        cmocka_unit_test(rolling_direction_mirrors),
        cmocka_unit_test(cold_solves_are_bitwise_reproducible),
        cmocka_unit_test(cold_solve_after_warm_solves_of_another_shape),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
