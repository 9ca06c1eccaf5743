/* ABI growth (header, "Structs"): a program built against an older, smaller
 * struct keeps working. The library reads and writes min(struct_size,
 * sizeof) bytes; fields beyond the caller's struct_size take their defaults
 * on input and are never written on output; batch arrays and the patch
 * array are strided by element 0's struct_size, and a result element
 * smaller than element 0 is refused. The "old" structs below are the
 * current ones cut before a field, exactly what an old header would have
 * declared. */
#include "capi_fixtures.h"

#include <stdlib.h>

/* cw_params before rolling_direction was appended. */
typedef struct {
    size_t struct_size;
    double a, b, normal_force, mu;
    int flexibility, pressure;
    double G, nu, L1, L2, L3, xi_x, xi_y, phi;
} params_v0;

/* cw_result before the semi-axes, flexibilities, coefficients and profile
 * measures were appended. */
typedef struct {
    size_t struct_size;
    double Fx, Fy, Mz, W_macro, W_micro_paper, K, W_consistent, balance_factor,
        adhesion_fraction;
    int n_contact, n_adhesion, n_slip, work_flags;
} result_v0;

/* Structs of a future, larger header: today's plus fields the library does
 * not know. */
typedef struct {
    cw_params p;
    double future[3];
} params_next;

typedef struct {
    cw_result r;
    double future[3];
} result_next;

static cw_solver* make_solver(int kind)
{
    return cw_test_solver(kind, 15, 12, 1.0);
}

static void copy_to_v0(const cw_params* p, params_v0* old)
{
    memcpy(old, p, sizeof *old); /* same leading layout */
    old->struct_size = sizeof *old;
}

/* The layouts really are prefixes of today's structs. */
static void old_structs_are_prefixes(void** state)
{
    (void)state;
    assert_int_equal(sizeof(params_v0), offsetof(cw_params, rolling_direction));
    assert_int_equal(offsetof(params_v0, phi), offsetof(cw_params, phi));
    assert_int_equal(sizeof(result_v0), offsetof(cw_result, a));
    assert_int_equal(offsetof(result_v0, work_flags), offsetof(cw_result, work_flags));
}

/* An old caller's params (heap object of exactly the old size, so reading
 * past it would be caught by AddressSanitizer): rolling_direction takes its
 * default +1. A case with spin and rolling -1 shows the difference. */
static void smaller_params_take_defaults(void** state)
{
    (void)state;
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind) {
        cw_solver* s = make_solver(kind);
        cw_params now;
        cw_test_case(2, &now); /* rolling_direction = -1 */
        assert_int_equal(now.rolling_direction, -1);
        cw_params forward = now;
        forward.rolling_direction = 1;

        params_v0* old = malloc(sizeof *old);
        assert_non_null(old);
        copy_to_v0(&now, old);
        cw_result r_old, r_fwd, r_back;
        cw_result_init(&r_old);
        cw_result_init(&r_fwd);
        cw_result_init(&r_back);
        assert_int_equal(cw_solver_solve(s, (const cw_params*)old, CW_SOLVE_FULL, &r_old), CW_OK);
        assert_int_equal(cw_solver_solve(s, &forward, CW_SOLVE_FULL, &r_fwd), CW_OK);
        assert_int_equal(cw_solver_solve(s, &now, CW_SOLVE_FULL, &r_back), CW_OK);
        assert_memory_equal(&r_old, &r_fwd, sizeof r_old);
        assert_false(cw_same_bits(r_old.Mz, r_back.Mz)); /* the default mattered */

        /* The same through a full-size struct whose struct_size says "old":
         * the -1 beyond struct_size is ignored. */
        cw_params cut = now;
        cut.struct_size = offsetof(cw_params, rolling_direction);
        cw_result r_cut;
        cw_result_init(&r_cut);
        assert_int_equal(cw_solver_solve(s, &cut, CW_SOLVE_FULL, &r_cut), CW_OK);
        assert_memory_equal(&r_cut, &r_fwd, sizeof r_cut);

        /* Cut before the creepages: they default to zero -> no force. */
        cut.struct_size = offsetof(cw_params, xi_x);
        assert_int_equal(cw_solver_solve(s, &cut, CW_SOLVE_FULL, &r_cut), CW_OK);
        assert_true(r_cut.Fx == 0.0 && r_cut.Fy == 0.0 && r_cut.Mz == 0.0);

        /* Only struct_size: every field is cw_params_init's default. */
        size_t* bare = malloc(sizeof *bare);
        assert_non_null(bare);
        *bare = sizeof *bare;
        cw_params defaults;
        cw_params_init(&defaults);
        cw_result r_bare, r_def;
        cw_result_init(&r_bare);
        cw_result_init(&r_def);
        assert_int_equal(cw_solver_solve(s, (const cw_params*)bare, CW_SOLVE_FULL, &r_bare),
                         CW_OK);
        assert_int_equal(cw_solver_solve(s, &defaults, CW_SOLVE_FULL, &r_def), CW_OK);
        assert_memory_equal(&r_bare, &r_def, sizeof r_bare);
        free(bare);
        free(old);
        cw_solver_destroy(s);
    }
}

