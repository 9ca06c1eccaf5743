/* Error paths of the solver handle: every status cw_solver_create,
 * cw_solver_solve and the getters document is provoked; each must name the
 * offending input, write nothing, and leave the handle usable (header,
 * "Errors"). Accumulator, batch and free-function errors live in their own
 * tests. */
#include "capi_fixtures.h"

#include <stdlib.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

enum { NX = 12, NY = 9, N = NX * NY };

static cw_solver* make_solver(void)
{
    return cw_test_solver(CW_GRID_KALKER_STRIPS, NX, NY, 1.0);
}

/* The handle still works: a good solve succeeds and gives bitwise what a
 * fresh handle gives. */
static void assert_handle_usable(cw_solver* s)
{
    cw_params p;
    cw_test_case(2, &p);
    cw_result r, fresh_r;
    cw_result_init(&r);
    cw_result_init(&fresh_r);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
    assert_string_equal(cw_solver_last_error(s), ""); /* header: "" after success */
    cw_solver* fresh = make_solver();
    assert_int_equal(cw_solver_solve(fresh, &p, CW_SOLVE_FULL, &fresh_r), CW_OK);
    assert_memory_equal(&r, &fresh_r, sizeof r);
    cw_solver_destroy(fresh);
}

/* Header, cw_solver_solve: "After an error the handle holds no solution". */
static void assert_no_solution(const cw_solver* s)
{
    double out[N];
    cw_fill(out, N, CW_SENTINEL);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PX, out, N), CW_ERR_NO_SOLUTION);
    assert_untouched(out, N);
}

/* ------------------------------------------------------------------ create */

typedef struct {
    int kind, nx, ny;
    double box_scale;
    int status;
    const char* names;
} bad_grid;

