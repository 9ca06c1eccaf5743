/* The C side of the exact-model cross-language test: solves a few contacts
 * on the uniform grid through the C ABI, FASTSIM and the exact model, each
 * on a fresh solver (so the exact model starts cold), and writes inputs and
 * outputs (%.17g, which round-trips every double) to the file named by
 * argv[1]. test_fortran_exact solves the same inputs through module
 * creepwork (after cw_solver_type%prepare) and the legacy CWSOLX and
 * requires bitwise identical numbers. Records, one per line:
 *   X model nx ny box a b N mu G nu xi eta phi
 *     Fx Fy Mz W_macro W_micro_paper K W_consistent p_max approach
 *     n_slip n_adhesion iterations residual          one solve
 *   F field count v1 .. vcount                        a field of it
 *   Z count s1 .. scount                              its element states
 */
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

static void solve_case(FILE* f, int model, int nx, int ny, double box, double a, double b,
                       double xi, double eta, double phi)
{
    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_UNIFORM;
    g.nx = nx;
    g.ny = ny;
    g.box_scale = box;
    cw_solver* s = NULL;
    require_ok(cw_solver_create(&g, &s, NULL, 0), "cw_solver_create");
    cw_params p;
    cw_params_init(&p);
    p.model = model;
    p.a = a;
    p.b = b;
    p.normal_force = 90e3;
    p.mu = 0.35;
    p.G = 8.2e10;
    p.nu = 0.28;
    p.xi_x = xi;
    p.xi_y = eta;
    p.phi = phi;
    cw_result r;
    cw_result_init(&r);
    require_ok(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), "cw_solver_solve");
    fprintf(f,
            "X %d %d %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g "
            "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %d %d %d %.17g\n",
            model, nx, ny, box, p.a, p.b, p.normal_force, p.mu, p.G, p.nu, p.xi_x, p.xi_y, p.phi,
            r.Fx, r.Fy, r.Mz, r.W_macro, r.W_micro_paper, r.K, r.W_consistent, r.p_max,
            r.approach, r.n_slip, r.n_adhesion, r.iterations, r.residual);
    const int n = nx * ny;
    double* v = malloc(sizeof(double) * (size_t)n);
    int* st = malloc(sizeof(int) * (size_t)n);
    if (!v || !st) exit(1);
    for (int field = CW_FIELD_X; field <= CW_FIELD_WORK_CONSISTENT; ++field) {
        require_ok(cw_solver_get_field(s, field, v, (size_t)n), "cw_solver_get_field");
        fprintf(f, "F %d %d", field, n);
        for (int k = 0; k < n; ++k) fprintf(f, " %.17g", v[k]);
        fprintf(f, "\n");
    }
    require_ok(cw_solver_get_state(s, st, (size_t)n), "cw_solver_get_state");
    fprintf(f, "Z %d", n);
    for (int k = 0; k < n; ++k) fprintf(f, " %d", st[k]);
    fprintf(f, "\n");
    free(st);
    free(v);
    cw_solver_destroy(s);
}

int main(int argc, char** argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: exact_language_cases <output file>\n");
        return 2;
    }
    FILE* f = fopen(argv[1], "w");
    if (!f) return 1;
    /* Partial slip with spin (CONTACT's layout: 16 across, two guard
     * cells), lateral creepage on an oblong patch, full slip; each by the
     * exact model and by FASTSIM on the same grid. Small grids: CI. */
    for (int model = CW_MODEL_FASTSIM; model <= CW_MODEL_EXACT; ++model) {
        solve_case(f, model, 20, 20, 1.25, 7.2e-3, 5.4e-3, 6e-4, 3e-4, 0.2);
        solve_case(f, model, 18, 12, 1.1, 8e-3, 4e-3, -2e-4, 1e-3, -1.5);
        solve_case(f, model, 14, 16, 1.2, 6e-3, 6e-3, 5e-3, 0.0, 0.0);
    }
    return fclose(f) == 0 ? 0 : 1;
}
