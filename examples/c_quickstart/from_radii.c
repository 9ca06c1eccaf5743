/* creepwork: from wheel and rail profile radii to a solve. The contact
 * ellipse comes from Hertz's theory: the undeformed gap between the bodies
 * is A x^2 + B y^2, so A and B are HALF the relative curvatures, summed
 * over both bodies: A = (1/R_wheel,x + 1/R_rail,x)/2 along the rolling
 * direction, B the same across. A flat rail head along the track and a flat
 * wheel tread across it have curvature 0. */
#include <stdio.h>
#include <creepwork/creepwork.h>

int main(void)
{
    const double R_wheel = 0.457; /* rolling radius [m] (along x) */
    const double R_crown = 0.300; /* rail head crown radius [m] (across y) */
    const double G = 82e9, nu = 0.28, N = 100e3;
    const double A = 0.5 * (1.0 / R_wheel), B = 0.5 * (1.0 / R_crown); /* [1/m] */
    double hertz[4]; /* a, b [m], p0 [Pa], approach [m] */
    char message[256];
    if (cw_hertz_solve(A, B, N, G / (1.0 - nu), hertz, message, sizeof message) != CW_OK) {
        fprintf(stderr, "creepwork: %s\n", message);
        return 1;
    }
    printf("Hertz: a = %.3f mm, b = %.3f mm, p0 = %.0f MPa\n", hertz[0] * 1e3, hertz[1] * 1e3,
           hertz[2] * 1e-6);

    cw_grid grid;
    cw_grid_init(&grid);
    cw_solver* solver = NULL;
    if (cw_solver_create(&grid, &solver, message, sizeof message) != CW_OK) {
        fprintf(stderr, "creepwork: %s\n", message);
        return 1;
    }
    cw_params p;
    cw_params_init(&p);
    p.a = hertz[0];
    p.b = hertz[1];
    p.normal_force = N;
    p.G = G;
    p.nu = nu;
    p.mu = 0.3;
    p.xi_x = 1.0e-3;
    cw_result r;
    cw_result_init(&r);
    if (cw_solver_solve(solver, &p, CW_SOLVE_FORCES, &r) != CW_OK) {
        fprintf(stderr, "creepwork: %s\n", cw_solver_last_error(solver));
        cw_solver_destroy(solver);
        return 1;
    }
    printf("xi_x = 1e-3: Fx = %.0f N on the wheel, %.0f %% of mu N\n", r.Fx,
           100.0 * -r.Fx / (p.mu * N));
    cw_solver_destroy(solver);
    return 0;
}