static void create_rejects_bad_grids(void** state)
{
    (void)state;
    const double nan = strtod("nan", NULL);
    const bad_grid bad[] = {
        {3, 20, 20, 1.0, CW_ERR_UNKNOWN_OPTION, "grid->kind"},
        {-1, 20, 20, 1.0, CW_ERR_UNKNOWN_OPTION, "grid->kind"},
        {CW_GRID_KALKER_STRIPS, 0, 20, 1.0, CW_ERR_GRID_OUT_OF_RANGE, "nx"},
        {CW_GRID_KALKER_STRIPS, 20, 0, 1.0, CW_ERR_GRID_OUT_OF_RANGE, "ny"},
        {CW_GRID_KALKER_STRIPS, CW_MAX_GRID_CELLS + 1, 20, 1.0, CW_ERR_GRID_OUT_OF_RANGE, "nx"},
        {CW_GRID_UNIFORM, 20, CW_MAX_GRID_CELLS + 1, 1.0, CW_ERR_GRID_OUT_OF_RANGE, "ny"},
        {CW_GRID_UNIFORM, 20, -5, 1.0, CW_ERR_GRID_OUT_OF_RANGE, "ny"},
        {CW_GRID_UNIFORM, 20, 20, 0.999, CW_ERR_GRID_OUT_OF_RANGE, "box_scale"},
        {CW_GRID_UNIFORM, 20, 20, CW_MAX_BOX_SCALE * 1.001, CW_ERR_GRID_OUT_OF_RANGE,
         "box_scale"},
        {CW_GRID_UNIFORM, 20, 20, nan, CW_ERR_GRID_OUT_OF_RANGE, "box_scale"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        cw_grid g;
        cw_grid_init(&g);
        g.kind = bad[k].kind;
        g.nx = bad[k].nx;
        g.ny = bad[k].ny;
        g.box_scale = bad[k].box_scale;
        cw_solver* s = (cw_solver*)&g; /* not NULL: must be reset */
        char message[256];
        memset(message, 'x', sizeof message);
        assert_int_equal(cw_solver_create(&g, &s, message, sizeof message), bad[k].status);
        assert_null(s); /* header: on error *solver is set to NULL */
        assert_names(message, bad[k].names);
    }
}

static void create_null_pointers_and_struct_size(void** state)
{
    (void)state;
    cw_grid g;
    cw_grid_init(&g);
    cw_solver* s = (cw_solver*)&g;
    char message[256];
    assert_int_equal(cw_solver_create(NULL, &s, message, sizeof message), CW_ERR_NULL_POINTER);
    assert_null(s);
    assert_names(message, "grid");
    assert_int_equal(cw_solver_create(&g, NULL, message, sizeof message), CW_ERR_NULL_POINTER);
    assert_names(message, "solver");

    /* struct_size not set (0), too small to hold itself, or garbage. */
    const size_t sizes[] = {0, sizeof(size_t) - 1, (size_t)-1};
    for (size_t k = 0; k < 3; ++k) {
        g.struct_size = sizes[k];
        s = (cw_solver*)&g;
        assert_int_equal(cw_solver_create(&g, &s, message, sizeof message), CW_ERR_STRUCT_SIZE);
        assert_null(s);
        assert_names(message, "struct_size");
    }
}

/* message is NUL-terminated and truncated to message_len bytes; NULL or
 * length 0 are accepted and nothing is written. */
static void create_message_buffer_rules(void** state)
{
    (void)state;
    cw_grid g;
    cw_grid_init(&g);
    g.nx = 0;
    cw_solver* s = NULL;
    char full[256], small[8];
    assert_int_equal(cw_solver_create(&g, &s, full, sizeof full), CW_ERR_GRID_OUT_OF_RANGE);
    assert_true(strlen(full) > sizeof small);
    memset(small, 'x', sizeof small);
    assert_int_equal(cw_solver_create(&g, &s, small, sizeof small), CW_ERR_GRID_OUT_OF_RANGE);
    assert_int_equal(small[sizeof small - 1], '\0');
    assert_memory_equal(small, full, sizeof small - 1);
    memset(small, 'x', sizeof small);
    assert_int_equal(cw_solver_create(&g, &s, small, 0), CW_ERR_GRID_OUT_OF_RANGE);
    for (size_t k = 0; k < sizeof small; ++k) assert_int_equal(small[k], 'x');
    assert_int_equal(cw_solver_create(&g, &s, NULL, 100), CW_ERR_GRID_OUT_OF_RANGE);
    /* After success the message is emptied. */
    g.nx = 4;
    assert_int_equal(cw_solver_create(&g, &s, full, sizeof full), CW_OK);
    assert_string_equal(full, "");
    cw_solver_destroy(s);
}

/* ------------------------------------------------------------------- solve */

typedef void (*spoil_fn)(cw_params*);

typedef struct {
    const char* what;
    spoil_fn spoil;
    int status;
    const char* names;
} bad_params;

#define SPOIL(name, body) \
    static void spoil_##name(cw_params* p) { body; }

static double inf(void) { return strtod("inf", NULL); }
static double nan_(void) { return strtod("nan", NULL); }

SPOIL(a_zero, p->a = 0.0)
SPOIL(a_negative, p->a = -1e-3)
SPOIL(a_nan, p->a = nan_())
SPOIL(a_inf, p->a = inf())
SPOIL(b_zero, p->b = 0.0)
SPOIL(b_nan, p->b = nan_())
SPOIL(aspect_low, p->a = p->b * CW_MIN_ASPECT * 0.99)
SPOIL(aspect_high, p->a = p->b * CW_MAX_ASPECT * 1.01)
SPOIL(load_negative, p->normal_force = -1.0)
SPOIL(load_nan, p->normal_force = nan_())
SPOIL(load_inf, p->normal_force = inf())
SPOIL(mu_negative, p->mu = -0.1)
SPOIL(mu_nan, p->mu = nan_())
SPOIL(V_negative, p->V = -30.0)
SPOIL(V_nan, p->V = nan_())
SPOIL(V_inf, p->V = inf())
SPOIL(G_zero, p->G = 0.0)
SPOIL(G_negative, p->G = -82e9)
SPOIL(G_inf, p->G = inf())
SPOIL(nu_negative, p->nu = -0.01)
SPOIL(nu_high, p->nu = 0.5000001)
SPOIL(nu_nan, p->nu = nan_())
SPOIL(L1_zero, p->flexibility = CW_FLEX_GIVEN; p->L1 = 0.0; p->L2 = p->L3 = 5e-14)
SPOIL(L2_negative, p->flexibility = CW_FLEX_GIVEN; p->L1 = p->L3 = 5e-14; p->L2 = -5e-14)
SPOIL(L3_nan, p->flexibility = CW_FLEX_GIVEN; p->L1 = p->L2 = 5e-14; p->L3 = nan_())
SPOIL(xi_x_nan, p->xi_x = nan_())
SPOIL(xi_y_inf, p->xi_y = -inf())
SPOIL(phi_nan, p->phi = nan_())
SPOIL(direction_zero, p->rolling_direction = 0)
SPOIL(direction_two, p->rolling_direction = 2)
SPOIL(flexibility_unknown, p->flexibility = 2)
SPOIL(pressure_unknown, p->pressure = -1)
SPOIL(struct_size_zero, p->struct_size = 0)
SPOIL(struct_size_garbage, p->struct_size = (size_t)-1)
/* Finite inputs whose work overflows: the forces (~mu N = 1e19 N) and the
 * normalised creepage are finite, W_macro ~ mu N xi_x = 1e309 is not. */
SPOIL(overflow, p->normal_force = 1e19; p->mu = 1.0; p->xi_x = 1e290)

static const bad_params bad_solves[] = {
    {"a = 0", spoil_a_zero, CW_ERR_INVALID_INPUT, "a = "},
    {"a < 0", spoil_a_negative, CW_ERR_INVALID_INPUT, "a = "},
    {"a NaN", spoil_a_nan, CW_ERR_INVALID_INPUT, "a = "},
    {"a Inf", spoil_a_inf, CW_ERR_INVALID_INPUT, "a = "},
    {"b = 0", spoil_b_zero, CW_ERR_INVALID_INPUT, "b = "},
    {"b NaN", spoil_b_nan, CW_ERR_INVALID_INPUT, "b = "},
    {"a/b < 1e-3", spoil_aspect_low, CW_ERR_INVALID_INPUT, "a/b"},
    {"a/b > 1e3", spoil_aspect_high, CW_ERR_INVALID_INPUT, "a/b"},
    {"N < 0", spoil_load_negative, CW_ERR_INVALID_INPUT, "normal_force"},
    {"N NaN", spoil_load_nan, CW_ERR_INVALID_INPUT, "normal_force"},
    {"N Inf", spoil_load_inf, CW_ERR_INVALID_INPUT, "normal_force"},
    {"mu < 0", spoil_mu_negative, CW_ERR_INVALID_INPUT, "mu"},
    {"mu NaN", spoil_mu_nan, CW_ERR_INVALID_INPUT, "mu"},
    {"V < 0", spoil_V_negative, CW_ERR_INVALID_INPUT, "V = "},
    {"V NaN", spoil_V_nan, CW_ERR_INVALID_INPUT, "V = "},
    {"V Inf", spoil_V_inf, CW_ERR_INVALID_INPUT, "V = "},
    {"G = 0", spoil_G_zero, CW_ERR_INVALID_INPUT, "G = "},
    {"G < 0", spoil_G_negative, CW_ERR_INVALID_INPUT, "G = "},
    {"G Inf", spoil_G_inf, CW_ERR_INVALID_INPUT, "G = "},
    {"nu < 0", spoil_nu_negative, CW_ERR_INVALID_INPUT, "nu = "},
    {"nu > 0.5", spoil_nu_high, CW_ERR_INVALID_INPUT, "nu = "},
    {"nu NaN", spoil_nu_nan, CW_ERR_INVALID_INPUT, "nu = "},
    {"L1 = 0", spoil_L1_zero, CW_ERR_INVALID_INPUT, "L1"},
    {"L2 < 0", spoil_L2_negative, CW_ERR_INVALID_INPUT, "L2"},
    {"L3 NaN", spoil_L3_nan, CW_ERR_INVALID_INPUT, "L3"},
    {"xi_x NaN", spoil_xi_x_nan, CW_ERR_INVALID_INPUT, "xi_x"},
    {"xi_y -Inf", spoil_xi_y_inf, CW_ERR_INVALID_INPUT, "xi_y"},
    {"phi NaN", spoil_phi_nan, CW_ERR_INVALID_INPUT, "phi"},
    {"direction 0", spoil_direction_zero, CW_ERR_INVALID_INPUT, "rolling_direction"},
    {"direction 2", spoil_direction_two, CW_ERR_INVALID_INPUT, "rolling_direction"},
    {"flexibility", spoil_flexibility_unknown, CW_ERR_UNKNOWN_OPTION, "flexibility"},
    {"pressure", spoil_pressure_unknown, CW_ERR_UNKNOWN_OPTION, "pressure"},
    {"struct_size 0", spoil_struct_size_zero, CW_ERR_STRUCT_SIZE, "params->struct_size"},
    {"struct_size -1", spoil_struct_size_garbage, CW_ERR_STRUCT_SIZE, "params->struct_size"},
    {"overflow", spoil_overflow, CW_ERR_NUMERIC, "overflowed"},
};

/* Each bad input, after a good solve (so there is something to lose): the
 * status, a message naming the input, the result untouched, no solution
 * left on the handle, and the handle usable. Both modes. */
static void solve_rejects_bad_params(void** state)
{
    (void)state;
    cw_solver* s = make_solver();
    for (int mode = CW_SOLVE_FORCES; mode <= CW_SOLVE_FULL; ++mode)
        for (size_t k = 0; k < sizeof bad_solves / sizeof bad_solves[0]; ++k) {
            cw_params good, p;
            cw_test_case(0, &good);
            assert_int_equal(cw_solver_solve(s, &good, CW_SOLVE_FULL, NULL), CW_OK);
            p = good;
            bad_solves[k].spoil(&p);
            cw_result r;
            cw_poison_result(&r);
            const cw_result before = r;
            const int status = cw_solver_solve(s, &p, mode, &r);
            if (status != bad_solves[k].status)
                fail_msg("%s: status %d, expected %d", bad_solves[k].what, status,
                         bad_solves[k].status);
            assert_names(cw_solver_last_error(s), bad_solves[k].names);
            assert_memory_equal(&r, &before, sizeof r);
            assert_no_solution(s);
            assert_handle_usable(s);
        }
    cw_solver_destroy(s);
}

/* The other arguments of solve: NULL solver / params, unknown mode, and a
 * result whose struct_size was never set. */
static int solve_null_params(cw_solver* s, cw_params* p, cw_result* r)
{
    (void)p;
    return cw_solver_solve(s, NULL, CW_SOLVE_FULL, r);
}
static int solve_mode_2(cw_solver* s, cw_params* p, cw_result* r)
{
    return cw_solver_solve(s, p, 2, r);
}
static int solve_mode_negative(cw_solver* s, cw_params* p, cw_result* r)
{
    return cw_solver_solve(s, p, -1, r);
}
static int solve_result_size_zero(cw_solver* s, cw_params* p, cw_result* r)
{
    r->struct_size = 0;
    return cw_solver_solve(s, p, CW_SOLVE_FULL, r);
}
static int solve_result_size_tiny(cw_solver* s, cw_params* p, cw_result* r)
{
    r->struct_size = 3;
    return cw_solver_solve(s, p, CW_SOLVE_FULL, r);
}

static void solve_rejects_bad_arguments(void** state)
{
    (void)state;
    const struct {
        int (*call)(cw_solver*, cw_params*, cw_result*);
        int status;
        const char* names;
    } bad[] = {
        {solve_null_params, CW_ERR_NULL_POINTER, "params"},
        {solve_mode_2, CW_ERR_UNKNOWN_OPTION, "mode"},
        {solve_mode_negative, CW_ERR_UNKNOWN_OPTION, "mode"},
        {solve_result_size_zero, CW_ERR_STRUCT_SIZE, "result->struct_size"},
        {solve_result_size_tiny, CW_ERR_STRUCT_SIZE, "result->struct_size"},
    };
    cw_solver* s = make_solver();
    cw_params p;
    cw_test_case(0, &p);
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_solve(NULL, &p, CW_SOLVE_FULL, &r), CW_ERR_NULL_POINTER);
    assert_non_null(cw_solver_last_error(NULL)); /* static message for a NULL handle */
    assert_names(cw_solver_last_error(NULL), "NULL");

    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
        cw_poison_result(&r);
        cw_result before = r;
        assert_int_equal(bad[k].call(s, &p, &r), bad[k].status);
        before.struct_size = r.struct_size; /* the one field the caller set */
        assert_names(cw_solver_last_error(s), bad[k].names);
        assert_memory_equal(&r, &before, sizeof r);
        assert_no_solution(s);
        assert_handle_usable(s);
    }
    cw_solver_destroy(s);
}

