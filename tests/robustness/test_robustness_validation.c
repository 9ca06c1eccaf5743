/* Hostile input at the C ABI: every numeric input is validated, every error
 * names the offending input, nothing is written on error, and the handle
 * stays usable. Also: zero load, zero friction and zero creepage are valid
 * and give exact zeros, never NaN. */
#include "capi_fixtures.h"

#include <float.h>
#include <limits.h>

static const double kNaN = NAN;
static const double kInf = INFINITY;

/* ------------------------------------------------------------- helpers */

/* The grid of the solver under test, to build a fresh twin of it. */
static cw_grid g_grid;

static cw_solver* make_solver(int kind, int nx, int ny, double box_scale)
{
    cw_grid_init(&g_grid);
    g_grid.kind = kind;
    g_grid.nx = nx;
    g_grid.ny = ny;
    g_grid.box_scale = box_scale;
    return cw_test_solver(kind, nx, ny, box_scale);
}

/* A solve that must fail: the status, the message names `name`, the result
 * is untouched, the handle then has no solution, and a valid solve on the
 * same handle afterwards reproduces a fresh handle's result bit for bit. */
static void expect_solve_error(cw_solver* s, const cw_params* p, int mode, int status,
                               const char* name)
{
    cw_result r;
    cw_poison_result(&r);
    assert_status(cw_solver_solve(s, p, mode, &r), status);
    assert_true(cw_result_poisoned(&r));
    assert_names(cw_solver_last_error(s), name);
    assert_status(cw_solver_get_result(s, &r), CW_ERR_NO_SOLUTION);
    assert_true(cw_result_poisoned(&r));
    double v = 42.0;
    assert_status(cw_solver_get_field(s, CW_FIELD_PX, &v, cw_cells(s)), CW_ERR_NO_SOLUTION);

    /* Still usable, and the failure left no trace. */
    cw_params good;
    cw_params_init(&good);
    good.xi_x = 1e-3;
    good.phi = 0.5;
    cw_result after, fresh;
    cw_result_init(&after);
    cw_result_init(&fresh);
    assert_status(cw_solver_solve(s, &good, CW_SOLVE_FULL, &after), CW_OK);
    assert_string_equal(cw_solver_last_error(s), "");
    cw_solver* other = NULL;
    assert_status(cw_solver_create(&g_grid, &other, NULL, 0), CW_OK);
    assert_status(cw_solver_solve(other, &good, CW_SOLVE_FULL, &fresh), CW_OK);
    assert_memory_equal(&after, &fresh, sizeof after);
    cw_solver_destroy(other);
}

typedef struct {
    size_t offset; /* of a double in cw_params */
    const char* name;
    double value;
    int flexibility;
} DoubleRule;

#define P(field) offsetof(cw_params, field), #field

static void set_double(cw_params* p, size_t offset, double v)
{
    memcpy((unsigned char*)p + offset, &v, sizeof v);
}

/* ---------------------------------------------------------- parameters */

static void test_every_numeric_parameter_is_validated(void** state)
{
    (void)state;
    const DoubleRule rules[] = {
        /* semi-axes: finite and > 0 */
        {P(a), NAN, CW_FLEX_FROM_MATERIAL}, {P(a), INFINITY, CW_FLEX_FROM_MATERIAL},
        {P(a), -INFINITY, CW_FLEX_FROM_MATERIAL}, {P(a), 0.0, CW_FLEX_FROM_MATERIAL},
        {P(a), -0.0, CW_FLEX_FROM_MATERIAL}, {P(a), -6e-3, CW_FLEX_FROM_MATERIAL},
        {P(b), NAN, CW_FLEX_FROM_MATERIAL}, {P(b), INFINITY, CW_FLEX_FROM_MATERIAL},
        {P(b), 0.0, CW_FLEX_FROM_MATERIAL}, {P(b), -1.0, CW_FLEX_FROM_MATERIAL},
        /* load and friction: finite and >= 0 */
        {P(normal_force), NAN, CW_FLEX_FROM_MATERIAL},
        {P(normal_force), INFINITY, CW_FLEX_FROM_MATERIAL},
        {P(normal_force), -1.0, CW_FLEX_FROM_MATERIAL},
        {P(normal_force), -DBL_MIN, CW_FLEX_FROM_MATERIAL},
        {P(mu), NAN, CW_FLEX_FROM_MATERIAL}, {P(mu), INFINITY, CW_FLEX_FROM_MATERIAL},
        {P(mu), -0.1, CW_FLEX_FROM_MATERIAL},
        /* material: G > 0, 0 <= nu <= 0.5 */
        {P(G), NAN, CW_FLEX_FROM_MATERIAL}, {P(G), INFINITY, CW_FLEX_FROM_MATERIAL},
        {P(G), 0.0, CW_FLEX_FROM_MATERIAL}, {P(G), -82e9, CW_FLEX_FROM_MATERIAL},
        {P(nu), NAN, CW_FLEX_FROM_MATERIAL}, {P(nu), -INFINITY, CW_FLEX_FROM_MATERIAL},
        {P(nu), -1e-9, CW_FLEX_FROM_MATERIAL}, {P(nu), 0.5000001, CW_FLEX_FROM_MATERIAL},
        /* given flexibilities: finite and > 0 */
        {P(L1), NAN, CW_FLEX_GIVEN}, {P(L1), INFINITY, CW_FLEX_GIVEN}, {P(L1), 0.0, CW_FLEX_GIVEN},
        {P(L1), -1e-11, CW_FLEX_GIVEN}, {P(L2), NAN, CW_FLEX_GIVEN}, {P(L2), 0.0, CW_FLEX_GIVEN},
        {P(L2), -1e-11, CW_FLEX_GIVEN}, {P(L3), NAN, CW_FLEX_GIVEN}, {P(L3), 0.0, CW_FLEX_GIVEN},
        {P(L3), -INFINITY, CW_FLEX_GIVEN},
        /* kinematics: finite */
        {P(xi_x), NAN, CW_FLEX_FROM_MATERIAL}, {P(xi_x), INFINITY, CW_FLEX_FROM_MATERIAL},
        {P(xi_x), -INFINITY, CW_FLEX_FROM_MATERIAL}, {P(xi_y), NAN, CW_FLEX_FROM_MATERIAL},
        {P(xi_y), INFINITY, CW_FLEX_FROM_MATERIAL}, {P(phi), NAN, CW_FLEX_FROM_MATERIAL},
        {P(phi), -INFINITY, CW_FLEX_FROM_MATERIAL},
        {P(xi_x), NAN, CW_FLEX_GIVEN}, {P(phi), INFINITY, CW_FLEX_GIVEN},
    };
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind) {
        cw_solver* s = make_solver(kind, 12, 10, 1.2);
        for (size_t k = 0; k < sizeof rules / sizeof rules[0]; ++k) {
            cw_params p;
            cw_params_init(&p);
            p.flexibility = rules[k].flexibility;
            p.L1 = p.L2 = p.L3 = 1e-11;
            p.xi_x = 1e-3;
            set_double(&p, rules[k].offset, rules[k].value);
            expect_solve_error(s, &p, CW_SOLVE_FULL, CW_ERR_INVALID_INPUT, rules[k].name);
            expect_solve_error(s, &p, CW_SOLVE_FORCES, CW_ERR_INVALID_INPUT, rules[k].name);
        }
        cw_solver_destroy(s);
    }
}

