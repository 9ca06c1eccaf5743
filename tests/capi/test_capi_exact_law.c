/* The exact model under a friction law of the slip speed through the C ABI
 * (model = CW_MODEL_EXACT with friction_law, mu = mu_kin): CONTACT's exact
 * theory on its tractcurv contact with the exponential law alone
 * (tests/data/contact_tractcurv_exponential.csv, FKIN 0.14, FEXP1 0.19,
 * SABSH1 1250 mm/s) on the uniform grid and on a gap grid holding the same
 * Hertzian gap, to every printed digit of Fx, Fy and Mz with CONTACT's slip
 * area (the bar of test_core_exact_law); mu_min and mu_max against the law
 * at the exported slip speeds; full mode's work maps against W_macro; a
 * Coulomb solve after a law's on one handle gives a fresh handle's bits;
 * with friction memory (MEMDST 3 um, MEM_S0 1 mm/s) CONTACT's rows of
 * tests/data/contact_tractcurv_memory.csv on both grids, to every printed
 * digit, and its Jacobian's xi_x column against central differences. */
#include "capi_fixtures.h"
#include "contact_csv.h"
#include "tractcurv_case.h"
#include "tractcurv_gap.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define N_TC CW_TRACTCURV_N
#define V_TC CW_TRACTCURV_V
#define MU_S 0.33 /* mu(0) = 0.14 + 0.19 */
#define MAX_ROWS 64

/* The contact of test_core_exact_law (tests/core/tractcurv_exact.hpp):
 * Hertz's pressure on CONTACT's printed semi-axes, the exponential law
 * FKIN 0.14, FEXP1 0.19, SABSH1 1.25 m/s at V = 10 m/s. */
static cw_params law_contact(double xi_x, double xi_y, double phi)
{
    cw_params p = cw_tractcurv_exact_params(xi_x, xi_y, phi);
    p.friction_law = CW_FRICTION_EXPONENTIAL;
    p.mu = 0.14;
    p.mu_e1 = 0.19;
    p.s_h1 = 1.25;
    return p;
}

static double law_mu(double s) { return 0.14 + 0.19 * exp(-log(2.0) * s / 1.25); }

/* ---- CONTACT's rows */

typedef struct {
    double cksi, ceta, cphi; /* cphi [1/m] */
    char fx[32], fy[32], mz[32];
    int ncon, nslip;
} exp_row;

static int read_rows(const char* file, exp_row* rows, int max)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", CW_TEST_DATA_DIR, file);
    FILE* f = fopen(path, "r");
    assert_non_null(f);
    char line[1024], *fields[40];
    assert_non_null(fgets(line, sizeof line, f));
    const int n = cw_csv_split(line, fields, 40);
    const int c[8] = {cw_csv_column(fields, n, "CKSI"),
                      cw_csv_column(fields, n, "CETA"),
                      cw_csv_column(fields, n, "CPHI_per_mm"),
                      cw_csv_column(fields, n, "FX_over_FSTAT_FN"),
                      cw_csv_column(fields, n, "FY_over_FSTAT_FN"),
                      cw_csv_column(fields, n, "MZ_Nmm"),
                      cw_csv_column(fields, n, "NCON"),
                      cw_csv_column(fields, n, "NSLIP")};
    for (int k = 0; k < 8; ++k) assert_true(c[k] >= 0);
    int count = 0;
    while (count < max && fgets(line, sizeof line, f)) {
        if (cw_csv_split(line, fields, 40) < n) continue;
        exp_row* r = &rows[count++];
        r->cksi = atof(fields[c[0]]);
        r->ceta = atof(fields[c[1]]);
        r->cphi = 1e3 * atof(fields[c[2]]);
        snprintf(r->fx, sizeof r->fx, "%s", fields[c[3]]);
        snprintf(r->fy, sizeof r->fy, "%s", fields[c[4]]);
        snprintf(r->mz, sizeof r->mz, "%s", fields[c[5]]);
        r->ncon = atoi(fields[c[6]]);
        r->nslip = atoi(fields[c[7]]);
    }
    fclose(f);
    return count;
}

/* |ours - printed| in halves of the printed number's last digit. */
static double digits(double ours, const char* printed)
{
    return fabs(ours - atof(printed)) / cw_printed_half_unit(printed);
}

