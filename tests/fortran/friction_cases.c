/* The C side of test_fortran_friction: CONTACT's tractcurv contact
 * (tests/support/tractcurv_case.h, series 4's law) solved through the C ABI,
 * so that the Fortran module's numbers can be compared bit for bit. */
#include "tractcurv_case.h"

/* Fx and mu_min of one solve on the 48 x 44 grid at creepage xi_x, the law
 * at every element (speed 0, forces mode) or at the contact's slip speed
 * with Spiryagin's reduction (speed 1, full mode); status < 0 on failure. */
int cw_test_friction_c(double xi_x, int speed, double out[2])
{
    const cw_grid g = cw_tractcurv_grid();
    cw_solver* s = NULL;
    if (cw_solver_create(&g, &s, NULL, 0) != CW_OK) return -1;
    cw_params p = cw_tractcurv_params(xi_x);
    cw_tractcurv_series4(&p, speed == CW_FRICTION_SPEED_GLOBAL);
    cw_result r;
    cw_result_init(&r);
    const int mode = speed == CW_FRICTION_SPEED_GLOBAL ? CW_SOLVE_FULL : CW_SOLVE_FORCES;
    const int status = cw_solver_solve(s, &p, mode, &r);
    cw_solver_destroy(s);
    out[0] = r.Fx;
    out[1] = r.mu_min;
    return status == CW_OK ? 0 : -status;
}
