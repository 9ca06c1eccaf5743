/* A friction law of the slip speed through the C ABI (cw_params.friction_law
 * and its terms, friction_speed, Spiryagin's k0, alpha_inf, beta, the
 * memory; cw_friction_polach; cw_result.mu_static, mu_min, mu_max):
 * CONTACT's tractcurv example (tests/data/contact_tractcurv.csv, series 3:
 * FASTSIM with Coulomb's 0.33; series 4: FASTSIM with the exponential law at
 * the contact's slip speed and Spiryagin's reduction) to its printed digits;
 * the law at every element against the full-sliding closed form; Coulomb's
 * results bitwise whatever the law's unread fields hold; every bad input
 * refused naming it; the half-speed plausibility rule. */
#include "capi_fixtures.h"
#include "contact_csv.h"
#include "tractcurv_case.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TRACTCURV_N CW_TRACTCURV_N
#define TRACTCURV_V CW_TRACTCURV_V

static cw_grid tractcurv_grid(void) { return cw_tractcurv_grid(); }
static cw_params tractcurv(double xi_x) { return cw_tractcurv_params(xi_x); }
static void series4(cw_params* p) { cw_tractcurv_series4(p, 1); }

/* ---- CONTACT's printed table */

typedef struct {
    int series, nadh, nslip;
    double cksi, fx; /* FX_over_FSTAT_FN */
    double tol;      /* half a unit of its last printed digit */
} tractcurv_row;

static int read_tractcurv(tractcurv_row* rows, int max)
{
    FILE* f = fopen(CW_TEST_DATA_DIR "/contact_tractcurv.csv", "r");
    assert_non_null(f);
    char line[1024], *fields[40];
    assert_non_null(fgets(line, sizeof line, f));
    const int n = cw_csv_split(line, fields, 40);
    const int c_series = cw_csv_column(fields, n, "series"), c_cksi = cw_csv_column(fields, n, "CKSI"),
              c_fx = cw_csv_column(fields, n, "FX_over_FSTAT_FN"),
              c_nadh = cw_csv_column(fields, n, "NADH"), c_nslip = cw_csv_column(fields, n, "NSLIP");
    assert_true(c_series >= 0 && c_cksi >= 0 && c_fx >= 0 && c_nadh >= 0 && c_nslip >= 0);
    int count = 0;
    while (count < max && fgets(line, sizeof line, f)) {
        if (cw_csv_split(line, fields, 40) <= c_nslip) continue;
        tractcurv_row* r = &rows[count++];
        r->series = atoi(fields[c_series]);
        r->cksi = atof(fields[c_cksi]);
        r->fx = atof(fields[c_fx]);
        r->tol = cw_printed_half_unit(fields[c_fx]);
        r->nadh = atoi(fields[c_nadh]);
        r->nslip = atoi(fields[c_nslip]);
    }
    fclose(f);
    return count;
}

/* Series 3 and 4, every creepage: Fx/(mu_s N) within half a unit of
 * CONTACT's last printed digit plus 6e-5 (creepwork's FASTSIM and
 * CONTACT's differ by up to 5e-5 on this grid with Coulomb's law already),
 * and series 4's slip area element for element. */
static void tractcurv_series_3_and_4(void** state)
{
    (void)state;
    tractcurv_row rows[200];
    const int n = read_tractcurv(rows, 200);
    const cw_grid g = tractcurv_grid();
    cw_solver* s = NULL;
    assert_status(cw_solver_create(&g, &s, NULL, 0), CW_OK);
    int seen[5] = {0};
    for (int k = 0; k < n; ++k) {
        const tractcurv_row* r = &rows[k];
        if (r->series != 3 && r->series != 4) continue;
        cw_params p = tractcurv(r->cksi);
        double mu_s = 0.33;
        if (r->series == 3) p.mu = 0.33;
        else series4(&p), mu_s = 0.36;
        cw_result res;
        cw_result_init(&res);
        assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &res), CW_OK);
        assert_close(res.Fx / (mu_s * TRACTCURV_N), r->fx, 0.0, r->tol + 6e-5);
        assert_close(res.mu_static, mu_s, 0.0, 1e-15);
        if (r->series == 4) {
            assert_int_equal(res.n_slip, r->nslip);
            /* One mu for the contact: mu(w), w = V xi, below mu_s. */
            const double w = TRACTCURV_V * fabs(r->cksi);
            const double mu_w = 0.1368 + 0.2232 * exp(-log(2.0) * w / 0.990);
            assert_close(res.mu_min, mu_w, 0.0, 1e-15);
            assert_close(res.mu_max, mu_w, 0.0, 1e-15);
        } else {
            assert_true(res.mu_min == 0.33 && res.mu_max == 0.33);
        }
        ++seen[r->series];
    }
    assert_int_equal(seen[3], 30);
    assert_int_equal(seen[4], 30);
    cw_solver_destroy(s);
}

