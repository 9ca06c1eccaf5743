/* creepwork campaign with friction-law columns (friction_law, mu_e1, s_h1,
 * friction_speed, k0, alpha_inf, beta, polach_A, polach_B, V): each row's
 * results.csv numbers are the C ABI's for the same cw_params, printed with
 * the shortest digits that read back (every row of the full-mode campaign
 * in full mode: the law at every element, the global slip speed, Polach's
 * law written by cw_friction_polach, the exact model's law), CONTACT's tractcurv
 * series 4 at 2 % (Fx/(mu_s N) = -0.8444), and a bad friction cell fails
 * its row alone, naming the column.
 *
 * usage: test_campaign_friction <creepwork> <mpirun> <scratch dir> [test] */
#include <cmath>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "../../cli/json.hpp"
#include "campaign_test_support.hpp"
#include "tractcurv_case.h"
// Last: cmocka defines macros (fail, skip) that clash with the C++ library.
#include "test_support.h"

using namespace cwtest;

namespace {

void friction_rows_match_library(void** state)
{
    (void)state;
    const std::string common = "uniform,48,44,1.1,6.304e-3,12.61e-3,106700,1,";
    std::string text = "id,grid,nx,ny,box_scale,a,b,N,exact_load,V,xi_x,friction_law,mu,mu_e1,"
                       "s_h1,friction_speed,k0,alpha_inf,beta,polach_A,polach_B,model\n";
    text += "local," + common + "10,0.004,exponential,0.1368,0.2232,0.99,,,,,,,\n";
    text += "global," + common + "10,0.02,exponential,0.1368,0.2232,0.99,global,0.54,0.02,0.62,,,\n";
    text += "polach," + common + "10,0.15,polach,0.36,,,,,,,0.38,0.7,\n";
    text += "no_V," + common + "0,0.02,exponential,0.1368,0.2232,0.99,,,,,,,\n";
    text += "bad_term," + common + "10,0.02,exponential,0.1368,-0.2,0.99,,,,,,,\n";
    text += "exact," + common + "10,0.003,exponential,0.14,0.19,1.25,,,,,,,exact\n";
    write_text(path("in.csv"), text);
    const Run r = expect_status(
        campaign(0, {"--in", path("in.csv"), "--out", path("out"), "--threads", "1"}), 0);
    expect_contains(r.err, "6 rows: 4 solved, 2 failed");

    const auto records = read_csv(path("out/results.csv"));
    assert_int_equal(records.size(), 7);
    const auto idx = header_index(records[0]);
    const auto cell = [&](size_t k, const char* column) { return records[k][idx.at(column)]; };

    const cw_grid g = cw_tractcurv_grid();
    cw_params local = cw_tractcurv_params(0.004);
    cw_tractcurv_series4(&local, 0);
    cw_params global = cw_tractcurv_params(0.02);
    cw_tractcurv_series4(&global, 1);
    cw_params polach = cw_tractcurv_params(0.15);
    assert_int_equal(cw_friction_polach(0.36, 0.38, 0.7, &polach, nullptr, 0), CW_OK);
    cw_params exact = cw_tractcurv_params(0.003);
    exact.model = CW_MODEL_EXACT;
    exact.friction_law = CW_FRICTION_EXPONENTIAL;
    exact.mu = 0.14;
    exact.mu_e1 = 0.19;
    exact.s_h1 = 1.25;
    const struct {
        size_t row;
        cw_result lib;
    } expect[] = {{1, library_solve(g, local, CW_SOLVE_FULL)},
                  {2, library_solve(g, global, CW_SOLVE_FULL)},
                  {3, library_solve(g, polach, CW_SOLVE_FULL)},
                  {6, library_solve(g, exact, CW_SOLVE_FULL)}};
    for (const auto& e : expect) {
        assert_string_equal(cell(e.row, "status").c_str(), "ok");
        const struct {
            const char* column;
            double value;
        } numbers[] = {{"Fx", e.lib.Fx},         {"Mz", e.lib.Mz},
                       {"W_macro", e.lib.W_macro}, {"mu_static", e.lib.mu_static},
                       {"mu_min", e.lib.mu_min},  {"mu_max", e.lib.mu_max}};
        for (const auto& n : numbers)
            assert_string_equal(cell(e.row, n.column).c_str(),
                                cwcli::shortest_exact(n.value).c_str());
    }
    assert_close(std::stod(cell(2, "Fx")) / (0.36 * 106700), -0.8444, 0.0, 0.5e-4 + 6e-5);
    assert_close(-std::stod(cell(3, "Fx")) / (0.36 * 106700),
                 0.38 + 0.62 * std::exp(-0.7 * 0.15 * 10), 0.0, 2e-4);
    assert_string_equal(cell(4, "status").c_str(), "CW_ERR_INVALID_INPUT");
    expect_contains(cell(4, "message"), "column V");
    assert_string_equal(cell(5, "status").c_str(), "CW_ERR_INVALID_INPUT");
    expect_contains(cell(5, "message"), "column mu_e1");
    assert_true(std::stod(cell(6, "W_macro")) > 0.0);
}

} // namespace

int main(int argc, char** argv)
{
    if (!set_up(argc, argv, "test_campaign_friction", {"creepwork", "mpirun", "scratch"}))
        return 2;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(friction_rows_match_library),
    };
    return cw_run_tests(tests, g_tools.test);
}
