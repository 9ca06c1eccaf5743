/* The C side of the cross-language test: solves a set of cases through the
 * C ABI and writes inputs and outputs (%.17g, which round-trips every
 * double) to the file named by argv[1]. test_fortran_cross replays the same
 * inputs through module creepwork and the legacy layer and requires
 * bitwise identical numbers. Records, one per line:
 *   N ux uy fx fy mx my tol tx ty                      Kalker normalised FASTSIM
 *   S kind nx ny pressure flexibility direction a b N mu G nu L1 L2 L3 xi eta phi
 *     Fx Fy Mz W_macro W_micro_paper K W_consistent n_slip  a dimensional solve
 *   F field count v1 .. vcount                          a field of the solve above
 *   Z count s1 .. scount                                its element states
 *   R ny count y1 .. yny width.. depth.. parabola..      its wear strips (USFD, defaults)
 *   B nx ny a b                                         the accumulation's grid and contact
 *   A xi eta phi distance                               one accumulated step
 *   T distance W_macro W_micro_paper K W_consistent steps  accumulator totals
 *   W field count v1 .. vcount                          an accumulated map
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "creepwork/creepwork.h"

static void require_ok(int status, const char* what)
{
    if (status != CW_OK) {
        fprintf(stderr, "%s failed: %s\n", what, cw_status_string(status));
        exit(1);
    }
}

static void print_map(FILE* f, char tag, int field, const double* v, int n)
{
    fprintf(f, "%c %d %d", tag, field, n);
    for (int k = 0; k < n; ++k) fprintf(f, " %.17g", v[k]);
    fprintf(f, "\n");
}

static void normalised_cases(FILE* f)
{
    /* Kalker's check rows (tests/data/kalker1982_checks.csv) and more. */
    const double cases[][7] = {
        {0, -2, 2, 4, 5, 5, 3},     {0, -2, 2, 4, 5, 5, 0.09}, {1, -2, 2, 4, 5, 5, 0.09},
        {1, -2, 2, 4, 5, 5, 3},     {1, -2, 2, 1, 5, 5, 0.09}, {0.3, 0.2, 0, 0, 8, 6, 1},
        {-0.5, 1.5, 3, 2, 20, 15, 0.05}, {2, 0.1, -1, 0.5, 40, 41, 0.2},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        const double* c = cases[k];
        double tx = 0, ty = 0;
        require_ok(cw_fastsim_normalised(c[0], c[1], c[2], c[3], (int)c[4], (int)c[5], c[6], &tx,
                                         &ty, NULL, 0),
                   "cw_fastsim_normalised");
        fprintf(f, "N %.17g %.17g %.17g %.17g %d %d %.17g %.17g %.17g\n", c[0], c[1], c[2], c[3],
                (int)c[4], (int)c[5], c[6], tx, ty);
    }
}

static void solve_case(FILE* f, int kind, int nx, int ny, int pressure, int flexibility,
                       int direction, double a, double b, double xi, double eta, double phi)
{
    cw_grid g;
    cw_grid_init(&g);
    g.kind = kind;
    g.nx = nx;
    g.ny = ny;
    g.box_scale = 1.1;
    cw_solver* s = NULL;
    require_ok(cw_solver_create(&g, &s, NULL, 0), "cw_solver_create");
    cw_params p;
    cw_params_init(&p);
    p.a = a;
    p.b = b;
    p.pressure = pressure;
    p.flexibility = flexibility;
    p.rolling_direction = direction;
    if (flexibility == CW_FLEX_GIVEN) {
        double L[3];
        require_ok(cw_kalker_flexibilities(a, b, p.G, p.nu, L, NULL, 0), "flexibilities");
        p.L1 = 1.1 * L[0];
        p.L2 = 0.9 * L[1];
        p.L3 = L[2];
    }
    p.xi_x = xi;
    p.xi_y = eta;
    p.phi = phi;
    cw_result r;
    cw_result_init(&r);
    require_ok(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), "cw_solver_solve");
    fprintf(f,
            "S %d %d %d %d %d %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g "
            "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %d\n",
            kind, nx, ny, pressure, flexibility, direction, p.a, p.b, p.normal_force, p.mu, p.G,
            p.nu, p.L1, p.L2, p.L3, p.xi_x, p.xi_y, p.phi, r.Fx, r.Fy, r.Mz, r.W_macro,
            r.W_micro_paper, r.K, r.W_consistent, r.n_slip);
    const int n = nx * ny;
    double* v = malloc(sizeof(double) * (size_t)n);
    int* st = malloc(sizeof(int) * (size_t)n);
    if (!v || !st) exit(1);
    for (int field = CW_FIELD_X; field <= CW_FIELD_WORK_CONSISTENT; ++field) {
        require_ok(cw_solver_get_field(s, field, v, (size_t)n), "cw_solver_get_field");
        print_map(f, 'F', field, v, n);
    }
    require_ok(cw_solver_get_state(s, st, (size_t)n), "cw_solver_get_state");
    fprintf(f, "Z %d", n);
    for (int k = 0; k < n; ++k) fprintf(f, " %d", st[k]);
    fprintf(f, "\n");
    /* The lateral wear profile (USFD, the defaults): y, width, depth,
     * parabola per strip, in the header's order. */
    cw_wear* w = NULL;
    require_ok(cw_wear_create(s, &w), "cw_wear_create");
    cw_wear_params wp;
    cw_wear_params_init(&wp);
    require_ok(cw_wear_compute(w, s, &wp, NULL), "cw_wear_compute");
    double* strips = malloc(sizeof(double) * 4 * (size_t)ny);
    if (!strips) exit(1);
    require_ok(cw_wear_get_strips(w, strips, strips + ny, strips + 2 * ny, strips + 3 * ny,
                                  (size_t)ny),
               "cw_wear_get_strips");
    print_map(f, 'R', ny, strips, 4 * ny);
    free(strips);
    cw_wear_destroy(w);
    free(st);
    free(v);
    cw_solver_destroy(s);
}