/* Inputs not used by the chosen flexibility source are not validated. */
static void test_unused_inputs_are_ignored(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_KALKER_STRIPS, 10, 10, 1.0);
    cw_params p;
    cw_params_init(&p);
    p.xi_y = 1e-3;
    p.L1 = p.L2 = p.L3 = kNaN; /* FROM_MATERIAL: L's unused */
    cw_result r;
    cw_result_init(&r);
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
    cw_params_init(&p);
    p.flexibility = CW_FLEX_GIVEN;
    p.L1 = p.L2 = p.L3 = 1e-11;
    p.G = -1.0; /* GIVEN: G and nu unused */
    p.nu = kInf;
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
    assert_true(cw_result_finite(&r));
    cw_solver_destroy(s);
}

/* Closed ranges: the ends are valid, one ulp outside is not. */
static void test_range_ends(void** state)
{
    (void)state;
    cw_solver* s = make_solver(CW_GRID_KALKER_STRIPS, 8, 8, 1.0);
    cw_params p;
    cw_result r;
    cw_result_init(&r);

    const double aspect_ok[] = {CW_MIN_ASPECT, CW_MAX_ASPECT};
    for (int k = 0; k < 2; ++k) {
        cw_params_init(&p);
        p.b = 1.0;
        p.a = aspect_ok[k];
        p.xi_x = 1e-4;
        assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
        assert_true(cw_result_finite(&r));
    }
    const double aspect_bad[] = {nextafter(CW_MIN_ASPECT, 0.0), nextafter(CW_MAX_ASPECT, 2e3),
                                 1e-300, 1e300};
    for (int k = 0; k < 4; ++k) {
        cw_params_init(&p);
        p.b = 1.0;
        p.a = aspect_bad[k];
        expect_solve_error(s, &p, CW_SOLVE_FULL, CW_ERR_INVALID_INPUT, "a/b");
    }

    const double nu_ok[] = {0.0, 0.5};
    for (int k = 0; k < 2; ++k) {
        cw_params_init(&p);
        p.nu = nu_ok[k];
        p.xi_x = 1e-3;
        assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
        assert_true(cw_result_finite(&r));
    }
    cw_params_init(&p);
    p.nu = nextafter(0.5, 1.0);
    expect_solve_error(s, &p, CW_SOLVE_FULL, CW_ERR_INVALID_INPUT, "nu");
    p.nu = -DBL_MIN;
    expect_solve_error(s, &p, CW_SOLVE_FULL, CW_ERR_INVALID_INPUT, "nu");
    cw_solver_destroy(s);
}

/* Finite inputs whose products overflow double precision are rejected
 * with an error, never turned into Inf or NaN. */
static void test_overflowing_combinations(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_UNIFORM, 10, 10, 1.5);
    cw_params p;
    cw_result r;
    cw_params_init(&p);
    p.a = p.b = 1e-200; /* pressure 2N/(pi a b) overflows */
    p.xi_x = 1e-3;
    cw_poison_result(&r);
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_ERR_INVALID_INPUT);
    assert_true(cw_result_poisoned(&r));
    assert_names(cw_solver_last_error(s), "a");
    assert_names(cw_solver_last_error(s), "normal_force");

    cw_params_init(&p);
    p.xi_x = 1e308; /* rigid slip a xi / L overflows */
    cw_poison_result(&r);
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_ERR_INVALID_INPUT);
    assert_true(cw_result_poisoned(&r));
    assert_names(cw_solver_last_error(s), "xi_x");

    /* Any failure leaves a usable handle. */
    cw_params_init(&p);
    p.xi_y = -2e-3;
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
    cw_check_solution(s, &p, CW_SOLVE_FULL, &r);
    cw_solver_destroy(s);
}

static void test_enumerations(void** state)
{
    (void)state;
    cw_solver* s = make_solver(CW_GRID_KALKER_STRIPS, 6, 6, 1.0);
    cw_params p;
    const int bad_enum[] = {-1, 2, 7, INT_MAX, INT_MIN};
    for (int k = 0; k < 5; ++k) {
        cw_params_init(&p);
        p.flexibility = bad_enum[k];
        expect_solve_error(s, &p, CW_SOLVE_FULL, CW_ERR_UNKNOWN_OPTION, "flexibility");
        cw_params_init(&p);
        p.pressure = bad_enum[k];
        expect_solve_error(s, &p, CW_SOLVE_FULL, CW_ERR_UNKNOWN_OPTION, "pressure");
        cw_params_init(&p);
        expect_solve_error(s, &p, bad_enum[k], CW_ERR_UNKNOWN_OPTION, "mode");
    }
    const int bad_direction[] = {0, 2, -2, INT_MAX, INT_MIN};
    for (int k = 0; k < 5; ++k) {
        cw_params_init(&p);
        p.rolling_direction = bad_direction[k];
        expect_solve_error(s, &p, CW_SOLVE_FORCES, CW_ERR_INVALID_INPUT, "rolling_direction");
    }
    cw_solver_destroy(s);
}

