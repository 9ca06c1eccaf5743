/* cw_solver_solve_jacobian through the public header (doc/theory/jacobians.md):
 * the layout and frame of the 4 x 4 matrix against central differences of
 * cw_solver_solve itself (FASTSIM and the calibrated model, both rolling
 * directions, SI units; 1e-6 relative to the row's scale at a step that
 * flips no element), the totals bitwise cw_solver_solve's, and every error:
 * NULL pointers, a short buffer, a bad mode, the calibrated model without
 * G and nu, no load -- each with nothing written. */
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

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(matches_central_differences),
        cmocka_unit_test(errors_write_nothing),
        cmocka_unit_test(exact_model),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : NULL);
}
