/* The legacy layer's per-thread state on plain pthreads (no OpenMP), as a
 * C host calls the F77 routines (gfortran's convention: every argument by
 * reference, a CHARACTER's length appended as size_t). Checks:
 *   - CWLAST: four threads fail CWKALK at the same time with their own
 *     nu (out of [0, 0.5], Kalker's table) and, after a barrier that lets
 *     every other thread fail too, each reads its own nu; after a success
 *     its own message is blank;
 *   - CWFORC equals the C ABI bit for bit: FX, FY, FMZ, WMAC, ADH against
 *     cw_solver_solve(CW_SOLVE_FORCES) on a reused C solver of the same
 *     grid (the same solve, so identical bits are the expected value), in
 *     every thread, on six grid shapes in turn, LOAD 0 and 1; and against
 *     CWSOLM's FX, FY, FMZ, WMAC (a full solve has the same totals);
 *   - the cache: at most 4 solvers per thread with six shapes in use,
 *     CWFREE empties it; threads that end without CWFREE free theirs at
 *     exit (LeakSanitizer reports it otherwise in the sanitizer build);
 *   - LOAD = 1 (cw_params.exact_load) in full sliding: |FX| = FMU FN to
 *     1e-12 (Coulomb: every element carries mu pz, and the discrete load
 *     is FN); LOAD = 0 misses it by more than 1e-4 (the analytic scale's
 *     midpoint sum differs from FN by 0.15 % on Kalker's 20 x 20 strips).
 */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

#include "creepwork/creepwork.h"

/* The legacy routines (creepwork_legacy.inc), as gfortran names them. */
void cwkalk_(const double* aob, const double* pnu, double* c11, double* c22, double* c23,
             double* c33, int* ierr);
void cwforc_(const double* a, const double* b, const double* fn, const double* fmu,
             const double* g, const double* pnu, const double* xi, const double* eta,
             const double* phi, const int* nx, const int* ny, const int* load, double* fx,
             double* fy, double* fmz, double* wmac, double* adh, int* ierr);
void cwsolm_(const double* a, const double* b, const double* fn, const double* fmu,
             const double* g, const double* pnu, const double* xi, const double* eta,
             const double* phi, const int* nx, const int* ny, double* fx, double* fy,
             double* fmz, double* wmac, double* wmic, double* ck, double* px, double* py,
             double* sx, double* sy, double* zmap, double* wpap, double* wcon, int* istate,
             int* ierr);
void cwfree_(void);
void cwlast_(char* msg, size_t len);
/* Internal to libcreepwork_fortran (legacy_thread_state.cpp; this test links
 * the static library to reach it): solvers the calling thread holds. */
int cwl_cached_solvers(void);

enum { kThreads = 4, kShapes = 6, kRounds = 40, kCases = 3 };
static const int kShapeNx[kShapes] = {20, 8, 13, 20, 31, 5};
static const int kShapeNy[kShapes] = {20, 8, 7, 11, 12, 30};

typedef struct {
    double a, b, fn, fmu, g, pnu, xi, eta, phi;
} Contact;

/* Partial slip with spin, lateral and saturated full slip along x. */
static const Contact kCases_[kCases] = {
    {6e-3, 4.5e-3, 80e3, 0.3, 82e9, 0.28, 6e-4, -3e-4, 0.8},
    {7.17e-3, 5.42e-3, 100e3, 0.35, 82e9, 0.25, -2e-4, 1.2e-3, -1.5},
    {7.17e-3, 5.42e-3, 100e3, 0.3, 82e9, 0.28, 0.3, 0.0, 0.0},
};

/* The C ABI's totals: Fx, Fy, Mz, W_macro, adhesion fraction. */
static double reference[kShapes][kCases][2][5];
static pthread_barrier_t barrier;
static int failures[kThreads];

static int same_bits(double x, double y) { return memcmp(&x, &y, sizeof x) == 0; }

static void c_reference(void)
{
    for (int s = 0; s < kShapes; ++s) {
        cw_grid g;
        cw_grid_init(&g);
        g.nx = kShapeNx[s];
        g.ny = kShapeNy[s];
        cw_solver* solver = NULL;
        if (cw_solver_create(&g, &solver, NULL, 0) != CW_OK) {
            fprintf(stderr, "cw_solver_create failed\n");
            failures[0]++;
            return;
        }
        for (int c = 0; c < kCases; ++c) {
            for (int load = 0; load < 2; ++load) {
                const Contact* k = &kCases_[c];
                cw_params p;
                cw_params_init(&p);
                p.a = k->a;
                p.b = k->b;
                p.normal_force = k->fn;
                p.mu = k->fmu;
                p.G = k->g;
                p.nu = k->pnu;
                p.xi_x = k->xi;
                p.xi_y = k->eta;
                p.phi = k->phi;
                p.exact_load = load;
                cw_result r;
                cw_result_init(&r);
                if (cw_solver_solve(solver, &p, CW_SOLVE_FORCES, &r) != CW_OK) failures[0]++;
                const double v[5] = {r.Fx, r.Fy, r.Mz, r.W_macro, r.adhesion_fraction};
                memcpy(reference[s][c][load], v, sizeof v);
            }
        }
        cw_solver_destroy(solver);
    }
}

static int cwforc_matches(int s, int c, int load)
{
    const Contact* k = &kCases_[c];
    double out[5] = {0};
    int ierr = -1;
    cwforc_(&k->a, &k->b, &k->fn, &k->fmu, &k->g, &k->pnu, &k->xi, &k->eta, &k->phi,
            &kShapeNx[s], &kShapeNy[s], &load, &out[0], &out[1], &out[2], &out[3], &out[4],
            &ierr);
    if (ierr != 0) return 0;
    for (int m = 0; m < 5; ++m)
        if (!same_bits(out[m], reference[s][c][load][m])) return 0;
    return 1;
}

