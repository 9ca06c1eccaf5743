// The building blocks of contacts of any shape, each against an independent
// reference: the normal problem on a given gap against the Hertzian path of
// the same solver (the same discrete problem built two ways) and against
// itself with the approach prescribed; the semi-Hertzian method against
// Hertz's closed form on a paraboloid (also with a raised band on one side,
// which the row fit must not reach) and against CONTACT's own ANALYN (B = 6)
// on the DEV gaps (an independent implementation of the same method,
// tests/data/nonhertz/dev/fast_methods.csv); the patch labels
// against masks labelled by hand; the products on a box of the grid
// (GridConvolution::set_size, other FFT lengths) against the whole grid's,
// and the normal problem with its products on the contact set's box against
// the one on the whole grid; the normal methods' dN/d(approach) against
// central differences of their own force; the warm exact steps' coarse
// space followed along a gap's changing contact set against a fresh one.
#include "gap_shape_grid.hpp"
#include "gap_shapes.hpp"
#include "gap_test_support.hpp"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "contact/hertz.hpp"
#include "exact/coarse_correction.hpp"
#include "halfspace/exact_geometry.hpp"
#include "halfspace/grid_convolution.hpp"
#include "normal/gap_normal.hpp"
#include "normal/normal_problem.hpp"
#include "normal/patches.hpp"
#include "normal/pressure_drift.hpp"
#include "normal/semi_hertz.hpp"

