/* Contacts of any shape through the C ABI (CW_GRID_GAP): the gap grid and
 * the gap inputs, the result's normal force and patch count, the patches
 * (also into an older or newer cw_patch), wear on a gap solve, the
 * semi-Hertzian normal method's row fit, and every error naming its input.
 * References: the elliptic exact model on the same uniform grid (a
 * Hertzian gap), the approach found given back, sums of the patches,
 * today's cw_patch bytes, Hertz's pressure, and the gap of two lobes solved
 * as two separate contacts (each lobe alone on its own grid). */
#include "capi_fixtures.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A 24 x 24 uniform grid of box 1.2 a x 1.2 b and its cells as a gap grid. */
enum { n = 24 };
static const double a = 7.0e-3, b = 5.0e-3, box = 1.2;

static cw_params exact_params(void)
{
    cw_params p;
    cw_params_init(&p);
    p.model = CW_MODEL_EXACT;
    p.a = a;
    p.b = b;
    p.normal_force = 90e3;
    p.xi_x = 5e-4;
    p.xi_y = 2e-4;
    p.phi = 0.4;
    p.warm_start = 0;
    return p;
}

static cw_grid gap_grid(double x0, double y0, int nx, int ny)
{
    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_GAP;
    g.nx = nx;
    g.ny = ny;
    g.dx = 2 * box * a / n;
    g.dy = 2 * box * b / n;
    g.x0 = x0;
    g.y0 = y0;
    return g;
}

/* h = A x^2 + B y^2 (Hertz's A, B of the semi-axes a, b under N), shifted
 * by (xc, yc), plus offset. */
static void hertz_gap(const cw_grid* g, double xc, double yc, double offset, double* h)
{
    double hz[4], A = 0, B = 0;
    /* A, B from a, b: solve Hertz for unit curvatures and scale (a^2 ~ 1/A at
     * fixed ratio): iterate the two curvatures to the semi-axes. */
    A = 1.0 / (2 * 0.4);
    B = 1.0 / (2 * 0.3);
    for (int it = 0; it < 60; ++it) {
        cw_hertz_solve(A, B, 90e3, 82e9 / (1 - 0.28), hz, NULL, 0);
        A *= (hz[0] / a) * (hz[0] / a);
        B *= (hz[1] / b) * (hz[1] / b);
    }
    for (int j = 0; j < g->ny; ++j)
        for (int i = 0; i < g->nx; ++i) {
            const double x = g->x0 + i * g->dx - xc, y = g->y0 + j * g->dy - yc;
            h[i + g->nx * j] = A * x * x + B * y * y + offset;
        }
}

