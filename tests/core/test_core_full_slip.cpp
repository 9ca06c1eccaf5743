// Full slip: |F| -> mu N up to the grid's quadrature of the
// pressure, and F antiparallel to the rigid slip for pure translation.
#include "core_test_support.hpp"
#include "test_support.h"

namespace cw = creepwork;

namespace {

// Discrete load: sum of pz * area over the elements, the grid's quadrature
// of N. In full slip under pure translation every element carries
// |p| = mu pz in one common direction, so |F| = mu * (this sum) exactly.
double discrete_load(const cw::Solver& s)
{
    const auto pz = cwtest::field(s, cw::Field::pz);
    const auto area = cwtest::field(s, cw::Field::area);
    double n = 0.0;
    for (size_t k = 0; k < pz.size(); ++k) n += pz[k] * area[k];
    return n;
}

void force_saturates_at_mu_n(void**)
{
    for (auto grid : {cwtest::kalker_grid(40, 40), cwtest::uniform_grid(40, 40, 1.05)}) {
        for (auto pressure : {cw::PressureKind::parabolic, cw::PressureKind::elliptic}) {
            cw::Solver s(grid);
            cw::ContactInput in = cwtest::steel_contact(2.0);
            in.pressure = pressure;
            in.xi_x = 0.3;  // far beyond saturation (mu N / (G c^2 C11) ~ 4e-3)
            in.xi_y = -0.2;
            const cw::SolveTotals& t = s.solve(in);
            assert_int_equal(t.n_slip, t.n_contact);
            const double F = std::hypot(t.Fx, t.Fy);
            assert_close(F, in.mu * discrete_load(s), 1e-12, 0.0);
            // The quadrature error of the load itself is small and is all
            // that separates |F| from mu N (midpoint rule: < 1 % at 40 x 40).
            assert_close(F, in.mu * in.normal_force, 0.01, 0.0);
            // FASTSIM scales the elastic predictor q ~ -(xi/L1, eta/L2) onto
            // the bound, so with Kalker's three flexibilities the force is
            // antiparallel to (xi/L1, eta/L2), not to the rigid slip -- a
            // known property of FASTSIM (CONTACT blends to one flexibility
            // at large creepage for this reason).
            const double dx = in.xi_x / t.L1, dy = in.xi_y / t.L2;
            assert_close(t.Fx * dy - t.Fy * dx, 0.0, 0.0, 1e-12 * F * std::hypot(dx, dy));
            assert_true(t.Fx * dx + t.Fy * dy < 0.0);
        }
    }
}

// With one flexibility (L1 = L2 = L3, Kalker's original simplified theory)
// the full-slip force is antiparallel to the rigid slip for pure translation.
void force_opposes_rigid_slip_with_one_flexibility(void**)
{
    for (auto grid : {cwtest::kalker_grid(31, 17), cwtest::uniform_grid(30, 30)}) {
        cw::Solver s(grid);
        cw::ContactInput in = cwtest::steel_contact(0.5);
        in.flexibility = cw::FlexibilitySource::given;
        in.L1 = in.L2 = in.L3 = 5e-14;  // m/Pa: about 8a/(3 C11 G) for this contact
        in.xi_x = -0.05;
        in.xi_y = 0.08;
        const cw::SolveTotals& t = s.solve(in);
        assert_int_equal(t.n_slip, t.n_contact);
        const double F = std::hypot(t.Fx, t.Fy), w = std::hypot(in.xi_x, in.xi_y);
        assert_close(t.Fx / F, -in.xi_x / w, 0.0, 1e-13);
        assert_close(t.Fy / F, -in.xi_y / w, 0.0, 1e-13);
    }
}

// Refining the grid drives the quadrature error, hence |F| - mu N, to zero,
// as 1/n^2. doc/validation/index.md quotes 3.6e-4 at 40 x 40 and 2.1e-5 at
// 160 x 160, held to those digits.
void saturation_converges_to_mu_n(void**)
{
    double previous = 1.0;
    for (int n : {10, 20, 40, 80, 160}) {
        cw::Solver s(cwtest::kalker_grid(n, n));
        cw::ContactInput in = cwtest::steel_contact(1.0);
        in.xi_x = 0.5;
        const cw::SolveTotals& t = s.solve(in);
        const double err = std::fabs(std::fabs(t.Fx) - in.mu * in.normal_force) /
                           (in.mu * in.normal_force);
        printf("  %3d x %-3d | |Fx| - mu N | / mu N = %.3e\n", n, n, err);
        assert_true(err < previous);
        if (n == 40) assert_close(err, 3.6e-4, 0.0, 0.05e-4);
        if (n == 160) assert_close(err, 2.1e-5, 0.0, 0.05e-5);
        previous = err;
    }
}

// With spin the tractions turn across the patch: |F| stays below mu N.
void spin_keeps_force_below_mu_n(void**)
{
    cw::Solver s(cwtest::kalker_grid(40, 40));
    cw::ContactInput in = cwtest::steel_contact(1.0);
    in.xi_x = 0.01;
    in.phi = 5.0;  // 1/m; phi*a = 0.03 > xi_x
    const cw::SolveTotals& t = s.solve(in);
    assert_true(std::hypot(t.Fx, t.Fy) < in.mu * discrete_load(s));
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(force_saturates_at_mu_n),
        cmocka_unit_test(force_opposes_rigid_slip_with_one_flexibility),
        cmocka_unit_test(saturation_converges_to_mu_n),
        cmocka_unit_test(spin_keeps_force_below_mu_n),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
