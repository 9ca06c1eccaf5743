// The calibrated model's Jacobian (core/calibrated/calibrated_model.cpp,
// core/calibrated/march_directional.hpp) against independent numbers:
//  - central differences of the solver's own totals, step study 1e-2 ...
//    1e-8 of each input's scale (truncation falls as h^2, roundoff rises as
//    eps/h): the best step among those that flip no element is held to 1e-6
//    relative to the row's scale, on partial-slip contacts where every
//    calibrated knob moves (table factors, equalisation, lateral-moment fade,
//    edge gain, bound blend), both grids, both rolling directions, a/b 0.3 to
//    3, and near full sliding;
//  - the linear limit: in full adhesion the table's knobs are at rest and the
//    model gives Kalker's C11, C22, C23 for the forces (1.0002 of them on the
//    50 x 50 strip grid, test_core_calibrated) and Kalker's C23, C33 for the
//    moments (within 0.2 %), and dF/dN = 0 (no element slips: the forces do
//    not depend on the bound);
//  - the totals and every field of a solve with the Jacobian are bitwise
//    those of a plain solve, and every kernel gives bitwise the same matrix;
//  - the W_macro row is paper eq. 34's.
#include <algorithm>
#include <array>
#include <cstring>
#include <cstdio>
#include <vector>

#include "calibrated/calibration_table.hpp"
#include "contact/error.hpp"
#include "contact/kalker_coefficients.hpp"
#include "core_test_support.hpp"
#include "jacobian_step_study.hpp"
#include "test_support.h"

namespace cw = creepwork;