static void test_struct_sizes(void** state)
{
    (void)state;
    cw_solver* s = make_solver(CW_GRID_KALKER_STRIPS, 6, 6, 1.0);
    const size_t bad[] = {0, 1, sizeof(size_t) - 1, (size_t)1 << 20, (size_t)-1};
    for (int k = 0; k < 5; ++k) {
        cw_params p;
        cw_params_init(&p);
        p.struct_size = bad[k];
        expect_solve_error(s, &p, CW_SOLVE_FULL, CW_ERR_STRUCT_SIZE, "params");

        cw_params_init(&p);
        assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
        cw_result r;
        cw_poison_result(&r);
        r.struct_size = bad[k];
        assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_ERR_STRUCT_SIZE);
        assert_names(cw_solver_last_error(s), "result");
        assert_true(cw_poisoned((unsigned char*)&r + sizeof r.struct_size,
                                  sizeof r - sizeof r.struct_size));
        cw_result fresh;
        cw_poison_result(&fresh);
        assert_status(cw_solver_get_result(s, &fresh), CW_ERR_NO_SOLUTION);
        assert_true(cw_result_poisoned(&fresh));
        /* Reading into a garbage struct is refused too. */
        assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
        assert_status(cw_solver_get_result(s, &r), CW_ERR_STRUCT_SIZE);
        assert_names(cw_solver_last_error(s), "result");

        cw_grid g;
        cw_grid_init(&g);
        g.struct_size = bad[k];
        cw_solver* t = (cw_solver*)&g; /* must be reset to NULL */
        char msg[128];
        assert_status(cw_solver_create(&g, &t, msg, sizeof msg), CW_ERR_STRUCT_SIZE);
        assert_null(t);
        assert_names(msg, "grid");
    }
    cw_solver_destroy(s);
}

/* ----------------------------------------------------------------- grid */

static void expect_create_error(const cw_grid* g, int status, const char* name)
{
    cw_solver* s = (cw_solver*)g;
    char msg[256];
    cw_poison(msg, sizeof msg);
    assert_status(cw_solver_create(g, &s, msg, sizeof msg), status);
    assert_null(s);
    assert_names(msg, name);

    cw_batch* b = (cw_batch*)g;
    cw_poison(msg, sizeof msg);
    assert_status(cw_batch_create(g, 2, &b, msg, sizeof msg), status);
    assert_null(b);
    assert_names(msg, name);
}

static void test_grid_limits(void** state)
{
    (void)state;
    const int bad_cells[] = {0, -1, CW_MAX_GRID_CELLS + 1, INT_MAX, INT_MIN};
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind) {
        for (int k = 0; k < 5; ++k) {
            cw_grid g;
            cw_grid_init(&g);
            g.kind = kind;
            g.nx = bad_cells[k];
            expect_create_error(&g, CW_ERR_GRID_OUT_OF_RANGE, "nx");
            cw_grid_init(&g);
            g.kind = kind;
            g.ny = bad_cells[k];
            expect_create_error(&g, CW_ERR_GRID_OUT_OF_RANGE, "ny");
        }
    }
    const double bad_scale[] = {0.0, -1.0, nextafter(1.0, 0.0), nextafter(CW_MAX_BOX_SCALE, 1e3),
                                NAN, INFINITY, -INFINITY};
    for (int k = 0; k < 7; ++k) {
        cw_grid g;
        cw_grid_init(&g);
        g.kind = CW_GRID_UNIFORM;
        g.box_scale = bad_scale[k];
        expect_create_error(&g, CW_ERR_GRID_OUT_OF_RANGE, "box_scale");
    }
    const int bad_kind[] = {-1, 3, INT_MAX};
    for (int k = 0; k < 3; ++k) {
        cw_grid g;
        cw_grid_init(&g);
        g.kind = bad_kind[k];
        expect_create_error(&g, CW_ERR_UNKNOWN_OPTION, "kind");
    }

    /* The ends of every range are valid. */
    const int ok_cells[][2] = {{1, 1}, {1, CW_MAX_GRID_CELLS}, {CW_MAX_GRID_CELLS, 1}};
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind)
        for (int k = 0; k < 3; ++k) {
            cw_solver* s = cw_test_solver(kind, ok_cells[k][0], ok_cells[k][1], 1.0);
            cw_solver_destroy(s);
        }
    cw_solver* s = cw_test_solver(CW_GRID_UNIFORM, 4, 4, CW_MAX_BOX_SCALE);
    cw_solver_destroy(s);
}

/* The strip grid ignores box_scale, whatever it holds, and an accumulator
 * on such a solver works (it once compared NaN != NaN). */
static void test_strip_grid_ignores_box_scale(void** state)
{
    (void)state;
    const double scales[] = {NAN, -INFINITY, 0.0, 1e300};
    for (int k = 0; k < 4; ++k) {
        cw_solver* s = cw_test_solver(CW_GRID_KALKER_STRIPS, 5, 5, scales[k]);
        cw_accumulator* acc = NULL;
        assert_status(cw_accumulator_create(s, &acc), CW_OK);
        cw_params p;
        cw_params_init(&p);
        p.xi_x = 2e-3;
        assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
        assert_status(cw_accumulator_add(acc, s, 0.01), CW_OK);
        cw_accumulator_destroy(acc);
        cw_solver_destroy(s);
    }
}

static void test_message_buffers(void** state)
{
    (void)state;
    cw_grid g;
    cw_grid_init(&g);
    g.nx = 0;
    cw_solver* s = NULL;
    char msg[64];

    /* NULL or zero length: nothing written. */
    assert_status(cw_solver_create(&g, &s, NULL, 100), CW_ERR_GRID_OUT_OF_RANGE);
    cw_poison(msg, sizeof msg);
    assert_status(cw_solver_create(&g, &s, msg, 0), CW_ERR_GRID_OUT_OF_RANGE);
    assert_true(cw_poisoned(msg, sizeof msg));
    /* Truncated to len - 1 characters plus NUL; the rest untouched. */
    for (size_t len = 1; len < 8; ++len) {
        cw_poison(msg, sizeof msg);
        assert_status(cw_solver_create(&g, &s, msg, len), CW_ERR_GRID_OUT_OF_RANGE);
        assert_int_equal(strlen(msg), len - 1);
        assert_true(cw_poisoned(msg + len, sizeof msg - len));
    }
    /* Success clears the message. */
    cw_grid_init(&g);
    cw_poison(msg, sizeof msg);
    assert_status(cw_solver_create(&g, &s, msg, sizeof msg), CW_OK);
    assert_string_equal(msg, "");
    cw_solver_destroy(s);
}

/* ------------------------------------------------------------- pointers */

