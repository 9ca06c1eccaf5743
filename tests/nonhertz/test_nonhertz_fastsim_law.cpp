// FASTSIM on a gap grid under a law of the slip speed (gap/gap_march.hpp,
// gap/gap_fastsim_model.hpp) through the core's Solver:
//  - the march on an elliptic patch with the ellipse's pressure and
//    flexibilities is the ellipse's march under the same law
//    (fastsim/march_law.hpp: the same equation per element, solved by
//    another implementation, a SIMD Newton from other starts, whose roots
//    agree to within their stopping rule, 1e-8 of the bound squared);
//  - on the Hertzian gap of CONTACT's tractcurv contact: full sliding
//    carries |F| = mu(xi V) N (the closed form of sliding friction, every
//    form of the law), and the law moves the forces as it moves the
//    ellipse's FASTSIM's (the gap and the ellipse differ in the pressure
//    and the patch's flexibilities, which the law does not see);
//  - a law without falling terms is Coulomb's law, bitwise (forces, fields,
//    Jacobian);
//  - full mode: the work map sums to W_macro, is >= 0 and 0 in adhesion on
//    shapes of one to three patches; mu_min, mu_max are the law's at the
//    exported slip speeds;
//  - the Jacobian against central differences before and past the peak;
//  - what is refused (the global slip speed, friction memory) is named.
#include "ellipse_march.hpp"
#include "gap_shape_grid.hpp"
#include "gap_shapes.hpp"
#include "gap_test_support.hpp"
#include "jacobian_step_study.hpp"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "contact/error.hpp"
#include "friction/slip_speed_law.hpp"
#include "gap/gap_march.hpp"
#include "solver.hpp"

namespace cw = creepwork;

namespace {

constexpr double kV = 10.0;       // [m/s]
constexpr double kMu0 = 0.36;     // Polach 2005's mu0, A, B [s/m]
constexpr double kA = 0.38, kB = 0.7;

// Polach's law as the input's exponential law (mu = mu_kin).
void polach(cw::ContactInput& in)
{
    in.mu = kMu0 * kA;
    in.friction_law = cw::FrictionLaw::exponential;
    in.mu_e1 = kMu0 * (1.0 - kA);
    in.s_h1 = std::log(2.0) / kB;
    in.V = kV;
}

double polach_mu(double s) { return kMu0 * (kA + (1.0 - kA) * std::exp(-kB * s)); }

// CONTACT's tractcurv contact (tests/core/tractcurv_contact.hpp's semi-axes,
// N, G, nu) as the Hertzian gap of a 48 x 48 grid over 1.1 times the
// semi-axes, the exact normal problem, the force prescribed.
struct TractcurvGap {
    cw::ContactInput in;
    std::vector<double> h;
    cw::GridSpec grid;

