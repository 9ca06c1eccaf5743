/* No heap allocation inside a successful solve once the solver exists, nor
 * in reading its results: cw_solver_solve (both modes), cw_solver_get_result,
 * _get_field, _get_state, _get_profile, cw_accumulator_add and its getters,
 * cw_batch_solve after its first call (the OpenMP runtime builds its
 * thread pool on first use), and the wear calls a campaign repeats.
 * Counted by interposing malloc (count_malloc.h), which also sees
 * libstdc++'s operator new and Eigen's aligned_malloc. */
#include "capi_fixtures.h"

#include "count_malloc.h"

static cw_params contact(int k)
{
    cw_params p;
    cw_params_init(&p);
    switch (k) {
    case 0: break;                                   /* zero creepage */
    case 1: p.xi_x = 1e-3; p.phi = 2.0; break;       /* partial slip */
    case 2: p.xi_y = -1.0; break;                    /* full slip */
    case 3: p.xi_x = 1e100; p.phi = -1e90; break;    /* scaled huge creepage */
    case 4: p.normal_force = 0.0; p.xi_x = 1e-3; break;
    case 5: p.mu = 0.0; p.xi_y = 1e-3; break;
    case 6: p.flexibility = CW_FLEX_GIVEN; p.L1 = p.L2 = p.L3 = 1e-11; p.phi = 5.0; break;
    case 7: p.rolling_direction = -1; p.pressure = CW_PRESSURE_ELLIPTIC; p.xi_x = 2e-3; break;
    case 8: p.a = 1e-3; p.b = 1.0; p.xi_x = 1e-12; break;
    default: p.a = 1.0; p.b = 1e-3; p.phi = 100.0; break;
    }
    return p;
}
enum { kContacts = 10 };

static void test_counter_sees_library_allocations(void** state)
{
    (void)state;
    cw_grid g;
    cw_grid_init(&g);
    cw_solver* s = NULL;
    cw_count_start();
    const int st = cw_solver_create(&g, &s, NULL, 0);
    const long at_create = cw_count_stop();
    assert_status(st, CW_OK);
    assert_true(at_create > 0); /* create allocates: the counter sees it */

    cw_params p;
    cw_params_init(&p);
    p.a = NAN;
    cw_count_start();
    const int bad = cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL);
    const long at_error = cw_count_stop();
    assert_status(bad, CW_ERR_INVALID_INPUT);
    assert_true(at_error > 0); /* the error path builds a message: seen too */
    cw_solver_destroy(s);
}

static void test_solve_and_export_allocate_nothing(void** state)
{
    (void)state;
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind) {
        const int nx = 33, ny = 21;
        const size_t n = (size_t)nx * ny;
        cw_solver* s = cw_test_solver(kind, nx, ny, 1.3);
        double* buf = (double*)malloc(n * sizeof *buf);
        int* ibuf = (int*)malloc(n * sizeof *ibuf);
        double profile[3 * 21];
        cw_result r;
        cw_result_init(&r);
        long allocations = 0;
        int failures = 0;
        for (int k = 0; k < kContacts; ++k) {
            const cw_params p = contact(k);
            cw_count_start(); /* the first solve on a new handle included */
            for (int mode = CW_SOLVE_FORCES; mode <= CW_SOLVE_FULL; ++mode) {
                failures += cw_solver_solve(s, &p, mode, &r) != CW_OK;
                failures += cw_solver_get_result(s, &r) != CW_OK;
                for (int f = CW_FIELD_X; f <= CW_FIELD_WORK_CONSISTENT; ++f) {
                    const int needs_full = f == CW_FIELD_SX || f == CW_FIELD_SY ||
                                           f == CW_FIELD_WORK_PAPER ||
                                           f == CW_FIELD_WORK_CONSISTENT;
                    if (mode == CW_SOLVE_FULL || !needs_full) /* errors may allocate */
                        failures += cw_solver_get_field(s, f, buf, n) != CW_OK;
                }
                failures += cw_solver_get_state(s, ibuf, n) != CW_OK;
            }
            failures += cw_solver_get_profile(s, profile, profile + ny, profile + 2 * ny, ny) !=
                        CW_OK;
            allocations += cw_count_stop();
        }
        assert_int_equal(failures, 0);
        assert_int_equal(allocations, 0);
        free(buf);
        free(ibuf);
        cw_solver_destroy(s);
    }
}