/* ----------------------------------------------------------------- getters */

static void grid_size_errors(void** state)
{
    (void)state;
    cw_solver* s = make_solver();
    int nx = CW_INT_SENTINEL, ny = CW_INT_SENTINEL;
    assert_int_equal(cw_solver_grid_size(NULL, &nx, &ny), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_solver_grid_size(s, NULL, &ny), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_solver_grid_size(s, &nx, NULL), CW_ERR_NULL_POINTER);
    assert_int_equal(nx, CW_INT_SENTINEL);
    assert_int_equal(ny, CW_INT_SENTINEL);
    assert_int_equal(cw_solver_grid_size(s, &nx, &ny), CW_OK);
    assert_int_equal(nx, NX);
    assert_int_equal(ny, NY);
    cw_solver_destroy(s);
}

static void get_result_errors(void** state)
{
    (void)state;
    cw_solver* s = make_solver();
    cw_result r, before;
    cw_poison_result(&r);
    before = r;
    assert_int_equal(cw_solver_get_result(NULL, &r), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_solver_get_result(s, &r), CW_ERR_NO_SOLUTION); /* fresh handle */
    assert_names(cw_solver_last_error(s), "solve");
    assert_memory_equal(&r, &before, sizeof r);
    assert_handle_usable(s);
    assert_int_equal(cw_solver_get_result(s, NULL), CW_ERR_NULL_POINTER);
    assert_names(cw_solver_last_error(s), "result");
    r.struct_size = 0;
    before = r;
    assert_int_equal(cw_solver_get_result(s, &r), CW_ERR_STRUCT_SIZE);
    assert_names(cw_solver_last_error(s), "struct_size");
    assert_memory_equal(&r, &before, sizeof r);
    /* A getter's failure does not lose the solution. */
    cw_result_init(&r);
    assert_int_equal(cw_solver_get_result(s, &r), CW_OK);
    assert_string_equal(cw_solver_last_error(s), "");
    cw_solver_destroy(s);
}