namespace cw = creepwork;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The Hertzian normal problem on a 24 x 24 uniform grid (a/b = 1.5, nu =
// 0.28) solved twice: from a, b (NormalProblem::solve, q = p/p0, gap in
// p0 dx / G) and from the gap A x^2 + B y^2 itself (solve_gap, q = p/G, gap
// in dx). The same discrete problem: pressures agree to the solver
// tolerance (1e-10 of the approach).
void gap_problem_matches_the_hertzian_path(void**)
{
    const int n = 24;
    const double S = 1.2, ratio = 1.5, nu = 0.28, G = 82e9;
    const cw::ExactGeometry g(n, n, S, ratio);
    cw::GridConvolution conv(n, n);
    conv.set_coefficients(g.rho, nu);
    cw::NormalProblem hertz(n, n), gap(n, n);
    const cw::NormalSolveInfo hi = hertz.solve(g, conv, false, 1e-12, 500);
    assert_true(hi.converged);

    // Physical units: a = alpha dx with dx = 1 mm, N = 1e5.
    const double dx = 1e-3, a = g.alpha * dx, b = g.beta * dx, N = 1e5;
    const cw::HertzCurvatures hz = cw::hertz_from_semi_axes(a, b, N, G / (1.0 - nu));
    std::vector<double> h(n * n), start(n * n, 0.0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double x = g.X(i) * dx, y = g.Y(j) * dx;
            h[i + n * j] = (hz.A * x * x + hz.B * y * y) / dx;
            start[i + n * j] = (x * x / (a * a) + y * y / (b * b)) < 1.0 ? 1.0 : 0.0;
        }
    const double dy = g.rho * dx;
    const cw::NormalSolveInfo gi =
        gap.solve_gap(conv, h.data(), start.data(), true, N / (G * dx * dy), 1e-12, 500);
    assert_true(gi.converged);
    assert_int_equal(gap.n_contact(), hertz.n_contact());
    double worst = 0.0;
    for (int k = 0; k < n * n; ++k)
        worst = std::max(worst, std::fabs(gap.pressure()[k] * G - hertz.pressure()[k] * hz.p0));
    print_message("pressure difference %.2g of p0, approach %.2g relative\n", worst / hz.p0,
                  std::fabs(gap.approach() * dx / (hertz.approach() * hz.p0 * dx / G) - 1.0));
    assert_true(worst <= 1e-9 * hz.p0);
    assert_close(gap.approach() * dx, hertz.approach() * hz.p0 * dx / G, 1e-9, 0.0);

    // The approach found, prescribed: the same pressures and the force back.
    cw::NormalProblem by_approach(n, n);
    const cw::NormalSolveInfo ai = by_approach.solve_gap(conv, h.data(), start.data(), false,
                                                         gap.approach(), 1e-12, 500);
    assert_true(ai.converged);
    double sum = 0.0, diff = 0.0;
    for (int k = 0; k < n * n; ++k) {
        sum += by_approach.pressure()[k];
        diff = std::max(diff, std::fabs(by_approach.pressure()[k] - gap.pressure()[k]));
    }
    assert_close(sum * G * dx * dy, N, 1e-9, 0.0);
    assert_true(diff * G <= 1e-9 * hz.p0);

    // An approach below the lowest point: no contact, converged.
    cw::NormalProblem apart(n, n);
    const cw::NormalSolveInfo ni =
        apart.solve_gap(conv, h.data(), start.data(), false, -1e-3, 1e-12, 500);
    assert_true(ni.converged);
    assert_int_equal(apart.n_contact(), 0);
}

// Hertz's paraboloid through the semi-Hertzian method: the row fits are
// exact for a quadratic gap, so each row is a chord of Hertz's ellipse and
// the pressure is Hertz's (Johnson 1985, eqs. 4.38-4.39) at the element
// centres; only the force's sum over elements differs from the integral.
// A field that vanishes outside a box of the grid: the products computed on
// the box alone (FFT lengths of the box) equal the whole grid's there, to
// rounding; a convolution resized away and back gives the same bits again.
void box_products_match_the_whole_grid(void**)
{
    using C = std::complex<double>;
    const int nx = 40, ny = 36, i0 = 7, j0 = 5, bx = 19, by = 26;
    const double rho = 1.3, nu = 0.28;
    cw::GridConvolution whole(nx, ny), box(nx, ny);
    whole.set_coefficients(rho, nu);
    std::vector<C> z(nx * ny, 0.0), s(nx * ny), zb(bx * by), sb(bx * by), again(bx * by);
    std::vector<double> p(nx * ny, 0.0), u(nx * ny), pb(bx * by), ub(bx * by);
    for (int j = 0; j < by; ++j)
        for (int i = 0; i < bx; ++i) {
            const double v = std::sin(0.7 * i + 1.3 * j) + 0.3 * std::cos(2.1 * i * j);
            zb[i + bx * j] = z[i0 + i + nx * (j0 + j)] = C(v, std::cos(0.4 * i - 0.9 * j));
            pb[i + bx * j] = p[i0 + i + nx * (j0 + j)] = 1.5 + v;
        }
    assert_true(box.set_size(bx, by)); // other FFT lengths than the whole grid's
    box.copy_coefficients(whole);
    for (int steady = 0; steady < 2; ++steady) {
        whole.apply_tangential(z.data(), s.data(), steady);
        box.apply_tangential(zb.data(), sb.data(), steady);
        double worst = 0.0, largest = 0.0;
        for (int j = 0; j < by; ++j)
            for (int i = 0; i < bx; ++i) {
                const C w = s[i0 + i + nx * (j0 + j)];
                worst = std::max(worst, std::abs(sb[i + bx * j] - w));
                largest = std::max(largest, std::abs(w));
            }
        print_message("tangential (steady %d): box against whole grid %.2g of the largest\n",
                      steady, worst / largest);
        assert_true(worst <= 1e-13 * largest);
    }
    whole.apply_normal(p.data(), u.data());
    box.apply_normal(pb.data(), ub.data());
    double worst = 0.0, largest = 0.0;
    for (int j = 0; j < by; ++j)
        for (int i = 0; i < bx; ++i) {
            const double w = u[i0 + i + nx * (j0 + j)];
            worst = std::max(worst, std::fabs(ub[i + bx * j] - w));
            largest = std::max(largest, std::fabs(w));
        }
    assert_true(worst <= 1e-13 * largest);
    // Away (a smaller field: new plans, new spectra) and back.
    assert_true(box.set_size(5, 4));
    box.apply_tangential(zb.data(), again.data(), true);
    assert_true(box.set_size(bx, by));
    box.apply_tangential(zb.data(), again.data(), true);
    for (int k = 0; k < bx * by; ++k) assert_true(again[k] == sb[k]); // sb: steady, before
}

// The normal problem of a gap (a crescent: a Hertzian gap with a ridge along
// x) with its conjugate-gradient products on the contact set's box: the
// pressures of the whole-grid solve to the solver's tolerance.
void normal_problem_on_the_box_matches_the_whole_grid(void**)
{
    const int nx = 44, ny = 40;
    const double nu = 0.28, rho = 0.9, load = 12.0; // sum q
    cw::GridConvolution conv(nx, ny), box(nx, ny, cw::ConvolutionUse::normal);
    conv.set_coefficients(rho, nu);
    std::vector<double> h(nx * ny), start(nx * ny, 0.0);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const double x = i - 0.45 * nx, y = (j - 0.5 * ny) * rho;
            h[i + nx * j] = 2e-3 * x * x + 4e-3 * y * y + 0.05 * std::exp(-0.05 * y * y) -
                            1e-3 * x * y;
        }
    cw::NormalProblem plain(nx, ny), boxed(nx, ny);
    boxed.set_box_convolution(&box);
    const cw::NormalSolveInfo a = plain.solve_gap(conv, h.data(), start.data(), true, load,
                                                  1e-12, 500, 1e-4);
    const cw::NormalSolveInfo b = boxed.solve_gap(conv, h.data(), start.data(), true, load,
                                                  1e-12, 500, 1e-4);
    assert_true(a.converged);
    assert_true(b.converged);
    assert_int_equal(plain.n_contact(), boxed.n_contact());
    double worst = 0.0, peak = 0.0;
    int i_lo = nx, i_hi = -1, j_lo = ny, j_hi = -1;
    for (int k = 0; k < nx * ny; ++k) {
        worst = std::max(worst, std::fabs(plain.pressure()[k] - boxed.pressure()[k]));
        peak = std::max(peak, plain.pressure()[k]);
        if (plain.pressure()[k] > 0.0) {
            i_lo = std::min(i_lo, k % nx), i_hi = std::max(i_hi, k % nx);
            j_lo = std::min(j_lo, k / nx), j_hi = std::max(j_hi, k / nx);
        }
    }
    print_message("%d elements in a %d x %d box, %d / %d iterations, pressure difference "
                  "%.2g of the peak\n", plain.n_contact(), i_hi - i_lo + 1, j_hi - j_lo + 1,
                  a.iterations, b.iterations, worst / peak);
    // The box is well inside the grid (so its FFT lengths are smaller).
    assert_true(i_hi - i_lo + 1 <= nx * 3 / 4 && j_hi - j_lo + 1 <= ny * 3 / 4);
    assert_true(worst <= 1e-9 * peak);
    assert_close(boxed.approach(), plain.approach(), 1e-10, 0.0);
    // A pass's cost besides its iterations' two products (the product and
    // the preconditioner): the force's share (one product, which the pass's
    // first residual reuses) and the complementarity check on the whole grid.
    assert_int_equal(a.products, 2 * a.iterations + 2 * a.active_set_passes);
    assert_int_equal(b.products, 2 * b.iterations + 2 * b.active_set_passes);
}

