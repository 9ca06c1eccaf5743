/* Batch solves: many independent contacts in one call give what one-by-one
 * solves give, and the batch's error paths. (Thread counts 1..8: see
 * test_capi_threads.) */
#include "capi_fixtures.h"

#include <stdlib.h>

enum { COUNT = 23 };

/* Contact k of a batch: the case list with the load and creepages varied,
 * so no two contacts are alike. */
static void batch_case(int k, cw_params* p)
{
    cw_test_case(k % CW_TEST_CASES, p);
    p->normal_force *= 1.0 + 0.05 * k;
    p->xi_x += 1e-5 * k;
    p->phi -= 0.01 * k;
}

static cw_grid grid_of(int kind) { return cw_test_grid(kind, 14, 9, 1.1); }

static cw_batch* make_batch(int kind, int threads)
{
    cw_batch* b = cw_test_batch(kind, 14, 9, 1.1, threads);
    assert_string_equal(cw_batch_last_error(b), "");
    return b;
}

/* The one-by-one answer for contact k. */
static void solve_one(const cw_grid* g, const cw_params* p, int mode, cw_result* r)
{
    cw_solver* s = NULL;
    assert_int_equal(cw_solver_create(g, &s, NULL, 0), CW_OK);
    cw_result_init(r);
    assert_int_equal(cw_solver_solve(s, p, mode, r), CW_OK);
    cw_solver_destroy(s);
}

static void lifecycle(void** state)
{
    (void)state;
    const int threads[] = {0, 1, 3, -2}; /* <= 0: all cores */
    for (int k = 0; k < 4; ++k) {
        cw_batch* b = make_batch(CW_GRID_KALKER_STRIPS, threads[k]);
        assert_string_equal(cw_batch_last_error(b), "");
        assert_int_equal(cw_batch_destroy(b), CW_OK);
    }
    assert_int_equal(cw_batch_destroy(NULL), CW_OK); /* header: NULL is a no-op */
    assert_names(cw_batch_last_error(NULL), "NULL");
}

/* Header: results are bitwise identical to one-by-one cw_solver_solve, and
 * statuses are all CW_OK. Both grid kinds, both modes. */
static void batch_equals_one_by_one(void** state)
{
    (void)state;
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind)
        for (int mode = CW_SOLVE_FORCES; mode <= CW_SOLVE_FULL; ++mode) {
            const cw_grid g = grid_of(kind);
            cw_batch* b = make_batch(kind, 0);
            cw_params p[COUNT];
            cw_result r[COUNT], expected;
            int statuses[COUNT];
            cw_fill_int(statuses, COUNT, CW_INT_SENTINEL);
            for (int k = 0; k < COUNT; ++k) {
                batch_case(k, &p[k]);
                cw_result_init(&r[k]);
            }
            assert_int_equal(cw_batch_solve(b, COUNT, p, mode, r, statuses), CW_OK);
            assert_string_equal(cw_batch_last_error(b), "");
            for (int k = 0; k < COUNT; ++k) {
                solve_one(&g, &p[k], mode, &expected);
                assert_memory_equal(&r[k], &expected, sizeof expected);
                assert_int_equal(statuses[k], CW_OK);
            }
            /* statuses may be NULL; the batch can be reused. */
            cw_result again[COUNT];
            for (int k = 0; k < COUNT; ++k) cw_result_init(&again[k]);
            assert_int_equal(cw_batch_solve(b, COUNT, p, mode, again, NULL), CW_OK);
            assert_memory_equal(again, r, sizeof r);
            cw_batch_destroy(b);
        }
}

/* count = 0: nothing to do, nothing written. */
static void empty_batch(void** state)
{
    (void)state;
    cw_batch* b = make_batch(CW_GRID_UNIFORM, 2);
    cw_params p;
    cw_params_init(&p);
    cw_result r, before;
    cw_poison_result(&r);
    before = r;
    int status = CW_INT_SENTINEL;
    assert_int_equal(cw_batch_solve(b, 0, &p, CW_SOLVE_FULL, &r, &status), CW_OK);
    assert_memory_equal(&r, &before, sizeof r);
    assert_int_equal(status, CW_INT_SENTINEL);
    cw_batch_destroy(b);
}

