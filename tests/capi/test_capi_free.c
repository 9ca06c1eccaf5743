/* Free functions: Kalker's coefficients, the flexibilities, the Hertz
 * helper, and the error paths of cw_fastsim_normalised (its values are
 * checked with the core against Kalker 1982). */
#include "capi_fixtures.h"

#include <stdlib.h>

static const double pi = 3.14159265358979323846;

/* ------------------------------------------------------------ coefficients */

/* At the table's nodes the interpolation returns the table: Kalker 1990,
 * Table E.3 (reference/kalker_cij.csv), every g and nu = 0, 0.25, 0.5, for
 * a/b = g and a/b = 1/g. The table prints 3 digits; the values in the
 * library are those digits, so 1e-12 relative covers rounding of 1/C. */
static void coefficients_reproduce_table_e3(void** state)
{
    (void)state;
    FILE* f = fopen(CW_TEST_DATA_DIR "/kalker_cij.csv", "r");
    assert_non_null(f);
    char line[256];
    assert_non_null(fgets(line, sizeof line, f));
    assert_int_equal(strncmp(line, "a_over_b,g,nu,C11,C22,C23,C33", 29), 0);
    int rows = 0;
    double a_over_b, g, nu, C[4];
    while (fgets(line, sizeof line, f)) {
        if (sscanf(line, "%lf,%lf,%lf,%lf,%lf,%lf,%lf", &a_over_b, &g, &nu, &C[0], &C[1], &C[2],
                   &C[3]) != 7)
            continue;
        /* The file rounds a/b = 1/g to 6 digits; the node is 1/g exactly. */
        const double ratio = a_over_b <= 1.0 ? g : 1.0 / g;
        double out[4];
        char message[128];
        assert_int_equal(cw_kalker_coefficients(ratio, nu, out, message, sizeof message), CW_OK);
        assert_string_equal(message, "");
        for (int k = 0; k < 4; ++k) assert_close(out[k], C[k], 1e-12, 0.0);
        ++rows;
    }
    fclose(f);
    assert_int_equal(rows, 57); /* 19 ratios x 3 values of nu */
}

/* Header: L1 = 8a/(3 C11 G), L2 = 8a/(3 C22 G), L3 = pi a sqrt(a/b)/(4 C23 G)
 * with the coefficients above (to rounding, 1e-14); and the pure-creepage
 * flexibilities CONTACT used (reference/contact_fastsim_dev.csv: L1 of the
 * lonS rows, L2 of latS, L3 of spnS; G = 82000 N/mm^2, nu = 0.28, a/b = 1
 * and 2). CONTACT interpolates Table E.3 the same way but with its own
 * rounding of the constants: they agree to 4e-8, so 1e-7. */
static void flexibilities_follow_kalker(void** state)
{
    (void)state;
    const double cases[][4] = {
        /* a, b, G, nu */
        {6e-3, 6e-3, 82e9, 0.28},  {7e-3, 4e-3, 82e9, 0.28}, {2e-3, 9e-3, 80e9, 0.3},
        {1e-3, 50e-3, 82e9, 0.25}, {30e-3, 1e-3, 70e9, 0.0}, {5e-3, 5e-3, 1.0, 0.5},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        const double a = cases[k][0], b = cases[k][1], G = cases[k][2], nu = cases[k][3];
        double C[4], L[3];
        assert_int_equal(cw_kalker_coefficients(a / b, nu, C, NULL, 0), CW_OK);
        assert_int_equal(cw_kalker_flexibilities(a, b, G, nu, L, NULL, 0), CW_OK);
        assert_close(L[0], 8.0 * a / (3.0 * C[0] * G), 1e-14, 0.0);
        assert_close(L[1], 8.0 * a / (3.0 * C[1] * G), 1e-14, 0.0);
        assert_close(L[2], pi * a * sqrt(a / b) / (4.0 * C[2] * G), 1e-14, 0.0);
    }
    const double contact[2][6] = {
        /* a, b [mm], L1 (lonS), L2 (latS), L3 (spnS) [mm^3/N] */
        {6.0, 6.0, 4.6169165596826505e-05, 5.266553432746571e-05, 3.86188279138296e-05},
        {8.485281374238571, 4.242640687119285, 5.302842474172814e-05, 5.550527578504869e-05,
         4.326407990721517e-05},
    };
    for (int k = 0; k < 2; ++k) {
        double L[3];
        assert_int_equal(
            cw_kalker_flexibilities(contact[k][0], contact[k][1], 82000.0, 0.28, L, NULL, 0),
            CW_OK);
        for (int i = 0; i < 3; ++i) assert_close(L[i], contact[k][2 + i], 1e-7, 0.0);
    }
}

