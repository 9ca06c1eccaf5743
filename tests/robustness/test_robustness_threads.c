/* The header's threading promise: distinct handles may be used concurrently
 * from different threads; the library has no global mutable state. Several
 * threads each own solvers, accumulators and batches (themselves using
 * OpenMP threads), solve, fail on purpose, read fields and call the free
 * functions at the same time; every result must equal the one computed
 * alone on the main thread, bit for bit, and every error message must be
 * the thread's own. Run under ThreadSanitizer in CI (label "threads").
 * cmocka's assertions are not thread-safe: workers record failures and the
 * main thread asserts. */
#include "capi_fixtures.h"

#include <pthread.h>

enum { kThreads = 4, kContacts = 12, kRounds = 6, kNx = 18, kNy = 14 };

static cw_params contact(int k)
{
    cw_params p;
    cw_params_init(&p);
    p.xi_x = 2e-4 * ((k % 5) - 2);
    p.xi_y = -1e-4 * ((k % 3) - 1);
    p.phi = 4.0 * ((k % 4) - 1.5);
    p.pressure = k % 2 ? CW_PRESSURE_ELLIPTIC : CW_PRESSURE_PARABOLIC;
    p.rolling_direction = k % 3 ? 1 : -1;
    return p;
}

/* Reference results computed alone, before any thread starts. */
static cw_result g_ref[2][kContacts];
static double g_ref_work[2][kContacts][kNx * kNy];
static cw_accumulation g_ref_acc[2];
static double g_ref_coefficients[4], g_ref_hertz[4], g_ref_t[2];

typedef struct {
    int id;
    int failures;
    char first[256];
} Worker;

static void record(Worker* w, const char* what)
{
    if (w->failures++ == 0) snprintf(w->first, sizeof w->first, "thread %d: %s", w->id, what);
}

static cw_solver* make_solver(int kind)
{
    cw_grid g;
    cw_grid_init(&g);
    g.kind = kind;
    g.nx = kNx;
    g.ny = kNy;
    g.box_scale = 1.1;
    cw_solver* s = NULL;
    return cw_solver_create(&g, &s, NULL, 0) == CW_OK ? s : NULL;
}

static void free_functions(double coefficients[4], double hertz[4], double t[2])
{
    cw_kalker_coefficients(0.37, 0.28, coefficients, NULL, 0);
    cw_hertz_solve(2.0, 7.0, 80e3, 1.1e11, hertz, NULL, 0);
    cw_fastsim_normalised(0.3, -0.2, 0.4, 0.5, 15, 15, 0.2, &t[0], &t[1], NULL, 0);
}

/* One accumulated run over every contact (distance k + 1 each). */
static int accumulate(cw_solver* s, cw_accumulator* acc, double* work_out, int kind, int check,
                      Worker* w)
{
    cw_accumulator_reset(acc);
    for (int k = 0; k < kContacts; ++k) {
        const cw_params p = contact(k);
        cw_result r;
        cw_result_init(&r);
        if (cw_solver_solve(s, &p, CW_SOLVE_FULL, &r) != CW_OK) return 0;
        if (check && memcmp(&r, &g_ref[kind][k], sizeof r) != 0) record(w, "solver result differs");
        if (work_out &&
            cw_solver_get_field(s, CW_FIELD_WORK_CONSISTENT, work_out + (size_t)k * kNx * kNy,
                                kNx * kNy) != CW_OK)
            return 0;
        if (check) {
            double work[kNx * kNy];
            cw_solver_get_field(s, CW_FIELD_WORK_CONSISTENT, work, kNx * kNy);
            if (memcmp(work, g_ref_work[kind][k], sizeof work) != 0) record(w, "work field differs");
        }
        if (cw_accumulator_add(acc, s, k + 1.0) != CW_OK) return 0;
    }
    return 1;
}