static void gap_equals_elliptic_model(void** state)
{
    (void)state;
    cw_grid u;
    cw_grid_init(&u);
    u.kind = CW_GRID_UNIFORM;
    u.nx = u.ny = n;
    u.box_scale = box;
    cw_solver *se = NULL, *sg = NULL;
    assert_int_equal(cw_solver_create(&u, &se, NULL, 0), CW_OK);
    const cw_grid g = gap_grid(-box * a + box * a / n, -box * b + box * b / n, n, n);
    assert_int_equal(cw_solver_create(&g, &sg, NULL, 0), CW_OK);
    double h[n * n];
    hertz_gap(&g, 0, 0, 0, h);
    cw_params p = exact_params();
    cw_result re, rg;
    cw_result_init(&re);
    cw_result_init(&rg);
    assert_int_equal(cw_solver_solve(se, &p, CW_SOLVE_FULL, &re), CW_OK);
    p.gap = h;
    p.gap_len = n * n;
    assert_int_equal(cw_solver_solve(sg, &p, CW_SOLVE_FULL, &rg), CW_OK);
    /* Hertz's A, B iterated to 1e-12 here, the solvers' tolerance 1e-8. */
    const double muN = 0.3 * 90e3;
    assert_close(rg.Fx, re.Fx, 0.0, 1e-7 * muN);
    assert_close(rg.Fy, re.Fy, 0.0, 1e-7 * muN);
    assert_close(rg.p_max, re.p_max, 1e-7, 0.0);
    assert_close(rg.approach, re.approach, 1e-7, 0.0);
    assert_int_equal(rg.n_contact, re.n_contact);
    assert_int_equal(rg.n_patches, 1);
    assert_int_equal(re.n_patches, 1);
    assert_close(rg.normal_force, 90e3, 1e-12, 0.0);
    assert_int_equal(rg.model, CW_MODEL_EXACT);

    /* The approach found, prescribed: the force back. */
    p.normal_load = CW_NORMAL_APPROACH;
    p.approach = rg.approach;
    cw_result ra;
    cw_result_init(&ra);
    assert_int_equal(cw_solver_solve(sg, &p, CW_SOLVE_FORCES, &ra), CW_OK);
    assert_close(ra.normal_force, 90e3, 1e-8, 0.0);
    /* The semi-Hertzian normal method: the same load, a close area. */
    p.normal_load = CW_NORMAL_FORCE;
    p.normal_method = CW_NORMAL_SEMI_HERTZ;
    assert_int_equal(cw_solver_solve(sg, &p, CW_SOLVE_FORCES, &ra), CW_OK);
    assert_close(ra.normal_force, 90e3, 1e-12, 0.0);
    assert_true(abs(ra.n_contact - rg.n_contact) <= rg.n_contact / 10);

    /* Wear of a gap solve: the strips are the grid's rows. */
    p.normal_method = CW_NORMAL_EXACT;
    assert_int_equal(cw_solver_solve(sg, &p, CW_SOLVE_FULL, NULL), CW_OK);
    cw_wear* w = NULL;
    assert_int_equal(cw_wear_create(sg, &w), CW_OK);
    cw_wear_params wp;
    cw_wear_params_init(&wp);
    cw_wear_result wr;
    cw_wear_result_init(&wr);
    assert_int_equal(cw_wear_compute(w, sg, &wp, &wr), CW_OK);
    assert_close(wr.work, rg.W_macro, 1e-12, 0.0);
    assert_true(wr.mass_per_distance > 0.0);
    double y[n], width[n], depth[n];
    assert_int_equal(cw_wear_get_strips(w, y, width, depth, NULL, n), CW_OK);
    for (int j = 0; j < n; ++j) {
        assert_close(y[j], g.y0 + j * g.dy, 1e-14, 1e-18);
        assert_close(width[j], g.dy, 1e-14, 0.0);
    }
    cw_wear_destroy(w);
    cw_solver_destroy(se);
    cw_solver_destroy(sg);
}

/* Two Hertzian lobes 12 mm apart on one gap, the second 2 um higher: two
 * patches, reported in the order of their first element (lower y first),
 * adding up to the totals. Each lobe alone is not the same contact (the
 * half-spaces couple them), so only sums and signs are checked here;
 * CONTACT's per-patch values are test_nonhertz_contact's. */