/* A solve with flexibilities from the material reports the same L's and
 * C's as the free functions. */
static void solve_reports_the_same_coefficients(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_KALKER_STRIPS, 20, 20, 1.0); /* cw_grid_init's */
    cw_params p;
    cw_test_case(2, &p);
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &r), CW_OK);
    double C[4], L[3];
    assert_int_equal(cw_kalker_coefficients(p.a / p.b, p.nu, C, NULL, 0), CW_OK);
    assert_int_equal(cw_kalker_flexibilities(p.a, p.b, p.G, p.nu, L, NULL, 0), CW_OK);
    assert_true(cw_same_bits(r.C11, C[0]) && cw_same_bits(r.C22, C[1]) &&
                cw_same_bits(r.C23, C[2]) && cw_same_bits(r.C33, C[3]));
    assert_true(cw_same_bits(r.L1, L[0]) && cw_same_bits(r.L2, L[1]) &&
                cw_same_bits(r.L3, L[2]));
    /* Given flexibilities: passed through, C's reported as 0 (header). */
    cw_test_case(7, &p);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &r), CW_OK);
    assert_true(r.L1 == p.L1 && r.L2 == p.L2 && r.L3 == p.L3);
    assert_true(r.C11 == 0.0 && r.C22 == 0.0 && r.C23 == 0.0 && r.C33 == 0.0);
    cw_solver_destroy(s);
}

/* ------------------------------------------------------------------- Hertz */

/* K(e), E(e) by the trapezoidal rule over a quarter period: exponentially
 * accurate for this smooth periodic integrand, with an error like
 * exp(-2n sqrt(1-e^2)); 20000 points reach rounding for b/a >= 0.005. */
static void elliptic_integrals(double e, double* K, double* E)
{
    const int n = 20000;
    double k = 0.0, ee = 0.0;
    for (int i = 0; i <= n; ++i) {
        const double t = 0.5 * pi * i / n;
        const double s = sqrt(1.0 - e * e * sin(t) * sin(t));
        const double w = (i == 0 || i == n) ? 0.5 : 1.0;
        k += w / s;
        ee += w * s;
    }
    *K = k * 0.5 * pi / n;
    *E = ee * 0.5 * pi / n;
}

/* Circular contact (A = B = 1/(2R)): Hertz, a = (3 N R / (4 E*))^(1/3),
 * p0 = 3N/(2 pi a^2), approach a^2/R (Johnson 1985, eqs. 4.22-4.23). */
static void hertz_circular(void** state)
{
    (void)state;
    const double R = 0.4, N = 80e3, E = 82e9 / (1.0 - 0.28);
    double h[4];
    char message[64];
    assert_int_equal(cw_hertz_solve(1.0 / (2.0 * R), 1.0 / (2.0 * R), N, E, h, message,
                                    sizeof message),
                     CW_OK);
    assert_string_equal(message, "");
    const double a = cbrt(3.0 * N * R / (4.0 * E));
    assert_close(h[0], a, 1e-13, 0.0);
    assert_close(h[1], a, 1e-13, 0.0);
    assert_close(h[2], 3.0 * N / (2.0 * pi * a * a), 1e-13, 0.0);
    assert_close(h[3], a * a / R, 1e-13, 0.0);
}

/* Elliptic contact, Johnson 1985 eqs. 4.39-4.40: with e^2 = 1 - (b/a)^2 for
 * the longer axis a (along the smaller curvature),
 *   A = (p0/E*) b/(e^2 a^2) (K - E),  B = (p0/E*) b/(e^2 a^2) ((a/b)^2 E - K),
 *   approach = p0 b K / E*,  p0 = 3N/(2 pi a b).
 * The helper solves for a, b from A, B; feeding its a, b back must return
 * the curvatures (1e-10: bisection to rounding). Swapping A and B swaps the
 * axes. N = 0 gives a point. */