    TractcurvGap()
    {
        in.a = 6.304e-3;
        in.b = 12.61e-3;
        in.normal_force = 106.7e3;
        in.G = 82e9;
        in.nu = 0.28;
        grid = gapshapes::hertzian_gap(in, 48, 1.1, h);
        in.gap = h.data();
        in.gap_len = h.size();
        in.model = cw::ModelKind::fastsim;
        in.normal_method = cw::NormalMethod::exact;
        in.warm_start = false;
    }
    cw::ContactInput at(double xi_x, double xi_y = 0.0, double phi = 0.0) const
    {
        cw::ContactInput c = in;
        c.xi_x = xi_x;
        c.xi_y = xi_y;
        c.phi = phi;
        return c;
    }
};

// The march on the uniform grid's elliptic contact (its parabolic pressure,
// the ellipse's flexibilities, one patch centred on the ellipse) under
// Polach's law is the ellipse's FASTSIM under that law: the same numbers
// within the two root finders' stopping rules (each stops a step below 1e-8
// of the bound and takes it, an error of order 1e-16 of the bound per
// element); asserted to 1e-12 mu_s N, with creepage, spin and partial slip.
void march_is_the_ellipse_law_march(void**)
{
    const int nx = 24, ny = 18;
    cw::ContactInput e = cwtest::steel_contact(1.4);
    polach(e);
    cw::Solver ellipse(cwtest::uniform_grid(nx, ny, 1.0));
    for (double xi : {4e-4, 2e-3, 0.02}) {
        e.xi_x = xi;
        e.xi_y = -0.75 * xi;
        e.phi = 2000.0 * xi;
        const cw::SolveTotals te = ellipse.solve(e, cw::SolveMode::full);
        const auto px = cwtest::field(ellipse, cw::Field::px);
        const auto py = cwtest::field(ellipse, cw::Field::py);
        cwtest::EllipseMarch march(ellipse, te, e);
        const std::vector<double>& pz = march.pz;
        const cw::SlipSpeedLaw law = cw::polach_law(kMu0, kA, kB);
        cw::GapMarchInput& in = march.in;
        in.speed_law = &law;
        in.V = kV;
        std::vector<std::complex<double>> p(pz.size()), s(pz.size()), w(pz.size());
        std::vector<signed char> state(pz.size());
        cw::GapMarchTotals t;
        cw::GapLawRange range;
        cw::gap_march(in, {p.data(), s.data(), w.data(), state.data(), &t, &range});
        const double muN = kMu0 * e.normal_force;
        print_message("xi %.4f: march vs FASTSIM under the law: dFx %.2g, dFy %.2g mu_s N, "
                      "dMz %.2g mu_s N a; %d of %d slip, mu %.4f .. %.4f\n",
                      xi, (t.Fx - te.Fx) / muN, (t.Fy - te.Fy) / muN,
                      (t.Mz - te.Mz) / (muN * e.a), t.n_slip, t.n_contact, range.mu_min,
                      range.mu_max);
        assert_close(t.Fx, te.Fx, 0.0, 1e-12 * muN);
        assert_close(t.Fy, te.Fy, 0.0, 1e-12 * muN);
        assert_close(t.Mz, te.Mz, 0.0, 1e-12 * muN * e.a);
        assert_int_equal(t.n_contact, te.n_contact);
        assert_int_equal(t.n_slip, te.n_slip);
        assert_true(te.n_slip > 0);
        assert_close(range.mu_min, te.mu_min, 0.0, 1e-12);
        assert_close(range.mu_max, te.mu_max, 0.0, 1e-12);
        const double scale = kMu0 * te.p_max;
        for (size_t k = 0; k < pz.size(); ++k) {
            assert_close(p[k].real(), px[k], 0.0, 1e-12 * scale);
            assert_close(p[k].imag(), py[k], 0.0, 1e-12 * scale);
        }
    }
}

// Full sliding on the Hertzian gap (xi_x 10 and 15 %, 1 and 1.5 m/s): each
// element slides at about xi V, so |Fx| / N -> mu(xi V) for every form of
// the law (two terms each, mu from the law's own formula; the linear law's
// kink at 2.5 m/s lies beyond) and Polach's: the elastic part of the slip,
// (L1, L2) dp/dx ~ mu p0 / (G c11) ~ 2e-3 against xi = 0.1, moves the
// speeds around xi V and the force by at most 2.3e-4 of mu_s here (the
// ellipse's FASTSIM meets 2e-4 on its 48 x 44 grid, test_core_friction_fastsim);
// 3e-4 of mu_s asserted.
void full_sliding_closed_form(void**)
{
    const TractcurvGap c;
    cw::Solver s(c.grid);
    for (const auto kind : {cw::FrictionLaw::linear, cw::FrictionLaw::rational,
                            cw::FrictionLaw::exponential}) {
        cw::SlipSpeedLaw law;
        law.kind = static_cast<cw::SlipSpeedLawKind>(static_cast<int>(kind));
        law.mu_kin = 0.14;
        law.mu_e1 = 0.19;
        law.s_h1 = 1.25;
        law.mu_e2 = 0.05;
        law.s_h2 = 0.3;
        for (double xi : {0.10, 0.15}) {
            cw::ContactInput in = c.at(xi);
            in.mu = law.mu_kin;
            in.friction_law = kind;
            in.mu_e1 = law.mu_e1;
            in.s_h1 = law.s_h1;
            in.mu_e2 = law.mu_e2;
            in.s_h2 = law.s_h2;
            in.V = kV;
            const cw::SolveTotals t = s.solve(in, cw::SolveMode::forces_only);
            assert_int_equal(t.n_slip, t.n_contact);
            const double mu = law.coefficient(xi * kV), ratio = -t.Fx / t.normal_force;
            print_message("law %d, xi %.2f: |Fx|/N %.6f, mu(xi V) %.6f (%.1e of mu_s)\n",
                          int(kind), xi, ratio, mu, (ratio - mu) / 0.38);
            assert_close(ratio, mu, 0.0, 3e-4 * 0.38);
            assert_true(t.mu_min <= mu && mu <= t.mu_max && t.mu_max < 0.38);
        }
    }
    // Polach's law too (its own parameters).
    for (double xi : {0.10, 0.25}) {
        cw::ContactInput in = c.at(xi);
        polach(in);
        const cw::SolveTotals t = s.solve(in, cw::SolveMode::forces_only);
        assert_int_equal(t.n_slip, t.n_contact);
        assert_close(-t.Fx / t.normal_force, polach_mu(xi * kV), 0.0, 3e-4 * kMu0);
    }
}

// The law against Coulomb's law at its static coefficient, on the gap and
// on the ellipse (FASTSIM, the same semi-axes, N, the elliptic pressure,
// 48 x 48 over 1.1 a, 1.1 b): the gap's contact differs from the ellipse's
// (the exact normal problem's discrete pressure, each patch's
// flexibilities from its rows), the law's effect -- the ratio of the
// law's force to Coulomb's -- is the same to 8.4e-6 (the forces differ by
// up to 1e-3 mu_s N), in partial slip before and past the peak and in full
// sliding. Asserted: the ratios within 1e-4 of each other.
void the_law_moves_the_gap_as_the_ellipse(void**)
{
    const TractcurvGap c;
    cw::Solver gap(c.grid), ellipse(cwtest::uniform_grid(48, 48, 1.1));
    double worst = 0.0, worst_force = 0.0;
    for (double xi : {1e-3, 4e-3, 0.02, 0.1}) {
        double ratio[2], force[2];
        for (int g = 0; g < 2; ++g) {
            cw::ContactInput in = c.at(xi, 0.1 * xi);
            if (g == 1) {
                in.gap = nullptr;
                in.gap_len = 0;
                in.pressure = cw::PressureKind::elliptic;
            }
            cw::Solver& s = g == 0 ? gap : ellipse;
            cw::ContactInput coulomb = in;
            coulomb.mu = kMu0;
            polach(in);
            const cw::SolveTotals tc = s.solve(coulomb, cw::SolveMode::forces_only);
            const cw::SolveTotals tl = s.solve(in, cw::SolveMode::forces_only);
            ratio[g] = tl.Fx / tc.Fx;
            force[g] = tl.Fx / (kMu0 * tl.normal_force);
        }
        print_message("xi %.3f: law / Coulomb on the gap %.5f, on the ellipse %.5f; Fx / mu_s N "
                      "%.5f, %.5f\n", xi, ratio[0], ratio[1], force[0], force[1]);
        worst = std::max(worst, std::fabs(ratio[0] - ratio[1]));
        worst_force = std::max(worst_force, std::fabs(force[0] - force[1]));
    }
    print_message("worst ratio difference %.2g, force difference %.2g mu_s N\n", worst, worst_force);
    assert_true(worst < 1e-4);
}

// The exponential law with no falling term is mu at every slip speed: the
// law's path gives Coulomb's bits (local_slip lands on t = mu pz at its
// first evaluation, f = mu pz / |q| as Coulomb's projection), forces and
// fields, with spin, both rolling directions; its Jacobian is Coulomb's
// derivative written another way (f dq + (mu dpz - f e.dq) e against
// f (dq - e (e.dq)) + e mu dpz), equal within 1e-12 of each row's scale.
void law_without_falling_terms_is_coulomb(void**)
{
    const TractcurvGap c;
    cw::Solver a(c.grid), b(c.grid);
    for (int direction : {1, -1}) {
        cw::ContactInput coulomb = c.at(2e-3, 1e-3, 0.5);
        coulomb.mu = 0.3;
        coulomb.rolling_direction = direction;
        cw::ContactInput law = coulomb;
        law.friction_law = cw::FrictionLaw::exponential;
        law.V = kV;
        cw::Jacobian Ja, Jb;
        const cw::SolveTotals ta = a.solve_jacobian(coulomb, cw::SolveMode::full, Ja);
        const cw::SolveTotals tb = b.solve_jacobian(law, cw::SolveMode::full, Jb);
        assert_true(ta.n_slip > 0 && ta.n_adhesion > 0);
        assert_true(ta.Fx == tb.Fx && ta.Fy == tb.Fy && ta.Mz == tb.Mz && ta.n_slip == tb.n_slip);
        assert_true(ta.W_consistent == tb.W_consistent);
        assert_true(tb.mu_min == 0.3 && tb.mu_max == 0.3);
        const double scale[4] = {1e-3, 1e-3, 1e-3 / coulomb.a, coulomb.normal_force};
        for (int r = 0; r < 3; ++r) {
            double row = 0.0;
            for (int k = 0; k < 4; ++k) row += std::fabs(Ja.d[r][k]) * scale[k];
            for (int k = 0; k < 4; ++k)
                assert_close(Jb.d[r][k] * scale[k], Ja.d[r][k] * scale[k], 0.0, 1e-12 * row);
        }
        for (cw::Field f : {cw::Field::px, cw::Field::py, cw::Field::sx, cw::Field::sy,
                            cw::Field::work_consistent})
            assert_true(cwtest::field(a, f) == cwtest::field(b, f));
    }
}

// Full mode under Polach's law on shapes of one to three patches: the work
// map sums to W_macro within 1e-12, is >= 0 and 0 outside slip; the forces
// are forces mode's, bitwise; mu_min and mu_max are the law's mu at the
// smallest and largest exported slip speed |s| V (1e-12).
void work_maps_and_range(void**)
{
    for (const char* id : {"N03_three_lobes", "N06_flange_root", "N05_ring"}) {
        const gapshapes::Shape& sp = [&]() -> const gapshapes::Shape& {
            static const std::vector<gapshapes::Shape> all = gapshapes::shapes();
            for (const gapshapes::Shape& s : all)
                if (s.id == id) return s;
            throw std::runtime_error("no shape");
        }();
        const cw::GridSpec g = gapshapes::grid_of(sp);
        for (double xi : {1e-3, 5e-3}) {
            cw::ContactInput in = gapshapes::contact_input(sp);
            in.model = cw::ModelKind::fastsim;
            in.warm_start = false;
            in.normal_method = cw::NormalMethod::semi_hertz;
            in.xi_x = xi, in.xi_y = 0.8 * xi, in.phi = 1200.0 * xi;
            polach(in);
            cw::Solver solver(g);
            const cw::SolveTotals t = solver.solve(in, cw::SolveMode::full);
            const cw::SolveTotals tf = solver.solve(in, cw::SolveMode::forces_only);
            assert_true(tf.Fx == t.Fx && tf.Fy == t.Fy && tf.Mz == t.Mz && tf.n_slip == t.n_slip);
            solver.solve(in, cw::SolveMode::full);
            const auto w = cwtest::field(solver, cw::Field::work_consistent);
            const auto sx = cwtest::field(solver, cw::Field::sx);
            const auto sy = cwtest::field(solver, cw::Field::sy);
            const std::vector<int> st = cwtest::states(solver);
            double sum = 0.0, lo = INFINITY, hi = -INFINITY;
            int slipping = 0;
            for (size_t k = 0; k < st.size(); ++k) {
                assert_true(w[k] >= 0.0);
                sum += w[k];
                if (st[k] != 2) {
                    assert_true(w[k] == 0.0);
                    continue;
                }
                ++slipping;
                const double mu = polach_mu(std::hypot(sx[k], sy[k]) * kV);
                lo = std::min(lo, mu);
                hi = std::max(hi, mu);
            }
            print_message("%s xi %.3f: %d patches, %d of %d slip, mu %.5f .. %.5f, "
                          "work %.3e of W_macro off\n", id, xi, t.n_patches, t.n_slip, t.n_contact,
                          t.mu_min, t.mu_max, sum / t.W_macro - 1.0);
            assert_int_equal(slipping, t.n_slip);
            assert_true(t.n_slip > 0 && t.n_adhesion > 0 && t.work_flags == 0);
            assert_close(sum, t.W_macro, 1e-12, 0.0);
            assert_close(t.W_consistent, t.W_macro, 1e-12, 0.0);
            assert_close(t.mu_min, lo, 0.0, 1e-12);
            assert_close(t.mu_max, hi, 0.0, 1e-12);
            assert_true(t.mu_max < kMu0);
        }
    }
}

// The Jacobian of Fx, Fy, Mz, W_macro by xi_x, xi_y, phi, N on the
// Hertzian gap under Polach's law against central differences of the
// model's solves (tests/core/jacobian_step_study.hpp: steps 1e-3 ... 1e-6 of
// each input's scale, each entry relative to its row's scale, steps that
// change an element's state not counted), before the peak (0.4 %) and past
// it (2 %, dFx/dxi_x of the other sign), alone and with lateral creepage
// and spin (rolling towards -x): within 1e-4, the bar of the ellipse's law
// Jacobian.
void jacobian_across_the_peak(void**)
{
    const TractcurvGap c;
    cw::Solver s(c.grid);
    for (double xi : {0.004, 0.02})
        for (double lateral : {0.0, 1.0}) {
            cw::ContactInput in = c.at(xi, 0.3 * lateral * xi, 0.2 * lateral * xi / 6.304e-3);
            in.rolling_direction = lateral > 0.0 && xi > 0.01 ? -1 : 1;
            polach(in);
            cw::Jacobian J;
            const cw::SolveTotals t = s.solve_jacobian(in, cw::SolveMode::forces_only, J);
            char label[64];
            std::snprintf(label, sizeof label, "xi_x %.3f%s", xi, lateral > 0 ? ", xi_y, phi" : "");
            const double best = cwtest::jacobian_step_study(
                label, 24, s, in, J, {xi, xi, xi / in.a, in.normal_force}, t.n_slip, 1e-3, 1e-6);
            assert_true(best <= 1e-4);
            if (lateral == 0.0) assert_true(xi < 0.01 ? J.d[0][0] < 0.0 : J.d[0][0] > 0.0);
        }
}

void expect_error(cw::Solver& s, const cw::ContactInput& in, const char* names)
{
    try {
        s.solve(in, cw::SolveMode::full);
    } catch (const cw::Error& e) {
        assert_int_equal(static_cast<int>(e.kind()), static_cast<int>(cw::ErrorKind::invalid_input));
        if (!std::strstr(e.what(), names)) fail_msg("'%s' does not name %s", e.what(), names);
        return;
    }
    fail_msg("no error for %s", names);
}

// The global slip speed and friction memory are the ellipse's FASTSIM's:
// refused by name; a law needs V (named); a Coulomb solve after a law's on
// one solver is a fresh solver's, bitwise.
void refusals_name_the_input(void**)
{
    const TractcurvGap c;
    cw::Solver s(c.grid);
    cw::ContactInput in = c.at(3e-3);
    polach(in);
    cw::ContactInput bad = in;
    bad.friction_speed = cw::FrictionSpeed::global;
    bad.k0 = 1.0;
    expect_error(s, bad, "friction_speed");
    bad = in;
    bad.memory_distance = 3e-6;
    expect_error(s, bad, "memory_distance");
    bad = in;
    bad.V = 0.0;
    expect_error(s, bad, "V");
    s.solve(in, cw::SolveMode::full);
    cw::ContactInput coulomb = c.at(3e-3);
    coulomb.mu = kMu0;
    const cw::SolveTotals after = s.solve(coulomb, cw::SolveMode::full);
    cw::Solver fresh(c.grid);
    const cw::SolveTotals first = fresh.solve(coulomb, cw::SolveMode::full);
    assert_true(after.Fx == first.Fx && after.Fy == first.Fy && after.Mz == first.Mz &&
                after.mu_min == kMu0 && after.mu_max == kMu0);
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(march_is_the_ellipse_law_march),
        cmocka_unit_test(full_sliding_closed_form),
        cmocka_unit_test(the_law_moves_the_gap_as_the_ellipse),
        cmocka_unit_test(law_without_falling_terms_is_coulomb),
        cmocka_unit_test(work_maps_and_range),
        cmocka_unit_test(jacobian_across_the_peak),
        cmocka_unit_test(refusals_name_the_input),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
