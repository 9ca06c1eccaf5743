// Tests of `creepwork wheelrail`, run as a user runs it: its JSON (the keys
// of its help text) equals what the C ABI gives for the same wheel, and its
// forces are CONTACT's module-1 ones on the Manchester benchmark (case
// left wheel at y_ws = 6.5 mm: FN 10010 N, FX 2260 N, FS -1979 N,
// p_max 637.0 N/mm^2, z_ws -3.046 mm; CONTACT's
// examples/mbench_a22_left.ref_out) within 1 % of the load, p_max within
// 3 %; the fast model comes within 3 % of mu Fz of the exact one where
// the validation measured it (doc/validation/manchester.md: case at
// 3 mm); --out writes data that add up to the printed forces and lie on the
// profiles, and pictures; implausible units are warned about; bad inputs
// fail cleanly.
//
// usage: test_cli_wheelrail <creepwork binary> <scratch dir> <profile dir> [cmocka filter]
#include <algorithm>
#include <cmath>
#include <fstream>
#include <cstdlib>
#include <filesystem>
#include <map>
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

// The benchmark_args() wheel through the C ABI (params: the defaults; the
// left side always), solved for Fz = 10 kN at forward speed vs and pitch
// rate vpitch.
cw_wheelrail* solved_benchmark(cw_wheelrail_totals& t, const cw_wheelrail_params* params = nullptr,
                               double vs = 2.0, double vpitch = -4.2748834)
{
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    if (params) p = *params;
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
    m.vs = vs;
    m.vpitch = vpitch;
    cw_wheelrail_totals_init(&t);
    assert_int_equal(cw_wheelrail_solve(w, &m, CW_WHEELRAIL_FORCE, 1e4, &t), CW_OK);
    return w;
}

void json_matches_library(void**)
{
    const cwtest::Run r = cwtest::cli_ok(cwtest::with(benchmark_args(), {"--format", "json"}));
    const cwtest::Json j = cwtest::parse_json(r.out);
    const cwtest::Json& list = j.at("patches");
    assert_int_equal(list.array.size(), 1);
    const cwtest::Json& q = list.array[0];
    for (const char* key : {"y_contact_rail", "z_contact_rail", "contact_angle", "cksi", "ceta", "cphi",
                            "Fn", "Fx_rail", "Fs_rail", "Mn_rail", "p_max", "n_contact", "n_adhesion",
                            "n_slip"})
        assert_true(q.has(key));
    // creepwork's own keys, of the opposite sign, are not used for CONTACT's values
    for (const char* key : {"xi_x", "xi_y", "phi", "Fx", "Fs", "Mn"}) assert_false(q.has(key));
    // CONTACT's module 1 (header comment)
    assert_close(q.num("Fn"), 10010.0, 0, 100);
    assert_close(q.num("Fx_rail"), 2260.0, 0, 100);
    assert_close(q.num("Fs_rail"), -1979.0, 0, 100);
    assert_close(q.num("p_max"), 637.0e6, 0.03, 0);
    assert_close(j.num("z_ws"), -3.046e-3, 0, 1e-6);
    assert_close(j.at("total_rail").num("Fz"), 1e4, 1e-6, 0);

    // the library, through the C ABI, for the same wheel
    cw_wheelrail_totals t;
    cw_wheelrail* w = solved_benchmark(t);
    cw_wheelrail_patch pa;
    cw_wheelrail_patch_init(&pa);
    assert_int_equal(cw_wheelrail_get_patch(w, 0, &pa), CW_OK);
    // JSON prints doubles exactly: the same numbers
    assert_close(j.num("z_ws"), t.z, 1e-15, 0);
    assert_close(j.at("total_rail").num("Fy"), t.Fy, 1e-15, 0);
    assert_close(q.num("Fn"), pa.Fn, 1e-15, 0);
    assert_close(q.num("Fx_rail"), pa.Fx, 1e-15, 0);
    assert_close(q.num("Fs_rail"), pa.Fs, 1e-15, 0);
    assert_close(q.num("Mn_rail"), pa.Mn, 1e-15, 0);
    assert_close(q.num("cksi"), pa.cksi, 1e-15, 0);
    assert_close(q.num("ceta"), pa.ceta, 1e-15, 0);
    assert_close(q.num("cphi"), pa.cphi, 1e-15, 0);
    assert_close(q.num("y_contact_rail"), pa.y_contact_rail, 1e-15, 0);
    assert_int_equal(static_cast<int>(q.num("n_slip")), pa.n_slip);
    cw_wheelrail_destroy(w);

    const cwtest::Run text = cwtest::cli_ok(benchmark_args());
    cwtest::expect_contains(text.out, "wheelset height z_ws = -3.04");
    cwtest::expect_contains(text.out, "total on the rail");
}