static void hertz_elliptic(void** state)
{
    (void)state;
    const double curvatures[][2] = {{1.0 / (2 * 0.46), 1.0 / (2 * 0.3)},
                                    {0.5, 5.0},
                                    {1.0, 1.001},
                                    {0.02, 40.0}};
    const double N = 100e3, Es = 82e9 / (1.0 - 0.28);
    for (size_t k = 0; k < sizeof curvatures / sizeof curvatures[0]; ++k) {
        const double A = curvatures[k][0], B = curvatures[k][1];
        double h[4], swapped[4];
        assert_int_equal(cw_hertz_solve(A, B, N, Es, h, NULL, 0), CW_OK);
        assert_int_equal(cw_hertz_solve(B, A, N, Es, swapped, NULL, 0), CW_OK);
        const double a = h[0], b = h[1], p0 = h[2];
        assert_true(a > b); /* A < B: the long axis is along x */
        assert_close(p0, 3.0 * N / (2.0 * pi * a * b), 1e-14, 0.0);
        double K, E;
        const double e = sqrt(1.0 - (b / a) * (b / a));
        elliptic_integrals(e, &K, &E);
        const double f = p0 / Es * b / (e * e * a * a);
        assert_close(f * (K - E), A, 1e-10, 0.0);
        assert_close(f * ((a / b) * (a / b) * E - K), B, 1e-10, 0.0);
        assert_close(h[3], p0 * b * K / Es, 1e-10, 0.0);
        assert_close(swapped[0], b, 1e-14, 0.0);
        assert_close(swapped[1], a, 1e-14, 0.0);
        assert_close(swapped[2], p0, 1e-14, 0.0);
        assert_close(swapped[3], h[3], 1e-14, 0.0);
    }
    double h[4];
    assert_int_equal(cw_hertz_solve(0.5, 2.0, 0.0, Es, h, NULL, 0), CW_OK);
    assert_true(h[0] == 0.0 && h[1] == 0.0 && h[2] == 0.0 && h[3] == 0.0);
}

/* ------------------------------------------------------------------- errors */

/* Status, message naming the input (also with a NULL or zero-length message
 * buffer), output untouched. */
#define EXPECT_FREE_ERROR(call_with_message, status, needle, out, n) \
    do {                                                             \
        char message[256];                                           \
        cw_fill((out), (n), CW_SENTINEL);                            \
        assert_int_equal((call_with_message), (status));             \
        assert_names(message, (needle));                             \
        assert_untouched((out), (n));                                \
    } while (0)

static void coefficients_errors(void** state)
{
    (void)state;
    const double nan = strtod("nan", NULL), inf = strtod("inf", NULL);
    double C[4];
    EXPECT_FREE_ERROR(cw_kalker_coefficients(1.0, 0.28, NULL, message, sizeof message),
                      CW_ERR_NULL_POINTER, "coefficients", C, 4);
    const double bad_ratio[] = {nan, inf, 0.0, -1.0, CW_MIN_ASPECT * 0.999,
                                CW_MAX_ASPECT * 1.001};
    for (size_t k = 0; k < sizeof bad_ratio / sizeof bad_ratio[0]; ++k)
        EXPECT_FREE_ERROR(cw_kalker_coefficients(bad_ratio[k], 0.28, C, message, sizeof message),
                          CW_ERR_INVALID_INPUT, "a_over_b", C, 4);
    const double bad_nu[] = {nan, -inf, -0.01, 0.51};
    for (size_t k = 0; k < sizeof bad_nu / sizeof bad_nu[0]; ++k)
        EXPECT_FREE_ERROR(cw_kalker_coefficients(1.0, bad_nu[k], C, message, sizeof message),
                          CW_ERR_INVALID_INPUT, "nu", C, 4);
    /* Limits are inclusive. */
    assert_int_equal(cw_kalker_coefficients(CW_MIN_ASPECT, 0.0, C, NULL, 0), CW_OK);
    assert_int_equal(cw_kalker_coefficients(CW_MAX_ASPECT, 0.5, C, NULL, 0), CW_OK);
    for (int k = 0; k < 4; ++k) assert_true(isfinite(C[k]) && C[k] > 0.0);
}

