/* The cw_transient handle: CONTACT's catt_to_cart through the C ABI (the
 * shift and the first 14 rolling steps, each printed digit of
 * tests/data/transient/catt_to_cart.csv: eve70a/CONTACT d431cdb), a trial
 * repeated after rewind and after save / restore gives the same bits, and
 * every function's errors name their input and leave the handle usable. */
#include "capi_fixtures.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static cw_transient* make(double* h)
{
    cw_params p;
    const cw_grid g = cw_test_catt_to_cart(h, &p);
    cw_transient* t = NULL;
    char message[256] = "";
    const int status = cw_transient_create(&g, &p, &t, message, sizeof message);
    if (status != CW_OK || !t) {
        print_error("cw_transient_create: %s\n", message);
        _fail(__FILE__, __LINE__);
    }
    return t;
}

static cw_transient_input force_step(double dq, double fx_over_mu_n)
{
    cw_transient_input s;
    cw_transient_input_init(&s);
    s.dq = dq;
    s.prescribe = CW_PRESCRIBE_FX;
    s.Fx = fx_over_mu_n * 0.4013 * 0.4705;
    return s;
}

/* The shift (case 1) and cases 2 ... 15 of the CSV, as CONTACT prints them:
 * shift and creepage, element division, frictional work. */
static void catt_to_cart_first_cases(void** state)
{
    (void)state;
    double h[CW_CATT_NX * CW_CATT_NY];
    cw_transient* t = make(h);
    FILE* f = fopen(CW_TEST_DATA_DIR "/transient/catt_to_cart.csv", "r");
    assert_non_null(f);
    char line[256];
    assert_non_null(fgets(line, sizeof line, f)); /* header */
    for (int k = 1; k <= 15; ++k) {
        int c = 0, adh = 0, slip = 0;
        char kind[16], value[32];
        double fric = 0.0;
        assert_int_equal(fscanf(f, "%d,%15[^,],%31[^,],%d,%d,%lf\n", &c, kind, value, &adh, &slip,
                                &fric),
                         6);
        const int shift = strcmp(kind, "shift") == 0;
        const cw_transient_input s = force_step(shift ? 0.0 : 0.25e-3, -0.657);
        cw_transient_result r;
        cw_transient_result_init(&r);
        assert_int_equal(cw_transient_step(t, &s, &r), CW_OK);
        assert_int_equal(cw_transient_commit(t), CW_OK);
        char got[32];
        snprintf(got, sizeof got, "%.3E", shift ? r.xi_x * 1e3 : r.xi_x);
        assert_string_equal(got, value);
        assert_int_equal(r.steps_committed, k - 1);
        assert_close(r.Fx, s.Fx, 0.0, 1e-8 * 0.4013 * 0.4705); /* tolerance * mu N */
        assert_int_equal(r.n_adhesion, adh);
        assert_int_equal(r.n_slip, slip);
        /* CONTACT's frictional work of the shift [N m] and power of a step
         * [N m/s] at V = 1 m/s (dt = 2.5e-4 s), negative. */
        snprintf(got, sizeof got, "%.3E", -r.W_slip / (shift ? 1.0 : 2.5e-4));
        char want[32];
        snprintf(want, sizeof want, "%.3E", fric);
        assert_string_equal(got, want);
    }
    fclose(f);
    cw_transient_destroy(t);
}