// --temperature: each patch's hottest rail and wheel element equal, bitwise,
// to cw_temperature on the patch's solver (cw_wheelrail_patch_solver) at
// the patch's veloc, rolling direction 0 (the patch's): the same bits as
// the patch's direction given, the other refused; a speed is needed.
void temperature_matches_library(void**)
{
    const cwtest::Run r = cwtest::cli_ok(cwtest::with(
        benchmark_args(), {"--temperature", "--T0-1", "10", "--T0-2", "30", "--format", "json"}));
    const cwtest::Json j = cwtest::parse_json(r.out);
    const cwtest::Json& q = j.at("patches").array.at(0);
    cw_wheelrail_totals t;
    cw_wheelrail* w = solved_benchmark(t);
    cw_wheelrail_patch pa;
    cw_wheelrail_patch_init(&pa);
    assert_int_equal(cw_wheelrail_get_patch(w, 0, &pa), CW_OK);
    const cw_solver* view = cw_wheelrail_patch_solver(w, 0);
    assert_non_null(view);
    cw_temperature* temperature = nullptr;
    assert_int_equal(cw_temperature_create(view, &temperature), CW_OK);
    cw_temperature_params tp;
    cw_temperature_params_init(&tp);
    tp.T0_1 = 10;
    tp.T0_2 = 30;
    tp.rolling_speed = pa.veloc;
    tp.rolling_direction = 0;
    cw_temperature_result from_patch, given;
    cw_temperature_result_init(&from_patch);
    cw_temperature_result_init(&given);
    assert_int_equal(cw_temperature_compute(temperature, view, &tp, &from_patch), CW_OK);
    assert_true(q.num("T_max_1") == from_patch.T_max_1);
    assert_true(q.num("T_max_2") == from_patch.T_max_2);
    assert_true(from_patch.T_max_1 > 20.0); /* in slip: the frictional power heats */
    tp.rolling_speed = 0; /* a patch view has no cw_params.V */
    assert_int_equal(cw_temperature_compute(temperature, view, &tp, &given), CW_ERR_INVALID_INPUT);
    cwtest::expect_contains(cw_temperature_last_error(temperature), "rolling_speed");
    tp.rolling_speed = pa.veloc;
    int refused = 0;
    for (int d : {1, -1}) {
        tp.rolling_direction = d;
        const int st = cw_temperature_compute(temperature, view, &tp, &given);
        if (st == CW_OK) {
            assert_memory_equal(&from_patch, &given, sizeof given);
        } else {
            assert_int_equal(st, CW_ERR_INVALID_INPUT);
            cwtest::expect_contains(cw_temperature_last_error(temperature), "rolling_direction");
            ++refused;
        }
    }
    assert_int_equal(refused, 1);
    cw_temperature_destroy(temperature);
    cw_wheelrail_destroy(w);
    const cwtest::Run text = cwtest::cli_ok(cwtest::with(benchmark_args(), {"--temperature"}));
    cwtest::expect_contains(text.out, "patch 0 temperature: rail max");
    const cwtest::Run bad = cwtest::cli(cwtest::with(benchmark_args(), {"--T0-1", "10"}));
    cwtest::expect_refusal(bad, 2, "--T0-1", "--T0-1 without --temperature");
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
        cwtest::cli_ok(cwtest::with(tread_args(), {"--model", "fastsim", "--format", "json"})).out);
    assert_true(exact.at("model").string == "exact");
    assert_true(fast.at("model").string == "fastsim");
    assert_int_equal(fast.at("patches").array.size(), 1);
    assert_int_equal(exact.at("patches").array.size(), 1);
    // The fast model's accuracy at 3 mm: within 3 % of mu Fz = 3 kN
    // (doc/validation/manchester.md, the fast model against the exact one).
    const cwtest::Json& e = exact.at("patches").array[0];
    const cwtest::Json& f = fast.at("patches").array[0];
    for (const char* key : {"Fn", "Fx_rail", "Fs_rail"})
        assert_close(f.num(key), e.num(key), 0, 0.03 * 0.3 * 1e4);
    // ... yet a different model: its own numbers, not the exact model's.
    assert_true(f.num("Fx_rail") != e.num("Fx_rail"));
    assert_close(fast.at("total_rail").num("Fz"), 1e4, 1e-6, 0);
    cwtest::expect_contains(cwtest::cli_ok(cwtest::with(tread_args(), {"--model", "fastsim"})).out,
                            "model fastsim: FASTSIM with the semi-Hertzian normal problem");
}

