/* Solver handle through the C ABI: lifecycle, solve, totals, every field,
 * states and the lateral profile, checked against formulas and identities
 * that hold for any correct solve. */
#include "capi_fixtures.h"

#include <stdlib.h>

enum { N_FIELDS = CW_FIELD_WORK_CONSISTENT + 1 };

/* Everything one FULL solve exposes. */
typedef struct {
    int nx, ny;
    size_t n;
    double* f[N_FIELDS];
    int* state;
    double *profile_y, *profile_w, *profile_parabola; /* per strip */
    cw_result r;
} solution;

static void solution_fetch(const cw_solver* s, solution* out)
{
    assert_int_equal(cw_solver_grid_size(s, &out->nx, &out->ny), CW_OK);
    out->n = (size_t)out->nx * (size_t)out->ny;
    for (int f = 0; f < N_FIELDS; ++f) {
        out->f[f] = malloc(out->n * sizeof(double));
        assert_non_null(out->f[f]);
        assert_int_equal(cw_solver_get_field(s, f, out->f[f], out->n), CW_OK);
    }
    out->state = malloc(out->n * sizeof(int));
    out->profile_y = malloc((size_t)out->ny * sizeof(double));
    out->profile_w = malloc((size_t)out->ny * sizeof(double));
    out->profile_parabola = malloc((size_t)out->ny * sizeof(double));
    assert_true(out->state && out->profile_y && out->profile_w && out->profile_parabola);
    assert_int_equal(cw_solver_get_state(s, out->state, out->n), CW_OK);
    assert_int_equal(cw_solver_get_profile(s, out->profile_y, out->profile_w, out->profile_parabola,
                                           (size_t)out->ny),
                     CW_OK);
    cw_result_init(&out->r);
    assert_int_equal(cw_solver_get_result(s, &out->r), CW_OK);
}

static void solution_free(solution* s)
{
    for (int f = 0; f < N_FIELDS; ++f) free(s->f[f]);
    free(s->state);
    free(s->profile_y);
    free(s->profile_w);
    free(s->profile_parabola);
}

/* Grids the identities are checked on: both kinds, square and not; strip
 * grids first, then uniform ones (the geometry tests take each half). */
typedef struct {
    int kind, nx, ny;
    double box_scale;
} grid_case;

static const grid_case grids[] = {
    {CW_GRID_KALKER_STRIPS, 20, 20, 1.0},
    {CW_GRID_KALKER_STRIPS, 13, 7, 1.0},
    {CW_GRID_UNIFORM, 24, 24, 1.2},
    {CW_GRID_UNIFORM, 15, 31, 1.05},
};
enum { N_GRIDS = sizeof grids / sizeof grids[0] };

static double max_abs(double a, double b) { return fabs(a) > fabs(b) ? fabs(a) : fabs(b); }

static cw_solver* solver_on(const grid_case* g)
{
    return cw_test_solver(g->kind, g->nx, g->ny, g->box_scale);
}

/* A check of one FULL solve: the handle (still holding it), the grid, the
 * contact and everything the solve exposes. */
typedef void (*solution_check)(cw_solver* s, const grid_case* g, const cw_params* p,
                               const solution* sol);

/* Runs check on every case of the list on every grid of grids[0..n). */
static void for_each_solve(const grid_case* grids_, int n, solution_check check)
{
    for (int g = 0; g < n; ++g) {
        cw_solver* s = solver_on(&grids_[g]);
        for (int k = 0; k < CW_TEST_CASES; ++k) {
            cw_params p;
            cw_test_case(k, &p);
            cw_result r;
            cw_result_init(&r);
            assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
            solution sol;
            solution_fetch(s, &sol);
            assert_memory_equal(&sol.r, &r, sizeof r); /* get_result = solve's result */
            check(s, &grids_[g], &p, &sol);
            solution_free(&sol);
        }
        cw_solver_destroy(s);
    }
}

/* ---------------------------------------------------------------- lifecycle */

static void create_destroy_and_grid_size(void** state)
{
    (void)state;
    for (int g = 0; g < N_GRIDS; ++g) {
        cw_solver* s = solver_on(&grids[g]);
        int nx = -1, ny = -1;
        assert_int_equal(cw_solver_grid_size(s, &nx, &ny), CW_OK);
        assert_int_equal(nx, grids[g].nx);
        assert_int_equal(ny, grids[g].ny);
        assert_string_equal(cw_solver_last_error(s), ""); /* nothing failed yet */
        assert_int_equal(cw_solver_destroy(s), CW_OK);
    }
    assert_int_equal(cw_solver_destroy(NULL), CW_OK); /* header: NULL is a no-op */
}

