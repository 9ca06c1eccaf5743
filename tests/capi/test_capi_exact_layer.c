/* The exact model with an interface layer through the C ABI (cw_params'
 * layer_h, layer_G, tau_c0, k_tau): CONTACT's exact theory on its tractcurv
 * contact with the elastic layer of its series 2 alone (GG3 8200 N/mm^2,
 * LAYTHK 1.25 mm; tests/data/contact_tractcurv_layer.csv) and with a
 * perfectly plastic surface (TAU_C0 150 N/mm^2; contact_tractcurv_plastic.csv),
 * hardening by K_TAU 2536.1 and softening by -81.918 N/mm^3
 * (contact_tractcurv_hardening.csv, contact_tractcurv_softening.csv),
 * every printed digit of Fx, Fy and Mz with CONTACT's adhesion area (the bar of
 * test_core_exact_layer); full mode's map against W_macro; the other
 * models, the gap grid and the transient handle refuse a layer naming
 * layer_h or tau_c0; cw_params_check warns of mm typed as m and MPa as Pa. */
#include "capi_fixtures.h"
#include "contact_csv.h"
#include "tractcurv_case.h"
#include "tractcurv_gap.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define N_TC CW_TRACTCURV_N
#define MU 0.33
#define MAX_ROWS 64

/* The layers of the tables: the elastic layer, the plastic surface,
 * hardening and softening. */
enum { ELASTIC, PLASTIC, HARDENING, SOFTENING };

/* Hertz's pressure on CONTACT's printed semi-axes, Coulomb's 0.33. */
static cw_params layer_contact(double xi_x, double xi_y, double phi, int plastic)
{
    cw_params p = cw_tractcurv_exact_params(xi_x, xi_y, phi);
    p.mu = MU;
    if (plastic) {
        p.tau_c0 = 150e6;
        if (plastic == HARDENING) p.k_tau = 2536.1e9;
        if (plastic == SOFTENING) p.k_tau = -81.918e9;
    } else {
        p.layer_h = 1.25e-3;
        p.layer_G = 8.2e9;
    }
    return p;
}

/* |ours - printed| in halves of the printed number's last digit, or in
 * floor where larger: where the exact value is 0 (Fy, Mz at pure xi_x)
 * CONTACT with its layer prints its rounding noise (test_core_exact_layer). */
static double digits(double ours, const char* printed, double floor)
{
    const double half = cw_printed_half_unit(printed);
    return fabs(ours - atof(printed)) / (half > floor ? half : floor);
}

/* Every row of a CONTACT table on grid g (gap: the Hertzian gap h): the
 * worst difference in halves of a printed digit; the contact and adhesion
 * areas element for element. */
static double contact_rows(const char* file, int plastic, const cw_grid* g, const double* h,
                           int expected_rows)
{
    FILE* f = fopen(file, "r");
    assert_non_null(f);
    char line[1024], *fields[40];
    assert_non_null(fgets(line, sizeof line, f));
    const int n = cw_csv_split(line, fields, 40);
    const int c[8] = {cw_csv_column(fields, n, "CKSI"),         cw_csv_column(fields, n, "CETA"),
                      cw_csv_column(fields, n, "CPHI_per_mm"),  cw_csv_column(fields, n, "FX_over_FSTAT_FN"),
                      cw_csv_column(fields, n, "FY_over_FSTAT_FN"), cw_csv_column(fields, n, "MZ_Nmm"),
                      cw_csv_column(fields, n, "NCON"),         cw_csv_column(fields, n, "NADH")};
    for (int k = 0; k < 8; ++k) assert_true(c[k] >= 0);
    cw_solver* s = NULL;
    assert_status(cw_solver_create(g, &s, NULL, 0), CW_OK);
    double worst = 0.0;
    int rows = 0;
    while (fgets(line, sizeof line, f)) {
        if (cw_csv_split(line, fields, 40) < n) continue;
        cw_params p = layer_contact(atof(fields[c[0]]), atof(fields[c[1]]),
                                    1e3 * atof(fields[c[2]]), plastic);
        if (h) {
            p.gap = h;
            p.gap_len = (size_t)g->nx * (size_t)g->ny;
        }
        cw_result r;
        cw_result_init(&r);
        assert_status(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &r), CW_OK);
        const double d[3] = {digits(r.Fx / (MU * N_TC), fields[c[3]], 1e-9),
                             digits(r.Fy / (MU * N_TC), fields[c[4]], 1e-9),
                             digits(1e3 * r.Mz, fields[c[5]], 1e-3)};
        for (int k = 0; k < 3; ++k) worst = d[k] > worst ? d[k] : worst;
        /* CONTACT counts plastic elements neither in NADH nor in NSLIP,
         * creepwork as slip: the adhesion areas are compared. */
        assert_int_equal(r.n_contact, atoi(fields[c[6]]));
        assert_int_equal(r.n_adhesion, atoi(fields[c[7]]));
        ++rows;
    }
    fclose(f);
    cw_solver_destroy(s);
    assert_int_equal(rows, expected_rows);
    return worst;
}

