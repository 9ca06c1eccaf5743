// Symmetries and units. Sources: mirror symmetry of the contact
// problem (the ellipse, the pressure and the grids are symmetric in x and y)
// and dimensional analysis.
#include "core_test_support.hpp"
#include "test_support.h"

namespace cw = creepwork;

namespace {

cw::ContactInput combined(double xi, double eta, double phi)
{
    cw::ContactInput in = cwtest::steel_contact(2.0);
    in.xi_x = xi;
    in.xi_y = eta;
    in.phi = phi;
    return in;
}

std::vector<cw::GridSpec> grids()
{
    return {cwtest::kalker_grid(30, 24), cwtest::uniform_grid(32, 26, 1.1)};
}

// Mirror y -> -y maps (xi, eta, phi) to (xi, -eta, -phi) and flips Fy, Mz;
// without spin, eta -> -eta alone does it.
void lateral_mirror(void**)
{
    for (const cw::GridSpec& g : grids()) {
        cw::Solver s(g);
        const cw::SolveTotals a = s.solve(combined(0.001, 0.0007, 0.0));
        const cw::SolveTotals b = s.solve(combined(0.001, -0.0007, 0.0));
        const double F = std::hypot(a.Fx, a.Fy);
        assert_close(b.Fx, a.Fx, 0.0, 1e-12 * F);
        assert_close(b.Fy, -a.Fy, 0.0, 1e-12 * F);
        assert_close(b.Mz, -a.Mz, 0.0, 1e-12 * F * 6e-3);
        const cw::SolveTotals c = s.solve(combined(0.001, 0.0007, 0.4));
        const cw::SolveTotals d = s.solve(combined(0.001, -0.0007, -0.4));
        assert_close(d.Fx, c.Fx, 0.0, 1e-12 * F);
        assert_close(d.Fy, -c.Fy, 0.0, 1e-12 * F);
        assert_close(d.Mz, -c.Mz, 0.0, 1e-12 * F * 6e-3);
        assert_int_equal(d.n_slip, c.n_slip);
    }
}

// Pure spin: px is odd in y, so Fx = 0 (to rounding), while Fy and Mz are not.
void pure_spin_has_no_longitudinal_force(void**)
{
    for (const cw::GridSpec& g : grids()) {
        cw::Solver s(g);
        const cw::SolveTotals t = s.solve(combined(0.0, 0.0, 2.0));
        assert_true(std::fabs(t.Fy) > 100.0);
        assert_close(t.Fx, 0.0, 0.0, 1e-12 * std::fabs(t.Fy));
        assert_true(t.Mz < 0.0);  // opposes positive spin (Kalker: Mz = -G c^4 C33 phi)
    }
}

// Rolling towards -x is the mirror x -> -x of rolling towards +x with
// (xi, eta, phi) -> (-xi, eta, -phi): maps mirror in i, x-components flip.
void reversed_rolling_mirrors_the_maps(void**)
{
    for (const cw::GridSpec& g : grids()) {
        cw::Solver fwd(g), rev(g);
        cw::ContactInput a = combined(0.0008, 0.0005, 0.3);
        cw::ContactInput b = combined(-0.0008, 0.0005, -0.3);
        b.rolling_direction = -1;
        const cw::SolveTotals ta = fwd.solve(a), tb = rev.solve(b);
        assert_true(ta.Fx == -tb.Fx && ta.Fy == tb.Fy && ta.Mz == -tb.Mz);
        assert_true(ta.W_macro == tb.W_macro && ta.W_consistent == tb.W_consistent);
        const int nx = g.nx, ny = g.ny;
        const auto sa = cwtest::states(fwd), sb = cwtest::states(rev);
        struct Mirror {
            cw::Field f;
            double sign;
        };
        const Mirror fields[] = {{cw::Field::x, -1}, {cw::Field::y, 1},
                                 {cw::Field::px, -1}, {cw::Field::py, 1},
                                 {cw::Field::sx, -1}, {cw::Field::sy, 1},
                                 {cw::Field::mz, -1}, {cw::Field::work_consistent, 1},
                                 {cw::Field::work_paper, 1}, {cw::Field::pz, 1}};
        for (const Mirror& m : fields) {
            const auto fa = cwtest::field(fwd, m.f), fb = cwtest::field(rev, m.f);
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx; ++i)
                    assert_true(fa[i + j * nx] == m.sign * fb[(nx - 1 - i) + j * nx]);
        }
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) assert_int_equal(sa[i + j * nx], sb[(nx - 1 - i) + j * nx]);
    }
}

// Physics of the direction: the leading edge adheres, the trailing edge
// slips. Rolling towards +x the leading edge is at x = +a; towards -x, -a.
void adhesion_at_the_leading_edge(void**)
{
    for (int direction : {1, -1}) {
        cw::Solver s(cwtest::kalker_grid(40, 20));
        cw::ContactInput in = combined(0.0005, 0.0, 0.0);
        in.rolling_direction = direction;
        s.solve(in);
        const auto st = cwtest::states(s);
        const int nx = 40, j = 10;  // a strip near the centre line
        const int leading = direction > 0 ? nx - 1 : 0, trailing = direction > 0 ? 0 : nx - 1;
        assert_int_equal(st[leading + j * nx], 1);
        assert_int_equal(st[trailing + j * nx], 2);
    }
}

// The library is unit-consistent: SI (m, N, Pa, 1/m) and (mm, N, MPa, 1/mm)
// give the same forces, Mz x 1000 (N m -> N mm) and the same work per unit
// rolling distance (J/m = N = N mm/mm).
void units_scale(void**)
{
    for (const cw::GridSpec& g : grids()) {
        cw::Solver s(g);
        const cw::ContactInput si = combined(0.0008, -0.0004, 0.5);
        cw::ContactInput mm = si;
        mm.a *= 1e3;
        mm.b *= 1e3;
        mm.G *= 1e-6;
        mm.phi *= 1e-3;
        const cw::SolveTotals a = s.solve(si);
        const cw::SolveTotals b = s.solve(mm);
        const double F = std::hypot(a.Fx, a.Fy);
        assert_close(b.Fx, a.Fx, 1e-12, 1e-12 * F);
        assert_close(b.Fy, a.Fy, 1e-12, 1e-12 * F);
        assert_close(b.Mz, 1e3 * a.Mz, 1e-11, 1e-12 * F * 6);
        assert_close(b.W_macro, a.W_macro, 1e-11, 0.0);
        assert_int_equal(b.n_slip, a.n_slip);
    }
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(lateral_mirror),
        cmocka_unit_test(pure_spin_has_no_longitudinal_force),
        cmocka_unit_test(reversed_rolling_mirrors_the_maps),
        cmocka_unit_test(adhesion_at_the_leading_edge),
        cmocka_unit_test(units_scale),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