/* Limits are inclusive: 1..CW_MAX_GRID_CELLS, box scale 1..CW_MAX_BOX_SCALE. */
static void grid_limits_are_inclusive(void** state)
{
    (void)state;
    const grid_case edge[] = {
        {CW_GRID_KALKER_STRIPS, 1, 1, 1.0},
        {CW_GRID_KALKER_STRIPS, CW_MAX_GRID_CELLS, 1, 1.0},
        {CW_GRID_KALKER_STRIPS, 1, CW_MAX_GRID_CELLS, 1.0},
        {CW_GRID_UNIFORM, 1, 1, 1.0},
        {CW_GRID_UNIFORM, 40, 40, CW_MAX_BOX_SCALE},
        {CW_GRID_UNIFORM, CW_MAX_GRID_CELLS, CW_MAX_GRID_CELLS, 1.0},
    };
    cw_params p;
    cw_test_case(0, &p);
    for (size_t k = 0; k < sizeof edge / sizeof edge[0]; ++k) {
        cw_solver* s = solver_on(&edge[k]);
        cw_result r;
        cw_result_init(&r);
        assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
        /* 1 x 1 uniform box: its only centre (0, 0) is inside the ellipse. A box
         * 100 times the ellipse at 40 x 40 cells has no centre inside
         * (cell 5a wide, centres at odd multiples of 2.5a). */
        if (edge[k].kind == CW_GRID_UNIFORM && edge[k].box_scale == CW_MAX_BOX_SCALE)
            assert_int_equal(r.n_contact, 0);
        else
            assert_true(r.n_contact >= 1);
        cw_solver_destroy(s);
    }
}

/* The plan pattern: a handle carries nothing from one solve to the next, so
 * A, B, A on one handle gives A bitwise as on a fresh handle. */
static void handle_reuse_is_stateless(void** state)
{
    (void)state;
    for (int g = 0; g < N_GRIDS; ++g) {
        cw_solver* s = solver_on(&grids[g]);
        cw_solver* fresh = solver_on(&grids[g]);
        for (int k = 0; k < CW_TEST_CASES; ++k) {
            cw_params p, other;
            cw_test_case(k, &p);
            cw_test_case((k + 3) % CW_TEST_CASES, &other);
            cw_result first, again, reference;
            cw_result_init(&first);
            cw_result_init(&again);
            cw_result_init(&reference);
            assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &first), CW_OK);
            assert_int_equal(cw_solver_solve(s, &other, CW_SOLVE_FULL, NULL), CW_OK);
            assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &again), CW_OK);
            assert_int_equal(cw_solver_solve(fresh, &p, CW_SOLVE_FULL, &reference), CW_OK);
            assert_memory_equal(&first, &again, sizeof first);
            assert_memory_equal(&first, &reference, sizeof first);

            solution a, b;
            solution_fetch(s, &a);
            solution_fetch(fresh, &b);
            for (int f = 0; f < N_FIELDS; ++f)
                assert_memory_equal(a.f[f], b.f[f], a.n * sizeof(double));
            assert_memory_equal(a.state, b.state, a.n * sizeof(int));
            assert_memory_equal(a.profile_w, b.profile_w, (size_t)a.ny * sizeof(double));
            solution_free(&a);
            solution_free(&b);
        }
        cw_solver_destroy(s);
        cw_solver_destroy(fresh);
    }
}

/* result may be NULL; cw_solver_get_result then gives what solve would have
 * written (same bytes). */
static void get_result_equals_solve_result(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_KALKER_STRIPS, 20, 20, 1.0);
    for (int mode = CW_SOLVE_FORCES; mode <= CW_SOLVE_FULL; ++mode)
        for (int k = 0; k < CW_TEST_CASES; ++k) {
            cw_params p;
            cw_test_case(k, &p);
            cw_result direct, later;
            cw_result_init(&direct);
            cw_result_init(&later);
            assert_int_equal(cw_solver_solve(s, &p, mode, &direct), CW_OK);
            assert_int_equal(cw_solver_solve(s, &p, mode, NULL), CW_OK);
            assert_int_equal(cw_solver_get_result(s, &later), CW_OK);
            assert_memory_equal(&direct, &later, sizeof direct);
        }
    cw_solver_destroy(s);
}

/* ----------------------------------------------------------------- geometry */

/* Kalker 1982 strip grid: ny equal strips over [-b, b]; each strip's chord
 * 2a sqrt(1 - Y^2) cut into nx equal elements; element (i, j) at
 * [i + j*nx] with x increasing with i whatever the rolling direction. */