static void* work(void* arg)
{
    Worker* w = (Worker*)arg;
    const int kind = w->id % 2;
    for (int round = 0; round < kRounds; ++round) {
        cw_solver* s = make_solver(kind);
        cw_accumulator* acc = NULL;
        if (!s || cw_accumulator_create(s, &acc) != CW_OK) {
            record(w, "create failed");
            cw_solver_destroy(s);
            return NULL;
        }
        if (!accumulate(s, acc, NULL, kind, 1, w)) record(w, "accumulate failed");
        cw_accumulation totals;
        cw_accumulation_init(&totals);
        cw_accumulator_get_totals(acc, &totals);
        if (memcmp(&totals, &g_ref_acc[kind], sizeof totals) != 0) record(w, "totals differ");

        /* A failure of this thread's own: the message names its input. */
        cw_params bad = contact(round);
        const char* name = w->id % 2 ? "mu" : "phi";
        if (w->id % 2) bad.mu = -1.0 - w->id;
        else bad.phi = NAN;
        if (cw_solver_solve(s, &bad, CW_SOLVE_FULL, NULL) != CW_ERR_INVALID_INPUT ||
            !cw_names(cw_solver_last_error(s), name))
            record(w, "error message is not this thread's");

        /* A batch per thread, itself multithreaded. */
        cw_grid g;
        cw_grid_init(&g);
        g.kind = kind;
        g.nx = kNx;
        g.ny = kNy;
        g.box_scale = 1.1;
        cw_batch* b = NULL;
        if (cw_batch_create(&g, 2, &b, NULL, 0) != CW_OK) {
            record(w, "batch create failed");
        } else {
            cw_params p[kContacts];
            cw_result r[kContacts];
            for (int k = 0; k < kContacts; ++k) {
                p[k] = contact(k);
                cw_result_init(&r[k]);
            }
            if (cw_batch_solve(b, kContacts, p, CW_SOLVE_FULL, r, NULL) != CW_OK)
                record(w, "batch solve failed");
            for (int k = 0; k < kContacts; ++k)
                if (memcmp(&r[k], &g_ref[kind][k], sizeof r[k]) != 0) record(w, "batch differs");
            cw_batch_destroy(b);
        }

        double c[4], h[4], t[2];
        free_functions(c, h, t);
        if (memcmp(c, g_ref_coefficients, sizeof c) || memcmp(h, g_ref_hertz, sizeof h) ||
            memcmp(t, g_ref_t, sizeof t))
            record(w, "free function differs");

        cw_accumulator_destroy(acc);
        cw_solver_destroy(s);
    }
    return NULL;
}

static void test_concurrent_handles(void** state)
{
    (void)state;
    for (int kind = 0; kind < 2; ++kind) {
        cw_solver* s = make_solver(kind);
        assert_non_null(s);
        cw_accumulator* acc = NULL;
        assert_status(cw_accumulator_create(s, &acc), CW_OK);
        assert_true(accumulate(s, acc, &g_ref_work[kind][0][0], kind, 0, NULL));
        for (int k = 0; k < kContacts; ++k) {
            const cw_params p = contact(k);
            cw_result_init(&g_ref[kind][k]);
            assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &g_ref[kind][k]), CW_OK);
        }
        cw_accumulation_init(&g_ref_acc[kind]);
        assert_status(cw_accumulator_get_totals(acc, &g_ref_acc[kind]), CW_OK);
        cw_accumulator_destroy(acc);
        cw_solver_destroy(s);
    }
    free_functions(g_ref_coefficients, g_ref_hertz, g_ref_t);

    pthread_t threads[kThreads];
    Worker workers[kThreads];
    for (int t = 0; t < kThreads; ++t) {
        workers[t].id = t;
        workers[t].failures = 0;
        workers[t].first[0] = '\0';
        assert_int_equal(pthread_create(&threads[t], NULL, work, &workers[t]), 0);
    }
    for (int t = 0; t < kThreads; ++t) assert_int_equal(pthread_join(threads[t], NULL), 0);
    for (int t = 0; t < kThreads; ++t) {
        if (workers[t].failures) print_error("%s (%d failures)\n", workers[t].first, workers[t].failures);
        assert_int_equal(workers[t].failures, 0);
    }
}

/* Several threads reading one solved handle's fields is not promised (one
 * handle, one thread at a time) and so not tested. Many short-lived
 * handles created and destroyed at once are. */
static void* churn(void* arg)
{
    Worker* w = (Worker*)arg;
    for (int k = 0; k < 50; ++k) {
        cw_solver* s = make_solver(k % 2);
        cw_batch* b = NULL;
        cw_grid g;
        cw_grid_init(&g);
        g.nx = 1 + k % 5;
        g.ny = 1 + (k + w->id) % 7;
        if (!s || cw_batch_create(&g, 1 + k % 3, &b, NULL, 0) != CW_OK) record(w, "create failed");
        g.nx = -k; /* and failed creates */
        cw_solver* bad = NULL;
        char msg[64];
        if (cw_solver_create(&g, &bad, msg, sizeof msg) != CW_ERR_GRID_OUT_OF_RANGE || bad ||
            !cw_names(msg, "nx"))
            record(w, "failed create misbehaved");
        cw_batch_destroy(b);
        cw_solver_destroy(s);
    }
    return NULL;
}

static void test_concurrent_create_destroy(void** state)
{
    (void)state;
    pthread_t threads[kThreads];
    Worker workers[kThreads];
    for (int t = 0; t < kThreads; ++t) {
        workers[t].id = t;
        workers[t].failures = 0;
        workers[t].first[0] = '\0';
        assert_int_equal(pthread_create(&threads[t], NULL, churn, &workers[t]), 0);
    }
    for (int t = 0; t < kThreads; ++t) assert_int_equal(pthread_join(threads[t], NULL), 0);
    for (int t = 0; t < kThreads; ++t) {
        if (workers[t].failures) print_error("%s\n", workers[t].first);
        assert_int_equal(workers[t].failures, 0);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_concurrent_handles),
        cmocka_unit_test(test_concurrent_create_destroy),
    };
    return cmocka_run_group_tests_name("robustness_threads", tests, NULL, NULL);
}