static void flexibilities_errors(void** state)
{
    (void)state;
    const double nan = strtod("nan", NULL), inf = strtod("inf", NULL);
    double L[3];
    EXPECT_FREE_ERROR(cw_kalker_flexibilities(6e-3, 6e-3, 82e9, 0.28, NULL, message,
                                              sizeof message),
                      CW_ERR_NULL_POINTER, "flexibilities", L, 3);
    EXPECT_FREE_ERROR(cw_kalker_flexibilities(0.0, 6e-3, 82e9, 0.28, L, message, sizeof message),
                      CW_ERR_INVALID_INPUT, "a = ", L, 3);
    EXPECT_FREE_ERROR(cw_kalker_flexibilities(6e-3, nan, 82e9, 0.28, L, message, sizeof message),
                      CW_ERR_INVALID_INPUT, "b = ", L, 3);
    EXPECT_FREE_ERROR(cw_kalker_flexibilities(6e-3, 7.0, 82e9, 0.28, L, message, sizeof message),
                      CW_ERR_INVALID_INPUT, "a/b", L, 3);
    EXPECT_FREE_ERROR(cw_kalker_flexibilities(6e-3, 6e-3, -1.0, 0.28, L, message, sizeof message),
                      CW_ERR_INVALID_INPUT, "G = ", L, 3);
    EXPECT_FREE_ERROR(cw_kalker_flexibilities(6e-3, 6e-3, inf, 0.28, L, message, sizeof message),
                      CW_ERR_INVALID_INPUT, "G = ", L, 3);
    EXPECT_FREE_ERROR(cw_kalker_flexibilities(6e-3, 6e-3, 82e9, 0.7, L, message, sizeof message),
                      CW_ERR_INVALID_INPUT, "nu = ", L, 3);
}

static void hertz_errors(void** state)
{
    (void)state;
    const double nan = strtod("nan", NULL), inf = strtod("inf", NULL);
    const double E = 1.1e11;
    double h[4];
    EXPECT_FREE_ERROR(cw_hertz_solve(1.0, 2.0, 1e5, E, NULL, message, sizeof message),
                      CW_ERR_NULL_POINTER, "hertz", h, 4);
    EXPECT_FREE_ERROR(cw_hertz_solve(0.0, 2.0, 1e5, E, h, message, sizeof message),
                      CW_ERR_INVALID_INPUT, "A = ", h, 4);
    EXPECT_FREE_ERROR(cw_hertz_solve(-1.0, 2.0, 1e5, E, h, message, sizeof message),
                      CW_ERR_INVALID_INPUT, "A = ", h, 4);
    EXPECT_FREE_ERROR(cw_hertz_solve(1.0, nan, 1e5, E, h, message, sizeof message),
                      CW_ERR_INVALID_INPUT, "B", h, 4);
    EXPECT_FREE_ERROR(cw_hertz_solve(1.0, 2.0, -1.0, E, h, message, sizeof message),
                      CW_ERR_INVALID_INPUT, "normal_force", h, 4);
    EXPECT_FREE_ERROR(cw_hertz_solve(1.0, 2.0, inf, E, h, message, sizeof message),
                      CW_ERR_INVALID_INPUT, "normal_force", h, 4);
    EXPECT_FREE_ERROR(cw_hertz_solve(1.0, 2.0, 1e5, 0.0, h, message, sizeof message),
                      CW_ERR_INVALID_INPUT, "E_star", h, 4);
    /* Curvature ratio beyond 1e12: no meaningful ellipse. */
    EXPECT_FREE_ERROR(cw_hertz_solve(1.0, 2e12, 1e5, E, h, message, sizeof message),
                      CW_ERR_INVALID_INPUT, "A/B", h, 4);
    /* Finite inputs, overflowing ellipse: a^3 ~ N/(E* A) = 1e300/1e-300.
     * (CW_ERR_NUMERIC is not in the header's list for this function.) */
    EXPECT_FREE_ERROR(cw_hertz_solve(1e-300, 1e-300, 1e300, 1e-300, h, message, sizeof message),
                      CW_ERR_NUMERIC, "overflowed", h, 4);
}