static void check_kalker_geometry(cw_solver* s, const grid_case* g, const cw_params* p,
                                  const solution* sol)
{
    (void)s;
    const int nx = g->nx, ny = g->ny;
    assert_int_equal(sol->r.n_contact, nx * ny);
    for (int j = 0; j < ny; ++j) {
        const double Y = -1.0 + (2.0 * j + 1.0) / ny;
        const double c = sqrt(1.0 - Y * Y);
        for (int i = 0; i < nx; ++i) {
            const size_t e = (size_t)i + (size_t)j * nx;
            /* x = a (c - (m + 1/2) dx) in the core: rounding of c a. */
            assert_close(sol->f[CW_FIELD_X][e], p->a * c * (-1.0 + (2.0 * i + 1.0) / nx), 1e-14,
                         1e-15 * p->a);
            assert_close(sol->f[CW_FIELD_Y][e], p->b * Y, 1e-14, 1e-15 * p->b);
            assert_close(sol->f[CW_FIELD_AREA][e], p->a * p->b * (2.0 * c / nx) * (2.0 / ny),
                         1e-14, 0.0);
            assert_int_not_equal(sol->state[e], CW_STATE_EXTERIOR);
        }
        assert_close(sol->profile_y[j], p->b * Y, 1e-14, 1e-15 * p->b);
    }
}

static void kalker_grid_geometry(void** state)
{
    (void)state;
    for_each_solve(grids, 2, check_kalker_geometry);
}

/* CONTACT's uniform grid: box [-S a, S a] x [-S b, S b] of equal cells; a
 * cell is in contact when its centre is inside the ellipse (reference
 * data's README); exterior cells have zero area, pressure and traction. */
static void check_uniform_geometry(cw_solver* s, const grid_case* g, const cw_params* p,
                                   const solution* sol)
{
    (void)s;
    const int nx = g->nx, ny = g->ny;
    const double S = g->box_scale;
    int inside_count = 0;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const size_t e = (size_t)i + (size_t)j * nx;
            const double X = S * (-1.0 + (2.0 * i + 1.0) / nx);
            const double Y = S * (-1.0 + (2.0 * j + 1.0) / ny);
            const int inside = X * X + Y * Y < 1.0;
            inside_count += inside;
            assert_close(sol->f[CW_FIELD_X][e], p->a * X, 1e-14, 1e-15 * p->a);
            assert_close(sol->f[CW_FIELD_Y][e], p->b * Y, 1e-14, 1e-15 * p->b);
            const double cell = (2.0 * S * p->a / nx) * (2.0 * S * p->b / ny);
            assert_close(sol->f[CW_FIELD_AREA][e], inside ? cell : 0.0, 1e-14, 0.0);
            if (!inside) {
                assert_int_equal(sol->state[e], CW_STATE_EXTERIOR);
                assert_true(sol->f[CW_FIELD_PZ][e] == 0.0);
                assert_true(sol->f[CW_FIELD_PX][e] == 0.0 && sol->f[CW_FIELD_PY][e] == 0.0);
            } else {
                assert_int_not_equal(sol->state[e], CW_STATE_EXTERIOR);
            }
        }
    assert_int_equal(sol->r.n_contact, inside_count);
}

static void uniform_grid_geometry(void** state)
{
    (void)state;
    for_each_solve(grids + 2, 2, check_uniform_geometry);
}

/* Header, CW_PRESSURE_*: parabolic 2N/(pi a b)(1 - x^2/a^2 - y^2/b^2) (paper
 * eq. 16), elliptic 3N/(2 pi a b) sqrt(...) (Hertz), at element centres
 * (the exterior of the uniform grid has none). */
static void check_pressure(cw_solver* s, const grid_case* g, const cw_params* p,
                           const solution* sol)
{
    (void)s;
    (void)g;
    const double pi = 3.14159265358979323846;
    const double p0 = p->pressure == CW_PRESSURE_PARABOLIC
                          ? 2.0 * p->normal_force / (pi * p->a * p->b)
                          : 3.0 * p->normal_force / (2.0 * pi * p->a * p->b);
    for (size_t e = 0; e < sol->n; ++e) {
        const double X = sol->f[CW_FIELD_X][e] / p->a, Y = sol->f[CW_FIELD_Y][e] / p->b;
        const double r = fmax(0.0, 1.0 - X * X - Y * Y);
        const double shape = sol->state[e] == CW_STATE_EXTERIOR ? 0.0
                             : p->pressure == CW_PRESSURE_PARABOLIC ? r
                                                                    : sqrt(r);
        /* Rounding of X, Y enters 1 - X^2 - Y^2 absolutely. */
        assert_close(sol->f[CW_FIELD_PZ][e], p0 * shape, 1e-13, 1e-13 * p0);
    }
}

static void pressure_laws(void** state)
{
    (void)state;
    for_each_solve(grids, N_GRIDS, check_pressure);
}

/* ---------------------------------------------------------- totals/fields */