static void elastic_layer_rows(void** state)
{
    (void)state;
    const cw_grid g = cw_tractcurv_grid();
    const double worst = contact_rows(CW_TEST_DATA_DIR "/contact_tractcurv_layer.csv", 0, &g, NULL, 34);
    printf("  elastic layer, 34 rows: worst %.3f of half a printed digit\n", worst);
    assert_true(worst <= 1.0);
}

/* The same rows on a gap grid holding the same Hertzian gap. */
static void elastic_layer_rows_on_a_gap_grid(void** state)
{
    (void)state;
    static double h[48 * 44];
    const cw_params p = layer_contact(0.0, 0.0, 0.0, 0);
    const cw_grid g = cw_tractcurv_gap_grid(&p, h);
    const double worst = contact_rows(CW_TEST_DATA_DIR "/contact_tractcurv_layer.csv", 0, &g, h, 34);
    printf("  elastic layer on a gap grid, 34 rows: worst %.3f of half a printed digit\n", worst);
    assert_true(worst <= 1.0);
}

static void plastic_surface_rows(void** state)
{
    (void)state;
    const cw_grid g = cw_tractcurv_grid();
    const double worst =
        contact_rows(CW_TEST_DATA_DIR "/contact_tractcurv_plastic.csv", 1, &g, NULL, 34);
    printf("  plastic surface, 34 rows: worst %.3f of half a printed digit\n", worst);
    assert_true(worst <= 1.0);
}

static void hardening_and_softening_rows(void** state)
{
    (void)state;
    const cw_grid g = cw_tractcurv_grid();
    const double hard =
        contact_rows(CW_TEST_DATA_DIR "/contact_tractcurv_hardening.csv", HARDENING, &g, NULL, 9);
    const double soft =
        contact_rows(CW_TEST_DATA_DIR "/contact_tractcurv_softening.csv", SOFTENING, &g, NULL, 9);
    printf("  hardening, softening surface, 9 rows each: worst %.3f, %.3f of half a printed "
           "digit\n", hard, soft);
    assert_true(hard <= 1.0);
    assert_true(soft <= 1.0);
}

/* Full mode with both the layer and the yield: the energy-consistent map
 * sums to W_macro (1e-9, the core test's bar). */
static void work_map_balances(void** state)
{
    (void)state;
    const cw_grid g = cw_tractcurv_grid();
    cw_solver* s = NULL;
    assert_status(cw_solver_create(&g, &s, NULL, 0), CW_OK);
    cw_params p = layer_contact(4e-3, 2e-4, 0.3, 0);
    p.tau_c0 = 150e6;
    cw_result r;
    cw_result_init(&r);
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
    assert_true(r.W_macro > 0.0);
    assert_close(r.W_consistent, r.W_macro, 1e-9, 0.0);
    cw_solver_destroy(s);
}

/* The Jacobian with the layer (and the yield on the uniform grid, perfectly
 * plastic and hardening; the elastic layer alone on a gap grid holding the
 * Hertzian gap): the xi_x and
 * N columns against central differences of cw_solver_solve (cold solves to
 * 1e-13, steps 1e-6 of xi_x and of N, where no element changes state;
 * held to 1e-6 of the row). The N column carries the yield's share (tau_c
 * does not grow with N). */