/* The law at every element's own slip speed: where every element slides
 * each slips at about V xi, so Fx/(mu_s N) meets series 4's full-sliding
 * rows (CONTACT: NADH = 0) and Polach's closed form A + (1 - A) exp(-B xi V)
 * within 2e-4 (Polach's mu0 = 0.36, A = 0.38, B = 0.7 s/m through
 * cw_friction_polach; no slope reduction: in full sliding it does not
 * matter). */
static void local_law_in_full_sliding(void** state)
{
    (void)state;
    tractcurv_row rows[200];
    const int n = read_tractcurv(rows, 200);
    const cw_grid g = tractcurv_grid();
    cw_solver* s = NULL;
    assert_status(cw_solver_create(&g, &s, NULL, 0), CW_OK);
    int checked = 0;
    for (int k = 0; k < n; ++k) {
        const tractcurv_row* r = &rows[k];
        if (r->series != 4 || r->nadh != 0) continue;
        cw_params p = tractcurv(r->cksi);
        assert_status(cw_friction_polach(0.36, 0.38, 0.7, &p, NULL, 0), CW_OK);
        cw_result res;
        cw_result_init(&res);
        assert_status(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &res), CW_OK);
        const double closed = 0.38 + 0.62 * exp(-0.7 * r->cksi * TRACTCURV_V);
        assert_close(-res.Fx / (0.36 * TRACTCURV_N), closed, 0.0, 2e-4);
        assert_close(res.Fx / (0.36 * TRACTCURV_N), r->fx, 0.0, 2e-4);
        assert_int_equal(res.n_adhesion, 0);
        /* Every element slips near V xi: mu within the law's range there. */
        assert_true(res.mu_min <= res.mu_max && res.mu_max < 0.36);
        assert_close(res.mu_min, 0.36 * closed, 0.0, 5e-3);
        ++checked;
    }
    assert_int_equal(checked, 6); /* 12.5 % to 25 % */
    cw_solver_destroy(s);
}

/* The Jacobian of Fx, Fy, Mz by xi_x, xi_y, phi, N through
 * cw_solver_solve_jacobian, the law at every element and at the global slip
 * speed, before the peak (0.4 %) and past it (2 % at every element, 5 % at
 * the global slip speed, whose peak is series 4's at 2.2 %), with lateral
 * creepage and spin: against central differences of the same door, the
 * worst entry relative to its row's scale sum_c |J_rc| scale_c, over the
 * best of four steps that change no element's state, within 1e-4. Past the
 * peak dFx/dxi_x > 0 (|Fx| falls), before it < 0. */
