// The friction laws of the slip speed, friction memory, FASTSIM's slipping
// element under a law and Polach's creep-force model, as pure functions:
// against CONTACT's formulas (m_friclaw.f90, evaluated here in CONTACT's own
// units, mm/s), their closed forms, central differences, Kalker's linear
// theory and the Polach table of doc/theory/friction.md.
#include "contact_friction_formula.hpp"
#include "core_test_support.hpp"
#include "test_support.h"

#include "contact/error.hpp"
#include "contact/kalker_coefficients.hpp"
#include "friction/slip_speed_law.hpp"
#include "friction/friction_memory.hpp"
#include "friction/global_slip.hpp"
#include "friction/local_slip.hpp"
#include "friction/polach_model.hpp"
#include "friction/slip_speed_law_lanes.hpp"
#include "simd/simd_exp.hpp"

#include <cfloat>
#include <cmath>
#include <string>
#include <vector>

namespace cw = creepwork;

namespace {

using cwtest::contact_mu_steady;

cw::SlipSpeedLaw law_of(cw::SlipSpeedLawKind kind, double kin, double e1, double h1, double e2,
                       double h2)
{
    cw::SlipSpeedLaw law;
    law.kind = kind;
    law.mu_kin = kin;
    law.mu_e1 = e1;
    law.s_h1 = h1;
    law.mu_e2 = e2;
    law.s_h2 = h2;
    return law;
}

const cw::SlipSpeedLawKind kFalling[] = {cw::SlipSpeedLawKind::linear, cw::SlipSpeedLawKind::rational,
                                        cw::SlipSpeedLawKind::exponential};

// Every form, two terms (tractcurv's extended set plus a second term), over
// 0 .. 20 m/s including both linear kinks: CONTACT's value to 1e-14.
void laws_match_contact_formulas(void**)
{
    for (const auto kind : kFalling) {
        const cw::SlipSpeedLaw law = law_of(kind, 0.14, 0.19, 1.25, 0.05, 0.3);
        for (int i = 0; i <= 400; ++i) {
            const double s = 0.05 * i; // m/s; includes 2 s_h1 = 2.5 and 2 s_h2 = 0.6
            const double ref = contact_mu_steady(int(kind), 0.14, 0.19, 1250.0, 0.05, 300.0, 1e3 * s);
            assert_close(cw::friction_value(law, s).mu, ref, 1e-14, 0.0);
        }
        assert_close(cw::static_friction(law), 0.14 + 0.19 + 0.05, 1e-15, 0.0);
    }
    // Coulomb: mu at every slip speed, slope 0.
    const cw::FrictionValue c = cw::friction_value(cw::coulomb_law(0.33), 7.0);
    assert_true(c.mu == 0.33 && c.dmu_ds == 0.0);
}

// Each term is halved at its half speed, in all three forms; far beyond,
// only mu_kin is left (the linear law exactly from 2 s_h on).
void terms_halve_at_half_speed(void**)
{
    for (const auto kind : kFalling) {
        const cw::SlipSpeedLaw one = law_of(kind, 0.1, 0.2, 0.8, 0.0, 0.0);
        assert_close(cw::friction_value(one, 0.8).mu, 0.1 + 0.1, 1e-15, 0.0);
        const cw::SlipSpeedLaw two = law_of(kind, 0.1, 0.0, 0.0, 0.2, 0.8);
        assert_close(cw::friction_value(two, 0.8).mu, 0.1 + 0.1, 1e-15, 0.0);
        assert_close(cw::friction_value(one, 0.0).mu, 0.3, 1e-15, 0.0);
        assert_close(cw::friction_value(one, 1e6).mu, 0.1, 1e-5, 0.0);
    }
    assert_true(cw::friction_value(law_of(cw::SlipSpeedLawKind::linear, 0.1, 0.2, 0.8, 0, 0), 1.6).mu ==
                0.1);
}

// dmu/ds against central differences, and the closed slopes at s = 0:
// -mu_e/(2 s_h) (linear), -mu_e/s_h (rational, first term), 0 (rational,
// second term), -ln2 mu_e/s_h (exponential).
void slopes_match_differences(void**)
{
    for (const auto kind : kFalling) {
        const cw::SlipSpeedLaw law = law_of(kind, 0.14, 0.19, 1.25, 0.05, 0.3);
        for (double s : {0.01, 0.2, 0.55, 1.0, 2.0, 3.7}) {
            const double h = 1e-6;
            const double fd = (cw::friction_value(law, s + h).mu - cw::friction_value(law, s - h).mu) /
                              (2 * h);
            assert_close(cw::friction_value(law, s).dmu_ds, fd, 1e-7, 1e-12);
        }
    }
    const double sh = 0.5, e = 0.2;
    assert_close(cw::friction_value(law_of(cw::SlipSpeedLawKind::linear, 0, e, sh, 0, 0), 0).dmu_ds,
                 -e / (2 * sh), 1e-15, 0);
    assert_close(cw::friction_value(law_of(cw::SlipSpeedLawKind::rational, 0, e, sh, 0, 0), 0).dmu_ds,
                 -e / sh, 1e-15, 0);
    assert_true(cw::friction_value(law_of(cw::SlipSpeedLawKind::rational, 0, 0, 0, e, sh), 0).dmu_ds ==
                0.0);
    assert_close(cw::friction_value(law_of(cw::SlipSpeedLawKind::exponential, 0, e, sh, 0, 0), 0).dmu_ds,
                 -std::log(2.0) * e / sh, 1e-15, 0);
    // The linear law's kink takes the right-hand slope.
    assert_true(cw::friction_value(law_of(cw::SlipSpeedLawKind::linear, 0, e, sh, 0, 0), 2 * sh).dmu_ds ==
                0.0);
}

// The kernels' exp (simd/simd_exp.hpp) against the C library's over
// [-700, 0] (every 3.5e-3, and near 0 every 1e-6): within its stated 1e-15
// relative. Below -700 and for NaN, exp(-700): a normal number.
void vector_exp_within_its_bound(void**)
{
    using V = cw::simd::Vec<2>;
    double worst = 0.0;
    auto check = [&](double x0, double x1) {
        const V x = {x0, x1};
        const V e = cw::simd::exp_nonpositive<2>(x);
        for (int l = 0; l < 2; ++l) {
            const double ref = std::exp(x[l]);
            worst = std::max(worst, std::fabs(e[l] - ref) / ref);
        }
    };
    for (int i = 0; i < 100000; ++i) check(-7e-3 * i, -7e-3 * i - 3.5e-3);
    for (int i = 0; i < 100000; ++i) check(-2e-6 * i, -2e-6 * i - 1e-6);
    check(0.0, -0.0);
    check(-DBL_MIN, -1e-300);
    check(-std::log(2.0), -0.5 * std::log(2.0));
    print_message("exp_nonpositive: worst relative error %.3g\n", worst);
    assert_true(worst <= 1e-15);
    const V low = cw::simd::exp_nonpositive<2>(V{-1e4, NAN});
    for (int l = 0; l < 2; ++l) {
        assert_close(low[l], std::exp(-700.0), 1e-15, 0.0);
        assert_true(low[l] >= DBL_MIN);
    }
}

// The kernels' form of every law (friction/slip_speed_law_lanes.hpp): mu_s m(s)
// against CONTACT's formula to 1e-14 and mu_s dm/ds against friction_value's
// slope to 1e-14 (relative, 1e-15 of mu_e / s_h absolute), over 0 .. 20
// m/s, with both terms, the first alone and the second alone (an absent
// term's half speed is not read: 1 m/s here); the curvature mu_s d2m/ds2
// (the march's Halley step) against central differences of that slope
// (step 1e-4 m/s, from s = 0.05 m/s) to 1e-6 of mu_e / s_h^2 (0.19/0.3^2),
// away from the linear law's kinks;
// the value and slope with it bitwise those without.
template <cw::SlipSpeedLawKind Kind>
void check_law_lanes(const cw::SlipSpeedLaw& law, const double* e)
{
    using V = cw::simd::Vec<2>;
    const double mu_s = cw::static_friction(law);
    const cw::SlipSpeedLawLanes<Kind, 2> lanes(law);
    const double curvature_scale = 1e-6 * 0.19 / (0.3 * 0.3);
    for (int i = 0; i <= 200; ++i) {
        const V s = {0.1 * i, 0.1 * i + 0.05};
        V m, dm, m2, dm2, d2m;
        lanes.value(s, m, dm);
        lanes.value(s, m2, dm2, d2m);
        for (int l = 0; l < 2; ++l) {
            assert_true(m2[l] == m[l] && dm2[l] == dm[l]);
            const double ref = contact_mu_steady(int(Kind), 0.14, e[0], 1e3 * e[1], e[2],
                                                 1e3 * e[3], 1e3 * s[l]);
            assert_close(mu_s * m[l], ref, 1e-14, 0.0);
            // Not at the linear law's kinks, where either side's slope is right.
            const bool kink = Kind == cw::SlipSpeedLawKind::linear &&
                              (std::fabs(s[l] - 2 * e[1]) < 1e-3 || std::fabs(s[l] - 2 * e[3]) < 1e-3);
            if (kink) continue;
            assert_close(mu_s * dm[l], cw::friction_value(law, s[l]).dmu_ds, 1e-14,
                         1e-15 * 0.19 / 0.3);
            const double h = 1e-4;
            if (s[l] < h) continue; // central differences need s >= h
            const double fd =
                (cw::friction_value(law, s[l] + h).dmu_ds - cw::friction_value(law, s[l] - h).dmu_ds) /
                (2 * h);
            assert_close(mu_s * d2m[l], fd, 0.0, curvature_scale);
        }
    }
}

void law_lanes_match_contact_formulas(void**)
{
    const double sets[3][4] = {{0.19, 1.25, 0.05, 0.3}, {0.19, 1.25, 0.0, 1.0}, {0.0, 1.0, 0.05, 0.3}};
    for (const auto kind : kFalling)
        for (const auto& e : sets) {
            const cw::SlipSpeedLaw law = law_of(kind, 0.14, e[0], e[1], e[2], e[3]);
            switch (kind) {
            case cw::SlipSpeedLawKind::linear:
                check_law_lanes<cw::SlipSpeedLawKind::linear>(law, e);
                break;
            case cw::SlipSpeedLawKind::rational:
                check_law_lanes<cw::SlipSpeedLawKind::rational>(law, e);
                break;
            default: check_law_lanes<cw::SlipSpeedLawKind::exponential>(law, e); break;
            }
        }
}

// Polach's form is the exponential law: the inputs CONTACT's tractcurv
// example gives for Polach's mu0 = 0.36, A = 0.38, B = 0.7 s/m (its fourth
// series: FKIN 0.1368, FEXP1 0.2232, SABSH1 990 mm/s, printed digits), and
// mu0 [(1 - A) exp(-B s) + A] itself.
void polach_form_is_exponential(void**)
{
    const cw::SlipSpeedLaw law = cw::polach_law(0.36, 0.38, 0.7);
    assert_true(law.kind == cw::SlipSpeedLawKind::exponential);
    assert_close(law.mu_kin, 0.1368, 0.0, 0.5e-4);
    assert_close(law.mu_e1, 0.2232, 0.0, 0.5e-4);
    assert_close(law.s_h1, 0.990, 0.0, 0.5e-3);
    for (double s : {0.0, 0.1, 1.0, 2.5, 10.0})
        assert_close(cw::friction_value(law, s).mu, 0.36 * ((1 - 0.38) * std::exp(-0.7 * s) + 0.38),
                     2e-15, 0.0);
}

void expect_invalid(const cw::SlipSpeedLaw& law, const char* name)
{
    try {
        cw::check_slip_speed_law(law);
        fail_msg("law accepted, expected an error naming %s", name);
    } catch (const cw::Error& e) {
        assert_int_equal(int(e.kind()), int(cw::ErrorKind::invalid_input));
        assert_true(std::string(e.what()).rfind(name, 0) == 0);
    }
}

void invalid_laws_name_their_input(void**)
{
    const auto E = cw::SlipSpeedLawKind::exponential;
    cw::check_slip_speed_law(law_of(E, 0.1, 0.2, 1.0, 0.0, 0.0)); // valid: mu_e2 = 0, s_h2 unread
    expect_invalid(law_of(E, -0.1, 0.2, 1.0, 0, 0), "mu_kin");
    expect_invalid(law_of(E, NAN, 0.2, 1.0, 0, 0), "mu_kin");
    expect_invalid(law_of(E, 0.1, -0.2, 1.0, 0, 0), "mu_e1");
    expect_invalid(law_of(E, 0.1, 0.2, 0.0, 0, 0), "s_h1");
    expect_invalid(law_of(E, 0.1, 0.2, 1.0, INFINITY, 1.0), "mu_e2");
    expect_invalid(law_of(E, 0.1, 0.2, 1.0, 0.1, -1.0), "s_h2");
    expect_invalid(cw::coulomb_law(-0.3), "mu_kin");
    for (auto bad : {std::vector<double>{-0.1, 0.4, 0.6}, {0.36, 1.5, 0.6}, {0.36, 0.4, 0.0}}) {
        try {
            cw::polach_law(bad[0], bad[1], bad[2]);
            fail_msg("Polach's form accepted");
        } catch (const cw::Error& e) {
            const std::string m = e.what();
            assert_true(m.rfind("mu", 0) == 0 || m.rfind("polach_A", 0) == 0 ||
                        m.rfind("polach_B", 0) == 0);
        }
    }
    try {
        cw::check_friction_memory({-1e-6, 0.0});
        fail_msg("negative memory distance accepted");
    } catch (const cw::Error& e) {
        assert_true(std::string(e.what()).rfind("memory_distance", 0) == 0);
    }
}

// At a constant slip speed the implicit Euler recursion has the closed form
// mu_i = mu_s + theta^(i+1) (mu_static - mu_s), theta = d_c/(d_c + dt max(s, s0));
// without memory mu_i = mu_s(s_i); below s0 the background speed counts.
void memory_closed_form(void**)
{
    const cw::SlipSpeedLaw law = law_of(cw::SlipSpeedLawKind::exponential, 0.14, 0.19, 1.25, 0, 0);
    const double dt = 0.2889e-3 / 10.0, d_c = 3e-6; // tractcurv: dx / V, d_c = 3 um
    for (double s : {0.5, 0.0002}) {
        const cw::FrictionMemory mem{d_c, 1e-3};
        std::vector<double> speed(48, s), mu(48);
        cw::memory_row(law, mem, dt, speed.data(), 48, mu.data());
        const double steady = cw::friction_value(law, s).mu;
        const double theta = d_c / (d_c + dt * std::max(s, 1e-3));
        for (int i = 0; i < 48; ++i)
            assert_close(mu[i], steady + std::pow(theta, i + 1) * (0.33 - steady), 1e-14, 1e-16);
        cw::memory_row(law, {0.0, 1e-3}, dt, speed.data(), 48, mu.data());
        for (int i = 0; i < 48; ++i) assert_true(mu[i] == steady);
    }
    // One element's mu_m(s): its slope against central differences, above s0.
    const cw::MemoryElement e{&law, {d_c, 1e-3}, dt, 0.3};
    for (double s : {0.01, 0.3, 2.0}) {
        const double h = 1e-6;
        const double fd = (cw::friction_value(e, s + h).mu - cw::friction_value(e, s - h).mu) / (2 * h);
        assert_close(cw::friction_value(e, s).dmu_ds, fd, 1e-7, 1e-12);
    }
}

// The slipping element: Coulomb's law gives t = pn mu at once; a falling
// law's root satisfies t = pn mu(c (P - t)) to rounding and lies below
// Coulomb's with mu(0).
void local_slip_solves_the_law(void**)
{
    const double pn = 640e6, c = 10.0 * 5.5e-14 / 0.2889e-3; // V L / h, tractcurv
    const cw::LocalSlip coulomb = cw::local_slip(cw::coulomb_law(0.33), 300e6, pn, c);
    assert_close(coulomb.t, 0.33 * pn, 1e-15, 0.0);
    const cw::SlipSpeedLaw law = law_of(cw::SlipSpeedLawKind::exponential, 0.14, 0.19, 1.25, 0, 0);
    for (double P : {0.34 * pn, 0.5 * pn, 2.0 * pn, 40.0 * pn}) {
        const cw::LocalSlip r = cw::local_slip(law, P, pn, c);
        assert_close(r.t, pn * cw::friction_value(law, c * (P - r.t)).mu, 1e-14, 0.0);
        assert_true(r.t <= 0.33 * pn && r.t > 0.14 * pn);
        assert_close(r.s, c * (P - r.t), 1e-15, 0.0);
    }
}

// tractcurv's Eurosprinter contact (CONTACT examples/tractcurv.inp: a =
// 6.304 mm, b = 12.61 mm, Q = 106.7 kN, G = 82 GPa, V = 10 m/s) with
// Kalker's C11 = 3.765 (his table at nu = 0.28, a/b = 0.5), as the table of
// doc/theory/friction.md takes it.
cw::PolachInput eurosprinter(double mu0, double A, double B, double kA, double kS, double xi)
{
    cw::PolachInput in;
    in.Q = 106.7e3;
    in.a = 6.304e-3;
    in.b = 12.61e-3;
    in.G = 82e9;
    in.C11 = 3.765;
    in.C22 = 3.0;
    in.C23 = 0.9;
    in.xi_x = xi;
    in.V = 10.0;
    in.law = cw::polach_law(mu0, A, B);
    in.k_A = kA;
    in.k_S = kS;
    return in;
}

// The dry and wet sets (mu0, A, B, k_A, k_S = 0.55, 0.4, 0.6 s/m, 1.0, 0.4
// and 0.30, 0.4, 0.2 s/m, 0.3, 0.1): F/Q at 0.1, 0.4, 2, 10 and 25 % and the
// peak, to 1e-4 of the table (its digits).
void polach_table(void**)
{
    struct Row {
        double mu0, A, B, kA, kS;
        double f[5];
        double peak, at;
    };
    const Row rows[] = {
        {0.55, 0.4, 0.6, 1.0, 0.4, {0.1495, 0.3348, 0.4468, 0.3926, 0.2918}, 0.4533, 0.0297},
        {0.30, 0.4, 0.2, 0.3, 0.1, {0.0449, 0.1355, 0.2129, 0.2507, 0.2242}, 0.2518, 0.0804},
    };
    const double xi[5] = {0.001, 0.004, 0.02, 0.10, 0.25};
    for (const Row& r : rows) {
        for (int i = 0; i < 5; ++i) {
            const cw::PolachResult p = cw::polach_forces(eurosprinter(r.mu0, r.A, r.B, r.kA, r.kS, xi[i]));
            assert_close(-p.Fx / 106.7e3, r.f[i], 0.0, 1e-4);
        }
        // The peak by golden section on [0.5 %, 20 %].
        double lo = 0.005, hi = 0.2;
        const double g = 0.5 * (std::sqrt(5.0) - 1.0);
        auto f = [&](double x) {
            return -cw::polach_forces(eurosprinter(r.mu0, r.A, r.B, r.kA, r.kS, x)).Fx / 106.7e3;
        };
        for (int it = 0; it < 80; ++it) {
            const double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
            (f(x1) < f(x2) ? lo : hi) = f(x1) < f(x2) ? x1 : x2;
        }
        assert_close(f(lo), r.peak, 0.0, 1e-4);
        assert_close(lo, r.at, 0.0, 0.5e-4 + 1e-6);
    }
}

// Small creepages: Polach's model is Kalker's linear theory,
// Fx = -G ab C11 xi_x, Fy = -G ab C22 xi_y, and for pure spin
// Fy = -G (ab)^(3/2) C23 phi; large creepage with Coulomb: |F| -> mu Q.
void polach_linear_and_saturation_limits(void**)
{
    const double nu = 0.28, a = 6.304e-3, b = 12.61e-3, G = 82e9;
    const cw::CreepCoefficients c = cw::kalker_coefficients(a / b, nu);
    cw::PolachInput in;
    in.Q = 106.7e3;
    in.a = a;
    in.b = b;
    in.G = G;
    in.C11 = c.C11;
    in.C22 = c.C22;
    in.C23 = c.C23;
    in.law = cw::coulomb_law(0.33);
    in.xi_x = 1e-8;
    assert_close(cw::polach_forces(in).Fx, -G * a * b * c.C11 * in.xi_x, 1e-6, 0.0);
    in.xi_x = 0.0;
    in.xi_y = -2e-8;
    assert_close(cw::polach_forces(in).Fy, -G * a * b * c.C22 * in.xi_y, 1e-6, 0.0);
    in.xi_y = 0.0;
    in.phi = 1e-6; // 1/m
    const double ab = a * b;
    assert_close(cw::polach_forces(in).Fy, -G * ab * std::sqrt(ab) * c.C23 * in.phi, 1e-5, 0.0);
    in.phi = 0.0;
    in.xi_x = 0.3;
    in.xi_y = -0.4;
    const cw::PolachResult sat = cw::polach_forces(in);
    assert_close(std::hypot(sat.Fx, sat.Fy), 0.33 * in.Q, 2e-3, 0.0);
    assert_close(sat.Fx * in.xi_y - sat.Fy * in.xi_x, 0.0, 0.0, 1e-9 * in.Q); // along the slip
    // No creepage, no load or no friction: no force, and no division by 0.
    in.xi_x = in.xi_y = 0.0;
    const cw::PolachResult zero = cw::polach_forces(in);
    assert_true(zero.Fx == 0.0 && zero.Fy == 0.0);
}

// Spiryagin's reduction k = k0 (alpha_inf + (1 - alpha_inf)/(1 + beta eps)),
// eps = G pi a b k0 C11 nu / (4 mu N), written out here for one contact:
// tractcurv's with mu(w) of Polach's 0.36, 0.38, 0.7 s/m at V = 10 m/s.
void slope_reduction_formula(void**)
{
    cw::ContactInput in;
    in.a = 6.304e-3;
    in.b = 12.61e-3;
    in.normal_force = 106.7e3;
    in.xi_x = 0.004;
    in.xi_y = -0.003;
    in.phi = 0.5; // 1/m: xi_y + phi a = -0.00085, smaller: nu_phi = xi_y
    const cw::SlipSpeedLaw law = cw::polach_law(0.36, 0.38, 0.7);
    const double GC11 = 82e9 * 3.7334;
    const cw::GlobalSlip g = cw::global_slip(in, law, {0.54, 0.02, 0.62}, 10.0, GC11);
    const double w = 10.0 * std::hypot(0.004, 0.003);
    const double mu = 0.36 * (0.62 * std::exp(-0.7 * w) + 0.38);
    const double eps = M_PI * in.a * in.b * 0.54 * GC11 * std::hypot(0.004, 0.003) / (4 * mu * 106.7e3);
    assert_close(g.slip_speed, w, 1e-15, 0.0);
    assert_close(g.mu, mu, 1e-14, 0.0);
    assert_close(g.epsilon, eps, 1e-14, 0.0);
    assert_close(g.k, 0.54 * (0.02 + 0.98 / (1 + 0.62 * eps)), 1e-14, 0.0);
    // Spin that enlarges the lateral creepage counts: nu_phi = xi_y + phi a.
    in.phi = -0.5;
    const double nu = std::hypot(0.004, -0.003 - 0.5 * in.a);
    assert_close(cw::global_slip(in, law, {0.54, 0.02, 0.62}, 10.0, GC11).epsilon,
                 eps * nu / std::hypot(0.004, 0.003), 1e-14, 0.0);
    // No reduction: k = 1 whatever eps.
    assert_true(cw::global_slip(in, law, {}, 10.0, GC11).k == 1.0);
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(laws_match_contact_formulas),
        cmocka_unit_test(terms_halve_at_half_speed),
        cmocka_unit_test(slopes_match_differences),
        cmocka_unit_test(vector_exp_within_its_bound),
        cmocka_unit_test(law_lanes_match_contact_formulas),
        cmocka_unit_test(polach_form_is_exponential),
        cmocka_unit_test(invalid_laws_name_their_input),
        cmocka_unit_test(memory_closed_form),
        cmocka_unit_test(local_slip_solves_the_law),
        cmocka_unit_test(polach_table),
        cmocka_unit_test(polach_linear_and_saturation_limits),
        cmocka_unit_test(slope_reduction_formula),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
