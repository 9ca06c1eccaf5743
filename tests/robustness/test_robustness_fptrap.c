/* Hosts that trap floating-point exceptions are safe (doc/reference/guarantees.md),
 * through the whole C ABI: with invalid, divide-by-zero, overflow and
 * denormal-operand traps on, no call raises one -- valid input of every
 * kind, in both modes, every getter, the Jacobians (FASTSIM, calibrated),
 * batches, the accumulator, the helpers, the wear calls,
 * and hostile or absurd input (NaN, Inf, 1e300 loads, subnormal creepages),
 * which gets a status or zeros, never a trap. And a call leaves no trace:
 * the caller's exception flags, masks and rounding mode are as before, and
 * the caller's rounding mode does not change a result. A trap ends the
 * process naming the case (fptrap_support.h). The requirement behind it
 * reported 45 traps in 256 solves (the default contact, xi_x = 1e-3, uniform
 * grid 14 x 16, CW_SOLVE_FULL among them): all of the sweep below runs. */
#include "fptrap_support.h"
#include "capi_fixtures.h"

static long g_calls;

/* Runs one library call with traps on; its arguments are evaluated before,
 * with traps off (the test's own arithmetic may touch subnormals). */
#define TRAPPED(call, name)                                                                   \
    do {                                                                                      \
        fptrap_on();                                                                          \
        call;                                                                                 \
        expect_no_trace(name);                                                                \
        fptrap_disable();                                                                     \
    } while (0)

/* After every call: no flag raised, traps still on (the mode is restored). */
static void expect_no_trace(const char* call)
{
    ++g_calls;
    const int flags = fptrap_flags();
    if (flags != 0) {
        print_error("%s raised flags %#x: %s\n", call, flags, fptrap_case);
        _fail(__FILE__, __LINE__);
    }
#if defined(__GLIBC__)
    assert_int_equal(fegetexcept(), FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
#endif
#if FPTRAP_HAVE_MXCSR
    assert_int_equal(_mm_getcsr() & (1u << 8), 0); /* denormal trap still on */
#endif
}

static cw_params params_of(const fptrap_contact_t* c)
{
    cw_params p;
    cw_params_init(&p);
    p.a = c->a;
    p.b = c->b;
    p.xi_x = c->xi_x;
    p.xi_y = c->xi_y;
    p.phi = c->phi;
    p.pressure = c->pressure;
    p.rolling_direction = c->rolling_direction;
    p.spin_offset = c->contact_options ? 1.0 / 6.0 : CW_SPIN_OFFSET_DEFAULT;
    p.flexibility_blending = c->contact_options;
    return p;
}

static cw_solver* make_solver(const fptrap_grid* g)
{
    cw_grid grid;
    cw_grid_init(&grid);
    grid.kind = g->kind;
    grid.nx = g->nx;
    grid.ny = g->ny;
    grid.box_scale = g->box_scale;
    cw_solver* s = NULL;
    assert_status(cw_solver_create(&grid, &s, NULL, 0), CW_OK);
    return s;
}

/* Every contact of the sweep on every grid, both modes, every getter, and
 * the accumulator fed with each full solve. */
static void test_contact_sweep(void** state)
{
    (void)state;
    for (int gi = 0; gi < FPTRAP_GRIDS; ++gi) {
        const fptrap_grid* g = &fptrap_grids[gi];
        cw_solver* s = make_solver(g);
        cw_accumulator* acc = NULL;
        assert_status(cw_accumulator_create(s, &acc), CW_OK);
        const size_t n = (size_t)g->nx * (size_t)g->ny;
        double* out = malloc(n * sizeof *out);
        double* strips = malloc(3 * (size_t)g->ny * sizeof *strips);
        int* states = malloc(n * sizeof *states);
        assert_true(out && strips && states);
        assert_true(fptrap_enable());
        for (int k = 0; k < FPTRAP_ALL_CONTACTS; ++k) {
            const fptrap_contact_t c = fptrap_contact(k);
            const cw_params p = params_of(&c);
            snprintf(fptrap_case, sizeof fptrap_case,
                     "grid kind %d %dx%d, a %g b %g xi (%g, %g) phi %g pressure %d "
                     "direction %d options %d",
                     g->kind, g->nx, g->ny, c.a, c.b, c.xi_x, c.xi_y, c.phi, c.pressure,
                     c.rolling_direction, c.contact_options);
            cw_result r;
            cw_result_init(&r);
            assert_status(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &r), CW_OK);
            expect_no_trace("cw_solver_solve(FORCES)");
            {
                /* The Jacobian of both simplified models (the contacts have
                 * N > 0; given flexibilities: FASTSIM's only). */
                double J[CW_JACOBIAN_LEN];
                assert_status(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, &r, J,
                                                       CW_JACOBIAN_LEN),
                              CW_OK);
                expect_no_trace("cw_solver_solve_jacobian(FASTSIM)");
                cw_params q = p;
                q.model = CW_MODEL_CALIBRATED;
                if (q.flexibility == CW_FLEX_FROM_MATERIAL) {
                    assert_status(cw_solver_solve_jacobian(s, &q, CW_SOLVE_FORCES, &r, J,
                                                           CW_JACOBIAN_LEN),
                                  CW_OK);
                    expect_no_trace("cw_solver_solve_jacobian(calibrated)");
                }
            }
            assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
            expect_no_trace("cw_solver_solve(FULL)");
            assert_true(cw_result_finite(&r));
            for (int f = CW_FIELD_X; f <= CW_FIELD_WORK_CONSISTENT; ++f) {
                assert_status(cw_solver_get_field(s, f, out, n), CW_OK);
                expect_no_trace("cw_solver_get_field");
            }
            assert_status(cw_solver_get_state(s, states, n), CW_OK);
            assert_status(cw_solver_get_profile(s, strips, strips + g->ny, strips + 2 * g->ny,
                                                (size_t)g->ny),
                          CW_OK);
            assert_status(cw_accumulator_add(acc, s, 0.01), CW_OK);
            expect_no_trace("cw_accumulator_add");
        }
        cw_accumulation tot;
        cw_accumulation_init(&tot);
        assert_status(cw_accumulator_get_totals(acc, &tot), CW_OK);
        assert_status(cw_accumulator_get_field(acc, CW_FIELD_WORK_CONSISTENT, out, n), CW_OK);
        assert_status(cw_accumulator_get_strip_work(acc, strips, (size_t)g->ny), CW_OK);
        expect_no_trace("cw_accumulator getters");
        fptrap_disable();
        free(out);
        free(strips);
        free(states);
        cw_accumulator_destroy(acc);
        cw_solver_destroy(s);
    }
    print_message("%ld calls with traps on, none raised a flag\n", g_calls);
}