static void trial_repeats_bitwise(void** state)
{
    (void)state;
    double h[CW_CATT_NX * CW_CATT_NY];
    cw_transient* t = make(h);
    const size_t n = (size_t)CW_CATT_NX * CW_CATT_NY;
    cw_transient_input s = force_step(0.0, -0.657);
    assert_int_equal(cw_transient_step(t, &s, NULL), CW_OK);
    assert_int_equal(cw_transient_commit(t), CW_OK);
    size_t size = 0;
    assert_int_equal(cw_transient_state_size(t, &size), CW_OK);
    uint64_t* saved = malloc(size * sizeof(uint64_t));
    assert_int_equal(cw_transient_save(t, saved, size), CW_OK);

    s = force_step(0.25e-3, -0.5);
    cw_transient_result a, b, c;
    cw_transient_result_init(&a);
    cw_transient_result_init(&b);
    cw_transient_result_init(&c);
    double* px_a = malloc(n * sizeof(double));
    double* px_b = malloc(n * sizeof(double));
    assert_int_equal(cw_transient_step(t, &s, &a), CW_OK);
    assert_int_equal(cw_transient_get_field(t, CW_FIELD_PX, px_a, n), CW_OK);
    assert_int_equal(cw_transient_rewind(t), CW_OK);
    assert_int_equal(cw_transient_commit(t), CW_ERR_NO_SOLUTION);
    assert_non_null(strstr(cw_transient_last_error(t), "no step to commit"));
    assert_int_equal(cw_transient_step(t, &s, &b), CW_OK);
    assert_int_equal(cw_transient_get_field(t, CW_FIELD_PX, px_b, n), CW_OK);
    assert_memory_equal(&a, &b, sizeof a);
    assert_memory_equal(px_a, px_b, n * sizeof(double));
    /* Commit two steps, restore the saved state: the trial again. */
    assert_int_equal(cw_transient_commit(t), CW_OK);
    assert_int_equal(cw_transient_step(t, &s, NULL), CW_OK);
    assert_int_equal(cw_transient_commit(t), CW_OK);
    assert_int_equal(cw_transient_restore(t, saved, size), CW_OK);
    assert_int_equal(cw_transient_get_field(t, CW_FIELD_PX, px_b, n), CW_ERR_NO_SOLUTION);
    assert_int_equal(cw_transient_step(t, &s, &c), CW_OK);
    assert_memory_equal(&a, &c, sizeof a);
    /* The traction sums to Fx. */
    double sum = 0.0;
    for (size_t k = 0; k < n; ++k) sum += px_a[k] * 0.25e-3 * 0.25e-3;
    assert_close(sum, a.Fx, 1e-12, 0.0);
    free(px_a);
    free(px_b);
    free(saved);
    cw_transient_destroy(t);
}

