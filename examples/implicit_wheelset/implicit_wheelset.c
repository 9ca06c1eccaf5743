/* A single-wheelset lateral model integrated with implicit Euler using the
 * creep-force Jacobian (doc/theory/jacobians.md), against an explicit reference
 * with a tiny step.
 *
 * One mass m (the wheelset) on a lateral spring k (primary suspension plus
 * gravitational stiffness, lumped), rolling at speed V: its lateral velocity
 * v is a lateral creepage xi_y = v / V at both wheels (no yaw in this toy),
 * which also carry a small longitudinal creepage (traction) so that Fy
 * saturates with the combined creepage:
 *   y' = v,   m v' = -k y + 2 Fy(xi_x, v / V)
 * The creep force acts like a damper of c = -2 dFy/dxi_y / V ~ 2e6 N s/m: a
 * fast mode m/c ~ 0.7 ms next to the slow motion k/c ~ 0.4 s -- stiff.
 *
 * Implicit Euler: y1 = y0 + h v1 and the residual
 *   R(v1) = m (v1 - v0) + h k (y0 + h v1) - 2 h Fy(xi_x, v1 / V) = 0
 * solved by Newton's method with R' = m + h^2 k - 2 h dFy/dxi_y / V, the
 * derivative from cw_solver_solve_jacobian. Reference: classical RK4 with
 * h = 2e-5 s. The program prints both trajectories' difference and the
 * number of contact solves, and fails (exit 1) if the implicit trajectory
 * is off by more than 1 % of the initial displacement. The argument
 * "calibrated" runs the same with CW_MODEL_CALIBRATED
 * (doc/theory/calibrated.md), whose Jacobian also follows its table's knobs. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <creepwork/creepwork.h>

static const double kMass = 1500.0;   /* [kg] wheelset */
static const double kSpring = 5e6;    /* [N/m] */
static const double kSpeed = 10.0;    /* [m/s] */
static const double kY0 = 8e-3;       /* [m] initial lateral displacement */
static const double kXiX = 5e-4;      /* longitudinal creepage (traction) */
static const double kEnd = 1.0;       /* [s] */

static cw_solver* g_solver;
static cw_params g_params;
static long g_solves;

static void fail(int status, const char* what)
{
    fprintf(stderr, "creepwork: %s: %s (%s)\n", what, cw_status_string(status),
            cw_solver_last_error(g_solver));
    exit(1);
}

/* Fy of one wheel and dFy/dxi_y at lateral velocity v. */
static double lateral_force(double v, double* dFy_dxi_y)
{
    cw_result r;
    cw_result_init(&r);
    g_params.xi_y = v / kSpeed;
    ++g_solves;
    if (dFy_dxi_y) {
        double J[CW_JACOBIAN_LEN];
        const int st =
            cw_solver_solve_jacobian(g_solver, &g_params, CW_SOLVE_FORCES, &r, J, CW_JACOBIAN_LEN);
        if (st != CW_OK) fail(st, "cw_solver_solve_jacobian");
        *dFy_dxi_y = J[4 * CW_JAC_FY + CW_JAC_XI_Y];
    } else {
        const int st = cw_solver_solve(g_solver, &g_params, CW_SOLVE_FORCES, &r);
        if (st != CW_OK) fail(st, "cw_solver_solve");
    }
    return r.Fy;
}

static double acceleration(double y, double v) { return (-kSpring * y + 2.0 * lateral_force(v, NULL)) / kMass; }

/* The reference: RK4 with step h, y sampled every `every` steps into out. */
static void rk4(double h, long steps, long every, double* out)
{
    double y = kY0, v = 0.0;
    out[0] = y;
    for (long n = 1; n <= steps; ++n) {
        const double k1y = v, k1v = acceleration(y, v);
        const double k2y = v + 0.5 * h * k1v, k2v = acceleration(y + 0.5 * h * k1y, v + 0.5 * h * k1v);
        const double k3y = v + 0.5 * h * k2v, k3v = acceleration(y + 0.5 * h * k2y, v + 0.5 * h * k2v);
        const double k4y = v + h * k3v, k4v = acceleration(y + h * k3y, v + h * k3v);
        y += h / 6.0 * (k1y + 2 * k2y + 2 * k3y + k4y);
        v += h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
        if (n % every == 0) out[n / every] = y;
    }
}

