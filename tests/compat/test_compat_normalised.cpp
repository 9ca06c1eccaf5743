// doc/migrating.md's mapping for codes normalised like Kalker's FASTSIM but with
// the peak Hertz pressure p0 = 3N/(2 pi a b) and the elliptic bound
// sqrt(1 - X^2 - Y^2): the dimensional call with a = 1, b = b/a, mu = 1,
// N = 2 pi b/3 (p0 = 1), L1 = L2 = L3 = 1 given, elliptic pressure,
// xi_x = UX, xi_y = UY, phi = FY gives their normalised forces as
// (-Fx, Fy)/N. Checked two ways:
//  - with the parabolic bound (N = pi b/2, p0 = 1) the same mapping must equal
//    cw_fastsim_normalised wherever Kalker's strip layout is the equal-strip
//    grid (no spin pole in the disk, even MY), to rounding;
//  - with the elliptic bound it must equal a direct normalised march written
//    here from the definition (unit disk, MX elements per strip over its
//    chord, half a step to the first centre, rigid slip at each step's
//    midpoint, the bound sqrt(1 - X^2 - Y^2) at the element centre), to
//    rounding.
#include "compat_support.hpp"
#include "test_support.h"

#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;

// The mapping, on Kalker's equal-strip grid mx x my.
void mapped(double ux, double uy, double fy, double b_over_a, int mx, int my, int pressure,
            double* tx, double* ty)
{
    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_KALKER_STRIPS;
    g.nx = mx;
    g.ny = my;
    cw_solver* s = nullptr;
    assert_int_equal(cw_solver_create(&g, &s, nullptr, 0), CW_OK);
    cw_params p;
    cw_params_init(&p);
    p.a = 1.0;
    p.b = b_over_a;
    p.mu = 1.0;
    p.normal_force = pressure == CW_PRESSURE_ELLIPTIC ? 2.0 * kPi * p.b / 3.0 : kPi * p.b / 2.0;
    p.flexibility = CW_FLEX_GIVEN;
    p.L1 = p.L2 = p.L3 = 1.0;
    p.pressure = pressure;
    p.xi_x = ux;
    p.xi_y = uy;
    p.phi = fy;
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &r), CW_OK);
    cw_solver_destroy(s);
    *tx = -r.Fx / p.normal_force; // Kalker's printed signs
    *ty = r.Fy / p.normal_force;
}

// A normalised FASTSIM with the elliptic bound, from the definition.
void direct_elliptic(double ux, double uy, double fx, double fy, int mx, int my, double* tx,
                     double* ty)
{
    double sx = 0.0, sy = 0.0;
    for (int j = 0; j < my; ++j) {
        const double Y = -1.0 + (j + 0.5) * 2.0 / my, dY = 2.0 / my;
        const double chord = std::sqrt(1.0 - Y * Y), dX = 2.0 * chord / mx;
        double px = 0.0, py = 0.0, prev = chord;
        for (int m = 0; m < mx; ++m) {
            const double X = chord - (m + 0.5) * dX, h = prev - X, Xs = 0.5 * (X + prev);
            double qx = px - h * (ux - fx * Y), qy = py - h * (uy + fy * Xs);
            const double g = std::sqrt(std::fmax(0.0, 1.0 - X * X - Y * Y));
            const double n = std::hypot(qx, qy);
            if (n > g) {
                qx *= g / n;
                qy *= g / n;
            }
            px = qx;
            py = qy;
            sx += px * dX * dY;
            sy += py * dX * dY;
            prev = X;
        }
    }
    // Force / (mu N) = sum p' A' p0 a b / N with p0 = 3N/(2 pi a b).
    *tx = -sx * 3.0 / (2.0 * kPi);
    *ty = sy * 3.0 / (2.0 * kPi);
}

struct Normalised {
    double ux, uy, fy;
};

// Partial and full slip, with spin whose pole lies outside the disk.
const Normalised kCases[] = {{0.05, 0.0, 0.0}, {0.3, -0.2, 0.0}, {1.5, 0.7, 0.0},
                             {-0.4, 0.1, 0.0}, {0.8, 0.1, 0.15},  {0.2, -0.6, -0.05}};

void test_parabolic_mapping_equals_kalkers_call(void**)
{
    for (const double ratio : {0.5, 1.0, 2.0})
        for (const Normalised& c : kCases) {
            const double fx = ratio * c.fy; // FX/FY = b/a
            double tx = 0, ty = 0, kx = 0, ky = 0;
            mapped(c.ux, c.uy, c.fy, ratio, 10, 10, CW_PRESSURE_PARABOLIC, &tx, &ty);
            char msg[128];
            assert_int_equal(cw_fastsim_normalised(c.ux, c.uy, fx, c.fy, 10, 10, 1.0, &kx, &ky,
                                                   msg, sizeof msg),
                             CW_OK);
            assert_close(tx, kx, 1e-12, 1e-15);
            assert_close(ty, ky, 1e-12, 1e-15);
        }
}

void test_elliptic_mapping_equals_direct_march(void**)
{
    for (const double ratio : {0.5, 1.0, 2.0})
        for (const Normalised& c : kCases) {
            double tx = 0, ty = 0, dx = 0, dy = 0;
            mapped(c.ux, c.uy, c.fy, ratio, 12, 9, CW_PRESSURE_ELLIPTIC, &tx, &ty);
            direct_elliptic(c.ux, c.uy, ratio * c.fy, c.fy, 12, 9, &dx, &dy);
            assert_close(tx, dx, 1e-12, 1e-15);
            assert_close(ty, dy, 1e-12, 1e-15);
        }
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_parabolic_mapping_equals_kalkers_call),
        cmocka_unit_test(test_elliptic_mapping_equals_direct_march),
    };
    return cmocka_run_group_tests_name("compat_normalised", tests, nullptr, nullptr);
}
