/* Work accumulator (paper eqs. 35 and 37): running totals and per-element
 * work over a simulation loop, and its error paths. */
#include "capi_fixtures.h"

#include <stdlib.h>

enum { NX = 16, NY = 11, N = NX * NY };

static cw_accumulator* make_accumulator(const cw_solver* s)
{
    cw_accumulator* acc = NULL;
    assert_int_equal(cw_accumulator_create(s, &acc), CW_OK);
    assert_non_null(acc);
    return acc;
}

static cw_accumulation totals_of(const cw_accumulator* acc)
{
    cw_accumulation t;
    cw_accumulation_init(&t);
    assert_int_equal(cw_accumulator_get_totals(acc, &t), CW_OK);
    return t;
}

/* A new (or reset) accumulator holds nothing: zero totals and maps. */
static void assert_empty(const cw_accumulator* acc)
{
    const cw_accumulation t = totals_of(acc);
    assert_true(t.distance == 0.0 && t.W_macro == 0.0 && t.W_micro_paper == 0.0 &&
                t.K == 0.0 && t.W_consistent == 0.0);
    assert_int_equal(t.steps, 0);
    double out[N];
    for (int f = CW_FIELD_WORK_PAPER; f <= CW_FIELD_WORK_CONSISTENT; ++f) {
        cw_fill(out, N, CW_SENTINEL);
        assert_int_equal(cw_accumulator_get_field(acc, f, out, N), CW_OK);
        assert_int_equal(cw_count_changed(out, N, 0.0), 0);
    }
    cw_fill(out, NY, CW_SENTINEL);
    assert_int_equal(cw_accumulator_get_strip_work(acc, out, NY), CW_OK);
    assert_int_equal(cw_count_changed(out, NY, 0.0), 0);
}

static void lifecycle(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_KALKER_STRIPS, NX, NY, 1.0);
    cw_accumulator* acc = make_accumulator(s); /* no solve needed to create */
    assert_empty(acc);
    assert_string_equal(cw_accumulator_last_error(acc), "");
    assert_int_equal(cw_accumulator_destroy(acc), CW_OK);
    assert_int_equal(cw_accumulator_destroy(NULL), CW_OK); /* header: NULL is a no-op */
    cw_solver_destroy(s);
}

/* A loop of steps with different contacts (a, b, creepage, pressure and
 * direction change) and step lengths V dt, one of them zero:
 *   distance = sum d_k; W_macro = sum W_macro_k d_k (eq. 35);
 *   W_micro_paper = sum W_micro_k d_k (eq. 37); K = their ratio (eq. 39);
 *   W_consistent = sum W_consistent_k d_k;
 *   each map element = sum d_k field_k (normalised patch grid, so element
 *   by element); strip work j = sum over i of the consistent map;
 *   sum of the consistent map = W_consistent.
 * Tolerances: rounding of sums of a few terms, 1e-13 of the magnitudes. */
