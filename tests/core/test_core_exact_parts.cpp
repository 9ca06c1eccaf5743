// The exact model's building blocks against direct computation: the batched
// FFT against the DFT sum, the influence coefficients against CONTACT's
// logarithm form (m_visc.f90:elascf_pcwcns, doc/theory/exact-discretisation.md rule 3),
// the FFT products against direct sums over element pairs (odd and even
// sizes, dy != dx), the local Coulomb solve against its definition, and the
// warm steps' coarse correction against the products and its definition.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstring>
#include <random>
#include <vector>

#include "test_support.h"

#include "exact/coarse_correction.hpp"
#include "halfspace/batched_fft.hpp"
#include "exact/creepage_history.hpp"
#include "halfspace/grid_convolution.hpp"
#include "halfspace/influence.hpp"
#include "exact/local_friction.hpp"

namespace cw = creepwork;
using C = std::complex<double>;

namespace {

constexpr double kPi = 3.14159265358979323846;

void fft_matches_dft(void**)
{
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    for (int n : {1, 2, 3, 4, 5, 6, 12, 45, 50, 64, 90, 216}) {
        const int L = 3;
        std::vector<double> re(n * L), im(n * L), work(2 * n * L);
        for (double& v : re) v = U(gen);
        for (double& v : im) v = U(gen);
        const std::vector<double> re0 = re, im0 = im;
        cw::BatchedFft f(n);
        // Out of place: the same operations, so the same bits as in place
        // (any number of stages), and the input untouched.
        std::vector<double> out_re(n * L), out_im(n * L);
        f.transform(re0.data(), im0.data(), out_re.data(), out_im.data(), L, false, work.data());
        f.transform(re.data(), im.data(), L, false, work.data());
        assert_true(out_re == re && out_im == im);
        double err = 0.0;
        for (int l = 0; l < L; ++l)
            for (int k = 0; k < n; ++k) {
                C s = 0.0;
                for (int e = 0; e < n; ++e)
                    s += C(re0[e * L + l], im0[e * L + l]) * std::polar(1.0, -2 * kPi * k * e / n);
                err = std::max(err, std::abs(s - C(re[k * L + l], im[k * L + l])));
            }
        assert_true(err < 1e-13 * n);
        f.transform(re.data(), im.data(), L, true, work.data());
        for (int i = 0; i < n * L; ++i) {
            assert_close(re[i] / n, re0[i], 0.0, 1e-14);
            assert_close(im[i] / n, im0[i], 0.0, 1e-14);
        }
    }
    assert_int_equal(cw::BatchedFft::good_size(49), 50);
    assert_int_equal(cw::BatchedFft::good_size(209), 216);
    assert_int_equal(cw::BatchedFft::good_size(89), 96);   // not 90
    assert_int_equal(cw::BatchedFft::good_size(7), 8);
}

// The pruned transforms (extent < n: forward with the inputs from extent on
// zero, inverse with only the outputs before extent read) against the full
// ones: the same bits where the caller reads, in place and out of place, on
// every ISA the CPU runs, for every extent of lengths whose first and last
// stages have each radix (2, 3, 4, 5) and the benchmark's (40, 45, 50).
// Inputs hold signed zeros too: skipping the zero inputs' arithmetic must
// not change a sign.
void pruned_fft_gives_the_full_bits(void**)
{
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    for (cw::KernelIsa isa : {cw::KernelIsa::baseline, cw::KernelIsa::avx2, cw::KernelIsa::avx512}) {
        if (!cw::kernel_isa_supported(isa)) continue;
        for (int n : {6, 8, 10, 12, 15, 20, 24, 40, 45, 50, 75}) {
            const int L = 5;
            cw::BatchedFft f(n);
            f.set_kernel_isa(isa);
            std::vector<double> work(2 * n * L);
            for (int extent = 1; extent < n; ++extent)
                for (bool inverse : {false, true}) {
                    std::vector<double> re(n * L), im(n * L);
                    for (int e = 0; e < n; ++e)
                        for (int l = 0; l < L; ++l) {
                            const bool zero = !inverse && e >= extent;
                            const double r = U(gen), i = U(gen);
                            re[e * L + l] = zero ? 0.0 : r < -0.8 ? -0.0 : r;
                            im[e * L + l] = zero ? 0.0 : i > 0.8 ? -0.0 : i;
                        }
                    std::vector<double> full_re = re, full_im = im;
                    f.transform(full_re.data(), full_im.data(), L, inverse, work.data());
                    std::vector<double> out_re(n * L), out_im(n * L);
                    f.transform(re.data(), im.data(), out_re.data(), out_im.data(), L, inverse,
                                work.data(), extent);
                    f.transform(re.data(), im.data(), L, inverse, work.data(), extent);
                    const int shown = inverse ? extent : n;
                    bool same = true;
                    for (int k = 0; k < shown * L; ++k)
                        same = same && std::memcmp(&re[k], &full_re[k], sizeof(double)) == 0 &&
                               std::memcmp(&im[k], &full_im[k], sizeof(double)) == 0 &&
                               std::memcmp(&out_re[k], &full_re[k], sizeof(double)) == 0 &&
                               std::memcmp(&out_im[k], &full_im[k], sizeof(double)) == 0;
                    if (!same)
                        printf("n %d extent %d %s %s: not the full transform's bits\n", n, extent,
                               inverse ? "inverse" : "forward", cw::kernel_isa_name(isa));
                    assert_true(same);
                }
        }
    }
}

double x_log_y(double x, double y1, double y2)
{
    const double r1 = std::hypot(x, y1), r2 = std::hypot(x, y2);
    return x * std::log((y2 + r2) / (y1 + r1));
}

void coefficients_match_contact_form(void**)
{
    for (double rho : {1.0, 0.5, 2.0, 0.05}) {
        double worst = 0.0, scale = 0.0;
        for (int k = -12; k <= 12; ++k)
            for (int l = -9; l <= 9; ++l) {
                const double x0 = k - 0.5, x1 = k + 0.5, y0 = (l - 0.5) * rho, y1 = (l + 0.5) * rho;
                const double X = x_log_y(x1, y0, y1) - x_log_y(x0, y0, y1);
                const double Y = x_log_y(y1, x0, x1) - x_log_y(y0, x0, x1);
                const double R = -std::hypot(x0, y0) + std::hypot(x0, y1) + std::hypot(x1, y0) -
                                 std::hypot(x1, y1);
                const cw::InfluenceParts p = cw::influence_parts(k, l, rho);
                worst = std::max({worst, std::fabs(p.X - X), std::fabs(p.Y - Y), std::fabs(p.R - R)});
                scale = std::max(scale, std::fabs(X) + std::fabs(Y));
            }
        printf("  dy/dx = %.2f: largest difference to the logarithm form %.2g of the largest value\n", rho, worst / scale);
        // The logarithm form itself loses digits to y + r for long thin
        // elements (6e-12 at dy/dx = 0.05), the reason for the asinh form.
        assert_true(worst < 1e-10 * scale);
    }
    // Kalker 1990 / Johnson: the centre of a uniformly loaded square of side
    // h sinks by 2 (1 - nu^2)/(pi E) * 2 h asinh(1) under unit pressure; with
    // the two bodies and E = 2 G (1 + nu) that is cf33 / G = 2 (1 - nu) asinh(1) h / (pi G) * 2.
    cw::GridConvolution conv(3, 3);
    conv.set_coefficients(1.0, 0.3);
    assert_close(conv.cf33(0, 0), (1.0 - 0.3) * 4.0 * std::asinh(1.0) / kPi, 1e-14, 0.0);
}

// The tangential product of conv on its nx x ny field against direct sums.
void check_tangential(cw::GridConvolution& conv, const std::vector<C>& z, bool steady)
{
    const int nx = conv.nx(), n = nx * conv.ny();
    std::vector<C> s(n);
    conv.apply_tangential(z.data(), s.data(), steady);
    for (int I = 0; I < n; ++I) {
        double sx = 0.0, sy = 0.0;
        for (int J = 0; J < n; ++J) {
            const int k = I % nx - J % nx, l = I / nx - J / nx;
            double a11 = conv.cf11(k, l), a12 = conv.cf12(k, l), a22 = conv.cf22(k, l);
            if (steady) {
                a11 -= conv.cf11(k + 1, l);
                a12 -= conv.cf12(k + 1, l);
                a22 -= conv.cf22(k + 1, l);
            }
            sx += a11 * z[J].real() + a12 * z[J].imag();
            sy += a12 * z[J].real() + a22 * z[J].imag();
        }
        assert_close(s[I].real(), sx, 0.0, 1e-13);
        assert_close(s[I].imag(), sy, 0.0, 1e-13);
    }
}

void products_match_direct_sums(void**)
{
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    for (int shape = 0; shape < 3; ++shape) {
        const int nx = shape == 0 ? 7 : shape == 1 ? 10 : 1, ny = shape == 0 ? 5 : shape == 1 ? 8 : 4;
        const double rho = shape == 1 ? 1.0 : 0.6, nu = 0.28;
        cw::GridConvolution conv(nx, ny);
        conv.set_coefficients(rho, nu);
        const int n = nx * ny;
        std::vector<C> z(n);
        std::vector<double> p(n), u(n), back(n);
        for (C& v : z) v = C(U(gen), U(gen));
        for (double& v : p) v = U(gen);
        for (int steady = 0; steady < 2; ++steady) check_tangential(conv, z, steady);
        // Again: the zero padding kept from the last product of this size.
        check_tangential(conv, z, true);
        conv.apply_normal(p.data(), u.data());
        for (int I = 0; I < n; ++I) {
            double v = 0.0;
            for (int J = 0; J < n; ++J) v += conv.cf33(I % nx - J % nx, I / nx - J / nx) * p[J];
            assert_close(u[I], v, 0.0, 1e-13);
        }
        // The preconditioner inverts the periodic kernel: on a grid as large
        // as the box it is close to the inverse, and it is finite.
        conv.apply_normal_inverse(u.data(), back.data());
        for (double v : back) assert_true(std::isfinite(v));
        // After the normal products (other layouts of the same buffers), and
        // on a smaller field of the same convolution with other values.
        check_tangential(conv, z, true);
        if (nx > 2) {
            conv.set_size(nx - 2, ny - 1);
            std::vector<C> zs((nx - 2) * (ny - 1));
            for (C& v : zs) v = C(U(gen), U(gen));
            check_tangential(conv, zs, true);
            check_tangential(conv, zs, false);
        }
    }
}

// An elliptic contact set on nx x ny, off-centre (1 inside, 0 outside);
// ra, rb: the semi-axes over the grid's.
std::vector<double> elliptic_set(int nx, int ny, double ra = 0.46, double rb = 0.42)
{
    std::vector<double> g(static_cast<size_t>(nx) * ny, 0.0);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const double x = (i - 0.45 * nx) / (ra * nx), y = (j - 0.5 * ny) / (rb * ny);
            if (x * x + y * y < 1.0) g[i + nx * j] = 1.0;
        }
    return g;
}

