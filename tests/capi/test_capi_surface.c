/* Surface temperature and damage indices through the C ABI: cw_temperature_*
 * and cw_damage_* on solved contacts, against an independent implementation
 * of the moving-source sum from the exported fields, the energy identity,
 * CONTACT's example and the indices' definitions; every invalid input: a
 * named status, nothing written, the handle usable. */
#include "capi_fixtures.h"

#include <stdlib.h>

enum { NX = 14, NY = 9, N = NX * NY };

static cw_solver* solved(int k, int kind, cw_params* p)
{
    cw_solver* s = cw_test_solver(kind, NX, NY, 1.25);
    cw_test_case(k, p);
    assert_status(cw_solver_solve(s, p, CW_SOLVE_FULL, NULL), CW_OK);
    return s;
}

static void defaults(void** state)
{
    (void)state;
    cw_temperature_params t;
    memset(&t, 0, sizeof t);
    assert_status(cw_temperature_params_init(&t), CW_OK);
    assert_int_equal(t.struct_size, sizeof t);
    assert_true(t.T0_1 == 20.0 && t.T0_2 == 20.0);
    assert_true(t.heat_capacity_1 == 450.0 && t.conductivity_1 == 50.0 && t.density_1 == 7850.0);
    assert_true(t.heat_capacity_2 == 450.0 && t.conductivity_2 == 50.0 && t.density_2 == 7850.0);
    assert_true(t.rolling_speed == 0.0 && t.rolling_direction == 1);
    assert_int_equal(t.discretisation, CW_TEMPERATURE_CONSISTENT);
    cw_damage_params d;
    assert_status(cw_damage_params_init(&d), CW_OK);
    assert_true(d.k_yield == 0.0 && d.wlrm_onset == 20.0 && d.wlrm_peak == 65.0);
    assert_true(d.wlrm_zero == 175.0 && d.wlrm_peak_damage == 1e-5);
    assert_status(cw_temperature_params_init(NULL), CW_ERR_NULL_POINTER);
    assert_status(cw_temperature_result_init(NULL), CW_ERR_NULL_POINTER);
    assert_status(cw_damage_params_init(NULL), CW_ERR_NULL_POINTER);
    assert_status(cw_damage_result_init(NULL), CW_ERR_NULL_POINTER);
    assert_status(cw_temperature_destroy(NULL), CW_OK);
    assert_status(cw_damage_destroy(NULL), CW_OK);
}

/* The temperature of each body written here from its definition, directly
 * from the exported fields: per row, in the order the material meets the
 * elements (x increasing with rolling_direction -1), the heat q = V W/A of
 * every upstream element integrated exactly over the element's length, taken
 * from the centres' distances, and half the element itself; T_c in contact,
 * the relaxation behind the row's contact, T0 ahead. */
