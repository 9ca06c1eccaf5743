// The two FASTSIM compatibility options, by what they mean rather than by
// one program's output (CONTACT's example: test_compat_contact_example.cpp).
//
// spin_offset s: the spin term of the lateral rigid slip is taken s element
// lengths ahead of the slip point, towards the leading edge:
//   w_y' = eta + (L2/L3) phi' (x' + s dx)   (rolling frame x' = d x, phi' = d phi)
// With fixed L's that is exactly a lateral creepage changed by
// (L2/L3) d phi s dx, whenever dx is the same for every strip: the uniform
// grid, and Kalker's strip grid with one strip (dx = 2a/nx). So each
// solve with an offset must equal a plain solve with that creepage, element
// by element, for both rolling directions.
//
// flexibility_blending: CONTACT's formula (contact/flexibility_blending.hpp)
// checked at its two ends: zero creepage (weight 1e-10/3) and full blending
// (weight 1: every L equals L_crss).
#include "compat_support.hpp"
#include "test_support.h"

#include <vector>

namespace {

struct Outcome {
    cw_result r{};
    std::vector<int> state;
    std::vector<double> px, py;
};

Outcome solve(int kind, int nx, int ny, const cw_params& p)
{
    cw_grid g;
    cw_grid_init(&g);
    g.kind = kind;
    g.nx = nx;
    g.ny = ny;
    g.box_scale = 1.1;
    cw_solver* s = nullptr;
    assert_int_equal(cw_solver_create(&g, &s, nullptr, 0), CW_OK);
    Outcome o;
    cw_result_init(&o.r);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &o.r), CW_OK);
    const size_t n = static_cast<size_t>(nx) * ny;
    o.state.resize(n);
    o.px.resize(n);
    o.py.resize(n);
    assert_int_equal(cw_solver_get_state(s, o.state.data(), n), CW_OK);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PX, o.px.data(), n), CW_OK);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PY, o.py.data(), n), CW_OK);
    cw_solver_destroy(s);
    return o;
}

cw_params contact(int direction, double xi, double eta, double phi)
{
    cw_params p;
    cw_params_init(&p);
    p.a = 8e-3;
    p.b = 4e-3;
    p.normal_force = 82e3;
    p.flexibility = CW_FLEX_GIVEN; // fixed L's: the identity needs them
    p.L1 = 4.9e-14;
    p.L2 = 5.2e-14;
    p.L3 = 4.1e-14;
    p.xi_x = xi;
    p.xi_y = eta;
    p.phi = phi;
    p.rolling_direction = direction;
    return p;
}

// Same states, and forces and tractions equal to rounding (the two solves
// add the same numbers in another order).
void assert_same(const Outcome& a, const Outcome& b)
{
    const double F = std::hypot(a.r.Fx, a.r.Fy);
    assert_close(a.r.Fx, b.r.Fx, 0.0, 1e-12 * F);
    assert_close(a.r.Fy, b.r.Fy, 0.0, 1e-12 * F);
    assert_close(a.r.Mz, b.r.Mz, 1e-11, 1e-12 * F * a.r.a);
    assert_int_equal(a.r.n_slip, b.r.n_slip);
    assert_true(a.state == b.state);
    double pmax = 0.0;
    for (double v : a.px) pmax = std::fmax(pmax, std::fabs(v));
    for (double v : a.py) pmax = std::fmax(pmax, std::fabs(v));
    for (size_t k = 0; k < a.px.size(); ++k) {
        assert_close(a.px[k], b.px[k], 0.0, 1e-12 * pmax);
        assert_close(a.py[k], b.py[k], 0.0, 1e-12 * pmax);
    }
}

