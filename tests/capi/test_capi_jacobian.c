/* cw_solver_solve_jacobian through the public header (doc/theory/jacobians.md):
 * the layout and frame of the 4 x 4 matrix against central differences of
 * cw_solver_solve itself (FASTSIM and the calibrated model, both rolling
 * directions, SI units; 1e-6 relative to the row's scale at a step that
 * flips no element), the totals bitwise cw_solver_solve's, and every error:
 * NULL pointers, a short buffer, a bad mode, the calibrated model without
 * G and nu, no load -- each with nothing written. On a gap grid (two
 * lobes, two patches) the exact model and FASTSIM (both normal methods, the
 * force or the approach given) against central differences of their own
 * solves, and normal_force = 0 an error naming it. */
#include "capi_fixtures.h"

#include <math.h>

static cw_params partial_slip(int direction)
{
    cw_params p;
    cw_params_init(&p);
    p.xi_x = 1e-3;
    p.xi_y = -6e-4;
    p.phi = 0.3;
    p.rolling_direction = direction;
    return p;
}

static double* column(cw_params* p, int c)
{
    switch (c) {
    case CW_JAC_XI_X: return &p->xi_x;
    case CW_JAC_XI_Y: return &p->xi_y;
    case CW_JAC_PHI: return &p->phi;
    default: return &p->normal_force;
    }
}

static void totals(cw_solver* s, const cw_params* p, double out[4], int* slips)
{
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_solve(s, p, CW_SOLVE_FORCES, &r), CW_OK);
    out[0] = r.Fx;
    out[1] = r.Fy;
    out[2] = r.Mz;
    out[3] = r.W_macro;
    *slips = r.n_slip;
}

static void matches_central_differences(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_UNIFORM, 24, 20, 1.0);
    for (int run = 0; run < 4; ++run) {
        const int direction = run % 2 ? 1 : -1;
        cw_params p = partial_slip(direction);
        p.pressure = CW_PRESSURE_ELLIPTIC;
        p.model = run < 2 ? CW_MODEL_FASTSIM : CW_MODEL_CALIBRATED;
        double J[CW_JACOBIAN_LEN];
        cw_result r;
        cw_result_init(&r);
        assert_int_equal(
            cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, &r, J, CW_JACOBIAN_LEN), CW_OK);
        assert_true(r.n_slip > 0 && r.n_adhesion > 0);
        /* Totals bitwise a plain solve's. */
        double plain[4];
        int slips = 0;
        totals(s, &p, plain, &slips);
        assert_true(cw_same_bits(plain[0], r.Fx) && cw_same_bits(plain[1], r.Fy) &&
                    cw_same_bits(plain[2], r.Mz) && cw_same_bits(plain[3], r.W_macro));

        const double c = sqrt(p.a * p.b);
        const double scale[4] = {1e-3, 1e-3, 1e-3 / c, p.normal_force};
        const double rel = 1e-5; /* the step study of test_core_jacobian: best 1e-5 ... 1e-4 */
        for (int col = 0; col < 4; ++col) {
            cw_params up = p, down = p;
            *column(&up, col) += rel * scale[col];
            *column(&down, col) -= rel * scale[col];
            double fu[4], fd[4];
            int su = 0, sd = 0;
            totals(s, &up, fu, &su);
            totals(s, &down, fd, &sd);
            assert_int_equal(su, r.n_slip);
            assert_int_equal(sd, r.n_slip);
            for (int row = 0; row < 4; ++row) {
                double row_scale = 0.0;
                for (int k = 0; k < 4; ++k) row_scale += fabs(J[4 * row + k]) * scale[k];
                const double fdiff = (fu[row] - fd[row]) / (2.0 * rel * scale[col]);
                assert_close(J[4 * row + col], fdiff, 0.0, 1e-6 * row_scale / scale[col]);
            }
        }
        /* Signs on the wheel: the forces oppose their own creepage. */
        assert_true(J[4 * CW_JAC_FX + CW_JAC_XI_X] < 0.0);
        assert_true(J[4 * CW_JAC_FY + CW_JAC_XI_Y] < 0.0);
    }
    cw_solver_destroy(s);
}