static void jacobian_against_differences(void** state)
{
    (void)state;
    static double h[48 * 44];
    const cw_params base = layer_contact(0.0, 0.0, 0.0, 0);
    cw_grid grids[3];
    grids[0] = grids[2] = cw_tractcurv_grid();
    grids[1] = cw_tractcurv_gap_grid(&base, h);
    for (int gi = 0; gi < 3; ++gi) {
        cw_solver* s = NULL;
        assert_status(cw_solver_create(&grids[gi], &s, NULL, 0), CW_OK);
        /* At 2.4e-3 most of the contact flows plastically (CONTACT: 666 of
         * 1384 elements), 148 elements adhere. */
        cw_params p = layer_contact(gi == 1 ? 2e-3 : 2.4e-3, 3e-4, 0.2, 0);
        if (gi != 1) {
            p.tau_c0 = 150e6;
            if (gi == 2) p.k_tau = 2536.1e9;
        } else {
            p.gap = h;
            p.gap_len = 48 * 44;
        }
        p.tolerance = 1e-13;
        p.warm_start = 0;
        cw_result r;
        cw_result_init(&r);
        double J[CW_JACOBIAN_LEN];
        assert_status(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, &r, J, CW_JACOBIAN_LEN),
                      CW_OK);
        assert_true(r.n_slip > 0 && r.n_adhesion > 0);
        const int cols[2] = {CW_JAC_XI_X, CW_JAC_N};
        const double steps[2] = {1e-6 * 2e-3, 1e-6 * N_TC};
        for (int k = 0; k < 2; ++k) {
            cw_params up = p, down = p;
            double* u = cols[k] == CW_JAC_N ? &up.normal_force : &up.xi_x;
            double* d = cols[k] == CW_JAC_N ? &down.normal_force : &down.xi_x;
            *u += steps[k];
            *d -= steps[k];
            cw_result ru, rd;
            cw_result_init(&ru);
            cw_result_init(&rd);
            assert_status(cw_solver_solve(s, &up, CW_SOLVE_FORCES, &ru), CW_OK);
            assert_status(cw_solver_solve(s, &down, CW_SOLVE_FORCES, &rd), CW_OK);
            assert_int_equal(ru.n_slip, r.n_slip);
            assert_int_equal(rd.n_slip, r.n_slip);
            const double dF[2] = {(ru.Fx - rd.Fx) / (2.0 * steps[k]),
                                  (ru.Fy - rd.Fy) / (2.0 * steps[k])};
            const double scale = cols[k] == CW_JAC_N ? N_TC : 2e-3;
            for (int row = 0; row < 2; ++row) {
                const double* Jr = J + 4 * (row == 0 ? CW_JAC_FX : CW_JAC_FY);
                const double size = fabs(Jr[CW_JAC_XI_X]) * 2e-3 + fabs(Jr[CW_JAC_N]) * N_TC;
                printf("  %s, column %d, row %d: %.8g (differences %.8g)\n",
                       gi == 1 ? "gap grid" : gi ? "hardening" : "uniform grid", cols[k], row,
                       Jr[cols[k]], dF[row]);
                assert_close(Jr[cols[k]] * scale, dF[row] * scale, 0.0, 1e-6 * size);
            }
        }
        cw_solver_destroy(s);
    }
}

/* A model without the layer refuses it by the name of its input: FASTSIM,
 * the calibrated model, the transient handle, and the yield the exact model
 * on a gap grid; the exact model refuses k_tau without a yield stress and
 * a yield under a law. */
