/* creepwork solve with a friction law of the slip speed (--friction-law and
 * its terms, --polach MU0,A,B, --friction-law polach --polach-A --polach-B,
 * --friction-speed, Spiryagin's --k0 --alpha-inf --beta, the memory): its
 * JSON equals the C ABI's result for the same cw_params bit for bit (the
 * law at every element in forces mode, at the global slip speed in full
 * mode), CONTACT's tractcurv series 4 at 2 % (tests/data/
 * contact_tractcurv.csv: Fx/(mu_s N) = -0.8444) is met, the exact model
 * with the law gives the C ABI's bits with every output, with friction
 * memory too (--memory-distance, --memory-s0: CONTACT's MEMDST 3 um, MEM_S0
 * 1 mm/s, tests/data/contact_tractcurv_memory.csv), and every bad friction
 * input is refused naming its option.
 *
 * usage: test_cli_friction <creepwork binary> <scratch dir> [cmocka filter] */
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "cli_checks.hpp"
#include "tractcurv_case.h"
// Last: cmocka defines macros (fail, skip) that clash with the C++ library.
#include "test_support.h"

using namespace cwtest;

namespace {

// CONTACT's tractcurv contact on its 48 x 44 grid (as test_capi_friction).
const std::vector<std::string> kTractcurv = {
    "solve", "--format", "json", "--a", "6.304e-3", "--b", "12.61e-3", "--N", "106700",
    "--exact-load", "--grid", "uniform", "--nx", "48", "--ny", "44", "--box-scale", "1.1",
    "--V", "10"};

cw_params tractcurv(double xi_x) { return cw_tractcurv_params(xi_x); }
cw_grid tractcurv_grid() { return cw_tractcurv_grid(); }

void expect_library_bits(const Json& j, const cw_result& lib)
{
    const struct {
        const char* key;
        double value;
    } expect[] = {{"Fx", lib.Fx},           {"Fy", lib.Fy},         {"Mz", lib.Mz},
                  {"mu_static", lib.mu_static}, {"mu_min", lib.mu_min}, {"mu_max", lib.mu_max}};
    for (const auto& e : expect) {
        if (j.num(e.key) != e.value)
            print_error("%s: CLI %.17g, library %.17g\n", e.key, j.num(e.key), e.value);
        assert_true(j.num(e.key) == e.value);
    }
    assert_int_equal(static_cast<int>(j.num("n_slip")), lib.n_slip);
}

void friction_json_matches_library(void**)
{
    // The law at every element, CONTACT's inputs one to one (mu is mu_kin).
    cw_params p = tractcurv(0.004);
    cw_tractcurv_series4(&p, 0);
    Json j = parse_or_fail(cli_ok(with(kTractcurv, {"--xi-x", "0.004", "--friction-law",
                                                    "exponential", "--mu", "0.1368", "--mu-e1",
                                                    "0.2232", "--s-h1", "0.99"}))
                               .out);
    expect_library_bits(j, library_solve(tractcurv_grid(), p, CW_SOLVE_FORCES));
    assert_string_equal(j.at("input").at("friction").at("law").string.c_str(), "exponential");

    // Polach's law two ways: --polach MU0,A,B and --friction-law polach; the
    // library's cw_friction_polach writes the law in both.
    p = tractcurv(0.15);
    assert_int_equal(cw_friction_polach(0.36, 0.38, 0.7, &p, nullptr, 0), CW_OK);
    const cw_result polach = library_solve(tractcurv_grid(), p, CW_SOLVE_FORCES);
    expect_library_bits(
        parse_or_fail(cli_ok(with(kTractcurv, {"--xi-x", "0.15", "--polach", "0.36,0.38,0.7"})).out),
        polach);
    expect_library_bits(parse_or_fail(cli_ok(with(kTractcurv, {"--xi-x", "0.15", "--friction-law",
                                                               "polach", "--mu", "0.36",
                                                               "--polach-A", "0.38",
                                                               "--polach-B", "0.7"}))
                                          .out),
                        polach);
    // Full sliding: Polach's closed form A + (1 - A) exp(-B xi V) within 2e-4.
    assert_close(-polach.Fx / (0.36 * 106700), 0.38 + 0.62 * std::exp(-0.7 * 0.15 * 10), 0.0, 2e-4);

    // Series 4: the global slip speed with Spiryagin's reduction, full mode.
    p = tractcurv(0.02);
    cw_tractcurv_series4(&p, 1);
    const cw_result global = library_solve(tractcurv_grid(), p, CW_SOLVE_FULL);
    j = parse_or_fail(cli_ok(with(kTractcurv, {"--xi-x", "0.02", "--friction-law", "exponential",
                                               "--mu", "0.1368", "--mu-e1", "0.2232", "--s-h1",
                                               "0.99", "--friction-speed", "global", "--k0",
                                               "0.54", "--alpha-inf", "0.02", "--beta", "0.62"}))
                          .out);
    expect_library_bits(j, global);
    assert_true(j.num("W_macro") == global.W_macro);
    assert_close(global.Fx / (0.36 * 106700), -0.8444, 0.0, 0.5e-4 + 6e-5);
}

// The exact model with the law at every element's slip speed (CONTACT's
// exact theory with the exponential law FKIN 0.14, FEXP1 0.19, SABSH1
// 1250 mm/s; tests/data/contact_tractcurv_exponential.csv): its JSON and
// its totals equal the C ABI's full solve bit for bit, --out writes the
// fields, whose work map sums to W_macro, and
// the row xi = 3e-3 meets CONTACT's printed Fx/(mu_s N) = -0.9840 to its digits.
cw_params exact_law_params(double xi_x)
{
    cw_params p = tractcurv(xi_x);
    p.model = CW_MODEL_EXACT;
    p.exact_load = 0;
    p.friction_law = CW_FRICTION_EXPONENTIAL;
    p.mu = 0.14;
    p.mu_e1 = 0.19;
    p.s_h1 = 1.25;
    return p;
}

// The same on the command line, and more.
std::vector<std::string> exact_law_args(const char* xi_x, const std::vector<std::string>& more)
{
    return with({"solve", "--format", "json", "--a", "6.304e-3", "--b", "12.61e-3", "--N",
                 "106700", "--grid", "uniform", "--nx", "48", "--ny", "44", "--box-scale", "1.1",
                 "--V", "10", "--model", "exact", "--xi-x", xi_x, "--friction-law", "exponential",
                 "--mu", "0.14", "--mu-e1", "0.19", "--s-h1", "1.25"},
                more);
}

void exact_law_json_matches_library(void**)
{
    const cw_params p = exact_law_params(3e-3);
    const cw_result lib = library_solve(tractcurv_grid(), p, CW_SOLVE_FULL);
    const std::vector<std::string> args =
        exact_law_args("3e-3", {"--out", path("exact_law"), "--no-plots"});
    const Json j = parse_or_fail(cli_ok(args).out);
    expect_library_bits(j, lib);
    assert_true(j.num("W_macro") == lib.W_macro);
    assert_true(j.num("W_consistent") == lib.W_consistent);
    assert_true(lib.mu_min < lib.mu_max && lib.mu_max < 0.33);
    assert_close(lib.Fx / (0.33 * 106700), -0.9840, 0.0, 0.5e-4);
    // fields.csv's energy-consistent map (exact doubles) sums to W_macro.
    const auto rows = read_csv(path("exact_law/fields.csv"));
    assert_true(rows.size() > 1);
    const size_t col = header_index(rows[0]).at("work_consistent_J_per_m");
    double sum = 0.0;
    for (size_t r = 1; r < rows.size(); ++r) sum += std::strtod(rows[r][col].c_str(), nullptr);
    assert_close(sum, lib.W_macro, 1e-9, 0.0);
}

// Each row's options, added to a partial-slip solve of an 80 kN circle,
// are refused with exit status 2 and a message naming row.names.
template <class Rows>
void expect_each_refused(const Rows& bad)
{
    for (const auto& b : bad) {
        std::vector<std::string> args = {"solve", "--a", "0.006", "--b", "0.006", "--N", "80000",
                                         "--xi-x", "0.01"};
        args.insert(args.end(), b.args.begin(), b.args.end());
        std::string shown = "creepwork";
        for (const std::string& a : args) shown += " " + a;
        expect_refusal(cli(args), 2, b.names, shown);
    }
}

// The exact model with an interface layer (CONTACT's tractcurv layer, G3 =
// 8200 N/mm^2, h = 1.25 mm, and a yield of 150 MPa): the JSON equals the C
// ABI's full solve bit for bit and echoes the layer; bad layer inputs are refused naming their option,
// the layer under FASTSIM naming --layer-h (the library's refusal).
void layer_json_matches_library(void**)
{
    cw_params p = tractcurv(2e-3);
    p.model = CW_MODEL_EXACT;
    p.exact_load = 0;
    p.mu = 0.33;
    p.layer_h = 1.25e-3;
    p.layer_G = 8.2e9;
    p.tau_c0 = 150e6;
    const cw_result lib = library_solve(tractcurv_grid(), p, CW_SOLVE_FULL);
    const std::vector<std::string> base = {
        "solve", "--format", "json", "--a", "6.304e-3", "--b", "12.61e-3", "--N", "106700",
        "--grid", "uniform", "--nx", "48", "--ny", "44", "--box-scale", "1.1", "--mu", "0.33",
        "--model", "exact", "--xi-x", "2e-3", "--layer-h", "1.25e-3", "--layer-G", "8.2e9",
        "--tau-c0", "1.5e8"};
    const Json j = parse_or_fail(cli_ok(base).out);
    expect_library_bits(j, lib);
    assert_true(j.num("W_consistent") == lib.W_consistent);
    assert_true(j.at("input").at("layer").num("layer_h") == 1.25e-3);
    assert_true(j.at("input").at("layer").num("tau_c0") == 150e6);
    // The layer lowers the force below Coulomb's without it.
    p.layer_h = p.tau_c0 = 0.0;
    assert_true(std::fabs(lib.Fx) < std::fabs(library_solve(tractcurv_grid(), p, CW_SOLVE_FORCES).Fx));

    // Millimetres typed as metres and MPa as Pa are warned about by option.
    const Run warned = cli_ok({"solve", "--a", "0.006", "--b", "0.006", "--N", "80000",
                                  "--xi-x", "0.001", "--model", "exact", "--layer-h", "1.25",
                                  "--layer-G", "8200", "--tau-c0", "150"});
    for (const char* option : {"--layer-h = 1.25 m", "--layer-G = 8200 Pa", "--tau-c0 = 150 Pa"})
        assert_true(warned.err.find(option) != std::string::npos);

    const std::vector<std::string> exact = {"--model", "exact"};
    const struct {
        std::vector<std::string> args;
        const char* names;
    } bad[] = {
        {with(exact, {"--layer-h", "-1e-3", "--layer-G", "8e9"}), "--layer-h"},
        {with(exact, {"--layer-h", "1e-3"}), "--layer-G"},
        {with(exact, {"--layer-G", "8e9"}), "--layer-G"},
        {with(exact, {"--tau-c0", "-5"}), "--tau-c0"},
        {with(exact, {"--k-tau", "1e9"}), "--k-tau"},
        {with(exact, {"--tau-c0", "1.5e8", "--k-tau", "inf"}), "--k-tau"},
        {{"--layer-h", "1e-3", "--layer-G", "8e9"}, "--layer-h"},
        {{"--model", "calibrated", "--tau-c0", "1.5e8"}, "--tau-c0"},
    };
    expect_each_refused(bad);
}

// The exact model with friction memory: --memory-distance and --memory-s0
// reach it; its JSON equals the C ABI's solve of the same cw_params bit for
// bit, and the row xi = 4e-3 meets CONTACT's printed Fx/(mu_s N) = -0.9887
// to its digits; with --jacobian every entry is the C ABI's.
void exact_memory_json_matches_library(void**)
{
    cw_params p = exact_law_params(4e-3);
    p.memory_distance = 3e-6;
    p.memory_s0 = 1e-3;
    const cw_result lib = library_solve(tractcurv_grid(), p, CW_SOLVE_FORCES);
    std::vector<std::string> args = exact_law_args(
        "4e-3", {"--G", "82e9", "--nu", "0.28", "--memory-distance", "3e-6", "--memory-s0", "1e-3"});
    expect_library_bits(parse_or_fail(cli_ok(args).out), lib);
    assert_close(lib.Fx / (0.33 * 106700), -0.9887, 0.0, 0.5e-4);
    args.push_back("--jacobian");
    const Json j = parse_or_fail(cli_ok(args).out).at("jacobian");
    cw_solver* s = nullptr;
    const cw_grid g = tractcurv_grid();
    assert_int_equal(cw_solver_create(&g, &s, nullptr, 0), CW_OK);
    double J[CW_JACOBIAN_LEN];
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, &r, J, CW_JACOBIAN_LEN), CW_OK);
    cw_solver_destroy(s);
    const char* rows[4] = {"Fx", "Fy", "Mz", "W_macro"};
    const char* cols[4] = {"xi_x", "xi_y", "phi", "N"};
    for (int row = 0; row < 4; ++row)
        for (int c = 0; c < 4; ++c) assert_true(j.at(rows[row]).num(cols[c]) == J[4 * row + c]);
}