static void errors_write_nothing(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_KALKER_STRIPS, 10, 10, 1.0);
    cw_params p = partial_slip(1);
    double J[CW_JACOBIAN_LEN + 1];
    cw_result r;

    assert_int_equal(cw_solver_solve_jacobian(NULL, &p, CW_SOLVE_FORCES, NULL, J,
                                              CW_JACOBIAN_LEN),
                     CW_ERR_NULL_POINTER);
    cw_fill(J, CW_JACOBIAN_LEN + 1, CW_SENTINEL);
    assert_int_equal(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, NULL, NULL, 16),
                     CW_ERR_NULL_POINTER);
    assert_names(cw_solver_last_error(s), "jacobian");
    assert_int_equal(cw_solver_solve_jacobian(s, NULL, CW_SOLVE_FORCES, NULL, J, 16),
                     CW_ERR_NULL_POINTER);
    assert_names(cw_solver_last_error(s), "params");

    cw_poison_result(&r);
    assert_int_equal(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, &r, J, 15),
                     CW_ERR_BUFFER_TOO_SMALL);
    assert_names(cw_solver_last_error(s), "jacobian");
    assert_untouched(J, CW_JACOBIAN_LEN + 1);
    {
        cw_result poisoned;
        cw_poison_result(&poisoned);
        assert_memory_equal(&r, &poisoned, sizeof r);
    }

    assert_int_equal(cw_solver_solve_jacobian(s, &p, 7, NULL, J, 16), CW_ERR_UNKNOWN_OPTION);
    assert_untouched(J, CW_JACOBIAN_LEN + 1);

    p.model = CW_MODEL_CALIBRATED; /* its table needs Kalker's flexibilities */
    p.flexibility = CW_FLEX_GIVEN;
    p.L1 = p.L2 = p.L3 = 1e-11;
    assert_int_equal(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, NULL, J, 16),
                     CW_ERR_INVALID_INPUT);
    assert_names(cw_solver_last_error(s), "calibrated");
    assert_untouched(J, CW_JACOBIAN_LEN + 1);
    p.flexibility = CW_FLEX_FROM_MATERIAL;

    p.model = CW_MODEL_EXACT; /* needs the uniform grid */
    assert_int_equal(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, NULL, J, 16),
                     CW_ERR_INVALID_INPUT);
    assert_untouched(J, CW_JACOBIAN_LEN + 1);

    p.model = CW_MODEL_FASTSIM;
    p.normal_force = 0.0;
    assert_int_equal(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, NULL, J, 16),
                     CW_ERR_INVALID_INPUT);
    assert_names(cw_solver_last_error(s), "normal_force");
    assert_untouched(J, CW_JACOBIAN_LEN + 1);
    /* After a failed solve the handle holds no solution. */
    double field[100];
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PX, field, 100), CW_ERR_NO_SOLUTION);

    p.normal_force = NAN;
    assert_int_equal(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, NULL, J, 16),
                     CW_ERR_INVALID_INPUT);
    assert_untouched(J, CW_JACOBIAN_LEN + 1);

    /* A longer buffer: exactly 16 entries written. */
    p.normal_force = 80e3;
    assert_int_equal(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FULL, NULL, J, 17), CW_OK);
    assert_int_equal(cw_count_changed(J, CW_JACOBIAN_LEN, CW_SENTINEL), CW_JACOBIAN_LEN);
    assert_untouched(J + CW_JACOBIAN_LEN, 1);
    /* The full solve's fields are there. */
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_WORK_CONSISTENT, field, 100), CW_OK);
    cw_solver_destroy(s);
}

/* The exact model through the ABI: its Jacobian against central differences
 * of its own solves (small grid, tight tolerance). */
static void exact_model(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_UNIFORM, 16, 16, 16.0 / 12.0);
    cw_params p = partial_slip(-1);
    p.model = CW_MODEL_EXACT;
    p.tolerance = 1e-13;
    p.warm_start = 0;
    double J[CW_JACOBIAN_LEN];
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, &r, J, CW_JACOBIAN_LEN),
                     CW_OK);
    const double h = 1e-8;
    cw_params up = p, down = p;
    up.xi_y += h;
    down.xi_y -= h;
    double fu[4], fd[4];
    int su = 0, sd = 0;
    totals(s, &up, fu, &su);
    totals(s, &down, fd, &sd);
    assert_int_equal(su, r.n_slip);
    assert_int_equal(sd, r.n_slip);
    for (int row = 0; row < 4; ++row)
        assert_close(J[4 * row + CW_JAC_XI_Y], (fu[row] - fd[row]) / (2 * h), 1e-6,
                     1e-6 * fabs(J[4 * CW_JAC_FY + CW_JAC_XI_Y]));
    cw_solver_destroy(s);
}

/* Two paraboloids 10 mm apart across, the upper one 2 um higher, on a
 * 30 x 48 gap grid of 0.3 x 0.45 mm. */