/* The rolling speed V, appended last: Coulomb's law does not use it, so
 * every model gives the same bits with V = 0 (the default), V = 30 m/s, and
 * a caller's params cut before V (whatever lies beyond struct_size: here an
 * invalid -1 that a full-size read would refuse). Totals, the traction field
 * and the Jacobian compared. */
static void rolling_speed_unused_by_coulomb(void** state)
{
    (void)state;
    static double h[CW_LOBES_NX * CW_LOBES_NY];
    const cw_grid lobes = cw_test_two_lobes(h);
    const struct {
        cw_grid grid;
        int model;
    } cases[] = {
        {cw_test_grid(CW_GRID_KALKER_STRIPS, 15, 12, 1.0), CW_MODEL_FASTSIM},
        {cw_test_grid(CW_GRID_KALKER_STRIPS, 15, 12, 1.0), CW_MODEL_CALIBRATED},
        {cw_test_grid(CW_GRID_UNIFORM, 14, 12, 1.1), CW_MODEL_EXACT},
        {lobes, CW_MODEL_FASTSIM},
        {lobes, CW_MODEL_EXACT},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        cw_solver* s = NULL;
        assert_int_equal(cw_solver_create(&cases[c].grid, &s, NULL, 0), CW_OK);
        const size_t n = cw_cells(s);
        cw_params base;
        cw_test_case(2, &base);
        base.model = cases[c].model;
        base.warm_start = 0; /* cold: a fresh handle's bits every time */
        if (cases[c].grid.kind == CW_GRID_GAP) base.gap = h, base.gap_len = n;
        double* px = malloc(3 * n * sizeof *px);
        assert_non_null(px);
        cw_result r[3];
        double jac[3][CW_JACOBIAN_LEN];
        for (int k = 0; k < 3; ++k) {
            cw_params p = base;
            if (k == 1) p.V = 30.0;
            if (k == 2) p.V = -1.0, p.struct_size = offsetof(cw_params, V);
            cw_result_init(&r[k]);
            assert_int_equal(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FULL, &r[k], jac[k],
                                                      CW_JACOBIAN_LEN),
                             CW_OK);
            assert_int_equal(cw_solver_get_field(s, CW_FIELD_PX, px + k * n, n), CW_OK);
        }
        for (int k = 1; k < 3; ++k) {
            assert_memory_equal(&r[k], &r[0], sizeof r[0]);
            assert_memory_equal(jac[k], jac[0], sizeof jac[0]);
            assert_memory_equal(px + k * n, px, n * sizeof *px);
        }
        assert_true(r[0].n_slip > 0 && r[0].Fx != 0.0); /* a solve with slip to tell */
        free(px);
        cw_solver_destroy(s);
    }
}

