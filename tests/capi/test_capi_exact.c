/* The exact model through the C ABI: cw_solver_prepare and
 * cw_batch_prepare, the result's p_max/approach/iterations/residual, named
 * errors, CW_ERR_NOT_CONVERGED leaving no solution, and one CONTACT row
 * (ab1_cmb, 20 elements across, tests/data/contact_exact_dev.csv;
 * CONTACT's units mm, N, N/mm^2). */
#include "capi_fixtures.h"

static cw_params cmb_row(void)
{
    cw_params p;
    cw_params_init(&p);
    p.model = CW_MODEL_EXACT;
    p.a = 6.0;
    p.b = 6.0;
    p.normal_force = 80000.0;
    p.mu = 0.3;
    p.G = 82000.0;
    p.nu = 0.28;
    p.xi_x = 0.001;
    p.xi_y = 0.0005;
    p.phi = 0.0002;
    return p;
}

static void test_prepare(void** state)
{
    (void)state;
    assert_int_equal(cw_solver_prepare(NULL, CW_MODEL_EXACT), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_batch_prepare(NULL, CW_MODEL_EXACT), CW_ERR_NULL_POINTER);
    cw_solver* strips = cw_test_solver(CW_GRID_KALKER_STRIPS, 20, 20, 1.0);
    assert_int_equal(cw_solver_prepare(strips, CW_MODEL_FASTSIM), CW_OK);
    assert_int_equal(cw_solver_prepare(strips, CW_MODEL_EXACT), CW_ERR_INVALID_INPUT);
    assert_names(cw_solver_last_error(strips), "uniform");
    assert_int_equal(cw_solver_prepare(strips, 7), CW_ERR_UNKNOWN_OPTION);
    assert_names(cw_solver_last_error(strips), "model = 7");
    /* The calibrated model runs on every grid FASTSIM runs on. */
    assert_int_equal(cw_solver_prepare(strips, CW_MODEL_CALIBRATED), CW_OK);
    cw_solver_destroy(strips);

    cw_solver* big = cw_test_solver(CW_GRID_UNIFORM, 257, 20, 1.1);
    assert_int_equal(cw_solver_prepare(big, CW_MODEL_EXACT), CW_ERR_GRID_OUT_OF_RANGE);
    assert_names(cw_solver_last_error(big), "nx = 257");
    cw_solver_destroy(big);

    cw_solver* s = cw_test_solver(CW_GRID_UNIFORM, 24, 24, 1.2);
    assert_int_equal(cw_solver_prepare(s, CW_MODEL_EXACT), CW_OK);
    assert_int_equal(cw_solver_prepare(s, CW_MODEL_EXACT), CW_OK); /* idempotent */
    cw_solver_destroy(s);

    cw_batch* b = cw_test_batch(CW_GRID_UNIFORM, 12, 12, 1.2, 2);
    assert_int_equal(cw_batch_prepare(b, CW_MODEL_EXACT), CW_OK);
    assert_int_equal(cw_batch_prepare(b, -1), CW_ERR_UNKNOWN_OPTION);
    cw_batch_destroy(b);
}

static void test_contact_row(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_UNIFORM, 24, 24, 1.2);
    cw_params p = cmb_row();
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
    /* CONTACT's FX, FY [N] and MZ [N mm] for ab1_cmb on 24 x 24. */
    const double F = hypot(-9802.446771474857, -9618.568108084106);
    assert_close(r.Fx, -9802.446771474857, 0.0, 1e-5 * F);
    assert_close(r.Fy, -9618.568108084106, 0.0, 1e-5 * F);
    assert_close(r.Mz, -10855.909669769027, 0.0, 1e-5 * F * 6.0);
    assert_close(r.p_max, 1058.8449623227186, 1e-5, 0.0);
    assert_close(r.approach, 0.0877677494455841, 1e-5, 0.0);
    assert_int_equal(r.n_adhesion, 203);
    assert_int_equal(r.n_slip, 113);
    assert_int_equal(r.model, CW_MODEL_EXACT);
    assert_true(r.iterations > 0 && r.residual <= 1e-8);
    assert_close(r.W_consistent, r.W_macro, 1e-12, 0.0);
    /* FASTSIM on the same handle reports no iterations, and its own p_max. */
    p.model = CW_MODEL_FASTSIM;
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
    assert_int_equal(r.model, CW_MODEL_FASTSIM);
    assert_int_equal(r.iterations, 0);
    cw_solver_destroy(s);
}