/* Identities between the totals and the fields, for every case on every
 * grid:
 *   Fx = sum px*area, Fy = sum py*area, Mz = sum MZ field (header, fields);
 *   MZ field = (x py - y px) area (header, CW_FIELD_MZ);
 *   W_macro = -(Fx xi_x + Fy xi_y + Mz phi) (paper eq. 34);
 *   W_micro_paper = sum WORK_PAPER, K = W_macro / W_micro_paper (eq. 39);
 *   W_consistent = sum WORK_CONSISTENT = W_macro when W_macro > 0;
 *   n_contact/n_adhesion/n_slip = counts of states, adhesion_fraction their
 *   ratio. Sums to 1e-12 of the sum of magnitudes (rounding of a sum). */
static void check_totals(cw_solver* s, const grid_case* g, const cw_params* p,
                         const solution* sol)
{
    (void)s;
    (void)g;
    const cw_result r = sol->r;
    const double *x = sol->f[CW_FIELD_X], *y = sol->f[CW_FIELD_Y], *area = sol->f[CW_FIELD_AREA],
                 *px = sol->f[CW_FIELD_PX], *py = sol->f[CW_FIELD_PY], *mz = sol->f[CW_FIELD_MZ],
                 *wp = sol->f[CW_FIELD_WORK_PAPER], *wc = sol->f[CW_FIELD_WORK_CONSISTENT];
    double fx = 0, fy = 0, m = 0, fmag = 0, mmag = 0, wpsum = 0, wpmag = 0, wcsum = 0;
    int counts[3] = {0, 0, 0};
    for (size_t e = 0; e < sol->n; ++e) {
        fx += px[e] * area[e];
        fy += py[e] * area[e];
        m += mz[e];
        fmag += (fabs(px[e]) + fabs(py[e])) * area[e];
        mmag += fabs(mz[e]);
        const double mz_e = (x[e] * py[e] - y[e] * px[e]) * area[e];
        assert_close(mz[e], mz_e, 1e-12,
                     1e-14 * (fabs(x[e] * py[e]) + fabs(y[e] * px[e])) * area[e]);
        wpsum += wp[e];
        wpmag += fabs(wp[e]);
        wcsum += wc[e];
        assert_in_range(sol->state[e], CW_STATE_EXTERIOR, CW_STATE_SLIP);
        counts[sol->state[e]]++;
        /* The energy-consistent map is a dissipation: >= 0 (work.hpp). */
        assert_true(wc[e] >= 0.0);
    }
    assert_close(r.Fx, fx, 0.0, 1e-12 * fmag + 1e-300);
    assert_close(r.Fy, fy, 0.0, 1e-12 * fmag + 1e-300);
    assert_close(r.Mz, m, 0.0, 1e-12 * mmag + 1e-300);

    const double terms = fabs(r.Fx * p->xi_x) + fabs(r.Fy * p->xi_y) + fabs(r.Mz * p->phi);
    assert_close(r.W_macro, -(r.Fx * p->xi_x + r.Fy * p->xi_y + r.Mz * p->phi), 0.0,
                 1e-15 * terms);
    assert_close(r.W_micro_paper, wpsum, 0.0, 1e-12 * wpmag);
    if (r.W_micro_paper != 0.0)
        assert_close(r.K, r.W_macro / r.W_micro_paper, 1e-15, 0.0);
    else
        assert_true(r.K == 0.0); /* header: 0 if undefined */
    assert_close(r.W_consistent, wcsum, 1e-12, 0.0);
    if (r.W_macro > 0.0 && !(r.work_flags & CW_WORK_NON_POSITIVE))
        assert_close(r.W_consistent, r.W_macro, 1e-12, 0.0);
    else
        assert_true(r.W_consistent == 0.0);

    assert_int_equal(counts[CW_STATE_ADHESION] + counts[CW_STATE_SLIP], r.n_contact);
    assert_int_equal(counts[CW_STATE_ADHESION], r.n_adhesion);
    assert_int_equal(counts[CW_STATE_SLIP], r.n_slip);
    assert_close(r.adhesion_fraction, r.n_contact ? (double)r.n_adhesion / r.n_contact : 0.0,
                 1e-15, 0.0);
    assert_true(r.a == p->a && r.b == p->b);
}

static void totals_are_the_sums_of_the_fields(void** state)
{
    (void)state;
    for_each_solve(grids, N_GRIDS, check_totals);
}

/* Coulomb's law on the discrete contact (Kalker 1982): |p| <= mu pz
 * everywhere, |p| = mu pz in slip; micro-slip zero in adhesion and opposed
 * to the traction component by component in slip (FASTSIM: s = (f-1) L q/h
 * with p = f q, 0 <= f < 1). The energy-consistent work is zero in adhesion
 * unless no element slips at all (CW_WORK_UNRESOLVED). */