static void test_null_pointers(void** state)
{
    (void)state;
    cw_params p;
    cw_params_init(&p);
    cw_result r;
    cw_result_init(&r);
    double buf[4];
    int ibuf[4];
    int nx, ny;
    char msg[128];

    assert_status(cw_grid_init(NULL), CW_ERR_NULL_POINTER);
    assert_status(cw_params_init(NULL), CW_ERR_NULL_POINTER);
    assert_status(cw_result_init(NULL), CW_ERR_NULL_POINTER);
    assert_status(cw_accumulation_init(NULL), CW_ERR_NULL_POINTER);

    cw_grid g;
    cw_grid_init(&g);
    cw_solver* s = NULL;
    assert_status(cw_solver_create(NULL, &s, msg, sizeof msg), CW_ERR_NULL_POINTER);
    assert_null(s);
    assert_names(msg, "grid");
    assert_status(cw_solver_create(&g, NULL, msg, sizeof msg), CW_ERR_NULL_POINTER);
    assert_names(msg, "solver");

    assert_status(cw_solver_solve(NULL, &p, CW_SOLVE_FULL, &r), CW_ERR_NULL_POINTER);
    assert_status(cw_solver_get_result(NULL, &r), CW_ERR_NULL_POINTER);
    assert_status(cw_solver_get_field(NULL, CW_FIELD_PX, buf, 4), CW_ERR_NULL_POINTER);
    assert_status(cw_solver_get_state(NULL, ibuf, 4), CW_ERR_NULL_POINTER);
    assert_status(cw_solver_get_profile(NULL, buf, buf, buf, 4), CW_ERR_NULL_POINTER);
    assert_status(cw_solver_grid_size(NULL, &nx, &ny), CW_ERR_NULL_POINTER);
    assert_status(cw_solver_destroy(NULL), CW_OK);
    assert_non_null(cw_solver_last_error(NULL));
    assert_true(strlen(cw_solver_last_error(NULL)) > 0);

    s = cw_test_solver(CW_GRID_KALKER_STRIPS, 2, 2, 1.0);
    assert_status(cw_solver_grid_size(s, NULL, &ny), CW_ERR_NULL_POINTER);
    assert_status(cw_solver_grid_size(s, &nx, NULL), CW_ERR_NULL_POINTER);
    assert_status(cw_solver_solve(s, NULL, CW_SOLVE_FULL, &r), CW_ERR_NULL_POINTER);
    assert_names(cw_solver_last_error(s), "params");
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK); /* result optional */
    assert_status(cw_solver_get_result(s, NULL), CW_ERR_NULL_POINTER);
    assert_names(cw_solver_last_error(s), "result");
    assert_status(cw_solver_get_field(s, CW_FIELD_PX, NULL, 4), CW_ERR_NULL_POINTER);
    assert_names(cw_solver_last_error(s), "out");
    assert_status(cw_solver_get_state(s, NULL, 4), CW_ERR_NULL_POINTER);
    assert_names(cw_solver_last_error(s), "out");
    assert_status(cw_solver_get_profile(s, NULL, NULL, NULL, 2), CW_OK); /* all optional */

    cw_accumulator* acc = (cw_accumulator*)&g;
    assert_status(cw_accumulator_create(NULL, &acc), CW_ERR_NULL_POINTER);
    assert_null(acc);
    assert_status(cw_accumulator_create(s, NULL), CW_ERR_NULL_POINTER);
    assert_status(cw_accumulator_add(NULL, s, 1.0), CW_ERR_NULL_POINTER);
    assert_status(cw_accumulator_reset(NULL), CW_ERR_NULL_POINTER);
    assert_status(cw_accumulator_get_totals(NULL, NULL), CW_ERR_NULL_POINTER);
    assert_status(cw_accumulator_get_field(NULL, CW_FIELD_WORK_PAPER, buf, 4),
                  CW_ERR_NULL_POINTER);
    assert_status(cw_accumulator_get_strip_work(NULL, buf, 4), CW_ERR_NULL_POINTER);
    assert_status(cw_accumulator_destroy(NULL), CW_OK);
    assert_true(strlen(cw_accumulator_last_error(NULL)) > 0);
    assert_status(cw_accumulator_create(s, &acc), CW_OK);
    assert_status(cw_accumulator_add(acc, NULL, 1.0), CW_ERR_NULL_POINTER);
    assert_names(cw_accumulator_last_error(acc), "solver");
    assert_status(cw_accumulator_get_totals(acc, NULL), CW_ERR_NULL_POINTER);
    assert_names(cw_accumulator_last_error(acc), "totals");
    assert_status(cw_accumulator_get_field(acc, CW_FIELD_WORK_PAPER, NULL, 4),
                  CW_ERR_NULL_POINTER);
    assert_status(cw_accumulator_get_strip_work(acc, NULL, 4), CW_ERR_NULL_POINTER);
    cw_accumulator_destroy(acc);

    cw_batch* b = NULL;
    assert_status(cw_batch_create(NULL, 1, &b, msg, sizeof msg), CW_ERR_NULL_POINTER);
    assert_status(cw_batch_create(&g, 1, NULL, msg, sizeof msg), CW_ERR_NULL_POINTER);
    assert_names(msg, "batch");
    assert_status(cw_batch_solve(NULL, 1, &p, CW_SOLVE_FULL, &r, NULL), CW_ERR_NULL_POINTER);
    assert_status(cw_batch_destroy(NULL), CW_OK);
    assert_true(strlen(cw_batch_last_error(NULL)) > 0);
    assert_status(cw_batch_create(&g, 1, &b, msg, sizeof msg), CW_OK);
    assert_status(cw_batch_solve(b, 1, NULL, CW_SOLVE_FULL, &r, NULL), CW_ERR_NULL_POINTER);
    assert_names(cw_batch_last_error(b), "params");
    assert_status(cw_batch_solve(b, 1, &p, CW_SOLVE_FULL, NULL, NULL), CW_ERR_NULL_POINTER);
    assert_names(cw_batch_last_error(b), "results");
    assert_status(cw_batch_solve(b, 0, NULL, CW_SOLVE_FULL, NULL, NULL), CW_OK);
    cw_batch_destroy(b);

    assert_status(cw_kalker_coefficients(1.0, 0.28, NULL, msg, sizeof msg), CW_ERR_NULL_POINTER);
    assert_names(msg, "coefficients");
    assert_status(cw_kalker_flexibilities(1, 1, 1, 0.3, NULL, msg, sizeof msg),
                  CW_ERR_NULL_POINTER);
    assert_names(msg, "flexibilities");
    assert_status(cw_hertz_solve(1, 1, 1, 1, NULL, msg, sizeof msg), CW_ERR_NULL_POINTER);
    assert_names(msg, "hertz");
    double t = 0.0;
    assert_status(cw_fastsim_normalised(1, 0, 0, 0, 4, 4, 1, NULL, &t, msg, sizeof msg),
                  CW_ERR_NULL_POINTER);
    assert_names(msg, "tx");
    assert_status(cw_fastsim_normalised(1, 0, 0, 0, 4, 4, 1, &t, NULL, msg, sizeof msg),
                  CW_ERR_NULL_POINTER);
    assert_names(msg, "ty");

    cw_solver_destroy(s);
}

