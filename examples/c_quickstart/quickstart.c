/* creepwork quickstart: creep forces and work map of one wheel-rail contact. */
#include <stdio.h>
#include <creepwork/creepwork.h>

int main(void)
{
    cw_grid grid;
    cw_grid_init(&grid); /* Kalker's strip grid, 20 x 20 elements */
    cw_solver* solver = NULL;
    char message[256];
    if (cw_solver_create(&grid, &solver, message, sizeof message) != CW_OK) {
        fprintf(stderr, "creepwork: %s\n", message);
        return 1;
    }

    cw_params p;
    cw_params_init(&p);     /* steel, mu = 0.3, parabolic pressure; SI units */
    p.a = 7.0e-3;           /* semi-axes along / across the rail [m] (cw_hertz_solve) */
    p.b = 5.0e-3;
    p.normal_force = 100e3; /* wheel load [N] */
    p.xi_x = 1.0e-3;        /* creepages [-] and spin [1/m] */
    p.xi_y = 5.0e-4;
    p.phi = 0.5;

    cw_result r;
    cw_result_init(&r);
    double work[20 * 20];   /* element (i, j) at [i + 20*j], i along x [J/m] */
    if (cw_solver_solve(solver, &p, CW_SOLVE_FULL, &r) != CW_OK ||
        cw_solver_get_field(solver, CW_FIELD_WORK_CONSISTENT, work, 20 * 20) != CW_OK) {
        fprintf(stderr, "creepwork: %s\n", cw_solver_last_error(solver));
        cw_solver_destroy(solver);
        return 1;
    }
    printf("Fx = %.1f N, Fy = %.1f N, Mz = %.3f N m (on the wheel)\n", r.Fx, r.Fy, r.Mz);
    printf("W_macro = %.4f J/m, K = %.3f, adhesion %.0f %%\n", r.W_macro, r.K,
           100.0 * r.adhesion_fraction);
    printf("work of element (0, 10) at the trailing edge: %.3g J/m\n", work[0 + 20 * 10]);
    cw_solver_destroy(solver); /* the solver is reusable: solve again before this */
    return 0;
}