// The drift prediction against fields where the pressure is linear in the
// gap (what it assumes on a fixed contact set): P(B + a v + b u + c) = P_B +
// a w + b z for drifts v, u of the gap's shape and any constant c (the force
// prescribed; with the approach prescribed, the approach moves by c too).
// After solutions at (a, b) = (0, 0), (1, 0) and (1, 1), any gap of that
// family gets its pressure, and after the first two, any gap along v; with
// the newest three along v, the newest difference alone; a difference of
// the height alone (rounding, the force prescribed) is left out. Elements out of contact in
// every solution take no part in the fit; a leap along the drift is taken;
// a gap that has not moved gives the newest pressure's bits, and so does
// one solution.
void pressure_drift_follows_a_linear_drift(void**)
{
    const int n = 16, in_contact = 11; // elements 11 ... 15: out of contact in all
    std::vector<double> B(n), v(n), u(n), P(n, 0.0), w(n, 0.0), z(n, 0.0), h(n), start(n);
    for (int k = 0; k < n; ++k) {
        B[k] = 1e-6 * (k - 5) * (k - 5);
        v[k] = 2e-8 * std::sin(0.7 * k) + 1e-8;
        u[k] = 3e-8 * std::cos(1.3 * k);
        if (k < in_contact) {
            P[k] = 1e9 * (1.0 + 0.1 * k);
            w[k] = 1e6 * std::cos(0.3 * k);
            z[k] = -2e6 * std::sin(0.5 * k);
        }
    }
    const double A = 2e-5; // the approach at c = 0
    // The gap (a, b, c) into h, the same plus far off outside the contact into
    // h_far; the pressure into p.
    auto gap = [&](double a, double b, double c, std::vector<double>& out, double far) {
        for (int k = 0; k < n; ++k)
            out[k] = B[k] + a * v[k] + b * u[k] + c + (k >= in_contact ? far : 0.0);
    };
    auto pressure = [&](double a, double b) {
        std::vector<double> p(n);
        for (int k = 0; k < n; ++k) p[k] = P[k] + a * w[k] + b * z[k];
        return p;
    };
    auto expect = [&](double a, double b, double tolerance = 1e-12) {
        const std::vector<double> p = pressure(a, b);
        for (int k = 0; k < n; ++k) assert_close(start[k], p[k], tolerance, 0.0);
    };
    std::vector<double> hs(n);
    double g[2];
    cw::PressureDrift drift(n);
    gap(0, 0, 3e-6, hs, 0.0);
    drift.remember(hs.data(), A + 3e-6, pressure(0, 0));
    assert_int_equal(drift.count(), 1);
    gap(0.5, 0, 0, h, 0.0);
    drift.predict(h.data(), true, 0.0, start.data(), g);
    assert_true(g[0] == 0.0 && g[1] == 0.0);
    assert_memory_equal(start.data(), pressure(0, 0).data(), n * sizeof(double));

    gap(1, 0, -1e-6, hs, 0.0);
    drift.remember(hs.data(), A - 1e-6, pressure(1, 0));
    for (const double a : {1.5, -0.25, 3.9}) {
        gap(a, 0, 5e-6, h, 1e-3 * a); // far off outside the contact: no weight
        drift.predict(h.data(), true, 0.0, start.data(), g);
        assert_close(g[0], 1.0 - a, 1e-9, 0.0); // steps of h_1 - h_0 = -v
        expect(a, 0);
        gap(a, 0, 5e-6, h, 0.0);
        drift.predict(h.data(), false, A + 5e-6, start.data());
        expect(a, 0);
    }
    gap(31, 0, 0, h, 0.0); // thirty steps of v beyond the newest: a leap
    drift.predict(h.data(), true, 0.0, start.data(), g);
    assert_close(g[0], -30.0, 1e-9, 0.0);
    expect(31, 0);

    gap(1, 1, 2e-6, hs, 0.0);
    drift.remember(hs.data(), A + 2e-6, pressure(1, 1));
    assert_int_equal(drift.count(), 3);
    for (const double a : {1.3, 0.6})
        for (const double b : {1.4, 0.8}) {
            gap(a, b, -4e-6, h, 1e-3);
            drift.predict(h.data(), true, 0.0, start.data());
            expect(a, b);
            gap(a, b, -4e-6, h, 0.0);
            drift.predict(h.data(), false, A - 4e-6, start.data());
            expect(a, b);
        }
    drift.predict(hs.data(), true, 0.0, start.data(), g); // the newest gap: not moved
    assert_true(g[0] == 0.0 && g[1] == 0.0);
    assert_memory_equal(start.data(), pressure(1, 1).data(), n * sizeof(double));
    gap(1, 1, 7e-6, h, 0.0); // raised: the same pressure (the force prescribed)
    drift.predict(h.data(), true, 0.0, start.data());
    expect(1, 1);

    // One shape drifting: the newest three along v.
    gap(2, 1, 0, hs, 0.0);
    drift.remember(hs.data(), A, pressure(2, 1));
    gap(3, 1, 0, hs, 0.0);
    drift.remember(hs.data(), A, pressure(3, 1));
    gap(3.5, 1, 1e-6, h, 0.0);
    drift.predict(h.data(), true, 0.0, start.data(), g);
    assert_true(g[1] == 0.0); // the newest difference alone
    expect(3.5, 1);
    // The height alone changed (the pressure within a solve's rounding of
    // the last): that difference is rounding, the other one is the drift.
    gap(3, 1, 2e-6, hs, 0.0);
    std::vector<double> p = pressure(3, 1);
    for (int k = 0; k < n; ++k) p[k] *= 1.0 + 1e-10 * std::sin(2.0 * k);
    drift.remember(hs.data(), A + 2e-6, p);
    gap(3.5, 1, 0, h, 0.0);
    drift.predict(h.data(), true, 0.0, start.data(), g);
    assert_true(g[0] == 0.0);
    expect(3.5, 1, 2e-10); // 1.5 times the newest's error
    drift.clear();
    assert_int_equal(drift.count(), 0);
}