/* cw_batch_solve on two threads over the whole sweep (the worker threads
 * run under the library's mode too). */
static void test_batch(void** state)
{
    (void)state;
    const fptrap_grid g = {1, 14, 16, 1.0};
    cw_grid grid;
    cw_grid_init(&grid);
    grid.kind = g.kind;
    grid.nx = g.nx;
    grid.ny = g.ny;
    cw_batch* b = NULL;
    assert_status(cw_batch_create(&grid, 2, &b, NULL, 0), CW_OK);
    cw_params* p = malloc(FPTRAP_ALL_CONTACTS * sizeof *p);
    cw_result* r = malloc(FPTRAP_ALL_CONTACTS * sizeof *r);
    assert_true(p && r);
    for (int k = 0; k < FPTRAP_ALL_CONTACTS; ++k) {
        const fptrap_contact_t c = fptrap_contact(k);
        p[k] = params_of(&c);
        cw_result_init(&r[k]);
    }
    assert_true(fptrap_enable());
    snprintf(fptrap_case, sizeof fptrap_case, "cw_batch_solve, 2 threads");
    for (int mode = CW_SOLVE_FORCES; mode <= CW_SOLVE_FULL; ++mode) {
        assert_status(cw_batch_solve(b, FPTRAP_ALL_CONTACTS, p, mode, r, NULL), CW_OK);
        expect_no_trace("cw_batch_solve");
    }
    fptrap_disable();
    for (int k = 0; k < FPTRAP_ALL_CONTACTS; ++k) assert_true(cw_result_finite(&r[k]));
    free(p);
    free(r);
    cw_batch_destroy(b);
}