static void check_coulomb(cw_solver* s, const grid_case* g, const cw_params* p,
                          const solution* sol)
{
    (void)s;
    (void)g;
    const double slip_scale = fabs(p->xi_x) + fabs(p->xi_y) + fabs(p->phi) * max_abs(p->a, p->b);
    for (size_t e = 0; e < sol->n; ++e) {
        const double px = sol->f[CW_FIELD_PX][e], py = sol->f[CW_FIELD_PY][e];
        const double sx = sol->f[CW_FIELD_SX][e], sy = sol->f[CW_FIELD_SY][e];
        const double bound = p->mu * sol->f[CW_FIELD_PZ][e];
        const double traction = sqrt(px * px + py * py);
        assert_true(traction <= bound * (1.0 + 1e-12));
        if (sol->state[e] == CW_STATE_SLIP) {
            assert_close(traction, bound, 1e-12, 0.0);
            assert_true(sx != 0.0 || sy != 0.0);
            assert_true(px * sx <= 1e-9 * fabs(px) * slip_scale);
            assert_true(py * sy <= 1e-9 * fabs(py) * slip_scale);
        } else {
            assert_true(sx == 0.0 && sy == 0.0);
            if (!(sol->r.work_flags & CW_WORK_UNRESOLVED))
                assert_true(sol->f[CW_FIELD_WORK_CONSISTENT][e] == 0.0);
        }
    }
}

static void coulomb_law_and_slip_directions(void** state)
{
    (void)state;
    for_each_solve(grids, N_GRIDS, check_coulomb);
}

/* Header "Forces": on the wheel, opposite in sign to the creepage, for both
 * rolling directions. Pure longitudinal full slip: every element slides
 * with |p| = mu pz against xi_x, so Fx = -mu sum(pz area) exactly (to
 * rounding), Fy = 0, and sum(pz area) is N up to the midpoint rule's error:
 * along a chord it overestimates the parabola by 1/(2 nx^2) = 0.125 % at
 * nx = 20, the sum over strips adds a little; bound 0.5 %. */
static void full_slip_longitudinal(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_KALKER_STRIPS, 20, 20, 1.0);
    for (int dir = -1; dir <= 1; dir += 2)
        for (int sign = -1; sign <= 1; sign += 2) {
            cw_params p;
            cw_params_init(&p);
            p.xi_x = sign * 0.5;
            p.rolling_direction = dir;
            cw_result r;
            cw_result_init(&r);
            assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
            solution sol;
            solution_fetch(s, &sol);
            double load = 0.0;
            for (size_t e = 0; e < sol.n; ++e)
                load += sol.f[CW_FIELD_PZ][e] * sol.f[CW_FIELD_AREA][e];
            assert_int_equal(r.n_slip, r.n_contact);
            assert_int_equal(r.n_adhesion, 0);
            assert_true(r.adhesion_fraction == 0.0);
            assert_close(r.Fx, -sign * p.mu * load, 1e-12, 0.0);
            assert_close(fabs(r.Fx), p.mu * p.normal_force, 5e-3, 0.0);
            assert_true(r.Fy == 0.0);
            assert_close(r.Mz, 0.0, 0.0, 1e-12 * fabs(r.Fx) * p.b); /* symmetric in y */
            /* All slides: W_macro = mu N |xi_x| to the same accuracy, and the
             * consistent map carries it. */
            assert_close(r.W_macro, fabs(r.Fx * p.xi_x), 1e-15, 0.0);
            assert_close(r.W_consistent, r.W_macro, 1e-12, 0.0);
            solution_free(&sol);
        }
    cw_solver_destroy(s);
}

/* Lateral: same statement for xi_y on the uniform grid with Hertz pressure:
 * Fy = -mu sum(pz area), Fx = 0 (no longitudinal rigid slip). */
static void full_slip_lateral_uniform_elliptic(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_UNIFORM, 40, 40, 1.0);
    cw_params p;
    cw_params_init(&p);
    p.pressure = CW_PRESSURE_ELLIPTIC;
    p.xi_y = 0.3;
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
    solution sol;
    solution_fetch(s, &sol);
    double load = 0.0;
    for (size_t e = 0; e < sol.n; ++e) load += sol.f[CW_FIELD_PZ][e] * sol.f[CW_FIELD_AREA][e];
    assert_int_equal(r.n_slip, r.n_contact);
    assert_close(r.Fy, -p.mu * load, 1e-12, 0.0);
    assert_true(r.Fx == 0.0);
    /* Centre-in-ellipse cells at 40 x 40: a staircase boundary, where the
     * Hertz pressure vanishes; the load is N to 0.1 %, bound 0.5 %. */
    assert_close(load, p.normal_force, 5e-3, 0.0);
    solution_free(&sol);
    cw_solver_destroy(s);
}