static double jacobian_error(cw_solver* s, const cw_params* p, int mode, const double* J,
                             int slips)
{
    const double scale[4] = {fabs(p->xi_x), fabs(p->xi_x), fabs(p->xi_x) / p->a,
                             p->normal_force};
    double best = INFINITY;
    const double rels[4] = {1e-3, 1e-4, 1e-5, 1e-6};
    for (int k = 0; k < 4; ++k) {
        double fd[3][4], worst = 0.0;
        int changed = 0;
        for (int c = 0; c < 4; ++c) {
            cw_params up = *p, down = *p;
            double* u[4] = {&up.xi_x, &up.xi_y, &up.phi, &up.normal_force};
            double* d[4] = {&down.xi_x, &down.xi_y, &down.phi, &down.normal_force};
            *u[c] += rels[k] * scale[c];
            *d[c] -= rels[k] * scale[c];
            cw_result a, b;
            cw_result_init(&a);
            cw_result_init(&b);
            assert_status(cw_solver_solve(s, &up, mode, &a), CW_OK);
            assert_status(cw_solver_solve(s, &down, mode, &b), CW_OK);
            changed |= a.n_slip != slips || b.n_slip != slips;
            const double h2 = 2 * rels[k] * scale[c];
            fd[0][c] = (a.Fx - b.Fx) / h2;
            fd[1][c] = (a.Fy - b.Fy) / h2;
            fd[2][c] = (a.Mz - b.Mz) / h2;
        }
        for (int r = 0; r < 3; ++r) {
            double row = 0.0;
            for (int c = 0; c < 4; ++c) row += fabs(J[4 * r + c]) * scale[c];
            for (int c = 0; c < 4; ++c)
                worst = fmax(worst, fabs(J[4 * r + c] - fd[r][c]) * scale[c] / row);
        }
        if (!changed) best = fmin(best, worst);
    }
    return best;
}

static void jacobian_across_the_peak(void** state)
{
    (void)state;
    const cw_grid g = tractcurv_grid();
    cw_solver* s = NULL;
    assert_status(cw_solver_create(&g, &s, NULL, 0), CW_OK);
    for (int global = 0; global <= 1; ++global)
        for (int k = 0; k < 4; ++k) {
            /* The peak: about 0.5 % at every element, 2.2 % at the global slip speed. */
            const double xi = k < 2 ? 0.004 : global ? 0.05 : 0.02;
            const int lateral = k % 2;
            cw_params p = tractcurv(xi);
            cw_tractcurv_series4(&p, global);
            p.xi_y = 0.3 * lateral * xi;
            p.phi = 0.2 * lateral * xi / p.a;
            const int mode = global ? CW_SOLVE_FULL : CW_SOLVE_FORCES;
            cw_result r, plain;
            cw_result_init(&r);
            cw_result_init(&plain);
            double J[CW_JACOBIAN_LEN];
            assert_status(cw_solver_solve_jacobian(s, &p, mode, &r, J, CW_JACOBIAN_LEN), CW_OK);
            assert_status(cw_solver_solve(s, &p, mode, &plain), CW_OK);
            assert_true(r.Fx == plain.Fx && r.Fy == plain.Fy && r.Mz == plain.Mz);
            const double err = jacobian_error(s, &p, mode, J, r.n_slip);
            print_message("%s, xi_x %.3f%s: dFx/dxi_x %.6g N, worst relative error %.2e\n",
                          global ? "global" : "local", xi, lateral ? " with xi_y, phi" : "",
                          J[0], err);
            assert_true(err <= 1e-4);
            if (!lateral) assert_true(k < 2 ? J[0] < 0.0 : J[0] > 0.0);
        }
    cw_solver_destroy(s);
}

/* Polach's (mu0, A, B) written as the exponential law: mu_kin = A mu0,
 * mu_e1 = (1 - A) mu0, s_h1 = ln2 / B (CONTACT's tractcurv: FKIN 0.1368,
 * FEXP1 0.2232, SABSH1 990 mm/s); bad values named. */
static void polach_inputs(void** state)
{
    (void)state;
    cw_params p;
    cw_params_init(&p);
    p.mu_e2 = 0.5; /* overwritten: Polach's law has one term */
    assert_status(cw_friction_polach(0.36, 0.38, 0.7, &p, NULL, 0), CW_OK);
    assert_int_equal(p.friction_law, CW_FRICTION_EXPONENTIAL);
    assert_close(p.mu, 0.1368, 1e-15, 0.0);
    assert_close(p.mu_e1, 0.2232, 1e-15, 0.0);
    assert_close(p.s_h1, log(2.0) / 0.7, 1e-15, 0.0);
    assert_true(p.mu_e2 == 0.0 && p.s_h2 == 0.0);
    char msg[256];
    assert_status(cw_friction_polach(0.36, 1.5, 0.7, &p, msg, sizeof msg), CW_ERR_INVALID_INPUT);
    assert_names(msg, "polach_A");
    assert_status(cw_friction_polach(0.36, 0.38, 0.0, &p, msg, sizeof msg), CW_ERR_INVALID_INPUT);
    assert_names(msg, "polach_B");
    assert_status(cw_friction_polach(-0.1, 0.38, 0.7, &p, msg, sizeof msg), CW_ERR_INVALID_INPUT);
    assert_names(msg, "mu");
    assert_status(cw_friction_polach(0.36, 0.38, 0.7, NULL, msg, sizeof msg), CW_ERR_NULL_POINTER);
    p.struct_size = offsetof(cw_params, V);
    assert_status(cw_friction_polach(0.36, 0.38, 0.7, &p, msg, sizeof msg), CW_ERR_STRUCT_SIZE);
}