/* Every row of CONTACT's table in file (rows of them) on grid g (gap: the
 * Hertzian gap h), with friction memory over memory_distance [m] (0: none,
 * else MEM_S0 1 mm/s): the worst difference in halves of a printed digit;
 * the contact and slip areas element for element. */
static double contact_rows(const cw_grid* g, const double* h, const char* file, int rows_expected,
                           double memory_distance)
{
    static exp_row rows[MAX_ROWS];
    const int n = read_rows(file, rows, MAX_ROWS);
    assert_int_equal(n, rows_expected);
    cw_solver* s = NULL;
    assert_status(cw_solver_create(g, &s, NULL, 0), CW_OK);
    double worst = 0.0;
    for (int k = 0; k < n; ++k) {
        const exp_row* r = &rows[k];
        cw_params p = law_contact(r->cksi, r->ceta, r->cphi);
        p.memory_distance = memory_distance;
        p.memory_s0 = memory_distance > 0.0 ? 1e-3 : 0.0;
        if (h) {
            p.gap = h;
            p.gap_len = (size_t)g->nx * (size_t)g->ny;
        }
        cw_result res;
        cw_result_init(&res);
        assert_status(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &res), CW_OK);
        const double d[3] = {digits(res.Fx / (MU_S * N_TC), r->fx),
                             digits(res.Fy / (MU_S * N_TC), r->fy), digits(1e3 * res.Mz, r->mz)};
        for (int c = 0; c < 3; ++c) worst = d[c] > worst ? d[c] : worst;
        assert_int_equal(res.n_contact, r->ncon);
        assert_int_equal(res.n_slip, r->nslip);
        assert_close(res.mu_static, MU_S, 0.0, 1e-15);
        assert_true(res.mu_min >= 0.14 && res.mu_max <= MU_S && res.mu_min <= res.mu_max);
        if (res.n_slip > 0) assert_true(res.mu_min < MU_S);
    }
    cw_solver_destroy(s);
    return worst;
}

static void contact_rows_on_the_uniform_grid(void** state)
{
    (void)state;
    const cw_grid g = cw_tractcurv_grid();
    const double worst = contact_rows(&g, NULL, "contact_tractcurv_exponential.csv", 36, 0.0);
    printf("  uniform grid, 36 rows: worst %.3f of half a printed digit\n", worst);
    assert_true(worst <= 1.0);
}

static void contact_rows_on_a_gap_grid(void** state)
{
    (void)state;
    static double h[48 * 44];
    const cw_params p = law_contact(0.0, 0.0, 0.0);
    const cw_grid g = cw_tractcurv_gap_grid(&p, h);
    const double worst = contact_rows(&g, h, "contact_tractcurv_exponential.csv", 36, 0.0);
    printf("  gap grid, 36 rows: worst %.3f of half a printed digit\n", worst);
    assert_true(worst <= 1.0);
}

/* mu_min, mu_max are the law's mu(s) at the slipping elements' slip speeds
 * s = |(sx, sy)| V from the exported micro-slip (full mode): their smallest
 * and largest, within SLIP_MU_TOL; in full sliding (xi = 0.15, every
 * element slips) both are near mu(xi V). Full mode's maps: the
 * energy-consistent map sums to W_macro (1e-9, the bar of the core's
 * work_map_balances), the paper's map to no more; both grids. */