static void errors_name_their_input(void** state)
{
    (void)state;
    double h[CW_CATT_NX * CW_CATT_NY];
    cw_params p;
    cw_grid g = cw_test_catt_to_cart(h, &p);
    cw_transient* t = NULL;
    char message[256] = "";
    /* Creation: NULL, another grid kind, another model, no friction. */
    assert_int_equal(cw_transient_create(&g, &p, NULL, message, sizeof message),
                     CW_ERR_NULL_POINTER);
    assert_int_equal(cw_transient_create(&g, NULL, &t, message, sizeof message),
                     CW_ERR_NULL_POINTER);
    assert_null(t);
    cw_grid strips = cw_test_grid(CW_GRID_KALKER_STRIPS, 20, 20, 1.0);
    assert_int_equal(cw_transient_create(&strips, &p, &t, message, sizeof message),
                     CW_ERR_INVALID_INPUT);
    assert_non_null(strstr(message, "grid->kind"));
    /* The uniform grid without semi-axes. */
    cw_grid uniform = cw_test_grid(CW_GRID_UNIFORM, 20, 20, 1.0);
    assert_int_equal(cw_transient_create(&uniform, &p, &t, message, sizeof message),
                     CW_ERR_INVALID_INPUT);
    assert_null(t);
    p.model = CW_MODEL_CALIBRATED;
    assert_int_equal(cw_transient_create(&g, &p, &t, message, sizeof message),
                     CW_ERR_INVALID_INPUT);
    assert_non_null(strstr(message, "params->model"));
    p.model = CW_MODEL_EXACT;
    p.mu = 0.0;
    assert_int_equal(cw_transient_create(&g, &p, &t, message, sizeof message),
                     CW_ERR_INVALID_INPUT);
    assert_non_null(strstr(message, "mu"));
    assert_null(t);
    p.mu = 0.4013;
    assert_int_equal(cw_transient_create(&g, &p, &t, message, sizeof message), CW_OK);

    /* Steps: dq outside [0, dx], NaN, a force beyond mu N, an unknown
     * prescribe, a bad struct_size; none leaves a trial. */
    cw_transient_result r;
    cw_transient_result_init(&r);
    cw_transient_input s = force_step(0.3e-3, -0.5);
    assert_int_equal(cw_transient_step(t, &s, &r), CW_ERR_INVALID_INPUT);
    assert_non_null(strstr(cw_transient_last_error(t), "dq"));
    s.dq = -1e-6;
    assert_int_equal(cw_transient_step(t, &s, &r), CW_ERR_INVALID_INPUT);
    s.dq = 0.25e-3;
    s.Fx = NAN;
    assert_int_equal(cw_transient_step(t, &s, &r), CW_ERR_INVALID_INPUT);
    assert_non_null(strstr(cw_transient_last_error(t), "Fx"));
    s.Fx = -1.0 * 0.4013 * 0.4705;
    assert_int_equal(cw_transient_step(t, &s, &r), CW_ERR_INVALID_INPUT);
    assert_non_null(strstr(cw_transient_last_error(t), "mu N"));
    s.Fx = 0.0;
    s.prescribe = 7;
    assert_int_equal(cw_transient_step(t, &s, &r), CW_ERR_UNKNOWN_OPTION);
    assert_non_null(strstr(cw_transient_last_error(t), "prescribe"));
    s.prescribe = CW_PRESCRIBE_CREEPAGES;
    s.struct_size = 1;
    assert_int_equal(cw_transient_step(t, &s, &r), CW_ERR_STRUCT_SIZE);
    assert_int_equal(cw_transient_commit(t), CW_ERR_NO_SOLUTION);
    assert_int_equal(cw_transient_step(t, NULL, &r), CW_ERR_NULL_POINTER);

    /* Fields and state: before a step, an unknown field, a short buffer. */
    double f[CW_CATT_NX * CW_CATT_NY];
    int st[CW_CATT_NX * CW_CATT_NY];
    const size_t n = (size_t)CW_CATT_NX * CW_CATT_NY;
    assert_int_equal(cw_transient_get_field(t, CW_FIELD_PX, f, n), CW_ERR_NO_SOLUTION);
    assert_int_equal(cw_transient_get_state(t, st, n), CW_ERR_NO_SOLUTION);
    cw_transient_input_init(&s);
    s.dq = 0.25e-3;
    s.xi_x = 1e-3;
    assert_int_equal(cw_transient_step(t, &s, &r), CW_OK);
    assert_int_equal(cw_transient_get_field(t, CW_FIELD_WORK_PAPER, f, n), CW_ERR_UNKNOWN_OPTION);
    assert_non_null(strstr(cw_transient_last_error(t), "field"));
    assert_int_equal(cw_transient_get_field(t, CW_FIELD_PX, f, n - 1), CW_ERR_BUFFER_TOO_SMALL);
    assert_int_equal(cw_transient_get_state(t, st, n - 1), CW_ERR_BUFFER_TOO_SMALL);
    assert_int_equal(cw_transient_get_state(t, st, n), CW_OK);
    int adhesion = 0;
    for (size_t k = 0; k < n; ++k) adhesion += st[k] == CW_STATE_ADHESION;
    assert_int_equal(adhesion, r.n_adhesion);

    /* Save and restore: a short buffer, foreign bytes. */
    size_t size = 0;
    assert_int_equal(cw_transient_state_size(t, &size), CW_OK);
    uint64_t* bytes = malloc(size * sizeof(uint64_t));
    assert_int_equal(cw_transient_save(t, bytes, size - 1), CW_ERR_BUFFER_TOO_SMALL);
    assert_int_equal(cw_transient_save(t, bytes, size), CW_OK);
    assert_int_equal(cw_transient_restore(t, bytes, size - 1), CW_ERR_INVALID_INPUT);
    bytes[0] ^= 1;
    assert_int_equal(cw_transient_restore(t, bytes, size), CW_ERR_INVALID_INPUT);
    assert_int_equal(cw_transient_restore(t, NULL, size), CW_ERR_NULL_POINTER);
    free(bytes);
    /* The handle stays usable. */
    assert_int_equal(cw_transient_commit(t), CW_OK);
    assert_int_equal(cw_transient_destroy(t), CW_OK);
    assert_int_equal(cw_transient_destroy(NULL), CW_OK);
    assert_int_equal(cw_transient_start_zero(NULL), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_transient_input_init(NULL), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_transient_result_init(NULL), CW_ERR_NULL_POINTER);
}

