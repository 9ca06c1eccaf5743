/* `creepwork solve --jacobian`, run as a user runs it: the JSON's "jacobian"
 * equals cw_solver_solve_jacobian's matrix for the same inputs (bitwise:
 * both print and read exact doubles), it is the derivative of the JSON's own
 * Fx, Fy, Mz, W_macro (central differences of the CLI's own output, step
 * 1e-5 of a characteristic creepage: 1e-6 relative to the row's scale, as
 * in test_core_jacobian), with rolling towards -x; the text gets a table;
 * without --jacobian there is no "jacobian" key.
 *
 * usage: test_cli_jacobian <creepwork binary> <scratch dir> [cmocka filter] */
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "cli_checks.hpp"
// Last: cmocka defines macros (fail, skip) that clash with the C++ library.
#include "test_support.h"

namespace fs = std::filesystem;
using namespace cwtest;

namespace {

// The contact of the test (SI): partial slip with spin, rolling towards -x,
// elliptic pressure on the uniform grid.
const double kXi[3] = {1e-3, -6e-4, 0.3}; // xi_x, xi_y, phi

Json solve_json(const double xi[3], double N, bool jacobian)
{
    std::vector<std::string> args = {"solve", "--a", "6e-3", "--b", "5e-3", "--N", exact(N),
                                     "--xi-x", exact(xi[0]), "--xi-y", exact(xi[1]), "--spin",
                                     exact(xi[2]), "--rolling-direction", "-1", "--pressure",
                                     "elliptic", "--grid", "uniform", "--nx", "24", "--ny", "20",
                                     "--format", "json"};
    if (jacobian) args.push_back("--jacobian");
    return parse_json(cli_ok(args).out);
}

void json_matches_library_and_differences(void**)
{
    const double N = 80e3;
    const Json j = solve_json(kXi, N, true);
    const char* rows[4] = {"Fx", "Fy", "Mz", "W_macro"};
    const char* cols[4] = {"xi_x", "xi_y", "phi", "N"};

    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_UNIFORM;
    g.nx = 24;
    g.ny = 20;
    cw_solver* s = nullptr;
    assert_int_equal(cw_solver_create(&g, &s, nullptr, 0), CW_OK);
    cw_params p;
    cw_params_init(&p);
    p.a = 6e-3;
    p.b = 5e-3;
    p.normal_force = N;
    p.xi_x = kXi[0];
    p.xi_y = kXi[1];
    p.phi = kXi[2];
    p.rolling_direction = -1;
    p.pressure = CW_PRESSURE_ELLIPTIC;
    double J[CW_JACOBIAN_LEN];
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, &r, J, CW_JACOBIAN_LEN),
                     CW_OK);
    cw_solver_destroy(s);
    for (int row = 0; row < 4; ++row)
        for (int c = 0; c < 4; ++c)
            assert_true(j.at("jacobian").at(rows[row]).num(cols[c]) == J[4 * row + c]);

    // Central differences of the CLI's own totals.
    const double scale[4] = {1e-3, 1e-3, 1e-3 / std::sqrt(6e-3 * 5e-3), N};
    const double rel = 1e-5;
    for (int c = 0; c < 4; ++c) {
        double up[3] = {kXi[0], kXi[1], kXi[2]}, down[3] = {kXi[0], kXi[1], kXi[2]};
        double Nu = N, Nd = N;
        const double h = rel * scale[c];
        if (c < 3) {
            up[c] += h;
            down[c] -= h;
        } else {
            Nu += h;
            Nd -= h;
        }
        const Json ju = solve_json(up, Nu, false), jd = solve_json(down, Nd, false);
        assert_false(ju.has("jacobian"));
        assert_true(ju.num("n_slip") == j.num("n_slip") && jd.num("n_slip") == j.num("n_slip"));
        for (int row = 0; row < 4; ++row) {
            double row_scale = 0.0;
            for (int k = 0; k < 4; ++k) row_scale += std::fabs(J[4 * row + k]) * scale[k];
            const double fd = (ju.num(rows[row]) - jd.num(rows[row])) / (2 * h);
            assert_close(j.at("jacobian").at(rows[row]).num(cols[c]), fd, 0.0,
                         1e-6 * row_scale / scale[c]);
        }
    }
}

void text_has_a_table(void**)
{
    const Run r = cli_ok({"solve", "--a", "6e-3", "--b", "6e-3", "--N", "80e3", "--xi-x", "1e-3",
                          "--jacobian"});
    assert_non_null(std::strstr(r.out.c_str(), "jacobian   (SI)"));
    assert_non_null(std::strstr(r.out.c_str(), "W_macro"));
    // No load: the Jacobian is refused with the library's message (status 1).
    const Run bad = cli({"solve", "--a", "6e-3", "--b", "6e-3", "--N", "0", "--xi-x", "1e-3",
                             "--jacobian"});
    assert_int_not_equal(bad.status, 0);
    assert_non_null(std::strstr(bad.err.c_str(), "normal_force"));
}

} // namespace

int main(int argc, char** argv)
{
    if (!set_up(argc, argv, "test_cli_jacobian", {"creepwork", "scratch"})) return 2;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(json_matches_library_and_differences),
        cmocka_unit_test(text_has_a_table),
    };
    return cw_run_tests(tests, g_tools.test);
}