static void test_helpers(void** state)
{
    (void)state;
    char msg[128];
    double out[4];
    const double values[] = {0.0, -0.0, 1e-310, 1e-300, 1e-9, 0.5, 1.0, 3.0, 1e9, 1e300,
                             -1.0, NAN, INFINITY, -INFINITY};
    const int nv = (int)(sizeof values / sizeof values[0]);
    assert_true(fptrap_enable());
    fptrap_disable();
    for (int i = 0; i < nv; ++i)
        for (int j = 0; j < nv; ++j) {
            const double u = values[i], v = values[j], v_nu = v * 0.1, half_v = 0.5 * v;
            snprintf(fptrap_case, sizeof fptrap_case, "helpers (%g, %g)", u, v);
            double tx = 0.0, ty = 0.0;
            TRAPPED(cw_kalker_coefficients(u, v_nu, out, msg, sizeof msg),
                    "cw_kalker_coefficients");
            TRAPPED(cw_kalker_flexibilities(u, v, 82e9, 0.28, out, msg, sizeof msg),
                    "cw_kalker_flexibilities");
            TRAPPED(cw_kalker_flexibilities(6e-3, 5e-3, u, v, out, msg, sizeof msg),
                    "cw_kalker_flexibilities");
            TRAPPED(cw_hertz_solve(u, v, 1e5, 9e10, out, msg, sizeof msg), "cw_hertz_solve");
            TRAPPED(cw_hertz_solve(0.5, 2.0, u, v, out, msg, sizeof msg), "cw_hertz_solve");
            TRAPPED(cw_fastsim_normalised(u, v, half_v, u, 5, 5, 1e-3, &tx, &ty, msg, sizeof msg),
                    "cw_fastsim_normalised");
            TRAPPED(cw_fastsim_normalised(0.3, -0.2, u, v, 7, 7, 1e-3, &tx, &ty, msg, sizeof msg),
                    "cw_fastsim_normalised");
        }
}

/* Every double input of cw_params set in turn to a hostile or absurd value:
 * a status (an error naming the input, or success with finite results or
 * zeros), never a trap, never a flag. */
static void test_hostile_and_absurd_inputs(void** state)
{
    (void)state;
    const double values[] = {NAN, INFINITY, -INFINITY, -1.0, -0.0, 0.0, 4.9e-324, 1e-310,
                             1e-300, 1e-200, 1e-150, 1e150, 1e300, 1.7976931348623157e308};
    const int nv = (int)(sizeof values / sizeof values[0]);
    const fptrap_grid g = {1, 12, 9, 1.2};
    cw_solver* s = make_solver(&g);
    long solved = 0, rejected = 0;
    assert_true(fptrap_enable());
    fptrap_disable();
    for (int field = 0; field < 11; ++field)
        for (int i = 0; i < nv; ++i)
            for (int flex = CW_FLEX_FROM_MATERIAL; flex <= CW_FLEX_GIVEN; ++flex) {
                cw_params p;
                cw_params_init(&p);
                p.flexibility = flex;
                p.L1 = 5e-14;
                p.L2 = 6e-14;
                p.L3 = 4e-14;
                p.xi_x = 1e-3;
                p.xi_y = -4e-4;
                p.phi = 0.5;
                p.flexibility_blending = 1;
                p.spin_offset = 1.0 / 6.0;
                double* targets[] = {&p.a,  &p.b,    &p.normal_force, &p.mu, &p.G, &p.nu,
                                     &p.L1, &p.xi_x, &p.xi_y,         &p.phi, &p.spin_offset};
                *targets[field] = values[i];
                snprintf(fptrap_case, sizeof fptrap_case, "params field %d = %g, flexibility %d",
                         field, values[i], flex);
                for (int mode = CW_SOLVE_FORCES; mode <= CW_SOLVE_FULL; ++mode) {
                    cw_result r;
                    cw_result_init(&r);
                    int st = CW_OK;
                    TRAPPED(st = cw_solver_solve(s, &p, mode, &r), "cw_solver_solve");
                    if (st == CW_OK) {
                        assert_true(cw_result_finite(&r));
                        ++solved;
                    } else {
                        assert_true(st == CW_ERR_INVALID_INPUT || st == CW_ERR_NUMERIC);
                        ++rejected;
                    }
                    /* The Jacobian, FASTSIM's and the calibrated model's. */
                    const int models[2] = {CW_MODEL_FASTSIM, CW_MODEL_CALIBRATED};
                    for (int m = 0; m < 2; ++m) {
                        cw_params q = p;
                        q.model = models[m];
                        double J[CW_JACOBIAN_LEN];
                        TRAPPED(st = cw_solver_solve_jacobian(s, &q, mode, &r, J, CW_JACOBIAN_LEN),
                                "cw_solver_solve_jacobian");
                        if (st == CW_OK) {
                            assert_true(cw_result_finite(&r));
                            for (int k = 0; k < CW_JACOBIAN_LEN; ++k) assert_true(isfinite(J[k]));
                            ++solved;
                        } else {
                            assert_true(st == CW_ERR_INVALID_INPUT || st == CW_ERR_NUMERIC);
                            ++rejected;
                        }
                    }
                }
            }
    cw_solver_destroy(s);
    print_message("hostile/absurd inputs: %ld solved, %ld rejected, no trap\n", solved,
                  rejected);
    assert_true(solved > 0 && rejected > 0);
}