/* Mirror x -> -x: Kalker's rigid slip (xi - phi y, eta + phi x) is mapped
 * onto itself with xi -> -xi, phi -> -phi, so rolling towards -x with
 * (xi, eta, phi) is the mirror image of rolling towards +x with
 * (-xi, eta, -phi): Fx and Mz change sign, Fy and the work do not, and
 * every field at i is the mirrored field at nx-1-i. */
static void rolling_direction_mirror_symmetry(void** state)
{
    (void)state;
    for (int g = 0; g < N_GRIDS; ++g) {
        cw_solver* s = solver_on(&grids[g]);
        const int nx = grids[g].nx, ny = grids[g].ny;
        for (int k = 0; k < CW_TEST_CASES; ++k) {
            cw_params back, fwd;
            cw_test_case(k, &back);
            back.rolling_direction = -1;
            fwd = back;
            fwd.rolling_direction = 1;
            fwd.xi_x = -back.xi_x;
            fwd.phi = -back.phi;
            assert_int_equal(cw_solver_solve(s, &back, CW_SOLVE_FULL, NULL), CW_OK);
            solution b;
            solution_fetch(s, &b);
            assert_int_equal(cw_solver_solve(s, &fwd, CW_SOLVE_FULL, NULL), CW_OK);
            solution f;
            solution_fetch(s, &f);
            const double F = fabs(f.r.Fx) + fabs(f.r.Fy) + 1e-300;
            assert_close(b.r.Fx, -f.r.Fx, 0.0, 1e-14 * F);
            assert_close(b.r.Fy, f.r.Fy, 0.0, 1e-14 * F);
            assert_close(b.r.Mz, -f.r.Mz, 0.0, 1e-14 * F * max_abs(back.a, back.b));
            assert_close(b.r.W_macro, f.r.W_macro, 1e-14, 1e-300);
            assert_close(b.r.W_consistent, f.r.W_consistent, 1e-14, 1e-300);
            assert_int_equal(b.r.n_slip, f.r.n_slip);
            /* x, px, sx and the moment arm flip sign; the rest is mirrored. */
            const double sign[N_FIELDS] = {-1, 1, 1, 1, -1, 1, -1, 1, -1, 1, 1};
            for (int fld = 0; fld < N_FIELDS; ++fld) {
                double scale = 0.0;
                for (size_t e = 0; e < f.n; ++e) scale = max_abs(scale, f.f[fld][e]);
                for (int j = 0; j < ny; ++j)
                    for (int i = 0; i < nx; ++i) {
                        const size_t e = (size_t)i + (size_t)j * nx;
                        const size_t m = (size_t)(nx - 1 - i) + (size_t)j * nx;
                        assert_close(b.f[fld][e], sign[fld] * f.f[fld][m], 0.0, 1e-13 * scale);
                    }
            }
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx; ++i)
                    assert_int_equal(b.state[i + j * nx], f.state[(nx - 1 - i) + j * nx]);
            solution_free(&b);
            solution_free(&f);
        }
        cw_solver_destroy(s);
    }
}

/* ------------------------------------------------------------ modes/profile */

/* CW_SOLVE_FORCES runs the same march: totals, tractions and states are
 * bitwise those of CW_SOLVE_FULL; the FULL-only totals stay zero. */
static void check_forces_mode(cw_solver* s, const grid_case* g, const cw_params* p,
                              const solution* sol)
{
    (void)g;
    cw_result forces;
    cw_result_init(&forces);
    assert_int_equal(cw_solver_solve(s, p, CW_SOLVE_FORCES, &forces), CW_OK);
    const cw_result full = sol->r;
    assert_true(cw_same_bits(forces.Fx, full.Fx) && cw_same_bits(forces.Fy, full.Fy) &&
                cw_same_bits(forces.Mz, full.Mz) && cw_same_bits(forces.W_macro, full.W_macro));
    assert_int_equal(forces.n_slip, full.n_slip);
    assert_int_equal(forces.n_adhesion, full.n_adhesion);
    assert_true(forces.W_micro_paper == 0.0 && forces.K == 0.0 && forces.W_consistent == 0.0 &&
                forces.work_flags == 0);
    const int available[] = {CW_FIELD_X,  CW_FIELD_Y,  CW_FIELD_AREA, CW_FIELD_PZ,
                             CW_FIELD_PX, CW_FIELD_PY, CW_FIELD_MZ};
    double* buf = malloc(sol->n * sizeof(double));
    int* st = malloc(sol->n * sizeof(int));
    assert_true(buf && st);
    for (size_t a = 0; a < sizeof available / sizeof available[0]; ++a) {
        assert_int_equal(cw_solver_get_field(s, available[a], buf, sol->n), CW_OK);
        assert_memory_equal(buf, sol->f[available[a]], sol->n * sizeof(double));
    }
    assert_int_equal(cw_solver_get_state(s, st, sol->n), CW_OK);
    assert_memory_equal(st, sol->state, sol->n * sizeof(int));
    free(buf);
    free(st);
}