namespace {

// Each input's scale: its saturation creepage (normalised creepage 1), N.
std::array<double, 4> input_scales(const cw::ContactInput& in)
{
    const cw::CreepCoefficients C = cw::kalker_coefficients(in.a / in.b, in.nu);
    const double muN = in.mu * in.normal_force, c2 = in.a * in.b, c = std::sqrt(c2);
    return {muN / (in.G * c2 * C.C11), muN / (in.G * c2 * C.C22), muN / (in.G * c2 * c * C.C23),
            in.normal_force};
}

// The step study (jacobian_step_study.hpp), steps 1e-2 ... 1e-8 of the
// input scale.
double step_study(const char* label, cw::Solver& s, const cw::ContactInput& in,
                  const cw::Jacobian& J)
{
    const int slips = s.solve(in, cw::SolveMode::forces_only).n_slip;
    return cwtest::jacobian_step_study(label, 40, s, in, J, input_scales(in), slips, 1e-2, 1e-8);
}

cw::ContactInput calibrated_contact(double a_over_b, double sx, double sy, double sphi)
{
    cw::ContactInput in = cwtest::steel_contact(a_over_b);
    in.model = cw::ModelKind::calibrated;
    const auto scale = input_scales(in);
    in.xi_x = sx * scale[0];
    in.xi_y = sy * scale[1];
    in.phi = sphi * scale[2];
    return in;
}

void matches_central_differences(void**)
{
    struct Case {
        const char* label;
        cw::GridSpec grid;
        cw::ContactInput in;
    };
    cw::ContactInput backwards = calibrated_contact(1.0, 0.3, -0.2, 0.25);
    backwards.rolling_direction = -1;
    const Case cases[] = {
        {"uniform 24x24 a/b 1, all three 40 %", cwtest::uniform_grid(24, 24),
         calibrated_contact(1.0, 0.3, -0.2, 0.2)},
        {"uniform 24x24 a/b 3, spin + xi_y 70 %", cwtest::uniform_grid(24, 24),
         calibrated_contact(3.0, 0.0, 0.5, -0.5)},
        {"uniform 20x28 a/b 0.3, xi_x + xi_y 60 %", cwtest::uniform_grid(20, 28),
         calibrated_contact(0.3, -0.4, 0.45, 0.0)},
        {"strips 20x20 a/b 1, spin alone 50 %", cwtest::kalker_grid(20, 20),
         calibrated_contact(1.0, 0.0, 0.0, 0.5)},
        {"uniform 24x24 backwards, all three", cwtest::uniform_grid(24, 24), backwards},
        {"uniform 16x16 a/b 2, all three 300 %", cwtest::uniform_grid(16, 16),
         calibrated_contact(2.0, 2.0, 1.5, 1.5)},
    };
    for (const Case& k : cases) {
        cw::Solver s(k.grid);
        cw::Jacobian J;
        s.solve_jacobian(k.in, cw::SolveMode::forces_only, J);
        // The knobs really move here (else this would test FASTSIM's march).
        const cw::CalibrationParams p = cw::calibration_for(k.in);
        assert_true(p.bound_blend > 0.01 && p.equalise > 0.01 && p.edge_gain != 0.0);
        assert_true(step_study(k.label, s, k.in, J) <= 1e-6);
    }
}

void linear_limit_is_kalkers(void**)
{
    constexpr double kTiny = 1e-9; // creepage: no slip on a 50 x 50 grid
    for (double ratio : {0.5, 1.0, 2.0}) {
        cw::Solver s(cwtest::kalker_grid(50, 50));
        cw::ContactInput in = cwtest::steel_contact(ratio);
        in.model = cw::ModelKind::calibrated;
        const double c = std::sqrt(in.a * in.b), G = in.G;
        in.xi_x = kTiny;
        in.xi_y = -kTiny;
        in.phi = kTiny / c;
        cw::Jacobian J;
        const cw::SolveTotals t = s.solve_jacobian(in, cw::SolveMode::forces_only, J);
        assert_int_equal(t.n_slip, 0);
        const double r11 = -J.d[cw::jac_Fx][cw::jac_xi_x] / (G * c * c * t.C11);
        const double r22 = -J.d[cw::jac_Fy][cw::jac_xi_y] / (G * c * c * t.C22);
        const double r23 = -J.d[cw::jac_Fy][cw::jac_phi] / (G * c * c * c * t.C23);
        const double m23 = J.d[cw::jac_Mz][cw::jac_xi_y] / (G * c * c * c * t.C23);
        const double m33 = -J.d[cw::jac_Mz][cw::jac_phi] / (G * c * c * c * c * t.C33);
        printf("  a/b %.1f: C11 %.5f C22 %.5f C23 %.5f Mz C23 %.5f Mz C33 %.5f dFx/dN %.1e\n",
               ratio, r11, r22, r23, m23, m33, J.d[cw::jac_Fx][cw::jac_N]);
        assert_close(r11, 1.0002, 0.0, 5e-5);
        assert_close(r22, 1.0002, 0.0, 5e-5);
        assert_close(r23, 1.0002, 0.0, 5e-5);
        assert_close(m23, 1.0, 0.0, 2e-3);
        assert_close(m33, 1.0, 0.0, 2e-3);
        // Cross terms of Kalker's linear theory are zero: Fx by eta, phi. The
        // table's knobs grow linearly with the normalised creepage s (~1e-5
        // here), so the model's cross terms are O(s) of the diagonal ones
        // (measured <= 3e-8).
        const double s11 = G * c * c * t.C11;
        assert_close(J.d[cw::jac_Fx][cw::jac_xi_y], 0.0, 0.0, 1e-6 * s11);
        assert_close(J.d[cw::jac_Fx][cw::jac_phi], 0.0, 0.0, 1e-6 * s11 * c);
        for (int r = 0; r < 3; ++r) assert_close(J.d[r][cw::jac_N], 0.0, 0.0, 1e-9);
    }
}

void totals_and_fields_are_a_plain_solves(void**)
{
    const cw::GridSpec grid = cwtest::uniform_grid(30, 30);
    const cw::ContactInput in = calibrated_contact(1.5, 0.3, 0.4, -0.3);
    cw::Solver plain(grid), with(grid);
    const cw::SolveTotals a = plain.solve(in, cw::SolveMode::full);
    cw::Jacobian J;
    const cw::SolveTotals b = with.solve_jacobian(in, cw::SolveMode::full, J);
    const double ta[] = {a.Fx, a.Fy, a.Mz, a.W_macro, a.W_consistent, a.W_micro_paper};
    const double tb[] = {b.Fx, b.Fy, b.Mz, b.W_macro, b.W_consistent, b.W_micro_paper};
    for (int k = 0; k < 6; ++k) assert_true(ta[k] == tb[k]);
    assert_int_equal(a.n_slip, b.n_slip);
    const int n = grid.nx * grid.ny;
    for (cw::Field f : {cw::Field::px, cw::Field::py, cw::Field::sx, cw::Field::sy,
                        cw::Field::work_consistent, cw::Field::work_paper}) {
        std::vector<double> fa(n), fb(n);
        cw::export_field(plain.solved(), f, fa.data());
        cw::export_field(with.solved(), f, fb.data());
        assert_true(fa == fb);
    }
    // W_macro = -(xi_x Fx + xi_y Fy + phi Mz), eq. 34: its row.
    for (int c = 0; c < 4; ++c) {
        const double own[4] = {b.Fx, b.Fy, b.Mz, 0.0};
        const double expected = -(own[c] + in.xi_x * J.d[0][c] + in.xi_y * J.d[1][c] +
                                  in.phi * J.d[2][c]);
        assert_close(J.d[cw::jac_W][c], expected, 1e-12, 1e-300);
    }
}

void every_kernel_gives_the_same_matrix(void**)
{
    const cw::GridSpec grid = cwtest::uniform_grid(21, 19); // strips not a multiple of 8
    const cw::ContactInput in = calibrated_contact(0.7, -0.5, 0.3, 0.4);
    cw::Jacobian reference;
    bool first = true;
    for (cw::KernelIsa isa : {cw::KernelIsa::baseline, cw::KernelIsa::avx2, cw::KernelIsa::avx512}) {
        if (!cw::kernel_isa_supported(isa)) continue;
        cw::Solver s(grid);
        s.calibrated_model().set_kernel_isa(isa);
        cw::Jacobian J;
        s.solve_jacobian(in, cw::SolveMode::forces_only, J);
        if (first) reference = J;
        first = false;
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) assert_true(J.d[r][c] == reference.d[r][c]);
    }
}

void zero_normal_force_is_refused(void**)
{
    cw::Solver s(cwtest::uniform_grid(10, 10));
    cw::ContactInput in = calibrated_contact(1.0, 0.2, 0.0, 0.0);
    in.normal_force = 0.0;
    cw::Jacobian J;
    try {
        s.solve_jacobian(in, cw::SolveMode::forces_only, J);
        fail_msg("normal_force = 0 was accepted");
    } catch (const cw::Error& e) {
        assert_int_equal(int(e.kind()), int(cw::ErrorKind::invalid_input));
        assert_non_null(std::strstr(e.what(), "normal_force"));
    }
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(matches_central_differences),
        cmocka_unit_test(linear_limit_is_kalkers),
        cmocka_unit_test(totals_and_fields_are_a_plain_solves),
        cmocka_unit_test(every_kernel_gives_the_same_matrix),
        cmocka_unit_test(zero_normal_force_is_refused),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