static void get_field_errors(void** state)
{
    (void)state;
    cw_solver* s = make_solver();
    double out[N + 1];
    cw_fill(out, N + 1, CW_SENTINEL);
    assert_int_equal(cw_solver_get_field(NULL, CW_FIELD_PX, out, N), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PX, out, N), CW_ERR_NO_SOLUTION);
    assert_names(cw_solver_last_error(s), "solve");

    cw_params p;
    cw_test_case(0, &p);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FORCES, NULL), CW_OK);
    const int full_only[] = {CW_FIELD_SX, CW_FIELD_SY, CW_FIELD_WORK_PAPER,
                             CW_FIELD_WORK_CONSISTENT};
    for (int k = 0; k < 4; ++k) {
        assert_int_equal(cw_solver_get_field(s, full_only[k], out, N), CW_ERR_NO_WORK);
        assert_names(cw_solver_last_error(s), "CW_SOLVE_FULL");
    }
    const int unknown[] = {-1, CW_FIELD_WORK_CONSISTENT + 1, 1000};
    for (int k = 0; k < 3; ++k) {
        assert_int_equal(cw_solver_get_field(s, unknown[k], out, N), CW_ERR_UNKNOWN_OPTION);
        assert_names(cw_solver_last_error(s), "field");
    }
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PX, out, N - 1), CW_ERR_BUFFER_TOO_SMALL);
    assert_names(cw_solver_last_error(s), "out");
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PX, out, 0), CW_ERR_BUFFER_TOO_SMALL);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PX, NULL, N), CW_ERR_NULL_POINTER);
    assert_names(cw_solver_last_error(s), "out");
    assert_untouched(out, N + 1);
    /* Still solved: the getters' errors do not discard the solution. */
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PX, out, N), CW_OK);
    assert_untouched(out + N, 1);
    assert_handle_usable(s);
    cw_solver_destroy(s);
}

