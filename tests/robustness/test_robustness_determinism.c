/* Determinism: the same inputs give bitwise identical results
 *  - on two separate solver handles, and on one handle solved repeatedly;
 *  - after an intervening different (or failed) solve on the same handle;
 *  - in cw_batch_solve with 1, 2, 4 and 8 threads, and equal to one-by-one
 *    cw_solver_solve calls;
 *  - across runs: the test re-runs itself as a child process (different
 *    address layout, heap disturbed) and compares a digest of everything.
 * "Everything" is the result struct and every field, state and profile. */
#include "capi_fixtures.h"

#include <stdint.h>

static const char* g_self; /* argv[0], for the child runs */

enum { kCount = 37 }; /* odd, not a multiple of any thread count */

static cw_params contact(int k)
{
    cw_params p;
    cw_params_init(&p);
    p.xi_x = 1e-4 * ((k % 7) - 3);
    p.xi_y = 2e-4 * ((k % 5) - 2);
    p.phi = 3.0 * ((k % 4) - 1.5);
    p.pressure = k % 2 ? CW_PRESSURE_ELLIPTIC : CW_PRESSURE_PARABOLIC;
    p.rolling_direction = k % 3 ? 1 : -1;
    p.a = 6e-3 * (1.0 + 0.05 * (k % 6));
    p.normal_force = 80e3 + 1e3 * k;
    if (k % 9 == 4) {
        p.flexibility = CW_FLEX_GIVEN;
        p.L1 = 1.1e-11;
        p.L2 = 1.3e-11;
        p.L3 = 0.9e-11;
    }
    return p;
}

/* Everything a FULL solve exposes, as raw bytes. */
typedef struct {
    cw_result result;
    double* fields; /* (CW_FIELD_WORK_CONSISTENT + 1) * n */
    int* states;    /* n */
    double* profile; /* 3 * ny */
    size_t n, ny;
} Snapshot;

static Snapshot snapshot(const cw_solver* s, const cw_result* r)
{
    Snapshot snap;
    int nx = 0, ny = 0;
    cw_solver_grid_size(s, &nx, &ny);
    snap.n = (size_t)nx * ny;
    snap.ny = (size_t)ny;
    snap.result = *r;
    snap.fields = (double*)malloc((CW_FIELD_WORK_CONSISTENT + 1) * snap.n * sizeof(double));
    snap.states = (int*)malloc(snap.n * sizeof(int));
    snap.profile = (double*)malloc(3 * snap.ny * sizeof(double));
    assert_true(snap.fields && snap.states && snap.profile);
    for (int f = 0; f <= CW_FIELD_WORK_CONSISTENT; ++f)
        assert_status(cw_solver_get_field(s, f, snap.fields + f * snap.n, snap.n), CW_OK);
    assert_status(cw_solver_get_state(s, snap.states, snap.n), CW_OK);
    assert_status(cw_solver_get_profile(s, snap.profile, snap.profile + ny,
                                        snap.profile + 2 * ny, snap.ny),
                  CW_OK);
    return snap;
}

static void free_snapshot(Snapshot* s)
{
    free(s->fields);
    free(s->states);
    free(s->profile);
}

static void assert_same(const Snapshot* a, const Snapshot* b)
{
    assert_memory_equal(&a->result, &b->result, sizeof a->result);
    assert_int_equal(a->n, b->n);
    assert_memory_equal(a->fields, b->fields, (CW_FIELD_WORK_CONSISTENT + 1) * a->n * sizeof(double));
    assert_memory_equal(a->states, b->states, a->n * sizeof(int));
    assert_memory_equal(a->profile, b->profile, 3 * a->ny * sizeof(double));
}

static Snapshot solve_snapshot(cw_solver* s, const cw_params* p)
{
    cw_result r;
    cw_result_init(&r);
    assert_status(cw_solver_solve(s, p, CW_SOLVE_FULL, &r), CW_OK);
    return snapshot(s, &r);
}

