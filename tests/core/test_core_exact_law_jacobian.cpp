// The exact models' Jacobian under a friction law of the slip speed
// (ExactModel and GapExactModel with set_law) against independent numbers
// on CONTACT's tractcurv contact (48 x 44) with the exponential law:
//  - central differences of the solver, on both sides of the adhesion
//    peak (about 0.35 %: at 0.2, 0.4 and 2 %), every column (xi_x, xi_y,
//    phi, N);
//  - the gap-exact model given the grid's Hertzian gap: the same forces and
//    creepage columns by another path, its own N column against its
//    central differences;
//  - with friction memory (CONTACT's MEMDST 3 um, MEM_S0 1 mm/s): central
//    differences of the solver at 0.2, 0.4 and 2 %, every column.
#include "core_test_support.hpp"
#include "tractcurv_exact.hpp"
#include "test_support.h"

#include "contact/hertz.hpp"
#include "exact/exact_model.hpp"
#include "gap/gap_exact_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace cw = creepwork;

namespace {

const double kN = cwtest::kTractcurvN, kV = cwtest::kTractcurvV;
using cwtest::tractcurv_exact;
cw::SlipSpeedLaw exponential_law() { return cwtest::tractcurv_exponential_law(); }

// Central differences of the solver, steps 1e-3 ... 1e-6 of each input's
// scale (the best of them: a step that moves an element across the slip
// boundary costs accuracy), against the Jacobian, on both sides of the
// peak (0.35 %).
double column_error(cw::ExactModel& m, const cw::ContactInput& base, const cw::Jacobian& J, int c,
                    double scale)
{
    double best = 1e300;
    for (double step : {1e-3, 1e-4, 1e-5, 1e-6}) {
        const double h = step * scale;
        cw::ContactInput p = base, q = base;
        double* vp[4] = {&p.xi_x, &p.xi_y, &p.phi, &p.normal_force};
        double* vq[4] = {&q.xi_x, &q.xi_y, &q.phi, &q.normal_force};
        *vp[c] += h;
        *vq[c] -= h;
        const cw::SolveTotals a = m.solve(p, cw::SolveMode::forces_only);
        const cw::SolveTotals b = m.solve(q, cw::SolveMode::forces_only);
        const double r = std::sqrt(base.a * base.b);
        const double d[3] = {(a.Fx - b.Fx) / (2 * h), (a.Fy - b.Fy) / (2 * h),
                             (a.Mz - b.Mz) / (2 * h * r)};
        const double jr[3] = {J.d[0][c], J.d[1][c], J.d[2][c] / r};
        const double col = std::max({std::fabs(jr[0]), std::fabs(jr[1]), std::fabs(jr[2])});
        double err = 0.0;
        for (int i = 0; i < 3; ++i) err = std::max(err, std::fabs(d[i] - jr[i]) / col);
        best = std::min(best, err);
    }
    return best;
}

// The Jacobian at tractcurv's creepage xi (with a lateral creepage and spin,
// tolerance 1e-13, cold) into J; returns its worst column error.
double worst_column_error(cw::ExactModel& m, double xi, cw::Jacobian& J)
{
    cw::ContactInput in = tractcurv_exact(xi, 3e-4, 0.1);
    in.tolerance = 1e-13;
    in.warm_start = false;
    m.solve_jacobian(in, cw::SolveMode::forces_only, J);
    const double scales[4] = {xi, 1e-3, 1.0, kN};
    double worst = 0.0;
    for (int c = 0; c < 4; ++c) worst = std::max(worst, column_error(m, in, J, c, scales[c]));
    return worst;
}

void jacobian_across_the_peak(void**)
{
    cw::ExactModel m(cwtest::tractcurv_grid());
    m.set_law(exponential_law(), kV);
    for (double xi : {2e-3, 4e-3, 2e-2}) {
        cw::Jacobian J;
        const double worst = worst_column_error(m, xi, J);
        printf("  xi %.3g: dFx/dxi_x / (mu_s N) = %+.4f, worst column error %.2g\n", xi,
               J.d[0][0] / (0.33 * kN), worst);
        assert_true(worst <= 1e-4);
        if (xi == 2e-2) assert_true(J.d[0][0] > 0.0); // past the peak |Fx| falls (Fx < 0)
        if (xi == 2e-3) assert_true(J.d[0][0] < 0.0);
    }
}

// Under friction memory the tangents carry the chain mu_k(sigma_k, mu_ahead)
// along each row (exact/steady_memory.cpp): every column against central
// differences of the solver on both sides of the peak.
void jacobian_under_memory(void**)
{
    cw::ExactModel m(cwtest::tractcurv_grid());
    m.set_law(exponential_law(), kV);
    m.set_friction_memory(3e-6, 1e-3);
    for (double xi : {2e-3, 4e-3, 2e-2}) {
        cw::Jacobian J;
        const double worst = worst_column_error(m, xi, J);
        assert_true(m.info().memory_iterations >= 2);
        printf("  memory, xi %.3g: dFx/dxi_x / (mu_s N) = %+.4f, worst column error %.2g\n", xi,
               J.d[0][0] / (0.33 * kN), worst);
        assert_true(worst <= 1e-4);
    }
}

// The gap-exact model given the Hertzian gap A x^2 + B y^2 of the tractcurv
// grid's cells (A, B by Hertz's theory from a, b and N, as the elliptic
// model builds its contact) solves the elliptic model's discrete problem in
// other units (tractions per mu(0) p_max, not mu(0) p0): under the law the
// same forces and the same creepage columns of the Jacobian. The N columns
// differ in what they hold (the gap, against the semi-axes), and the gap's
// is checked against its own central differences (it holds the traction
// unit and the slip speed's unit fixed and moves the bound).
void gap_grid_meets_the_ellipse(void**)
{
    const cw::GridSpec ge = cwtest::tractcurv_grid();
    cw::ContactInput e = tractcurv_exact(0.0);
    e.tolerance = 1e-12;
    e.warm_start = false;
    cw::GridSpec gg;
    gg.kind = cw::GridKind::gap;
    gg.nx = ge.nx;
    gg.ny = ge.ny;
    gg.dx = 2 * ge.box_scale * e.a / ge.nx;
    gg.dy = 2 * ge.box_scale * e.b / ge.ny;
    gg.x0 = -ge.box_scale * e.a + 0.5 * gg.dx;
    gg.y0 = -ge.box_scale * e.b + 0.5 * gg.dy;
    const cw::HertzCurvatures hz =
        cw::hertz_from_semi_axes(e.a, e.b, e.normal_force, e.G / (1.0 - e.nu));
    std::vector<double> h(static_cast<size_t>(gg.nx) * gg.ny);
    for (int j = 0; j < gg.ny; ++j)
        for (int i = 0; i < gg.nx; ++i) {
            const double x = gg.x0 + i * gg.dx, y = gg.y0 + j * gg.dy;
            h[i + static_cast<size_t>(gg.nx) * j] = hz.A * x * x + hz.B * y * y;
        }
    cw::ExactModel ellipse(ge);
    cw::GapExactModel gap(gg);
    ellipse.set_law(exponential_law(), kV);
    gap.set_law(exponential_law(), kV);
    const double muN = 0.33 * kN, r = std::sqrt(e.a * e.b);
    for (double xi : {2e-3, 2e-2}) {
        e.xi_x = xi;
        e.xi_y = 3e-4;
        e.phi = 0.1;
        cw::ContactInput g = e;
        g.gap = h.data();
        g.gap_len = h.size();
        cw::Jacobian Je, Jg;
        const cw::SolveTotals te = ellipse.solve_jacobian(e, cw::SolveMode::full, Je);
        const cw::SolveTotals tg = gap.solve_jacobian(g, cw::SolveMode::full, Jg);
        printf("  gap vs ellipse at xi %.3g: Fx %.3g, Fy %.3g mu N, Mz %.3g mu N r; W %.3g\n", xi,
               (tg.Fx - te.Fx) / muN, (tg.Fy - te.Fy) / muN, (tg.Mz - te.Mz) / (muN * r),
               tg.W_consistent / te.W_consistent - 1.0);
        assert_close(tg.Fx, te.Fx, 0.0, 1e-9 * muN);
        assert_close(tg.Fy, te.Fy, 0.0, 1e-9 * muN);
        assert_close(tg.Mz, te.Mz, 0.0, 1e-9 * muN * r);
        assert_close(tg.W_consistent, te.W_consistent, 1e-8, 1e-300);
        assert_int_equal(tg.n_slip, te.n_slip);
        assert_true(gap.info().friction_iterations > 0 && gap.info().mu_min < 0.33);
        const double scales[3] = {1.0, 1.0, r};
        for (int c = 0; c < 3; ++c) {
            double col = 0.0, diff = 0.0;
            for (int i = 0; i < 3; ++i) {
                const double rs = i == 2 ? 1.0 / r : 1.0;
                col = std::max(col, std::fabs(Je.d[i][c] * rs * scales[c]));
                diff = std::max(diff, std::fabs((Jg.d[i][c] - Je.d[i][c]) * rs * scales[c]));
            }
            assert_true(diff <= 1e-8 * col);
        }
        double best = 1e300;
        for (double step : {1e-3, 1e-4, 1e-5}) {
            cw::ContactInput p = g, q = g;
            p.normal_force += step * kN;
            q.normal_force -= step * kN;
            const cw::SolveTotals a = gap.solve(p, cw::SolveMode::forces_only);
            const cw::SolveTotals b = gap.solve(q, cw::SolveMode::forces_only);
            const double d[3] = {(a.Fx - b.Fx) / (2 * step * kN), (a.Fy - b.Fy) / (2 * step * kN),
                                 (a.Mz - b.Mz) / (2 * step * kN * r)};
            const double j[3] = {Jg.d[0][3], Jg.d[1][3], Jg.d[2][3] / r};
            const double col = std::max({std::fabs(j[0]), std::fabs(j[1]), std::fabs(j[2])});
            double err = 0.0;
            for (int i = 0; i < 3; ++i) err = std::max(err, std::fabs(d[i] - j[i]) / col);
            best = std::min(best, err);
        }
        printf("    gap's N column against central differences: %.2g\n", best);
        assert_true(best <= 1e-4);
    }
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(jacobian_across_the_peak),
        cmocka_unit_test(gap_grid_meets_the_ellipse),
        cmocka_unit_test(jacobian_under_memory),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