static void reference_temperatures(const cw_solver* s, const cw_temperature_params* tp, double* T1,
                                   double* T2)
{
    double* x = cw_field(s, CW_FIELD_X);
    double* area = cw_field(s, CW_FIELD_AREA);
    double* work = cw_field(s, CW_FIELD_WORK_CONSISTENT);
    int st[N];
    assert_status(cw_solver_get_state(s, st, N), CW_OK);
    const double b1 = sqrt(tp->conductivity_1 * tp->density_1 * tp->heat_capacity_1);
    const double b2 = sqrt(tp->conductivity_2 * tp->density_2 * tp->heat_capacity_2);
    const double V = tp->rolling_speed, Tc = (b1 * tp->T0_1 + b2 * tp->T0_2) / (b1 + b2);
    const double C = 1.0 / ((b1 + b2) * sqrt(M_PI * V));
    const int d = tp->rolling_direction; /* material moves towards -d x */
    for (int j = 0; j < NY; ++j) {
        const double h = 0.5 * fabs(x[1 + j * NX] - x[j * NX]);
        int first = -1, last = -1; /* the contact span in time order */
        for (int t = 0; t < NX; ++t) {
            const int i = d > 0 ? NX - 1 - t : t;
            if (st[i + j * NX] >= 1) {
                if (first < 0) first = t;
                last = t;
            }
        }
        for (int t = 0; t < NX; ++t) {
            const int e = (d > 0 ? NX - 1 - t : t) + j * NX;
            double flash = 0.0;
            for (int u = 0; u <= t; ++u) {
                const int f = (d > 0 ? NX - 1 - u : u) + j * NX;
                const double q = area[f] > 0.0 && work[f] > 0.0 ? V * work[f] / area[f] : 0.0;
                const double dist = fabs(x[e] - x[f]);
                flash += u == t ? 2.0 * q * sqrt(h) : 2.0 * q * (sqrt(dist + h) - sqrt(dist - h));
            }
            flash *= C;
            double g = st[e] >= 1 ? 1.0 : 0.0;
            if (st[e] < 1 && first >= 0 && t > last) {
                const double a = (last - first + 1) * h, from_centre = (t - 0.5 * (first + last)) * 2 * h;
                g = 2.0 / M_PI * asin(sqrt(fmin(1.0, 2 * a / (a + from_centre))));
            }
            T1[e] = tp->T0_1 + g * (Tc - tp->T0_1) + flash;
            T2[e] = tp->T0_2 + g * (Tc - tp->T0_2) + flash;
        }
    }
    free(x);
    free(area);
    free(work);
}

/* Both grids, every test contact (both rolling directions, spin, full and
 * partial slip), dissimilar bodies at different bulk temperatures: every
 * element within 1e-10 of the hottest against the reference above; the
 * maxima are the fields' largest contact values at their elements' centres;
 * the heat is V times the work map's sum (W_macro, see work.md). */
static void temperature_matches_its_definition(void** state)
{
    (void)state;
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind)
        for (int k = 0; k < CW_TEST_CASES; ++k) {
            cw_params p;
            cw_solver* s = solved(k, kind, &p);
            cw_result r;
            cw_result_init(&r);
            assert_status(cw_solver_get_result(s, &r), CW_OK);
            cw_temperature* t = NULL;
            assert_status(cw_temperature_create(s, &t), CW_OK);
            cw_temperature_params tp;
            cw_temperature_params_init(&tp);
            tp.T0_1 = 15.0;
            tp.T0_2 = 60.0;
            tp.conductivity_1 = 4 * 50.0; /* beta1 = 2 beta2 */
            tp.rolling_speed = 25.0;
            tp.rolling_direction = p.rolling_direction;
            cw_temperature_result tr;
            cw_temperature_result_init(&tr);
            assert_status(cw_temperature_compute(t, s, &tp, &tr), CW_OK);
            double T1[N], T2[N], R1[N], R2[N], X[N], Y[N];
            int st[N];
            assert_status(cw_temperature_get_field(t, CW_TEMPERATURE_FIELD_RAIL, T1, N), CW_OK);
            assert_status(cw_temperature_get_field(t, CW_TEMPERATURE_FIELD_WHEEL, T2, N), CW_OK);
            assert_status(cw_solver_get_field(s, CW_FIELD_X, X, N), CW_OK);
            assert_status(cw_solver_get_field(s, CW_FIELD_Y, Y, N), CW_OK);
            assert_status(cw_solver_get_state(s, st, N), CW_OK);
            reference_temperatures(s, &tp, R1, R2);
            const double Tc = (2 * 15.0 + 60.0) / 3;
            assert_close(tr.contact_temperature, Tc, 1e-14, 0);
            double top1 = -1e300, top2 = -1e300;
            for (int e = 0; e < N; ++e) {
                assert_close(T1[e], R1[e], 0, 1e-10 * (fabs(R1[e]) + 100));
                assert_close(T2[e], R2[e], 0, 1e-10 * (fabs(R2[e]) + 100));
                if (st[e] >= 1) {
                    assert_true(T1[e] == T2[e]); /* one surface temperature in contact */
                    top1 = fmax(top1, T1[e]);
                    top2 = fmax(top2, T2[e]);
                }
            }
            assert_true(tr.T_max_1 == top1 && tr.T_max_2 == top2);
            int at = 0;
            while (!(st[at] >= 1 && T1[at] == top1)) ++at;
            assert_true(tr.x_max_1 == X[at] && tr.y_max_1 == Y[at]);
            assert_close(tr.power, tp.rolling_speed * r.W_consistent, 1e-12, 1e-12);
            assert_int_equal(tr.iterations, 1);
            cw_temperature_destroy(t);
            cw_solver_destroy(s);
        }
}

