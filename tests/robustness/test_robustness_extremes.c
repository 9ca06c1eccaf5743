/* Extreme but valid inputs give finite, physically bounded results:
 * creepages 1e-12 .. 1 (and far beyond), spin up to 100/a, a/b at both ends
 * of its range, mu = 0, grids from 1x1 to 1000x1000, both grids, both
 * pressures, both rolling directions. For every solve (cw_check_solution):
 * no NaN or Inf in any total or field, |p| <= mu pz on every element,
 * |F| <= sum mu pz area, counts consistent with the state map, and the
 * energy-consistent map non-negative and summing to W_macro. */
#include "capi_fixtures.h"

/* Solves in both modes, checks both, returns the FULL result; FORCES and
 * FULL agree on the forces bit for bit. */
static cw_result solve_checked(cw_solver* s, const cw_params* p)
{
    cw_result forces, full;
    cw_result_init(&forces);
    cw_result_init(&full);
    const int st = cw_solver_solve(s, p, CW_SOLVE_FORCES, &forces);
    if (st != CW_OK) {
        print_error("solve failed (%s): a=%g b=%g N=%g mu=%g xi=(%g, %g) phi=%g\n",
                    cw_solver_last_error(s), p->a, p->b, p->normal_force, p->mu, p->xi_x,
                    p->xi_y, p->phi);
        _fail(__FILE__, __LINE__);
    }
    cw_check_solution(s, p, CW_SOLVE_FORCES, &forces);
    assert_status(cw_solver_solve(s, p, CW_SOLVE_FULL, &full), CW_OK);
    cw_check_solution(s, p, CW_SOLVE_FULL, &full);
    assert_true(forces.Fx == full.Fx && forces.Fy == full.Fy && forces.Mz == full.Mz);
    return full;
}

/* The discrete bound sum mu pz area of the last solve. */
static double traction_bound(const cw_solver* s, double mu)
{
    const size_t n = cw_cells(s);
    double* pz = cw_field(s, CW_FIELD_PZ);
    double* area = cw_field(s, CW_FIELD_AREA);
    double bound = 0.0;
    for (size_t k = 0; k < n; ++k) bound += mu * pz[k] * area[k];
    free(pz);
    free(area);
    return bound;
}

static void test_creepage_and_spin_ranges(void** state)
{
    (void)state;
    const double creepages[] = {1e-12, -1e-9, 1e-6, -1e-4, 1e-3, -1e-2, 0.1, 1.0};
    const double spins_over_a[] = {0.0, 1e-12, -1.0, 10.0, -100.0, 100.0};
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind) {
        cw_solver* s = cw_test_solver(kind, 16, 13, 1.25);
        for (int pressure = CW_PRESSURE_PARABOLIC; pressure <= CW_PRESSURE_ELLIPTIC; ++pressure)
            for (int dir = -1; dir <= 1; dir += 2)
                for (size_t c = 0; c < sizeof creepages / sizeof creepages[0]; ++c)
                    for (size_t w = 0; w < sizeof spins_over_a / sizeof spins_over_a[0]; ++w) {
                        cw_params p;
                        cw_params_init(&p);
                        p.pressure = pressure;
                        p.rolling_direction = dir;
                        p.phi = spins_over_a[w] / p.a;
                        p.xi_x = creepages[c];
                        p.xi_y = 0.0;
                        solve_checked(s, &p);
                        p.xi_x = 0.0;
                        p.xi_y = creepages[c];
                        solve_checked(s, &p);
                        p.xi_x = -0.7 * creepages[c];
                        solve_checked(s, &p);
                    }
        cw_solver_destroy(s);
    }
}

/* Far beyond 1 the contact slides everywhere: |F| reaches the discrete
 * bound sum mu pz area (to rounding), it never exceeds it and never
 * collapses. Up to 1e100 the rigid slip cannot overflow. */
static void test_full_sliding(void** state)
{
    (void)state;
    const double creepages[] = {10.0, 1e6, 1e50, 1e100};
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind) {
        cw_solver* s = cw_test_solver(kind, 20, 20, 1.0);
        for (int pressure = CW_PRESSURE_PARABOLIC; pressure <= CW_PRESSURE_ELLIPTIC; ++pressure)
            for (size_t c = 0; c < sizeof creepages / sizeof creepages[0]; ++c) {
                cw_params p;
                cw_params_init(&p);
                p.pressure = pressure;
                p.xi_x = creepages[c];
                const cw_result r = solve_checked(s, &p);
                const double bound = traction_bound(s, p.mu);
                assert_close(hypot(r.Fx, r.Fy), bound, 1e-9, 0.0);
                assert_true(r.Fx < 0.0); /* on the wheel: opposite to the creepage */
                assert_int_equal(r.n_slip, r.n_contact);
            }
        cw_solver_destroy(s);
    }
}

/* a/b at both ends of [1e-3, 1e3] (and near the table's edges at 0.1 and
 * 10), both flexibility sources, creepage and spin up to 100/a. */