static void test_status_strings(void** state)
{
    (void)state;
    for (int code = -5; code < 40; ++code) {
        const char* m = cw_status_string(code);
        assert_non_null(m);
        assert_true(strlen(m) > 0);
        if (code < CW_OK || code >= CW_STATUS_END_)
            assert_string_equal(m, "unknown status code");
        else
            assert_string_not_equal(m, "unknown status code");
    }
    assert_string_equal(cw_status_string(INT_MIN), "unknown status code");
    assert_string_equal(cw_status_string(INT_MAX), "unknown status code");
}

/* -------------------------------------------------------------- outputs */

static void test_output_buffers(void** state)
{
    (void)state;
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind) {
        const int nx = 7, ny = 5;
        const size_t n = (size_t)nx * ny;
        cw_solver* s = cw_test_solver(kind, nx, ny, 1.1);
        double buf[64];
        int ibuf[64];
        cw_result r;

        /* Nothing solved yet. */
        cw_poison(buf, sizeof buf);
        assert_status(cw_solver_get_field(s, CW_FIELD_X, buf, n), CW_ERR_NO_SOLUTION);
        assert_status(cw_solver_get_state(s, ibuf, n), CW_ERR_NO_SOLUTION);
        assert_status(cw_solver_get_profile(s, buf, buf, buf, ny), CW_ERR_NO_SOLUTION);
        cw_poison_result(&r);
        assert_status(cw_solver_get_result(s, &r), CW_ERR_NO_SOLUTION);
        assert_true(cw_result_poisoned(&r));
        assert_true(cw_poisoned(buf, sizeof buf));

        cw_params p;
        cw_params_init(&p);
        p.xi_x = 1e-3;
        p.xi_y = -1e-3;
        p.phi = 2.0;
        assert_status(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &r), CW_OK);

        /* Unknown fields. */
        const int bad_field[] = {-1, CW_FIELD_WORK_CONSISTENT + 1, INT_MAX, INT_MIN};
        for (int k = 0; k < 4; ++k) {
            assert_status(cw_solver_get_field(s, bad_field[k], buf, n), CW_ERR_UNKNOWN_OPTION);
            assert_names(cw_solver_last_error(s), "field");
            assert_true(cw_poisoned(buf, sizeof buf));
        }
        /* Work fields and the profile need a FULL solve. */
        const int work_fields[] = {CW_FIELD_SX, CW_FIELD_SY, CW_FIELD_WORK_PAPER,
                                   CW_FIELD_WORK_CONSISTENT};
        for (int k = 0; k < 4; ++k)
            assert_status(cw_solver_get_field(s, work_fields[k], buf, n), CW_ERR_NO_WORK);
        assert_status(cw_solver_get_profile(s, buf, buf, buf, ny), CW_ERR_NO_WORK);
        assert_true(cw_poisoned(buf, sizeof buf));
        /* Too short is an error, never truncation; the buffer is untouched. */
        const int force_fields[] = {CW_FIELD_X,  CW_FIELD_Y,  CW_FIELD_AREA, CW_FIELD_PZ,
                                    CW_FIELD_PX, CW_FIELD_PY, CW_FIELD_MZ};
        for (int k = 0; k < 7; ++k) {
            const int f = force_fields[k];
            assert_status(cw_solver_get_field(s, f, buf, n - 1), CW_ERR_BUFFER_TOO_SMALL);
            assert_names(cw_solver_last_error(s), "out");
            assert_status(cw_solver_get_field(s, f, buf, 0), CW_ERR_BUFFER_TOO_SMALL);
        }
        assert_status(cw_solver_get_state(s, ibuf, n - 1), CW_ERR_BUFFER_TOO_SMALL);
        assert_true(cw_poisoned(buf, sizeof buf));
        /* Exact and longer buffers work; beyond n nothing is written. */
        for (int k = 0; k < 7; ++k) {
            const int f = force_fields[k];
            cw_poison(buf, sizeof buf);
            assert_status(cw_solver_get_field(s, f, buf, sizeof buf / sizeof buf[0]), CW_OK);
            assert_true(cw_all_finite(buf, n));
            assert_true(cw_poisoned(buf + n, sizeof buf - n * sizeof buf[0]));
        }
        cw_poison(ibuf, sizeof ibuf);
        assert_status(cw_solver_get_state(s, ibuf, n), CW_OK);
        assert_true(cw_poisoned(ibuf + n, sizeof ibuf - n * sizeof ibuf[0]));

        /* FULL: every field; the profile checks its length. */
        assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
        for (int f = CW_FIELD_X; f <= CW_FIELD_WORK_CONSISTENT; ++f)
            assert_status(cw_solver_get_field(s, f, buf, n), CW_OK);
        cw_poison(buf, sizeof buf);
        assert_status(cw_solver_get_profile(s, buf, buf + 10, buf + 20, ny - 1),
                      CW_ERR_BUFFER_TOO_SMALL);
        assert_true(cw_poisoned(buf, sizeof buf));
        assert_status(cw_solver_get_profile(s, buf, NULL, buf + 20, ny), CW_OK);
        assert_true(cw_poisoned(buf + 10, 10 * sizeof buf[0]));
        cw_check_solution(s, &p, CW_SOLVE_FULL, &r);
        cw_solver_destroy(s);
    }
}

/* --------------------------------------------------------------- zeros */