static void two_lobes_are_two_patches(void** state)
{
    (void)state;
    const cw_grid g = gap_grid(-10e-3, -12e-3, 40, 70);
    double* h = malloc(sizeof(double) * 40 * 70);
    double* h2 = malloc(sizeof(double) * 40 * 70);
    hertz_gap(&g, 0, -6e-3, 0, h);
    hertz_gap(&g, 1e-3, 6e-3, 2e-6, h2);
    for (int k = 0; k < 40 * 70; ++k) h[k] = h[k] < h2[k] ? h[k] : h2[k];
    cw_solver* s = NULL;
    assert_int_equal(cw_solver_create(&g, &s, NULL, 0), CW_OK);
    cw_params p = exact_params();
    p.gap = h;
    p.gap_len = 40 * 70;
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
    assert_int_equal(r.n_patches, 2);
    size_t count = 99;
    assert_int_equal(cw_solver_get_patches(s, NULL, 0, &count), CW_OK);
    assert_int_equal(count, 2);
    cw_patch one[1];
    cw_patch_init(&one[0]);
    count = 0;
    assert_int_equal(cw_solver_get_patches(s, one, 1, &count), CW_ERR_BUFFER_TOO_SMALL);
    assert_int_equal(count, 2);
    assert_int_equal(one[0].n_contact, 0); /* nothing written */
    cw_patch P[3];
    for (int k = 0; k < 3; ++k) cw_patch_init(&P[k]);
    assert_int_equal(cw_solver_get_patches(s, P, 3, &count), CW_OK);
    assert_int_equal(count, 2);
    assert_true(P[0].y_centroid < -3e-3 && P[1].y_centroid > 3e-3);
    assert_true(P[0].Fn > P[1].Fn); /* the higher lobe carries less */
    assert_close(P[0].Fn + P[1].Fn, 90e3, 1e-12, 0.0);
    assert_close(P[0].Fx + P[1].Fx, r.Fx, 0.0, 1e-9 * 27e3);
    assert_close(P[0].Fy + P[1].Fy, r.Fy, 0.0, 1e-9 * 27e3);
    assert_close(P[0].Mz + P[1].Mz, r.Mz, 0.0, 1e-12 * 27e3);
    assert_close(P[0].W_macro + P[1].W_macro, r.W_macro, 1e-12, 0.0);
    assert_int_equal(P[0].n_contact + P[1].n_contact, r.n_contact);
    assert_true(P[0].p_max == r.p_max || P[1].p_max == r.p_max);
    /* Each patch's Mz is its elements' (x py - y px) area about the grid's
     * origin: the lobes lie either side of y = 0. */
    double* mz = malloc(sizeof(double) * 40 * 70);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_MZ, mz, 40 * 70), CW_OK);
    double below = 0.0, above = 0.0;
    for (int k = 0; k < 40 * 70; ++k) {
        if (g.y0 + (k / 40) * g.dy < 0.0)
            below += mz[k];
        else
            above += mz[k];
    }
    assert_close(P[0].Mz, below, 1e-12, 1e-12);
    assert_close(P[1].Mz, above, 1e-12, 1e-12);
    free(mz);

    /* Patch k lands at k times the caller's struct_size: an older or a
     * newer cw_patch gets every patch. */
    cw_check_patch_strides(s, P, 2);

    /* Elements must all carry out[0]'s struct_size; nothing is written
     * otherwise. */
    cw_patch mixed[2];
    cw_patch_init(&mixed[0]);
    cw_patch_init(&mixed[1]);
    mixed[1].struct_size = offsetof(cw_patch, Fn);
    assert_int_equal(cw_solver_get_patches(s, mixed, 2, &count), CW_ERR_STRUCT_SIZE);
    assert_int_equal(mixed[0].n_contact, 0);
    free(h);
    free(h2);
    cw_solver_destroy(s);
}

/* FASTSIM on a Hertzian gap centred at (X, Y), away from the grid's origin,
 * with the exact normal problem, against FASTSIM on the uniform grid's
 * ellipse (parabolic pressure, Kalker's flexibilities of a, b) with the
 * creepages of the same rigid slip about the contact's centre (xi_x + phi Y,
 * xi_y - phi X on the gap grid): the forces, and Mz transferred to the
 * ellipse's centre, agree to the difference between the discrete exact
 * pressure and the parabolic law and between the patch ellipse and a, b
 * (measured 0.43 % of mu N and 0.98 % of mu N a; bounds 1.5 % and 2 %). */
