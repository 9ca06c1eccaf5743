/* The legacy layer's cost against the C ABI, side by side in one run, as a
 * FORTRAN 77 vehicle loop sees it: per contact, on Kalker's strip grid
 * n x n (the partial-slip contact of creepwork_bench, and full sliding),
 *   C forces    cw_solver_solve(CW_SOLVE_FORCES) on a reused solver
 *   CWFORC      the legacy forces-only call (a solver kept per thread)
 *   C full      cw_solver_solve(CW_SOLVE_FULL) on a reused solver and the
 *               seven maps and the states CWSOLM returns
 *   CWSOLM      the legacy full call (a solver made and freed per call)
 * Each time is the thread's CPU time (so that time spent descheduled on a
 * shared machine does not count), the median of 15 samples (the four
 * runners take turns within a sample, so load changes hit them alike) of
 * about 2 ms of C forces-only solves each. Also checks that CWFORC's FX, FY,
 * FMZ equal the C forces-only solve's bit for bit. Not a test: prints a
 * table with its stamp (`build/bin/creepwork_bench_legacy [n [samples]]`:
 * only the n x n grid, fewer samples, e.g. under valgrind --tool=callgrind).
 */
#define _POSIX_C_SOURCE 200112L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <creepwork/creepwork.h>

/* The legacy routines (creepwork_legacy.inc), as gfortran names them. */
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

enum { SAMPLES = 15, RUNNERS = 4 };

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int by_value(const void* x, const void* y)
{
    const double a = *(const double*)x, b = *(const double*)y;
    return (a > b) - (a < b);
}

typedef struct {
    const char* name;
    double a, b, fn, fmu, g, pnu, xi, eta, phi;
} Contact;

typedef struct {
    int n;
    const Contact* k;
    cw_solver* solver;
    cw_params params;
    double *maps, *px, *py, *sx, *sy, *zmap, *wpap, *wcon;
    int* istate;
    int failures;
} Setup;

static void c_forces(Setup* s, long reps)
{
    cw_result r;
    cw_result_init(&r);
    for (long i = 0; i < reps; ++i) s->failures += cw_solver_solve(s->solver, &s->params,
                                                                    CW_SOLVE_FORCES, &r) != CW_OK;
}

static void legacy_forces(Setup* s, long reps)
{
    const Contact* k = s->k;
    const int load = 0;
    double fx, fy, fmz, wmac, adh;
    int ierr;
    for (long i = 0; i < reps; ++i) {
        cwforc_(&k->a, &k->b, &k->fn, &k->fmu, &k->g, &k->pnu, &k->xi, &k->eta, &k->phi, &s->n,
                &s->n, &load, &fx, &fy, &fmz, &wmac, &adh, &ierr);
        s->failures += ierr != 0;
    }
}

static void c_full(Setup* s, long reps)
{
    const size_t len = (size_t)s->n * (size_t)s->n;
    static const int fields[7] = {CW_FIELD_PX, CW_FIELD_PY, CW_FIELD_SX, CW_FIELD_SY,
                                  CW_FIELD_MZ, CW_FIELD_WORK_PAPER, CW_FIELD_WORK_CONSISTENT};
    cw_result r;
    cw_result_init(&r);
    for (long i = 0; i < reps; ++i) {
        s->failures += cw_solver_solve(s->solver, &s->params, CW_SOLVE_FULL, &r) != CW_OK;
        for (int f = 0; f < 7; ++f)
            s->failures += cw_solver_get_field(s->solver, fields[f], s->maps + f * len, len);
        s->failures += cw_solver_get_state(s->solver, s->istate, len);
    }
}

static void legacy_full(Setup* s, long reps)
{
    const Contact* k = s->k;
    double fx, fy, fmz, wmac, wmic, ck;
    int ierr;
    for (long i = 0; i < reps; ++i) {
        cwsolm_(&k->a, &k->b, &k->fn, &k->fmu, &k->g, &k->pnu, &k->xi, &k->eta, &k->phi, &s->n,
                &s->n, &fx, &fy, &fmz, &wmac, &wmic, &ck, s->px, s->py, s->sx, s->sy, s->zmap,
                s->wpap, s->wcon, s->istate, &ierr);
        s->failures += ierr != 0;
    }
}

static int same_bits(double x, double y) { return memcmp(&x, &y, sizeof x) == 0; }

/* CWFORC's FX, FY, FMZ against the C forces-only solve. */
static int bitwise_equal(Setup* s)
{
    cw_result r;
    cw_result_init(&r);
    if (cw_solver_solve(s->solver, &s->params, CW_SOLVE_FORCES, &r) != CW_OK) return 0;
    const Contact* k = s->k;
    const int load = 0;
    double fx, fy, fmz, wmac, adh;
    int ierr;
    cwforc_(&k->a, &k->b, &k->fn, &k->fmu, &k->g, &k->pnu, &k->xi, &k->eta, &k->phi, &s->n,
            &s->n, &load, &fx, &fy, &fmz, &wmac, &adh, &ierr);
    return ierr == 0 && same_bits(fx, r.Fx) && same_bits(fy, r.Fy) && same_bits(fmz, r.Mz);
}

