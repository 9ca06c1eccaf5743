/* CONTACT's tractcurv example contact (examples/tractcurv.inp, the
 * Eurosprinter wheel of Polach 2005) through the public header, for the
 * friction tests of every door (C, Fortran's C side, CLI, campaign): the
 * semi-axes as CONTACT prints them (6.304 and 12.61 mm), N = 106.7 kN,
 * steel, V = 10 m/s, the parabolic bound carrying N exactly (CONTACT's
 * B=3), on CONTACT's 48 x 44 grid over 1.1 times the semi-axes. Its series
 * 4: CONTACT's L=4 with FKIN 0.1368, FEXP1 0.2232, SABSH1 990 mm/s (Polach's
 * mu0 = 0.36, A = 0.38, B = 0.7 s/m) and M=3 with k0 = 0.54, alpha_inf =
 * 0.02, beta = 0.62. tests/core/tractcurv_contact.hpp is the core's copy. */
#ifndef CREEPWORK_TRACTCURV_CASE_H
#define CREEPWORK_TRACTCURV_CASE_H

#include "creepwork/creepwork.h"

#define CW_TRACTCURV_N 106.7e3 /* [N] */
#define CW_TRACTCURV_V 10.0    /* [m/s] */

static inline cw_grid cw_tractcurv_grid(void)
{
    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_UNIFORM;
    g.nx = 48;
    g.ny = 44;
    g.box_scale = 1.1;
    return g;
}

/* The contact at creepage xi_x under cw_params_init's law (Coulomb's). */
static inline cw_params cw_tractcurv_params(double xi_x)
{
    cw_params p;
    cw_params_init(&p);
    p.a = 6.304e-3;
    p.b = 12.61e-3;
    p.normal_force = CW_TRACTCURV_N;
    p.exact_load = 1;
    p.V = CW_TRACTCURV_V;
    p.xi_x = xi_x;
    return p;
}

/* The exact model on the contact (CONTACT's exact theory): its own
 * discrete normal problem on the printed semi-axes, steel, creepages
 * (xi_x, xi_y) and spin phi [1/m]; the friction left to the caller. */
static inline cw_params cw_tractcurv_exact_params(double xi_x, double xi_y, double phi)
{
    cw_params p = cw_tractcurv_params(xi_x);
    p.model = CW_MODEL_EXACT;
    p.pressure = CW_PRESSURE_ELLIPTIC;
    p.exact_load = 0;
    p.G = 82e9;
    p.nu = 0.28;
    p.xi_y = xi_y;
    p.phi = phi;
    return p;
}

/* Series 4's law as CONTACT reads it, one to one (mu is mu_kin), at every
 * element's slip speed; global: at the contact's with Spiryagin's reduction. */
static inline void cw_tractcurv_series4(cw_params* p, int global)
{
    p->friction_law = CW_FRICTION_EXPONENTIAL;
    p->mu = 0.1368;
    p->mu_e1 = 0.2232;
    p->s_h1 = 0.990;
    if (global) {
        p->friction_speed = CW_FRICTION_SPEED_GLOBAL;
        p->k0 = 0.54;
        p->alpha_inf = 0.02;
        p->beta = 0.62;
    }
}

#endif