/* After the shift and three steps of catt_to_cart: the work field adds up
 * to W_step (1e-12, relative) and W_step >= W_slip (a small shift that
 * sticks: W_step = 0 to 1e-9 of the rigid work); the Jacobian of a step
 * at prescribed Fx (row xi_x, column Fx) equals a central difference of two
 * trials (h = 1e-5 mu N) to 1e-6, and so does d Fx / d xi_x of a step at
 * the creepage found (its inverse); its errors. */
static void work_field_and_jacobian(void** state)
{
    (void)state;
    double h[CW_CATT_NX * CW_CATT_NY];
    cw_transient* t = make(h);
    const size_t n = (size_t)CW_CATT_NX * CW_CATT_NY;
    double J[CW_TRANSIENT_JACOBIAN_LEN], K[CW_TRANSIENT_JACOBIAN_LEN];
    assert_int_equal(cw_transient_jacobian(t, J, 9), CW_ERR_NO_SOLUTION);
    cw_transient_result r;
    cw_transient_result_init(&r);
    for (int k = 0; k < 4; ++k) {
        const cw_transient_input s = force_step(k == 0 ? 0.0 : 0.25e-3, -0.657);
        assert_int_equal(cw_transient_step(t, &s, &r), CW_OK);
        assert_int_equal(cw_transient_commit(t), CW_OK);
    }
    const cw_transient_input s = force_step(0.25e-3, -0.5);
    assert_int_equal(cw_transient_step(t, &s, &r), CW_OK);
    double* w = malloc(n * sizeof(double));
    assert_int_equal(cw_transient_get_field(t, CW_FIELD_WORK_CONSISTENT, w, n), CW_OK);
    double sum = 0.0;
    for (size_t k = 0; k < n; ++k) sum += w[k];
    free(w);
    assert_true(fabs(sum / r.W_step - 1.0) <= 1e-12);
    assert_true(r.W_step >= r.W_slip && r.W_slip > 0.0);
    assert_int_equal(cw_transient_jacobian(t, J, 8), CW_ERR_BUFFER_TOO_SMALL);
    assert_int_equal(cw_transient_jacobian(t, NULL, 9), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_transient_jacobian(NULL, J, 9), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_transient_jacobian(t, J, 9), CW_OK);
    const double muN = 0.4013 * 0.4705, dF = 1e-5 * muN, xi = r.xi_x;
    double side[2];
    for (int k = 0; k < 2; ++k) {
        cw_transient_input p = s;
        p.Fx += k == 0 ? dF : -dF;
        assert_int_equal(cw_transient_step(t, &p, &r), CW_OK);
        side[k] = r.xi_x;
        assert_int_equal(cw_transient_rewind(t), CW_OK);
    }
    const double fd = (side[0] - side[1]) / (2 * dF);
    printf("d xi_x / d Fx: Jacobian %.9e, central difference %.9e\n", J[0], fd);
    assert_true(fabs(fd / J[0] - 1.0) <= 1e-6);
    cw_transient_input c;
    cw_transient_input_init(&c);
    c.dq = 0.25e-3;
    c.xi_x = xi;
    assert_int_equal(cw_transient_step(t, &c, &r), CW_OK);
    assert_int_equal(cw_transient_jacobian(t, K, 9), CW_OK);
    assert_true(fabs(K[0] * J[0] - 1.0) <= 1e-6);
    assert_int_equal(cw_transient_destroy(t), CW_OK);

    /* A small shift from zero sticks everywhere: the rigid work goes into
     * elastic energy, W_step is 0 to 1e-9 of it. */
    t = make(h);
    const cw_transient_input small = force_step(0.0, -0.01);
    assert_int_equal(cw_transient_step(t, &small, &r), CW_OK);
    assert_int_equal(r.n_slip, 0);
    assert_true(fabs(r.W_step) <= 1e-9 * (-0.5 * r.Fx * r.xi_x));
    assert_int_equal(cw_transient_destroy(t), CW_OK);
}

