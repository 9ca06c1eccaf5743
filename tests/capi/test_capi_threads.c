/* Header, "Threads": distinct handles may be used concurrently. Four
 * threads, each with its own handles, solve the case list over and over
 * (each from a different starting point, so different contacts run at the
 * same moment) and must reproduce the serial results bit for bit. The batch
 * must give one-by-one results bit for bit at 1, 2, 4 and 8 threads. Worker
 * threads record; only the main thread asserts (cmocka is not thread-safe). */
#include "capi_fixtures.h"

#include <pthread.h>
#include <stdlib.h>

enum { THREADS = 4, ROUNDS = 8, KINDS = 2, FIELDS = CW_FIELD_WORK_CONSISTENT + 1 };
/* Large enough that solves on different threads overlap in time. */
enum { NX = 60, NY = 40, N = NX * NY };

/* Everything one FULL solve exposes, for one case on one grid kind. */
typedef struct {
    cw_result r;
    double f[FIELDS][N];
    int state[N];
    double profile[NY];
} snapshot;

static int snapshot_take(cw_solver* s, const cw_params* p, snapshot* out)
{
    int status = cw_solver_solve(s, p, CW_SOLVE_FULL, NULL);
    cw_result_init(&out->r);
    status |= cw_solver_get_result(s, &out->r);
    for (int f = 0; f < FIELDS; ++f) status |= cw_solver_get_field(s, f, out->f[f], N);
    status |= cw_solver_get_state(s, out->state, N);
    status |= cw_solver_get_profile(s, NULL, out->profile, NULL, NY);
    return status;
}

static cw_grid grid_of(int kind) { return cw_test_grid(kind, NX, NY, 1.07); }

/* No cmocka here: called from the worker threads too. */
static cw_solver* make_solver(int kind)
{
    const cw_grid g = grid_of(kind);
    cw_solver* s = NULL;
    return cw_solver_create(&g, &s, NULL, 0) == CW_OK ? s : NULL;
}

static snapshot serial[KINDS][CW_TEST_CASES];

typedef struct {
    int id;
    int failures; /* mismatches against the serial snapshots, or errors */
    snapshot scratch;
} worker;

static void* work(void* arg)
{
    worker* w = arg;
    cw_solver* s[KINDS] = {make_solver(CW_GRID_KALKER_STRIPS), make_solver(CW_GRID_UNIFORM)};
    if (!s[0] || !s[1]) {
        w->failures = -1;
        return NULL;
    }
    for (int round = 0; round < ROUNDS; ++round)
        for (int n = 0; n < KINDS * CW_TEST_CASES; ++n) {
            const int k = (n + 3 * w->id + round) % (KINDS * CW_TEST_CASES);
            const int kind = k / CW_TEST_CASES, c = k % CW_TEST_CASES;
            cw_params p;
            cw_test_case(c, &p);
            if (snapshot_take(s[kind], &p, &w->scratch) != CW_OK ||
                memcmp(&w->scratch, &serial[kind][c], sizeof w->scratch) != 0)
                w->failures++;
        }
    cw_solver_destroy(s[0]);
    cw_solver_destroy(s[1]);
    return NULL;
}

static void distinct_handles_on_distinct_threads(void** state)
{
    (void)state;
    for (int kind = 0; kind < KINDS; ++kind) {
        cw_solver* s = make_solver(kind);
        assert_non_null(s);
        for (int c = 0; c < CW_TEST_CASES; ++c) {
            cw_params p;
            cw_test_case(c, &p);
            memset(&serial[kind][c], 0, sizeof serial[kind][c]);
            assert_int_equal(snapshot_take(s, &p, &serial[kind][c]), CW_OK);
        }
        cw_solver_destroy(s);
    }
    /* The snapshots differ from case to case, so a thread that read another
     * thread's handle would be caught. */
    assert_memory_not_equal(&serial[0][0].r, &serial[0][1].r, sizeof(cw_result));

    static worker workers[THREADS];
    pthread_t ids[THREADS];
    for (int t = 0; t < THREADS; ++t) {
        memset(&workers[t], 0, sizeof workers[t]);
        workers[t].id = t;
        assert_int_equal(pthread_create(&ids[t], NULL, work, &workers[t]), 0);
    }
    for (int t = 0; t < THREADS; ++t) assert_int_equal(pthread_join(ids[t], NULL), 0);
    for (int t = 0; t < THREADS; ++t) assert_int_equal(workers[t].failures, 0);
}

/* ------------------------------------------------------------------- batch */

enum { COUNT = 53 }; /* not a multiple of any thread count */

static void batch_case(int k, cw_params* p)
{
    cw_test_case(k % CW_TEST_CASES, p);
    p->normal_force *= 1.0 + 0.03 * k;
    p->xi_y += 2e-5 * k;
}

static void batch_equals_one_by_one_at_any_thread_count(void** state)
{
    (void)state;
#if defined(__SANITIZE_THREAD__)
    /* GCC with TSan means libgomp, which is not instrumented: TSan cannot see
     * a parallel region's barriers and reports every hand-over as a race.
     * (scripts/test-all.sh uses clang, libomp and Archer, where this runs.) */
    cw_skip();
#endif
    static cw_params p[COUNT];
    static cw_result expected[COUNT], got[COUNT];
    int statuses[COUNT];
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind)
        for (int mode = CW_SOLVE_FORCES; mode <= CW_SOLVE_FULL; ++mode) {
            cw_solver* s = make_solver(kind);
            assert_non_null(s);
            for (int k = 0; k < COUNT; ++k) {
                batch_case(k, &p[k]);
                cw_result_init(&expected[k]);
                assert_int_equal(cw_solver_solve(s, &p[k], mode, &expected[k]), CW_OK);
            }
            cw_solver_destroy(s);
            const int counts[] = {1, 2, 4, 8};
            for (int t = 0; t < 4; ++t) {
                const cw_grid g = grid_of(kind);
                cw_batch* b = NULL;
                assert_int_equal(cw_batch_create(&g, counts[t], &b, NULL, 0), CW_OK);
                for (int k = 0; k < COUNT; ++k) cw_result_init(&got[k]);
                assert_int_equal(cw_batch_solve(b, COUNT, p, mode, got, statuses), CW_OK);
                assert_memory_equal(got, expected, sizeof got);
                cw_batch_destroy(b);
            }
        }
}

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(distinct_handles_on_distinct_threads),
        cmocka_unit_test(batch_equals_one_by_one_at_any_thread_count),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : NULL);
}