// Distance from (y, z) to the polyline through the points of `body`.
double polyline_distance(const std::vector<std::vector<std::string>>& rows, const std::string& body,
                         double y, double z)
{
    std::vector<std::pair<double, double>> p;
    for (size_t k = 1; k < rows.size(); ++k)
        if (rows[k][0] == body) p.push_back({std::strtod(rows[k][1].c_str(), nullptr),
                                             std::strtod(rows[k][2].c_str(), nullptr)});
    double best = HUGE_VAL;
    for (size_t k = 0; k + 1 < p.size(); ++k) {
        const double dy = p[k + 1].first - p[k].first, dz = p[k + 1].second - p[k].second;
        const double len2 = dy * dy + dz * dz;
        double t = len2 > 0 ? ((y - p[k].first) * dy + (z - p[k].second) * dz) / len2 : 0.0;
        t = std::clamp(t, 0.0, 1.0);
        best = std::min(best, std::hypot(p[k].first + t * dy - y, p[k].second + t * dz - z));
    }
    return best;
}

void writes_the_data_files(void**)
{
    const std::string out = cwtest::g_tools.scratch + "/tread";
    const cwtest::Run r =
        cwtest::cli_ok(cwtest::with(tread_args(), {"--format", "json", "--out", out, "--no-plots"}));
    cwtest::expect_contains(r.err, "wrote 3 files to");
    // result.json is the run's JSON.
    assert_true(cwtest::slurp(out + "/result.json") == r.out);
    const cwtest::Json j = cwtest::parse_json(r.out);
    const cwtest::Json& q = j.at("patches").array[0];

    // The fields add up to the patch's forces (their definition): Fn is the
    // sum of pz * area, Fx and Fs the sums of the tractions on the rail.
    const auto rows = cwtest::read_csv(out + "/patch_0_fields.csv");
    assert_true(rows.size() > 100);
    const std::vector<std::string> columns = {"x_m", "s_m", "area_m2", "pz_Pa", "px_Pa",
                                              "ps_Pa", "sx", "ss", "state", "work_J_per_m"};
    assert_true(rows[0] == columns);
    std::map<std::string, size_t> c = cwtest::header_index(rows[0]);
    const auto num = [&](size_t k, const char* name) {
        return std::strtod(rows[k][c.at(name)].c_str(), nullptr);
    };
    double Fn = 0, Fx = 0, Fs = 0, Mn = 0;
    int contact = 0;
    for (size_t k = 1; k < rows.size(); ++k) {
        const double a = num(k, "area_m2");
        Fn += num(k, "pz_Pa") * a;
        Fx += num(k, "px_Pa") * a;
        Fs += num(k, "ps_Pa") * a;
        Mn += (num(k, "x_m") * num(k, "ps_Pa") - num(k, "s_m") * num(k, "px_Pa")) * a;
        contact += num(k, "state") != 0.0;
    }
    assert_close(Fn, q.num("Fn"), 1e-9, 0);
    assert_close(Fx, q.num("Fx_rail"), 0, 1e-9 * q.num("Fn"));
    assert_close(Fs, q.num("Fs_rail"), 0, 1e-9 * q.num("Fn"));
    // Mn about the reference point, on the rail (x, s from it).
    assert_close(Mn, q.num("Mn_rail"), 0, 1e-9 * q.num("Fn") * 1e-2);
    assert_int_equal(contact, static_cast<int>(q.num("n_contact")));

    // The rail's points run through the contact reference point, which lies
    // on the rail's surface (to 1 um: the polyline between the points).
    const auto profile = cwtest::read_csv(out + "/profiles.csv");
    assert_true(profile[0] == (std::vector<std::string>{"body", "y_m", "z_m"}));
    assert_true(polyline_distance(profile, "rail", q.num("y_contact"), q.num("z_contact")) < 1e-6);
    // The wheel's come within the patch's approach of it (its surfaces
    // overlap there by the approach), not far beyond.
    assert_true(polyline_distance(profile, "wheel", q.num("y_contact"), q.num("z_contact")) <
                2 * q.num("approach") + 1e-6);
    assert_false(std::filesystem::exists(out + "/profiles.png"));

    // A second run into the same directory needs --force.
    cwtest::expect_refusal(cwtest::cli(cwtest::with(tread_args(), {"--out", out})), 2, "--force",
                           "output exists");
}