void bad_friction_inputs_are_named(void**)
{
    const std::vector<std::string> law = {"--friction-law", "exponential", "--mu-e1", "0.2",
                                          "--s-h1", "1"};
    const struct {
        std::vector<std::string> args;
        const char* names;
    } bad[] = {
        {with(law, {"--V", "0"}), "--V"},
        {{"--friction-law", "exponential", "--mu-e1", "0.2", "--s-h1", "1"}, "--V"},
        {{"--friction-law", "stribeck", "--V", "10"}, "--friction-law"},
        {with(law, {"--V", "10", "--mu-e1", "-0.2"}), "--mu-e1"},
        {{"--friction-law", "rational", "--mu-e1", "0.2", "--V", "10"}, "--s-h1"},
        {{"--mu-e1", "0.2", "--V", "10"}, "--mu-e1"},
        {with(law, {"--V", "10", "--polach-A", "0.4"}), "--polach-A"},
        {{"--friction-law", "polach", "--polach-A", "0.4", "--V", "10"}, "--polach-B"},
        {{"--friction-law", "polach", "--polach-A", "1.4", "--polach-B", "0.7", "--V", "10"},
         "--polach-A"},
        {{"--polach", "0.36,0.38", "--V", "10"}, "--polach"},
        {{"--polach", "0.36,0.38,0", "--V", "10"}, "--polach"},
        {{"--polach", "0.36,0.38,0.7"}, "--V"},
        {{"--polach", "0.36,0.38,0.7", "--mu", "0.3", "--V", "10"}, "--polach/--mu"},
        {with(law, {"--V", "10", "--k0", "0.5"}), "--k0"},
        {with(law, {"--V", "10", "--friction-speed", "global", "--alpha-inf", "2"}),
         "--alpha-inf"},
        {with(law, {"--V", "10", "--friction-speed", "global", "--memory-distance", "1e-3"}),
         "--memory-distance"},
        {with(law, {"--V", "10", "--memory-s0", "-1"}), "--memory-s0"},
        {with(law, {"--V", "10", "--model", "calibrated"}), "--friction-law"},
    };
    expect_each_refused(bad);
}

} // namespace

int main(int argc, char** argv)
{
    if (!set_up(argc, argv, "test_cli_friction", {"creepwork", "scratch"})) return 2;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(friction_json_matches_library),
        cmocka_unit_test(exact_law_json_matches_library),
        cmocka_unit_test(exact_memory_json_matches_library),
        cmocka_unit_test(bad_friction_inputs_are_named),
        cmocka_unit_test(layer_json_matches_library),
    };
    return cw_run_tests(tests, g_tools.test);
}