// The coarse correction of the warm exact steps (exact/coarse_correction.hpp)
// follows a gap's contact set as it grows and shrinks by the columns of the
// elements that joined or left it: its B P equals a fresh set-up's on the
// last set, to rounding (1e-12 of the largest entry), on N07_wide's grid
// with the sets h < t for three levels t a few elements apart.
void coarse_space_follows_the_contact_set(void**)
{
    static const std::vector<gapshapes::Shape> all = gapshapes::shapes();
    const gapshapes::Shape* sp = nullptr;
    for (const gapshapes::Shape& s : all)
        if (s.id == "N07_wide") sp = &s;
    assert_non_null(sp);
    const gapshapes::Shape& s = *sp;
    const int n = s.nx * s.ny;
    std::vector<double> sorted = s.h;
    std::sort(sorted.begin(), sorted.end());
    auto set_below = [&](int rank) {
        std::vector<double> g(n);
        for (int k = 0; k < n; ++k) g[k] = s.h[k] < sorted[rank] ? 1.0 : 0.0;
        return g;
    };
    cw::GridConvolution conv(s.nx, s.ny, cw::ConvolutionUse::tangential);
    conv.set_coefficients(s.dy / s.dx, s.nu);
    cw::CoarseCorrection followed, fresh;
    followed.reserve(n);
    fresh.reserve(n);
    for (int rank : {1200, 1230, 1185}) followed.set_space(conv, true, 0.0, s.nx, s.ny, set_below(rank));
    fresh.set_space(conv, true, 0.0, s.nx, s.ny, set_below(1185));
    assert_int_equal(followed.columns(), fresh.columns());
    double scale = 0.0;
    for (int c = 0; c < fresh.columns(); ++c)
        for (int k = 0; k < n; ++k) scale = std::max(scale, std::abs(fresh.bp(c)[k]));
    for (int c = 0; c < fresh.columns(); ++c)
        for (int k = 0; k < n; ++k) {
            assert_close(followed.bp(c)[k].real(), fresh.bp(c)[k].real(), 0.0, 1e-12 * scale);
            assert_close(followed.bp(c)[k].imag(), fresh.bp(c)[k].imag(), 0.0, 1e-12 * scale);
        }
}