// Without yaw at 3 mm the patch rolls partly in adhesion: adhesion ahead of
// slip (the wheel rolls towards +x: material enters at the leading edge,
// Carter's and Kalker's theory), no work where it adheres, the highest
// pressure inside the patch.
void adhesion_leads(void**)
{
    std::vector<std::string> args = tread_args();
    args[8] = "0"; // --yaw
    const std::string out = cwtest::g_tools.scratch + "/adhesion";
    cwtest::cli_ok(cwtest::with(args, {"--out", out, "--no-plots"}));
    const auto rows = cwtest::read_numbers(out + "/patch_0_fields.csv");
    double x_adhesion = 0, x_slip = 0, p_max = 0, x_lo = HUGE_VAL, x_hi = -HUGE_VAL, x_pmax = 0;
    int n_adhesion = 0, n_slip = 0;
    for (const std::vector<double>& e : rows) {
        if (e[8] == CW_STATE_EXTERIOR) continue;
        x_lo = std::min(x_lo, e[0]);
        x_hi = std::max(x_hi, e[0]);
        if (e[3] > p_max) {
            p_max = e[3];
            x_pmax = e[0];
        }
        if (e[8] == CW_STATE_ADHESION) {
            x_adhesion += e[0];
            ++n_adhesion;
            assert_true(e[9] == 0.0);
        } else {
            x_slip += e[0];
            ++n_slip;
        }
    }
    assert_true(n_adhesion > 50 && n_slip > 50);
    assert_true(x_adhesion / n_adhesion > x_slip / n_slip + 1e-3);
    assert_true(x_pmax > x_lo + 0.25 * (x_hi - x_lo) && x_pmax < x_hi - 0.25 * (x_hi - x_lo));
}

