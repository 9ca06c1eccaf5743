/* The C side of test_fortran_friction: CONTACT's tractcurv contact (series
 * 4's law, as tests/capi/test_capi_friction.c) solved through the C ABI,
 * so that the Fortran module's numbers can be compared bit for bit. */
#include "creepwork/creepwork.h"

/* Fx and mu_min of one solve on the 48 x 44 grid at creepage xi_x, the law
 * at every element (speed 0, forces mode) or at the contact's slip speed
 * with Spiryagin's reduction (speed 1, full mode); status < 0 on failure. */
int cw_test_friction_c(double xi_x, int speed, double out[2])
{
    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_UNIFORM;
    g.nx = 48;
    g.ny = 44;
    g.box_scale = 1.1;
    cw_solver* s = NULL;
    if (cw_solver_create(&g, &s, NULL, 0) != CW_OK) return -1;
    cw_params p;
    cw_params_init(&p);
    p.a = 6.304e-3;
    p.b = 12.61e-3;
    p.normal_force = 106.7e3;
    p.exact_load = 1;
    p.V = 10.0;
    p.xi_x = xi_x;
    p.friction_law = CW_FRICTION_EXPONENTIAL;
    p.mu = 0.1368;
    p.mu_e1 = 0.2232;
    p.s_h1 = 0.990;
    p.friction_speed = speed;
    if (speed == CW_FRICTION_SPEED_GLOBAL) {
        p.k0 = 0.54;
        p.alpha_inf = 0.02;
        p.beta = 0.62;
    }
    cw_result r;
    cw_result_init(&r);
    const int mode = speed == CW_FRICTION_SPEED_GLOBAL ? CW_SOLVE_FULL : CW_SOLVE_FORCES;
    const int status = cw_solver_solve(s, &p, mode, &r);
    cw_solver_destroy(s);
    out[0] = r.Fx;
    out[1] = r.mu_min;
    return status == CW_OK ? 0 : -status;
}