static void expect_zero_solution(cw_solver* s, const cw_params* p, int zero_pressure)
{
    for (int mode = CW_SOLVE_FORCES; mode <= CW_SOLVE_FULL; ++mode) {
        cw_result r;
        cw_poison_result(&r);
        assert_status(cw_solver_solve(s, p, mode, &r), CW_OK);
        assert_true(cw_result_finite(&r));
        assert_true(r.Fx == 0.0 && r.Fy == 0.0 && r.Mz == 0.0);
        assert_true(r.W_macro == 0.0 && r.W_micro_paper == 0.0 && r.W_consistent == 0.0);
        assert_true(r.K == 0.0);
        const size_t n = cw_cells(s);
        const int zero_fields[] = {CW_FIELD_PX, CW_FIELD_PY, CW_FIELD_MZ};
        for (int k = 0; k < 3; ++k) {
            double* v = cw_field(s, zero_fields[k]);
            for (size_t e = 0; e < n; ++e) assert_true(v[e] == 0.0);
            free(v);
        }
        double* pz = cw_field(s, CW_FIELD_PZ);
        for (size_t e = 0; e < n; ++e)
            assert_true(zero_pressure ? pz[e] == 0.0 : (isfinite(pz[e]) && pz[e] >= 0.0));
        free(pz);
        if (mode == CW_SOLVE_FULL) {
            const int work_fields[] = {CW_FIELD_WORK_PAPER, CW_FIELD_WORK_CONSISTENT};
            for (int k = 0; k < 2; ++k) {
                double* v = cw_field(s, work_fields[k]);
                for (size_t e = 0; e < n; ++e) assert_true(v[e] == 0.0);
                free(v);
            }
        }
        cw_check_solution(s, p, mode, &r);
    }
}

static void test_zero_load_friction_and_creepage(void** state)
{
    (void)state;
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind) {
        cw_solver* s = cw_test_solver(kind, 9, 11, 1.3);
        for (int pressure = CW_PRESSURE_PARABOLIC; pressure <= CW_PRESSURE_ELLIPTIC; ++pressure) {
            cw_params p;
            cw_params_init(&p);
            p.pressure = pressure;
            p.xi_x = 3e-3;
            p.xi_y = -2e-3;
            p.phi = 5.0;
            p.normal_force = 0.0;
            expect_zero_solution(s, &p, 1);
            p.normal_force = 80e3;
            p.mu = 0.0;
            expect_zero_solution(s, &p, 0);
            cw_params_init(&p);
            p.pressure = pressure;
            p.xi_x = p.xi_y = p.phi = 0.0;
            expect_zero_solution(s, &p, 0);
            p.normal_force = 0.0;
            p.mu = 0.0;
            expect_zero_solution(s, &p, 1);
            p.flexibility = CW_FLEX_GIVEN;
            p.L1 = p.L2 = p.L3 = 1e-11;
            expect_zero_solution(s, &p, 1);
        }
        cw_solver_destroy(s);
    }
}

/* ---------------------------------------------------------- accumulator */

static void test_accumulator_rules(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_KALKER_STRIPS, 6, 4, 1.0);
    cw_solver* other = cw_test_solver(CW_GRID_KALKER_STRIPS, 6, 5, 1.0);
    cw_solver* uniform = cw_test_solver(CW_GRID_UNIFORM, 6, 4, 1.0);
    cw_accumulator* acc = NULL;
    assert_status(cw_accumulator_create(s, &acc), CW_OK);
    const size_t n = 24;
    double buf[32];
    cw_accumulation before, after;
    cw_accumulation_init(&before);
    cw_accumulation_init(&after);

    assert_status(cw_accumulator_add(acc, s, 1.0), CW_ERR_NO_SOLUTION);
    cw_params p;
    cw_params_init(&p);
    p.xi_x = 1e-3;
    p.phi = 1.0;
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FORCES, NULL), CW_OK);
    assert_status(cw_accumulator_add(acc, s, 1.0), CW_ERR_NO_WORK);
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
    assert_status(cw_accumulator_add(acc, s, 0.5), CW_OK);
    assert_status(cw_accumulator_add(acc, s, 0.0), CW_OK);
    assert_status(cw_accumulator_get_totals(acc, &before), CW_OK);

    const double bad_distance[] = {NAN, INFINITY, -INFINITY, -1.0, -DBL_MIN};
    for (int k = 0; k < 5; ++k) {
        assert_status(cw_accumulator_add(acc, s, bad_distance[k]), CW_ERR_INVALID_INPUT);
        assert_names(cw_accumulator_last_error(acc), "distance");
    }
    assert_status(cw_solver_solve(other, &p, CW_SOLVE_FULL, NULL), CW_OK);
    assert_status(cw_solver_solve(uniform, &p, CW_SOLVE_FULL, NULL), CW_OK);
    assert_status(cw_accumulator_add(acc, other, 1.0), CW_ERR_GRID_MISMATCH);
    assert_status(cw_accumulator_add(acc, uniform, 1.0), CW_ERR_GRID_MISMATCH);
    assert_status(cw_accumulator_get_totals(acc, &after), CW_OK);
    assert_memory_equal(&before, &after, sizeof before);

    /* A finite distance whose product overflows is an error, and the
     * accumulator keeps its previous totals: no Inf ever leaves it. */
    double field_before[24], field_after[24];
    assert_status(cw_accumulator_get_field(acc, CW_FIELD_WORK_PAPER, field_before, n), CW_OK);
    assert_status(cw_accumulator_add(acc, s, DBL_MAX), CW_ERR_NUMERIC);
    assert_names(cw_accumulator_last_error(acc), "distance");
    assert_status(cw_accumulator_get_totals(acc, &after), CW_OK);
    assert_memory_equal(&before, &after, sizeof before);
    assert_status(cw_accumulator_get_field(acc, CW_FIELD_WORK_PAPER, field_after, n), CW_OK);
    assert_memory_equal(field_before, field_after, sizeof field_before);
    /* Repeated large steps: each either adds finitely or is refused. */
    for (int k = 0; k < 8; ++k) {
        const int st = cw_accumulator_add(acc, s, 1e300);
        assert_true(st == CW_OK || st == CW_ERR_NUMERIC);
        assert_status(cw_accumulator_get_totals(acc, &after), CW_OK);
        const double t[] = {after.distance, after.W_macro, after.W_micro_paper, after.K,
                            after.W_consistent};
        assert_true(cw_all_finite(t, 5));
        for (int f = CW_FIELD_WORK_PAPER; f <= CW_FIELD_WORK_CONSISTENT; ++f) {
            assert_status(cw_accumulator_get_field(acc, f, buf, n), CW_OK);
            assert_true(cw_all_finite(buf, n));
        }
        assert_status(cw_accumulator_get_strip_work(acc, buf, 4), CW_OK);
        assert_true(cw_all_finite(buf, 4));
    }

    const int bad_field[] = {-1, CW_FIELD_PX, CW_FIELD_WORK_CONSISTENT + 1};
    for (int k = 0; k < 3; ++k) {
        assert_status(cw_accumulator_get_field(acc, bad_field[k], buf, n), CW_ERR_UNKNOWN_OPTION);
        assert_names(cw_accumulator_last_error(acc), "field");
    }
    cw_poison(buf, sizeof buf);
    assert_status(cw_accumulator_get_field(acc, CW_FIELD_WORK_PAPER, buf, n - 1),
                  CW_ERR_BUFFER_TOO_SMALL);
    assert_status(cw_accumulator_get_strip_work(acc, buf, 3), CW_ERR_BUFFER_TOO_SMALL);
    assert_true(cw_poisoned(buf, sizeof buf));
    cw_accumulation bad;
    cw_accumulation_init(&bad);
    bad.struct_size = 3;
    assert_status(cw_accumulator_get_totals(acc, &bad), CW_ERR_STRUCT_SIZE);

    cw_accumulator_destroy(acc);
    cw_solver_destroy(s);
    cw_solver_destroy(other);
    cw_solver_destroy(uniform);
}