/* World-fixed coordinates through the ABI: the shift and two steps of
 * catt_to_cart (the contact moves two elements, still on the 34 x 33 grid)
 * give the contact-fixed creepages to 1e-6 (the core test compares 57
 * steps on 90 x 33); a bad coordinates value names itself. */
static void world_coordinates(void** state)
{
    (void)state;
    double h[CW_CATT_NX * CW_CATT_NY];
    cw_transient* c = make(h);
    cw_transient* w = make(h);
    assert_int_equal(cw_transient_set_coordinates(w, 7), CW_ERR_UNKNOWN_OPTION);
    assert_non_null(strstr(cw_transient_last_error(w), "coordinates"));
    assert_int_equal(cw_transient_set_coordinates(NULL, CW_COORDINATES_WORLD), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_transient_set_coordinates(w, CW_COORDINATES_WORLD), CW_OK);
    for (int k = 0; k < 3; ++k) {
        const cw_transient_input s = force_step(k == 0 ? 0.0 : 0.25e-3, -0.657);
        cw_transient_result a, b;
        cw_transient_result_init(&a);
        cw_transient_result_init(&b);
        assert_int_equal(cw_transient_step(c, &s, &a), CW_OK);
        assert_int_equal(cw_transient_step(w, &s, &b), CW_OK);
        assert_int_equal(cw_transient_commit(c), CW_OK);
        assert_int_equal(cw_transient_commit(w), CW_OK);
        assert_true(fabs(b.xi_x / a.xi_x - 1.0) <= 1e-6);
        assert_int_equal(b.n_slip, a.n_slip);
    }
    cw_transient_destroy(c);
    cw_transient_destroy(w);
}

/* An elliptic contact on the uniform grid (a = 4 mm, b = 2.5 mm, 32 x 24,
 * box scale 1.1): its steady start equals cw_solver's exact model on the
 * same grid to 1e-6 mu N, and a shift and two steps at Fx run. */
static void ellipse_on_uniform_grid(void** state)
{
    (void)state;
    cw_params p;
    const cw_grid g = cw_test_transient_ellipse(&p);
    cw_transient* t = NULL;
    char message[256] = "";
    assert_int_equal(cw_transient_create(&g, &p, &t, message, sizeof message), CW_OK);
    cw_transient_input s;
    cw_transient_input_init(&s);
    s.xi_x = 1e-3;
    s.xi_y = 5e-4;
    cw_transient_result r;
    cw_transient_result_init(&r);
    assert_int_equal(cw_transient_start_steady(t, &s, &r), CW_OK);
    cw_solver* solver = cw_test_solver(CW_GRID_UNIFORM, 32, 24, 1.1);
    p.xi_x = s.xi_x;
    p.xi_y = s.xi_y;
    cw_result steady;
    cw_result_init(&steady);
    assert_int_equal(cw_solver_solve(solver, &p, CW_SOLVE_FORCES, &steady), CW_OK);
    const double muN = 0.4013 * 0.4705;
    assert_true(fabs(r.Fx - steady.Fx) <= 1e-6 * muN);
    assert_true(fabs(r.Fy - steady.Fy) <= 1e-6 * muN);
    cw_solver_destroy(solver);
    assert_int_equal(cw_transient_start_zero(t), CW_OK);
    for (int k = 0; k < 3; ++k) {
        cw_transient_input f;
        cw_transient_input_init(&f);
        f.dq = k == 0 ? 0.0 : 2.0 * 1.1 * 4e-3 / 32;
        f.prescribe = CW_PRESCRIBE_FX;
        f.Fx = -0.5 * muN;
        assert_int_equal(cw_transient_step(t, &f, &r), CW_OK);
        assert_int_equal(cw_transient_commit(t), CW_OK);
        assert_true(fabs(r.Fx - f.Fx) <= 1e-8 * muN);
    }
    cw_transient_destroy(t);
}