/* A future caller's larger params: the unknown tail is ignored. */
static void larger_params_are_read_up_to_today(void** state)
{
    (void)state;
    cw_solver* s = make_solver(CW_GRID_UNIFORM);
    params_next next;
    memset(&next, CW_POISON, sizeof next);
    cw_test_case(3, &next.p);
    next.p.struct_size = sizeof next;
    cw_params today;
    cw_test_case(3, &today);
    cw_result r_next, r_today;
    cw_result_init(&r_next);
    cw_result_init(&r_today);
    assert_int_equal(cw_solver_solve(s, &next.p, CW_SOLVE_FULL, &r_next), CW_OK);
    assert_int_equal(cw_solver_solve(s, &today, CW_SOLVE_FULL, &r_today), CW_OK);
    assert_memory_equal(&r_next, &r_today, sizeof r_next);
    cw_solver_destroy(s);
}

/* An old caller's result (heap object of exactly the old size): the known
 * prefix is written, its struct_size kept, and nothing beyond. Through
 * solve and get_result. */
static void smaller_result_is_written_up_to_its_size(void** state)
{
    (void)state;
    cw_solver* s = make_solver(CW_GRID_KALKER_STRIPS);
    cw_params p;
    cw_test_case(1, &p);
    cw_result full;
    cw_result_init(&full);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &full), CW_OK);

    result_v0* old = malloc(sizeof *old);
    assert_non_null(old);
    memset(old, CW_POISON, sizeof *old);
    old->struct_size = sizeof *old;
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, (cw_result*)old), CW_OK);
    assert_int_equal(old->struct_size, sizeof *old);
    assert_memory_equal((const char*)old + sizeof(size_t), (const char*)&full + sizeof(size_t),
                        sizeof *old - sizeof(size_t));
    memset(old, CW_POISON, sizeof *old);
    old->struct_size = sizeof *old;
    assert_int_equal(cw_solver_get_result(s, (cw_result*)old), CW_OK);
    assert_true(cw_same_bits(old->Fy, full.Fy) && old->n_slip == full.n_slip);
    free(old);

    /* A full-size struct with a smaller struct_size: the bytes beyond it
     * keep the caller's poison. */
    cw_result cut;
    cw_poison_result(&cut);
    const cw_result poisoned = cut;
    cut.struct_size = offsetof(cw_result, K);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &cut), CW_OK);
    assert_int_equal(cut.struct_size, offsetof(cw_result, K));
    assert_true(cw_same_bits(cut.W_micro_paper, full.W_micro_paper));
    assert_memory_equal((const char*)&cut + offsetof(cw_result, K),
                        (const char*)&poisoned + offsetof(cw_result, K),
                        sizeof cut - offsetof(cw_result, K));
    cw_solver_destroy(s);
}

/* A future caller's larger result: today's fields written, the tail kept. */
static void larger_result_keeps_its_tail(void** state)
{
    (void)state;
    cw_solver* s = make_solver(CW_GRID_UNIFORM);
    cw_params p;
    cw_test_case(0, &p);
    cw_result full;
    cw_result_init(&full);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &full), CW_OK);
    result_next next;
    memset(&next, CW_POISON, sizeof next);
    next.r.struct_size = sizeof next;
    const result_next poisoned = next;
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &next.r), CW_OK);
    assert_int_equal(next.r.struct_size, sizeof next);
    assert_memory_equal((const char*)&next.r + sizeof(size_t),
                        (const char*)&full + sizeof(size_t), sizeof full - sizeof(size_t));
    assert_memory_equal(next.future, poisoned.future, sizeof next.future);
    cw_solver_destroy(s);
}

/* Accumulated totals into an older cw_accumulation (without steps): the
 * known prefix only. */
