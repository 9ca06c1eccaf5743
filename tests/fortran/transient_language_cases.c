/* The C side of the transient cross-language test: CONTACT's catt_to_cart
 * (examples/catt_to_cart.inp in SI, as tests/support/capi_fixtures.h: a
 * sphere h = 2.963 (x^2 + y^2) [m] on 34 x 33 cells of 0.25 mm from -4 mm,
 * N = 0.4705 N, G = 1e6 Pa, nu = 0.28, mu = 0.4013) through the C ABI: the
 * Cattaneo shift to Fx = -0.657 mu N and 14 rolling steps of 0.25 mm at that
 * Fx, each committed; then, after a rewound trial at xi_x = 1e-3, a trial at
 * Fx = -0.5 mu N. Each committed step's wear is added (the USFD law's
 * defaults). Then the shift and two steps in world-fixed coordinates on a
 * second handle. Writes the results (%.17g, which round-trips every double)
 * to the file named by argv[1]; test_fortran_transient steps the same
 * contact through module creepwork and requires the same bits. Records:
 *   S dq Fx  xi_x xi_y phi Fx Fy Mz W_step n_contact n_adhesion n_slip iterations
 *     W_slip step_mass               (step_mass 0 for the uncommitted trial)
 *   F field count v1 .. vcount      a field of the last step (px, sx, work)
 *   Z count s1 .. scount            its element states
 *   J j1 .. j9                      its Jacobian (row-major, as the C API)
 *   M mass count m1 .. mcount       the accumulated wear and its map
 *   X dq Fx xi_x Fx W_step n_slip   a world-fixed step (committed)
 */
#include <stdio.h>
#include <stdlib.h>

#include "creepwork/creepwork.h"

enum { NX = 34, NY = 33, N_ROLLING = 14 };

static void require_ok(int status, const char* what)
{
    if (status != CW_OK) {
        fprintf(stderr, "%s failed: %s\n", what, cw_status_string(status));
        exit(1);
    }
}

static void step(FILE* f, cw_transient* t, double dq, double fx, int commit)
{
    cw_wear_params law;
    cw_wear_params_init(&law);
    double mass = 0.0;
    cw_transient_input s;
    cw_transient_input_init(&s);
    s.dq = dq;
    s.prescribe = CW_PRESCRIBE_FX;
    s.Fx = fx;
    cw_transient_result r;
    cw_transient_result_init(&r);
    require_ok(cw_transient_step(t, &s, &r), "cw_transient_step");
    if (commit) {
        require_ok(cw_transient_commit(t), "cw_transient_commit");
        require_ok(cw_transient_add_wear(t, &law, &mass), "cw_transient_add_wear");
    }
    fprintf(f, "S %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %d %d %d %d %.17g %.17g\n",
            dq, fx, r.xi_x, r.xi_y, r.phi, r.Fx, r.Fy, r.Mz, r.W_step, r.n_contact, r.n_adhesion,
            r.n_slip, r.iterations, r.W_slip, mass);
}

int main(int argc, char** argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: transient_language_cases OUTPUT\n");
        return 2;
    }
    FILE* f = fopen(argv[1], "w");
    if (!f) return 1;
    static double h[NX * NY];
    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_GAP;
    g.nx = NX;
    g.ny = NY;
    g.dx = g.dy = 0.25e-3;
    g.x0 = g.y0 = -4.0e-3;
    for (int j = 0; j < NY; ++j)
        for (int i = 0; i < NX; ++i) {
            const double x = g.x0 + i * g.dx, y = g.y0 + j * g.dy;
            h[i + NX * j] = 2.963 * (x * x + y * y);
        }
    cw_params p;
    cw_params_init(&p);
    p.model = CW_MODEL_EXACT;
    p.normal_force = 0.4705;
    p.G = 1e6;
    p.nu = 0.28;
    p.mu = 0.4013;
    p.gap = h;
    p.gap_len = (size_t)NX * NY;
    cw_transient* t = NULL;
    char message[256] = "";
    if (cw_transient_create(&g, &p, &t, message, sizeof message) != CW_OK) {
        fprintf(stderr, "cw_transient_create: %s\n", message);
        return 1;
    }
    const double mu_n = 0.4013 * 0.4705;
    step(f, t, 0.0, -0.657 * mu_n, 1);
    for (int k = 0; k < N_ROLLING; ++k) step(f, t, 0.25e-3, -0.657 * mu_n, 1);
    /* A trial at a creepage, rewound, then the trial the fields are of. */
    cw_transient_input s;
    cw_transient_input_init(&s);
    s.dq = 0.25e-3;
    s.xi_x = 1e-3;
    require_ok(cw_transient_step(t, &s, NULL), "cw_transient_step (creepage)");
    require_ok(cw_transient_rewind(t), "cw_transient_rewind");
    step(f, t, 0.25e-3, -0.5 * mu_n, 0);
    static double v[NX * NY];
    const int fields[] = {CW_FIELD_PX, CW_FIELD_SX, CW_FIELD_WORK_CONSISTENT};
    for (int k = 0; k < 3; ++k) {
        require_ok(cw_transient_get_field(t, fields[k], v, NX * NY), "cw_transient_get_field");
        fprintf(f, "F %d %d", fields[k], NX * NY);
        for (int e = 0; e < NX * NY; ++e) fprintf(f, " %.17g", v[e]);
        fprintf(f, "\n");
    }
    static int st[NX * NY];
    require_ok(cw_transient_get_state(t, st, NX * NY), "cw_transient_get_state");
    fprintf(f, "Z %d", NX * NY);
    for (int e = 0; e < NX * NY; ++e) fprintf(f, " %d", st[e]);
    fprintf(f, "\n");
    double J[CW_TRANSIENT_JACOBIAN_LEN];
    require_ok(cw_transient_jacobian(t, J, CW_TRANSIENT_JACOBIAN_LEN), "cw_transient_jacobian");
    fprintf(f, "J");
    for (int e = 0; e < CW_TRANSIENT_JACOBIAN_LEN; ++e) fprintf(f, " %.17g", J[e]);
    fprintf(f, "\n");
    double mass = 0.0;
    require_ok(cw_transient_get_wear(t, v, NX * NY, &mass), "cw_transient_get_wear");
    fprintf(f, "M %.17g %d", mass, NX * NY);
    for (int e = 0; e < NX * NY; ++e) fprintf(f, " %.17g", v[e]);
    fprintf(f, "\n");
    cw_transient_destroy(t);
    /* World-fixed: the shift and two steps (the contact stays on the grid). */
    require_ok(cw_transient_create(&g, &p, &t, message, sizeof message), "cw_transient_create");
    require_ok(cw_transient_set_coordinates(t, CW_COORDINATES_WORLD),
               "cw_transient_set_coordinates");
    for (int k = 0; k < 3; ++k) {
        cw_transient_input w;
        cw_transient_input_init(&w);
        w.dq = k == 0 ? 0.0 : 0.25e-3;
        w.prescribe = CW_PRESCRIBE_FX;
        w.Fx = -0.657 * mu_n;
        cw_transient_result r;
        cw_transient_result_init(&r);
        require_ok(cw_transient_step(t, &w, &r), "cw_transient_step (world)");
        require_ok(cw_transient_commit(t), "cw_transient_commit (world)");
        fprintf(f, "X %.17g %.17g %.17g %.17g %.17g %d\n", w.dq, w.Fx, r.xi_x, r.Fx, r.W_step,
                r.n_slip);
    }
    cw_transient_destroy(t);
    return fclose(f) == 0 ? 0 : 1;
}