static void accumulation(FILE* f)
{
    const int nx = 9, ny = 7, steps = 60;
    cw_grid g;
    cw_grid_init(&g);
    g.nx = nx;
    g.ny = ny;
    cw_solver* s = NULL;
    require_ok(cw_solver_create(&g, &s, NULL, 0), "cw_solver_create");
    cw_accumulator* acc = NULL;
    require_ok(cw_accumulator_create(s, &acc), "cw_accumulator_create");
    cw_params p;
    cw_params_init(&p);
    p.a = 7e-3;
    p.b = 4.5e-3;
    fprintf(f, "B %d %d %.17g %.17g\n", nx, ny, p.a, p.b);
    for (int k = 0; k < steps; ++k) {
        p.xi_x = 1.5e-3 * sin(0.37 * k);
        p.xi_y = -1e-3 * cos(0.23 * k);
        p.phi = 0.8 * sin(0.11 * k + 0.4);
        const double distance = 0.02 + 1e-3 * k;
        require_ok(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), "cw_solver_solve");
        require_ok(cw_accumulator_add(acc, s, distance), "cw_accumulator_add");
        fprintf(f, "A %.17g %.17g %.17g %.17g\n", p.xi_x, p.xi_y, p.phi, distance);
    }
    cw_accumulation t;
    cw_accumulation_init(&t);
    require_ok(cw_accumulator_get_totals(acc, &t), "cw_accumulator_get_totals");
    fprintf(f, "T %.17g %.17g %.17g %.17g %.17g %lld\n", t.distance, t.W_macro, t.W_micro_paper,
            t.K, t.W_consistent, (long long)t.steps);
    double v[9 * 7];
    require_ok(cw_accumulator_get_field(acc, CW_FIELD_WORK_PAPER, v, 63), "accumulated paper");
    print_map(f, 'W', CW_FIELD_WORK_PAPER, v, nx * ny);
    require_ok(cw_accumulator_get_field(acc, CW_FIELD_WORK_CONSISTENT, v, 63), "accumulated map");
    print_map(f, 'W', CW_FIELD_WORK_CONSISTENT, v, nx * ny);
    cw_accumulator_destroy(acc);
    cw_solver_destroy(s);
}

int main(int argc, char** argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: %s <output file>\n", argv[0]);
        return 2;
    }
    FILE* f = fopen(argv[1], "w");
    if (!f) {
        perror(argv[1]);
        return 2;
    }
    normalised_cases(f);
    /* Kalker strips, parabolic, material flexibilities, +x: also the legacy CWSOLM case. */
    solve_case(f, CW_GRID_KALKER_STRIPS, 7, 5, CW_PRESSURE_PARABOLIC, CW_FLEX_FROM_MATERIAL, 1,
               6e-3, 4e-3, 1e-3, -6e-4, 0.7);
    solve_case(f, CW_GRID_KALKER_STRIPS, 11, 6, CW_PRESSURE_PARABOLIC, CW_FLEX_FROM_MATERIAL, 1,
               3e-3, 9e-3, -4e-3, 2e-3, -3.0);
    /* Given flexibilities (legacy CWSOLL). */
    solve_case(f, CW_GRID_KALKER_STRIPS, 8, 8, CW_PRESSURE_PARABOLIC, CW_FLEX_GIVEN, 1, 5e-3,
               5e-3, 2e-4, 3e-4, 0.2);
    /* Module only: uniform grid, elliptic pressure, rolling towards -x. */
    solve_case(f, CW_GRID_UNIFORM, 10, 9, CW_PRESSURE_ELLIPTIC, CW_FLEX_FROM_MATERIAL, -1, 6e-3,
               4e-3, 1e-3, -6e-4, 0.7);
    solve_case(f, CW_GRID_KALKER_STRIPS, 6, 7, CW_PRESSURE_ELLIPTIC, CW_FLEX_GIVEN, -1, 8e-3,
               3e-3, -2e-3, 0.0, 1.5);
    accumulation(f);
    return fclose(f) == 0 ? 0 : 1;
}
