/* Every handle's life, including the error paths, so that valgrind (label
 * "valgrind") and LeakSanitizer (the ASan stage) can prove there are no
 * leaks and no invalid accesses: create/solve/destroy of solvers,
 * accumulators and batches, failed creates, failed solves (exceptions and
 * messages inside the library), destruction in any order, NULL destroys. */
#include "capi_fixtures.h"

static void test_solver_lifecycle(void** state)
{
    (void)state;
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind)
        for (int round = 0; round < 5; ++round) {
            cw_solver* s = cw_test_solver(kind, 1 + 9 * round, 2 + 7 * round, 1.0 + round);
            cw_params p;
            cw_params_init(&p);
            p.xi_x = 1e-3;
            p.phi = round;
            cw_result r;
            cw_result_init(&r);
            assert_status(cw_solver_solve(s, &p, round % 2, &r), CW_OK);
            p.nu = 0.7; /* an error: exception and message inside */
            assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_ERR_INVALID_INPUT);
            assert_status(cw_solver_get_field(s, 99, NULL, 0), CW_ERR_UNKNOWN_OPTION);
            p.nu = 0.3;
            assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
            cw_check_solution(s, &p, CW_SOLVE_FULL, &r);
            cw_solver_destroy(s);
        }
    cw_solver_destroy(NULL);
}

static void test_failed_creates(void** state)
{
    (void)state;
    char msg[256];
    for (int k = 0; k < 20; ++k) {
        cw_grid g;
        cw_grid_init(&g);
        g.nx = k % 2 ? 0 : 1001;
        cw_solver* s = NULL;
        assert_status(cw_solver_create(&g, &s, msg, sizeof msg), CW_ERR_GRID_OUT_OF_RANGE);
        assert_null(s);
        cw_batch* b = NULL;
        g.kind = 5;
        assert_status(cw_batch_create(&g, 3, &b, msg, sizeof msg), CW_ERR_UNKNOWN_OPTION);
        assert_null(b);
    }
}

static void test_accumulator_and_batch_lifecycle(void** state)
{
    (void)state;
    for (int round = 0; round < 4; ++round) {
        cw_solver* s = cw_test_solver(round % 2, 12, 9, 1.2);
        cw_accumulator* acc = NULL;
        assert_status(cw_accumulator_create(s, &acc), CW_OK);
        cw_params p;
        cw_params_init(&p);
        p.xi_y = 2e-3;
        assert_status(cw_accumulator_add(acc, s, 1.0), CW_ERR_NO_SOLUTION);
        assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
        assert_status(cw_accumulator_add(acc, s, 1.0), CW_OK);
        assert_status(cw_accumulator_add(acc, s, -1.0), CW_ERR_INVALID_INPUT);
        assert_status(cw_accumulator_add(acc, s, 1e308), CW_ERR_NUMERIC);

        cw_batch* b = cw_test_batch(round % 2, 12, 9, 1.2, round);
        cw_params ps[5];
        cw_result rs[5];
        for (int k = 0; k < 5; ++k) {
            cw_params_init(&ps[k]);
            ps[k].xi_x = 1e-3 * k;
            cw_result_init(&rs[k]);
        }
        ps[2].G = -1.0;
        assert_status(cw_batch_solve(b, 5, ps, CW_SOLVE_FULL, rs, NULL), CW_ERR_INVALID_INPUT);
        ps[2].G = 82e9;
        assert_status(cw_batch_solve(b, 5, ps, CW_SOLVE_FULL, rs, NULL), CW_OK);

        /* Destruction in either order: the accumulator does not hold the solver. */
        if (round % 2) {
            cw_solver_destroy(s);
            cw_accumulator_destroy(acc);
        } else {
            cw_accumulator_destroy(acc);
            cw_solver_destroy(s);
        }
        cw_batch_destroy(b);
    }
    cw_accumulator_destroy(NULL);
    cw_batch_destroy(NULL);
}

static void test_free_function_errors(void** state)
{
    (void)state;
    char msg[32];
    double out[4], tx, ty;
    for (int k = 0; k < 10; ++k) {
        assert_status(cw_kalker_coefficients(-1.0, 0.3, out, msg, sizeof msg),
                      CW_ERR_INVALID_INPUT);
        assert_status(cw_kalker_flexibilities(1, 1, -1, 0.3, out, msg, sizeof msg),
                      CW_ERR_INVALID_INPUT);
        assert_status(cw_hertz_solve(1, 1, -1, 1, out, msg, sizeof msg), CW_ERR_INVALID_INPUT);
        assert_status(cw_fastsim_normalised(NAN, 0, 0, 0, 5, 5, 1, &tx, &ty, msg, sizeof msg),
                      CW_ERR_INVALID_INPUT);
        assert_status(cw_fastsim_normalised(1, 0, 0, 0, 0, 5, 1, &tx, &ty, msg, sizeof msg),
                      CW_ERR_GRID_OUT_OF_RANGE);
        assert_status(cw_fastsim_normalised(1, 0, 0.3, 0, 5, 5, 0.1, &tx, &ty, NULL, 0), CW_OK);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_solver_lifecycle),
        cmocka_unit_test(test_failed_creates),
        cmocka_unit_test(test_accumulator_and_batch_lifecycle),
        cmocka_unit_test(test_free_function_errors),
    };
    return cmocka_run_group_tests_name("robustness_lifecycle", tests, NULL, NULL);
}