static void* worker(void* arg)
{
    const int t = (int)(size_t)arg;
    /* Thread t's own invalid Poisson's ratio and how CWLAST prints it. */
    const double bad_nu[kThreads] = {0.75, 1.5, 2.5, 3.5};
    const char* printed[kThreads] = {"nu = 0.75", "nu = 1.5", "nu = 2.5", "nu = 3.5"};
    const double aob = 1.0, good_nu = 0.25;
    char msg[200];
    for (int round = 0; round < kRounds; ++round) {
        double c11, c22, c23, c33;
        int ierr = 0;
        cwkalk_(&aob, &bad_nu[t], &c11, &c22, &c23, &c33, &ierr);
        if (ierr != CW_ERR_INVALID_INPUT) failures[t]++;
        pthread_barrier_wait(&barrier); /* every thread has failed now */
        cwlast_(msg, sizeof msg);
        msg[sizeof msg - 1] = '\0';
        if (!strstr(msg, printed[t])) {
            if (failures[t]++ < 3) fprintf(stderr, "thread %d read: %.80s\n", t, msg);
        }
        for (int u = 0; u < kThreads; ++u)
            if (u != t && strstr(msg, printed[u])) failures[t]++;
        pthread_barrier_wait(&barrier);
        cwkalk_(&aob, &good_nu, &c11, &c22, &c23, &c33, &ierr);
        cwlast_(msg, sizeof msg);
        for (size_t i = 0; i < sizeof msg; ++i)
            if (msg[i] != ' ') {
                failures[t]++;
                break;
            }

        /* Six shapes in turn, starting where this thread's index says. */
        const int s = (t + round) % kShapes;
        for (int c = 0; c < kCases; ++c)
            for (int load = 0; load < 2; ++load)
                if (!cwforc_matches(s, c, load)) {
                    if (failures[t]++ < 3)
                        fprintf(stderr, "thread %d: CWFORC != C ABI (shape %d, case %d, load %d)\n",
                                t, s, c, load);
                }
        const int held = cwl_cached_solvers();
        const int expected = round + 1 < 4 ? round + 1 : 4;
        if (held != expected) {
            if (failures[t]++ < 3)
                fprintf(stderr, "thread %d round %d holds %d solvers, expected %d\n", t, round,
                        held, expected);
        }
    }
    /* Half the threads free explicitly, half leave it to the thread's end. */
    if (t % 2 == 0) {
        cwfree_();
        if (cwl_cached_solvers() != 0) failures[t]++;
    }
    return NULL;
}

/* CWSOLM (a full solve, fresh solver) has CWFORC's totals. */
static int cwsolm_matches(void)
{
    enum { nx = 20, ny = 20 };
    static double px[nx * ny], py[nx * ny], sx[nx * ny], sy[nx * ny], zmap[nx * ny],
        wpap[nx * ny], wcon[nx * ny];
    static int istate[nx * ny];
    const int mx = nx, my = ny;
    int ok = 1;
    for (int c = 0; c < kCases; ++c) {
        const Contact* k = &kCases_[c];
        double fx, fy, fmz, wmac, wmic, ck;
        int ierr = -1;
        cwsolm_(&k->a, &k->b, &k->fn, &k->fmu, &k->g, &k->pnu, &k->xi, &k->eta, &k->phi, &mx,
                &my, &fx, &fy, &fmz, &wmac, &wmic, &ck, px, py, sx, sy, zmap, wpap, wcon, istate,
                &ierr);
        const double* ref = reference[0][c][0]; /* shape 0 is 20 x 20 */
        ok = ok && ierr == 0 && same_bits(fx, ref[0]) && same_bits(fy, ref[1]) &&
             same_bits(fmz, ref[2]) && same_bits(wmac, ref[3]);
    }
    return ok;
}

int main(void)
{
    int bad = 0;
    c_reference();
    bad += failures[0];
    failures[0] = 0;

    /* exact_load through LOAD: Coulomb's mu N in full sliding (case 2). */
    const double muN = kCases_[2].fmu * kCases_[2].fn;
    const double* exact = reference[0][2][1];
    const double* analytic = reference[0][2][0];
    if (!(exact[4] == 0.0 && fabs(-exact[0] - muN) <= 1e-12 * muN)) {
        fprintf(stderr, "LOAD = 1 in full sliding: -FX = %.17g, mu N = %.17g\n", -exact[0], muN);
        bad++;
    }
    if (!(fabs(-analytic[0] / muN - 1.0) > 1e-4)) {
        fprintf(stderr, "LOAD = 0 gave -FX = %.17g, expected the analytic scale's\n", -analytic[0]);
        bad++;
    }
    for (int load = 0; load < 2; ++load)
        if (!cwforc_matches(0, 2, load)) bad++;
    if (!cwsolm_matches()) {
        fprintf(stderr, "CWSOLM's totals differ from CWFORC's\n");
        bad++;
    }
    cwfree_();

    pthread_t threads[kThreads];
    pthread_barrier_init(&barrier, NULL, kThreads);
    for (int t = 0; t < kThreads; ++t)
        pthread_create(&threads[t], NULL, worker, (void*)(size_t)t);
    for (int t = 0; t < kThreads; ++t) pthread_join(threads[t], NULL);
    pthread_barrier_destroy(&barrier);
    for (int t = 0; t < kThreads; ++t) bad += failures[t];

    if (bad) {
        printf("%d checks failed\n", bad);
        return 1;
    }
    printf("all checks passed: %d threads x %d rounds\n", kThreads, kRounds);
    return 0;
}
