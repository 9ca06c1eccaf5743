/* Friction that depends on the surface temperature through the C ABI
 * (cw_mu_temperature, cw_temperature_solve): CONTACT's testbank example
 * euro_tractcurv (tests/data/temperature/contact_euro_tractcurv.csv, its L=6
 * series 2-4 and the Coulomb series 1) with CONTACT's temperature
 * discretisation; the fixed point against the fields (in full sliding each
 * element carries mu(T) p); a table of one mu bitwise Coulomb's first
 * pass; every invalid input refused naming it, and no solution left. */
#include "capi_fixtures.h"
#include "contact_csv.h"

#include <stdio.h>
#include <stdlib.h>

enum { NX = 44, NY = 44, N = NX * NY };

#define EURO_N 106.7e3 /* [N] */
#define FREF 0.33

/* The contact of euro_tractcurv.inp: A1 = 0.0008/mm, a/b = 0.5 (a, b as
 * CONTACT prints them), FN = 106.7 kN, steel (G = 82 GPa, nu = 0.28),
 * V = 10 m/s, the exact model on 44 x 44 elements over 1.1 times the
 * semi-axes (CONTACT's DX = 0.3152 mm). */
static cw_solver* euro_solver(void) { return cw_test_solver(CW_GRID_UNIFORM, NX, NY, 1.1); }

static cw_params euro_params(double xi_x)
{
    cw_params p;
    cw_params_init(&p);
    p.model = CW_MODEL_EXACT;
    p.a = 6.304e-3;
    p.b = 12.61e-3;
    p.normal_force = EURO_N;
    p.mu = FREF;
    p.V = 10.0;
    p.xi_x = xi_x;
    return p;
}

/* Both bodies steel at 0 deg C (BKTEMP 0), CONTACT's discretisation. */
static cw_temperature_params euro_temperature(void)
{
    cw_temperature_params t;
    cw_temperature_params_init(&t);
    t.T0_1 = t.T0_2 = 0.0;
    t.discretisation = CW_TEMPERATURE_CONTACT;
    return t;
}

/* L=6 as a table: (TREF, FREF), (TREF + DTHEAT, FREF + DFHEAT). */
typedef struct {
    double T[2], mu[2];
    cw_mu_temperature m;
} l6_table;

static void l6(l6_table* t, double dfheat, double dtheat)
{
    t->T[0] = 0.0;
    t->T[1] = dtheat;
    t->mu[0] = FREF;
    t->mu[1] = FREF + dfheat;
    cw_mu_temperature_init(&t->m);
    t->m.count = 2;
    t->m.temperature = t->T;
    t->m.mu = t->mu;
}

typedef struct {
    int series;
    double cksi, fx, tmax, fx_tol, t_tol;
} euro_row;

static int read_euro(euro_row* rows, int max)
{
    FILE* f = fopen(CW_TEST_DATA_DIR "/temperature/contact_euro_tractcurv.csv", "r");
    assert_non_null(f);
    char line[512], *fields[16];
    assert_non_null(fgets(line, sizeof line, f));
    const int n = cw_csv_split(line, fields, 16);
    const int c_series = cw_csv_column(fields, n, "series"), c_cksi = cw_csv_column(fields, n, "CKSI"),
              c_fx = cw_csv_column(fields, n, "FX_over_FSTAT_FN"),
              c_t = cw_csv_column(fields, n, "T_MAX_C");
    assert_true(c_series >= 0 && c_cksi >= 0 && c_fx >= 0 && c_t >= 0);
    int count = 0;
    while (count < max && fgets(line, sizeof line, f)) {
        if (cw_csv_split(line, fields, 16) <= c_t) continue;
        euro_row* r = &rows[count++];
        r->series = atoi(fields[c_series]);
        r->cksi = atof(fields[c_cksi]);
        r->fx = atof(fields[c_fx]);
        r->fx_tol = cw_printed_half_unit(fields[c_fx]);
        r->tmax = atof(fields[c_t]);
        r->t_tol = cw_printed_half_unit(fields[c_t]);
    }
    fclose(f);
    return count;
}

static const double kDfheat[5] = {0.0, 0.0, 0.19, -0.19, -0.19};
static const double kDtheat[5] = {0.0, 0.0, 1200.0, 1200.0, 400.0};