// The benchmark at 5 mm: one patch of two lobes (tread and gauge corner).
void writes_pictures(void**)
{
    if (std::getenv("CW_TEST_NO_GNUPLOT")) cw_skip();
    const std::string out = cwtest::g_tools.scratch + "/pictures";
    std::vector<std::string> args = tread_args();
    args[6] = "5e-3";
    args[8] = "0.012";
    args[10] = "-3.554e-4";
    args[16] = "-4.3353637";
    const cwtest::Json j = cwtest::parse_json(
        cwtest::cli_ok(cwtest::with(args, {"--out", out, "--format", "json"})).out);
    assert_int_equal(j.at("patches").array.size(), 1);
    for (const char* png : {"profiles.png", "patch_0.png"}) {
        const std::string data = cwtest::slurp(out + "/" + png);
        if (!(data.size() > 5000 && data.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0))
            fail_msg("%s is not a PNG picture (%zu bytes)", png, data.size());
    }
    // Each lobe is drawn across the profiles and labelled on the maps.
    const auto extents = cwtest::read_csv(out + "/gnuplot/extents.dat");
    size_t intervals = 0;
    for (const auto& row : extents) intervals += !row.empty() && row[0][0] != '#';
    assert_int_equal(intervals, 2);
    const std::string script = cwtest::slurp(out + "/gnuplot/wheelrail.gp");
    cwtest::expect_contains(script, "'gnuplot/patch_0_lobes.dat' using 2:3:(sprintf('lobe %d'");
}

void warns_about_implausible_units(void**)
{
    std::vector<std::string> args = benchmark_args();
    args[14] = "10"; // --Fz in kN
    const cwtest::Run k = cwtest::cli_ok(cwtest::with(args, {"--G", "82000"}));
    cwtest::expect_contains(k.err, "warning: --Fz = 10 N is implausible");
    cwtest::expect_contains(k.err, "warning: --G = 82000 Pa is implausible");
}

// One vocabulary: --N is --Fz and fast is fastsim (the same numbers, to the
// bit), the text numbers the patches from 0 as the files and pictures do,
// and an error names the option as it was typed.
void one_vocabulary(void**)
{
    std::vector<std::string> n_args = tread_args();
    n_args[11] = "--N";
    const std::string fz = cwtest::cli_ok(cwtest::with(tread_args(), {"--model", "fastsim", "--format", "json"})).out;
    assert_true(cwtest::cli_ok(cwtest::with(n_args, {"--model", "fast", "--format", "json"})).out == fz);
    const std::string text = cwtest::cli_ok(cwtest::with(n_args, {"--model", "fastsim"})).out;
    const size_t header = text.find("patch  y_rail[mm]");
    assert_true(header != std::string::npos);
    const std::string first = text.substr(text.find('\n', header) + 1, 2);
    assert_string_equal(first.c_str(), "0 ");
    n_args[12] = "-5";
    cwtest::expect_refusal(cwtest::cli(n_args), 2, "--N: must be > 0", "--N as typed");
    cwtest::expect_refusal(cwtest::cli(cwtest::with(tread_args(), {"--N", "1e4"})), 2,
                           "given twice, as --Fz and --N", "--Fz and --N");
}