/* CONTACT's example ertz_temperature, case 1 (its grid 216 x 45 as a gap
 * grid, full sliding at 1 m/s, V = 30 m/s rolling towards -x, equal steel
 * bodies at 0 deg C), with CONTACT's discretisation: its printed MAX(T1,T2)
 * 166.8 deg C (examples/ertz_temperature.ref_out, to 0.1). The consistent
 * one, heated by the work map (which differs from traction x slip by 0.2 %
 * here), within 0.5 deg C of the consistent maximum on CONTACT's heat,
 * 152.3 deg C (doc/validation/temperature.md). */
static void contact_example_through_the_door(void** state)
{
    (void)state;
    enum { MX = 216, MY = 45 };
    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_GAP;
    g.nx = MX;
    g.ny = MY;
    g.x0 = -7.8e-3;
    g.y0 = -11.0e-3;
    g.dx = 0.2e-3;
    g.dy = 0.5e-3;
    cw_solver* s = NULL;
    assert_status(cw_solver_create(&g, &s, NULL, 0), CW_OK);
    static double gap[MX * MY];
    for (int j = 0; j < MY; ++j)
        for (int i = 0; i < MX; ++i) {
            const double x = g.x0 + i * g.dx, y = g.y0 + j * g.dy;
            gap[i + j * MX] = 1.015 * x * x + 0.4215 * y * y;
        }
    cw_params p;
    cw_params_init(&p);
    p.model = CW_MODEL_EXACT;
    p.gap = gap;
    p.gap_len = MX * MY;
    p.normal_force = 1e5;
    p.mu = 0.3;
    p.G = 82e9;
    p.nu = 0.28;
    p.rolling_direction = -1;
    p.xi_x = -0.03333;
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
    cw_temperature* t = NULL;
    assert_status(cw_temperature_create(s, &t), CW_OK);
    cw_temperature_params tp;
    cw_temperature_params_init(&tp);
    tp.T0_1 = tp.T0_2 = 0.0;
    tp.rolling_speed = 30.0;
    tp.rolling_direction = -1;
    tp.discretisation = CW_TEMPERATURE_CONTACT;
    cw_temperature_result r;
    cw_temperature_result_init(&r);
    assert_status(cw_temperature_compute(t, s, &tp, &r), CW_OK);
    assert_close(fmax(r.T_max_1, r.T_max_2), 166.8, 0, 0.1);
    assert_int_equal(r.discretisation, CW_TEMPERATURE_CONTACT);
    tp.discretisation = CW_TEMPERATURE_CONSISTENT;
    assert_status(cw_temperature_compute(t, s, &tp, &r), CW_OK);
    assert_close(r.T_max_1, 152.3, 0, 0.5);
    /* FI_surf on a gap grid from the contact elements' area */
    cw_damage* d = NULL;
    assert_status(cw_damage_create(s, &d), CW_OK);
    cw_damage_params dp;
    cw_damage_params_init(&dp);
    dp.k_yield = 300e6;
    cw_damage_result dr;
    cw_damage_result_init(&dr);
    assert_status(cw_damage_compute(d, s, &dp, &dr), CW_OK);
    assert_close(dr.contact_area, 1969 * 0.2e-3 * 0.5e-3, 1e-12, 0);
    assert_close(dr.FI_surf, dr.mu_eff - 2 * dr.contact_area * 300e6 / (3 * 1e5), 1e-13, 1e-15);
    cw_damage_destroy(d);
    cw_temperature_destroy(t);
    cw_solver_destroy(s);
}