/* ------------------------------------------------------------------- errors */

static void create_errors(void** state)
{
    (void)state;
    cw_grid g = grid_of(CW_GRID_UNIFORM);
    char message[128];
    cw_batch* b = (cw_batch*)&g; /* not NULL: must be reset */
    assert_int_equal(cw_batch_create(NULL, 2, &b, message, sizeof message),
                     CW_ERR_NULL_POINTER);
    assert_null(b);
    assert_names(message, "grid");
    assert_int_equal(cw_batch_create(&g, 2, NULL, message, sizeof message), CW_ERR_NULL_POINTER);
    assert_names(message, "batch");

    const struct {
        int field; /* 0 struct_size, 1 kind, 2 nx, 3 box_scale */
        int status;
        const char* names;
    } bad[] = {
        {0, CW_ERR_STRUCT_SIZE, "struct_size"},
        {1, CW_ERR_UNKNOWN_OPTION, "kind"},
        {2, CW_ERR_GRID_OUT_OF_RANGE, "nx"},
        {3, CW_ERR_GRID_OUT_OF_RANGE, "box_scale"},
    };
    for (int k = 0; k < 4; ++k) {
        g = grid_of(CW_GRID_UNIFORM);
        if (bad[k].field == 0) g.struct_size = 0;
        if (bad[k].field == 1) g.kind = 5;
        if (bad[k].field == 2) g.nx = CW_MAX_GRID_CELLS + 1;
        if (bad[k].field == 3) g.box_scale = 0.5;
        b = (cw_batch*)&g;
        assert_int_equal(cw_batch_create(&g, 2, &b, message, sizeof message), bad[k].status);
        assert_null(b);
        assert_names(message, bad[k].names);
    }
    /* More threads than CW_MAX_BATCH_THREADS (each would own a solver). */
    g = grid_of(CW_GRID_UNIFORM);
    b = (cw_batch*)&g;
    assert_int_equal(cw_batch_create(&g, CW_MAX_BATCH_THREADS + 1, &b, message, sizeof message),
                     CW_ERR_INVALID_INPUT);
    assert_null(b);
    assert_names(message, "threads");
    /* CW_ERR_OUT_OF_MEMORY: test_capi_errors (needs an address-space limit). */
}

/* Arguments that fail the whole call before any contact is solved: nothing
 * written, statuses included. */
static void solve_argument_errors(void** state)
{
    (void)state;
    cw_batch* b = make_batch(CW_GRID_KALKER_STRIPS, 2);
    cw_params p[4];
    cw_result r[4], before[4];
    int statuses[4];
    for (int k = 0; k < 4; ++k) {
        batch_case(k, &p[k]);
        cw_poison_result(&r[k]);
    }
    memcpy(before, r, sizeof r);
    cw_fill_int(statuses, 4, CW_INT_SENTINEL);

    assert_int_equal(cw_batch_solve(NULL, 4, p, CW_SOLVE_FULL, r, statuses), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_batch_solve(b, 4, NULL, CW_SOLVE_FULL, r, statuses), CW_ERR_NULL_POINTER);
    assert_names(cw_batch_last_error(b), "params");
    assert_int_equal(cw_batch_solve(b, 4, p, CW_SOLVE_FULL, NULL, statuses), CW_ERR_NULL_POINTER);
    assert_names(cw_batch_last_error(b), "results");
    assert_int_equal(cw_batch_solve(b, 4, p, 7, r, statuses), CW_ERR_UNKNOWN_OPTION);
    assert_names(cw_batch_last_error(b), "mode");

    p[0].struct_size = 0;
    assert_int_equal(cw_batch_solve(b, 4, p, CW_SOLVE_FULL, r, statuses), CW_ERR_STRUCT_SIZE);
    assert_names(cw_batch_last_error(b), "params[0].struct_size");
    p[0].struct_size = sizeof(cw_params);
    /* Every element must carry element 0's struct_size (it is the stride). */
    p[3].struct_size = sizeof(cw_params) - 8;
    assert_int_equal(cw_batch_solve(b, 4, p, CW_SOLVE_FULL, r, statuses), CW_ERR_STRUCT_SIZE);
    assert_names(cw_batch_last_error(b), "params[3]");
    p[3].struct_size = sizeof(cw_params);
    r[0].struct_size = 0;
    assert_int_equal(cw_batch_solve(b, 4, p, CW_SOLVE_FULL, r, statuses), CW_ERR_STRUCT_SIZE);
    assert_names(cw_batch_last_error(b), "results[0].struct_size");
    r[0].struct_size = sizeof(cw_result);
    r[2].struct_size = 16;
    assert_int_equal(cw_batch_solve(b, 4, p, CW_SOLVE_FULL, r, statuses), CW_ERR_STRUCT_SIZE);
    assert_names(cw_batch_last_error(b), "results[2]");
    r[2].struct_size = sizeof(cw_result);

    assert_memory_equal(r, before, sizeof r);
    assert_untouched_int(statuses, 4);
    assert_int_equal(cw_batch_solve(b, 4, p, CW_SOLVE_FULL, r, statuses), CW_OK);
    assert_string_equal(cw_batch_last_error(b), "");
    cw_batch_destroy(b);
}