// The coarse correction's B P (exact/coarse_correction.hpp: sums of the
// influence coefficients) against the FFT product of each aggregate's
// indicator with the layer's share (steady_rolling.hpp: c (v - v_ahead)
// rolling, c v shift), at every contact element: both operators, with and
// without the layer, on two grids (several aggregate sides), as the contact
// set changes.
void coarse_space_matches_products(void**)
{
    for (int shape = 0; shape < 2; ++shape) {
        const int nx = shape == 0 ? 14 : 24, ny = shape == 0 ? 11 : 24;
        const int n = nx * ny;
        cw::GridConvolution conv(nx, ny);
        conv.set_coefficients(shape == 0 ? 0.8 : 1.0, 0.28);
        // The set, a narrower and longer one (elements leave and join
        // within the blocks: B P updated in place), and the first again.
        const std::vector<double> sets[3] = {elliptic_set(nx, ny), elliptic_set(nx, ny, 0.42, 0.45),
                                             elliptic_set(nx, ny)};
        std::vector<C> v(n), s(n);
        for (int rolling = 0; rolling < 2; ++rolling)
            for (double layer : {0.0, 0.3}) {
                cw::CoarseCorrection cc;
                cc.reserve(n);
                for (const std::vector<double>& g : sets) {
                int contact = 0;
                for (double e : g) contact += e > 0.0;
                cc.set_space(conv, rolling, layer, nx, ny, g);
                assert_true(cc.columns() >= 8 && cc.columns() <= 2 * cw::kMaxAggregates);
                int members = 0;
                for (int c = 0; c < cc.columns(); ++c) {
                    std::fill(v.begin(), v.end(), C(0.0, 0.0));
                    cc.indicator(c, v.data());
                    for (int k = 0; k < n; ++k) members += v[k] != C(0.0, 0.0);
                    conv.apply_tangential(v.data(), s.data(), rolling);
                    double scale = 0.0;
                    for (int k = 0; k < n; ++k) {
                        const int i = k % nx;
                        const C ahead = rolling && i + 1 < nx ? v[k + 1] : C(0.0, 0.0);
                        s[k] += layer * (v[k] - ahead);
                        scale = std::max(scale, std::abs(s[k]));
                    }
                    for (int k = 0; k < n; ++k) {
                        if (!(g[k] > 0.0)) continue;
                        assert_close(cc.bp(c)[k].real(), s[k].real(), 0.0, 1e-13 * scale);
                        assert_close(cc.bp(c)[k].imag(), s[k].imag(), 0.0, 1e-13 * scale);
                    }
                }
                // Every contact element in one aggregate, once per component.
                assert_int_equal(members, 2 * contact);
                }
            }
    }
}