/* Full sliding (test case 4, uniform grid with exterior elements): the RCF
 * index max(-0.5, mu - k/p_n) in contact and -0.5 outside (to 1e-12), the
 * T_gamma density summing to W_macro (1e-12), FI_surf = mu_eff - 2 pi a b
 * k/(3 N) from the solve's totals, the WLRM damage of W_macro. */
static void damage_indices(void** state)
{
    (void)state;
    cw_params p;
    cw_solver* s = solved(4, CW_GRID_UNIFORM, &p);
    cw_result r;
    cw_result_init(&r);
    assert_status(cw_solver_get_result(s, &r), CW_OK);
    assert_int_equal(r.n_adhesion, 0);
    cw_damage* d = NULL;
    assert_status(cw_damage_create(s, &d), CW_OK);
    cw_damage_params dp;
    cw_damage_params_init(&dp);
    dp.k_yield = 200e6;
    cw_damage_result dr;
    cw_damage_result_init(&dr);
    assert_status(cw_damage_compute(d, s, &dp, &dr), CW_OK);
    double rcf[N], dens[N], area[N], pz[N];
    int st[N];
    assert_status(cw_damage_get_field(d, CW_DAMAGE_FIELD_RCF_INDEX, rcf, N), CW_OK);
    assert_status(cw_damage_get_field(d, CW_DAMAGE_FIELD_T_GAMMA_DENSITY, dens, N), CW_OK);
    assert_status(cw_solver_get_field(s, CW_FIELD_AREA, area, N), CW_OK);
    assert_status(cw_solver_get_field(s, CW_FIELD_PZ, pz, N), CW_OK);
    assert_status(cw_solver_get_state(s, st, N), CW_OK);
    double sum = 0.0, top = -0.5;
    int exterior = 0;
    for (int e = 0; e < N; ++e) {
        const double expect = st[e] >= 1 && pz[e] > 0 ? fmax(-0.5, p.mu - dp.k_yield / pz[e]) : -0.5;
        assert_close(rcf[e], expect, 0, 1e-12);
        top = fmax(top, expect);
        exterior += st[e] == CW_STATE_EXTERIOR;
        sum += dens[e] * area[e];
    }
    assert_true(exterior > 0);
    assert_close(dr.rcf_index_max, top, 0, 1e-12);
    assert_close(sum, r.W_macro, 1e-12, 0);
    assert_true(dr.T_gamma == r.W_macro);
    const double mu_eff = hypot(r.Fx, r.Fy) / p.normal_force;
    assert_close(dr.mu_eff, mu_eff, 1e-14, 0);
    assert_close(dr.FI_surf, mu_eff - 2 * M_PI * r.a * r.b * dp.k_yield / (3 * p.normal_force),
                 1e-14, 1e-15);
    /* W_macro here is far above 175 N: no RCF damage, wear dominates */
    assert_true(r.W_macro > 175.0 && dr.wlrm_damage == 0.0);
    cw_damage_destroy(d);
    cw_solver_destroy(s);
}

/* Burstow's damage function with the defaults, written here: 0 up to 20 N,
 * rising to 1e-5 at 65 N, falling to 0 at 175 N; on every test contact (its
 * T_gamma = W_macro), some of them on each slope. */