/* Wear over the shift and five steps of catt_to_cart by the USFD law (all
 * in its mild regime, mass = k1 x work): each step's mass is k1 W_step to
 * 1e-12, the shift's zero, the accumulated map sums to the total; errors. */
static void wear_over_steps(void** state)
{
    (void)state;
    double h[CW_CATT_NX * CW_CATT_NY];
    cw_transient* t = make(h);
    cw_wear_params law;
    cw_wear_params_init(&law);
    double mass = -1.0, total = 0.0;
    assert_int_equal(cw_transient_add_wear(t, &law, &mass), CW_ERR_NO_SOLUTION);
    for (int k = 0; k < 6; ++k) {
        const cw_transient_input s = force_step(k == 0 ? 0.0 : 0.25e-3, -0.657);
        cw_transient_result r;
        cw_transient_result_init(&r);
        assert_int_equal(cw_transient_step(t, &s, &r), CW_OK);
        assert_int_equal(cw_transient_commit(t), CW_OK);
        assert_int_equal(cw_transient_add_wear(t, &law, &mass), CW_OK);
        if (k == 0)
            assert_true(mass == 0.0);
        else
            assert_true(fabs(mass / (law.usfd_k1 * r.W_step) - 1.0) <= 1e-12);
        total += mass;
    }
    const size_t n = (size_t)CW_CATT_NX * CW_CATT_NY;
    double* map = malloc(n * sizeof(double));
    double got = 0.0, sum = 0.0;
    assert_int_equal(cw_transient_get_wear(t, map, n - 1, &got), CW_ERR_BUFFER_TOO_SMALL);
    assert_int_equal(cw_transient_get_wear(t, map, n, &got), CW_OK);
    for (size_t k = 0; k < n; ++k) sum += map[k];
    free(map);
    assert_true(fabs(got / total - 1.0) <= 1e-12);
    assert_true(fabs(sum / total - 1.0) <= 1e-12);
    law.law = 9;
    assert_int_equal(cw_transient_add_wear(t, &law, NULL), CW_ERR_UNKNOWN_OPTION);
    assert_non_null(strstr(cw_transient_last_error(t), "law"));
    assert_int_equal(cw_transient_add_wear(t, NULL, NULL), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_transient_reset_wear(t), CW_OK);
    assert_int_equal(cw_transient_get_wear(t, NULL, 0, &got), CW_OK);
    assert_true(got == 0.0);
    cw_transient_destroy(t);
}

/* model = CW_MODEL_FASTSIM: FASTSIM's transient form through the same
 * handle. Its steady start equals the steady FASTSIM of a cw_solver on the
 * same gap grid (another implementation of the march) to 1e-12 mu N; a
 * step of dx at the steady creepages keeps the forces; Fx prescribed is met,
 * the shift, rewound and repeated, gives the same bits and is the
 * simplified theory's closed form. */