static void test_accumulator_allocates_nothing(void** state)
{
    (void)state;
    const int nx = 16, ny = 12;
    const size_t n = (size_t)nx * ny;
    cw_solver* s = cw_test_solver(CW_GRID_UNIFORM, nx, ny, 1.0);
    cw_accumulator* acc = NULL;
    assert_status(cw_accumulator_create(s, &acc), CW_OK);
    double buf[16 * 12];
    cw_accumulation totals;
    cw_accumulation_init(&totals);
    int failures = 0;
    cw_count_start();
    for (int k = 0; k < kContacts; ++k) {
        const cw_params p = contact(k);
        failures += cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL) != CW_OK;
        failures += cw_accumulator_add(acc, s, 0.01 * (k + 1)) != CW_OK;
        failures += cw_accumulator_get_totals(acc, &totals) != CW_OK;
        failures += cw_accumulator_get_field(acc, CW_FIELD_WORK_PAPER, buf, n) != CW_OK;
        failures += cw_accumulator_get_field(acc, CW_FIELD_WORK_CONSISTENT, buf, n) != CW_OK;
        failures += cw_accumulator_get_strip_work(acc, buf, (size_t)ny) != CW_OK;
    }
    failures += cw_accumulator_reset(acc) != CW_OK;
    const long allocations = cw_count_stop();
    assert_int_equal(failures, 0);
    assert_int_equal(allocations, 0);
    cw_accumulator_destroy(acc);
    cw_solver_destroy(s);
}

/* The exact model after cw_solver_prepare / cw_batch_prepare. */
static void test_exact_allocates_nothing_after_prepare(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_UNIFORM, 24, 24, 1.2);
    assert_status(cw_solver_prepare(s, CW_MODEL_EXACT), CW_OK);
    double out[24 * 24];
    int states[24 * 24];
    double y[24], w[24], par[24];
    long allocations = 0;
    for (int k = 0; k < kContacts; ++k) {
        cw_params p = contact(k);
        p.model = CW_MODEL_EXACT;
        p.flexibility = CW_FLEX_FROM_MATERIAL;
        if (k == 8 || k == 9) continue; /* a/b = 1e-3: the box is 1000 elements long */
        cw_result r;
        cw_result_init(&r);
        cw_count_start();
        const int st = cw_solver_solve(s, &p, CW_SOLVE_FULL, &r);
        for (int f = CW_FIELD_X; f <= CW_FIELD_WORK_CONSISTENT; ++f)
            cw_solver_get_field(s, f, out, 24 * 24);
        cw_solver_get_state(s, states, 24 * 24);
        cw_solver_get_profile(s, y, w, par, 24);
        allocations += cw_count_stop();
        assert_status(st, CW_OK);
    }
    assert_int_equal(allocations, 0);
    cw_solver_destroy(s);

    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_UNIFORM;
    g.nx = g.ny = 16;
    g.box_scale = 1.25;
    cw_batch* b = NULL;
    assert_status(cw_batch_create(&g, 2, &b, NULL, 0), CW_OK);
    assert_status(cw_batch_prepare(b, CW_MODEL_EXACT), CW_OK);
    cw_params p[4];
    cw_result r[4];
    for (int k = 0; k < 4; ++k) {
        p[k] = contact(k + 1);
        p[k].model = CW_MODEL_EXACT;
        cw_result_init(&r[k]);
    }
    assert_status(cw_batch_solve(b, 4, p, CW_SOLVE_FULL, r, NULL), CW_OK); /* OpenMP pool */
    cw_count_start();
    const int st = cw_batch_solve(b, 4, p, CW_SOLVE_FULL, r, NULL);
    assert_int_equal(cw_count_stop(), 0);
    assert_status(st, CW_OK);
    cw_batch_destroy(b);
}

/* The wear of a solve and its accumulation on a profile allocate nothing
 * once the handles exist: cw_wear_compute (both laws, every source) and its
 * getters, cw_wear_profile_add/_add_strips/_get_depth/_get_totals/_merge/
 * _get_state/_add_state/_reset (a campaign's hot calls). The update helper
 * allocates its workspace, as the header says. */