// A measured MiniProf wheel, whose y runs from its flange back, on the
// benchmark rail at 2 mm: its flange tip lands on the rail crown, the
// wheelset 27.97 mm up (the file's flange height Sh). Solved, with warnings
// naming the cause and the option that fixes it; with --wheel-y-offset
// -0.07 (its flange back at -70 mm) the wheel runs on its tread and nothing
// is said. A shift of 21 mm is warned about ("+-20 mm"), 19 mm is not.
void warns_about_misplaced_wheel(void**)
{
    const std::vector<std::string> args = {
        "wheelrail", "--wheel-profile", g_data + "/right-wheel-v1-pre-dry.whl", "--rail-profile",
        g_data + "/MBench_UIC60_v3.prr", "--y-shift", "2e-3", "--Fz", "80e3", "--model", "fastsim",
        "--V", "1", "--pitch-rate", "-2.1739130434782608", "--format", "json"};
    const cwtest::Run r = cwtest::cli_ok(args);
    const cwtest::Json j = cwtest::parse_json(r.out);
    assert_close(j.num("z_ws"), -27.9698e-3, 0, 0.5e-3);
    cwtest::expect_contains(r.err, "creepwork: warning: --wheel-y-offset = 0 m is implausible for a "
                                   "wheel-rail contact: the flange tip lies at y = +");
    cwtest::expect_contains(r.err, "mm from the flange back at the flange-back position = -70.0 mm (a "
                                   "tip lies 10-30 mm from it): the profile starts at its flange back "
                                   "(y = +0.5 mm): offset it by --wheel-y-offset = the flange-back "
                                   "position");
    cwtest::expect_contains(r.err, "creepwork: warning: the wheelset height z_ws = -0.0276");
    cwtest::expect_contains(r.err, "from its flange tip: the wheelset rides on its flange tip");
    cwtest::expect_contains(r.err, "the wheel profile's origin is off (see --wheel-y-offset)");

    const cwtest::Run fixed = cwtest::cli_ok(cwtest::with(args, {"--wheel-y-offset", "-0.07"}));
    assert_true(fixed.err.empty());
    const cwtest::Json f = cwtest::parse_json(fixed.out);
    assert_true(std::fabs(f.num("z_ws")) < 2e-3);
    // the same as the profile's points moved by -70 mm through the C ABI
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    p.model = CW_MODEL_FASTSIM;
    p.normal_method = CW_NORMAL_SEMI_HERTZ;
    p.flange_back_position = 0.0; // the flange back where this profile has it
    cw_wheelrail* w = nullptr;
    assert_int_equal(cw_wheelrail_create(&p, (g_data + "/MBench_UIC60_v3.prr").c_str(),
                                         (g_data + "/right-wheel-v1-pre-dry.whl").c_str(), &w, nullptr, 0),
                     CW_OK);
    cw_wheelrail_motion m;
    cw_wheelrail_motion_init(&m);
    m.y = 2e-3, m.vs = 1, m.vpitch = -2.1739130434782608;
    cw_wheelrail_totals t;
    cw_wheelrail_totals_init(&t);
    assert_int_equal(cw_wheelrail_solve(w, &m, CW_WHEELRAIL_FORCE, 80e3, &t), CW_OK);
    assert_close(f.num("z_ws"), t.z, 0, 1e-9);
    cw_wheelrail_destroy(w);

    std::vector<std::string> shift = benchmark_args();
    shift[8] = "21e-3";
    cwtest::expect_contains(cwtest::cli_ok(shift).err,
                            "warning: --y-shift = 0.021 m is implausible for a wheel-rail contact: "
                            "lateral shifts stay within +-20 mm");
    shift[8] = "19e-3";
    assert_true(cwtest::cli_ok(shift).err.find("--y-shift") == std::string::npos);
}

// Profiles that are not what their name says: the message names the cause.
void profile_messages_name_the_cause(void**)
{
    const auto file = [](const std::string& name, const std::string& text) {
        const std::string path = cwtest::g_tools.scratch + "/" + name;
        std::ofstream(path, std::ios::binary) << text;
        return path;
    };
    // The benchmark rail as a table in metres (read as mm: 1000 times too short).
    std::string metres = "y z\n";
    for (int k = 0; k <= 60; ++k) {
        const double y = -0.035 + 0.07 * k / 60.0;
        char row[64];
        std::snprintf(row, sizeof row, "%.6f %.6f\n", y, y * y / 0.6);
        metres += row;
    }
    const std::vector<std::string> base = {"wheelrail", "--wheel-profile", g_data + "/MBench_S1002_v3.prw",
                                           "--Fz", "1e4"};
    const cwtest::Run m = cwtest::cli(cwtest::with(base, {"--rail-profile", file("rail_in_m.txt", metres)}));
    cwtest::expect_refusal(m, 2, "rail_in_m.txt: the rail profile is", "metres read as mm");
    cwtest::expect_contains(m.err, "a profile in metres read as millimetres is 1000 times too short");
    assert_true(m.err.find("duplicate") == std::string::npos);
    // ... read in metres: no unit message (the flat parabola is a poor rail, but a rail)
    const cwtest::Run ok = cwtest::cli(cwtest::with(base, {"--rail-profile", file("rail_in_m2.txt", metres),
                                                           "--profile-unit", "1"}));
    assert_true(ok.err.find("too short") == std::string::npos);
    // A binary file: its bytes are not echoed.
    std::string binary = "\x7f" "ELF\x02\x01\x01";
    for (int k = 0; k < 300; ++k) binary += static_cast<char>((k * 37) & 0xff);
    const cwtest::Run b = cwtest::cli(cwtest::with(base, {"--rail-profile", file("random.bin", binary)}));
    cwtest::expect_refusal(b, 2, "random.bin line 1: byte 0x7f at column 1 is not text", "binary file");
    assert_true(b.err.size() < 300);
    // A zig-zag where measured sections were joined: no advice about
    // options the command lacks.
    const cwtest::Run z = cwtest::cli({"wheelrail", "--wheel-profile", g_data + "/Car7216_0001r.whl",
                                       "--rail-profile", g_data + "/MBench_UIC60_v3.prr", "--Fz", "1e4"});
    assert_int_equal(z.status, 2);
    assert_true(z.err.find("threshold") == std::string::npos);
}