static void smaller_accumulation(void** state)
{
    (void)state;
    cw_solver* s = make_solver(CW_GRID_KALKER_STRIPS);
    cw_accumulator* acc = NULL;
    assert_int_equal(cw_accumulator_create(s, &acc), CW_OK);
    cw_params p;
    cw_test_case(0, &p);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
    assert_int_equal(cw_accumulator_add(acc, s, 0.5), CW_OK);
    cw_accumulation full, cut;
    cw_accumulation_init(&full);
    assert_int_equal(cw_accumulator_get_totals(acc, &full), CW_OK);
    memset(&cut, CW_POISON, sizeof cut);
    cut.struct_size = offsetof(cw_accumulation, steps);
    const cw_accumulation poisoned = cut;
    assert_int_equal(cw_accumulator_get_totals(acc, &cut), CW_OK);
    assert_true(cw_same_bits(cut.W_macro, full.W_macro) && cw_same_bits(cut.K, full.K));
    assert_memory_equal(&cut.steps, &poisoned.steps, sizeof cut.steps);
    cw_accumulator_destroy(acc);
    cw_solver_destroy(s);
}

/* A grid without box_scale: the default S = 1 is used, whatever the bytes
 * beyond struct_size hold. */
static void smaller_grid_takes_defaults(void** state)
{
    (void)state;
    cw_grid cut, plain;
    cw_grid_init(&cut);
    cut.kind = CW_GRID_UNIFORM;
    cut.nx = cut.ny = 30;
    plain = cut;
    cut.box_scale = 50.0;
    cut.struct_size = offsetof(cw_grid, box_scale);
    cw_solver *a = NULL, *b = NULL;
    assert_int_equal(cw_solver_create(&cut, &a, NULL, 0), CW_OK);
    assert_int_equal(cw_solver_create(&plain, &b, NULL, 0), CW_OK);
    cw_params p;
    cw_test_case(0, &p);
    cw_result ra, rb;
    cw_result_init(&ra);
    cw_result_init(&rb);
    assert_int_equal(cw_solver_solve(a, &p, CW_SOLVE_FULL, &ra), CW_OK);
    assert_int_equal(cw_solver_solve(b, &p, CW_SOLVE_FULL, &rb), CW_OK);
    assert_memory_equal(&ra, &rb, sizeof ra);
    cw_solver_destroy(a);
    cw_solver_destroy(b);
}

/* struct_size 0 (never initialised) is refused everywhere it is read. */
static void zero_struct_size_is_refused(void** state)
{
    (void)state;
    cw_grid g;
    cw_grid_init(&g);
    g.struct_size = 0;
    cw_solver* s = NULL;
    char message[128];
    assert_int_equal(cw_solver_create(&g, &s, message, sizeof message), CW_ERR_STRUCT_SIZE);
    assert_names(message, "grid->struct_size");
    s = make_solver(CW_GRID_KALKER_STRIPS);
    cw_params p;
    cw_params_init(&p);
    p.struct_size = 0;
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_ERR_STRUCT_SIZE);
    assert_names(cw_solver_last_error(s), "params->struct_size");
    cw_params_init(&p);
    r.struct_size = 0;
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_ERR_STRUCT_SIZE);
    assert_names(cw_solver_last_error(s), "result->struct_size");
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
    assert_int_equal(cw_solver_get_result(s, &r), CW_ERR_STRUCT_SIZE);
    cw_accumulator* acc = NULL;
    assert_int_equal(cw_accumulator_create(s, &acc), CW_OK);
    cw_accumulation t;
    cw_accumulation_init(&t);
    t.struct_size = 0;
    assert_int_equal(cw_accumulator_get_totals(acc, &t), CW_ERR_STRUCT_SIZE);
    cw_accumulator_destroy(acc);
    cw_solver_destroy(s);
}

/* Batch arrays strided by element 0's struct_size: old (smaller) and future
 * (larger) element types both give the one-by-one results. */
enum { COUNT = 9 };