/* Per-contact failures: every contact gets its own status, the call returns
 * the first failing contact's status with a message naming its index and
 * input, failed results stay untouched, and the others are exactly the
 * one-by-one results. */
static void per_contact_errors(void** state)
{
    (void)state;
    for (int threads = 1; threads <= 3; ++threads) {
        const cw_grid g = grid_of(CW_GRID_UNIFORM);
        cw_batch* b = make_batch(CW_GRID_UNIFORM, threads);
        cw_params p[COUNT];
        cw_result r[COUNT], expected;
        int statuses[COUNT];
        int want[COUNT];
        for (int k = 0; k < COUNT; ++k) {
            batch_case(k, &p[k]);
            cw_poison_result(&r[k]);
            want[k] = CW_OK;
        }
        /* The first failure (index 4) is on a different thread from the
         * later ones whenever threads > 1. */
        p[4].pressure = 9;
        want[4] = CW_ERR_UNKNOWN_OPTION;
        p[9].a = -1.0;
        want[9] = CW_ERR_INVALID_INPUT;
        p[COUNT - 1].mu = strtod("nan", NULL);
        want[COUNT - 1] = CW_ERR_INVALID_INPUT;
        p[15].normal_force = 1e19; /* finite inputs, W_macro ~ 1e309 overflows */
        p[15].mu = 1.0;
        p[15].xi_x = 1e290;
        want[15] = CW_ERR_NUMERIC;
        cw_fill_int(statuses, COUNT, CW_INT_SENTINEL);

        assert_int_equal(cw_batch_solve(b, COUNT, p, CW_SOLVE_FULL, r, statuses),
                         CW_ERR_UNKNOWN_OPTION);
        assert_names(cw_batch_last_error(b), "params[4]");
        assert_names(cw_batch_last_error(b), "pressure");
        for (int k = 0; k < COUNT; ++k) {
            assert_int_equal(statuses[k], want[k]);
            if (want[k] != CW_OK) {
                cw_result poisoned;
                cw_poison_result(&poisoned);
                assert_memory_equal(&r[k], &poisoned, sizeof poisoned);
            } else {
                solve_one(&g, &p[k], CW_SOLVE_FULL, &expected);
                assert_memory_equal(&r[k], &expected, sizeof expected);
            }
        }
        /* Only the later failure left: its index and input are named. */
        batch_case(4, &p[4]);
        assert_int_equal(cw_batch_solve(b, COUNT, p, CW_SOLVE_FULL, r, NULL),
                         CW_ERR_INVALID_INPUT);
        assert_names(cw_batch_last_error(b), "params[9]");
        assert_names(cw_batch_last_error(b), "a = ");
        cw_batch_destroy(b);
    }
}