static void sums_over_a_run(void** state, int kind, double box_scale)
{
    (void)state;
    cw_solver* s = cw_test_solver(kind, NX, NY, box_scale);
    cw_accumulator* acc = make_accumulator(s);
    const double distances[] = {0.02, 0.0, 0.035, 0.01, 0.5};
    const int cases[] = {0, 1, 2, 3, 4};
    const int steps = sizeof distances / sizeof distances[0];
    double paper[N] = {0}, consistent[N] = {0}, field[N];
    double dist = 0, W = 0, Wm = 0, Wc = 0, Wmag = 0;
    for (int k = 0; k < steps; ++k) {
        cw_params p;
        cw_test_case(cases[k], &p);
        cw_result r;
        cw_result_init(&r);
        assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
        assert_int_equal(cw_accumulator_add(acc, s, distances[k]), CW_OK);
        dist += distances[k];
        W += r.W_macro * distances[k];
        Wm += r.W_micro_paper * distances[k];
        Wc += r.W_consistent * distances[k];
        Wmag += (fabs(r.W_macro) + fabs(r.W_micro_paper)) * distances[k];
        assert_int_equal(cw_solver_get_field(s, CW_FIELD_WORK_PAPER, field, N), CW_OK);
        for (int e = 0; e < N; ++e) paper[e] += distances[k] * field[e];
        assert_int_equal(cw_solver_get_field(s, CW_FIELD_WORK_CONSISTENT, field, N), CW_OK);
        for (int e = 0; e < N; ++e) consistent[e] += distances[k] * field[e];
    }
    const cw_accumulation t = totals_of(acc);
    assert_int_equal(t.steps, steps);
    assert_close(t.distance, dist, 1e-15, 0.0);
    assert_close(t.W_macro, W, 0.0, 1e-13 * Wmag);
    assert_close(t.W_micro_paper, Wm, 0.0, 1e-13 * Wmag);
    assert_close(t.W_consistent, Wc, 0.0, 1e-13 * Wmag);
    assert_close(t.K, t.W_macro / t.W_micro_paper, 1e-15, 0.0);
    assert_true(t.W_macro > 0.0); /* the run dissipates */

    double acc_paper[N], acc_cons[N], strips[NY], scale = 0.0, total = 0.0;
    assert_int_equal(cw_accumulator_get_field(acc, CW_FIELD_WORK_PAPER, acc_paper, N), CW_OK);
    assert_int_equal(cw_accumulator_get_field(acc, CW_FIELD_WORK_CONSISTENT, acc_cons, N),
                     CW_OK);
    assert_int_equal(cw_accumulator_get_strip_work(acc, strips, NY), CW_OK);
    for (int e = 0; e < N; ++e) scale = fmax(scale, fabs(paper[e]) + fabs(consistent[e]));
    for (int e = 0; e < N; ++e) {
        assert_close(acc_paper[e], paper[e], 0.0, 1e-13 * scale);
        assert_close(acc_cons[e], consistent[e], 0.0, 1e-13 * scale);
        total += acc_cons[e];
    }
    assert_close(total, t.W_consistent, 1e-12, 0.0);
    for (int j = 0; j < NY; ++j) {
        double sum = 0.0;
        for (int i = 0; i < NX; ++i) sum += acc_cons[i + j * NX];
        assert_close(strips[j], sum, 1e-13, 1e-300);
    }

    /* Reset: back to empty, and a run after it equals a fresh accumulator's. */
    assert_int_equal(cw_accumulator_reset(acc), CW_OK);
    assert_empty(acc);
    cw_accumulator* fresh = make_accumulator(s);
    assert_int_equal(cw_accumulator_add(acc, s, 0.25), CW_OK);
    assert_int_equal(cw_accumulator_add(fresh, s, 0.25), CW_OK);
    const cw_accumulation a = totals_of(acc), b = totals_of(fresh);
    assert_memory_equal(&a, &b, sizeof a);
    cw_accumulator_destroy(fresh);
    cw_accumulator_destroy(acc);
    cw_solver_destroy(s);
}

static void sums_kalker_grid(void** state) { sums_over_a_run(state, CW_GRID_KALKER_STRIPS, 1.0); }
static void sums_uniform_grid(void** state) { sums_over_a_run(state, CW_GRID_UNIFORM, 1.1); }

/* ------------------------------------------------------------------- errors */

/* After each failed call the totals and maps are as before and the
 * accumulator still adds. */
static void assert_unchanged_and_usable(cw_accumulator* acc, cw_solver* good,
                                        const cw_accumulation* before)
{
    const cw_accumulation now = totals_of(acc);
    assert_memory_equal(&now, before, sizeof now);
    assert_int_equal(cw_accumulator_add(acc, good, 0.0), CW_OK);
    assert_string_equal(cw_accumulator_last_error(acc), "");
    const cw_accumulation after = totals_of(acc);
    assert_int_equal(after.steps, before->steps + 1);
}

static void create_errors(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_KALKER_STRIPS, NX, NY, 1.0);
    cw_accumulator* acc = (cw_accumulator*)s; /* not NULL: must be reset */
    assert_int_equal(cw_accumulator_create(NULL, &acc), CW_ERR_NULL_POINTER);
    assert_null(acc);
    assert_int_equal(cw_accumulator_create(s, NULL), CW_ERR_NULL_POINTER);
    /* CW_ERR_OUT_OF_MEMORY: test_capi_errors (needs an address-space limit). */
    assert_int_equal(cw_accumulator_reset(NULL), CW_ERR_NULL_POINTER);
    assert_names(cw_accumulator_last_error(NULL), "NULL");
    cw_solver_destroy(s);
}