static void test_handles_and_repeats(void** state)
{
    (void)state;
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind) {
        cw_solver* a = cw_test_solver(kind, 23, 17, 1.2);
        cw_solver* b = cw_test_solver(kind, 23, 17, 1.2);
        Snapshot ref[kCount];
        for (int k = 0; k < kCount; ++k) {
            const cw_params p = contact(k);
            ref[k] = solve_snapshot(a, &p);
        }
        for (int round = 0; round < 3; ++round)
            for (int k = 0; k < kCount; ++k) {
                /* Other handle; same handle again, after another contact and
                 * after a failed solve. */
                const cw_params p = contact(k);
                Snapshot other = solve_snapshot(b, &p);
                assert_same(&ref[k], &other);
                free_snapshot(&other);

                const cw_params q = contact(k + 11 + round);
                assert_status(cw_solver_solve(a, &q, CW_SOLVE_FULL, NULL), CW_OK);
                Snapshot again = solve_snapshot(a, &p);
                assert_same(&ref[k], &again);
                free_snapshot(&again);

                cw_params bad = p;
                bad.mu = -1.0;
                assert_status(cw_solver_solve(a, &bad, CW_SOLVE_FULL, NULL),
                              CW_ERR_INVALID_INPUT);
                assert_status(cw_solver_solve(a, &q, CW_SOLVE_FORCES, NULL), CW_OK);
                again = solve_snapshot(a, &p);
                assert_same(&ref[k], &again);
                free_snapshot(&again);
            }
        for (int k = 0; k < kCount; ++k) free_snapshot(&ref[k]);
        cw_solver_destroy(a);
        cw_solver_destroy(b);
    }
}

static void test_batch_thread_counts(void** state)
{
    (void)state;
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind) {
        const cw_grid g = cw_test_grid(kind, 31, 29, 1.05);
        cw_solver* s = cw_test_solver(kind, 31, 29, 1.05);
        cw_params p[kCount];
        cw_result single[kCount][2];
        for (int k = 0; k < kCount; ++k) {
            p[k] = contact(k);
            for (int mode = 0; mode < 2; ++mode) {
                cw_result_init(&single[k][mode]);
                assert_status(cw_solver_solve(s, &p[k], mode, &single[k][mode]), CW_OK);
            }
        }
        const int threads[] = {1, 2, 4, 8, 0};
        for (int t = 0; t < 5; ++t) {
            cw_batch* b = NULL;
            assert_status(cw_batch_create(&g, threads[t], &b, NULL, 0), CW_OK);
            for (int mode = 0; mode < 2; ++mode)
                for (int repeat = 0; repeat < 2; ++repeat) {
                    cw_result r[kCount];
                    int statuses[kCount];
                    for (int k = 0; k < kCount; ++k) cw_poison_result(&r[k]);
                    assert_status(cw_batch_solve(b, kCount, p, mode, r, statuses), CW_OK);
                    for (int k = 0; k < kCount; ++k) {
                        assert_int_equal(statuses[k], CW_OK);
                        assert_memory_equal(&r[k], &single[k][mode], sizeof r[k]);
                    }
                    /* Sub-ranges: the partition between threads changes. */
                    assert_status(cw_batch_solve(b, kCount - 5, p + 5, mode, r, NULL), CW_OK);
                    for (int k = 0; k + 5 < kCount; ++k)
                        assert_memory_equal(&r[k], &single[k + 5][mode], sizeof r[k]);
                }
            cw_batch_destroy(b);
        }
        cw_solver_destroy(s);
    }
}

/* The exact model in a batch: every contact starts cold, so the
 * results are those of one-by-one solves with warm_start = 0, bitwise,
 * whatever the thread count and the partition. Small grid: this runs under
 * ThreadSanitizer. */
enum { kExact = 6 };
static cw_params exact_contact(int k)
{
    cw_params p;
    cw_params_init(&p);
    p.model = CW_MODEL_EXACT;
    p.a = 7.17e-3;
    p.b = 5.42e-3 * (k % 3 == 2 ? 0.5 : 1.0);
    p.normal_force = 100e3;
    p.xi_x = 6e-4 * (k + 1);
    p.xi_y = -3e-4 * (k % 2);
    p.phi = 0.2 * (k - 2);
    return p;
}