static void fastsim_on_a_shifted_hertzian_gap(void** state)
{
    (void)state;
    cw_grid u;
    cw_grid_init(&u);
    u.kind = CW_GRID_UNIFORM;
    u.nx = u.ny = n;
    u.box_scale = box;
    const double X = 11 * (2 * box * a / n), Y = -7 * (2 * box * b / n);
    const cw_grid g = gap_grid(-box * a + box * a / n + X, -box * b + box * b / n + Y, n, n);
    cw_solver *se = NULL, *sg = NULL;
    assert_int_equal(cw_solver_create(&u, &se, NULL, 0), CW_OK);
    assert_int_equal(cw_solver_create(&g, &sg, NULL, 0), CW_OK);
    double h[n * n];
    hertz_gap(&g, X, Y, 0, h);
    cw_params p = exact_params();
    p.model = CW_MODEL_FASTSIM;
    p.xi_x = 1e-4;
    p.xi_y = -1.5e-4;
    p.phi = 0.15;
    cw_result re, rg;
    cw_result_init(&re);
    cw_result_init(&rg);
    assert_int_equal(cw_solver_solve(se, &p, CW_SOLVE_FULL, &re), CW_OK);
    p.gap = h;
    p.gap_len = n * n;
    p.xi_x += p.phi * Y;
    p.xi_y -= p.phi * X;
    assert_int_equal(cw_solver_solve(sg, &p, CW_SOLVE_FULL, &rg), CW_OK);
    const double muN = 0.3 * 90e3;
    print_message("shifted Hertzian gap, FASTSIM: Fx %.3g, Fy %.3g mu N; dFx %.2g, dFy %.2g mu N, "
                  "dMz %.2g mu N a (slip %d / %d elements)\n",
                  re.Fx / muN, re.Fy / muN, (rg.Fx - re.Fx) / muN, (rg.Fy - re.Fy) / muN,
                  (rg.Mz - X * rg.Fy + Y * rg.Fx - re.Mz) / (muN * a), rg.n_slip, rg.n_contact);
    assert_int_equal(rg.model, CW_MODEL_FASTSIM);
    assert_int_equal(rg.n_patches, 1);
    assert_true(re.n_slip > 0 && re.n_adhesion > 0);
    assert_close(rg.Fx, re.Fx, 0.0, 0.015 * muN);
    assert_close(rg.Fy, re.Fy, 0.0, 0.015 * muN);
    assert_close(rg.Mz - X * rg.Fy + Y * rg.Fx, re.Mz, 0.0, 0.02 * muN * a);
    assert_close(rg.W_consistent, rg.W_macro, 1e-12, 0.0);
    /* The patch: its centroid at the contact's centre, its totals the result's. */
    cw_patch P;
    cw_patch_init(&P);
    size_t count = 0;
    assert_int_equal(cw_solver_get_patches(sg, &P, 1, &count), CW_OK);
    assert_int_equal((int)count, 1);
    assert_close(P.x_centroid, X, 0.0, 1e-12);
    assert_close(P.y_centroid, Y, 0.0, 1e-12);
    assert_close(P.Fx, rg.Fx, 0.0, 1e-12 * muN);
    assert_close(P.Mz, rg.Mz, 0.0, 1e-12 * muN * a);
    cw_solver_destroy(se);
    cw_solver_destroy(sg);
}

/* FASTSIM on the Hertzian gap under the exponential law (mu_kin 0.14,
 * mu_e1 0.19, s_h1 1.25 m/s, V = 10 m/s) through the C ABI: in full
 * sliding (xi_x 15 %, 1.5 m/s) |Fx| / N -> mu(xi V), the closed form of
 * sliding friction (each element slides at about xi V): measured 3.7e-4 of
 * mu(0) on this 24 x 24 grid (2.1e-4 on 48 x 48, test_nonhertz_fastsim_law:
 * the elements near each row's leading edge, where the traction builds up,
 * slide at other speeds, a share of the load of order 1/nx), 5e-4 asserted;
 * mu_min <= mu(xi V) <= mu_max; past the peak (0.8 %) the Jacobian's
 * dFx/dxi_x and dFx/dN against central differences of the solves (steps
 * 1e-5 xi and N, within 1e-4 of the entry), dFx/dxi_x positive: |Fx| falls. */
