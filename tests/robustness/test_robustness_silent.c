/* "Prints nothing" (doc/reference/guarantees.md, header of cw_solver_solve):
 * file descriptors 1 and 2 are redirected to a temporary file around calls
 * of every public function -- successes and error paths, both grids, the
 * accumulator, the batch on several threads, the helpers and Kalker's
 * normalised interface -- and the file must stay empty. Descriptors, not
 * FILE streams, so output through printf, std::cout, std::cerr or write(2)
 * is all caught; stdio buffers are flushed before the check. */
#include "capi_fixtures.h"

#include <unistd.h>

static int g_saved_out = -1, g_saved_err = -1;
static FILE* g_capture = NULL;

/* No cmocka assertion while the descriptors are redirected (a failure would
 * longjmp past the restore and its message would land in the capture):
 * checks there only record the first failing line. */
static int g_failed_line = 0;
#define CHECK(cond)                                       \
    do {                                                  \
        if (!(cond) && g_failed_line == 0) g_failed_line = __LINE__; \
    } while (0)

static void capture_begin(void)
{
    fflush(NULL);
    g_failed_line = 0;
    g_capture = tmpfile();
    assert_non_null(g_capture);
    g_saved_out = dup(1);
    g_saved_err = dup(2);
    assert_true(g_saved_out >= 0 && g_saved_err >= 0);
    assert_true(dup2(fileno(g_capture), 1) == 1);
    assert_true(dup2(fileno(g_capture), 2) == 2);
}

/* Restores the descriptors and returns the number of bytes written (shown
 * unless quiet). */
static long capture_end(int quiet)
{
    fflush(NULL);
    dup2(g_saved_out, 1);
    dup2(g_saved_err, 2);
    close(g_saved_out);
    close(g_saved_err);
    fseek(g_capture, 0, SEEK_END);
    const long bytes = ftell(g_capture);
    if (bytes > 0 && !quiet) { /* show what was printed */
        char text[512];
        rewind(g_capture);
        const size_t n = fread(text, 1, sizeof text - 1, g_capture);
        text[n] = '\0';
        print_error("the library printed %ld bytes: \"%s\"\n", bytes, text);
    }
    fclose(g_capture);
    return bytes;
}

static cw_params contact(double xi, double eta, double phi)
{
    cw_params p;
    cw_params_init(&p);
    p.xi_x = xi;
    p.xi_y = eta;
    p.phi = phi;
    return p;
}

/* Every call whose status is not checked here is exercised for its output
 * only; the other robustness tests check the statuses. */