static void add_errors(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_KALKER_STRIPS, NX, NY, 1.0);
    cw_accumulator* acc = make_accumulator(s);
    cw_params p;
    cw_test_case(2, &p);

    /* No solve yet, then a FORCES solve: nothing to add. */
    assert_int_equal(cw_accumulator_add(acc, s, 0.1), CW_ERR_NO_SOLUTION);
    assert_names(cw_accumulator_last_error(acc), "solve");
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FORCES, NULL), CW_OK);
    assert_int_equal(cw_accumulator_add(acc, s, 0.1), CW_ERR_NO_WORK);
    assert_names(cw_accumulator_last_error(acc), "CW_SOLVE_FULL");
    assert_empty(acc);

    /* One good step, so there is something to keep. */
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
    assert_int_equal(cw_accumulator_add(acc, s, 0.1), CW_OK);
    cw_accumulation before = totals_of(acc);
    double map_before[N], map_after[N];
    assert_int_equal(cw_accumulator_get_field(acc, CW_FIELD_WORK_CONSISTENT, map_before, N),
                     CW_OK);

    const double nan = strtod("nan", NULL), inf = strtod("inf", NULL);
    const double bad_distances[] = {-1e-3, nan, inf, -inf};
    for (int k = 0; k < 4; ++k) {
        assert_int_equal(cw_accumulator_add(acc, s, bad_distances[k]), CW_ERR_INVALID_INPUT);
        assert_names(cw_accumulator_last_error(acc), "distance");
        assert_unchanged_and_usable(acc, s, &before);
        before = totals_of(acc);
    }
    /* Finite but so long a step that the running totals would overflow
     * (W_macro * 1e308 J): refused, the accumulator unchanged. */
    assert_int_equal(cw_accumulator_add(acc, s, 1e308), CW_ERR_NUMERIC);
    assert_names(cw_accumulator_last_error(acc), "distance");
    assert_unchanged_and_usable(acc, s, &before);
    before = totals_of(acc);
    assert_int_equal(cw_accumulator_add(NULL, s, 0.1), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_accumulator_add(acc, NULL, 0.1), CW_ERR_NULL_POINTER);
    assert_names(cw_accumulator_last_error(acc), "solver");
    assert_unchanged_and_usable(acc, s, &before);
    before = totals_of(acc);

    /* Grids that differ in size, kind or box scale (all solved, FULL). */
    cw_solver* other[] = {
        cw_test_solver(CW_GRID_KALKER_STRIPS, NX + 1, NY, 1.0),
        cw_test_solver(CW_GRID_KALKER_STRIPS, NX, NY - 1, 1.0),
        cw_test_solver(CW_GRID_UNIFORM, NX, NY, 1.0),
    };
    for (int k = 0; k < 3; ++k) {
        assert_int_equal(cw_solver_solve(other[k], &p, CW_SOLVE_FULL, NULL), CW_OK);
        assert_int_equal(cw_accumulator_add(acc, other[k], 0.1), CW_ERR_GRID_MISMATCH);
        assert_names(cw_accumulator_last_error(acc), "grid");
        assert_unchanged_and_usable(acc, s, &before);
        before = totals_of(acc);
        cw_solver_destroy(other[k]);
    }
    cw_solver* u1 = cw_test_solver(CW_GRID_UNIFORM, NX, NY, 1.0);
    cw_solver* u2 = cw_test_solver(CW_GRID_UNIFORM, NX, NY, 1.5);
    cw_accumulator* uacc = make_accumulator(u1);
    assert_int_equal(cw_solver_solve(u2, &p, CW_SOLVE_FULL, NULL), CW_OK);
    assert_int_equal(cw_accumulator_add(uacc, u2, 0.1), CW_ERR_GRID_MISMATCH);
    assert_empty(uacc);
    cw_accumulator_destroy(uacc);
    cw_solver_destroy(u1);
    cw_solver_destroy(u2);

    /* A failed solve leaves no solution to add. */
    cw_params bad = p;
    bad.mu = -1.0;
    assert_int_equal(cw_solver_solve(s, &bad, CW_SOLVE_FULL, NULL), CW_ERR_INVALID_INPUT);
    assert_int_equal(cw_accumulator_add(acc, s, 0.1), CW_ERR_NO_SOLUTION);
    const cw_accumulation now = totals_of(acc);
    assert_memory_equal(&now, &before, sizeof now);
    assert_int_equal(cw_accumulator_get_field(acc, CW_FIELD_WORK_CONSISTENT, map_after, N),
                     CW_OK);
    assert_memory_equal(map_after, map_before, sizeof map_after);

    cw_accumulator_destroy(acc);
    cw_solver_destroy(s);
}