/* Wear with traps on: every contact of the sweep on a strip and a uniform
 * grid, both laws, every source, every getter, the profile calls; then
 * every double of cw_wear_params, of a placement, of the strips, the nodes
 * and the update helper set in turn to each hostile value: a status or
 * finite results, never a trap, never a flag. */
static void test_wear(void** state)
{
    (void)state;
    const double values[] = {NAN, INFINITY, -INFINITY, -1.0, -0.0, 0.0, 4.9e-324, 1e-310,
                             1e-300, 1e-200, 1e-150, 1e150, 1e300, 1.7976931348623157e308};
    const int nv = (int)(sizeof values / sizeof values[0]);
    double nodes[60];
    for (int k = 0; k < 60; ++k) nodes[k] = -0.015 + 5e-4 * k;
    long computed = 0, rejected = 0;
    for (int gi = 0; gi < 2; ++gi) {
        const fptrap_grid g = gi ? (fptrap_grid){1, 14, 16, 1.3} : (fptrap_grid){0, 12, 10, 1.0};
        cw_solver* s = make_solver(&g);
        cw_wear* w = NULL;
        assert_status(cw_wear_create(s, &w), CW_OK);
        cw_wear_profile *a = NULL, *b = NULL;
        assert_status(cw_wear_profile_create(nodes, 60, &a, NULL, 0), CW_OK);
        assert_status(cw_wear_profile_create(nodes, 60, &b, NULL, 0), CW_OK);
        const size_t n = (size_t)g.nx * (size_t)g.ny;
        double* out = malloc(n * sizeof *out);
        int* regimes = malloc(n * sizeof *regimes);
        double y[16], width[16], depth[16], par[16], prof[60], upd[60];
        size_t words = 0;
        cw_wear_profile_state_size(a, &words);
        uint64_t* saved = malloc(words * sizeof *saved);
        assert_true(out && regimes && saved);
        assert_true(fptrap_enable());
        for (int k = 0; k < FPTRAP_ALL_CONTACTS; ++k) {
            const fptrap_contact_t c = fptrap_contact(k);
            const cw_params p = params_of(&c);
            snprintf(fptrap_case, sizeof fptrap_case, "wear: grid %d, contact %d", gi, k);
            if (cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL) != CW_OK) continue;
            expect_no_trace("cw_solver_solve");
            for (int law = CW_WEAR_USFD; law <= CW_WEAR_ARCHARD_KTH; ++law)
                for (int src = CW_WEAR_SOURCE_CONSISTENT; src <= CW_WEAR_SOURCE_SLIP; ++src) {
                    cw_wear_params wp;
                    cw_wear_params_init(&wp);
                    wp.law = law;
                    wp.source = src;
                    wp.rolling_speed = 30.0;
                    cw_wear_result r;
                    cw_wear_result_init(&r);
                    const int st = cw_wear_compute(w, s, &wp, &r);
                    expect_no_trace("cw_wear_compute");
                    if (st != CW_OK) {
                        assert_int_equal(st, CW_ERR_NUMERIC);
                        ++rejected;
                        continue;
                    }
                    ++computed;
                    for (int f = CW_WEAR_FIELD_RATE; f <= CW_WEAR_FIELD_SLIDING; ++f) {
                        assert_status(cw_wear_get_field(w, f, out, n), CW_OK);
                        for (size_t e = 0; e < n; ++e) assert_true(isfinite(out[e]));
                    }
                    assert_status(cw_wear_get_regimes(w, regimes, n), CW_OK);
                    assert_status(cw_wear_get_strips(w, y, width, depth, par, (size_t)g.ny),
                                  CW_OK);
                    expect_no_trace("cw_wear getters");
                    cw_wear_profile_add(a, w, 1e-3 * (k % 9 - 4), 1, 0.05 * (k % 5), 100.0);
                    cw_wear_profile_add_strips(b, y, width, par, (size_t)g.ny, 2e-3, -1, 0.3,
                                               7.0);
                    expect_no_trace("cw_wear_profile_add");
                }
        }
        snprintf(fptrap_case, sizeof fptrap_case, "wear profile getters, grid %d", gi);
        cw_wear_profile_totals t;
        cw_wear_profile_totals_init(&t);
        assert_status(cw_wear_profile_get_depth(a, CW_WEAR_DEPTH_HEIGHT, prof, 60), CW_OK);
        assert_status(cw_wear_profile_get_totals(a, &t), CW_OK);
        assert_status(cw_wear_profile_merge(a, b), CW_OK);
        assert_status(cw_wear_profile_get_state(b, saved, words), CW_OK);
        assert_status(cw_wear_profile_add_state(a, saved, words), CW_OK);
        assert_status(cw_wear_profile_update(nodes, prof, prof, 60, 1e-3, upd, 60, NULL, 0), CW_OK);
        expect_no_trace("cw_wear_profile calls");
        fptrap_disable();
        /* Hostile values, one input at a time. */
        for (int i = 0; i < nv; ++i) {
            const double v = values[i];
            snprintf(fptrap_case, sizeof fptrap_case, "wear hostile %g", v);
            for (int field = 0; field < 17; ++field)
                for (int law = CW_WEAR_USFD; law <= CW_WEAR_ARCHARD_KTH; ++law) {
                    cw_wear_params wp;
                    cw_wear_params_init(&wp);
                    wp.law = law;
                    wp.rolling_speed = 30.0;
                    double* targets[] = {&wp.density,  &wp.rolling_speed, &wp.pass_length,
                                         &wp.usfd_k1,  &wp.usfd_t1,       &wp.usfd_k2,
                                         &wp.usfd_t2,  &wp.usfd_k3,       &wp.usfd_c3,
                                         &wp.hardness, &wp.kth_v1,        &wp.kth_v2,
                                         &wp.kth_seizure_ratio, &wp.kth_k_seizure,
                                         &wp.kth_k_slow, &wp.kth_k_severe, &wp.kth_k_fast};
                    *targets[field] = v;
                    cw_wear_result r;
                    cw_wear_result_init(&r);
                    int st = CW_OK;
                    TRAPPED(st = cw_wear_compute(w, s, &wp, &r), "cw_wear_compute hostile");
                    if (st == CW_OK) {
                        const double tot[] = {r.mass_per_distance, r.mass_per_pass, r.max_depth,
                                              r.work, r.volume_per_distance};
                        for (int q = 0; q < 5; ++q) assert_true(isfinite(tot[q]));
                    }
                }
            double hy[3] = {-1e-3, 0.0, 1e-3}, hw[3] = {1e-3, 1e-3, 1e-3}, hd[3] = {1e-9, 2e-9, 1e-9};
            double* strip_targets[] = {&hy[1], &hw[1], &hd[1]};
            for (int q = 0; q < 3; ++q) {
                const double keep = *strip_targets[q];
                *strip_targets[q] = v;
                TRAPPED(cw_wear_profile_add_strips(a, hy, hw, hd, 3, 0.0, 1, 0.2, 5.0),
                        "cw_wear_profile_add_strips hostile strip");
                *strip_targets[q] = keep;
            }
            TRAPPED(cw_wear_profile_add_strips(a, hy, hw, hd, 3, v, 1, 0.2, 5.0), "hostile s0");
            TRAPPED(cw_wear_profile_add_strips(a, hy, hw, hd, 3, 0.0, 1, v, 5.0), "hostile angle");
            TRAPPED(cw_wear_profile_add_strips(a, hy, hw, hd, 3, 0.0, 1, 0.2, v), "hostile passes");
            double bad_nodes[60], old[60], dep[60];
            for (int k = 0; k < 60; ++k) {
                bad_nodes[k] = nodes[k];
                old[k] = 1e-3;
                dep[k] = 1e-6;
            }
            cw_wear_profile* p = NULL;
            bad_nodes[30] = v;
            TRAPPED(cw_wear_profile_create(bad_nodes, 60, &p, NULL, 0), "hostile node");
            cw_wear_profile_destroy(p);
            TRAPPED(cw_wear_profile_update(bad_nodes, old, dep, 60, 1e-3, upd, 60, NULL, 0),
                    "hostile node (update)");
            old[7] = v;
            TRAPPED(cw_wear_profile_update(nodes, old, dep, 60, 1e-3, upd, 60, NULL, 0),
                    "hostile old profile");
            old[7] = 1e-3;
            dep[7] = v;
            TRAPPED(cw_wear_profile_update(nodes, old, dep, 60, 1e-3, upd, 60, NULL, 0),
                    "hostile depth");
            TRAPPED(cw_wear_profile_update(nodes, old, old, 60, v, upd, 60, NULL, 0),
                    "hostile smoothing");
        }
        assert_status(cw_wear_profile_get_depth(a, CW_WEAR_DEPTH_NORMAL, prof, 60), CW_OK);
        for (int k = 0; k < 60; ++k) assert_true(isfinite(prof[k]) && prof[k] >= 0.0);
        free(out);
        free(regimes);
        free(saved);
        cw_wear_profile_destroy(a);
        cw_wear_profile_destroy(b);
        cw_wear_destroy(w);
        cw_solver_destroy(s);
    }
    print_message("wear: %ld computed, %ld refused (overflow), no trap\n", computed, rejected);
    assert_true(computed > 0);
}

