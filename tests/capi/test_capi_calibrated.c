/* CW_MODEL_CALIBRATED through the C ABI: it solves on both grid
 * kinds, every field, the state map and the profile are finite and
 * consistent with the totals, the result names the model, the energy-
 * consistent map sums to W_macro, given flexibilities are refused with a
 * message naming the input, and a batch of calibrated contacts gives
 * bitwise what one-by-one solves give, run after run. */
#include "capi_fixtures.h"

#include <math.h>
#include <stdlib.h>

enum { NX = 18, NY = 14, N = NX * NY };

/* The shared case list minus the given-flexibility case (7). */
static int calibrated_case(int k, cw_params* p)
{
    if (k == 7) return 0;
    cw_test_case(k, p);
    p->model = CW_MODEL_CALIBRATED;
    return 1;
}

static void every_field_finite(void** state)
{
    (void)state;
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind) {
        cw_solver* s = cw_test_solver(kind, NX, NY, 1.1);
        for (int k = 0; k < CW_TEST_CASES; ++k) {
            cw_params p;
            if (!calibrated_case(k, &p)) continue;
            cw_result r;
            cw_result_init(&r);
            assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
            assert_int_equal(r.model, CW_MODEL_CALIBRATED);
            const double totals[] = {r.Fx, r.Fy, r.Mz, r.W_macro, r.W_micro_paper, r.K,
                                     r.W_consistent, r.balance_factor, r.adhesion_fraction,
                                     r.profile_max_diff, r.profile_rms_diff, r.p_max};
            for (size_t q = 0; q < sizeof totals / sizeof totals[0]; ++q)
                assert_true(isfinite(totals[q]));
            double field[N], pz[N], area[N];
            assert_int_equal(cw_solver_get_field(s, CW_FIELD_PZ, pz, N), CW_OK);
            assert_int_equal(cw_solver_get_field(s, CW_FIELD_AREA, area, N), CW_OK);
            double load = 0;
            for (int e = 0; e < N; ++e) load += pz[e] * area[e];
            /* Coulomb on every element: |F| <= mu sum(pz area) (the grid's
             * load, not exactly N); 1e-12 for rounding. */
            assert_true(hypot(r.Fx, r.Fy) <= p.mu * load * (1 + 1e-12) + 1e-12);
            for (int f = CW_FIELD_X; f <= CW_FIELD_WORK_CONSISTENT; ++f) {
                cw_fill(field, N, CW_SENTINEL);
                assert_int_equal(cw_solver_get_field(s, f, field, N), CW_OK);
                double sum = 0;
                for (int e = 0; e < N; ++e) {
                    assert_true(isfinite(field[e]));
                    sum += field[e];
                }
                /* The consistent map sums to W_macro (header), the moment
                 * field to Mz (same sums in another order: 1e-9). */
                if (f == CW_FIELD_WORK_CONSISTENT)
                    assert_close(sum, r.W_macro, 1e-9, 1e-12 * (fabs(r.W_macro) + 1));
                if (f == CW_FIELD_MZ) assert_close(sum, r.Mz, 1e-9, 1e-12);
            }
            int states[N];
            cw_fill_int(states, N, CW_INT_SENTINEL);
            assert_int_equal(cw_solver_get_state(s, states, N), CW_OK);
            int slip = 0;
            for (int e = 0; e < N; ++e) slip += states[e] == CW_STATE_SLIP;
            assert_int_equal(slip, r.n_slip);
            double y[NY], w[NY], par[NY];
            assert_int_equal(cw_solver_get_profile(s, y, w, par, NY), CW_OK);
            for (int j = 0; j < NY; ++j)
                assert_true(isfinite(y[j]) && isfinite(w[j]) && isfinite(par[j]));
        }
        cw_solver_destroy(s);
    }
}

static void given_flexibilities_refused(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_KALKER_STRIPS, NX, NY, 1.0);
    cw_params p;
    cw_test_case(7, &p);
    p.model = CW_MODEL_CALIBRATED;
    cw_result r;
    cw_poison_result(&r);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_ERR_INVALID_INPUT);
    assert_names(cw_solver_last_error(s), "flexibility");
    assert_int_equal(cw_solver_get_result(s, &r), CW_ERR_NO_SOLUTION);
    cw_solver_destroy(s);
}

static void batch_is_deterministic(void** state)
{
    (void)state;
    enum { COUNT = 17 };
    cw_batch* b = cw_test_batch(CW_GRID_UNIFORM, NX, NY, 1.05, 0);
    assert_int_equal(cw_batch_prepare(b, CW_MODEL_CALIBRATED), CW_OK);
    cw_params p[COUNT];
    cw_result r[COUNT], again[COUNT];
    int n = 0;
    for (int k = 0; n < COUNT; ++k) {
        if (!calibrated_case(k % CW_TEST_CASES, &p[n])) continue;
        p[n].xi_x += 2e-5 * k; /* no two alike */
        p[n].phi -= 0.02 * k;
        ++n;
    }
    for (int k = 0; k < COUNT; ++k) {
        cw_result_init(&r[k]);
        cw_result_init(&again[k]);
    }
    int statuses[COUNT];
    assert_int_equal(cw_batch_solve(b, COUNT, p, CW_SOLVE_FULL, r, statuses), CW_OK);
    assert_int_equal(cw_batch_solve(b, COUNT, p, CW_SOLVE_FULL, again, NULL), CW_OK);
    assert_memory_equal(again, r, sizeof r);
    cw_solver* s = cw_test_solver(CW_GRID_UNIFORM, NX, NY, 1.05);
    for (int k = 0; k < COUNT; ++k) {
        assert_int_equal(statuses[k], CW_OK);
        cw_result one;
        cw_result_init(&one);
        assert_int_equal(cw_solver_solve(s, &p[k], CW_SOLVE_FULL, &one), CW_OK);
        assert_memory_equal(&one, &r[k], sizeof one);
    }
    cw_solver_destroy(s);
    cw_batch_destroy(b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_field_finite),
        cmocka_unit_test(given_flexibilities_refused),
        cmocka_unit_test(batch_is_deterministic),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
