/* creepwork wear quickstart: the rail wear of one contact state, 1000 axle
 * passages, accumulated on a rail profile grid (doc/theory/wear.md). */
#include <stdio.h>
#include <creepwork/creepwork.h>

int main(void)
{
    cw_grid grid;
    cw_grid_init(&grid); /* Kalker's strip grid, 20 x 20 */
    cw_solver* solver = NULL;
    cw_wear* wear = NULL;
    cw_wear_profile* rail = NULL;
    double s[121]; /* rail profile nodes: -30 .. 30 mm every 0.5 mm */
    for (int k = 0; k < 121; ++k) s[k] = -0.030 + 0.0005 * k;
    if (cw_solver_create(&grid, &solver, NULL, 0) != CW_OK || cw_wear_create(solver, &wear) ||
        cw_wear_profile_create(s, 121, &rail, NULL, 0) != CW_OK)
        return 1;

    cw_params p;
    cw_params_init(&p);
    p.a = 7.0e-3;
    p.b = 5.0e-3;
    p.normal_force = 100e3;
    p.xi_x = 1.0e-3;
    p.xi_y = 5.0e-4;
    p.phi = 0.5;
    cw_wear_params wp;
    cw_wear_params_init(&wp); /* USFD, R8T/900A (Braghin et al. 2006), energy-consistent map */
    cw_wear_result w;
    cw_wear_result_init(&w);
    if (cw_solver_solve(solver, &p, CW_SOLVE_FULL, NULL) != CW_OK ||
        cw_wear_compute(wear, solver, &wp, &w) != CW_OK ||
        /* the patch centre 2 mm from the rail's centre line, contact angle 0.02 rad */
        cw_wear_profile_add(rail, wear, 0.002, +1, 0.02, 1000.0) != CW_OK) {
        fprintf(stderr, "creepwork: %s %s\n", cw_wear_last_error(wear),
                cw_wear_profile_last_error(rail));
        return 1;
    }
    double depth[121];
    cw_wear_profile_get_depth(rail, CW_WEAR_DEPTH_HEIGHT, depth, 121);
    int peak = 0;
    for (int k = 1; k < 121; ++k)
        if (depth[k] > depth[peak]) peak = k;
    printf("wear per rolled metre: %.3g kg; deepest strip per pass: %.3g m\n",
           w.mass_per_distance, w.max_depth);
    printf("after 1000 passes: %.3g m deep at s = %.1f mm\n", depth[peak], 1e3 * s[peak]);
    cw_wear_profile_destroy(rail);
    cw_wear_destroy(wear);
    cw_solver_destroy(solver);
    return 0;
}
