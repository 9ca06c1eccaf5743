/* cw_params.exact_load through the public header: the pressure scale set so
 * that the discrete load sum(pz * area) equals normal_force, so that
 * |F| <= mu N holds to rounding in full sliding on every grid and model.
 * Sources of the expected values: Coulomb's law (in full sliding along x
 * every element carries mu pz, so |Fx| = mu sum(pz area)); the models'
 * homogeneity in the pressure scale (FASTSIM depends on N only through
 * p0, so a solve with exact_load equals one at the load N' = N * N /
 * sum(pz area) of the default scale); central differences for the
 * Jacobians; and the default, whose discrete load differs from N. */
#include "capi_fixtures.h"

#include <math.h>
#include <stdlib.h>

enum { kMaxCells = 64 * 64 };

/* sum(pz * area) of the solver's last solve. */
static double discrete_load(const cw_solver* s)
{
    int nx = 0, ny = 0;
    assert_int_equal(cw_solver_grid_size(s, &nx, &ny), CW_OK);
    const size_t n = (size_t)nx * (size_t)ny;
    double* pz = malloc(n * sizeof *pz);
    double* area = malloc(n * sizeof *area);
    assert_non_null(pz);
    assert_non_null(area);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PZ, pz, n), CW_OK);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_AREA, area, n), CW_OK);
    double load = 0.0;
    for (size_t k = 0; k < n; ++k) load += pz[k] * area[k];
    free(pz);
    free(area);
    return load;
}

typedef struct {
    int kind, nx, ny, model, pressure;
} Setup;

static const Setup kSetups[] = {
    {CW_GRID_KALKER_STRIPS, 20, 20, CW_MODEL_FASTSIM, CW_PRESSURE_PARABOLIC},
    {CW_GRID_KALKER_STRIPS, 7, 11, CW_MODEL_FASTSIM, CW_PRESSURE_ELLIPTIC},
    {CW_GRID_UNIFORM, 20, 20, CW_MODEL_FASTSIM, CW_PRESSURE_PARABOLIC},
    {CW_GRID_UNIFORM, 15, 9, CW_MODEL_FASTSIM, CW_PRESSURE_ELLIPTIC},
    {CW_GRID_KALKER_STRIPS, 20, 20, CW_MODEL_CALIBRATED, CW_PRESSURE_PARABOLIC},
    {CW_GRID_UNIFORM, 24, 24, CW_MODEL_CALIBRATED, CW_PRESSURE_PARABOLIC},
    {CW_GRID_UNIFORM, 16, 16, CW_MODEL_EXACT, CW_PRESSURE_PARABOLIC},
};

static cw_params contact(const Setup* setup, double xi_x, double xi_y, double phi)
{
    cw_params p;
    cw_params_init(&p);
    p.a = 7.17e-3;
    p.b = 5.42e-3;
    p.normal_force = 100e3;
    p.model = setup->model;
    p.pressure = setup->pressure;
    p.xi_x = xi_x;
    p.xi_y = xi_y;
    p.phi = phi;
    p.exact_load = 1;
    return p;
}

/* In full sliding along x every contact element carries mu pz along -x:
 * |Fx| = mu N to rounding, with exact_load, on every grid and model. */
static void full_sliding_carries_mu_n(void** state)
{
    (void)state;
    for (size_t k = 0; k < sizeof kSetups / sizeof kSetups[0]; ++k) {
        const Setup* setup = &kSetups[k];
        cw_solver* s = cw_test_solver(setup->kind, setup->nx, setup->ny, 1.0);
        const double xis[] = {0.01, 0.05, 0.3};
        for (int i = 0; i < 3; ++i) {
            cw_params p = contact(setup, xis[i], 0.0, 0.0);
            cw_result r;
            cw_result_init(&r);
            assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
            const double muN = p.mu * p.normal_force;
            assert_close(discrete_load(s), p.normal_force, 1e-12, 0.0);
            if (setup->model != CW_MODEL_EXACT && i == 2) assert_int_equal(r.n_adhesion, 0);
            if (setup->model != CW_MODEL_EXACT && r.n_adhesion == 0)
                assert_close(-r.Fx, muN, 1e-12, 0.0); /* on the wheel, opposite to xi_x */
            /* Every model: never above mu N (the exact model's micro-slip
             * turns some traction sideways, so it may stay below). */
            assert_true(hypot(r.Fx, r.Fy) <= muN * (1.0 + 1e-12));
            assert_true(-r.Fx > 0.99 * muN);
        }
        /* Combined creepage with spin, saturated: the resultant stays within mu N. */
        cw_params p = contact(setup, 0.2, -0.1, 30.0);
        cw_result r;
        cw_result_init(&r);
        assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &r), CW_OK);
        assert_true(hypot(r.Fx, r.Fy) <= p.mu * p.normal_force * (1.0 + 1e-12));
        cw_solver_destroy(s);
    }
}

/* The default keeps the analytic scale: its discrete load differs from N
 * (by 0.15 % on the default 20 x 20 strip grid, as the grid's midpoint sum
 * of the parabola), so the option is what changes the numbers. */
static void default_keeps_the_analytic_scale(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_KALKER_STRIPS, 20, 20, 1.0);
    cw_params p = contact(&kSetups[0], 0.3, 0.0, 0.0);
    p.exact_load = 0;
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &r), CW_OK);
    const double load = discrete_load(s);
    assert_true(fabs(load / p.normal_force - 1.0) > 1e-4);
    /* Full sliding: |Fx| = mu * (the discrete load), not mu N. */
    assert_close(-r.Fx, p.mu * load, 1e-12, 0.0);
    /* A 1.1 caller's struct (ending before exact_load) gets the default. */
    cw_params old = p;
    old.exact_load = 1;
    old.struct_size = offsetof(cw_params, exact_load);
    cw_result r_old;
    cw_result_init(&r_old);
    assert_int_equal(cw_solver_solve(s, &old, CW_SOLVE_FORCES, &r_old), CW_OK);
    assert_true(cw_same_bits(r_old.Fx, r.Fx) && cw_same_bits(r_old.Fy, r.Fy));
    cw_solver_destroy(s);
}