static void fastsim_model(void** state)
{
    (void)state;
    double h[CW_CATT_NX * CW_CATT_NY];
    cw_params p;
    const cw_grid g = cw_test_catt_to_cart(h, &p);
    p.model = CW_MODEL_FASTSIM;
    const double mu_n = 0.4013 * 0.4705;
    cw_transient* t = NULL;
    char message[256] = "";
    assert_int_equal(cw_transient_create(&g, &p, &t, message, sizeof message), CW_OK);
    cw_transient_input s;
    cw_transient_input_init(&s);
    s.xi_x = 1.5e-3;
    s.xi_y = -1e-3;
    s.phi = 40.0;
    cw_transient_result st, r;
    cw_transient_result_init(&st);
    cw_transient_result_init(&r);
    assert_int_equal(cw_transient_start_steady(t, &s, &st), CW_OK);
    cw_solver* solver = NULL;
    assert_int_equal(cw_solver_create(&g, &solver, message, sizeof message), CW_OK);
    cw_params q = p;
    q.xi_x = s.xi_x;
    q.xi_y = s.xi_y;
    q.phi = s.phi;
    cw_result steady;
    cw_result_init(&steady);
    assert_int_equal(cw_solver_solve(solver, &q, CW_SOLVE_FORCES, &steady), CW_OK);
    assert_close(st.Fx, steady.Fx, 0.0, 1e-12 * mu_n);
    assert_close(st.Fy, steady.Fy, 0.0, 1e-12 * mu_n);
    assert_close(st.Mz, steady.Mz, 0.0, 1e-12 * mu_n * 3.5e-3);
    s.dq = 0.25e-3;
    assert_int_equal(cw_transient_step(t, &s, &r), CW_OK);
    assert_close(r.Fx, st.Fx, 0.0, 1e-12 * mu_n);
    /* The shift to Fx = -0.657 mu N from zero, twice. */
    assert_int_equal(cw_transient_start_zero(t), CW_OK);
    cw_transient_input f = force_step(0.0, -0.657);
    cw_transient_result a, b;
    cw_transient_result_init(&a);
    cw_transient_result_init(&b);
    assert_int_equal(cw_transient_step(t, &f, &a), CW_OK);
    assert_int_equal(cw_transient_rewind(t), CW_OK);
    assert_int_equal(cw_transient_step(t, &f, &b), CW_OK);
    assert_memory_equal(&a, &b, sizeof a);
    assert_close(a.Fx, f.Fx, 0.0, 1e-8 * mu_n);
    assert_true(a.n_adhesion > 0 && a.n_slip > 0);
    /* The simplified theory's shift in closed form: on Hertz's pressure p0
     * sqrt(1 - r^2/a^2) (a = 3.50 mm: N R (1 - nu) 3 / (4 G), R = 1 / (2 x
     * 2.963)) a uniform stick traction t = s mu p0 carries F / (mu N) =
     * 3/2 (s - s^3/3), and the shift is t Ls, Ls = pi r (2 - nu) / (4 G)
     * with r = sqrt(area / pi) of the contact (theory/transient.md): the
     * grid's within 2 %. */
    const double R = 1.0 / (2.0 * 2.963), aH = cbrt(3.0 * 0.4705 * R * 0.72 / 4e6);
    const double p0 = 3.0 * 0.4705 / (2.0 * M_PI * aH * aH);
    double sl = 0.0, sh = 1.0; /* bisection: 3/2 (s - s^3/3) = 0.657 */
    for (int k = 0; k < 60; ++k) {
        const double m = 0.5 * (sl + sh);
        if (1.5 * (m - m * m * m / 3.0) < 0.657) sl = m; else sh = m;
    }
    const double radius = sqrt(a.n_contact * 0.25e-3 * 0.25e-3 / M_PI);
    const double shift = sl * 0.4013 * p0 * M_PI * radius * (2.0 - 0.28) / 4e6;
    assert_close(a.xi_x, shift, 0.02, 0.0);
    cw_solver_destroy(solver);
    cw_transient_destroy(t);
}

/* What FASTSIM's transient form takes of the exact model's additions and
 * what it refuses. Takes: the work field (its slip's dissipation, summing
 * to W_step to 1e-12; W_slip = W_step: the step is explicit), wear (the
 * USFD law's mild regime, mass = k1 W_step to 1e-12) and the elliptic
 * contact (its steady start within 3 % of mu N of cw_solver's steady FASTSIM
 * on the same uniform grid: Hertz's pressure and ellipse there, the
 * discrete normal problem and the patch rule here; measured 1.7 % in Fx,
 * 0.9 % in Fy). Refuses, naming the
 * model: world-fixed coordinates, the step Jacobian. */