/* ---------------------------------------------------------------- batch */

static void test_batch_rules(void** state)
{
    (void)state;
    cw_grid g;
    cw_grid_init(&g);
    g.nx = 8;
    g.ny = 6;
    cw_batch* b = NULL;
    char msg[128];
    assert_status(cw_batch_create(&g, 3, &b, msg, sizeof msg), CW_OK);
    cw_solver* s = NULL;
    assert_status(cw_solver_create(&g, &s, msg, sizeof msg), CW_OK);

    enum { count = 9 };
    cw_params p[count];
    cw_result r[count];
    int statuses[count];
    for (int k = 0; k < count; ++k) {
        cw_params_init(&p[k]);
        p[k].xi_x = 1e-4 * (k + 1);
        p[k].phi = 0.3 * k;
        cw_poison_result(&r[k]);
    }
    p[3].a = kNaN;
    p[6].mu = -1.0;
    p[7].pressure = 5;
    assert_status(cw_batch_solve(b, count, p, CW_SOLVE_FULL, r, statuses), CW_ERR_INVALID_INPUT);
    assert_names(cw_batch_last_error(b), "params");
    assert_non_null(strstr(cw_batch_last_error(b), "params[3]"));
    assert_names(cw_batch_last_error(b), "a");
    for (int k = 0; k < count; ++k) {
        if (k == 3 || k == 6 || k == 7) {
            assert_true(cw_result_poisoned(&r[k]));
            assert_int_equal(statuses[k], k == 7 ? CW_ERR_UNKNOWN_OPTION : CW_ERR_INVALID_INPUT);
        } else {
            assert_int_equal(statuses[k], CW_OK);
            cw_result single;
            cw_result_init(&single);
            assert_status(cw_solver_solve(s, &p[k], CW_SOLVE_FULL, &single), CW_OK);
            assert_memory_equal(&single, &r[k], sizeof single);
        }
    }

    /* Unknown mode; struct sizes that differ or are garbage. */
    assert_status(cw_batch_solve(b, count, p, 9, r, NULL), CW_ERR_UNKNOWN_OPTION);
    assert_names(cw_batch_last_error(b), "mode");
    cw_params_init(&p[3]);
    p[5].struct_size = sizeof p[5] - 8;
    assert_status(cw_batch_solve(b, count, p, CW_SOLVE_FULL, r, NULL), CW_ERR_STRUCT_SIZE);
    assert_non_null(strstr(cw_batch_last_error(b), "[5]"));
    p[5].struct_size = sizeof p[5];
    p[0].struct_size = 0;
    assert_status(cw_batch_solve(b, count, p, CW_SOLVE_FULL, r, NULL), CW_ERR_STRUCT_SIZE);
    p[0].struct_size = sizeof p[0];
    r[0].struct_size = 1;
    assert_status(cw_batch_solve(b, count, p, CW_SOLVE_FULL, r, NULL), CW_ERR_STRUCT_SIZE);
    r[0].struct_size = sizeof r[0];

    /* After errors the batch works, and NULL statuses are allowed. */
    p[6].mu = 0.3;
    p[7].pressure = CW_PRESSURE_ELLIPTIC;
    assert_status(cw_batch_solve(b, count, p, CW_SOLVE_FULL, r, NULL), CW_OK);
    assert_string_equal(cw_batch_last_error(b), "");

    cw_batch_destroy(b);
    cw_solver_destroy(s);
}

/* -------------------------------------------------------- free functions */