/* cw_fastsim_normalised: only the error paths here. */
static void fastsim_normalised_errors(void** state)
{
    (void)state;
    const double nan = strtod("nan", NULL), inf = strtod("inf", NULL);
    double t[2];
    double tx, ty;
    EXPECT_FREE_ERROR(cw_fastsim_normalised(0, 0, 0, 0, 5, 5, 3, NULL, &t[1], message,
                                            sizeof message),
                      CW_ERR_NULL_POINTER, "tx", t, 2);
    EXPECT_FREE_ERROR(cw_fastsim_normalised(0, 0, 0, 0, 5, 5, 3, &t[0], NULL, message,
                                            sizeof message),
                      CW_ERR_NULL_POINTER, "ty", t, 2);
    EXPECT_FREE_ERROR(cw_fastsim_normalised(nan, 0, 0, 0, 5, 5, 3, &t[0], &t[1], message,
                                            sizeof message),
                      CW_ERR_INVALID_INPUT, "ux", t, 2);
    EXPECT_FREE_ERROR(cw_fastsim_normalised(0, inf, 0, 0, 5, 5, 3, &t[0], &t[1], message,
                                            sizeof message),
                      CW_ERR_INVALID_INPUT, "uy", t, 2);
    EXPECT_FREE_ERROR(cw_fastsim_normalised(0, 0, -inf, 0, 5, 5, 3, &t[0], &t[1], message,
                                            sizeof message),
                      CW_ERR_INVALID_INPUT, "fx", t, 2);
    EXPECT_FREE_ERROR(cw_fastsim_normalised(0, 0, 0, nan, 5, 5, 3, &t[0], &t[1], message,
                                            sizeof message),
                      CW_ERR_INVALID_INPUT, "fy", t, 2);
    EXPECT_FREE_ERROR(cw_fastsim_normalised(0, 0, 0, 0, 5, 5, nan, &t[0], &t[1], message,
                                            sizeof message),
                      CW_ERR_INVALID_INPUT, "tol", t, 2);
    const int bad_cells[] = {0, -3, CW_MAX_GRID_CELLS + 1};
    for (int k = 0; k < 3; ++k) {
        EXPECT_FREE_ERROR(cw_fastsim_normalised(1, 0, 0, 0, bad_cells[k], 5, 3, &t[0], &t[1],
                                                message, sizeof message),
                          CW_ERR_GRID_OUT_OF_RANGE, "mx", t, 2);
        EXPECT_FREE_ERROR(cw_fastsim_normalised(1, 0, 0, 0, 5, bad_cells[k], 3, &t[0], &t[1],
                                                message, sizeof message),
                          CW_ERR_GRID_OUT_OF_RANGE, "my", t, 2);
    }
    /* After an error, a good call works (no hidden state) and clears the
     * message. */
    char message[64];
    assert_int_equal(cw_fastsim_normalised(0, -2, 2, 4, 5, 5, 3, &tx, &ty, message,
                                           sizeof message),
                     CW_OK);
    assert_string_equal(message, "");
    assert_true(isfinite(tx) && isfinite(ty));
}

/* Message buffers of the free functions: truncated to message_len bytes
 * with a NUL, untouched for length 0, and NULL accepted. */
static void free_function_message_buffers(void** state)
{
    (void)state;
    double C[4];
    char full[256], small[6];
    assert_int_equal(cw_kalker_coefficients(-1.0, 0.28, C, full, sizeof full),
                     CW_ERR_INVALID_INPUT);
    memset(small, 'x', sizeof small);
    assert_int_equal(cw_kalker_coefficients(-1.0, 0.28, C, small, sizeof small),
                     CW_ERR_INVALID_INPUT);
    assert_int_equal(small[sizeof small - 1], '\0');
    assert_memory_equal(small, full, sizeof small - 1);
    memset(small, 'x', sizeof small);
    assert_int_equal(cw_kalker_coefficients(-1.0, 0.28, C, small, 0), CW_ERR_INVALID_INPUT);
    for (size_t k = 0; k < sizeof small; ++k) assert_int_equal(small[k], 'x');
    assert_int_equal(cw_hertz_solve(-1.0, 1.0, 1.0, 1.0, C, NULL, 10), CW_ERR_INVALID_INPUT);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(coefficients_reproduce_table_e3),
        cmocka_unit_test(flexibilities_follow_kalker),
        cmocka_unit_test(solve_reports_the_same_coefficients),
        cmocka_unit_test(hertz_circular),
        cmocka_unit_test(hertz_elliptic),
        cmocka_unit_test(coefficients_errors),
        cmocka_unit_test(flexibilities_errors),
        cmocka_unit_test(hertz_errors),
        cmocka_unit_test(fastsim_normalised_errors),
        cmocka_unit_test(free_function_message_buffers),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
