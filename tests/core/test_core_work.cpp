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

// The paper's local work is element force x physical micro-slip, i.e. the
// model's micro-slip with its scaled spin (L/L3) replaced by the true one.
// On the uniform grid (slip points = centres):
//   W_micro_paper = sum -(p . s) A - phi sum [(1 - L2/L3) x py - (1 - L1/L3) y px] A
void paper_work_is_force_times_physical_slip(void**)
{
    cw::Solver s(cwtest::uniform_grid(30, 30, 1.05));
    const cw::ContactInput in = contact(0.0006, 0.0003, 0.5, 1.5);
    const cw::SolveTotals t = s.solve(in);
    const auto px = cwtest::field(s, cw::Field::px), py = cwtest::field(s, cw::Field::py);
    const auto sx = cwtest::field(s, cw::Field::sx), sy = cwtest::field(s, cw::Field::sy);
    const auto x = cwtest::field(s, cw::Field::x), y = cwtest::field(s, cw::Field::y);
    const auto A = cwtest::field(s, cw::Field::area);
    const auto wp = cwtest::field(s, cw::Field::work_paper);
    double expected = 0.0;
    for (size_t k = 0; k < A.size(); ++k) {
        const double phys_x = sx[k] - (1 - t.L1 / t.L3) * in.phi * y[k];
        const double phys_y = sy[k] + (1 - t.L2 / t.L3) * in.phi * x[k];
        const double local = -(px[k] * phys_x + py[k] * phys_y) * A[k];
        assert_close(wp[k], local, 1e-12, 1e-15 * std::fabs(t.W_macro));
        expected += local;
    }
    assert_close(t.W_micro_paper, expected, 1e-12, 0.0);
    assert_close(t.K, t.W_macro / t.W_micro_paper, 1e-15, 0.0);
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
        cmocka_unit_test(paper_work_is_force_times_physical_slip),
        cmocka_unit_test(strips_without_slip),
        cmocka_unit_test(unresolved_slip_zone_is_flagged),
        cmocka_unit_test(lateral_profile),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