static void get_state_errors(void** state)
{
    (void)state;
    cw_solver* s = make_solver();
    int out[N];
    cw_fill_int(out, N, CW_INT_SENTINEL);
    assert_int_equal(cw_solver_get_state(NULL, out, N), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_solver_get_state(s, out, N), CW_ERR_NO_SOLUTION);
    assert_names(cw_solver_last_error(s), "solve");
    cw_params p;
    cw_test_case(0, &p);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FORCES, NULL), CW_OK);
    assert_int_equal(cw_solver_get_state(s, out, N - 1), CW_ERR_BUFFER_TOO_SMALL);
    assert_names(cw_solver_last_error(s), "out");
    assert_int_equal(cw_solver_get_state(s, NULL, N), CW_ERR_NULL_POINTER);
    assert_names(cw_solver_last_error(s), "out");
    assert_untouched_int(out, N);
    /* States need no work map: fine after a FORCES solve. */
    assert_int_equal(cw_solver_get_state(s, out, N), CW_OK);
    assert_handle_usable(s);
    cw_solver_destroy(s);
}

static void get_profile_errors(void** state)
{
    (void)state;
    cw_solver* s = make_solver();
    double y[NY], w[NY], par[NY];
    cw_fill(y, NY, CW_SENTINEL);
    cw_fill(w, NY, CW_SENTINEL);
    cw_fill(par, NY, CW_SENTINEL);
    assert_int_equal(cw_solver_get_profile(NULL, y, w, par, NY), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_solver_get_profile(s, y, w, par, NY), CW_ERR_NO_SOLUTION);
    assert_names(cw_solver_last_error(s), "solve");
    cw_params p;
    cw_test_case(0, &p);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FORCES, NULL), CW_OK);
    assert_int_equal(cw_solver_get_profile(s, y, w, par, NY), CW_ERR_NO_WORK);
    assert_names(cw_solver_last_error(s), "CW_SOLVE_FULL");
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
    assert_int_equal(cw_solver_get_profile(s, y, w, par, NY - 1), CW_ERR_BUFFER_TOO_SMALL);
    assert_names(cw_solver_last_error(s), "profile");
    assert_untouched(y, NY);
    assert_untouched(w, NY);
    assert_untouched(par, NY);
    assert_int_equal(cw_solver_get_profile(s, y, w, par, NY), CW_OK);
    assert_handle_usable(s);
    cw_solver_destroy(s);
}