static void test_aspect_ratio_ends(void** state)
{
    (void)state;
    const double ratios[] = {1e-3, 2e-3, 0.0999, 0.1, 1.0, 10.0, 10.01, 500.0, 1e3};
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind) {
        cw_solver* s = cw_test_solver(kind, 24, 17, 1.0);
        for (size_t k = 0; k < sizeof ratios / sizeof ratios[0]; ++k)
            for (int flex = CW_FLEX_FROM_MATERIAL; flex <= CW_FLEX_GIVEN; ++flex) {
                cw_params p;
                cw_params_init(&p);
                p.b = 1.0;
                p.a = ratios[k]; /* exactly representable ratio a/b */
                p.flexibility = flex;
                p.L1 = 2e-11;
                p.L2 = 3e-11;
                p.L3 = 5e-11;
                const double xis[] = {1e-12, 1e-5, 1e-3, 1.0};
                for (int c = 0; c < 4; ++c) {
                    p.xi_x = xis[c];
                    p.xi_y = -0.5 * xis[c];
                    p.phi = 0.0;
                    solve_checked(s, &p);
                    p.phi = 100.0 / p.a;
                    solve_checked(s, &p);
                    p.phi = -1.0 / p.a;
                    solve_checked(s, &p);
                }
            }
        cw_solver_destroy(s);
    }
}

/* Units from micro-contacts to large ones: every combination is finite. */
static void test_wide_magnitudes(void** state)
{
    (void)state;
    const double sizes[] = {1e-9, 1e-6, 6e-3, 1.0, 1e3};
    const double loads[] = {1e-12, 1e-3, 80e3, 1e9, 1e15};
    const double moduli[] = {1e3, 1e6, 82e9, 1e15};
    const double mus[] = {0.0, 1e-6, 0.3, 10.0};
    cw_solver* s = cw_test_solver(CW_GRID_KALKER_STRIPS, 8, 7, 1.0);
    for (size_t i = 0; i < 5; ++i)
        for (size_t j = 0; j < 5; ++j)
            for (size_t k = 0; k < 4; ++k)
                for (size_t m = 0; m < 4; ++m) {
                    cw_params p;
                    cw_params_init(&p);
                    p.a = sizes[i];
                    p.b = 2.0 * sizes[i];
                    p.normal_force = loads[j];
                    p.G = moduli[k];
                    p.mu = mus[m];
                    p.xi_x = 1e-3;
                    p.xi_y = 2e-4;
                    p.phi = 3.0 / p.a;
                    solve_checked(s, &p);
                }
    cw_solver_destroy(s);
}

static void test_zero_friction(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_UNIFORM, 30, 30, 1.1);
    cw_params p;
    cw_params_init(&p);
    p.mu = 0.0;
    p.xi_x = 1.0;
    p.phi = 100.0 / p.a;
    const cw_result r = solve_checked(s, &p);
    assert_true(r.Fx == 0.0 && r.Fy == 0.0 && r.Mz == 0.0 && r.W_macro == 0.0);
    cw_solver_destroy(s);
}

static void test_grid_sizes(void** state)
{
    (void)state;
    const int cells[] = {1, 2, 3, 7, 64};
    const double scales[] = {1.0, 3.7, CW_MAX_BOX_SCALE};
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind)
        for (int i = 0; i < 5; ++i)
            for (int j = 0; j < 5; ++j)
                for (int b = 0; b < (kind == CW_GRID_UNIFORM ? 3 : 1); ++b) {
                    cw_solver* s = cw_test_solver(kind, cells[i], cells[j], scales[b]);
                    for (int pressure = CW_PRESSURE_PARABOLIC; pressure <= CW_PRESSURE_ELLIPTIC;
                         ++pressure) {
                        cw_params p;
                        cw_params_init(&p);
                        p.pressure = pressure;
                        p.xi_x = 2e-3;
                        p.xi_y = -1e-3;
                        p.phi = 20.0;
                        const cw_result r = solve_checked(s, &p);
                        if (r.n_contact == 0) /* a box too coarse to hold the ellipse */
                            assert_true(r.Fx == 0.0 && r.Fy == 0.0 && r.adhesion_fraction == 0.0);
                    }
                    cw_solver_destroy(s);
                }
}

/* A few solves at the maximum grid size (1000 x 1000 = 1e6 elements). */
static void test_maximum_grid(void** state)
{
    (void)state;
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind) {
        cw_solver* s = cw_test_solver(kind, CW_MAX_GRID_CELLS, CW_MAX_GRID_CELLS, 1.0);
        cw_params p;
        cw_params_init(&p);
        p.pressure = kind == CW_GRID_UNIFORM ? CW_PRESSURE_ELLIPTIC : CW_PRESSURE_PARABOLIC;
        p.xi_x = 1e-3;
        p.xi_y = 5e-4;
        p.phi = 100.0 / p.a;
        solve_checked(s, &p);
        cw_solver_destroy(s);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_creepage_and_spin_ranges),
        cmocka_unit_test(test_full_sliding),
        cmocka_unit_test(test_aspect_ratio_ends),
        cmocka_unit_test(test_wide_magnitudes),
        cmocka_unit_test(test_zero_friction),
        cmocka_unit_test(test_grid_sizes),
        cmocka_unit_test(test_maximum_grid),
    };
    return cmocka_run_group_tests_name("robustness_extremes", tests, NULL, NULL);
}
