// Tests of `creepwork wheelrail`, run as a user runs it: its JSON (the keys
// of its help text) equals what the C ABI gives for the same wheel, and its
// forces are CONTACT's module-1 ones on the Manchester benchmark (case
// left wheel at y_ws = 6.5 mm: FN 10010 N, FX 2260 N, FS -1979 N,
// p_max 637.0 N/mm^2, z_ws -3.046 mm; CONTACT's
// examples/mbench_a22_left.ref_out) within 1 % of the load, p_max within
// 3 %; the fast model comes within 3 % of mu Fz of the exact one where
// the validation measured it (doc/validation/manchester.md: case at
// 3 mm); implausible units are warned about; bad inputs fail cleanly.
//
// usage: test_cli_wheelrail <creepwork binary> <scratch dir> <profile dir> [cmocka filter]
#include <cmath>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "cli_checks.hpp"
// Last: cmocka defines macros (fail, skip) that clash with the C++ library.
#include "test_support.h"

namespace {

std::string g_data;

std::vector<std::string> benchmark_args()
{
    return {"wheelrail", "--wheel-profile", g_data + "/MBench_S1002_v3.prw", "--rail-profile",
            g_data + "/MBench_UIC60_v3.prr", "--side", "left", "--y-shift", "6.5e-3", "--yaw", "0.0156",
            "--roll", "-0.004376", "--Fz", "1e4", "--V", "2", "--pitch-rate", "-4.2748834"};
}

void json_matches_library(void**)
{
    const cwtest::Run r = cwtest::cli_ok(cwtest::with(benchmark_args(), {"--format", "json"}));
    const cwtest::Json j = cwtest::parse_json(r.out);
    const cwtest::Json& list = j.at("patches");
    assert_int_equal(list.array.size(), 1);
    const cwtest::Json& q = list.array[0];
    for (const char* key : {"y_contact_rail", "z_contact_rail", "contact_angle", "xi_x", "xi_y", "phi", "Fn",
                            "Fx", "Fs", "Mn", "p_max", "n_contact", "n_adhesion", "n_slip"})
        assert_true(q.has(key));
    // CONTACT's module 1 (header comment)
    assert_close(q.num("Fn"), 10010.0, 0, 100);
    assert_close(q.num("Fx"), 2260.0, 0, 100);
    assert_close(q.num("Fs"), -1979.0, 0, 100);
    assert_close(q.num("p_max"), 637.0e6, 0.03, 0);
    assert_close(j.num("z_ws"), -3.046e-3, 0, 1e-6);
    assert_close(j.at("total_rail").num("Fz"), 1e4, 1e-6, 0);

    // the library, through the C ABI, for the same wheel
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    p.side = CW_WHEELRAIL_LEFT;
    cw_wheelrail* w = nullptr;
    assert_int_equal(cw_wheelrail_create(&p, (g_data + "/MBench_UIC60_v3.prr").c_str(),
                                         (g_data + "/MBench_S1002_v3.prw").c_str(), &w, nullptr, 0),
                     CW_OK);
    cw_wheelrail_motion m;
    cw_wheelrail_motion_init(&m);
    m.y = 6.5e-3;
    m.yaw = 0.0156;
    m.roll = -0.004376;
    m.vs = 2.0;
    m.vpitch = -4.2748834;
    cw_wheelrail_totals t;
    cw_wheelrail_totals_init(&t);
    assert_int_equal(cw_wheelrail_solve(w, &m, CW_WHEELRAIL_FORCE, 1e4, &t), CW_OK);
    cw_wheelrail_patch pa;
    cw_wheelrail_patch_init(&pa);
    assert_int_equal(cw_wheelrail_get_patch(w, 0, &pa), CW_OK);
    // JSON prints doubles exactly: the same numbers
    assert_close(j.num("z_ws"), t.z, 1e-15, 0);
    assert_close(j.at("total_rail").num("Fy"), t.Fy, 1e-15, 0);
    assert_close(q.num("Fn"), pa.Fn, 1e-15, 0);
    assert_close(q.num("Fs"), pa.Fs, 1e-15, 0);
    assert_close(q.num("Mn"), pa.Mn, 1e-15, 0);
    assert_close(q.num("xi_y"), pa.ceta, 1e-15, 0);
    assert_close(q.num("phi"), pa.cphi, 1e-15, 0);
    assert_close(q.num("y_contact_rail"), pa.y_contact_rail, 1e-15, 0);
    assert_int_equal(static_cast<int>(q.num("n_slip")), pa.n_slip);
    cw_wheelrail_destroy(w);

    const cwtest::Run text = cwtest::cli_ok(benchmark_args());
    cwtest::expect_contains(text.out, "wheelset height z_ws = -3.04");
    cwtest::expect_contains(text.out, "total on the rail");
}

// Case at y_ws = 3 mm, the right wheel (CONTACT's
// examples/mbench_a22_right.inp: yaw 7.2 mrad, roll -0.1803 mrad, V 2 m/s).
std::vector<std::string> tread_args()
{
    return {"wheelrail", "--wheel-profile", g_data + "/MBench_S1002_v3.prw", "--rail-profile",
            g_data + "/MBench_UIC60_v3.prr", "--y-shift", "3e-3", "--yaw", "0.0072", "--roll",
            "-1.803e-4", "--Fz", "1e4", "--V", "2", "--pitch-rate", "-4.34515"};
}

void fast_model_near_exact(void**)
{
    const cwtest::Json exact =
        cwtest::parse_json(cwtest::cli_ok(cwtest::with(tread_args(), {"--format", "json"})).out);
    const cwtest::Json fast = cwtest::parse_json(
        cwtest::cli_ok(cwtest::with(tread_args(), {"--model", "fast", "--format", "json"})).out);
    assert_true(exact.at("model").string == "exact");
    assert_true(fast.at("model").string == "fast");
    assert_int_equal(fast.at("patches").array.size(), 1);
    assert_int_equal(exact.at("patches").array.size(), 1);
    // The fast model's accuracy at 3 mm: within 3 % of mu Fz = 3 kN
    // (doc/validation/manchester.md, the fast model against the exact one).
    const cwtest::Json& e = exact.at("patches").array[0];
    const cwtest::Json& f = fast.at("patches").array[0];
    for (const char* key : {"Fn", "Fx", "Fs"}) assert_close(f.num(key), e.num(key), 0, 0.03 * 0.3 * 1e4);
    // ... yet a different model: its own numbers, not the exact model's.
    assert_true(f.num("Fx") != e.num("Fx"));
    assert_close(fast.at("total_rail").num("Fz"), 1e4, 1e-6, 0);
    cwtest::expect_contains(cwtest::cli_ok(cwtest::with(tread_args(), {"--model", "fast"})).out,
                            "model fast: FASTSIM with the semi-Hertzian normal problem");
}

void warns_about_implausible_units(void**)
{
    std::vector<std::string> args = benchmark_args();
    args[14] = "10"; // --Fz in kN
    const cwtest::Run k = cwtest::cli_ok(cwtest::with(args, {"--G", "82000"}));
    cwtest::expect_contains(k.err, "warning: --Fz = 10 N is implausible");
    cwtest::expect_contains(k.err, "warning: --G = 82000 Pa is implausible");
}

void bad_inputs_fail_cleanly(void**)
{
    using cwtest::cli;
    using cwtest::expect_refusal;
    expect_refusal(cli({"wheelrail", "--rail-profile", g_data + "/MBench_UIC60_v3.prr", "--Fz", "1e4"}), 2,
                   "--wheel-profile", "no wheel");
    expect_refusal(cli({"wheelrail", "--wheel-profile", "no/such.prw", "--rail-profile",
                        g_data + "/MBench_UIC60_v3.prr", "--Fz", "1e4"}),
                   2, "no/such.prw", "missing file");
    expect_refusal(cli(cwtest::with(benchmark_args(), {"--mu", "-1"})), 2, "mu", "negative mu");
    expect_refusal(cli(cwtest::with(benchmark_args(), {"--side", "middle"})), 2, "--side", "bad side");
    expect_refusal(cli(cwtest::with(benchmark_args(), {"--z", "0"})), 2, "--z", "unknown option");
    expect_refusal(cli(cwtest::with(benchmark_args(), {"--dx", "0.2"})), 2, "--dx", "dx in mm");
    expect_refusal(cli(cwtest::with(benchmark_args(), {"--model", "kalker"})), 2, "--model",
                   "unknown model");
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 4) return 2;
    g_data = argv[3];
    // set_up reads the creepwork binary and the scratch directory; the
    // profile directory is ours, the filter follows it
    std::vector<char*> args(argv, argv + argc);
    args.erase(args.begin() + 3);
    if (!cwtest::set_up(static_cast<int>(args.size()), args.data(), "test_cli_wheelrail", {"creepwork", "scratch"}))
        return 2;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(json_matches_library),
        cmocka_unit_test(fast_model_near_exact),
        cmocka_unit_test(warns_about_implausible_units),
        cmocka_unit_test(bad_inputs_fail_cleanly),
    };
    return cw_run_tests(tests, cwtest::g_tools.test);
}