// The exact normal problem held for warm solves (GapNormal with the warm
// option, as the exact model makes it) along a drifting gap, the force
// prescribed (N04_crescent's gap times 1 + 0.01 sin(2 pi k / 100), raised
// by 0.2 um sin(2 pi k / 100 + 1)), then the approach (drifting by 1 % in
// phase with the shape): every step's pressure within 1e-8 of the peak and
// the approach within 1e-9 of a cold solve's (both solved to 1e-10 of the
// depth; measured 2.6e-9 and 4e-12); the same calls on a second handle give
// the same bits; the start predicted along the drift (pressure_drift.hpp)
// with its product predicted from the solutions' (no FFT product for the
// first pass's) keeps the steps at 8.0 (force) and 13.5 (approach) FFT
// products of the half-space problem over these 12 steps (the start's
// product taken: 8.5 and 14.3; from the last pressure alone: 21.5 and
// 21.0), bounded 5 % above.
void warm_normal_solves_follow_a_drifting_gap(void**)
{
    static const std::vector<gapshapes::Shape> all = gapshapes::shapes();
    const gapshapes::Shape* sp = nullptr;
    for (const gapshapes::Shape& s : all)
        if (s.id == "N04_crescent") sp = &s;
    assert_non_null(sp);
    const gapshapes::Shape& s = *sp;
    const cw::GridSpec g = gapshapes::grid_of(s);
    cw::GapNormal a(g, cw::GapNormalOptions{true, true}), b(g, cw::GapNormalOptions{true, true});
    cw::ContactInput in = gapshapes::contact_input(s);
    in.model = cw::ModelKind::exact;
    in.normal_method = cw::NormalMethod::exact;
    std::vector<double> h = s.h;
    in.gap = h.data();
    const int steps = 12;
    for (const cw::NormalLoad load : {cw::NormalLoad::force, cw::NormalLoad::approach}) {
        in.normal_load = load;
        a.solve(in, false);
        b.solve(in, false);
        const double approach0 = a.approach();
        long products = 0;
        double worst_p = 0.0, worst_a = 0.0;
        for (int k = 1; k <= steps; ++k) {
            const double t = 2.0 * kPi * k / 100.0;
            for (size_t q = 0; q < h.size(); ++q)
                h[q] = s.h[q] * (1.0 + 0.01 * std::sin(t)) + 2e-7 * std::sin(t + 1.0);
            in.approach = approach0 * (1.0 + 0.01 * std::sin(t));
            products += a.solve(in, true).normal_products;
            b.solve(in, true);
            assert_memory_equal(a.pressure().data(), b.pressure().data(), h.size() * sizeof(double));
            cw::GapNormal cold(g, cw::GapNormalOptions{false, true});
            cold.solve(in, false);
            double peak = 0.0;
            for (size_t q = 0; q < h.size(); ++q) {
                peak = std::max(peak, cold.pressure()[q]);
                worst_p = std::max(worst_p, std::fabs(a.pressure()[q] - cold.pressure()[q]));
            }
            worst_p /= peak;
            worst_a = std::max(worst_a, std::fabs(a.approach() / cold.approach() - 1.0));
        }
        const bool force = load == cw::NormalLoad::force;
        print_message("%s prescribed: %.2f products a warm step; pressure %.2g of the peak, "
                      "approach %.2g relative\n", force ? "force" : "approach",
                      double(products) / steps, worst_p, worst_a);
        assert_true(worst_p <= 1e-8);
        assert_true(worst_a <= 1e-9);
        assert_true(double(products) / steps <= (force ? 8.0 : 13.5) * 1.05);
    }
}