/* The caller's rounding mode (toward zero here) and flush bits do not leak
 * into the library, and come back unchanged. */
static void test_caller_mode_restored_and_irrelevant(void** state)
{
    (void)state;
    const fptrap_grid g = {0, 20, 20, 1.0};
    cw_solver* s = make_solver(&g);
    cw_params p;
    cw_params_init(&p);
    p.xi_x = 1e-3;
    p.xi_y = 3e-4;
    p.phi = 0.7;
    cw_result nearest, toward_zero;
    cw_result_init(&nearest);
    cw_result_init(&toward_zero);
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &nearest), CW_OK);
    assert_true(fptrap_enable());
    assert_int_equal(fesetround(FE_TOWARDZERO), 0);
#if FPTRAP_HAVE_MXCSR
    const unsigned before = _mm_getcsr();
#endif
    snprintf(fptrap_case, sizeof fptrap_case, "rounding toward zero");
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &toward_zero), CW_OK);
    assert_int_equal(fegetround(), FE_TOWARDZERO);
#if FPTRAP_HAVE_MXCSR
    assert_int_equal(_mm_getcsr(), before);
#endif
    fesetround(FE_TONEAREST);
    fptrap_disable();
    assert_memory_equal(&nearest, &toward_zero, sizeof nearest);
    cw_solver_destroy(s);
}

int main(void)
{
    /* No way to trap here (not glibc on x86-64): SKIP, not a pass. */
    const int available = fptrap_enable();
    fptrap_disable();
    if (!available) return FPTRAP_SKIP;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_contact_sweep),
        cmocka_unit_test(test_batch),
        cmocka_unit_test(test_helpers),
        cmocka_unit_test(test_hostile_and_absurd_inputs),
        cmocka_unit_test(test_wear),
        cmocka_unit_test(test_caller_mode_restored_and_irrelevant),
    };
    return cmocka_run_group_tests_name("robustness_fptrap", tests, NULL, NULL);
}