/* One case: Fx / (FREF N) and the hotter body's maximum [deg C]. */
static void solve_case(cw_solver* s, cw_temperature* t, const euro_row* r, double* fx,
                       double* tmax, int* iterations)
{
    const cw_params p = euro_params(r->cksi);
    const cw_temperature_params tp = euro_temperature();
    cw_result res;
    cw_result_init(&res);
    cw_temperature_result tr;
    cw_temperature_result_init(&tr);
    if (r->series == 1) {
        assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &res), CW_OK);
        assert_status(cw_temperature_compute(t, s, &tp, &tr), CW_OK);
    } else {
        l6_table l;
        l6(&l, kDfheat[r->series], kDtheat[r->series]);
        assert_status(cw_temperature_solve(t, s, &p, &tp, &l.m, &res, &tr), CW_OK);
    }
    *fx = res.Fx / (FREF * EURO_N);
    *tmax = tr.T_max_1 > tr.T_max_2 ? tr.T_max_1 : tr.T_max_2;
    *iterations = tr.iterations;
}

/* Every case of the four series, solved in turn on one solver (each warm
 * from the last, as CONTACT runs them). */
typedef struct {
    euro_row contact;
    double fx, tmax;
    int passes;
} euro_result;

static int run_euro(euro_result* out, int max)
{
    euro_row rows[130];
    const int n = read_euro(rows, 130);
    cw_solver* s = euro_solver();
    cw_temperature* t = NULL;
    assert_status(cw_temperature_create(s, &t), CW_OK);
    for (int k = 0; k < n && k < max; ++k) {
        out[k].contact = rows[k];
        solve_case(s, t, &rows[k], &out[k].fx, &out[k].tmax, &out[k].passes);
    }
    cw_temperature_destroy(t);
    cw_solver_destroy(s);
    return n;
}

/* Fx/(FREF N) within FX_TOL of CONTACT's printed value and the maximum
 * temperature within T_REL of it (plus half its last printed digit). */
#define FX_TOL 5e-4
#define T_REL 2e-3
static void euro_tractcurv(void** state)
{
    (void)state;
    euro_result r[130];
    const int n = run_euro(r, 130);
    assert_int_equal(n, 120);
    for (int k = 0; k < n; ++k) {
        const euro_row* c = &r[k].contact;
        assert_close(r[k].fx, c->fx, 0.0, c->fx_tol + FX_TOL);
        assert_close(r[k].tmax, c->tmax, T_REL, c->t_tol);
        if (c->series > 1) assert_true(r[k].passes >= 2 && r[k].passes < 100);
    }
}

/* doc/validation/temperature.md's tables: per series the largest
 * differences, then series 4 row by row. */
static int print_markdown(void)
{
    euro_result r[130];
    const int n = run_euro(r, 130);
    static const char* const law[5] = {"", "Coulomb 0.33", "L=6, +0.19 over 1200 deg C",
                                       "L=6, -0.19 over 1200 deg C", "L=6, -0.19 over 400 deg C"};
    printf("| series | friction | cases | max diff Fx/(FREF N) | max diff T_max [deg C] | "
           "passes |\n|---:|---|---:|---:|---:|---:|\n");
    for (int series = 1; series <= 4; ++series) {
        double dfx = 0.0, dt = 0.0;
        int cases = 0, lo = 1000, hi = 0;
        for (int k = 0; k < n; ++k) {
            if (r[k].contact.series != series) continue;
            ++cases;
            dfx = fmax(dfx, fabs(r[k].fx - r[k].contact.fx));
            dt = fmax(dt, fabs(r[k].tmax - r[k].contact.tmax));
            lo = r[k].passes < lo ? r[k].passes : lo;
            hi = r[k].passes > hi ? r[k].passes : hi;
        }
        printf("| %d | %s | %d | %.1e | %.2f | %d-%d |\n", series, law[series], cases, dfx, dt, lo,
               hi);
    }
    printf("\nSeries 4 (L=6, mu from 0.33 at 0 deg C to 0.14 at 400 deg C)\n\n"
           "| creepage | Fx/(FREF N) | CONTACT | T_max [deg C] | CONTACT | passes |\n"
           "|---:|---:|---:|---:|---:|---:|\n");
    for (int k = 0; k < n; ++k) {
        if (r[k].contact.series != 4) continue;
        printf("| %.5g | %.4f | %.4f | %.4g | %.4g | %d |\n", r[k].contact.cksi, r[k].fx,
               r[k].contact.fx, r[k].tmax, r[k].contact.tmax, r[k].passes);
    }
    return 0;
}

/* The fixed point against the fields: at 25 % creepage every element
 * slides, so each carries mu(T1) p along -x, T1 its rail temperature, and
 * Fx = -sum mu(T1_e) p_e A_e within the loop's tolerance, 1e-6 N (measured
 * 1.4e-7 N). */