// The correction M u = u + W T^-1 P^T u with T = P^T (P - W) inverts K =
// I - G' on the aggregates' space whatever W = G' P is: M (P - W) y = P y
// for any coarse y (coarse_correction.hpp), here with W random at the
// contact elements.
void coarse_correction_inverts_its_space(void**)
{
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    const int nx = 24, ny = 24, n = nx * ny;
    cw::GridConvolution conv(nx, ny);
    conv.set_coefficients(1.0, 0.28);
    const std::vector<double> g = elliptic_set(nx, ny);
    cw::CoarseCorrection cc;
    cc.reserve(n);
    cc.set_space(conv, true, 0.0, nx, ny, g);
    const int m = cc.columns();
    for (int c = 0; c < m; ++c)
        for (int k = 0; k < n; ++k) cc.gp(c)[k] = g[k] > 0.0 ? C(U(gen), U(gen)) : C(0.0, 0.0);
    assert_true(cc.factor());
    assert_true(cc.active());
    std::vector<C> u(n, C(0.0, 0.0)), py(n, C(0.0, 0.0)), p(n, C(0.0, 0.0)), x(n);
    for (int c = 0; c < m; ++c) {
        const double y = U(gen);
        std::fill(p.begin(), p.end(), C(0.0, 0.0));
        cc.indicator(c, p.data());
        for (int k = 0; k < n; ++k) {
            py[k] += y * p[k];
            u[k] += y * (p[k] - cc.gp(c)[k]);
        }
    }
    cc.apply(u.data(), x.data());
    for (int k = 0; k < n; ++k) {
        // (T with a random W is far from the identity: rounding to 1e-10.)
        assert_close(x[k].real(), py[k].real(), 0.0, 1e-10);
        assert_close(x[k].imag(), py[k].imag(), 0.0, 1e-10);
    }
}