static void test_free_functions(void** state)
{
    (void)state;
    char msg[160];
    double c[4], out[4];

    /* Kalker's coefficients: a/b in [1e-3, 1e3], nu in [0, 0.5]. */
    const double bad_ratio[] = {NAN, INFINITY, 0.0, -1.0, nextafter(1e-3, 0), 1.0001e3};
    for (int k = 0; k < 6; ++k) {
        cw_poison(c, sizeof c);
        assert_status(cw_kalker_coefficients(bad_ratio[k], 0.28, c, msg, sizeof msg),
                      CW_ERR_INVALID_INPUT);
        assert_names(msg, "a_over_b");
        assert_true(cw_poisoned(c, sizeof c));
    }
    const double bad_nu[] = {NAN, -INFINITY, -0.01, 0.51};
    for (int k = 0; k < 4; ++k) {
        assert_status(cw_kalker_coefficients(1.0, bad_nu[k], c, msg, sizeof msg),
                      CW_ERR_INVALID_INPUT);
        assert_names(msg, "nu");
    }
    const double ratios[] = {1e-3, 0.0999, 0.1, 1.0, 10.0, 10.01, 1e3};
    for (int k = 0; k < 7; ++k)
        for (double nu = 0.0; nu <= 0.5; nu += 0.125) {
            assert_status(cw_kalker_coefficients(ratios[k], nu, c, msg, sizeof msg), CW_OK);
            assert_string_equal(msg, "");
            for (int i = 0; i < 4; ++i) assert_true(isfinite(c[i]) && c[i] > 0.0);
        }

    /* Flexibilities: a, b > 0, a/b in range, G > 0, nu in [0, 0.5]. */
    struct {
        double a, b, G, nu;
        const char* name;
    } flex[] = {
        {NAN, 1, 1, 0.3, "a"},  {0, 1, 1, 0.3, "a"},     {1, -1, 1, 0.3, "b"},
        {1, INFINITY, 1, 0.3, "b"}, {1, 1, 0, 0.3, "G"}, {1, 1, NAN, 0.3, "G"},
        {1, 1, 1, 0.6, "nu"},   {1, 1, 1, NAN, "nu"},    {1e-4, 1, 1, 0.3, "a/b"},
        {1, 1e-4, 1, 0.3, "a/b"},
    };
    for (size_t k = 0; k < sizeof flex / sizeof flex[0]; ++k) {
        cw_poison(out, sizeof out);
        assert_status(cw_kalker_flexibilities(flex[k].a, flex[k].b, flex[k].G, flex[k].nu, out,
                                              msg, sizeof msg),
                      CW_ERR_INVALID_INPUT);
        assert_names(msg, flex[k].name);
        assert_true(cw_poisoned(out, sizeof out));
    }
    assert_status(cw_kalker_flexibilities(1e200, 1e200, 1e-200, 0.3, out, msg, sizeof msg),
                  CW_ERR_INVALID_INPUT); /* L = 8a/(3 C G) overflows */
    assert_names(msg, "G");

    /* Hertz: A, B, E* > 0, N >= 0, all finite. */
    struct {
        double A, B, N, E;
        const char* name;
    } hz[] = {
        {NAN, 1, 1, 1, "A"},         {0, 1, 1, 1, "A"},  {-1, 1, 1, 1, "A"},
        {1, INFINITY, 1, 1, "B"},    {1, 0, 1, 1, "B"},  {1, 1, -1, 1, "normal_force"},
        {1, 1, NAN, 1, "normal_force"}, {1, 1, 1, 0, "E_star"}, {1, 1, 1, -INFINITY, "E_star"},
        {1, 1e-13, 1, 1, "A/B"},
    };
    for (size_t k = 0; k < sizeof hz / sizeof hz[0]; ++k) {
        cw_poison(out, sizeof out);
        assert_status(cw_hertz_solve(hz[k].A, hz[k].B, hz[k].N, hz[k].E, out, msg, sizeof msg),
                      CW_ERR_INVALID_INPUT);
        assert_names(msg, hz[k].name);
        assert_true(cw_poisoned(out, sizeof out));
    }
    assert_status(cw_hertz_solve(2.0, 5.0, 0.0, 1e11, out, msg, sizeof msg), CW_OK);
    for (int i = 0; i < 4; ++i) assert_true(out[i] == 0.0);
    assert_status(cw_hertz_solve(1e-300, 1e-300, 1e300, 1e-300, out, msg, sizeof msg),
                  CW_ERR_NUMERIC);

    /* Normalised FASTSIM: finite inputs, mx and my in 1..1000, named. */
    double tx = 7.0, ty = 7.0;
    const char* names[] = {"ux", "uy", "fx", "fy", "tol"};
    for (int k = 0; k < 5; ++k) {
        double v[5] = {1.0, 0.0, 0.0, 0.0, 0.5};
        v[k] = k % 2 ? -INFINITY : NAN;
        assert_status(cw_fastsim_normalised(v[0], v[1], v[2], v[3], 10, 10, v[4], &tx, &ty, msg,
                                            sizeof msg),
                      CW_ERR_INVALID_INPUT);
        assert_names(msg, names[k]);
    }
    const int bad_cells[] = {0, -3, CW_MAX_GRID_CELLS + 1};
    for (int k = 0; k < 3; ++k) {
        assert_status(cw_fastsim_normalised(1, 0, 0, 0, bad_cells[k], 10, 1, &tx, &ty, msg,
                                            sizeof msg),
                      CW_ERR_GRID_OUT_OF_RANGE);
        assert_names(msg, "mx");
        assert_status(cw_fastsim_normalised(1, 0, 0, 0, 10, bad_cells[k], 1, &tx, &ty, msg,
                                            sizeof msg),
                      CW_ERR_GRID_OUT_OF_RANGE);
        assert_names(msg, "my");
    }
    assert_true(tx == 7.0 && ty == 7.0);
}

/* Huge normalised creepages mean full sliding: |t| is the discrete
 * sliding bound (about 1), never 0 or NaN from an overflowing square. */
static void test_normalised_huge_creepage(void** state)
{
    (void)state;
    double tx_ref = 0.0, ty_ref = 0.0;
    assert_status(cw_fastsim_normalised(1e6, 0, 0, 0, 20, 20, 1e9, &tx_ref, &ty_ref, NULL, 0),
                  CW_OK);
    assert_close(tx_ref, 1.0, 5e-3, 0.0);
    const double huge[] = {1e100, 1e160, 1e300, DBL_MAX};
    for (int k = 0; k < 4; ++k) {
        double tx = 0.0, ty = 0.0;
        assert_status(cw_fastsim_normalised(huge[k], 0, 0, 0, 20, 20, 1e9, &tx, &ty, NULL, 0),
                      CW_OK);
        assert_close(tx, tx_ref, 1e-12, 0.0);
        assert_true(ty == 0.0);
        assert_status(cw_fastsim_normalised(-huge[k], huge[k], huge[k], -huge[k], 20, 20, 0.5,
                                            &tx, &ty, NULL, 0),
                      CW_OK);
        assert_true(isfinite(tx) && isfinite(ty));
        assert_true(hypot(tx, ty) <= 1.01 && hypot(tx, ty) > 0.5);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_numeric_parameter_is_validated),
        cmocka_unit_test(test_unused_inputs_are_ignored),
        cmocka_unit_test(test_range_ends),
        cmocka_unit_test(test_overflowing_combinations),
        cmocka_unit_test(test_enumerations),
        cmocka_unit_test(test_struct_sizes),
        cmocka_unit_test(test_grid_limits),
        cmocka_unit_test(test_strip_grid_ignores_box_scale),
        cmocka_unit_test(test_message_buffers),
        cmocka_unit_test(test_null_pointers),
        cmocka_unit_test(test_status_strings),
        cmocka_unit_test(test_output_buffers),
        cmocka_unit_test(test_zero_load_friction_and_creepage),
        cmocka_unit_test(test_accumulator_rules),
        cmocka_unit_test(test_batch_rules),
        cmocka_unit_test(test_free_functions),
        cmocka_unit_test(test_normalised_huge_creepage),
    };
    return cmocka_run_group_tests_name("robustness_validation", tests, NULL, NULL);
}