static cw_grid two_lobes(double* h)
{
    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_GAP;
    g.nx = 30;
    g.ny = 48;
    g.dx = 0.3e-3;
    g.dy = 0.45e-3;
    g.x0 = -14.5 * g.dx;
    g.y0 = -23.5 * g.dy;
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const double x = g.x0 + i * g.dx, y = g.y0 + j * g.dy;
            const double lo = x * x / 0.9 + (y + 5e-3) * (y + 5e-3) / 0.5;
            const double hi = x * x / 0.8 + (y - 5e-3) * (y - 5e-3) / 0.3 + 2e-6;
            h[i + g.nx * j] = lo < hi ? lo : hi;
        }
    return g;
}

/* The Jacobian on a gap grid against central differences of cw_solver_solve
 * (steps 1e-6 of each input's scale, at which no element changes state or
 * contact; tests/nonhertz/test_nonhertz_jacobian.cpp's step study finds
 * 1e-10 ... 1e-9 there), within 1e-7 of the row's scale. With the approach
 * given the N column is dF/dN along the solution: the differences of F over
 * those of N in the approach. */
static void gap_grid(void** state)
{
    (void)state;
    static double h[30 * 48];
    const cw_grid g = two_lobes(h);
    cw_solver* s = NULL;
    assert_int_equal(cw_solver_create(&g, &s, NULL, 0), CW_OK);
    for (int run = 0; run < 4; ++run) {
        cw_params p = partial_slip(run % 2 ? 1 : -1);
        p.xi_x = 2e-4;
        p.xi_y = -1.5e-4;
        p.phi = 0.1;
        p.normal_force = 50e3;
        p.model = run < 2 ? CW_MODEL_EXACT : CW_MODEL_FASTSIM;
        p.tolerance = run < 2 ? 1e-12 : 0.0;
        p.warm_start = 0;
        p.gap = h;
        p.gap_len = 30 * 48;
        if (run == 1 || run == 3) {
            p.normal_load = CW_NORMAL_APPROACH;
            p.approach = 40e-6;
        }
        if (run == 3) p.normal_method = CW_NORMAL_SEMI_HERTZ;
        double J[CW_JACOBIAN_LEN];
        cw_result r;
        cw_result_init(&r);
        assert_int_equal(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, &r, J, CW_JACOBIAN_LEN),
                         CW_OK);
        assert_true(r.n_slip > 0 && r.n_adhesion > 0 && r.n_patches == 2);
        const double scale[4] = {1e-3, 1e-3, 1e-3 / 5e-3, r.normal_force};
        const double rel = 1e-6;
        for (int col = 0; col < 4; ++col) {
            cw_params up = p, down = p;
            double step = rel * scale[col];
            if (col == CW_JAC_N && p.normal_load == CW_NORMAL_APPROACH) {
                step = rel * 40e-6;
                up.approach += step;
                down.approach -= step;
            } else {
                *column(&up, col) += step;
                *column(&down, col) -= step;
            }
            cw_result ru, rd;
            cw_result_init(&ru);
            cw_result_init(&rd);
            assert_int_equal(cw_solver_solve(s, &up, CW_SOLVE_FORCES, &ru), CW_OK);
            assert_int_equal(cw_solver_solve(s, &down, CW_SOLVE_FORCES, &rd), CW_OK);
            assert_true(ru.n_slip == r.n_slip && rd.n_slip == r.n_slip);
            assert_true(ru.n_contact == r.n_contact && rd.n_contact == r.n_contact);
            const double fu[4] = {ru.Fx, ru.Fy, ru.Mz, ru.W_macro};
            const double fd[4] = {rd.Fx, rd.Fy, rd.Mz, rd.W_macro};
            const double denominator =
                col == CW_JAC_N ? ru.normal_force - rd.normal_force : 2.0 * step;
            for (int row = 0; row < 4; ++row) {
                double row_scale = 0.0;
                for (int k = 0; k < 4; ++k) row_scale += fabs(J[4 * row + k]) * scale[k];
                assert_close(J[4 * row + col], (fu[row] - fd[row]) / denominator, 0.0,
                             1e-7 * row_scale / scale[col]);
            }
        }
    }
    /* No load: no derivative by N. */
    cw_params p = partial_slip(1);
    p.model = CW_MODEL_FASTSIM;
    p.gap = h;
    p.gap_len = 30 * 48;
    p.normal_force = 0.0;
    double J[CW_JACOBIAN_LEN];
    cw_fill(J, CW_JACOBIAN_LEN, CW_SENTINEL);
    assert_int_equal(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, NULL, J, CW_JACOBIAN_LEN),
                     CW_ERR_INVALID_INPUT);
    assert_names(cw_solver_last_error(s), "normal_force");
    assert_untouched(J, CW_JACOBIAN_LEN);
    cw_solver_destroy(s);
}

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(matches_central_differences),
        cmocka_unit_test(errors_write_nothing),
        cmocka_unit_test(exact_model),
        cmocka_unit_test(gap_grid),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : NULL);
}