static void forces_mode_equals_full_mode(void** state)
{
    (void)state;
    for_each_solve(grids, N_GRIDS, check_forces_mode);
}

/* Lateral profile (header, cw_solver_get_profile): w_j is strip j's
 * energy-consistent work per unit width, so sum_j w_j * width_j =
 * W_consistent (width 2b/ny on the strip grid, 2Sb/ny on the uniform grid);
 * parabola_j = (3W/4b)(1 - y_j^2/b^2) (zero outside |y| < b); and
 * profile_max_diff / rms_diff are max / RMS |w - parabola| over strips with
 * contact, divided by the peak of w. Each output may be NULL. */
static void check_profile(cw_solver* s, const grid_case* g, const cw_params* p,
                          const solution* sol)
{
    const int ny = g->ny;
    const double W = sol->r.W_consistent;
    const double width = 2.0 * g->box_scale * p->b / ny;
    double area = 0.0, peak = 0.0, max_diff = 0.0, sum_sq = 0.0;
    int strips = 0;
    for (int j = 0; j < ny; ++j) {
        const double yj = sol->profile_y[j];
        const double r = 1.0 - (yj / p->b) * (yj / p->b);
        const double parabola = r > 0.0 ? 0.75 * W / p->b * r : 0.0;
        assert_close(sol->profile_parabola[j], parabola, 1e-14, 1e-300);
        double strip = 0.0;
        int contact = 0;
        for (int i = 0; i < sol->nx; ++i) {
            strip += sol->f[CW_FIELD_WORK_CONSISTENT][i + (size_t)j * sol->nx];
            contact += sol->state[i + (size_t)j * sol->nx] != CW_STATE_EXTERIOR;
        }
        assert_close(sol->profile_w[j] * width, strip, 1e-13, 1e-300);
        area += sol->profile_w[j] * width;
        peak = max_abs(peak, sol->profile_w[j]);
        if (contact) {
            const double d = fabs(sol->profile_w[j] - sol->profile_parabola[j]);
            max_diff = max_abs(max_diff, d);
            sum_sq += d * d;
            ++strips;
        }
    }
    assert_close(area, W, 1e-12, 1e-300);
    if (peak > 0.0) {
        assert_close(sol->r.profile_max_diff, max_diff / peak, 1e-12, 0.0);
        assert_close(sol->r.profile_rms_diff, sqrt(sum_sq / strips) / peak, 1e-12, 0.0);
    }
    /* One output at a time: the same numbers. */
    double* one = malloc((size_t)ny * sizeof(double));
    assert_non_null(one);
    assert_int_equal(cw_solver_get_profile(s, NULL, one, NULL, (size_t)ny), CW_OK);
    assert_memory_equal(one, sol->profile_w, (size_t)ny * sizeof(double));
    assert_int_equal(cw_solver_get_profile(s, NULL, NULL, one, (size_t)ny), CW_OK);
    assert_memory_equal(one, sol->profile_parabola, (size_t)ny * sizeof(double));
    assert_int_equal(cw_solver_get_profile(s, NULL, NULL, NULL, (size_t)ny), CW_OK);
    free(one);
}

static void lateral_profile_identities(void** state)
{
    (void)state;
    for_each_solve(grids, N_GRIDS, check_profile);
}

/* Longer buffers are fine: exactly nx*ny values are written, the rest is
 * left alone. */
static void longer_buffers_keep_their_tail(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_UNIFORM, 9, 5, 1.1);
    cw_params p;
    cw_test_case(2, &p);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
    double buf[45 + 3];
    int st[45 + 3];
    cw_fill(buf, 48, CW_SENTINEL);
    cw_fill_int(st, 48, CW_INT_SENTINEL);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PX, buf, 48), CW_OK);
    assert_int_equal(cw_solver_get_state(s, st, 48), CW_OK);
    assert_int_equal(cw_count_changed(buf, 45, CW_SENTINEL), 45); /* all written */
    assert_untouched(buf + 45, 3);
    assert_untouched_int(st + 45, 3);
    cw_fill(buf, 48, CW_SENTINEL);
    assert_int_equal(cw_solver_get_profile(s, buf, NULL, NULL, 8), CW_OK);
    assert_untouched(buf + 5, 3);
    cw_solver_destroy(s);
}

/* ------------------------------------------------------------- reference */

/* CONTACT (Vollebregt & Kalker, reference/contact_fastsim_dev.csv), through
 * the ABI in CONTACT's own units (mm, N, N/mm^2): uniform grid, flexibilities
 * given, rolling towards +x. Rows whose FASTSIM variant is exactly specified
 * (the reference data's README): b, c without spin; b0, bk. FX, FY, MZ to 1e-9 of |F|
 * (MZ / a), adhesion/slip counts exactly, and W_macro = -FRIC_POWER_macro
 * (V = 1000 mm/s and /1000 cancel). */