int main(int argc, char** argv)
{
    const int calibrated = argc > 1 && strcmp(argv[1], "calibrated") == 0;
    cw_grid grid;
    cw_grid_init(&grid); /* Kalker strips 20 x 20 */
    char message[256];
    int st = cw_solver_create(&grid, &g_solver, message, sizeof message);
    if (st != CW_OK) {
        fprintf(stderr, "creepwork: %s\n", message);
        return 1;
    }
    cw_params_init(&g_params); /* steel, a = b = 6 mm, N = 80 kN, mu = 0.3 */
    g_params.xi_x = kXiX;
    if (calibrated) g_params.model = CW_MODEL_CALIBRATED;

    /* Implicit Euler, h = 2 ms: 500 steps. */
    const double h = 2e-3;
    const long steps = (long)(kEnd / h + 0.5);
    double* implicit_y = malloc(sizeof(double) * (size_t)(steps + 1));
    double* reference_y = malloc(sizeof(double) * (size_t)(steps + 1));
    if (!implicit_y || !reference_y) return 1;
    double y = kY0, v = 0.0;
    int max_newton = 0;
    implicit_y[0] = y;
    for (long n = 1; n <= steps; ++n) {
        double v1 = v; /* Newton from the last velocity */
        int it = 0;
        for (;; ++it) {
            double dF = 0.0;
            const double F = lateral_force(v1, &dF);
            const double R = kMass * (v1 - v) + h * kSpring * (y + h * v1) - 2.0 * h * F;
            const double dR = kMass + h * h * kSpring - 2.0 * h * dF / kSpeed;
            const double dv = -R / dR;
            v1 += dv;
            if (fabs(dv) <= 1e-12 * (fabs(v1) + 1e-6) || it == 20) break;
        }
        if (it > max_newton) max_newton = it + 1;
        v = v1;
        y += h * v;
        implicit_y[n] = y;
    }
    const long implicit_solves = g_solves;

    /* Reference: RK4 with h = 2e-5 s (100 steps per implicit step). */
    g_solves = 0;
    rk4(h / 100.0, steps * 100, 100, reference_y);
    const long reference_solves = g_solves;

    double worst = 0.0;
    for (long n = 0; n <= steps; ++n) worst = fmax(worst, fabs(implicit_y[n] - reference_y[n]));
    printf("single wheelset, lateral, %s model: y(0) = %.1f mm, V = %.0f m/s, t = 0 .. %.1f s\n",
           calibrated ? "calibrated" : "FASTSIM", kY0 * 1e3, kSpeed, kEnd);
    printf("  y(0.1 s) = %.4f mm, y(0.5 s) = %.4f mm, y(1 s) = %.4f mm (reference)\n",
           reference_y[steps / 10] * 1e3, reference_y[steps / 2] * 1e3, reference_y[steps] * 1e3);
    printf("implicit Euler, h = %.0f ms: %ld steps, %ld contact solves (at most %d Newton "
           "iterations per step)\n",
           h * 1e3, steps, implicit_solves, max_newton);
    printf("RK4 reference, h = %.0f us: %ld steps, %ld contact solves\n", h / 100.0 * 1e6,
           steps * 100, reference_solves);
    printf("largest difference: %.4f mm = %.2f %% of y(0)\n", worst * 1e3, 100.0 * worst / kY0);
    free(implicit_y);
    free(reference_y);
    cw_solver_destroy(g_solver);
    /* Implicit Euler is first order: the error is h/(2 tau) of the slow mode
     * (tau = c/k ~ 0.4 s), about 0.3 %; 1 % is the bound. */
    if (!(worst <= 0.01 * kY0)) {
        printf("FAILED: the implicit trajectory differs by more than 1 %% of y(0)\n");
        return 1;
    }
    printf("same trajectory within 1 %% of y(0), %.0fx fewer contact solves\n",
           (double)reference_solves / (double)implicit_solves);
    return 0;
}