static void test_exact_batch_thread_counts(void** state)
{
    (void)state;
    const cw_grid g = cw_test_grid(CW_GRID_UNIFORM, 14, 12, 1.2);
    cw_solver* s = cw_test_solver(CW_GRID_UNIFORM, 14, 12, 1.2);
    cw_params p[kExact];
    cw_result single[kExact];
    for (int k = 0; k < kExact; ++k) {
        p[k] = exact_contact(k);
        cw_params cold = p[k];
        cold.warm_start = 0;
        cw_result_init(&single[k]);
        assert_status(cw_solver_solve(s, &cold, CW_SOLVE_FULL, &single[k]), CW_OK);
    }
    const int threads[] = {1, 2, 3};
    for (int t = 0; t < 3; ++t) {
        cw_batch* b = NULL;
        assert_status(cw_batch_create(&g, threads[t], &b, NULL, 0), CW_OK);
        for (int repeat = 0; repeat < 2; ++repeat) {
            cw_result r[kExact];
            for (int k = 0; k < kExact; ++k) cw_poison_result(&r[k]);
            assert_status(cw_batch_solve(b, kExact, p, CW_SOLVE_FULL, r, NULL), CW_OK);
            for (int k = 0; k < kExact; ++k)
                assert_memory_equal(&r[k], &single[k], sizeof r[k]);
            assert_status(cw_batch_solve(b, kExact - 1, p + 1, CW_SOLVE_FULL, r, NULL), CW_OK);
            for (int k = 0; k + 1 < kExact; ++k)
                assert_memory_equal(&r[k], &single[k + 1], sizeof r[k]);
        }
        cw_batch_destroy(b);
    }
    cw_solver_destroy(s);
}

/* ----------------------------------------------------- across processes */

static uint64_t fnv1a(uint64_t h, const void* data, size_t bytes)
{
    const unsigned char* c = (const unsigned char*)data;
    for (size_t k = 0; k < bytes; ++k) {
        h ^= c[k];
        h *= 1099511628211ull;
    }
    return h;
}

static uint64_t digest_everything(void)
{
    uint64_t h = 1469598103934665603ull;
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind) {
        cw_solver* s = cw_test_solver(kind, 40, 33, 1.1);
        for (int k = 0; k < kCount; ++k) {
            const cw_params p = contact(k);
            Snapshot snap = solve_snapshot(s, &p);
            h = fnv1a(h, &snap.result, sizeof snap.result);
            h = fnv1a(h, snap.fields, (CW_FIELD_WORK_CONSISTENT + 1) * snap.n * sizeof(double));
            h = fnv1a(h, snap.states, snap.n * sizeof(int));
            h = fnv1a(h, snap.profile, 3 * snap.ny * sizeof(double));
            free_snapshot(&snap);
        }
        cw_solver_destroy(s);
    }
    /* The exact model, warm-started in sequence on one handle. */
    cw_solver* s = cw_test_solver(CW_GRID_UNIFORM, 16, 14, 1.2);
    for (int k = 0; k < kExact; ++k) {
        const cw_params p = exact_contact(k);
        Snapshot snap = solve_snapshot(s, &p);
        h = fnv1a(h, &snap.result, sizeof snap.result);
        h = fnv1a(h, snap.fields, (CW_FIELD_WORK_CONSISTENT + 1) * snap.n * sizeof(double));
        h = fnv1a(h, snap.states, snap.n * sizeof(int));
        free_snapshot(&snap);
    }
    cw_solver_destroy(s);
    return h;
}

static uint64_t child_digest(const char* how)
{
    char command[4096];
    snprintf(command, sizeof command, "'%s' %s", g_self, how);
    FILE* pipe = popen(command, "r");
    assert_non_null(pipe);
    unsigned long long value = 0;
    const int got = fscanf(pipe, "%llx", &value);
    assert_int_equal(pclose(pipe), 0);
    assert_int_equal(got, 1);
    return (uint64_t)value;
}

static void test_across_runs(void** state)
{
    (void)state;
    const uint64_t here = digest_everything();
    assert_true(here == child_digest("--digest"));
    assert_true(here == child_digest("--digest-disturbed"));
}

int main(int argc, char** argv)
{
    g_self = argv[0];
    if (argc > 1 && strncmp(argv[1], "--digest", 8) == 0) {
        /* Shift the heap so the solver's arrays land elsewhere. */
        void* junk[7] = {0};
        if (strcmp(argv[1], "--digest-disturbed") == 0)
            for (int k = 0; k < 7; ++k) junk[k] = malloc(24 + 40 * (size_t)k);
        printf("%llx\n", (unsigned long long)digest_everything());
        for (int k = 0; k < 7; ++k) free(junk[k]);
        return 0;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_handles_and_repeats),
        cmocka_unit_test(test_batch_thread_counts),
        cmocka_unit_test(test_exact_batch_thread_counts),
        cmocka_unit_test(test_across_runs),
    };
    return cmocka_run_group_tests_name("robustness_determinism", tests, NULL, NULL);
}