static void fixed_point_in_full_sliding(void** state)
{
    (void)state;
    cw_solver* s = euro_solver();
    cw_temperature* t = NULL;
    assert_status(cw_temperature_create(s, &t), CW_OK);
    const cw_params p = euro_params(0.25);
    const cw_temperature_params tp = euro_temperature();
    l6_table l;
    l6(&l, -0.19, 400.0);
    cw_result res;
    cw_result_init(&res);
    cw_temperature_result tr;
    cw_temperature_result_init(&tr);
    assert_status(cw_temperature_solve(t, s, &p, &tp, &l.m, &res, &tr), CW_OK);
    assert_true(tr.iterations >= 2 && tr.iterations < 100);
    assert_int_equal(res.n_adhesion, 0);
    double T1[N];
    assert_status(cw_temperature_get_field(t, CW_TEMPERATURE_FIELD_RAIL, T1, N), CW_OK);
    double* pz = cw_field(s, CW_FIELD_PZ);
    double* area = cw_field(s, CW_FIELD_AREA);
    int st[N];
    assert_status(cw_solver_get_state(s, st, N), CW_OK);
    double fx = 0.0, lo = 1.0, hi = 0.0;
    for (int e = 0; e < N; ++e) {
        if (st[e] != 2) continue;
        const double w = T1[e] <= 0.0 ? 0.0 : T1[e] >= 400.0 ? 1.0 : T1[e] / 400.0;
        const double mu = FREF - 0.19 * w;
        fx -= mu * pz[e] * area[e];
        lo = mu < lo ? mu : lo;
        hi = mu > hi ? mu : hi;
    }
    assert_close(res.Fx, fx, 0.0, 1e-6 * EURO_N);
    /* The result's range of mu: that of the solve's factors, from the
     * temperatures one pass before (1.3e-6 apart measured; 1e-5). */
    assert_close(res.mu_min, lo, 0.0, 1e-5);
    assert_close(res.mu_max, hi, 0.0, 1e-5);
    assert_true(res.mu_static == FREF);
    assert_true(res.mu_min < 0.2 && res.mu_max <= FREF);
    /* The solver is left without factors: a plain solve is Coulomb's. */
    cw_result plain;
    cw_result_init(&plain);
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, &plain), CW_OK);
    assert_close(plain.Fx, -FREF * EURO_N, 1e-6, 0.0);
    free(pz);
    free(area);
    cw_temperature_destroy(t);
    cw_solver_destroy(s);
}

/* A table of one coefficient: every factor is 1, so the first pass is the
 * Coulomb solve (a fresh solver each, the same cold start), and the second
 * (warm, the same bounds) ends the loop with the forces of a plain Coulomb
 * solve within the exact model's tolerance (1e-8; 1e-7 asked). One pass
 * allowed is not convergence. */
static void constant_table_is_coulomb(void** state)
{
    (void)state;
    const double T[2] = {0.0, 500.0}, mu[2] = {FREF, FREF};
    cw_mu_temperature m;
    cw_mu_temperature_init(&m);
    m.count = 2;
    m.temperature = T;
    m.mu = mu;
    m.max_iterations = 1; /* the first pass alone: not converged, by definition */
    const cw_params p = euro_params(1.2e-3);
    const cw_temperature_params tp = euro_temperature();
    cw_solver* a = euro_solver();
    cw_solver* b = euro_solver();
    cw_temperature* t = NULL;
    assert_status(cw_temperature_create(a, &t), CW_OK);
    cw_result ra, rb;
    cw_result_init(&ra);
    cw_result_init(&rb);
    assert_status(cw_temperature_solve(t, a, &p, &tp, &m, &ra, NULL), CW_ERR_NOT_CONVERGED);
    assert_names(cw_temperature_last_error(t), "mu_T.max_iterations");
    assert_status(cw_solver_get_result(a, &ra), CW_ERR_NO_SOLUTION);
    m.max_iterations = 100;
    cw_temperature_result tr;
    cw_temperature_result_init(&tr);
    assert_status(cw_temperature_solve(t, a, &p, &tp, &m, &ra, &tr), CW_OK);
    assert_int_equal(tr.iterations, 2);
    assert_status(cw_solver_solve(b, &p, CW_SOLVE_FULL, &rb), CW_OK);
    assert_close(ra.Fx, rb.Fx, 1e-7, 0.0);
    assert_int_equal(ra.n_slip, rb.n_slip);
    assert_true(ra.mu_min == FREF && ra.mu_max == FREF);
    cw_temperature_destroy(t);
    cw_solver_destroy(a);
    cw_solver_destroy(b);
}