static void test_errors(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_UNIFORM, 24, 24, 1.2);
    cw_params p = cmb_row();
    cw_result r;
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);

    p.max_iterations = 1; /* partial slip needs more Newton steps from cold */
    p.warm_start = 0;
    cw_poison_result(&r);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_ERR_NOT_CONVERGED);
    assert_names(cw_solver_last_error(s), "max_iterations");
    double out[24 * 24];
    cw_fill(out, 24 * 24, CW_SENTINEL);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PX, out, 24 * 24), CW_ERR_NO_SOLUTION);
    assert_untouched(out, 24 * 24);
    p.max_iterations = 0;
    p.warm_start = 1;

    p.tolerance = 1e-15;
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_ERR_INVALID_INPUT);
    assert_names(cw_solver_last_error(s), "tolerance");
    p.tolerance = 0.0;
    p.flexibility = CW_FLEX_GIVEN;
    p.L1 = p.L2 = p.L3 = 1e-7;
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_ERR_INVALID_INPUT);
    assert_names(cw_solver_last_error(s), "flexibility");
    p = cmb_row();
    p.warm_start = 2;
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_ERR_INVALID_INPUT);
    assert_names(cw_solver_last_error(s), "warm_start");
    /* Still usable; the next warm solve starts cold (no solution to start from). */
    p.warm_start = 1;
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
    cw_solver_destroy(s);

    cw_solver* strips = cw_test_solver(CW_GRID_KALKER_STRIPS, 20, 20, 1.0);
    p = cmb_row();
    assert_int_equal(cw_solver_solve(strips, &p, CW_SOLVE_FULL, NULL), CW_ERR_INVALID_INPUT);
    assert_names(cw_solver_last_error(strips), "grid kind");
    cw_solver_destroy(strips);
}

/* A cold solve (warm_start = 0) on a handle whose earlier solves were warm
 * and of another a/b, or cold on the same contact with other creepages
 * (the cold solve's coarse correction made again, not kept: partial slip),
 * gives a fresh handle's bits: totals, pressure and tractions (the
 * header's determinism promise for cold solves). */
static void test_cold_solve_forgets_other_contacts(void** state)
{
    (void)state;
    enum { NX = 16, NY = 16, N = NX * NY };
    cw_params cold = cmb_row();
    cold.warm_start = 0;
    cw_params other = cmb_row();
    other.a = 9.0;
    other.xi_x = 0.004;
    cw_params warm = cmb_row();
    warm.xi_y = -0.0002;
    cw_params near = cold;
    near.xi_x = 0.0011;
    cw_result fresh_r, used_r;
    double fresh_f[3][N], used_f[3][N];
    const int fields[3] = {CW_FIELD_PZ, CW_FIELD_PX, CW_FIELD_PY};
    cw_solver* fresh = cw_test_solver(CW_GRID_UNIFORM, NX, NY, 1.1);
    cw_result_init(&fresh_r);
    assert_int_equal(cw_solver_solve(fresh, &cold, CW_SOLVE_FULL, &fresh_r), CW_OK);
    for (int f = 0; f < 3; ++f)
        assert_int_equal(cw_solver_get_field(fresh, fields[f], fresh_f[f], N), CW_OK);
    for (int before = 0; before < 3; ++before) {
        cw_solver* used = cw_test_solver(CW_GRID_UNIFORM, NX, NY, 1.1);
        assert_int_equal(cw_solver_solve(used, before == 2 ? &near : &other, CW_SOLVE_FORCES, NULL),
                         CW_OK);
        if (before == 1)
            assert_int_equal(cw_solver_solve(used, &warm, CW_SOLVE_FORCES, NULL), CW_OK);
        cw_result_init(&used_r);
        assert_int_equal(cw_solver_solve(used, &cold, CW_SOLVE_FULL, &used_r), CW_OK);
        for (int f = 0; f < 3; ++f)
            assert_int_equal(cw_solver_get_field(used, fields[f], used_f[f], N), CW_OK);
        assert_memory_equal(&used_r, &fresh_r, sizeof used_r);
        assert_memory_equal(used_f, fresh_f, sizeof used_f);
        cw_solver_destroy(used);
    }
    cw_solver_destroy(fresh);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_prepare),
        cmocka_unit_test(test_contact_row),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_cold_solve_forgets_other_contacts),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