void check_offset_is_a_creepage_shift(int kind, int nx, int ny, double dx)
{
    const double offsets[] = {1.0 / 6.0, 0.5, 1.0};
    int solves = 0;
    for (int d = -1; d <= 1; d += 2)
        for (double s : offsets)
            for (double phi : {0.3, -1.0, 2.0}) {
                cw_params with = contact(d, 2e-4, -6.25e-4, phi);
                with.spin_offset = s;
                cw_params shifted = contact(d, 2e-4, -6.25e-4, phi);
                shifted.xi_y += with.L2 / with.L3 * d * phi * s * dx;
                const Outcome a = solve(kind, nx, ny, with), b = solve(kind, nx, ny, shifted);
                assert_true(a.r.n_slip > 0 && a.r.n_adhesion > 0); // partial slip: a real test
                assert_same(a, b);
                solves += 2;
            }
    assert_int_equal(solves, 36);
}

void test_spin_offset_uniform_grid(void**)
{
    // dx = 2 S a / nx with S = 1.1.
    check_offset_is_a_creepage_shift(CW_GRID_UNIFORM, 44, 30, 2.0 * 1.1 * 8e-3 / 44);
}

void test_spin_offset_kalker_strip(void**)
{
    // One strip: its centre is y = 0, its chord 2a.
    check_offset_is_a_creepage_shift(CW_GRID_KALKER_STRIPS, 40, 1, 2.0 * 8e-3 / 40);
}

// FASTSIM's default offset is Kalker's, none: bitwise the same as 0.
void test_spin_offset_default_is_zero(void**)
{
    cw_params p = contact(1, 2e-4, -6.25e-4, 0.625);
    p.spin_offset = CW_SPIN_OFFSET_DEFAULT;
    const Outcome a = solve(CW_GRID_UNIFORM, 44, 44, p);
    p.spin_offset = 0.0;
    const Outcome b = solve(CW_GRID_UNIFORM, 44, 44, p);
    assert_memory_equal(&a.r, &b.r, sizeof a.r);
    assert_true(a.px == b.px && a.py == b.py && a.state == b.state);
}

cw_result flexibilities(double xi, double eta, double phi, int blending)
{
    cw_params p;
    cw_params_init(&p);
    p.a = 8e-3;
    p.b = 4e-3;
    p.normal_force = 82e3;
    p.xi_x = xi;
    p.xi_y = eta;
    p.phi = phi;
    p.flexibility_blending = blending;
    return solve(CW_GRID_UNIFORM, 8, 8, p).r;
}

void test_blending_ends(void**)
{
    // Zero creepage: CONTACT's weight is its floor 1e-10/3 and L_crss = 0.
    const cw_result kalker = flexibilities(0, 0, 0, 0), zero = flexibilities(0, 0, 0, 1);
    const double keep = 1.0 - 1e-10 / 3.0;
    assert_close(zero.L1, keep * kalker.L1, 1e-15, 0.0);
    assert_close(zero.L2, keep * kalker.L2, 1e-15, 0.0);
    assert_close(zero.L3, keep * kalker.L3, 1e-15, 0.0);
    // Three times the characteristic creepage: weight 1, every L is L_crss,
    // the creepage-weighted harmonic mean (here of L1 and L2 only).
    const double mu_N = 0.3 * 82e3, c2 = 8e-3 * 4e-3;
    const double ch = mu_N / (c2 * 82e9) * std::hypot(1.0 / kalker.C11, 1.0 / kalker.C22);
    const double xi = 3.0 * ch / std::sqrt(2.0), eta = -xi;
    const cw_result full = flexibilities(xi * 1.0001, eta * 1.0001, 0, 1);
    const double L_crss = 2.0 / (1.0 / kalker.L1 + 1.0 / kalker.L2);
    assert_close(full.L1, L_crss, 1e-12, 0.0);
    assert_close(full.L2, L_crss, 1e-12, 0.0);
    assert_close(full.L3, L_crss, 1e-12, 0.0);
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_spin_offset_uniform_grid),
        cmocka_unit_test(test_spin_offset_kalker_strip),
        cmocka_unit_test(test_spin_offset_default_is_zero),
        cmocka_unit_test(test_blending_ends),
    };
    return cmocka_run_group_tests_name("compat_options", tests, nullptr, nullptr);
}