static void wlrm_damage_of_every_contact(void** state)
{
    (void)state;
    int rising = 0, falling = 0;
    for (int k = 0; k < CW_TEST_CASES; ++k) {
        cw_params p;
        cw_solver* s = solved(k, CW_GRID_KALKER_STRIPS, &p);
        cw_result r;
        cw_result_init(&r);
        assert_status(cw_solver_get_result(s, &r), CW_OK);
        cw_damage* d = NULL;
        assert_status(cw_damage_create(s, &d), CW_OK);
        cw_damage_params dp;
        cw_damage_params_init(&dp);
        dp.k_yield = 3e8;
        cw_damage_result dr;
        cw_damage_result_init(&dr);
        assert_status(cw_damage_compute(d, s, &dp, &dr), CW_OK);
        const double T = r.W_macro;
        double expect = 0.0;
        if (T > 20.0 && T <= 65.0) {
            expect = 1e-5 * (T - 20.0) / 45.0;
            ++rising;
        } else if (T > 65.0 && T < 175.0) {
            expect = 1e-5 * (175.0 - T) / 110.0;
            ++falling;
        }
        assert_close(dr.wlrm_damage, expect, 1e-13, 1e-22);
        cw_damage_destroy(d);
        cw_solver_destroy(s);
    }
    assert_true(rising > 0 && falling > 0);
}

/* Every invalid input: its status, a message naming it, nothing written,
 * and the handle holds no result afterwards. */
/* One rolling speed: rolling_speed = 0 takes the solve's cw_params.V, and
 * gives the bits of rolling_speed = V; both given must agree (to 1e-9), and
 * the error names both; neither given names both too. rolling_direction = 0
 * takes the solve's likewise. */
static void rolling_speed_from_the_solve(void** state)
{
    (void)state;
    cw_params p;
    cw_solver* s = solved(1, CW_GRID_KALKER_STRIPS, &p);
    p.V = 30.0;
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
    cw_temperature* t = NULL;
    assert_status(cw_temperature_create(s, &t), CW_OK);
    cw_temperature_params tp;
    cw_temperature_params_init(&tp);
    tp.rolling_direction = p.rolling_direction;
    cw_temperature_result from_V, given;
    cw_temperature_result_init(&from_V);
    cw_temperature_result_init(&given);
    double T_from_V[N], T_given[N];
    assert_status(cw_temperature_compute(t, s, &tp, &from_V), CW_OK); /* rolling_speed 0 */
    assert_status(cw_temperature_get_field(t, CW_TEMPERATURE_FIELD_RAIL, T_from_V, N), CW_OK);
    tp.rolling_speed = 30.0;
    assert_status(cw_temperature_compute(t, s, &tp, &given), CW_OK);
    assert_status(cw_temperature_get_field(t, CW_TEMPERATURE_FIELD_RAIL, T_given, N), CW_OK);
    assert_memory_equal(&from_V, &given, sizeof given);
    assert_memory_equal(T_from_V, T_given, sizeof T_given);
    assert_true(given.T_max_1 > tp.T0_1 + 1.0); /* the speed heats */
    tp.rolling_direction = 0; /* the solve's */
    assert_status(cw_temperature_compute(t, s, &tp, &given), CW_OK);
    assert_status(cw_temperature_get_field(t, CW_TEMPERATURE_FIELD_RAIL, T_given, N), CW_OK);
    assert_memory_equal(T_from_V, T_given, sizeof T_given);
    tp.rolling_direction = p.rolling_direction;
    tp.rolling_speed = 30.0 * (1 + 1e-12); /* the same speed, another rounding */
    assert_status(cw_temperature_compute(t, s, &tp, &given), CW_OK);
    tp.rolling_speed = 31.0;
    assert_status(cw_temperature_compute(t, s, &tp, &given), CW_ERR_INVALID_INPUT);
    assert_names(cw_temperature_last_error(t), "rolling_speed");
    assert_names(cw_temperature_last_error(t), "cw_params.V");
    p.V = 0.0; /* neither */
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
    tp.rolling_speed = 0.0;
    assert_status(cw_temperature_compute(t, s, &tp, &given), CW_ERR_INVALID_INPUT);
    assert_names(cw_temperature_last_error(t), "rolling_speed");
    assert_names(cw_temperature_last_error(t), "cw_params.V");
    tp.rolling_speed = 31.0; /* its own alone */
    assert_status(cw_temperature_compute(t, s, &tp, &given), CW_OK);
    cw_temperature_destroy(t);
    cw_solver_destroy(s);
}