// A tangential convolution given the spectra of a normal one (the gap
// model's fine grid from the normal problem's box products): the products
// are bitwise those of a convolution that made its own, and nothing is
// copied from a convolution of another FFT size or other coefficients.
void copied_spectra_give_the_same_products(void**)
{
    std::mt19937 gen(13);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    const int nx = 24, ny = 22, bx = 19, by = 17;
    const double rho = 0.8, nu = 0.28;
    cw::GridConvolution whole(nx, ny, cw::ConvolutionUse::normal);
    whole.set_coefficients(rho, nu);
    cw::GridConvolution box(nx, ny, cw::ConvolutionUse::normal);
    box.set_size(bx, by);
    box.copy_coefficients(whole);
    std::vector<double> p(bx * by), u(bx * by);
    for (double& v : p) v = U(gen);
    box.apply_normal(p.data(), u.data()); // makes its spectra
    cw::GridConvolution own(nx, ny, cw::ConvolutionUse::tangential),
        copied(nx, ny, cw::ConvolutionUse::tangential);
    for (cw::GridConvolution* c : {&own, &copied}) {
        c->set_size(bx, by);
        c->copy_coefficients(whole);
    }
    // Not from a convolution without spectra, of another size or material.
    cw::GridConvolution fresh(nx, ny, cw::ConvolutionUse::normal);
    fresh.set_size(bx, by);
    fresh.copy_coefficients(whole);
    assert_false(copied.copy_pair_spectra(fresh));
    cw::GridConvolution other_size(nx, ny, cw::ConvolutionUse::normal);
    other_size.set_size(bx - 4, by);
    other_size.copy_coefficients(whole);
    other_size.apply_normal(p.data(), u.data());
    assert_false(copied.copy_pair_spectra(other_size));
    cw::GridConvolution other_nu(nx, ny, cw::ConvolutionUse::normal);
    other_nu.set_size(bx, by);
    other_nu.set_coefficients(rho, 0.3);
    other_nu.apply_normal(p.data(), u.data());
    assert_false(copied.copy_pair_spectra(other_nu));
    assert_true(copied.copy_pair_spectra(box));
    assert_false(copied.copy_pair_spectra(box)); // has them now
    std::vector<C> z(bx * by), s_own(bx * by), s_copied(bx * by);
    for (C& v : z) v = C(U(gen), U(gen));
    for (bool steady : {true, false}) {
        own.apply_tangential(z.data(), s_own.data(), steady);
        copied.apply_tangential(z.data(), s_copied.data(), steady);
        assert_memory_equal(s_own.data(), s_copied.data(), s_own.size() * sizeof(C));
    }
}

