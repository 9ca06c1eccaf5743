/* The tractcurv contact (tractcurv_case.h) as a contact of any shape: a gap
 * grid over the uniform grid's box holding Hertz's gap of its semi-axes, for
 * the exact model's tests on a gap grid (test_capi_exact_law,
 * test_capi_exact_layer, and with another uniform grid test_capi_mu_temperature). */
#ifndef CREEPWORK_TRACTCURV_GAP_H
#define CREEPWORK_TRACTCURV_GAP_H

#include <math.h>

#include "capi_fixtures.h"
#include "tractcurv_case.h"

/* Complete elliptic integrals K(k), E(k) by the arithmetic-geometric mean
 * (Abramowitz and Stegun 17.6), to rounding. */
static inline void cw_elliptic_KE(double k, double* K, double* E)
{
    double a = 1.0, b = sqrt(1.0 - k * k), sum = 0.5 * k * k, w = 0.5;
    for (int n = 0; n < 40 && fabs(a - b) > 1e-16 * a; ++n) {
        const double c = 0.5 * (a - b), an = 0.5 * (a + b);
        b = sqrt(a * b);
        a = an;
        w *= 2.0;
        sum += w * c * c;
    }
    *K = 3.14159265358979323846 / (2.0 * a);
    *E = *K * (1.0 - sum);
}

/* The gap grid over uniform grid u's box (u.nx x u.ny elements over
 * u.box_scale times the semi-axes, so the same element centres) holding
 * Hertz's gap A x^2 + B y^2 of the semi-axes a < b under N (Johnson eqs.
 * 4.38-4.39, as hertz_from_semi_axes): h receives u.nx * u.ny values. */
static inline cw_grid cw_hertz_gap_grid(const cw_grid* u, const cw_params* p, double* h)
{
    cw_grid g = cw_test_grid(CW_GRID_GAP, u->nx, u->ny, 1.0);
    g.dx = 2.0 * u->box_scale * p->a / u->nx;
    g.dy = 2.0 * u->box_scale * p->b / u->ny;
    g.x0 = -u->box_scale * p->a + 0.5 * g.dx;
    g.y0 = -u->box_scale * p->b + 0.5 * g.dy;
    const double small = p->a, big = p->b, k = sqrt(1.0 - (small / big) * (small / big));
    double K, E;
    cw_elliptic_KE(k, &K, &E);
    const double p0 = 3.0 * p->normal_force / (2.0 * 3.14159265358979323846 * p->a * p->b);
    const double c = p0 * small / (p->G / (1.0 - p->nu) * k * k * big * big);
    const double A = c * ((big / small) * (big / small) * E - K), B = c * (K - E);
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const double x = g.x0 + i * g.dx, y = g.y0 + j * g.dy;
            h[i + g.nx * j] = A * x * x + B * y * y;
        }
    return g;
}

/* The gap grid over the tractcurv uniform grid's box (48 x 44 over 1.1 a,
 * 1.1 b) holding Hertz's gap: h receives 48 * 44 values. */
static inline cw_grid cw_tractcurv_gap_grid(const cw_params* p, double* h)
{
    const cw_grid u = cw_tractcurv_grid();
    return cw_hertz_gap_grid(&u, p, h);
}

#endif