/* A results array whose element type is older (smaller) than the params'
 * (header, "Structs": each array is strided by its own element 0's
 * struct_size): result k lands at k * its own size and holds the first
 * bytes of the one-by-one result, and nothing beyond the last is written. */
static void results_smaller_than_params(void** state)
{
    (void)state;
    enum { COUNT = 6 };
    const size_t rsize = offsetof(cw_result, a); /* a result before the semi-axes */
    const cw_grid g = grid_of(CW_GRID_KALKER_STRIPS);
    cw_batch* b = make_batch(CW_GRID_KALKER_STRIPS, 3);
    cw_params p[COUNT];
    cw_result expected[COUNT];
    double storage[(COUNT + 2) * sizeof(cw_result) / sizeof(double)]; /* aligned bytes */
    unsigned char* bytes = (unsigned char*)storage;
    cw_poison(storage, sizeof storage);
    for (int k = 0; k < COUNT; ++k) {
        batch_case(k, &p[k]);
        solve_one(&g, &p[k], CW_SOLVE_FULL, &expected[k]);
        memcpy(bytes + k * rsize, &rsize, sizeof rsize); /* its struct_size */
    }
    int statuses[COUNT];
    assert_int_equal(
        cw_batch_solve(b, COUNT, p, CW_SOLVE_FULL, (cw_result*)storage, statuses), CW_OK);
    for (int k = 0; k < COUNT; ++k) {
        assert_int_equal(statuses[k], CW_OK);
        size_t size;
        memcpy(&size, bytes + k * rsize, sizeof size);
        assert_int_equal(size, rsize);
        assert_memory_equal(bytes + k * rsize + sizeof(size_t),
                            (const unsigned char*)&expected[k] + sizeof(size_t),
                            rsize - sizeof(size_t));
    }
    assert_true(cw_poisoned(bytes + COUNT * rsize, sizeof storage - COUNT * rsize));
    cw_batch_destroy(b);
}

/* The other way round: a params array of an older (smaller) element type
 * than the results'. Each contact is read up to its own struct_size and
 * takes the defaults beyond it (cw_params_init's), never the next
 * element's bytes. */
static void params_smaller_than_results(void** state)
{
    (void)state;
    enum { COUNT = 6 };
    const size_t psize = offsetof(cw_params, rolling_direction); /* an older header's */
    const cw_grid g = grid_of(CW_GRID_UNIFORM);
    cw_batch* b = make_batch(CW_GRID_UNIFORM, 3);
    double storage[(COUNT + 1) * sizeof(cw_params) / sizeof(double)]; /* aligned bytes */
    unsigned char* bytes = (unsigned char*)storage;
    cw_poison(storage, sizeof storage);
    cw_result r[COUNT], expected[COUNT];
    for (int k = 0; k < COUNT; ++k) {
        cw_params full, old;
        batch_case(k, &full);
        cw_params_init(&old); /* what the library must use beyond psize */
        memcpy(&old, &full, psize);
        old.struct_size = sizeof old;
        solve_one(&g, &old, CW_SOLVE_FULL, &expected[k]);
        memcpy(bytes + k * psize, &full, psize);
        memcpy(bytes + k * psize, &psize, sizeof psize); /* its struct_size */
        cw_result_init(&r[k]);
    }
    assert_int_equal(
        cw_batch_solve(b, COUNT, (const cw_params*)storage, CW_SOLVE_FULL, r, NULL), CW_OK);
    for (int k = 0; k < COUNT; ++k) assert_memory_equal(&r[k], &expected[k], sizeof r[k]);
    cw_batch_destroy(b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(lifecycle),
        cmocka_unit_test(batch_equals_one_by_one),
        cmocka_unit_test(empty_batch),
        cmocka_unit_test(create_errors),
        cmocka_unit_test(solve_argument_errors),
        cmocka_unit_test(per_contact_errors),
        cmocka_unit_test(results_smaller_than_params),
        cmocka_unit_test(params_smaller_than_results),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