void semi_hertz_reproduces_hertz_on_a_paraboloid(void**)
{
    const double A = 1.0 / (2 * 0.46), B = 1.0 / (2 * 0.3), N = 80e3, G = 82e9, nu = 0.28;
    const double E = G / (1.0 - nu);
    const cw::HertzContact hz = cw::hertz_from_curvatures(A, B, N, E);
    for (int n : {40, 80}) {
        const double dx = 3.0 * hz.a / n, dy = 3.0 * hz.b / n;
        std::vector<double> h(n * n), p(n * n);
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double x = (i + 0.5 - 0.5 * n) * dx, y = (j + 0.5 - 0.5 * n) * dy;
                h[i + n * j] = A * x * x + B * y * y + 1e-6; // a datum 1 um below
            }
        cw::SemiHertz sh(n, n);
        const cw::SemiHertzResult r = sh.solve(h.data(), dx, dy, E, true, N, p.data());
        const double pmax = *std::max_element(p.begin(), p.end());
        print_message("%d x %d: p_max %.3g, approach %.3g from Hertz's, %d force evaluations\n",
                      n, n, pmax / hz.p0 - 1.0, (r.approach - 1e-6) / hz.approach - 1.0,
                      r.iterations);
        assert_close(r.normal_force, N, 1e-12, 0.0);
        // The element sum of the ellipse converges as (dx/a)^(3/2).
        const double tol = 2.0 * std::pow(3.0 / n, 1.5);
        assert_close(r.approach - 1e-6, hz.approach, tol, 0.0);
        assert_close(pmax, hz.p0, tol, 0.0);
        // The approach prescribed: no iteration, the same pressures.
        std::vector<double> q(n * n);
        const cw::SemiHertzResult ra = sh.solve(h.data(), dx, dy, E, false, r.approach, q.data());
        assert_close(ra.normal_force, N, 1e-9, 0.0);
    }
}