/* Every invalid input: its status, a message naming it, no solution left. */
static void refusals(void** state)
{
    (void)state;
    cw_solver* s = euro_solver();
    cw_temperature* t = NULL;
    assert_status(cw_temperature_create(s, &t), CW_OK);
    const cw_params p = euro_params(1e-3);
    const cw_temperature_params tp = euro_temperature();
    double T[3] = {0.0, 200.0, 400.0}, mu[3] = {0.3, 0.25, 0.2};
    cw_mu_temperature m;
    assert_status(cw_mu_temperature_init(NULL), CW_ERR_NULL_POINTER);
    assert_status(cw_mu_temperature_init(&m), CW_OK);
    assert_true(m.struct_size == sizeof m && m.count == 0 && m.tolerance == 1e-6 &&
                m.max_iterations == 100 && !m.temperature && !m.mu);
    m.temperature = T;
    m.mu = mu;
    struct {
        size_t count;
        double T1, mu2, tolerance;
        int max_iterations;
        const char* name;
    } bad[] = {
        {0, 200.0, 0.2, 1e-6, 100, "mu_T: count"},
        {1, 200.0, 0.2, 1e-6, 100, "mu_T: count"},
        {3, 500.0, 0.2, 1e-6, 100, "temperature[2]"},   /* 500 then 400: unsorted */
        {3, 0.0, 0.2, 1e-6, 100, "temperature[1]"},     /* equal */
        {3, NAN, 0.2, 1e-6, 100, "temperature[1]"},
        {3, 200.0, NAN, 1e-6, 100, "mu[2]"},
        {3, 200.0, 0.0, 1e-6, 100, "mu[2]"},
        {3, 200.0, -0.1, 1e-6, 100, "mu[2]"},
        {3, 200.0, 0.2, 0.0, 100, "mu_T.tolerance"},
        {3, 200.0, 0.2, NAN, 100, "mu_T.tolerance"},
        {3, 200.0, 0.2, 1e-6, 0, "mu_T.max_iterations"},
    };
    cw_result res;
    cw_result_init(&res);
    cw_temperature_result tr;
    cw_temperature_result_init(&tr);
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
        m.count = bad[k].count;
        T[1] = bad[k].T1;
        mu[2] = bad[k].mu2;
        m.tolerance = bad[k].tolerance;
        m.max_iterations = bad[k].max_iterations;
        assert_status(cw_temperature_solve(t, s, &p, &tp, &m, NULL, NULL), CW_ERR_INVALID_INPUT);
        assert_names(cw_temperature_last_error(t), bad[k].name);
        assert_names(cw_solver_last_error(s), bad[k].name);
        assert_status(cw_solver_get_result(s, &res), CW_ERR_NO_SOLUTION);
        assert_status(cw_temperature_get_result(t, &tr), CW_ERR_NO_SOLUTION);
    }
    T[1] = 200.0;
    mu[2] = 0.2;
    m.count = 3;
    m.tolerance = 1e-6;
    m.max_iterations = 100;
    /* A model without mu(T): FASTSIM. */
    cw_params f = p;
    f.model = CW_MODEL_FASTSIM;
    cw_solver* sf = cw_test_solver(CW_GRID_UNIFORM, NX, NY, 1.1);
    cw_temperature* tf = NULL;
    assert_status(cw_temperature_create(sf, &tf), CW_OK);
    assert_status(cw_temperature_solve(tf, sf, &f, &tp, &m, NULL, NULL), CW_ERR_INVALID_INPUT);
    assert_names(cw_temperature_last_error(tf), "mu_T");
    /* NULL pointers. */
    assert_status(cw_temperature_solve(NULL, s, &p, &tp, &m, NULL, NULL), CW_ERR_NULL_POINTER);
    assert_status(cw_temperature_solve(t, NULL, &p, &tp, &m, NULL, NULL), CW_ERR_NULL_POINTER);
    assert_status(cw_temperature_solve(t, s, NULL, &tp, &m, NULL, NULL), CW_ERR_NULL_POINTER);
    assert_status(cw_temperature_solve(t, s, &p, NULL, &m, NULL, NULL), CW_ERR_NULL_POINTER);
    assert_status(cw_temperature_solve(t, s, &p, &tp, NULL, NULL, NULL), CW_ERR_NULL_POINTER);
    m.temperature = NULL;
    assert_status(cw_temperature_solve(t, s, &p, &tp, &m, NULL, NULL), CW_ERR_INVALID_INPUT);
    assert_names(cw_temperature_last_error(t), "mu_T");
    m.temperature = T;
    /* Still usable: a valid table solves. */
    assert_status(cw_temperature_solve(t, s, &p, &tp, &m, &res, NULL), CW_OK);
    assert_status(cw_solver_get_result(s, &res), CW_OK);
    cw_temperature_destroy(tf);
    cw_solver_destroy(sf);
    cw_temperature_destroy(t);
    cw_solver_destroy(s);
}

int main(int argc, char** argv)
{
    if (argc > 1 && !strcmp(argv[1], "--markdown")) return print_markdown();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(euro_tractcurv),
        cmocka_unit_test(fixed_point_in_full_sliding),
        cmocka_unit_test(constant_table_is_coulomb),
        cmocka_unit_test(refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
