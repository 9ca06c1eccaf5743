/* Cost of wear on top of a solve, through the C ABI (doc/theory/wear.md): per
 * contact, cw_solver_solve (CW_SOLVE_FULL), cw_wear_compute (USFD and
 * Archard/KTH), cw_wear_profile_add onto a 400-node profile, and
 * cw_wear_profile_get_depth. The partial-slip contact of creepwork_bench,
 * Kalker strip grid n x n, best of 21 samples of 200 repetitions each.
 * Not a test: prints a table (`build/bin/creepwork_bench_wear`). */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <time.h>

#include <creepwork/creepwork.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

enum { REPS = 200, SAMPLES = 21, NODES = 400 };

int main(void)
{
    static const int grids[] = {10, 20, 40, 100};
    double nodes[NODES];
    for (int k = 0; k < NODES; ++k) nodes[k] = -0.02 + 1e-4 * k;
    printf("| grid | solve (full) us | wear USFD us | wear Archard us | profile add us | "
           "get depth us |\n|---|---:|---:|---:|---:|---:|\n");
    for (size_t gi = 0; gi < sizeof grids / sizeof grids[0]; ++gi) {
        cw_grid g;
        cw_grid_init(&g);
        g.nx = g.ny = grids[gi];
        cw_solver* s = NULL;
        cw_wear* w = NULL;
        cw_wear_profile* pr = NULL;
        if (cw_solver_create(&g, &s, NULL, 0) || cw_wear_create(s, &w) ||
            cw_wear_profile_create(nodes, NODES, &pr, NULL, 0))
            return 1;
        cw_params p;
        cw_params_init(&p);
        p.a = 7.17e-3;
        p.b = 5.42e-3;
        p.normal_force = 100e3;
        p.xi_x = 6e-4;
        p.xi_y = 3e-4;
        p.phi = 0.2;
        cw_wear_params usfd, archard;
        cw_wear_params_init(&usfd);
        cw_wear_params_init(&archard);
        archard.law = CW_WEAR_ARCHARD_KTH;
        archard.rolling_speed = 30.0;
        double out[NODES];
        double best[5] = {1e9, 1e9, 1e9, 1e9, 1e9};
        int failures = 0;
        for (int sample = 0; sample < SAMPLES; ++sample) {
            double t[6];
            t[0] = now();
            for (int r = 0; r < REPS; ++r) failures += cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL);
            t[1] = now();
            for (int r = 0; r < REPS; ++r) failures += cw_wear_compute(w, s, &usfd, NULL);
            t[2] = now();
            for (int r = 0; r < REPS; ++r) failures += cw_wear_compute(w, s, &archard, NULL);
            t[3] = now();
            for (int r = 0; r < REPS; ++r)
                failures += cw_wear_profile_add(pr, w, 1e-5 * r, 1, 0.1, 1.0);
            t[4] = now();
            for (int r = 0; r < REPS; ++r)
                failures += cw_wear_profile_get_depth(pr, CW_WEAR_DEPTH_NORMAL, out, NODES);
            t[5] = now();
            for (int k = 0; k < 5; ++k)
                if ((t[k + 1] - t[k]) / REPS < best[k]) best[k] = (t[k + 1] - t[k]) / REPS;
        }
        if (failures) return 1;
        printf("| %d x %d | %.2f | %.2f | %.2f | %.2f | %.2f |\n", grids[gi], grids[gi],
               1e6 * best[0], 1e6 * best[1], 1e6 * best[2], 1e6 * best[3], 1e6 * best[4]);
        cw_wear_profile_destroy(pr);
        cw_wear_destroy(w);
        cw_solver_destroy(s);
    }
    return 0;
}