static void fastsim_law_on_a_hertzian_gap(void** state)
{
    (void)state;
    const cw_grid g = gap_grid(-box * a + box * a / n, -box * b + box * b / n, n, n);
    cw_solver* s = NULL;
    assert_int_equal(cw_solver_create(&g, &s, NULL, 0), CW_OK);
    double h[n * n];
    hertz_gap(&g, 0, 0, 0, h);
    cw_params p = exact_params();
    p.model = CW_MODEL_FASTSIM;
    p.gap = h;
    p.gap_len = n * n;
    p.friction_law = CW_FRICTION_EXPONENTIAL;
    p.mu = 0.14;
    p.mu_e1 = 0.19;
    p.s_h1 = 1.25;
    p.V = 10.0;
    p.xi_x = 0.15;
    p.xi_y = 0.0;
    p.phi = 0.0;
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
    const double mu = 0.14 + 0.19 * exp(-log(2.0) * 0.15 * 10.0 / 1.25);
    print_message("FASTSIM on a gap, full sliding: |Fx|/N %.6f, mu(xi V) %.6f\n",
                  -r.Fx / r.normal_force, mu);
    assert_int_equal(r.n_slip, r.n_contact);
    assert_close(-r.Fx / r.normal_force, mu, 0.0, 5e-4 * 0.33);
    assert_true(r.mu_min <= mu && mu <= r.mu_max && r.mu_max < 0.33);
    assert_close(r.mu_static, 0.33, 1e-15, 0.0);
    assert_close(r.W_consistent, r.W_macro, 1e-12, 0.0);

    p.xi_x = 0.008;
    p.xi_y = 3e-4;
    double J[CW_JACOBIAN_LEN];
    assert_int_equal(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, &r, J, CW_JACOBIAN_LEN), CW_OK);
    assert_true(r.n_adhesion > 0 && r.n_slip > 0);
    /* Columns xi_x and N of Fx (J[0], J[3]). */
    double F[2][2];
    for (int side = 0; side < 2; ++side) {
        cw_params q = p;
        q.xi_x += (side ? -1.0 : 1.0) * 1e-5 * p.xi_x;
        assert_int_equal(cw_solver_solve(s, &q, CW_SOLVE_FORCES, &r), CW_OK);
        F[0][side] = r.Fx;
        q = p;
        q.normal_force += (side ? -1.0 : 1.0) * 1e-5 * p.normal_force;
        assert_int_equal(cw_solver_solve(s, &q, CW_SOLVE_FORCES, &r), CW_OK);
        F[1][side] = r.Fx;
    }
    const double central = (F[0][0] - F[0][1]) / (2e-5 * p.xi_x);
    const double central_N = (F[1][0] - F[1][1]) / (2e-5 * p.normal_force);
    print_message("FASTSIM on a gap, 0.8 %% (%d of %d slip): dFx/dxi_x %.6g, central differences "
                  "%.6g; dFx/dN %.6g, %.6g\n", r.n_slip, r.n_contact, J[0], central, J[3], central_N);
    assert_true(J[0] > 0.0);
    assert_close(J[0], central, 1e-4, 0.0);
    assert_close(J[3], central_N, 1e-4, 0.0);
    cw_solver_destroy(s);
}

/* FASTSIM's adhesion limit per patch, computed by hand: with friction too
 * large for any slip and no spin, each segment of n elements carries the
 * tractions -k dx (xi_x / L1, xi_y / L2), k = 1..n, from its leading edge,
 * so a patch's force is -(xi_x / L1, xi_y / L2) dx^2 dy sum n (n + 1) / 2
 * over its segments, with L1, L2 of its patch ellipse (a = half its longest
 * row, b = its area / (pi a); cw_kalker_flexibilities). Two lobes of
 * different size: two patches, two flexibilities. Bound 1e-12 (rounding). */