static void refusals_name_the_input(void** state)
{
    (void)state;
    cw_grid strips;
    cw_grid_init(&strips);
    cw_solver* s = NULL;
    assert_status(cw_solver_create(&strips, &s, NULL, 0), CW_OK);
    cw_result r;
    const int models[2] = {CW_MODEL_FASTSIM, CW_MODEL_CALIBRATED};
    for (int k = 0; k < 2; ++k)
        for (int plastic = 0; plastic < 2; ++plastic) {
            cw_params p = layer_contact(1e-3, 0.0, 0.0, plastic);
            p.model = models[k];
            p.pressure = CW_PRESSURE_PARABOLIC;
            cw_result_init(&r);
            assert_status(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &r), CW_ERR_INVALID_INPUT);
            assert_names(cw_solver_last_error(s), plastic ? "tau_c0" : "layer_h");
        }
    cw_solver_destroy(s);

    static double h[12 * 12];
    cw_grid gap = cw_test_grid(CW_GRID_GAP, 12, 12, 1.0);
    gap.dx = gap.dy = 1e-3;
    gap.x0 = gap.y0 = -5.5e-3;
    for (int j = 0; j < 12; ++j)
        for (int i = 0; i < 12; ++i) {
            const double x = gap.x0 + i * gap.dx, y = gap.y0 + j * gap.dy;
            h[i + 12 * j] = 10.0 * (x * x + y * y);
        }
    cw_params p = layer_contact(1e-3, 0.0, 0.0, 1);
    p.gap = h;
    p.gap_len = 12 * 12;
    assert_status(cw_solver_create(&gap, &s, NULL, 0), CW_OK);
    cw_result_init(&r);
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &r), CW_ERR_INVALID_INPUT);
    assert_names(cw_solver_last_error(s), "tau_c0");
    p.model = CW_MODEL_FASTSIM;
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &r), CW_ERR_INVALID_INPUT);
    assert_names(cw_solver_last_error(s), "tau_c0");
    cw_solver_destroy(s);
    p = layer_contact(1e-3, 0.0, 0.0, 0);
    p.gap = h;
    p.gap_len = 12 * 12;
    cw_transient* t = NULL;
    char message[512] = "";
    assert_status(cw_transient_create(&gap, &p, &t, message, sizeof message), CW_ERR_INVALID_INPUT);
    assert_null(t);
    assert_names(message, "layer_h");

    const cw_grid g = cw_tractcurv_grid();
    assert_status(cw_solver_create(&g, &s, NULL, 0), CW_OK);
    struct {
        const char* name;
        int field;
        double value;
    } bad[] = {{"layer_h", 0, -1e-3}, {"layer_G", 1, 0.0}, {"layer_G", 1, NAN},
               {"tau_c0", 2, -1.0},   {"k_tau", 3, 1e9}};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        cw_params q = layer_contact(1e-3, 0.0, 0.0, 0);
        double* f[4] = {&q.layer_h, &q.layer_G, &q.tau_c0, &q.k_tau};
        *f[bad[k].field] = bad[k].value;
        cw_result_init(&r);
        assert_status(cw_solver_solve(s, &q, CW_SOLVE_FORCES, &r), CW_ERR_INVALID_INPUT);
        assert_names(cw_solver_last_error(s), bad[k].name);
    }
    cw_params q = layer_contact(1e-3, 0.0, 0.0, 1);
    q.friction_law = CW_FRICTION_EXPONENTIAL;
    q.mu = 0.14;
    q.mu_e1 = 0.19;
    q.s_h1 = 1.25;
    cw_result_init(&r);
    assert_status(cw_solver_solve(s, &q, CW_SOLVE_FORCES, &r), CW_ERR_INVALID_INPUT);
    assert_names(cw_solver_last_error(s), "tau_c0");
    cw_solver_destroy(s);
}

/* Millimetres typed as metres (h = 1.25 m), MPa typed as Pa (G3 = 8200 Pa,
 * tau_c0 = 150 Pa) are found by cw_params_check, naming the input;
 * tractcurv's layer and a yield of 150 MPa are not. */
static void implausible_units_are_warned(void** state)
{
    (void)state;
    const cw_grid g = cw_tractcurv_grid();
    cw_check c[8];
    for (int k = 0; k < 8; ++k) cw_check_init(&c[k]);
    size_t found = 99;
    cw_params p = layer_contact(1e-3, 0.0, 0.0, 0);
    p.tau_c0 = 150e6;
    assert_status(cw_params_check(&g, &p, 1, c, 8, &found), CW_OK);
    assert_int_equal(found, 0);
    struct {
        int field;
        double value;
        int rule;
        const char* name;
    } cases[] = {{0, 1.25, CW_CHECK_LAYER_THICKNESS, "layer_h"},
                 {1, 8200.0, CW_CHECK_MODULUS, "layer_G"},
                 {2, 150.0, CW_CHECK_YIELD_STRESS, "tau_c0"}};
    for (size_t k = 0; k < 3; ++k) {
        cw_params q = p;
        double* f[3] = {&q.layer_h, &q.layer_G, &q.tau_c0};
        *f[cases[k].field] = cases[k].value;
        assert_status(cw_params_check(&g, &q, 1, c, 8, &found), CW_OK);
        assert_int_equal(found, 1);
        assert_int_equal(c[0].rule, cases[k].rule);
        assert_string_equal(c[0].input, cases[k].name);
        assert_true(c[0].value == cases[k].value);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(elastic_layer_rows),
        cmocka_unit_test(elastic_layer_rows_on_a_gap_grid),
        cmocka_unit_test(plastic_surface_rows),
        cmocka_unit_test(hardening_and_softening_rows),
        cmocka_unit_test(work_map_balances),
        cmocka_unit_test(jacobian_against_differences),
        cmocka_unit_test(refusals_name_the_input),
        cmocka_unit_test(implausible_units_are_warned),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