#define SLIP_MU_TOL 1e-12
static void range_and_work_maps(void** state)
{
    (void)state;
    static double h[48 * 44];
    const cw_params base = law_contact(0.0, 0.0, 0.0);
    cw_grid grids[2];
    grids[0] = cw_tractcurv_grid();
    grids[1] = cw_tractcurv_gap_grid(&base, h);
    const double creep[][3] = {{2e-3, 0.0, 0.0}, {3e-3, 2e-4, 0.3}, {0.02, 0.0, 1.0}, {0.15, 0.0, 0.0}};
    static double sx[48 * 44], sy[48 * 44], wc[48 * 44], wp[48 * 44];
    static int st[48 * 44];
    double worst = 0.0;
    for (int gi = 0; gi < 2; ++gi) {
        cw_solver* s = NULL;
        assert_status(cw_solver_create(&grids[gi], &s, NULL, 0), CW_OK);
        const size_t cells = cw_cells(s);
        for (size_t c = 0; c < sizeof creep / sizeof creep[0]; ++c) {
            cw_params p = law_contact(creep[c][0], creep[c][1], creep[c][2]);
            if (gi == 1) p.gap = h, p.gap_len = 48 * 44;
            cw_result r;
            cw_result_init(&r);
            assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
            assert_status(cw_solver_get_field(s, CW_FIELD_SX, sx, cells), CW_OK);
            assert_status(cw_solver_get_field(s, CW_FIELD_SY, sy, cells), CW_OK);
            assert_status(cw_solver_get_field(s, CW_FIELD_WORK_CONSISTENT, wc, cells), CW_OK);
            assert_status(cw_solver_get_field(s, CW_FIELD_WORK_PAPER, wp, cells), CW_OK);
            assert_status(cw_solver_get_state(s, st, cells), CW_OK);
            double lo = INFINITY, hi = -INFINITY, sum_c = 0.0, sum_p = 0.0;
            int slipping = 0;
            for (size_t k = 0; k < cells; ++k) {
                sum_c += wc[k];
                sum_p += wp[k];
                assert_true(wc[k] >= 0.0 && wp[k] >= 0.0);
                if (st[k] != CW_STATE_SLIP) continue;
                const double mu = law_mu(hypot(sx[k], sy[k]) * V_TC);
                lo = mu < lo ? mu : lo;
                hi = mu > hi ? mu : hi;
                ++slipping;
            }
            assert_int_equal(slipping, r.n_slip);
            assert_true(slipping > 0);
            const double d = fmax(fabs(r.mu_min - lo), fabs(r.mu_max - hi));
            worst = d > worst ? d : worst;
            assert_close(r.mu_min, lo, 0.0, SLIP_MU_TOL);
            assert_close(r.mu_max, hi, 0.0, SLIP_MU_TOL);
            if (creep[c][0] == 0.15) {
                assert_int_equal(r.n_slip, r.n_contact);
                const double mu_w = law_mu(0.15 * V_TC);
                assert_close(r.mu_min, mu_w, 0.02, 0.0);
                assert_close(r.mu_max, mu_w, 0.02, 0.0);
            }
            assert_true(r.W_macro > 0.0);
            assert_int_equal(r.work_flags, 0);
            assert_close(sum_c, r.W_macro, 1e-9, 0.0);
            assert_close(r.W_consistent, r.W_macro, 1e-9, 0.0);
            assert_true(sum_p > 0.0 && sum_p <= r.W_macro * (1.0 + 1e-12));
        }
        cw_solver_destroy(s);
    }
    printf("  mu_min, mu_max against the law at the exported slip speeds: worst %.3g\n", worst);
}

/* A Coulomb solve (mu 0.33, warm starts on) after a law's on one handle:
 * the bits of a fresh handle's Coulomb solve (the law and the law's warm
 * start gone), result and traction; and the law's solve again after it the
 * bits of a fresh handle's law solve. Both grids. */