// Patch 0 of the CLI's JSON q (benchmark_args() at --V 10) against the C
// ABI's with params p: the same forces, to the bit. The library's patch.
cw_wheelrail_patch expect_library_patch(const cwtest::Json& q, const cw_wheelrail_params& p)
{
    cw_wheelrail_totals t;
    cw_wheelrail* w = solved_benchmark(t, &p, 10.0, -21.374417);
    cw_wheelrail_patch pa;
    cw_wheelrail_patch_init(&pa);
    assert_int_equal(cw_wheelrail_get_patch(w, 0, &pa), CW_OK);
    cw_wheelrail_destroy(w);
    assert_close(q.num("Fn"), pa.Fn, 1e-15, 0);
    assert_close(q.num("Fx_rail"), pa.Fx, 1e-15, 0);
    assert_close(q.num("Fs_rail"), pa.Fs, 1e-15, 0);
    return pa;
}

// --friction-law polach --mu MU0 --polach-A A --polach-B B: the patch's
// forces equal, bitwise, the C ABI's with the law cw_friction_polach writes
// (the option's documented meaning), at 10 m/s, with the exact model and
// with the fast model (--model fastsim); the law lowers the force below
// Coulomb's mu0 Fn (Polach's mu falls from mu0 with the slip speed).
void friction_law_matches_library(void**)
{
    std::vector<std::string> args = benchmark_args();
    const auto v = std::find(args.begin(), args.end(), "--V");
    *(v + 1) = "10";
    *(v + 3) = "-21.374417"; // the pitch rate scaled with V
    for (const bool fast : {false, true}) {
        std::vector<std::string> more = {"--format", "json", "--friction-law", "polach", "--mu",
                                         "0.36", "--polach-A", "0.38", "--polach-B", "0.7"};
        if (fast) more.insert(more.end(), {"--model", "fastsim"});
        const cwtest::Run r = cwtest::cli_ok(cwtest::with(args, more));
        const cwtest::Json j = cwtest::parse_json(r.out);
        const cwtest::Json& q = j.at("patches").array[0];

        cw_params law;
        cw_params_init(&law);
        assert_int_equal(cw_friction_polach(0.36, 0.38, 0.7, &law, nullptr, 0), CW_OK);
        cw_wheelrail_params p;
        cw_wheelrail_params_init(&p);
        p.friction_law = law.friction_law;
        p.mu = law.mu;
        p.mu_e1 = law.mu_e1;
        p.s_h1 = law.s_h1;
        if (fast) {
            p.model = CW_MODEL_FASTSIM;
            p.normal_method = CW_NORMAL_SEMI_HERTZ;
        }
        const cw_wheelrail_patch pa = expect_library_patch(q, p);
        assert_true(std::hypot(pa.Fx, pa.Fs) < 0.36 * pa.Fn * 0.95);
    }

    using cwtest::cli;
    using cwtest::expect_refusal;
    expect_refusal(cli(cwtest::with(args, {"--friction-law", "polach", "--polach-A", "0.38"})), 2,
                   "--polach-B", "Polach without B");
    expect_refusal(cli(cwtest::with(args, {"--mu-e1", "0.1"})), 2, "--mu-e1", "a term without a law");
    expect_refusal(cli(cwtest::with(args, {"--friction-law", "exponential", "--mu-e1", "0.1",
                                           "--model", "fastsim"})),
                   2, "s_h1", "a falling term without its half speed, the fast model");
    expect_refusal(cli(cwtest::with(args, {"--friction-law", "exponential", "--mu-e1", "0.1"})), 2,
                   "s_h1", "a falling term without its half speed");
}