static void stamp(void)
{
    char cpu[256] = "unknown CPU";
    FILE* f = fopen("/proc/cpuinfo", "r");
    if (f) {
        char line[512];
        while (fgets(line, sizeof line, f)) {
            if (strncmp(line, "model name", 10) == 0) {
                const char* colon = strchr(line, ':');
                if (colon) {
                    snprintf(cpu, sizeof cpu, "%s", colon + 2);
                    cpu[strcspn(cpu, "\n")] = '\0';
                }
                break;
            }
        }
        fclose(f);
    }
    double load = -1.0;
    f = fopen("/proc/loadavg", "r");
    if (f) {
        if (fscanf(f, "%lf", &load) != 1) load = -1.0;
        fclose(f);
    }
    char date[32];
    const time_t t = time(NULL);
    strftime(date, sizeof date, "%Y-%m-%d", gmtime(&t));
    /* The machine only: scripts/bench-report.sh stamps the commit of the tree it measures. */
    printf("%s; %s (%s); library %s; %s; load average %.1f\n\n", cpu, CW_BENCH_COMPILER,
           CW_BENCH_BUILD_TYPE, cw_version_string(), date, load);
}

int main(int argc, char** argv)
{
    const int only_grid = argc > 1 ? atoi(argv[1]) : 0;
    int samples_n = argc > 2 ? atoi(argv[2]) : SAMPLES;
    if (samples_n < 1 || samples_n > SAMPLES) samples_n = SAMPLES;
    static const Contact contacts[] = {
        {"partial slip", 7.17e-3, 5.42e-3, 100e3, 0.3, 82e9, 0.28, 6e-4, 3e-4, 0.2},
        {"full sliding", 7.17e-3, 5.42e-3, 100e3, 0.3, 82e9, 0.28, 0.3, 0.0, 0.0},
    };
    static const int grids[] = {10, 20, 40};
    void (*const runners[RUNNERS])(Setup*, long) = {c_forces, legacy_forces, c_full, legacy_full};
    stamp();
    printf("CPU time per call [us], median of %d samples\n", samples_n);
    printf("\n| contact | grid | C forces us | CWFORC us | CWFORC / C | C full + maps us | CWSOLM us "
           "| CWSOLM / C full | bitwise |\n|---|---|---:|---:|---:|---:|---:|---:|---|\n");
    int failures = 0;
    for (size_t ci = 0; ci < sizeof contacts / sizeof contacts[0]; ++ci) {
        for (size_t gi = 0; gi < sizeof grids / sizeof grids[0]; ++gi) {
            if (only_grid > 0 && grids[gi] != only_grid) continue;
            Setup s = {0};
            s.n = grids[gi];
            s.k = &contacts[ci];
            cw_grid g;
            cw_grid_init(&g);
            g.nx = g.ny = s.n;
            if (cw_solver_create(&g, &s.solver, NULL, 0) != CW_OK) return 1;
            cw_params_init(&s.params);
            s.params.a = s.k->a;
            s.params.b = s.k->b;
            s.params.normal_force = s.k->fn;
            s.params.mu = s.k->fmu;
            s.params.G = s.k->g;
            s.params.nu = s.k->pnu;
            s.params.xi_x = s.k->xi;
            s.params.xi_y = s.k->eta;
            s.params.phi = s.k->phi;
            const size_t len = (size_t)s.n * (size_t)s.n;
            s.maps = malloc(14 * len * sizeof(double));
            s.istate = malloc(len * sizeof(int));
            if (!s.maps || !s.istate) return 1;
            s.px = s.maps + 7 * len;
            s.py = s.px + len;
            s.sx = s.py + len;
            s.sy = s.sx + len;
            s.zmap = s.sy + len;
            s.wpap = s.zmap + len;
            s.wcon = s.wpap + len;
            /* About 2 ms of forces-only solves per sample and runner. */
            const long reps = 800000 / (long)len;
            for (int r = 0; r < RUNNERS; ++r) runners[r](&s, reps / 10 + 1); /* warm up */
            double samples[RUNNERS][SAMPLES];
            for (int k = 0; k < samples_n; ++k)
                for (int r = 0; r < RUNNERS; ++r) {
                    const double t0 = now();
                    runners[r](&s, reps);
                    samples[r][k] = (now() - t0) / (double)reps * 1e6;
                }
            double median[RUNNERS];
            for (int r = 0; r < RUNNERS; ++r) {
                qsort(samples[r], samples_n, sizeof(double), by_value);
                median[r] = samples[r][samples_n / 2];
            }
            const int same = bitwise_equal(&s);
            failures += s.failures + !same;
            printf("| %s | %d x %d | %.3f | %.3f | %.2f | %.3f | %.3f | %.2f | %s |\n", s.k->name,
                   s.n, s.n, median[0], median[1], median[1] / median[0], median[2], median[3],
                   median[3] / median[2], same ? "yes" : "NO");
            cw_solver_destroy(s.solver);
            free(s.maps);
            free(s.istate);
        }
    }
    cwfree_();
    if (failures) {
        fprintf(stderr, "creepwork_bench_legacy: %d failures\n", failures);
        return 1;
    }
    return 0;
}