/* Coulomb's law (the default) reads none of the law's fields: every model
 * gives the same bits with them at their defaults, holding values that a
 * law would refuse, and cut off by struct_size. */
static void coulomb_ignores_the_law_fields(void** state)
{
    (void)state;
    const struct {
        cw_grid grid;
        int model;
    } cases[] = {
        {cw_test_grid(CW_GRID_KALKER_STRIPS, 15, 12, 1.0), CW_MODEL_FASTSIM},
        {cw_test_grid(CW_GRID_KALKER_STRIPS, 15, 12, 1.0), CW_MODEL_CALIBRATED},
        {cw_test_grid(CW_GRID_UNIFORM, 14, 12, 1.1), CW_MODEL_EXACT},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        cw_solver* s = NULL;
        assert_status(cw_solver_create(&cases[c].grid, &s, NULL, 0), CW_OK);
        cw_params base;
        cw_test_case(2, &base);
        base.model = cases[c].model;
        base.warm_start = 0;
        cw_result r[3];
        double jac[3][CW_JACOBIAN_LEN];
        for (int k = 0; k < 3; ++k) {
            cw_params p = base;
            if (k == 1) p.mu_e1 = -1.0, p.s_h1 = 0.0, p.k0 = -2.0, p.alpha_inf = 7.0;
            if (k == 2) p.friction_law = 99, p.struct_size = offsetof(cw_params, friction_law);
            cw_result_init(&r[k]);
            assert_status(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FULL, &r[k], jac[k],
                                                   CW_JACOBIAN_LEN),
                          CW_OK);
        }
        for (int k = 1; k < 3; ++k) {
            assert_memory_equal(&r[k], &r[0], sizeof r[0]);
            assert_memory_equal(jac[k], jac[0], sizeof jac[0]);
        }
        assert_true(r[0].n_slip > 0);
        assert_true(r[0].mu_static == base.mu && r[0].mu_min == base.mu && r[0].mu_max == base.mu);
        cw_solver_destroy(s);
    }
}

/* Full mode with series 4's law at every element (and with friction
 * memory): the energy-consistent work map through cw_solver_get_field sums
 * to W_macro within 1e-12, is >= 0 and 0 wherever the state is not slip
 * (the march's energy identity); the forces are forces mode's bits. */
static void local_law_work_map(void** state)
{
    (void)state;
    const cw_grid g = cw_tractcurv_grid();
    cw_solver* s = NULL;
    assert_status(cw_solver_create(&g, &s, NULL, 0), CW_OK);
    const size_t n = (size_t)g.nx * (size_t)g.ny;
    double* work = malloc(n * sizeof *work);
    int* st = malloc(n * sizeof *st);
    assert_non_null(work);
    assert_non_null(st);
    const double xis[] = {0.002, 0.004, 0.02};
    for (int memory = 0; memory < 2; ++memory)
        for (int k = 0; k < 3; ++k) {
            cw_params p = tractcurv(xis[k]);
            cw_tractcurv_series4(&p, 0);
            p.memory_distance = memory ? 3e-6 : 0.0;
            p.memory_s0 = 1e-3;
            cw_result forces, full;
            cw_result_init(&forces);
            cw_result_init(&full);
            assert_status(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &forces), CW_OK);
            assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &full), CW_OK);
            assert_true(full.Fx == forces.Fx && full.Fy == forces.Fy && full.Mz == forces.Mz);
            assert_true(full.W_macro > 0.0 && full.n_slip > 0);
            assert_status(cw_solver_get_field(s, CW_FIELD_WORK_CONSISTENT, work, n), CW_OK);
            assert_status(cw_solver_get_state(s, st, n), CW_OK);
            double sum = 0.0;
            for (size_t e = 0; e < n; ++e) {
                assert_true(work[e] >= 0.0);
                if (st[e] != CW_STATE_SLIP) assert_true(work[e] == 0.0);
                sum += work[e];
            }
            assert_close(sum, full.W_macro, 1e-12, 0.0);
        }
    free(work);
    free(st);
    cw_solver_destroy(s);
}