void local_friction_solves_coulomb(void**)
{
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> U(-3.0, 3.0);
    for (int t = 0; t < 2000; ++t) {
        const C c(U(gen), U(gen));
        const double b1 = 0.5 + std::fabs(U(gen)), b2 = 0.5 + std::fabs(U(gen));
        const double g = t % 7 == 0 ? 0.0 : std::fabs(U(gen));
        C q;
        cw::LocalJacobian J;
        const bool slip = cw::solve_local_friction(c, b1, b2, g, q, J);
        const C s(c.real() + b1 * q.real(), c.imag() + b2 * q.imag());
        if (!slip) {
            assert_true(std::abs(s) < 1e-12 * (1 + std::abs(c)));
            assert_true(std::abs(q) <= g * (1 + 1e-15));
        } else {
            assert_close(std::abs(q), g, 1e-13, 0.0);
            if (g > 0.0) // q = -g s / |s|
                assert_true(std::abs(q + g * s / std::abs(s)) < 1e-10 * (1 + g));
        }
        // The derivative against a difference quotient (away from the switch).
        const double h = 1e-7;
        C qp, qm;
        cw::LocalJacobian dummy;
        const bool sp = cw::solve_local_friction(c + C(h, 0), b1, b2, g, qp, dummy);
        const bool sm = cw::solve_local_friction(c - C(h, 0), b1, b2, g, qm, dummy);
        if (sp == slip && sm == slip && g > 0.0 && std::abs(s) > 1e-3) {
            const C d = (qp - qm) / (2 * h);
            assert_close(d.real(), J.j11, 1e-5, 1e-6);
            assert_close(d.imag(), J.j21, 1e-5, 1e-6);
        }
    }
}

} // namespace