static void batch_with_old_and_new_strides(void** state)
{
    (void)state;
    cw_grid g;
    cw_grid_init(&g);
    g.nx = 15;
    g.ny = 12;
    cw_batch* b = NULL;
    assert_int_equal(cw_batch_create(&g, 3, &b, NULL, 0), CW_OK);
    cw_solver* s = make_solver(CW_GRID_KALKER_STRIPS);

    params_v0 old_p[COUNT];
    result_v0 old_r[COUNT];
    params_next next_p[COUNT];
    result_next next_r[COUNT];
    cw_result expected[COUNT];
    for (int k = 0; k < COUNT; ++k) {
        cw_params p;
        cw_test_case(k, &p);
        p.rolling_direction = 1; /* what an old caller gets */
        copy_to_v0(&p, &old_p[k]);
        memset(&old_r[k], CW_POISON, sizeof old_r[k]);
        old_r[k].struct_size = sizeof old_r[k];
        memset(&next_p[k], CW_POISON, sizeof next_p[k]);
        next_p[k].p = p;
        next_p[k].p.struct_size = sizeof next_p[k];
        memset(&next_r[k], CW_POISON, sizeof next_r[k]);
        next_r[k].r.struct_size = sizeof next_r[k];
        cw_result_init(&expected[k]);
        assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &expected[k]), CW_OK);
    }
    const result_next poisoned = next_r[0];

    /* Old params, old results. */
    assert_int_equal(
        cw_batch_solve(b, COUNT, (const cw_params*)old_p, CW_SOLVE_FULL, (cw_result*)old_r, NULL),
        CW_OK);
    for (int k = 0; k < COUNT; ++k) {
        assert_int_equal(old_r[k].struct_size, sizeof old_r[k]);
        assert_memory_equal((const char*)&old_r[k] + sizeof(size_t),
                            (const char*)&expected[k] + sizeof(size_t),
                            sizeof old_r[k] - sizeof(size_t));
    }
    /* Future params, future results: tails untouched. */
    assert_int_equal(cw_batch_solve(b, COUNT, &next_p[0].p, CW_SOLVE_FULL, &next_r[0].r, NULL),
                     CW_OK);
    for (int k = 0; k < COUNT; ++k) {
        assert_memory_equal((const char*)&next_r[k].r + sizeof(size_t),
                            (const char*)&expected[k] + sizeof(size_t),
                            sizeof(cw_result) - sizeof(size_t));
        assert_memory_equal(next_r[k].future, poisoned.future, sizeof poisoned.future);
    }
    /* Mixed: old params into future results, future params into old results. */
    for (int k = 0; k < COUNT; ++k) {
        memset(&old_r[k], CW_POISON, sizeof old_r[k]);
        old_r[k].struct_size = sizeof old_r[k];
    }
    assert_int_equal(
        cw_batch_solve(b, COUNT, &next_p[0].p, CW_SOLVE_FORCES, (cw_result*)old_r, NULL), CW_OK);
    assert_int_equal(
        cw_batch_solve(b, COUNT, (const cw_params*)old_p, CW_SOLVE_FORCES, &next_r[0].r, NULL),
        CW_OK);
    for (int k = 0; k < COUNT; ++k) {
        assert_true(cw_same_bits(old_r[k].Fx, expected[k].Fx) &&
                    cw_same_bits(old_r[k].Mz, expected[k].Mz));
        assert_true(cw_same_bits(next_r[k].r.Fy, expected[k].Fy) &&
                    next_r[k].r.n_slip == expected[k].n_slip);
    }
    cw_solver_destroy(s);
    cw_batch_destroy(b);
}

/* A results array is strided by results[0].struct_size, so an element that
 * carries a smaller one (an old struct among today's, or an older one among
 * old ones) would be written past its own end: the batch is refused with
 * CW_ERR_STRUCT_SIZE naming the element, before anything is written (every
 * result and status as it was). */