/* Every bad friction input is refused with a message naming it. */
typedef struct {
    const char* what;
    int status;
    const char* name;
    int mode;
} bad_case;

static void spoil(int k, cw_params* p, cw_grid* g)
{
    series4(p);
    p->friction_speed = CW_FRICTION_SPEED_LOCAL;
    switch (k) {
    case 0: p->V = 0.0; break;
    case 1: p->mu_e1 = -0.1; break;
    case 2: p->s_h1 = 0.0; break;
    case 3: p->mu_e2 = 0.1, p->s_h2 = -1.0; break;
    case 4: p->mu = NAN; break;
    case 5: p->friction_law = 1; break;
    case 6: p->friction_speed = 2; break;
    case 7: p->friction_speed = CW_FRICTION_SPEED_GLOBAL, p->k0 = 0.0; break;
    case 8: p->friction_speed = CW_FRICTION_SPEED_GLOBAL, p->alpha_inf = 1.5; break;
    case 9: p->friction_speed = CW_FRICTION_SPEED_GLOBAL, p->beta = -1.0; break;
    case 10: p->memory_distance = -1e-3; break;
    case 11: p->memory_s0 = NAN; break;
    case 12: p->friction_speed = CW_FRICTION_SPEED_GLOBAL, p->memory_distance = 1e-3; break;
    case 13: p->model = CW_MODEL_CALIBRATED; break;
    case 14: p->model = CW_MODEL_EXACT, p->memory_distance = 1e-3, p->memory_s0 = -1e-3;
             *g = cw_test_grid(CW_GRID_UNIFORM, 14, 12, 1.1); break;
    case 15: p->V = NAN; break; /* full mode: named as in forces mode */
    case 16: p->s_h1 = INFINITY; break;
    default: p->model = CW_MODEL_EXACT, p->friction_law = CW_FRICTION_COULOMB;
             p->friction_speed = CW_FRICTION_SPEED_GLOBAL;
             *g = cw_test_grid(CW_GRID_UNIFORM, 14, 12, 1.1); break;
    }
}

static void bad_inputs_are_named(void** state)
{
    (void)state;
    static const bad_case cases[] = {
        {"V = 0 with a law", CW_ERR_INVALID_INPUT, "V", CW_SOLVE_FORCES},
        {"mu_e1 < 0", CW_ERR_INVALID_INPUT, "mu_e1", CW_SOLVE_FORCES},
        {"s_h1 = 0", CW_ERR_INVALID_INPUT, "s_h1", CW_SOLVE_FORCES},
        {"s_h2 < 0", CW_ERR_INVALID_INPUT, "s_h2", CW_SOLVE_FORCES},
        {"mu NaN", CW_ERR_INVALID_INPUT, "mu", CW_SOLVE_FORCES},
        {"friction_law 1", CW_ERR_UNKNOWN_OPTION, "friction_law", CW_SOLVE_FORCES},
        {"friction_speed 2", CW_ERR_UNKNOWN_OPTION, "friction_speed", CW_SOLVE_FORCES},
        {"k0 = 0", CW_ERR_INVALID_INPUT, "k0", CW_SOLVE_FORCES},
        {"alpha_inf > 1", CW_ERR_INVALID_INPUT, "alpha_inf", CW_SOLVE_FORCES},
        {"beta < 0", CW_ERR_INVALID_INPUT, "beta", CW_SOLVE_FORCES},
        {"memory_distance < 0", CW_ERR_INVALID_INPUT, "memory_distance", CW_SOLVE_FORCES},
        {"memory_s0 NaN", CW_ERR_INVALID_INPUT, "memory_s0", CW_SOLVE_FORCES},
        {"memory with global", CW_ERR_INVALID_INPUT, "memory_distance", CW_SOLVE_FORCES},
        {"calibrated", CW_ERR_INVALID_INPUT, "friction_law", CW_SOLVE_FORCES},
        {"memory_s0 < 0 with exact", CW_ERR_INVALID_INPUT, "memory_s0", CW_SOLVE_FORCES},
        {"V NaN, full mode", CW_ERR_INVALID_INPUT, "V", CW_SOLVE_FULL},
        {"s_h1 Inf", CW_ERR_INVALID_INPUT, "s_h1", CW_SOLVE_FORCES},
        {"global with exact", CW_ERR_INVALID_INPUT, "friction_speed", CW_SOLVE_FORCES},
    };
    for (int k = 0; k < (int)(sizeof cases / sizeof cases[0]); ++k) {
        cw_params p = tractcurv(0.01);
        cw_grid g = cw_test_grid(CW_GRID_KALKER_STRIPS, 15, 12, 1.0);
        spoil(k, &p, &g);
        cw_solver* s = NULL;
        assert_status(cw_solver_create(&g, &s, NULL, 0), CW_OK);
        cw_result res;
        cw_result_init(&res);
        const int st = cw_solver_solve(s, &p, cases[k].mode, &res);
        if (st != cases[k].status)
            fail_msg("%s: status %d, expected %d (%s)", cases[k].what, st, cases[k].status,
                     cw_solver_last_error(s));
        assert_names(cw_solver_last_error(s), cases[k].name);
        cw_solver_destroy(s);
    }
}