enum { CSV_COLUMNS = 29 };

static int split_csv(char* line, char* cols[CSV_COLUMNS])
{
    int n = 0;
    char* c = line;
    while (n < CSV_COLUMNS) {
        cols[n++] = c;
        char* comma = strchr(c, ',');
        if (!comma) break;
        *comma = '\0';
        c = comma + 1;
    }
    return n;
}

static void contact_reference_rows(void** state)
{
    (void)state;
    FILE* f = fopen(CW_TEST_DATA_DIR "/contact_fastsim_dev.csv", "r");
    assert_non_null(f);
    char line[2048];
    char* cols[CSV_COLUMNS];
    assert_non_null(fgets(line, sizeof line, f));
    /* Columns of the header line, checked so a reordered file fails loudly. */
    line[strcspn(line, "\r\n")] = '\0';
    assert_int_equal(split_csv(line, cols), CSV_COLUMNS);
    assert_string_equal(cols[1], "method");
    assert_string_equal(cols[4], "MX");
    assert_string_equal(cols[9], "a_mm");
    assert_string_equal(cols[18], "L1_mm3_per_N");
    assert_string_equal(cols[21], "FX_N");
    assert_string_equal(cols[25], "FRIC_POWER_macro_W");
    assert_string_equal(cols[28], "n_contact");
    int checked = 0;
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\r\n")] = '\0';
        if (split_csv(line, cols) != CSV_COLUMNS) continue;
        const char* m = cols[1];
        const double phi = atof(cols[17]);
        const int specified = ((!strcmp(m, "b") || !strcmp(m, "c")) && phi == 0.0) ||
                              !strcmp(m, "b0") || !strcmp(m, "bk");
        if (!specified) continue;
        cw_solver* s = cw_test_solver(CW_GRID_UNIFORM, atoi(cols[4]), atoi(cols[5]), atof(cols[6]));
        cw_params p;
        cw_params_init(&p);
        p.a = atof(cols[9]);
        p.b = atof(cols[10]);
        p.normal_force = atof(cols[11]);
        p.mu = atof(cols[12]);
        p.flexibility = CW_FLEX_GIVEN;
        p.L1 = atof(cols[18]);
        p.L2 = atof(cols[19]);
        p.L3 = atof(cols[20]);
        p.xi_x = atof(cols[15]);
        p.xi_y = atof(cols[16]);
        p.phi = phi;
        p.pressure = !strcmp(m, "c") ? CW_PRESSURE_ELLIPTIC : CW_PRESSURE_PARABOLIC;
        cw_result r;
        cw_result_init(&r);
        assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &r), CW_OK);
        const double FX = atof(cols[21]), FY = atof(cols[22]), MZ = atof(cols[23]);
        const double F = sqrt(FX * FX + FY * FY);
        assert_close(r.Fx, FX, 0.0, 1e-9 * F);
        assert_close(r.Fy, FY, 0.0, 1e-9 * F);
        assert_close(r.Mz, MZ, 0.0, 1e-9 * F * p.a);
        assert_close(r.W_macro, -atof(cols[25]), 1e-9, 0.0);
        assert_int_equal(r.n_adhesion, atoi(cols[26]));
        assert_int_equal(r.n_slip, atoi(cols[27]));
        assert_int_equal(r.n_contact, atoi(cols[28]));
        cw_solver_destroy(s);
        ++checked;
    }
    fclose(f);
    /* b and c for 12 pure-creepage cases, b0 for 6 spin cases, bk for 2
     * combined ones, each on 3 grids. */
    assert_int_equal(checked, 96);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(create_destroy_and_grid_size),
        cmocka_unit_test(grid_limits_are_inclusive),
        cmocka_unit_test(handle_reuse_is_stateless),
        cmocka_unit_test(get_result_equals_solve_result),
        cmocka_unit_test(kalker_grid_geometry),
        cmocka_unit_test(uniform_grid_geometry),
        cmocka_unit_test(pressure_laws),
        cmocka_unit_test(totals_are_the_sums_of_the_fields),
        cmocka_unit_test(coulomb_law_and_slip_directions),
        cmocka_unit_test(full_slip_longitudinal),
        cmocka_unit_test(full_slip_lateral_uniform_elliptic),
        cmocka_unit_test(rolling_direction_mirror_symmetry),
        cmocka_unit_test(forces_mode_equals_full_mode),
        cmocka_unit_test(lateral_profile_identities),
        cmocka_unit_test(longer_buffers_keep_their_tail),
        cmocka_unit_test(contact_reference_rows),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