static void fastsim_adhesion_limit_per_patch(void** state)
{
    (void)state;
    enum { NX = 40, NY = 70 };
    const cw_grid g = gap_grid(-10e-3, -12e-3, NX, NY);
    double* h = malloc(sizeof(double) * NX * NY);
    double* h2 = malloc(sizeof(double) * NX * NY);
    double* pz = malloc(sizeof(double) * NX * NY);
    hertz_gap(&g, 0, -6e-3, 0, h);
    hertz_gap(&g, 1e-3, 6e-3, 2e-6, h2);
    for (int k = 0; k < NX * NY; ++k) h[k] = h[k] < h2[k] ? h[k] : h2[k];
    cw_solver* s = NULL;
    assert_int_equal(cw_solver_create(&g, &s, NULL, 0), CW_OK);
    cw_params p = exact_params();
    p.model = CW_MODEL_FASTSIM;
    p.normal_method = CW_NORMAL_SEMI_HERTZ;
    p.gap = h;
    p.gap_len = NX * NY;
    p.mu = 100.0;
    p.xi_x = 1e-5;
    p.xi_y = -2e-5;
    p.phi = 0.0;
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
    assert_int_equal(r.n_patches, 2);
    assert_int_equal(r.n_slip, 0);
    cw_patch P[2];
    cw_patch_init(&P[0]);
    cw_patch_init(&P[1]);
    size_t count = 0;
    assert_int_equal(cw_solver_get_patches(s, P, 2, &count), CW_OK);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PZ, pz, NX * NY), CW_OK);
    /* The lobes lie apart across y = 0: patch 0 below, patch 1 above. */
    double L1[2] = {0, 0};
    for (int q = 0; q < 2; ++q) {
        int elements = 0, longest = 0;
        double sum = 0.0;
        for (int j = 0; j < NY; ++j) {
            if ((g.y0 + j * g.dy < 0.0) != (q == 0)) continue;
            int run = 0;
            for (int i = 0; i <= NX; ++i) {
                if (i < NX && pz[i + NX * j] > 0.0) {
                    ++run;
                    ++elements;
                } else if (run > 0) {
                    longest = run > longest ? run : longest;
                    sum += 0.5 * run * (run + 1.0);
                    run = 0;
                }
            }
        }
        assert_int_equal(elements, P[q].n_contact);
        const double pa = 0.5 * longest * g.dx, pb = elements * g.dx * g.dy / (3.14159265358979323846 * pa);
        double L[3];
        assert_int_equal(cw_kalker_flexibilities(pa, pb, p.G, p.nu, L, NULL, 0), CW_OK);
        const double Fx = -p.xi_x / L[0] * g.dx * g.dx * g.dy * sum;
        const double Fy = -p.xi_y / L[1] * g.dx * g.dx * g.dy * sum;
        assert_close(P[q].Fx, Fx, 1e-12, 0.0);
        assert_close(P[q].Fy, Fy, 1e-12, 0.0);
        L1[q] = L[0];
    }
    /* The lobes differ in size, so do their flexibilities (one L1 for both
     * would miss one patch's forces by more than the bound). */
    assert_true(fabs(L1[0] / L1[1] - 1.0) > 0.01);
    /* The handle solved the exact normal problem in between: the same
     * semi-Hertzian solve again gives the first one's bits (a solve does not
     * depend on the handle's last). */
    p.normal_method = CW_NORMAL_EXACT;
    cw_result r_exact;
    cw_result_init(&r_exact);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r_exact), CW_OK);
    assert_true(r_exact.n_contact != r.n_contact); /* a different pressure */
    p.normal_method = CW_NORMAL_SEMI_HERTZ;
    cw_result again;
    cw_result_init(&again);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &again), CW_OK);
    assert_true(memcmp(&again.Fx, &r.Fx, sizeof r.Fx) == 0);
    assert_true(memcmp(&again.Fy, &r.Fy, sizeof r.Fy) == 0);
    assert_true(memcmp(&again.Mz, &r.Mz, sizeof r.Mz) == 0);
    assert_true(memcmp(&again.p_max, &r.p_max, sizeof r.p_max) == 0);
    assert_int_equal(again.n_contact, r.n_contact);
    double* pz2 = malloc(sizeof(double) * NX * NY);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PZ, pz2, NX * NY), CW_OK);
    assert_true(memcmp(pz2, pz, sizeof(double) * NX * NY) == 0);
    free(pz2);
    cw_solver_destroy(s);
    free(h);
    free(h2);
    free(pz);
}

/* The semi-Hertzian row fit widens pair by pair only while both elements of
 * the next pair penetrate by more than 30 % of the row's locus, the higher
 * one deciding (doc/theory/non-hertzian.md). Hertz's paraboloid with every
 * element from x = -1.07 a on raised by 1 mm: the band lies outside the
 * contact but within the fit's reach from the other side (the rigid
 * overlap reaches 30 % of the depth at |x| = 1.2 a on the middle row), so a
 * fit that let the lower element of a pair decide would take in the band.
 * With the approach of Hertz's N prescribed, every element's pressure is
 * Hertz's, p^2 = p0^2 (1 - x^2/a^2 - y^2/b^2) (cw_hertz_solve; Johnson
 * 1985, eqs. 4.38-4.39), to the shape table's 1e-8, and the normal force
 * is their sum. */