static void exercise_everything(void)
{
    char msg[256];
    double buf[4];
    cw_grid grid;
    cw_grid_init(&grid);
    grid.nx = 12;
    grid.ny = 9;
    size_t n = 12 * 9;
    double* field = malloc(n * sizeof *field);
    int* state = malloc(n * sizeof *state);

    (void)cw_version_number();
    (void)cw_abi_version();
    for (int code = -5; code < 40; ++code) (void)cw_status_string(code);

    for (int kind = 0; kind < 2; ++kind) {
        grid.kind = kind == 0 ? CW_GRID_KALKER_STRIPS : CW_GRID_UNIFORM;
        cw_solver* s = NULL;
        CHECK(cw_solver_create(&grid, &s, msg, sizeof msg) == CW_OK);
        cw_result r;
        cw_result_init(&r);
        const cw_params cases[] = {contact(6e-4, 3e-4, 0.2), contact(1e-2, 5e-3, 2.0),
                                   contact(0.0, 0.0, 0.0), contact(1e-7, 0.0, 0.0)};
        for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
            CHECK(cw_solver_solve(s, &cases[c], CW_SOLVE_FULL, &r) == CW_OK);
            for (int f = CW_FIELD_X; f <= CW_FIELD_WORK_CONSISTENT; ++f)
                CHECK(cw_solver_get_field(s, f, field, n) == CW_OK);
            CHECK(cw_solver_get_state(s, state, n) == CW_OK);
            CHECK(cw_solver_get_profile(s, field, field + 9, field + 18, 9) == CW_OK);
            CHECK(cw_solver_get_result(s, &r) == CW_OK);
        }
        /* Error paths: each builds a message, none may print it. */
        cw_params bad = contact(0.0, 0.0, 0.0);
        bad.mu = -1.0;
        CHECK(cw_solver_solve(s, &bad, CW_SOLVE_FULL, &r) != CW_OK);
        (void)cw_solver_last_error(s);
        bad = contact(1e300 * 1e300, 0.0, 0.0);
        CHECK(cw_solver_solve(s, &bad, CW_SOLVE_FULL, &r) != CW_OK);
        CHECK(cw_solver_solve(s, &cases[0], 77, &r) != CW_OK);
        CHECK(cw_solver_get_field(s, CW_FIELD_PX, field, n) != CW_OK);
        CHECK(cw_solver_get_field(s, 99, field, n) != CW_OK);
        CHECK(cw_solver_solve(s, &cases[0], CW_SOLVE_FORCES, &r) == CW_OK);
        CHECK(cw_solver_get_field(s, CW_FIELD_WORK_PAPER, field, n) != CW_OK);
        CHECK(cw_solver_get_field(s, CW_FIELD_PX, field, 3) != CW_OK);

        cw_accumulator* acc = NULL;
        CHECK(cw_accumulator_create(s, &acc) == CW_OK);
        CHECK(cw_accumulator_add(acc, s, 1.0) != CW_OK); /* no work */
        CHECK(cw_solver_solve(s, &cases[1], CW_SOLVE_FULL, &r) == CW_OK);
        CHECK(cw_accumulator_add(acc, s, 0.5) == CW_OK);
        CHECK(cw_accumulator_add(acc, s, -1.0) != CW_OK);
        (void)cw_accumulator_last_error(acc);
        cw_accumulation t;
        cw_accumulation_init(&t);
        CHECK(cw_accumulator_get_totals(acc, &t) == CW_OK);
        CHECK(cw_accumulator_get_field(acc, CW_FIELD_WORK_CONSISTENT, field, n) == CW_OK);
        CHECK(cw_accumulator_get_strip_work(acc, field, 9) == CW_OK);
        CHECK(cw_accumulator_reset(acc) == CW_OK);
        cw_accumulator_destroy(acc);
        cw_solver_destroy(s);
    }

    cw_solver* none = NULL;
    grid.nx = 0;
    CHECK(cw_solver_create(&grid, &none, msg, sizeof msg) != CW_OK);
    CHECK(cw_solver_create(NULL, &none, NULL, 0) != CW_OK);
    (void)cw_solver_last_error(NULL);
    grid.nx = 12;

    cw_batch* batch = NULL;
    CHECK(cw_batch_create(&grid, 2, &batch, msg, sizeof msg) == CW_OK);
    cw_params many[6];
    cw_result results[6];
    int statuses[6];
    for (int k = 0; k < 6; ++k) {
        many[k] = contact(1e-4 * k, 2e-4, 0.1 * k);
        cw_result_init(&results[k]);
    }
    CHECK(cw_batch_solve(batch, 6, many, CW_SOLVE_FULL, results, statuses) == CW_OK);
    many[3].normal_force = -1.0;
    CHECK(cw_batch_solve(batch, 6, many, CW_SOLVE_FULL, results, statuses) != CW_OK);
    (void)cw_batch_last_error(batch);
    cw_batch_destroy(batch);
    batch = NULL;
    CHECK(cw_batch_create(&grid, CW_MAX_BATCH_THREADS + 1, &batch, msg, sizeof msg) != CW_OK);
    cw_batch_destroy(batch);

    CHECK(cw_kalker_coefficients(1.0, 0.25, buf, msg, sizeof msg) == CW_OK);
    CHECK(cw_kalker_coefficients(-1.0, 0.25, buf, msg, sizeof msg) != CW_OK);
    CHECK(cw_kalker_flexibilities(6e-3, 6e-3, 82e9, 0.28, buf, msg, sizeof msg) == CW_OK);
    CHECK(cw_kalker_flexibilities(6e-3, 6e-3, -1.0, 0.28, buf, msg, sizeof msg) != CW_OK);
    CHECK(cw_hertz_solve(1.0, 2.0, 1e5, 9e10, buf, msg, sizeof msg) == CW_OK);
    CHECK(cw_hertz_solve(-1.0, 2.0, 1e5, 9e10, buf, msg, sizeof msg) != CW_OK);
    double tx, ty;
    CHECK(cw_fastsim_normalised(0.1, 0.2, 0.3, 0.3, 5, 5, 1e-3, &tx, &ty, msg, sizeof msg) == CW_OK);
    CHECK(
        cw_fastsim_normalised(0.1, 0.2, 0.3, 0.3, 0, 5, 1e-3, &tx, &ty, msg, sizeof msg) != CW_OK);
    free(field);
    free(state);
}

static void library_prints_nothing(void** unused)
{
    (void)unused;
    capture_begin();
    exercise_everything();
    assert_int_equal(capture_end(0), 0);
    if (g_failed_line != 0) fail_msg("check at line %d failed", g_failed_line);
}

/* The capture itself works: a printf between begin and end is seen. */
static void capture_sees_output(void** unused)
{
    (void)unused;
    capture_begin();
    printf("x");
    fprintf(stderr, "y");
    const long bytes = capture_end(1);
    assert_int_equal(bytes, 2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(capture_sees_output),
        cmocka_unit_test(library_prints_nothing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