/* ----------------------------------------------------------- out of memory */

/* CW_ERR_OUT_OF_MEMORY cannot be provoked portably; on Linux a child process
 * under an address-space limit makes the allocations of the largest grid
 * fail (1000 x 1000 elements need ~100 MB of workspace, an accumulator on it
 * 16 MB). Sanitizers reserve huge shadow mappings and cannot run under such
 * a limit, so they skip. */
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define CW_UNDER_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define CW_UNDER_SANITIZER 1
#endif
#endif

#ifndef CW_UNDER_SANITIZER
/* Limits the address space to what is mapped now plus headroom bytes. */
static int limit_address_space(size_t headroom)
{
    FILE* statm = fopen("/proc/self/statm", "r");
    unsigned long pages = 0;
    if (!statm) return -1;
    const int read = fscanf(statm, "%lu", &pages);
    fclose(statm);
    if (read != 1) return -1;
    const rlim_t limit = (rlim_t)pages * (rlim_t)sysconf(_SC_PAGESIZE) + (rlim_t)headroom;
    const struct rlimit rl = {limit, limit};
    return setrlimit(RLIMIT_AS, &rl);
}

/* The child cannot use cmocka's asserts: it reports and exits non-zero. */
#define CHILD_EXPECT(c)                                                       \
    do {                                                                      \
        if (!(c)) {                                                           \
            fprintf(stderr, "%s:%d: child expected %s\n", __FILE__, __LINE__, #c); \
            return 1;                                                         \
        }                                                                     \
    } while (0)

static int oom_child(void)
{
    cw_grid g;
    cw_grid_init(&g);
    g.nx = CW_MAX_GRID_CELLS;
    g.ny = CW_MAX_GRID_CELLS;
    cw_solver* big = NULL;
    CHILD_EXPECT(cw_solver_create(&g, &big, NULL, 0) == CW_OK);
    CHILD_EXPECT(limit_address_space(4u << 20) == 0);

    char message[256];
    cw_solver* s = (cw_solver*)&g;
    CHILD_EXPECT(cw_solver_create(&g, &s, message, sizeof message) == CW_ERR_OUT_OF_MEMORY);
    CHILD_EXPECT(s == NULL);
    CHILD_EXPECT(strcmp(message, cw_status_string(CW_ERR_OUT_OF_MEMORY)) == 0);

    cw_batch* b = (cw_batch*)&g;
    CHILD_EXPECT(cw_batch_create(&g, 2, &b, message, sizeof message) == CW_ERR_OUT_OF_MEMORY);
    CHILD_EXPECT(b == NULL);

    cw_accumulator* acc = (cw_accumulator*)&g;
    CHILD_EXPECT(cw_accumulator_create(big, &acc) == CW_ERR_OUT_OF_MEMORY);
    CHILD_EXPECT(acc == NULL);

    /* Header: create allocates everything, solve nothing -- so the largest
     * solver still solves under the limit, and its fields can be read. */
    cw_params p;
    cw_test_case(2, &p);
    cw_result r;
    cw_result_init(&r);
    CHILD_EXPECT(cw_solver_solve(big, &p, CW_SOLVE_FULL, &r) == CW_OK);
    CHILD_EXPECT(r.n_contact == CW_MAX_GRID_CELLS * CW_MAX_GRID_CELLS);
    double w[CW_MAX_GRID_CELLS];
    CHILD_EXPECT(cw_solver_get_profile(big, NULL, w, NULL, CW_MAX_GRID_CELLS) == CW_OK);
    cw_solver_destroy(big);
    return 0;
}
#endif

static void out_of_memory_is_reported(void** state)
{
    (void)state;
#ifdef CW_UNDER_SANITIZER
    cw_skip(); /* the sanitizer runtime owns the allocator */
#else
    fflush(NULL);
    const pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) _exit(oom_child());
    int wstatus = 0;
    assert_int_equal(waitpid(pid, &wstatus, 0), pid);
    assert_true(WIFEXITED(wstatus));
    assert_int_equal(WEXITSTATUS(wstatus), 0);
#endif
}

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(create_rejects_bad_grids),
        cmocka_unit_test(create_null_pointers_and_struct_size),
        cmocka_unit_test(create_message_buffer_rules),
        cmocka_unit_test(solve_rejects_bad_params),
        cmocka_unit_test(solve_rejects_bad_arguments),
        cmocka_unit_test(grid_size_errors),
        cmocka_unit_test(get_result_errors),
        cmocka_unit_test(get_field_errors),
        cmocka_unit_test(get_state_errors),
        cmocka_unit_test(get_profile_errors),
        cmocka_unit_test(out_of_memory_is_reported),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : NULL);
}