static void fastsim_takes_or_refuses(void** state)
{
    (void)state;
    double h[CW_CATT_NX * CW_CATT_NY];
    cw_params p;
    const cw_grid g = cw_test_catt_to_cart(h, &p);
    p.model = CW_MODEL_FASTSIM;
    const double mu_n = 0.4013 * 0.4705;
    cw_transient* t = NULL;
    char message[256] = "";
    assert_int_equal(cw_transient_create(&g, &p, &t, message, sizeof message), CW_OK);
    assert_int_equal(cw_transient_set_coordinates(t, CW_COORDINATES_WORLD), CW_ERR_INVALID_INPUT);
    assert_non_null(strstr(cw_transient_last_error(t), "CW_COORDINATES_WORLD"));
    assert_non_null(strstr(cw_transient_last_error(t), "CW_MODEL_FASTSIM"));
    assert_int_equal(cw_transient_set_coordinates(t, CW_COORDINATES_CONTACT), CW_OK);
    cw_wear_params law;
    cw_wear_params_init(&law);
    const size_t n = (size_t)CW_CATT_NX * CW_CATT_NY;
    double* w = malloc(n * sizeof(double));
    double mass = -1.0, total = 0.0, got = 0.0;
    cw_transient_result r;
    cw_transient_result_init(&r);
    for (int k = 0; k < 4; ++k) {
        const cw_transient_input s = force_step(k == 0 ? 0.0 : 0.25e-3, -0.657);
        assert_int_equal(cw_transient_step(t, &s, &r), CW_OK);
        assert_int_equal(cw_transient_commit(t), CW_OK);
        assert_int_equal(cw_transient_get_field(t, CW_FIELD_WORK_CONSISTENT, w, n), CW_OK);
        double sum = 0.0;
        for (size_t e = 0; e < n; ++e) sum += w[e];
        assert_true(r.W_step > 0.0 && r.W_slip == r.W_step);
        assert_close(sum, r.W_step, 1e-12, 0.0);
        assert_int_equal(cw_transient_add_wear(t, &law, &mass), CW_OK);
        if (k == 0)
            assert_true(mass == 0.0);
        else
            assert_close(mass, law.usfd_k1 * r.W_step, 1e-12, 0.0);
        total += mass;
    }
    free(w);
    assert_int_equal(cw_transient_get_wear(t, NULL, 0, &got), CW_OK);
    assert_close(got, total, 1e-12, 0.0);
    double J[CW_TRANSIENT_JACOBIAN_LEN];
    assert_int_equal(cw_transient_jacobian(t, J, 9), CW_ERR_INVALID_INPUT);
    assert_non_null(strstr(cw_transient_last_error(t), "CW_MODEL_FASTSIM"));
    cw_transient_destroy(t);

    cw_params e;
    const cw_grid u = cw_test_transient_ellipse(&e);
    e.model = CW_MODEL_FASTSIM;
    t = NULL;
    assert_int_equal(cw_transient_create(&u, &e, &t, message, sizeof message), CW_OK);
    cw_transient_input s;
    cw_transient_input_init(&s);
    s.xi_x = 1e-3;
    s.xi_y = 5e-4;
    assert_int_equal(cw_transient_start_steady(t, &s, &r), CW_OK);
    cw_solver* solver = cw_test_solver(CW_GRID_UNIFORM, 32, 24, 1.1);
    e.xi_x = s.xi_x;
    e.xi_y = s.xi_y;
    cw_result steady;
    cw_result_init(&steady);
    assert_int_equal(cw_solver_solve(solver, &e, CW_SOLVE_FORCES, &steady), CW_OK);
    printf("FASTSIM ellipse: transient Fx %.6e Fy %.6e, steady Fx %.6e Fy %.6e\n", r.Fx, r.Fy,
           steady.Fx, steady.Fy);
    assert_close(r.Fx, steady.Fx, 0.0, 0.03 * mu_n);
    assert_close(r.Fy, steady.Fy, 0.0, 0.03 * mu_n);
    cw_solver_destroy(solver);
    cw_transient_destroy(t);
}

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(catt_to_cart_first_cases),
        cmocka_unit_test(trial_repeats_bitwise),
        cmocka_unit_test(errors_name_their_input),
        cmocka_unit_test(work_field_and_jacobian),
        cmocka_unit_test(world_coordinates),
        cmocka_unit_test(ellipse_on_uniform_grid),
        cmocka_unit_test(wear_over_steps),
        cmocka_unit_test(fastsim_model),
        cmocka_unit_test(fastsim_takes_or_refuses),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : NULL);
}
