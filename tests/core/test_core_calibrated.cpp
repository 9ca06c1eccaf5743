// The calibrated model.
//  - Linear limit: it keeps Kalker's C11, C22, C23 for the forces (its
//    factors are 1 at vanishing creepage) and, through the moment-consistent
//    spin term L_M = 8b/(15 G C33) and the lateral-moment term, also gives
//    Kalker's moments Mz = G c^3 C23 eta and Mz = -G c^4 C33 phi, which
//    plain FASTSIM misses by -16 % (C33, a/b = 1) and more (Kalker 1990,
//    Table E.3, via kalker_coefficients; see test_core_linear_theory for
//    FASTSIM's own closed forms).
//  - Accuracy against the exact model, solved here on a 24 x 24 uniform
//    grid, for evaluation cases (never training cases), in partial slip
//    and near full sliding.
//  - Plain FASTSIM is not changed by the model's presence (bitwise).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "calibrated/calibration_table.hpp"
#include "calibration_limit.hpp"
#include "calibration_metrics.hpp"
#include "contact/error.hpp"
#include "contact/kalker_coefficients.hpp"
#include "calibrated/blended_bound.hpp"
#include "core_test_support.hpp"
#include "test_support.h"

namespace cw = creepwork;

namespace {

constexpr double kTiny = 1e-9; // creepage: no slip on a 50 x 50 grid

void linear_limit_is_kalkers(void**)
{
    printf("  a/b   Fx/C11   Fy/C22   Fy/C23  Mz(eta)/C23  Mz(phi)/C33\n");
    for (double ratio : {0.2, 0.5, 1.0, 2.0, 5.0}) {
        cw::Solver s(cwtest::kalker_grid(50, 50));
        cw::ContactInput in = cwtest::steel_contact(ratio);
        in.model = cw::ModelKind::calibrated;
        const double c = std::sqrt(in.a * in.b), G = in.G;

        in.xi_x = kTiny;
        cw::SolveTotals t = s.solve(in);
        assert_int_equal(t.n_slip, 0);
        assert_int_equal(int(t.model), int(cw::ModelKind::calibrated));
        const double r11 = -t.Fx / (G * c * c * t.C11 * in.xi_x);

        in.xi_x = 0.0;
        in.xi_y = kTiny;
        t = s.solve(in);
        const double r22 = -t.Fy / (G * c * c * t.C22 * in.xi_y);
        const double m23 = t.Mz / (G * c * c * c * t.C23 * in.xi_y);

        in.xi_y = 0.0;
        in.phi = kTiny / c;
        t = s.solve(in);
        const double r23 = -t.Fy / (G * c * c * c * t.C23 * in.phi);
        const double m33 = -t.Mz / (G * c * c * c * c * t.C33 * in.phi);
        printf("  %.1f  %.5f  %.5f  %.5f  %.5f      %.5f\n", ratio, r11, r22, r23, m23, m33);
        // Forces: FASTSIM's own ratios on this grid, 1.0002 (test_core_linear_theory).
        assert_close(r11, 1.0002, 0.0, 5e-5);
        assert_close(r22, 1.0002, 0.0, 5e-5);
        assert_close(r23, 1.0002, 0.0, 5e-5);
        // Moments: the continuum derivation is exact, the grid's error is
        // the march's O(1/n^2) (measured within 0.1 % at 50 x 50).
        assert_close(m23, 1.0, 0.0, 2e-3);
        assert_close(m33, 1.0, 0.0, 2e-3);
    }
}

// Three contacts of the kind of the evaluation set (a/b 0.5-2, nu 0.28-0.5,
// partial slip, spin alone and combined), none of them a training case:
// the calibrated model and plain FASTSIM on the 48 x 48 uniform grid against
// the exact model's continuum estimate (exact_continuum below: 24, 48, 96
// across; maps of the 96 x 96 solve summed onto the 48 x 48 cells). Not the
// exact model on the same coarse grid: since the calibrated model marches
// from the leading edge (its leading-edge march) it is near its own continuum limit there,
// while the exact 24 x 24 moment of the a/b 2 case is 12 % from its own.
// The calibrated model's force errors are held to the accuracy target's bound (3 % of
// mu N; measured <= 1.4 %); its Mz and W errors and the L1 distance of its
// energy-consistent work map to what was measured with the committed table
// plus 10-20 % (Mz 2.7, 1.7, 4.4 %; W 1.4, 1.7, 5.4 %, the last beyond
// the W target's 5 %; map 0.352, 0.470, 0.226), and all of them to below
// FASTSIM's (Mz 8.8-11.0 %, W 6.1-13.5 %, map 0.43-0.68). A new fit of the
// table moves them: the limits follow the committed table.
struct AccuracyCase {
    const char* name;
    double a_over_b, nu, xi_sat, eta_sat, phi_sat; // creepages in units of saturation
    double max_dMz, max_dW;                        // [%]
    double max_map_L1;                             // unit-total work maps [-]
};

// A steel contact (cwtest::steel_contact) whose creepages are the given
// fractions of their saturation values, xi_sat = xi G c^2 C11 / (mu N) etc.
// (the normalisation of calibration_table.cpp).
cw::ContactInput contact_at(double a_over_b, double nu, double xi_sat, double eta_sat,
                      double phi_sat)
{
    cw::ContactInput in = cwtest::steel_contact(a_over_b);
    in.nu = nu;
    const cw::CreepCoefficients C = cw::kalker_coefficients(a_over_b, nu);
    const double c = std::sqrt(in.a * in.b), muN = in.mu * in.normal_force;
    in.xi_x = xi_sat * muN / (in.G * c * c * C.C11);
    in.xi_y = eta_sat * muN / (in.G * c * c * C.C22);
    in.phi = phi_sat * muN / (in.G * c * c * c * C.C23);
    return in;
}

// The exact model's continuum estimate of one contact (calibration_limit:
// Richardson from 24, 48, 96 across with the observed order when clean,
// else the 96 value) and its 96 x 96 work map summed onto 48 x 48 cells.
struct ExactContinuum {
    double Fx, Fy, Mz, W;
    std::vector<double> map48;
    bool partial_slip;
};

ExactContinuum exact_continuum(cw::ContactInput in)
{
    in.model = cw::ModelKind::exact;
    in.pressure = cw::PressureKind::elliptic;
    const double muN = in.mu * in.normal_force, c = std::sqrt(in.a * in.b);
    double q[4][3]; // Fx, Fy, Mz, W on 24, 48, 96
    ExactContinuum e;
    const int n[3] = {24, 48, 96};
    for (int g = 0; g < 3; ++g) {
        cw::Solver s(cwtest::uniform_grid(n[g], n[g]));
        const cw::SolveTotals t = s.solve(in, cw::SolveMode::full);
        q[0][g] = t.Fx;
        q[1][g] = t.Fy;
        q[2][g] = t.Mz;
        q[3][g] = t.W_macro;
        if (g == 2) {
            e.partial_slip = t.n_slip > 0 && t.n_adhesion > 0;
            e.map48 = cwcal::summed_onto_coarse_grid(
                cwtest::field(s, cw::Field::work_consistent), 96, 48);
        }
    }
    const double h[3] = {1.0 / 24, 1.0 / 48, 1.0 / 96};
    const double scale[4] = {muN, muN, muN * c, muN};
    double* out[4] = {&e.Fx, &e.Fy, &e.Mz, &e.W};
    for (int k = 0; k < 4; ++k) *out[k] = cwcal::continuum_limit(h, q[k], scale[k]).value;
    return e;
}

void closer_to_exact_than_fastsim(void**)
{
    const AccuracyCase cases[] = {
        {"a/b 1, xi + spin", 1.0, 0.28, 0.4, 0.0, 0.3, 3.1, 1.6, 0.40},
        {"a/b 2, spin", 2.0, 0.28, 0.0, 0.0, 0.35, 2.0, 2.0, 0.53},
        {"a/b 0.5, eta + spin", 0.5, 0.5, 0.0, -0.5, 0.4, 5.1, 6.2, 0.26},
    };
    cw::Solver s(cwtest::uniform_grid(48, 48));
    printf("  case                   model       dFx %%muN dFy %%muN  dMz %%   dW %%  map L1\n");
    for (const AccuracyCase& k : cases) {
        cw::ContactInput in = contact_at(k.a_over_b, k.nu, k.xi_sat, k.eta_sat, k.phi_sat);
        const double muN = in.mu * in.normal_force;
        const ExactContinuum ex = exact_continuum(in);
        assert_true(ex.partial_slip);
        double err[2][5];
        for (int m = 0; m < 2; ++m) {
            in.model = m ? cw::ModelKind::calibrated : cw::ModelKind::fastsim;
            in.pressure = cw::PressureKind::parabolic;
            const cw::SolveTotals t = s.solve(in, cw::SolveMode::full);
            err[m][0] = 100 * std::fabs(t.Fx - ex.Fx) / muN;
            err[m][1] = 100 * std::fabs(t.Fy - ex.Fy) / muN;
            err[m][2] = 100 * std::fabs(t.Mz - ex.Mz) / std::fabs(ex.Mz);
            err[m][3] = 100 * std::fabs(t.W_macro - ex.W) / ex.W;
            err[m][4] = cwcal::unit_l1(cwtest::field(s, cw::Field::work_consistent), ex.map48);
            printf("  %-22s %-10s %8.2f %8.2f %7.1f %6.1f %6.3f\n", k.name,
                   m ? "calibrated" : "FASTSIM", err[m][0], err[m][1], err[m][2], err[m][3],
                   err[m][4]);
        }
        assert_true(err[1][0] <= 3.0 && err[1][1] <= 3.0);
        assert_true(err[1][2] <= k.max_dMz);
        assert_true(err[1][3] <= k.max_dW);
        assert_true(err[1][2] < err[0][2]);
        assert_true(err[1][3] < err[0][3]);
        assert_true(err[1][4] <= k.max_map_L1);
        assert_true(err[1][4] < err[0][4]);
    }
}

// On the uniform grid (CONTACT's layout) plain FASTSIM starts each strip
// with a full element step and takes the rigid slip at element centres:
// errors of the first order in the element size. The calibrated model
// marches from where each strip enters the ellipse and takes the slip at
// each step's midpoint (MarchGeometry::march_from_leading_edges), so in the
// linear limit its forces and moment on the uniform grid are much closer to
// Kalker's. Error: the largest of |Fx/C11|, |Fy/C22|, |Fy(phi)/C23| (and
// for the calibrated model |Mz(phi)/C33|) - 1, a/b = 1. Measured at 20, 40,
// 80 across: calibrated 0.92, 1.01, 0.13 %, FASTSIM 6.9, 3.9, 1.4 % (first
// order). What is left is the boundary elements' area (an element counts
// whole when its centre is inside), which does not fall smoothly with n.
// Held to 1.2 % and to a third of FASTSIM's error on the same grid.
double worst_linear_ratio_error(cw::ModelKind model, int n)
{
    cw::Solver s(cwtest::uniform_grid(n, n));
    cw::ContactInput in = cwtest::steel_contact(1.0);
    in.model = model;
    in.pressure = cw::PressureKind::parabolic;
    const double c = std::sqrt(in.a * in.b), G = in.G;
    double worst = 0.0;
    in.xi_x = kTiny;
    cw::SolveTotals t = s.solve(in);
    worst = std::max(worst, std::fabs(-t.Fx / (G * c * c * t.C11 * in.xi_x) - 1.0));
    in.xi_x = 0.0;
    in.xi_y = kTiny;
    t = s.solve(in);
    worst = std::max(worst, std::fabs(-t.Fy / (G * c * c * t.C22 * in.xi_y) - 1.0));
    in.xi_y = 0.0;
    in.phi = kTiny / c;
    t = s.solve(in);
    worst = std::max(worst, std::fabs(-t.Fy / (G * c * c * c * t.C23 * in.phi) - 1.0));
    if (model == cw::ModelKind::calibrated) // FASTSIM's Mz(phi) is not Kalker's anyway
        worst = std::max(worst, std::fabs(-t.Mz / (G * c * c * c * c * t.C33 * in.phi) - 1.0));
    return worst;
}

void uniform_grid_marches_from_leading_edge(void**)
{
    printf("  n across   calibrated   FASTSIM (CONTACT's steps)\n");
    double err[3];
    const int n[3] = {20, 40, 80};
    // err[k]: the calibrated model's error on n[k] x n[k].
    for (int k = 0; k < 3; ++k) {
        err[k] = worst_linear_ratio_error(cw::ModelKind::calibrated, n[k]);
        const double fastsim = worst_linear_ratio_error(cw::ModelKind::fastsim, n[k]);
        printf("  %8d   %10.5f   %10.5f\n", n[k], err[k], fastsim);
        assert_true(err[k] <= 0.012);
        assert_true(err[k] <= fastsim / 3.0);
    }
}

// Plain FASTSIM does not depend on the calibrated model having run on the
// same solver (they share no state): bitwise the same totals as a fresh one.
void fastsim_unchanged_by_calibrated(void**)
{
    cw::ContactInput in = cwtest::steel_contact(1.5);
    in.xi_x = 4e-4;
    in.xi_y = -2e-4;
    in.phi = 0.4;
    cw::Solver fresh(cwtest::kalker_grid(20, 20)), mixed(cwtest::kalker_grid(20, 20));
    const cw::SolveTotals a = fresh.solve(in, cw::SolveMode::full);
    in.model = cw::ModelKind::calibrated;
    const cw::SolveTotals cal = mixed.solve(in, cw::SolveMode::full);
    in.model = cw::ModelKind::fastsim;
    const cw::SolveTotals b = mixed.solve(in, cw::SolveMode::full);
    assert_memory_equal(&a, &b, sizeof a);
    assert_true(cal.Mz != a.Mz); // the calibrated model did run, differently
    std::vector<double> fa = cwtest::field(fresh, cw::Field::work_consistent);
    std::vector<double> fb = cwtest::field(mixed, cw::Field::work_consistent);
    assert_memory_equal(fa.data(), fb.data(), fa.size() * sizeof(double));
}

// The traction bound blends (calibrated/blended_bound.hpp) carry the normal
// force: P and (3/4) sqrt(P) (P = 1 - r^2) each integrate over the unit disc
// to pi/2 (= N / p0 / (ab) with the parabolic p0 = 2N/(pi a b)), so every
// blend does. In polar coordinates with r^2 = 1 - t^2: int_disc f dA =
// 2 pi int_0^1 f(P = t^2, sqrt P = t) t dt, a polynomial of degree <= 3 in
// t, which 4-point Gauss-Legendre integrates exactly (to rounding).
void blended_bound_carries_normal_force(void**)
{
    const double node[4] = {0.3399810435848563, 0.8611363115940526, -0.3399810435848563,
                            -0.8611363115940526};
    const double weight[4] = {0.6521451548625461, 0.3478548451374538, 0.6521451548625461,
                              0.3478548451374538};
    const double pi = 3.14159265358979323846;
    for (double blend : {0.0, 0.25, 0.66, 1.0}) {
        double integral = 0.0;
        for (int k = 0; k < 4; ++k) {
            const double t = 0.5 * (node[k] + 1.0); // [-1, 1] -> [0, 1]
            integral += 0.5 * weight[k] * 2.0 * pi * t *
                        cw::blended_bound_shape(t * t, t, blend);
        }
        assert_close(integral, pi / 2.0, 1e-12, 0.0);
    }
    // The end points are the laws themselves (parabolic units).
    assert_close(cw::blended_bound_shape(0.36, 0.6, 0.0), 0.36, 0.0, 0.0);
    assert_close(cw::blended_bound_shape(0.36, 0.6, 1.0), 0.75 * 0.6, 1e-15, 0.0);
}

// The pressure the calibrated model reports is the bound its march used:
// on a 40 x 40 uniform grid in partial slip (where the table's blend is
// well away from 0), pz is the blended shape times the parabolic p0 in every
// element (from the grid geometry, to 1e-12), |p| <= mu pz everywhere and
// |p| = mu pz in every slip element (to 1e-12), p_max is the largest pz, and
// pz sums to N within the grid's quadrature error (0.5 %: the element-centre
// rule on the ellipse's ragged edge).
void reported_pressure_is_the_bound(void**)
{
    cw::Solver s(cwtest::uniform_grid(40, 40));
    cw::ContactInput in = contact_at(1.5, cwtest::steel_contact(1.5).nu, 0.5, 0.0, 0.3);
    in.model = cw::ModelKind::calibrated;
    const double blend = cw::calibration_for(in).bound_blend;
    printf("  blend at this contact: %.4f\n", blend);
    assert_true(blend > 0.1);
    const cw::SolveTotals t = s.solve(in, cw::SolveMode::full);
    assert_true(t.n_slip > 0 && t.n_adhesion > 0);
    const std::vector<double> x = cwtest::field(s, cw::Field::x), y = cwtest::field(s, cw::Field::y),
                              area = cwtest::field(s, cw::Field::area),
                              pz = cwtest::field(s, cw::Field::pz), px = cwtest::field(s, cw::Field::px),
                              py = cwtest::field(s, cw::Field::py);
    std::vector<int> state(x.size());
    s.copy_state(state.data());
    const double p0 = 2.0 * in.normal_force / (3.14159265358979323846 * in.a * in.b);
    double force = 0.0, largest = 0.0;
    for (size_t k = 0; k < x.size(); ++k) {
        const double X = x[k] / in.a, Y = y[k] / in.b;
        const double P = state[k] == int(cw::ElementState::exterior) ? 0.0 : 1.0 - X * X - Y * Y;
        const double expected = p0 * cw::blended_bound_shape(P, std::sqrt(P), blend);
        assert_close(pz[k], expected, 1e-12, 1e-12 * p0);
        const double traction = std::hypot(px[k], py[k]);
        assert_true(traction <= in.mu * pz[k] * (1.0 + 1e-12));
        if (state[k] == int(cw::ElementState::slip))
            assert_close(traction, in.mu * pz[k], 1e-12, 0.0);
        force += pz[k] * area[k];
        largest = std::max(largest, pz[k]);
    }
    printf("  sum pz dA / N = %.5f\n", force / in.normal_force);
    assert_close(force, in.normal_force, 5e-3, 0.0);
    assert_close(t.p_max, largest, 1e-14, 0.0);
}

// The model needs Kalker's normalisation (G, nu), and says so.
void given_flexibilities_rejected(void**)
{
    cw::ContactInput in = cwtest::steel_contact(1.0);
    in.model = cw::ModelKind::calibrated;
    in.flexibility = cw::FlexibilitySource::given;
    in.L1 = in.L2 = in.L3 = 5e-14;
    in.xi_x = 1e-3;
    cw::Solver s(cwtest::kalker_grid(10, 10));
    try {
        s.solve(in);
        fail_msg("given flexibilities accepted");
    } catch (const cw::Error& e) {
        assert_true(std::string(e.what()).find("flexibility") != std::string::npos);
        assert_false(s.has_solution());
    }
}

// Near full sliding the force points nearly along the rigid slip, so with
// L1 != L2 (or spin) the direction is what goes wrong: the flexibility
// equalisation (calibration_table.hpp, h = min(1, e s), the factors
// equalised too) must turn the calibrated force to the exact one. Two
// contacts beyond 250 % of saturation, the exact model on the same 24 x 24
// uniform grid as the yardstick; without the equalisation of the factors
// such cases are direction errors of several per cent of mu N
// (doc/theory/calibrated.md, "Flexibility equalisation"; doc/dev/decisions.md).
// Held to the force target's bound, 3 % of mu N, per component (measured
// with the committed table: 1.0 and 1.0, 0.6 and 0.2; FASTSIM 14.2 % in Fx
// in the first case); FASTSIM is printed beside it.
void saturated_force_direction(void**)
{
    struct SlidingCase {
        const char* name;
        double a_over_b, nu, xi_sat, eta_sat, phi_sat;
    };
    const SlidingCase cases[] = {
        {"a/b 0.2, xi + eta", 0.2, 0.5, 1.3, -2.4, 0.0},
        {"a/b 1, xi + spin", 1.0, 0.5, -1.9, 0.0, 1.8},
    };
    cw::Solver s(cwtest::uniform_grid(24, 24));
    printf("  case                 exact Fx, Fy /muN   model       Fx, Fy /muN\n");
    for (const SlidingCase& k : cases) {
        cw::ContactInput in = contact_at(k.a_over_b, k.nu, k.xi_sat, k.eta_sat, k.phi_sat);
        const double muN = in.mu * in.normal_force;
        in.model = cw::ModelKind::exact;
        in.pressure = cw::PressureKind::elliptic;
        const cw::SolveTotals ex = s.solve(in, cw::SolveMode::forces_only);
        for (int m = 0; m < 2; ++m) {
            in.model = m ? cw::ModelKind::calibrated : cw::ModelKind::fastsim;
            in.pressure = cw::PressureKind::parabolic;
            const cw::SolveTotals t = s.solve(in, cw::SolveMode::forces_only);
            printf("  %-20s %7.4f %7.4f   %-10s %7.4f %7.4f\n", k.name, ex.Fx / muN, ex.Fy / muN,
                   m ? "calibrated" : "FASTSIM", t.Fx / muN, t.Fy / muN);
            if (m) {
                assert_true(100 * std::fabs(t.Fx - ex.Fx) / muN <= 3.0);
                assert_true(100 * std::fabs(t.Fy - ex.Fy) / muN <= 3.0);
            }
        }
    }
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(linear_limit_is_kalkers),
        cmocka_unit_test(uniform_grid_marches_from_leading_edge),
        cmocka_unit_test(closer_to_exact_than_fastsim),
        cmocka_unit_test(saturated_force_direction),
        cmocka_unit_test(fastsim_unchanged_by_calibrated),
        cmocka_unit_test(blended_bound_carries_normal_force),
        cmocka_unit_test(reported_pressure_is_the_bound),
        cmocka_unit_test(given_flexibilities_rejected),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