static void coulomb_after_a_law_is_a_fresh_handles(void** state)
{
    (void)state;
    static double h[48 * 44];
    const cw_params base = law_contact(0.0, 0.0, 0.0);
    cw_grid grids[2];
    grids[0] = cw_tractcurv_grid();
    grids[1] = cw_tractcurv_gap_grid(&base, h);
    static double px[2][48 * 44];
    for (int gi = 0; gi < 2; ++gi) {
        cw_params law = law_contact(3e-3, 2e-4, 0.3);
        law.warm_start = 1;
        if (gi == 1) law.gap = h, law.gap_len = 48 * 44;
        cw_params coulomb = law;
        coulomb.friction_law = CW_FRICTION_COULOMB;
        coulomb.mu = MU_S;
        const cw_params* order[2][3] = {{&law, &coulomb, &law}, {&coulomb, &law, NULL}};
        cw_result r[2][3];
        /* used: one handle law, Coulomb, law; fresh handles Coulomb and law. */
        cw_solver* used = NULL;
        assert_status(cw_solver_create(&grids[gi], &used, NULL, 0), CW_OK);
        for (int k = 0; k < 3; ++k) {
            cw_result_init(&r[0][k]);
            assert_status(cw_solver_solve(used, order[0][k], CW_SOLVE_FULL, &r[0][k]), CW_OK);
            if (k == 1)
                assert_status(cw_solver_get_field(used, CW_FIELD_PX, px[0], 48 * 44), CW_OK);
        }
        for (int k = 0; k < 2; ++k) {
            cw_solver* fresh = NULL;
            assert_status(cw_solver_create(&grids[gi], &fresh, NULL, 0), CW_OK);
            cw_result_init(&r[1][k]);
            assert_status(cw_solver_solve(fresh, order[1][k], CW_SOLVE_FULL, &r[1][k]), CW_OK);
            if (k == 0)
                assert_status(cw_solver_get_field(fresh, CW_FIELD_PX, px[1], 48 * 44), CW_OK);
            cw_solver_destroy(fresh);
        }
        assert_memory_equal(&r[0][1], &r[1][0], sizeof r[0][1]);
        assert_memory_equal(px[0], px[1], sizeof px[0]);
        assert_memory_equal(&r[0][2], &r[1][1], sizeof r[0][2]);
        assert_memory_equal(&r[0][0], &r[1][1], sizeof r[0][0]);
        /* Coulomb's and the law's results differ: mu(s) < 0.33 where it slips. */
        assert_true(r[1][1].mu_min < MU_S && r[1][0].mu_min == MU_S);
        assert_true(fabs(r[1][1].Fx) < fabs(r[1][0].Fx));
        cw_solver_destroy(used);
    }
}

/* Friction memory, CONTACT's MEMDST 3 um and MEM_S0 1 mm/s: its rows on
 * the uniform grid and on the gap grid of the same Hertzian gap, every
 * printed digit of Fx / (mu_s N) and the slip area; on both the Jacobian's
 * dFx/dxi_x at 2 % (past the peak) against central differences of the
 * solves (step 1e-5 xi, within 1e-4 of the column). */
static void memory_rows_and_jacobian(void** state)
{
    (void)state;
    static double h[48 * 44];
    cw_params p = law_contact(3e-3, 0.0, 0.0);
    cw_grid grids[2];
    grids[0] = cw_tractcurv_grid();
    grids[1] = cw_tractcurv_gap_grid(&p, h);
    p.memory_distance = 3e-6;
    p.memory_s0 = 1e-3;
    p.xi_x = 0.02;
    p.xi_y = 3e-4;
    p.tolerance = 1e-12;
    p.warm_start = 0;
    for (int gi = 0; gi < 2; ++gi) {
        const double worst = contact_rows(&grids[gi], gi ? h : NULL,
                                          "contact_tractcurv_memory.csv", 6, 3e-6);
        printf("  memory, %s grid, 6 rows: worst %.3f of half a printed digit\n",
               gi ? "gap" : "uniform", worst);
        assert_true(worst <= 1.0);
        if (gi == 1) p.gap = h, p.gap_len = 48 * 44;
        cw_solver* s = NULL;
        assert_status(cw_solver_create(&grids[gi], &s, NULL, 0), CW_OK);
        cw_result r;
        cw_result_init(&r);
        double J[CW_JACOBIAN_LEN];
        assert_status(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, &r, J, CW_JACOBIAN_LEN),
                      CW_OK);
        double F[2];
        for (int side = 0; side < 2; ++side) {
            cw_params q = p;
            q.xi_x += (side ? -1.0 : 1.0) * 1e-5 * p.xi_x;
            assert_status(cw_solver_solve(s, &q, CW_SOLVE_FORCES, &r), CW_OK);
            F[side] = r.Fx;
        }
        const double central = (F[0] - F[1]) / (2e-5 * p.xi_x);
        printf("  memory, %s grid: dFx/dxi_x %.6g, central differences %.6g\n",
               gi ? "gap" : "uniform", J[0], central);
        assert_true(J[0] > 0.0); /* past the peak |Fx| falls (Fx < 0) */
        assert_close(J[0], central, 1e-4, 0.0);
        cw_solver_destroy(s);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(contact_rows_on_the_uniform_grid),
        cmocka_unit_test(contact_rows_on_a_gap_grid),
        cmocka_unit_test(range_and_work_maps),
        cmocka_unit_test(coulomb_after_a_law_is_a_fresh_handles),
        cmocka_unit_test(memory_rows_and_jacobian),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
