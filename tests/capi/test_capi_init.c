/* The _init functions: documented defaults and struct_size, whatever the
 * struct held before (hosts often pass uninitialised stack memory). */
#include "capi_fixtures.h"

/* Garbage, so a default that is silently left unset shows up. */
#define GARBAGE 0xA5

static void grid_init_sets_documented_defaults(void** state)
{
    (void)state;
    cw_grid g;
    memset(&g, GARBAGE, sizeof g);
    assert_int_equal(cw_grid_init(&g), CW_OK);
    /* Header, cw_grid: Kalker strips, 20 x 20, box scale 1. */
    assert_int_equal(g.struct_size, sizeof(cw_grid));
    assert_int_equal(g.kind, CW_GRID_KALKER_STRIPS);
    assert_int_equal(g.nx, 20);
    assert_int_equal(g.ny, 20);
    assert_true(g.box_scale == 1.0);
}

static void params_init_sets_documented_defaults(void** state)
{
    (void)state;
    cw_params p;
    memset(&p, GARBAGE, sizeof p);
    assert_int_equal(cw_params_init(&p), CW_OK);
    /* Header, cw_params_init: steel (G = 82e9 Pa, nu = 0.28), mu = 0.3,
     * a = b = 6e-3 m, N = 80e3 N, zero creepage, parabolic pressure, rolling
     * towards +x; flexibilities from the material (cw_params comment). */
    assert_int_equal(p.struct_size, sizeof(cw_params));
    assert_true(p.a == 6e-3);
    assert_true(p.b == 6e-3);
    assert_true(p.normal_force == 80e3);
    assert_true(p.mu == 0.3);
    assert_int_equal(p.flexibility, CW_FLEX_FROM_MATERIAL);
    assert_int_equal(p.pressure, CW_PRESSURE_PARABOLIC);
    assert_true(p.G == 82e9);
    assert_true(p.nu == 0.28);
    assert_true(p.xi_x == 0.0);
    assert_true(p.xi_y == 0.0);
    assert_true(p.phi == 0.0);
    assert_int_equal(p.rolling_direction, 1);
}

/* The defaults describe a valid contact: a solve succeeds and, with zero
 * creepage, gives zero force, moment and work (Kalker: no rigid slip, no
 * traction). */
static void params_defaults_are_a_valid_contact(void** state)
{
    (void)state;
    cw_grid g;
    cw_params p;
    cw_result r;
    cw_solver* s = NULL;
    cw_grid_init(&g);
    cw_params_init(&p);
    cw_result_init(&r);
    assert_int_equal(cw_solver_create(&g, &s, NULL, 0), CW_OK);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
    assert_true(r.Fx == 0.0 && r.Fy == 0.0 && r.Mz == 0.0);
    assert_true(r.W_macro == 0.0 && r.W_consistent == 0.0);
    assert_true(r.a == p.a && r.b == p.b);
    assert_int_equal(r.n_contact, 20 * 20); /* Kalker strips: every element is in contact */
    assert_int_equal(r.n_adhesion, r.n_contact);
    assert_true(r.adhesion_fraction == 1.0);
    cw_solver_destroy(s);
}

static void result_init_zeroes_everything(void** state)
{
    (void)state;
    cw_result r, zero;
    memset(&r, GARBAGE, sizeof r);
    memset(&zero, 0, sizeof zero);
    assert_int_equal(cw_result_init(&r), CW_OK);
    assert_int_equal(r.struct_size, sizeof(cw_result));
    /* Header: "Zeroes the result and sets struct_size." */
    assert_memory_equal((const char*)&r + sizeof(size_t), (const char*)&zero + sizeof(size_t),
                        sizeof r - sizeof(size_t));
}

static void accumulation_init_zeroes_everything(void** state)
{
    (void)state;
    cw_accumulation t, zero;
    memset(&t, GARBAGE, sizeof t);
    memset(&zero, 0, sizeof zero);
    assert_int_equal(cw_accumulation_init(&t), CW_OK);
    assert_int_equal(t.struct_size, sizeof(cw_accumulation));
    assert_memory_equal((const char*)&t + sizeof(size_t), (const char*)&zero + sizeof(size_t),
                        sizeof t - sizeof(size_t));
}

/* Header: each _init documents CW_ERR_NULL_POINTER. */
static void init_null_pointer(void** state)
{
    (void)state;
    assert_int_equal(cw_grid_init(NULL), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_params_init(NULL), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_result_init(NULL), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_accumulation_init(NULL), CW_ERR_NULL_POINTER);
}

/* struct_size is the first member of every versioned struct: the library
 * reads it before knowing anything else about the caller's layout. */
static void struct_size_comes_first(void** state)
{
    (void)state;
    assert_int_equal(offsetof(cw_grid, struct_size), 0);
    assert_int_equal(offsetof(cw_params, struct_size), 0);
    assert_int_equal(offsetof(cw_result, struct_size), 0);
    assert_int_equal(offsetof(cw_accumulation, struct_size), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(grid_init_sets_documented_defaults),
        cmocka_unit_test(params_init_sets_documented_defaults),
        cmocka_unit_test(params_defaults_are_a_valid_contact),
        cmocka_unit_test(result_init_zeroes_everything),
        cmocka_unit_test(accumulation_init_zeroes_everything),
        cmocka_unit_test(init_null_pointer),
        cmocka_unit_test(struct_size_comes_first),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