/* A half speed in mm/s typed as m/s (CONTACT's SABSH1 990 mm/s kept as
 * 990) is found by cw_params_check, naming s_h1; 0.99 m/s is not, nor a
 * term that is absent or under Coulomb's law. */
static void half_speed_in_mm_per_s_is_warned(void** state)
{
    (void)state;
    cw_grid g;
    cw_grid_init(&g);
    cw_params p = tractcurv(0.01);
    p.friction_law = CW_FRICTION_EXPONENTIAL;
    p.mu_e1 = 0.2232;
    cw_check c[8];
    for (int k = 0; k < 8; ++k) cw_check_init(&c[k]);
    size_t found = 0;
    const double values[] = {990.0, 50.5, 49.5, 0.99};
    for (int k = 0; k < 4; ++k) {
        p.s_h1 = values[k];
        assert_status(cw_params_check(&g, &p, 1, c, 8, &found), CW_OK);
        const int warned = k < 2;
        assert_int_equal(found, (size_t)warned);
        if (warned) {
            assert_int_equal(c[0].rule, CW_CHECK_HALF_SPEED);
            assert_string_equal(c[0].input, "s_h1");
            assert_string_equal(c[0].unit, "m/s");
            assert_true(c[0].value == values[k]);
            assert_non_null(strstr(c[0].reason, "mm/s typed as m/s"));
        }
    }
    p.s_h1 = 990.0;
    p.mu_e1 = 0.0; /* the term is absent */
    assert_status(cw_params_check(&g, &p, 1, c, 8, &found), CW_OK);
    assert_int_equal(found, 0);
    p.mu_e1 = 0.2232;
    p.friction_law = CW_FRICTION_COULOMB;
    assert_status(cw_params_check(&g, &p, 1, c, 8, &found), CW_OK);
    assert_int_equal(found, 0);
    p.friction_law = CW_FRICTION_RATIONAL;
    p.mu_e2 = 0.1;
    p.s_h2 = 400.0;
    assert_status(cw_params_check(&g, &p, 1, c, 8, &found), CW_OK);
    assert_int_equal(found, 2);
    assert_string_equal(c[1].input, "s_h2");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(tractcurv_series_3_and_4),
        cmocka_unit_test(local_law_in_full_sliding),
        cmocka_unit_test(jacobian_across_the_peak),
        cmocka_unit_test(local_law_work_map),
        cmocka_unit_test(polach_inputs),
        cmocka_unit_test(coulomb_ignores_the_law_fields),
        cmocka_unit_test(bad_inputs_are_named),
        cmocka_unit_test(half_speed_in_mm_per_s_is_warned),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