static void test_wear_allocates_nothing(void** state)
{
    (void)state;
    const int nx = 15, ny = 11;
    const size_t n = (size_t)nx * ny;
    cw_solver* s = cw_test_solver(CW_GRID_KALKER_STRIPS, nx, ny, 1.0);
    cw_wear* w = NULL;
    assert_status(cw_wear_create(s, &w), CW_OK);
    double nodes[80];
    for (int k = 0; k < 80; ++k) nodes[k] = -0.02 + 5e-4 * k;
    cw_wear_profile *a = NULL, *b = NULL;
    assert_status(cw_wear_profile_create(nodes, 80, &a, NULL, 0), CW_OK);
    assert_status(cw_wear_profile_create(nodes, 80, &b, NULL, 0), CW_OK);
    size_t words = 0;
    assert_status(cw_wear_profile_state_size(a, &words), CW_OK);
    uint64_t* saved = (uint64_t*)malloc(words * sizeof *saved);
    double* buf = (double*)malloc(n * sizeof *buf);
    int* ibuf = (int*)malloc(n * sizeof *ibuf);
    double y[11], width[11], depth[11], par[11], profile[80];
    cw_wear_result r;
    cw_wear_result_init(&r);
    cw_wear_profile_totals t;
    cw_wear_profile_totals_init(&t);
    int failures = 0;
    cw_count_start();
    for (int k = 0; k < kContacts; ++k) {
        const cw_params p = contact(k);
        failures += cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL) != CW_OK;
        for (int law = CW_WEAR_USFD; law <= CW_WEAR_ARCHARD_KTH; ++law)
            for (int src = CW_WEAR_SOURCE_CONSISTENT; src <= CW_WEAR_SOURCE_SLIP; ++src) {
                cw_wear_params wp;
                cw_wear_params_init(&wp);
                wp.law = law;
                wp.source = src;
                wp.rolling_speed = 20.0;
                failures += cw_wear_compute(w, s, &wp, &r) != CW_OK;
                for (int f = CW_WEAR_FIELD_RATE; f <= CW_WEAR_FIELD_SLIDING; ++f)
                    failures += cw_wear_get_field(w, f, buf, n) != CW_OK;
                failures += cw_wear_get_regimes(w, ibuf, n) != CW_OK;
                failures += cw_wear_get_strips(w, y, width, depth, par, (size_t)ny) != CW_OK;
                failures += cw_wear_get_result(w, &r) != CW_OK;
                if (k == 3) continue; /* xi = 1e100 wears ~1e40 m a pass: refused (an
                                         error, which may allocate its message) */
                failures += cw_wear_profile_add(a, w, 1e-3 * (k - 5), 1, 0.1, 10.0) != CW_OK;
                failures += cw_wear_profile_add_strips(b, y, width, par, (size_t)ny,
                                                       1e-3 * (k - 5), -1, 0.0, 3.0) != CW_OK;
            }
        failures += cw_wear_profile_get_depth(a, CW_WEAR_DEPTH_NORMAL, profile, 80) != CW_OK;
        failures += cw_wear_profile_get_depth(a, CW_WEAR_DEPTH_HEIGHT, profile, 80) != CW_OK;
        failures += cw_wear_profile_get_totals(a, &t) != CW_OK;
    }
    failures += cw_wear_profile_merge(a, b) != CW_OK;
    failures += cw_wear_profile_get_state(b, saved, words) != CW_OK;
    failures += cw_wear_profile_add_state(a, saved, words) != CW_OK;
    failures += cw_wear_profile_reset(b) != CW_OK;
    const long allocations = cw_count_stop();
    assert_int_equal(failures, 0);
    assert_int_equal(allocations, 0);
    /* ... and the counter sees the helper's documented workspace. */
    double old[80] = {0}, out[80];
    cw_count_start();
    assert_status(cw_wear_profile_update(nodes, old, profile, 80, 1e-3, out, 80, NULL, 0), CW_OK);
    assert_true(cw_count_stop() > 0);
    free(saved);
    free(buf);
    free(ibuf);
    cw_wear_profile_destroy(a);
    cw_wear_profile_destroy(b);
    cw_wear_destroy(w);
    cw_solver_destroy(s);
}

static void test_batch_allocates_nothing_after_first_call(void** state)
{
    (void)state;
    cw_grid g;
    cw_grid_init(&g);
    g.nx = 25;
    g.ny = 19;
    cw_params p[kContacts];
    cw_result r[kContacts];
    int statuses[kContacts];
    for (int k = 0; k < kContacts; ++k) {
        p[k] = contact(k);
        cw_result_init(&r[k]);
    }
    const int threads[] = {1, 2, 4};
    for (int t = 0; t < 3; ++t) {
        cw_batch* b = NULL;
        assert_status(cw_batch_create(&g, threads[t], &b, NULL, 0), CW_OK);
        assert_status(cw_batch_solve(b, kContacts, p, CW_SOLVE_FULL, r, statuses), CW_OK);
        int failures = 0;
        cw_count_start();
        for (int repeat = 0; repeat < 5; ++repeat)
            for (int mode = CW_SOLVE_FORCES; mode <= CW_SOLVE_FULL; ++mode)
                failures += cw_batch_solve(b, kContacts, p, mode, r, statuses) != CW_OK;
        const long allocations = cw_count_stop();
        assert_int_equal(failures, 0);
        if (allocations != 0) print_error("threads = %d: %ld allocations\n", threads[t], allocations);
        assert_int_equal(allocations, 0);
        cw_batch_destroy(b);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_counter_sees_library_allocations),
        cmocka_unit_test(test_solve_and_export_allocate_nothing),
        cmocka_unit_test(test_accumulator_allocates_nothing),
        cmocka_unit_test(test_wear_allocates_nothing),
        cmocka_unit_test(test_batch_allocates_nothing_after_first_call),
        cmocka_unit_test(test_exact_allocates_nothing_after_prepare),
    };
    return cmocka_run_group_tests_name("robustness_noalloc_capi", tests, NULL, NULL);
}