static void semi_hertz_fit_stops_at_a_raised_band(void** state)
{
    (void)state;
    enum { M = 17, MID = M / 2 };
    const double A = 1.0 / (2 * 0.46), B = 1.0 / (2 * 0.3), N = 80e3, E = 82e9 / (1 - 0.28);
    double hz[4];
    assert_int_equal(cw_hertz_solve(A, B, N, E, hz, NULL, 0), CW_OK);
    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_GAP;
    g.nx = g.ny = M;
    g.dx = 2.6 * hz[0] / M;
    g.dy = 2.6 * hz[1] / M;
    g.x0 = -MID * g.dx;
    g.y0 = -MID * g.dy;
    double h[M * M], pz[M * M], area[M * M];
    for (int j = 0; j < M; ++j)
        for (int i = 0; i < M; ++i) {
            const double x = g.x0 + i * g.dx, y = g.y0 + j * g.dy;
            h[i + M * j] = A * x * x + B * y * y + (x <= -1.07 * hz[0] ? 1e-3 : 0.0);
        }
    cw_solver* s = NULL;
    assert_int_equal(cw_solver_create(&g, &s, NULL, 0), CW_OK);
    cw_params p;
    cw_params_init(&p);
    p.model = CW_MODEL_FASTSIM;
    p.normal_method = CW_NORMAL_SEMI_HERTZ;
    p.normal_load = CW_NORMAL_APPROACH;
    p.approach = hz[3];
    p.xi_x = 2e-4;
    p.gap = h;
    p.gap_len = M * M;
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PZ, pz, M * M), CW_OK);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_AREA, area, M * M), CW_OK);
    const double p0 = hz[2];
    double worst = 0.0, force = 0.0;
    for (int j = 0; j < M; ++j)
        for (int i = 0; i < M; ++i) {
            const double x = g.x0 + i * g.dx, y = g.y0 + j * g.dy;
            const double q = 1.0 - x * x / (hz[0] * hz[0]) - y * y / (hz[1] * hz[1]);
            const double pk = pz[i + M * j];
            worst = fmax(worst, fabs(pk * pk - (q > 0.0 ? p0 * p0 * q : 0.0)));
            force += pk * area[i + M * j];
        }
    print_message("p^2 within %.2g p0^2 of Hertz's\n", worst / (p0 * p0));
    assert_true(worst <= 1e-7 * p0 * p0);
    assert_close(r.normal_force, force, 1e-12, 0.0);
    assert_close(r.p_max, p0, 1e-7, 0.0); /* the middle element, x = y = 0 */
    cw_solver_destroy(s);
}

