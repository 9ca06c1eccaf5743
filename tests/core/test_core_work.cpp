// Work bookkeeping (issue 2): the macro work of paper eq. 34, the paper's
// local work and K (eqs. 36-39), the energy-consistent map and its exact
// discrete energy identity, and the lateral profile of paper Figs. 8-9.
#include "core_test_support.hpp"
#include "test_support.h"

namespace cw = creepwork;

namespace {

cw::ContactInput contact(double xi, double eta, double phi, double a_over_b = 1.0)
{
    cw::ContactInput in = cwtest::steel_contact(a_over_b);
    in.xi_x = xi;
    in.xi_y = eta;
    in.phi = phi;
    return in;
}

// Paper eq. 34 per unit rolling distance, positive for dissipation.
void macro_work_is_eq_34(void**)
{
    cw::Solver s(cwtest::kalker_grid(20, 20));
    const cw::ContactInput in = contact(0.001, -0.0004, 0.3, 2.0);
    const cw::SolveTotals t = s.solve(in);
    assert_close(t.W_macro, -(t.Fx * in.xi_x + t.Fy * in.xi_y + t.Mz * in.phi), 1e-15, 0.0);
    assert_true(t.W_macro > 0.0);
}

// The march's exact discrete energy identity: on the uniform grid, with the
// rigid slip at the element centres, the friction dissipation plus the
// numerical dissipation 1/2 dp L dp plus the elastic energy carried out of
// the trailing edge equal W_macro to rounding -- so the balance factor is 1
// without spin, and with spin when L1 = L2 = L3 (no scaled spin).
void discrete_energy_identity(void**)
{
    for (int n : {7, 24, 101}) {
        cw::Solver s(cwtest::uniform_grid(n, n + 3, 1.07));
        const cw::SolveTotals a = s.solve(contact(0.0007, 0.0004, 0.0, 1.7));
        assert_close(a.balance_factor, 1.0, 1e-12, 0.0);
        cw::ContactInput single = contact(0.0007, 0.0004, 0.6, 1.7);
        single.flexibility = cw::FlexibilitySource::given;
        single.L1 = single.L2 = single.L3 = 5e-14;
        const cw::SolveTotals b = s.solve(single);
        assert_close(b.balance_factor, 1.0, 1e-12, 0.0);
    }
}

// With three flexibilities and spin the simplified theory is not energy
// consistent (../shared/README.md): its own dissipation differs from W_macro
// by a model factor that does not depend on the grid. Measured here for the
// uniform grid; the map absorbs it through the balance factor.
void spin_defect_is_a_model_property(void**)
{
    const cw::ContactInput in = contact(0.01, 0.0, 2.0, 0.5);
    double factor[3];
    const int n[3] = {40, 160, 320};
    for (int k = 0; k < 3; ++k) {
        cw::Solver s(cwtest::uniform_grid(n[k], n[k]));
        factor[k] = s.solve(in).balance_factor;
    }
    printf("  W_macro / model power, spin case: %.5f %.5f %.5f\n", factor[0], factor[1], factor[2]);
    assert_close(factor[1], factor[2], 2e-4, 0.0);
    assert_true(std::fabs(factor[2] - 1.0) > 0.05);
}

// Paper eq. 36 as printed, element by element: work = -(F . s_t + M phi)
// (forces on the wheel), F = p A, M = x Fy - y Fx the element's moment about
// its own position (eq. 28), s_t the translational micro-slip. s_t is
// recomputed here from the exported tractions, not from the slip field or
// the slip points: the march sets u = L p with u = u_prev - h w, so
// s = w + (u - u_prev)/h and its translational part is
//   s_t = (xi, eta) + L (p - p_upstream) / h
// along each strip in rolling order, p_upstream = 0 ahead of the first
// contact element, h the distance from the upstream element centre -- on
// Kalker's strips from the leading edge a sqrt(1 - y^2/b^2) for the first
// one (Kalker 1982's half step), on CONTACT's grid always dx. Holds in
// adhesion too (s = 0 there, s_t = minus the model's spin slip).
void paper_work_is_eq_36_per_element(void**)
{
    struct Case {
        cw::GridSpec grid;
        cw::ContactInput in;
    };
    std::vector<Case> cases;
    // Spin-dominated full slip on a coarse strip grid (the Fig. 7 kind).
    cases.push_back({cwtest::kalker_grid(10, 10), contact(0.0, 0.0022, 1.9, 1.8)});
    cases.push_back({cwtest::kalker_grid(20, 13), contact(0.0006, 0.0003, 0.5, 1.5)});
    cases.push_back({cwtest::kalker_grid(7, 9), contact(0.001, -0.0004, 3.0, 0.4)});
    cases.back().in.rolling_direction = -1;
    cases.back().in.pressure = cw::PressureKind::elliptic;
    cases.push_back({cwtest::uniform_grid(30, 30, 1.05), contact(0.0006, 0.0003, 0.5, 1.5)});
    cases.push_back({cwtest::uniform_grid(17, 23, 1.2), contact(0.0, 0.001, 2.0, 0.7)});
    cases.back().in.rolling_direction = -1;
    for (const Case& c : cases) {
        cw::Solver s(c.grid);
        const cw::ContactInput& in = c.in;
        const cw::SolveTotals t = s.solve(in);
        const int nx = s.grid().nx(), ny = s.grid().ny();
        const bool strips = c.grid.kind == cw::GridKind::kalker_strips;
        const auto px = cwtest::field(s, cw::Field::px), py = cwtest::field(s, cw::Field::py);
        const auto x = cwtest::field(s, cw::Field::x), y = cwtest::field(s, cw::Field::y);
        const auto A = cwtest::field(s, cw::Field::area);
        const auto wp = cwtest::field(s, cw::Field::work_paper);
        const auto st = cwtest::states(s);
        double total = 0.0;
        for (int j = 0; j < ny; ++j) {
            double px_up = 0.0, py_up = 0.0;
            for (int m = 0; m < nx; ++m) {
                const int i = in.rolling_direction > 0 ? nx - 1 - m : m;
                const size_t k = static_cast<size_t>(i) + static_cast<size_t>(j) * nx;
                if (st[k] == 0) {  // exterior: no work, the march restarts from zero
                    assert_true(wp[k] == 0.0);
                    px_up = py_up = 0.0;
                    continue;
                }
                const int up = i + in.rolling_direction; // upstream neighbour
                const double h =
                    up >= 0 && up < nx
                        ? std::fabs(x[k] - x[static_cast<size_t>(up) + static_cast<size_t>(j) * nx])
                        : in.a * std::sqrt(1.0 - y[k] * y[k] / (in.b * in.b)) - std::fabs(x[k]);
                assert_true(strips || up >= 0); // the uniform box has a row of exterior elements
                const double stx = in.xi_x + t.L1 * (px[k] - px_up) / h;
                const double sty = in.xi_y + t.L2 * (py[k] - py_up) / h;
                const double Fx = px[k] * A[k], Fy = py[k] * A[k];
                const double M = x[k] * Fy - y[k] * Fx;
                const double expected = -(Fx * stx + Fy * sty + M * in.phi);
                // Rounding of the terms summed (the slip is a difference).
                const double scale = std::hypot(Fx, Fy) *
                                     (std::fabs(in.xi_x) + std::fabs(in.xi_y) +
                                      std::fabs(in.phi) * (std::fabs(x[k]) + std::fabs(y[k])) +
                                      (t.L1 + t.L2) * std::hypot(px[k] - px_up, py[k] - py_up) / h);
                assert_close(wp[k], expected, 0.0, 1e-12 * scale);
                total += expected;
                px_up = px[k];
                py_up = py[k];
            }
        }
        assert_close(t.W_micro_paper, total, 1e-12, 0.0);
        assert_close(t.K, t.W_macro / t.W_micro_paper, 1e-15, 0.0);
    }
}

// Strips without a slip element hand their released energy to the nearest
// strip(s) with slip: the map stays zero there and still sums to W_macro.
void strips_without_slip(void**)
{
    cw::Solver s(cwtest::kalker_grid(20, 20));
    const cw::SolveTotals t = s.solve(contact(0.0005, 0.0, 0.2));
    const auto st = cwtest::states(s);
    const auto w = cwtest::field(s, cw::Field::work_consistent);
    int orphans = 0;
    for (int j = 0; j < 20; ++j) {
        int slips = 0;
        double strip_work = 0.0;
        for (int i = 0; i < 20; ++i) {
            slips += st[i + 20 * j] == 2;
            strip_work += w[i + 20 * j];
        }
        if (slips == 0) {
            ++orphans;
            assert_true(strip_work == 0.0);
        }
    }
    assert_true(orphans >= 2);  // this case has strips without slip (checked)
    assert_int_equal(t.work_flags, 0);
    assert_close(cwtest::sum(w), t.W_macro, 1e-12, 0.0);
}

// No element slips at all (tiny creepage, coarse grid): the energy released
// at the trailing edge goes to each strip's trailing element, flagged.
void unresolved_slip_zone_is_flagged(void**)
{
    cw::Solver s(cwtest::kalker_grid(10, 10));
    const cw::SolveTotals t = s.solve(contact(1e-5, 0.0, 0.0));
    assert_int_equal(t.n_slip, 0);
    assert_int_equal(t.work_flags, cw::kWorkUnresolved);
    const auto w = cwtest::field(s, cw::Field::work_consistent);
    for (int j = 0; j < 10; ++j)
        for (int i = 0; i < 10; ++i) {
            // Rolling towards +x: the trailing element of a strip is i = 0.
            if (i == 0)
                assert_true(w[i + 10 * j] > 0.0);
            else
                assert_true(w[i + 10 * j] == 0.0);
        }
    assert_close(cwtest::sum(w), t.W_macro, 1e-12, 0.0);
}

// Lateral profile (paper Figs. 8-9): the map summed along x per unit width
// integrates to W; the parabola (3W/4b)(1 - y^2/b^2) has the same area
// (midpoint rule on the strips: 1/(2 ny^2) relative error, Kalker grid).
void lateral_profile(void**)
{
    const int ny = 16;
    cw::Solver s(cwtest::kalker_grid(24, ny));
    const cw::ContactInput in = contact(0.0019, 0.0011, 0.5, 2.0);
    const cw::SolveTotals t = s.solve(in);
    std::vector<double> y(ny), w(ny), par(ny);
    s.copy_profile(y.data(), w.data(), par.data());
    const auto map = cwtest::field(s, cw::Field::work_consistent);
    const double dy = 2 * in.b / ny;
    double area = 0.0, par_area = 0.0, peak = 0.0, max_diff = 0.0, sq = 0.0;
    for (int j = 0; j < ny; ++j) {
        double column = 0.0;
        for (int i = 0; i < 24; ++i) column += map[i + 24 * j];
        assert_close(w[j], column / dy, 1e-13, 0.0);
        assert_close(y[j], -in.b + (j + 0.5) * dy, 1e-12, 0.0);
        area += w[j] * dy;
        par_area += par[j] * dy;
        peak = std::max(peak, w[j]);
        max_diff = std::max(max_diff, std::fabs(w[j] - par[j]));
        sq += (w[j] - par[j]) * (w[j] - par[j]);
    }
    assert_close(area, t.W_macro, 1e-12, 0.0);
    assert_close(par_area, t.W_macro, 1.0 / (2 * ny * ny) + 1e-12, 0.0);
    assert_close(t.profile_max_diff, max_diff / peak, 1e-12, 0.0);
    assert_close(t.profile_rms_diff, std::sqrt(sq / ny) / peak, 1e-12, 0.0);
    printf("  profile vs equal-area parabola: max %.1f %%, rms %.1f %% of the peak\n",
           100 * t.profile_max_diff, 100 * t.profile_rms_diff);
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(macro_work_is_eq_34),
        cmocka_unit_test(discrete_energy_identity),
        cmocka_unit_test(spin_defect_is_a_model_property),
        cmocka_unit_test(paper_work_is_eq_36_per_element),
        cmocka_unit_test(strips_without_slip),
        cmocka_unit_test(unresolved_slip_zone_is_flagged),
        cmocka_unit_test(lateral_profile),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