// The row fit widens only while both elements of the next pair penetrate by
// more than 30 % of the row's locus; the higher of the pair decides. Hertz's
// paraboloid (A < B: alpha = f, the rigid overlap at 30 % of the depth lies
// at 1.2 a on the middle row, outside the contact) with every element from
// x = 1.07 a on raised by 1 mm, on one side only: the band lies outside the
// contact, but within the fit's reach on the other side. The fit stops at
// the pair that holds the band's first element, so it sees the paraboloid
// alone (exact: a least-squares parabola of a parabola) and every element's
// pressure is Hertz's p0^2 (1 - x^2/a^2 - y^2/b^2) at the approach of N
// (Johnson 1985, eqs. 4.38-4.39), to the shape table's 1e-8; a fit that
// reaches the band curves the rows far more.
void semi_hertz_fit_stops_at_the_higher_of_a_pair(void**)
{
    const double A = 1.0 / (2 * 0.46), B = 1.0 / (2 * 0.3), N = 80e3, G = 82e9, nu = 0.28;
    const double E = G / (1.0 - nu), datum = 1e-6;
    const cw::HertzContact hz = cw::hertz_from_curvatures(A, B, N, E);
    const int n = 17, mid = n / 2; // element mid at x = y = 0
    const double dx = 2.6 * hz.a / n, dy = 2.6 * hz.b / n;
    std::vector<double> h(n * n), p(n * n), plain(n * n);
    for (int banded = 0; banded < 2; ++banded) {
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double x = (i - mid) * dx, y = (j - mid) * dy;
                const bool band = banded && x >= 1.07 * hz.a;
                h[i + n * j] = A * x * x + B * y * y + datum + (band ? 1e-3 : 0.0);
            }
        cw::SemiHertz sh(n, n);
        const cw::SemiHertzResult r =
            sh.solve(h.data(), dx, dy, E, false, hz.approach + datum, p.data());
        double worst = 0.0, sum = 0.0;
        int in_band = 0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double x = (i - mid) * dx, y = (j - mid) * dy;
                const double q = 1.0 - x * x / (hz.a * hz.a) - y * y / (hz.b * hz.b);
                const double expected = q > 0.0 ? hz.p0 * hz.p0 * q : 0.0;
                const double pk = p[i + n * j];
                worst = std::max(worst, std::fabs(pk * pk - expected));
                sum += pk;
                in_band += x >= 1.07 * hz.a && pk > 0.0;
            }
        print_message("%s: p^2 within %.2g p0^2 of Hertz's, Fn %.6g N\n",
                      banded ? "band on one side" : "paraboloid", worst / (hz.p0 * hz.p0),
                      r.normal_force);
        assert_true(worst <= 1e-7 * hz.p0 * hz.p0);
        assert_int_equal(in_band, 0);
        assert_close(r.normal_force, sum * dx * dy, 1e-12, 0.0);
        if (!banded)
            plain = p;
        else
            for (int k = 0; k < n * n; ++k) assert_close(p[k], plain[k], 1e-12, 1e-12 * hz.p0);
    }
}

// The DEV gaps through the semi-Hertzian method against CONTACT's ANALYN
// (B = 6, its approach iterated to the force, |Fn/N - 1| <= 1e-12): an
// independent implementation of one method, so element counts are equal
// and p_max, approach agree to CONTACT's Hertz solve (its hzcalc3d stops at
// a relative change of 1e-6, which left 1.4e-5 in p_max; this table is good
// to 1e-9).
void semi_hertz_matches_contacts_analyn(void**)
{
    const cwtest::CsvTable fm =
        cwtest::read_csv(cwtest::test_data_path("nonhertz/dev/fast_methods.csv"));
    int compared = 0;
    double dp = 0.0, da = 0.0;
    for (const cwtest::GapCase& c : cwtest::dev_cases()) {
        size_t row = fm.rows.size();
        for (size_t r = 0; r < fm.rows.size(); ++r)
            if (fm.text(r, "case_id") == c.id && fm.text(r, "method") == "analyn-fastsim") row = r;
        assert_true(row < fm.rows.size());
        const cw::GridSpec& g = c.gap.grid;
        cw::SemiHertz sh(g.nx, g.ny);
        std::vector<double> p(c.gap.h.size());
        const cw::SemiHertzResult r = sh.solve(c.gap.h.data(), g.dx, g.dy,
                                               c.input.G / (1.0 - c.input.nu), true,
                                               c.input.normal_force, p.data());
        const double pmax = *std::max_element(p.begin(), p.end());
        assert_int_equal(r.n_contact, static_cast<int>(fm.number(row, "n_contact")));
        dp = std::max(dp, std::fabs(pmax / fm.number(row, "p_max_Pa") - 1.0));
        da = std::max(da, std::fabs(r.approach / fm.number(row, "approach_m") - 1.0));
        ++compared;
    }
    assert_int_equal(compared, 15);
    print_message("against CONTACT's ANALYN: p_max %.2g, approach %.2g relative\n", dp, da);
    assert_true(dp <= 3e-5 && da <= 3e-5);
}