/* FASTSIM depends on the load only through the pressure scale p0 = N c:
 * exact_load at N is the default scale at N' = N * N / load(N). */
static void equals_the_default_at_the_corrected_load(void** state)
{
    (void)state;
    const Setup setups[] = {kSetups[0], kSetups[3]};
    for (int k = 0; k < 2; ++k) {
        cw_solver* s = cw_test_solver(setups[k].kind, setups[k].nx, setups[k].ny, 1.0);
        cw_params p = contact(&setups[k], 8e-4, -5e-4, 0.4); /* partial slip */
        p.exact_load = 0;
        cw_result plain;
        cw_result_init(&plain);
        assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &plain), CW_OK);
        const double N_prime = p.normal_force * p.normal_force / discrete_load(s);

        cw_result exact;
        cw_result_init(&exact);
        p.exact_load = 1;
        assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &exact), CW_OK);
        assert_true(exact.n_slip > 0 && exact.n_adhesion > 0);

        cw_result shifted;
        cw_result_init(&shifted);
        p.exact_load = 0;
        p.normal_force = N_prime;
        assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &shifted), CW_OK);
        assert_int_equal(exact.n_slip, shifted.n_slip);
        const double F = hypot(exact.Fx, exact.Fy);
        assert_close(exact.Fx, shifted.Fx, 1e-12, 1e-12 * F);
        assert_close(exact.Fy, shifted.Fy, 1e-12, 1e-12 * F);
        assert_close(exact.Mz, shifted.Mz, 1e-12, 1e-12 * F * p.a);
        assert_close(exact.W_macro, shifted.W_macro, 1e-11, 0.0);
        assert_close(exact.p_max, shifted.p_max, 1e-13, 0.0);
        cw_solver_destroy(s);
    }
}

/* The Jacobian of the exact-load solve against central differences of it:
 * FASTSIM (the scale moves only with N) and the calibrated model, whose
 * bound blend moves with the creepages and with it the scale. */
static void jacobian_matches_central_differences(void** state)
{
    (void)state;
    const Setup setups[] = {kSetups[2], kSetups[5]};
    for (int k = 0; k < 2; ++k) {
        cw_solver* s = cw_test_solver(setups[k].kind, setups[k].nx, setups[k].ny, 1.0);
        cw_params p = contact(&setups[k], 1e-3, -6e-4, 0.3);
        double J[CW_JACOBIAN_LEN];
        cw_result r;
        cw_result_init(&r);
        assert_int_equal(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, &r, J, CW_JACOBIAN_LEN),
                         CW_OK);
        assert_true(r.n_slip > 0 && r.n_adhesion > 0);
        const double c = sqrt(p.a * p.b);
        const double scale[4] = {1e-3, 1e-3, 1e-3 / c, p.normal_force};
        const double rel = 1e-5; /* as test_capi_jacobian: no element flips at this step */
        for (int col = 0; col < 4; ++col) {
            cw_params up = p, down = p;
            double* field[4] = {&up.xi_x, &up.xi_y, &up.phi, &up.normal_force};
            double* field_down[4] = {&down.xi_x, &down.xi_y, &down.phi, &down.normal_force};
            *field[col] += rel * scale[col];
            *field_down[col] -= rel * scale[col];
            cw_result ru, rd;
            cw_result_init(&ru);
            cw_result_init(&rd);
            assert_int_equal(cw_solver_solve(s, &up, CW_SOLVE_FORCES, &ru), CW_OK);
            assert_int_equal(cw_solver_solve(s, &down, CW_SOLVE_FORCES, &rd), CW_OK);
            assert_int_equal(ru.n_slip, r.n_slip);
            assert_int_equal(rd.n_slip, r.n_slip);
            const double fu[4] = {ru.Fx, ru.Fy, ru.Mz, ru.W_macro};
            const double fd[4] = {rd.Fx, rd.Fy, rd.Mz, rd.W_macro};
            for (int row = 0; row < 4; ++row) {
                double row_scale = 0.0;
                for (int m = 0; m < 4; ++m) row_scale += fabs(J[4 * row + m]) * scale[m];
                const double fdiff = (fu[row] - fd[row]) / (2.0 * rel * scale[col]);
                assert_close(J[4 * row + col], fdiff, 0.0, 1e-6 * row_scale / scale[col]);
            }
        }
        cw_solver_destroy(s);
    }
}

static void invalid_flag_is_named(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_KALKER_STRIPS, 10, 10, 1.0);
    cw_params p = contact(&kSetups[0], 1e-3, 0.0, 0.0);
    p.exact_load = 2;
    cw_result r;
    cw_poison_result(&r);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &r), CW_ERR_INVALID_INPUT);
    assert_names(cw_solver_last_error(s), "exact_load");
    cw_solver_destroy(s);
}

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(full_sliding_carries_mu_n),
        cmocka_unit_test(default_keeps_the_analytic_scale),
        cmocka_unit_test(equals_the_default_at_the_corrected_load),
        cmocka_unit_test(jacobian_matches_central_differences),
        cmocka_unit_test(invalid_flag_is_named),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : NULL);
}
