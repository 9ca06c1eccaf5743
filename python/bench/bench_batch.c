/* The C side of python/bench/bench_python.py: the same contacts as the
 * Python side (see contact() there: one formula, evaluated in the same
 * order in both languages, so the inputs are bitwise equal), solved by one
 * cw_batch_solve call (FASTSIM, Kalker's strip grid 20 x 20, CW_SOLVE_FORCES;
 * wall clock) and one by one by cw_solver_solve (CPU time of the thread).
 * Prints the best time of each over the repetitions and writes Fx, Fy, Mz, W_macro of every contact to a binary
 * file, which the driver compares bitwise with solve_many's.
 *
 * usage: creepwork_bench_python_batch COUNT THREADS REPETITIONS OUT.bin */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include <creepwork/creepwork.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* CPU time of this thread: one-by-one solves are timed by it, which a busy
 * machine disturbs far less than the wall clock (bench_python.py times its
 * one-contact calls the same way). */
static double cpu(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Contact k of the benchmark: a sweep over creepages and spin. */
static void contact(size_t k, cw_params* p)
{
    cw_params_init(p);
    p->a = 7e-3;
    p->b = 5e-3;
    p->normal_force = 100e3;
    p->xi_x = -3e-3 + 6e-3 * (double)(k % 101) / 100.0;
    p->xi_y = -2e-3 + 4e-3 * (double)(k % 37) / 36.0;
    p->phi = -1.5 + 3.0 * (double)(k % 13) / 12.0;
}

int main(int argc, char** argv)
{
    if (argc != 5) {
        fprintf(stderr, "usage: %s COUNT THREADS REPETITIONS OUT.bin\n", argv[0]);
        return 2;
    }
    const size_t n = (size_t)strtoul(argv[1], NULL, 10);
    const int threads = atoi(argv[2]);
    const int reps = atoi(argv[3]);
    cw_params* params = malloc(n * sizeof *params);
    cw_result* results = malloc(n * sizeof *results);
    int* statuses = malloc(n * sizeof *statuses);
    if (!params || !results || !statuses || n == 0 || reps < 1) return 1;
    for (size_t k = 0; k < n; ++k) {
        contact(k, &params[k]);
        cw_result_init(&results[k]);
    }
    cw_grid grid;
    cw_grid_init(&grid);
    cw_batch* batch = NULL;
    cw_solver* solver = NULL;
    char message[256];
    if (cw_batch_create(&grid, threads, &batch, message, sizeof message) != CW_OK ||
        cw_solver_create(&grid, &solver, message, sizeof message) != CW_OK) {
        fprintf(stderr, "%s\n", message);
        return 1;
    }
    double best_batch = 1e30, best_single = 1e30;
    for (int r = 0; r < reps; ++r) {
        double t0 = now();
        if (cw_batch_solve(batch, n, params, CW_SOLVE_FORCES, results, statuses) != CW_OK) {
            fprintf(stderr, "%s\n", cw_batch_last_error(batch));
            return 1;
        }
        double t1 = now();
        if (t1 - t0 < best_batch) best_batch = t1 - t0;
        cw_result one;
        cw_result_init(&one);
        t0 = cpu();
        for (size_t k = 0; k < n; ++k)
            if (cw_solver_solve(solver, &params[k], CW_SOLVE_FORCES, &one) != CW_OK) return 1;
        t1 = cpu();
        if (t1 - t0 < best_single) best_single = t1 - t0;
    }
    FILE* out = fopen(argv[4], "wb");
    if (!out) return 1;
    for (size_t k = 0; k < n; ++k) {
        const double v[4] = {results[k].Fx, results[k].Fy, results[k].Mz, results[k].W_macro};
        if (fwrite(v, sizeof v[0], 4, out) != 4) return 1;
    }
    if (fclose(out) != 0) return 1;
    printf("c_batch_seconds %.9g\nc_single_seconds %.9g\n", best_batch, best_single);
    cw_solver_destroy(solver);
    cw_batch_destroy(batch);
    free(params);
    free(results);
    free(statuses);
    return 0;
}