// dN/d(approach) of both normal methods (GapNormal::force_by_approach)
// against the central difference of the force at the approach +- 1e-4 of
// the depth, on the DEV gaps at their approach: to 3e-3 relative for the
// semi-Hertzian method's closed form (exact while no element's contact or
// row fit changes; on some gaps an element at a row's end enters contact
// within the step, where the force's slope has a 1 / sqrt; 1.3e-3
// measured), to 1e-3 for the half-space problem's linearisation (the
// solves' own 1e-10 tolerance over the step, and contact-set changes at
// the edge; 4e-4 measured).
void normal_methods_give_the_force_by_approach(void**)
{
    double worst[2] = {0.0, 0.0};
    for (const cwtest::GapCase& c : cwtest::dev_cases()) {
        const cw::GridSpec& g = c.gap.grid;
        for (const cw::NormalMethod method : {cw::NormalMethod::semi_hertz, cw::NormalMethod::exact}) {
            cw::GapNormal normal(g, cw::GapNormalOptions{});
            cw::ContactInput in = c.input;
            in.gap = c.gap.h.data();
            in.gap_len = c.gap.h.size();
            in.normal_method = method;
            normal.solve(in, false); // the force prescribed: its approach
            const double approach = normal.approach();
            const double depth = approach - *std::min_element(c.gap.h.begin(), c.gap.h.end());
            in.normal_load = cw::NormalLoad::approach;
            in.approach = approach;
            normal.solve(in, false);
            const double slope = normal.force_by_approach();
            const double step = 1e-4 * depth;
            double f[2];
            for (int s = 0; s < 2; ++s) {
                in.approach = approach + (s ? step : -step);
                normal.solve(in, false);
                f[s] = normal.force();
            }
            const double fd = (f[1] - f[0]) / (2.0 * step);
            const int m = method == cw::NormalMethod::exact;
            worst[m] = std::max(worst[m], std::fabs(slope / fd - 1.0));
        }
    }
    print_message("dN/d(approach) against central differences: semi-Hertz %.2g, exact %.2g\n", worst[0],
                  worst[1]);
    assert_true(worst[0] <= 3e-3);
    assert_true(worst[1] <= 1e-3);
}

std::vector<signed char> mask(const char* rows[], int ny)
{
    const int nx = static_cast<int>(std::strlen(rows[0]));
    std::vector<signed char> m(nx * ny);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) m[i + nx * j] = rows[j][i] == '#';
    return m;
}

// 4-connected components, numbered by first element in [i + nx j].
void patches_are_edge_connected(void**)
{
    const char* rows[] = {"##..#.",  // j = 0
                          ".#..#.",  // an L joined at (1, 1); a bar at i = 4
                          "..#..#",  // (2, 2) touches (1, 1) only by a corner
                          "......",
                          "######"}; // one row-long patch
    const std::vector<signed char> m = mask(rows, 5);
    cw::PatchLabels L(6, 5);
    assert_int_equal(L.label(m.data()), 5);
    const int expect[5][6] = {{0, 0, -1, -1, 1, -1},
                              {-1, 0, -1, -1, 1, -1},
                              {-1, -1, 2, -1, -1, 3},
                              {-1, -1, -1, -1, -1, -1},
                              {4, 4, 4, 4, 4, 4}};
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 6; ++i) assert_int_equal(L.of(i + 6 * j), expect[j][i]);
    // A checkerboard: every element its own patch; an empty mask: none.
    std::vector<signed char> chess(8 * 8), none(8 * 8, 0);
    for (int k = 0; k < 64; ++k) chess[k] = ((k % 8) + (k / 8)) % 2;
    cw::PatchLabels C(8, 8);
    assert_int_equal(C.label(chess.data()), 32);
    assert_int_equal(C.label(none.data()), 0);
    assert_int_equal(C.of(0), -1);
}

} // namespace

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(gap_problem_matches_the_hertzian_path),
        cmocka_unit_test(box_products_match_the_whole_grid),
        cmocka_unit_test(normal_problem_on_the_box_matches_the_whole_grid),
        cmocka_unit_test(pressure_drift_follows_a_linear_drift),
        cmocka_unit_test(warm_normal_solves_follow_a_drifting_gap),
        cmocka_unit_test(semi_hertz_reproduces_hertz_on_a_paraboloid),
        cmocka_unit_test(semi_hertz_fit_stops_at_the_higher_of_a_pair),
        cmocka_unit_test(semi_hertz_matches_contacts_analyn),
        cmocka_unit_test(patches_are_edge_connected),
        cmocka_unit_test(normal_methods_give_the_force_by_approach),
        cmocka_unit_test(coarse_space_follows_the_contact_set),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