// The warm start's prediction on a traction cubic in the step t along a
// creepage path c(t) = (t, t^2, 0) (the secant step's weights are then
// exactly the quadratic extrapolation's: 3, -3, 1). Its error is that of
// quadratic extrapolation of a cubic, q(t + 1) - 3 q(t) + 3 q(t - 1) -
// q(t - 2) = 6 d for q = a + b t + c t^2 + d t^3; with the last error added
// (the four newest solutions in the same states) the prediction is exact.
void history_predicts_a_drift(void**)
{
    const C a(0.3, -0.1), b(0.02, 0.01), c2(-0.004, 0.003), d(5e-4, -2e-4);
    auto q_of = [&](double t) { return a + t * (b + t * (c2 + t * d)); };
    auto c_of = [](double t, double* c) {
        c[0] = t;
        c[1] = t * t;
        c[2] = 0.0;
    };
    const double key[cw::CreepageHistory::kKey] = {1.0, 0.28, 1.15, 1.0};
    for (int change : {-1, 5}) { // the step at which the element changes state (-1: never)
        cw::CreepageHistory h;
        h.resize(1);
        std::vector<C> q(1);
        signed char state = 2;
        for (int t = 0; t <= 12; ++t) {
            double c[3];
            c_of(t, c);
            if (t > 0) {
                assert_true(h.predict(key, c, q));
                // Corrected from step 4 on (the solution of step `change` is
                // predicted from the old states), and again four solutions
                // after the change; the secant step alone between (three
                // solutions from step 3 on).
                const bool corrected = t >= 4 && (change < 0 || t <= change || t >= change + 4);
                if (corrected)
                    assert_close(std::abs(q[0] - q_of(t)), 0.0, 0.0, 1e-13);
                else if (t >= 3)
                    assert_close(std::abs(q[0] - q_of(t)), std::abs(6.0 * d), 1e-9, 0.0);
            }
            if (t == change) state = 1;
            q[0] = q_of(t);
            h.remember(key, c, q, 1.0, &state);
        }
    }
}

// The same on a quartic q = a + ... + d t^3 + e t^4: quadratic
// extrapolation's error is then E(t) = q(t) - 3 q(t - 1) + 3 q(t - 2) -
// q(t - 3) = 6 d + (24 t - 36) e, linear in t. The last error added leaves E(t) - E(t - 1) = 24 e; once the
// five newest solutions share their states the error is extrapolated
// linearly from the last two, 2 E(t - 1) - E(t - 2) = E(t), and the
// prediction is exact.
void history_extrapolates_the_error(void**)
{
    const C a(0.3, -0.1), b(0.02, 0.01), c2(-0.004, 0.003), d(5e-4, -2e-4), e(2e-5, 3e-5);
    auto q_of = [&](double t) { return a + t * (b + t * (c2 + t * (d + t * e))); };
    const double key[cw::CreepageHistory::kKey] = {1.0, 0.28, 1.15, 1.0};
    for (int change : {-1, 5}) { // the step at which the element changes state (-1: never)
        cw::CreepageHistory h;
        h.resize(1);
        std::vector<C> q(1);
        signed char state = 2;
        for (int t = 0; t <= 14; ++t) {
            const double c[3] = {double(t), double(t) * t, 0.0};
            if (t > 0) {
                assert_true(h.predict(key, c, q));
                const bool same4 = change < 0 || t <= change || t >= change + 4;
                const bool same5 = change < 0 || t <= change || t >= change + 5;
                const double err = std::abs(q[0] - q_of(t));
                if (t >= 5 && same5)
                    assert_close(err, 0.0, 0.0, 1e-12);
                else if (t >= 4 && same4)
                    assert_close(err, 24.0 * std::abs(e), 1e-9, 0.0);
                else if (t >= 3)
                    assert_close(err, std::abs(6.0 * d + (24.0 * t - 36.0) * e), 1e-9, 0.0);
            }
            if (t == change) state = 1;
            q[0] = q_of(t);
            h.remember(key, c, q, 1.0, &state);
        }
    }
}

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(fft_matches_dft),
        cmocka_unit_test(pruned_fft_gives_the_full_bits),
        cmocka_unit_test(coefficients_match_contact_form),
        cmocka_unit_test(products_match_direct_sums),
        cmocka_unit_test(copied_spectra_give_the_same_products),
        cmocka_unit_test(coarse_space_matches_products),
        cmocka_unit_test(coarse_correction_inverts_its_space),
        cmocka_unit_test(local_friction_solves_coulomb),
        cmocka_unit_test(history_predicts_a_drift),
        cmocka_unit_test(history_extrapolates_the_error),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