static void getter_errors(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_KALKER_STRIPS, NX, NY, 1.0);
    cw_accumulator* acc = make_accumulator(s);
    cw_params p;
    cw_test_case(0, &p);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
    assert_int_equal(cw_accumulator_add(acc, s, 0.3), CW_OK);

    cw_accumulation t;
    memset(&t, CW_POISON, sizeof t);
    t.struct_size = 0;
    const cw_accumulation poisoned = t;
    assert_int_equal(cw_accumulator_get_totals(NULL, &t), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_accumulator_get_totals(acc, NULL), CW_ERR_NULL_POINTER);
    assert_names(cw_accumulator_last_error(acc), "totals");
    assert_int_equal(cw_accumulator_get_totals(acc, &t), CW_ERR_STRUCT_SIZE);
    assert_names(cw_accumulator_last_error(acc), "struct_size");
    assert_memory_equal(&t, &poisoned, sizeof t);

    double out[N + 1];
    cw_fill(out, N + 1, CW_SENTINEL);
    const int not_work[] = {CW_FIELD_PX, CW_FIELD_X, -1, CW_FIELD_WORK_CONSISTENT + 1};
    for (int k = 0; k < 4; ++k) {
        assert_int_equal(cw_accumulator_get_field(acc, not_work[k], out, N),
                         CW_ERR_UNKNOWN_OPTION);
        assert_names(cw_accumulator_last_error(acc), "field");
    }
    assert_int_equal(cw_accumulator_get_field(NULL, CW_FIELD_WORK_PAPER, out, N),
                     CW_ERR_NULL_POINTER);
    assert_int_equal(cw_accumulator_get_field(acc, CW_FIELD_WORK_PAPER, NULL, N),
                     CW_ERR_NULL_POINTER);
    assert_names(cw_accumulator_last_error(acc), "out");
    assert_int_equal(cw_accumulator_get_field(acc, CW_FIELD_WORK_PAPER, out, N - 1),
                     CW_ERR_BUFFER_TOO_SMALL);
    assert_names(cw_accumulator_last_error(acc), "out");
    assert_untouched(out, N + 1);

    assert_int_equal(cw_accumulator_get_strip_work(NULL, out, NY), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_accumulator_get_strip_work(acc, NULL, NY), CW_ERR_NULL_POINTER);
    assert_names(cw_accumulator_last_error(acc), "out");
    assert_int_equal(cw_accumulator_get_strip_work(acc, out, NY - 1), CW_ERR_BUFFER_TOO_SMALL);
    assert_names(cw_accumulator_last_error(acc), "out");
    assert_untouched(out, N + 1);

    /* Still intact: one step of 0.3 of the solve. */
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_get_result(s, &r), CW_OK);
    cw_accumulation_init(&t);
    assert_int_equal(cw_accumulator_get_totals(acc, &t), CW_OK);
    assert_int_equal(t.steps, 1);
    assert_close(t.W_macro, 0.3 * r.W_macro, 1e-15, 0.0);
    cw_accumulator_destroy(acc);
    cw_solver_destroy(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(lifecycle),
        cmocka_unit_test(sums_kalker_grid),
        cmocka_unit_test(sums_uniform_grid),
        cmocka_unit_test(create_errors),
        cmocka_unit_test(add_errors),
        cmocka_unit_test(getter_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
