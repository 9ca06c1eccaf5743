/* Vehicle loop, C version: a wheel on tangent track while the wheelset hunts.
 *
 * A solver and an accumulator are made once; every time step computes the
 * creepages of the right wheel from the lateral motion, solves the contact
 * (forces, moment, work maps) and adds the step's work, V*dt of rolling, to
 * the running totals (paper eqs. 35 and 37). At the end it writes the
 * lateral work profile: per strip, the accumulated energy-consistent work
 * per unit width [J/m] -- the distribution the wear model needs.
 *
 * The same loop is in vehicle_loop_f77.f (FORTRAN 77, legacy layer) and
 * vehicle_loop.f90 (module creepwork); CTest checks that the three print the
 * same profile. */
#include <math.h>
#include <stdio.h>

#include "creepwork/creepwork.h"

enum { NX = 20, NY = 20, STEPS = 3000 };

static int check(int status, const char* what)
{
    if (status != CW_OK) fprintf(stderr, "%s: %s\n", what, cw_status_string(status));
    return status != CW_OK;
}

int main(void)
{
    const double pi = 3.14159265358979323846;
    /* Vehicle: V = 30 m/s, dt = 1 ms; wheelset hunting at 2 Hz with 3 mm
     * amplitude; conicity 0.15, rolling radius 0.46 m. */
    const double V = 30.0, dt = 1e-3, f = 2.0, y0 = 3e-3, lambda = 0.15, r0 = 0.46;
    const double omega = 2.0 * pi * f;

    cw_grid grid;
    cw_grid_init(&grid);
    grid.nx = NX;
    grid.ny = NY;
    cw_solver* solver = NULL;
    char message[256];
    if (cw_solver_create(&grid, &solver, message, sizeof message) != CW_OK) {
        fprintf(stderr, "cw_solver_create: %s\n", message);
        return 1;
    }
    cw_accumulator* acc = NULL;
    if (check(cw_accumulator_create(solver, &acc), "cw_accumulator_create")) return 1;

    cw_params p;
    cw_params_init(&p);
    p.a = 6e-3; /* contact ellipse [m] */
    p.b = 4e-3;
    p.normal_force = 60e3; /* [N] */
    p.mu = 0.35;
    for (int k = 1; k <= STEPS; ++k) {
        const double t = k * dt;
        const double y = y0 * sin(omega * t);           /* lateral displacement [m] */
        const double ydot = y0 * omega * cos(omega * t); /* lateral velocity [m/s] */
        const double yaw = 0.7 * ydot / V;               /* yaw lags the kinematic 1.0 [rad] */
        p.xi_x = -lambda * y / r0;               /* rolling-radius difference */
        p.xi_y = ydot / V - yaw;                 /* lateral creepage */
        p.phi = (0.05 + 10.0 * y) / r0;          /* spin from the contact angle [1/m] */
        if (check(cw_solver_solve(solver, &p, CW_SOLVE_FULL, NULL), "cw_solver_solve")) return 1;
        if (check(cw_accumulator_add(acc, solver, V * dt), "cw_accumulator_add")) return 1;
    }

    cw_accumulation totals;
    cw_accumulation_init(&totals);
    double y[NY], strip[NY];
    if (check(cw_accumulator_get_totals(acc, &totals), "cw_accumulator_get_totals") ||
        check(cw_accumulator_get_strip_work(acc, strip, NY), "cw_accumulator_get_strip_work") ||
        check(cw_solver_get_profile(solver, y, NULL, NULL, NY), "cw_solver_get_profile"))
        return 1;
    printf("# creepwork vehicle loop: %d steps, %.1f m rolled\n", STEPS, totals.distance);
    printf("# W_macro = %.9e J, W_micro = %.9e J, K = %.9f\n", totals.W_macro,
           totals.W_micro_paper, totals.K);
    printf("# strip  y [m]  work per unit width [J/m]\n");
    const double width = 2.0 * p.b / NY;
    for (int j = 0; j < NY; ++j) printf("%3d %12.5e %.9e\n", j + 1, y[j], strip[j] / width);

    cw_accumulator_destroy(acc);
    cw_solver_destroy(solver);
    return 0;
}