static void errors_name_the_input(void** state)
{
    (void)state;
    char message[256];
    /* Grids. */
    cw_grid g = gap_grid(0, 0, 10, 10);
    cw_solver* s = NULL;
    g.dx = -1.0;
    assert_int_equal(cw_solver_create(&g, &s, message, sizeof message), CW_ERR_INVALID_INPUT);
    assert_names(message, "dx");
    g = gap_grid(0, 0, 2, 10);
    assert_int_equal(cw_solver_create(&g, &s, message, sizeof message), CW_ERR_GRID_OUT_OF_RANGE);
    assert_names(message, "nx");
    g = gap_grid(0, 0, 10, CW_MAX_EXACT_CELLS + 1);
    assert_int_equal(cw_solver_create(&g, &s, message, sizeof message), CW_ERR_GRID_OUT_OF_RANGE);
    assert_names(message, "ny");
    g = gap_grid(strtod("inf", NULL), 0, 10, 10);
    assert_int_equal(cw_solver_create(&g, &s, message, sizeof message), CW_ERR_INVALID_INPUT);
    assert_names(message, "x0");
    assert_null(s);

    /* Inputs of a solve. */
    g = gap_grid(-3e-3, -3e-3, 30, 30);
    assert_int_equal(cw_solver_create(&g, &s, NULL, 0), CW_OK);
    double h[900];
    hertz_gap(&g, 0, 0, 0, h);
    const cw_params ok = exact_params();
    struct {
        int field;
        int status;
        const char* names;
    } bad[] = {{0, CW_ERR_INVALID_INPUT, "gap is NULL"}, {1, CW_ERR_INVALID_INPUT, "gap_len"},
               {2, CW_ERR_INVALID_INPUT, "gap[5]"},      {3, CW_ERR_UNKNOWN_OPTION, "normal_load"},
               {4, CW_ERR_UNKNOWN_OPTION, "normal_method"}, {5, CW_ERR_INVALID_INPUT, "model = calibrated"},
               {6, CW_ERR_INVALID_INPUT, "approach"},    {7, CW_ERR_INVALID_INPUT, "G"}};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        cw_params p = ok;
        double hb[900];
        memcpy(hb, h, sizeof h);
        p.gap = hb;
        p.gap_len = 900;
        switch (bad[k].field) {
        case 0: p.gap = NULL; break;
        case 1: p.gap_len = 899; break;
        case 2: hb[5] = strtod("nan", NULL); break;
        case 3: p.normal_load = 7; break;
        case 4: p.normal_method = -1; break;
        case 5: p.model = CW_MODEL_CALIBRATED; break;
        case 6: p.normal_load = CW_NORMAL_APPROACH, p.approach = strtod("inf", NULL); break;
        case 7: p.G = 0.0; break;
        }
        assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), bad[k].status);
        assert_names(cw_solver_last_error(s), bad[k].names);
        size_t count;
        assert_int_equal(cw_solver_get_patches(s, NULL, 0, &count), CW_ERR_NO_SOLUTION);
    }
    cw_params p = ok;
    p.gap = h;
    p.gap_len = 900;
    double J[CW_JACOBIAN_LEN];
    p.normal_force = 0.0; /* no derivative by N at N = 0 */
    assert_int_equal(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, NULL, J, CW_JACOBIAN_LEN),
                     CW_ERR_INVALID_INPUT);
    assert_names(cw_solver_last_error(s), "normal_force");
    p = ok;
    p.gap = h;
    p.gap_len = 900;
    assert_int_equal(cw_solver_prepare(s, CW_MODEL_CALIBRATED), CW_ERR_INVALID_INPUT);
    assert_int_equal(cw_solver_prepare(s, CW_MODEL_FASTSIM), CW_OK);
    assert_int_equal(cw_solver_prepare(s, CW_MODEL_EXACT), CW_OK);
    assert_int_equal(cw_solver_get_patches(s, NULL, 0, NULL), CW_ERR_NULL_POINTER);
    /* A params struct of 1.1 (before the gap fields): no gap, an error. */
    p.struct_size = offsetof(cw_params, gap);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_ERR_INVALID_INPUT);
    assert_names(cw_solver_last_error(s), "gap is NULL");
    cw_solver_destroy(s);

    /* The gap inputs off a gap grid. */
    cw_grid u;
    cw_grid_init(&u);
    u.kind = CW_GRID_UNIFORM;
    assert_int_equal(cw_solver_create(&u, &s, NULL, 0), CW_OK);
    p = ok;
    p.gap = h;
    p.gap_len = 900;
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_ERR_INVALID_INPUT);
    assert_names(cw_solver_last_error(s), "not a gap grid");
    p = ok;
    p.normal_method = CW_NORMAL_SEMI_HERTZ;
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_ERR_INVALID_INPUT);
    assert_names(cw_solver_last_error(s), "normal_method");
    /* The elliptic contact is one patch. */
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_solve(s, &ok, CW_SOLVE_FORCES, &r), CW_OK);
    cw_patch P;
    cw_patch_init(&P);
    size_t count = 0;
    assert_int_equal(cw_solver_get_patches(s, &P, 1, &count), CW_OK);
    assert_int_equal(count, 1);
    assert_true(P.Fx == r.Fx && P.Mz == r.Mz && P.Fn == ok.normal_force && P.p_max == r.p_max);
    cw_solver_destroy(s);
    assert_int_equal(cw_patch_init(NULL), CW_ERR_NULL_POINTER);
}

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(gap_equals_elliptic_model),
        cmocka_unit_test(two_lobes_are_two_patches),
        cmocka_unit_test(fastsim_on_a_shifted_hertzian_gap),
        cmocka_unit_test(fastsim_adhesion_limit_per_patch),
        cmocka_unit_test(fastsim_law_on_a_hertzian_gap),
        cmocka_unit_test(semi_hertz_fit_stops_at_a_raised_band),
        cmocka_unit_test(errors_name_the_input),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : NULL);
}