static void batch_refuses_a_smaller_result_element(void** state)
{
    (void)state;
    cw_batch* b = cw_test_batch(CW_GRID_KALKER_STRIPS, 15, 12, 1.0, 3);
    cw_params p[COUNT];
    for (int k = 0; k < COUNT; ++k) cw_test_case(k, &p[k]);
    int statuses[COUNT];

    result_next next_r[COUNT];
    cw_poison(next_r, sizeof next_r);
    for (int k = 0; k < COUNT; ++k) next_r[k].r.struct_size = sizeof next_r[k];
    next_r[6].r.struct_size = sizeof(cw_result); /* today's among future ones */
    result_next next_before[COUNT];
    memcpy(next_before, next_r, sizeof next_r);
    cw_fill_int(statuses, COUNT, CW_INT_SENTINEL);
    assert_status(cw_batch_solve(b, COUNT, p, CW_SOLVE_FULL, &next_r[0].r, statuses),
                  CW_ERR_STRUCT_SIZE);
    assert_names(cw_batch_last_error(b), "results[6]");
    assert_memory_equal(next_r, next_before, sizeof next_r);
    assert_untouched_int(statuses, COUNT);

    result_v0 old_r[COUNT];
    cw_poison(old_r, sizeof old_r);
    for (int k = 0; k < COUNT; ++k) old_r[k].struct_size = sizeof old_r[k];
    old_r[3].struct_size = offsetof(cw_result, K); /* older still */
    result_v0 old_before[COUNT];
    memcpy(old_before, old_r, sizeof old_r);
    assert_status(cw_batch_solve(b, COUNT, p, CW_SOLVE_FULL, (cw_result*)old_r, statuses),
                  CW_ERR_STRUCT_SIZE);
    assert_names(cw_batch_last_error(b), "results[3]");
    assert_memory_equal(old_r, old_before, sizeof old_r);
    assert_untouched_int(statuses, COUNT);

    /* The same arrays with every element alike are solved. */
    old_r[3].struct_size = sizeof old_r[3];
    assert_status(cw_batch_solve(b, COUNT, p, CW_SOLVE_FULL, (cw_result*)old_r, statuses), CW_OK);
    cw_batch_destroy(b);
}

/* cw_solver_get_patches strides the caller's array by out[0].struct_size:
 * patch k of two lands at k times it, for an old cw_patch (cut before Fn,
 * the leading fields written) and a future one (today's fields written, its
 * tail untouched), each the patch of today's struct. */
static void patches_with_old_and_new_strides(void** state)
{
    (void)state;
    double h[CW_LOBES_NX * CW_LOBES_NY];
    const cw_grid g = cw_test_two_lobes(h);
    cw_solver* s = NULL;
    assert_int_equal(cw_solver_create(&g, &s, NULL, 0), CW_OK);
    cw_params p;
    cw_params_init(&p);
    p.model = CW_MODEL_EXACT;
    p.normal_force = 60e3;
    p.xi_x = 4e-4;
    p.xi_y = -3e-4;
    p.phi = 0.3;
    p.gap = h;
    p.gap_len = CW_LOBES_NX * CW_LOBES_NY;
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FORCES, NULL), CW_OK);
    cw_patch today[2];
    cw_patch_init(&today[0]);
    cw_patch_init(&today[1]);
    size_t count = 0;
    assert_int_equal(cw_solver_get_patches(s, today, 2, &count), CW_OK);
    assert_int_equal(count, 2);
    assert_true(today[0].Fn > today[1].Fn && today[1].Fn > 0.0); /* two different patches */
    cw_check_patch_strides(s, today, 2);
    cw_solver_destroy(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(old_structs_are_prefixes),
        cmocka_unit_test(smaller_params_take_defaults),
        cmocka_unit_test(larger_params_are_read_up_to_today),
        cmocka_unit_test(rolling_speed_unused_by_coulomb),
        cmocka_unit_test(smaller_result_is_written_up_to_its_size),
        cmocka_unit_test(larger_result_keeps_its_tail),
        cmocka_unit_test(smaller_accumulation),
        cmocka_unit_test(smaller_grid_takes_defaults),
        cmocka_unit_test(zero_struct_size_is_refused),
        cmocka_unit_test(batch_with_old_and_new_strides),
        cmocka_unit_test(batch_refuses_a_smaller_result_element),
        cmocka_unit_test(patches_with_old_and_new_strides),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