static void invalid_inputs(void** state)
{
    (void)state;
    cw_params p;
    cw_solver* s = solved(0, CW_GRID_KALKER_STRIPS, &p);
    cw_temperature* first = NULL;
    assert_status(cw_temperature_create(s, &first), CW_OK);
    cw_temperature* t = first; /* a failed create sets *temperature to NULL */
    assert_status(cw_temperature_create(NULL, &t), CW_ERR_NULL_POINTER);
    assert_null(t);
    cw_temperature_destroy(first);
    assert_status(cw_temperature_create(s, &t), CW_OK);
    assert_status(cw_temperature_create(s, NULL), CW_ERR_NULL_POINTER);
    cw_temperature_params tp;
    cw_temperature_params_init(&tp);
    tp.rolling_speed = 30.0;
    cw_temperature_result r;
    cw_temperature_result_init(&r);
    double out[N];
    cw_fill(out, N, CW_SENTINEL);
    assert_status(cw_temperature_get_field(t, CW_TEMPERATURE_FIELD_RAIL, out, N),
                  CW_ERR_NO_SOLUTION);
    assert_status(cw_temperature_get_result(t, &r), CW_ERR_NO_SOLUTION);
    assert_status(cw_temperature_compute(NULL, s, &tp, &r), CW_ERR_NULL_POINTER);
    assert_status(cw_temperature_compute(t, NULL, &tp, &r), CW_ERR_NULL_POINTER);
    assert_names(cw_temperature_last_error(t), "solver");
    assert_status(cw_temperature_compute(t, s, NULL, &r), CW_ERR_NULL_POINTER);
    assert_names(cw_temperature_last_error(t), "params");
    struct {
        double* field;
        double value;
        const char* name;
    } bad[] = {{&tp.T0_1, -300, "T0_1"},          {&tp.T0_2, NAN, "T0_2"},
               {&tp.heat_capacity_1, 0, "heat_capacity_1"},
               {&tp.heat_capacity_2, INFINITY, "heat_capacity_2"},
               {&tp.conductivity_1, -1, "conductivity_1"},
               {&tp.conductivity_2, 1e9, "conductivity_2"},
               {&tp.density_1, 7.85e-6, "density_1"}, {&tp.density_2, 0, "density_2"},
               {&tp.rolling_speed, 0, "rolling_speed"}};
    for (size_t b = 0; b < sizeof bad / sizeof bad[0]; ++b) {
        const double keep = *bad[b].field;
        *bad[b].field = bad[b].value;
        assert_status(cw_temperature_compute(t, s, &tp, &r), CW_ERR_INVALID_INPUT);
        assert_names(cw_temperature_last_error(t), bad[b].name);
        *bad[b].field = keep;
    }
    tp.rolling_direction = 2;
    assert_status(cw_temperature_compute(t, s, &tp, &r), CW_ERR_INVALID_INPUT);
    assert_names(cw_temperature_last_error(t), "rolling_direction");
    tp.rolling_direction = -p.rolling_direction; /* not the solve's */
    assert_status(cw_temperature_compute(t, s, &tp, &r), CW_ERR_INVALID_INPUT);
    assert_names(cw_temperature_last_error(t), "rolling_direction");
    assert_names(cw_temperature_last_error(t), "cw_params.rolling_direction");
    tp.rolling_direction = p.rolling_direction;
    tp.discretisation = 7;
    assert_status(cw_temperature_compute(t, s, &tp, &r), CW_ERR_UNKNOWN_OPTION);
    assert_names(cw_temperature_last_error(t), "discretisation");
    tp.discretisation = CW_TEMPERATURE_CONSISTENT;
    cw_temperature_params small = tp;
    small.struct_size = 1;
    assert_status(cw_temperature_compute(t, s, &small, &r), CW_ERR_STRUCT_SIZE);
    /* a forces-only solve has no work map; another grid is refused */
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FORCES, NULL), CW_OK);
    assert_status(cw_temperature_compute(t, s, &tp, &r), CW_ERR_NO_WORK);
    cw_solver* other = cw_test_solver(CW_GRID_UNIFORM, NX, NY, 1.25);
    assert_status(cw_solver_solve(other, &p, CW_SOLVE_FULL, NULL), CW_OK);
    assert_status(cw_temperature_compute(t, other, &tp, &r), CW_ERR_GRID_MISMATCH);
    assert_status(cw_temperature_get_field(t, CW_TEMPERATURE_FIELD_RAIL, out, N),
                  CW_ERR_NO_SOLUTION);
    assert_untouched(out, N);
    /* after a good compute: fields, unknown field, short buffer */
    assert_status(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
    assert_status(cw_temperature_compute(t, s, &tp, NULL), CW_OK);
    assert_status(cw_temperature_get_field(t, 3, out, N), CW_ERR_UNKNOWN_OPTION);
    assert_names(cw_temperature_last_error(t), "field");
    assert_status(cw_temperature_get_field(t, CW_TEMPERATURE_FIELD_HEAT, out, N - 1),
                  CW_ERR_BUFFER_TOO_SMALL);
    assert_untouched(out, N);
    assert_status(cw_temperature_get_field(t, CW_TEMPERATURE_FIELD_HEAT, NULL, N),
                  CW_ERR_NULL_POINTER);
    assert_status(cw_temperature_get_field(t, CW_TEMPERATURE_FIELD_HEAT, out, N), CW_OK);
    assert_true(cw_all_finite(out, N));

    cw_damage* d = NULL;
    assert_status(cw_damage_create(s, &d), CW_OK);
    cw_damage_params dp;
    cw_damage_params_init(&dp);
    cw_damage_result dr;
    cw_damage_result_init(&dr);
    assert_status(cw_damage_compute(d, s, &dp, &dr), CW_ERR_INVALID_INPUT); /* k not set */
    assert_names(cw_damage_last_error(d), "k_yield");
    dp.k_yield = 3e8;
    dp.wlrm_peak = 10.0;
    assert_status(cw_damage_compute(d, s, &dp, &dr), CW_ERR_INVALID_INPUT);
    assert_names(cw_damage_last_error(d), "wlrm_peak");
    dp.wlrm_peak = 65.0;
    dp.wlrm_zero = 50.0;
    assert_status(cw_damage_compute(d, s, &dp, &dr), CW_ERR_INVALID_INPUT);
    assert_names(cw_damage_last_error(d), "wlrm_zero");
    dp.wlrm_zero = 175.0;
    assert_status(cw_damage_get_result(d, &dr), CW_ERR_NO_SOLUTION);
    assert_status(cw_damage_compute(d, other, &dp, &dr), CW_ERR_GRID_MISMATCH);
    assert_status(cw_damage_compute(d, s, &dp, &dr), CW_OK);
    assert_status(cw_damage_get_field(d, 2, out, N), CW_ERR_UNKNOWN_OPTION);
    assert_status(cw_damage_get_field(d, CW_DAMAGE_FIELD_RCF_INDEX, out, 3),
                  CW_ERR_BUFFER_TOO_SMALL);
    assert_status(cw_damage_get_result(d, &dr), CW_OK);
    assert_true(strcmp(cw_damage_last_error(NULL), "damage handle is NULL") == 0);
    assert_true(strcmp(cw_temperature_last_error(NULL), "temperature handle is NULL") == 0);
    cw_damage_destroy(d);
    cw_temperature_destroy(t);
    cw_solver_destroy(other);
    cw_solver_destroy(s);
}

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(defaults),
        cmocka_unit_test(temperature_matches_its_definition),
        cmocka_unit_test(contact_example_through_the_door),
        cmocka_unit_test(damage_indices),
        cmocka_unit_test(wlrm_damage_of_every_contact),
        cmocka_unit_test(rolling_speed_from_the_solve),
        cmocka_unit_test(invalid_inputs),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : NULL);
}