// --memory-distance, --memory-s0 with CONTACT's tractcurv law and --layer-h,
// --layer-G (CONTACT's tractcurv layer): the patch's forces equal, bitwise,
// the C ABI's with the same cw_wheelrail_params fields; a layer typed in mm
// is warned of by its option; refusals name the option or the field.
void memory_and_layer_match_library(void**)
{
    std::vector<std::string> args = benchmark_args();
    const auto v = std::find(args.begin(), args.end(), "--V");
    *(v + 1) = "10";
    *(v + 3) = "-21.374417"; // the pitch rate scaled with V
    const std::vector<std::string> law = {"--friction-law", "exponential", "--mu", "0.14", "--mu-e1",
                                          "0.19", "--s-h1", "1.25"};
    const cwtest::Run r = cwtest::cli_ok(cwtest::with(
        cwtest::with(args, law), {"--format", "json", "--memory-distance", "3e-4", "--memory-s0", "1e-3",
                                  "--layer-h", "1.25e-3", "--layer-G", "8.2e9"}));
    const cwtest::Json j = cwtest::parse_json(r.out);
    const cwtest::Json& q = j.at("patches").array[0];

    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    p.friction_law = CW_FRICTION_EXPONENTIAL;
    p.mu = 0.14;
    p.mu_e1 = 0.19;
    p.s_h1 = 1.25;
    p.memory_distance = 3e-4;
    p.memory_s0 = 1e-3;
    p.layer_h = 1.25e-3;
    p.layer_G = 8.2e9;
    expect_library_patch(q, p);

    const cwtest::Run mm = cwtest::cli_ok(cwtest::with(args, {"--layer-h", "1.25", "--layer-G", "8.2e9"}));
    cwtest::expect_contains(mm.err, "warning: --layer-h = 1.25 m is implausible");
    using cwtest::cli;
    using cwtest::expect_refusal;
    expect_refusal(cli(cwtest::with(args, {"--memory-distance", "3e-4"})), 2, "--memory-distance",
                   "memory without a law");
    expect_refusal(cli(cwtest::with(args, {"--layer-h", "1.25e-3"})), 2, "layer_G",
                   "a layer without its modulus");
    expect_refusal(cli(cwtest::with(args, {"--layer-h", "1.25e-3", "--layer-G", "8.2e9", "--model",
                                           "fastsim"})),
                   2, "layer_h", "a layer with the fast model");
    expect_refusal(cli(cwtest::with(args, {"--tau-c0", "150e6"})), 2, "tau_c0", "yield on a patch");
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
    expect_refusal(cli(cwtest::with(benchmark_args(), {"--no-plots"})), 2, "--no-plots",
                   "--no-plots without --out");
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
        cmocka_unit_test(temperature_matches_library),
        cmocka_unit_test(fast_model_near_exact),
        cmocka_unit_test(writes_the_data_files),
        cmocka_unit_test(adhesion_leads),
        cmocka_unit_test(writes_pictures),
        cmocka_unit_test(warns_about_implausible_units),
        cmocka_unit_test(bad_inputs_fail_cleanly),
        cmocka_unit_test(friction_law_matches_library),
        cmocka_unit_test(memory_and_layer_match_library),
        cmocka_unit_test(one_vocabulary),
        cmocka_unit_test(warns_about_misplaced_wheel),
        cmocka_unit_test(profile_messages_name_the_cause),
    };
    return cw_run_tests(tests, cwtest::g_tools.test);
}
