// Tests of `creepwork transient`, run as a user runs it: its JSON equals,
// bit for bit, what the C ABI's cw_transient gives for the same gap and
// steps (CONTACT's catt_to_cart: the Cattaneo shift to Fx = -0.657 mu N and
// rolling at that force; creepages prescribed too); a steady start; steps
// files and options that are wrong fail cleanly (status 2, one stderr line
// naming the file and line or the option); --out writes history.csv with
// the same bits and the pictures, whose data show Cattaneo's stick disc.
//
// usage: test_cli_transient <creepwork binary> <scratch dir> [cmocka filter]
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "capi_fixtures.h"
#include "cli_checks.hpp"
#include "test_files.hpp"
// Last: cmocka defines macros (fail, skip) that clash with the C++ library.
#include "test_support.h"

namespace {

constexpr int kNx = 34, kNy = 33;
constexpr double kDx = 0.25e-3, kX0 = -4.0e-3, kFx = -0.657 * 0.4013 * 0.4705;

// catt_to_cart's gap file (examples/catt_to_cart.inp in SI), rows as the
// library's grid reads them.
std::string write_gap(std::vector<double>& h, cw_grid& g)
{
    cw_grid_init(&g);
    g.kind = CW_GRID_GAP;
    g.nx = kNx;
    g.ny = kNy;
    g.dx = g.dy = kDx;
    g.x0 = g.y0 = kX0;
    h.assign(static_cast<size_t>(kNx) * kNy, 0.0);
    std::string text = "x_m,y_m,h_m\n";
    char line[128];
    for (int j = 0; j < kNy; ++j)
        for (int i = 0; i < kNx; ++i) {
            const double x = kX0 + i * kDx, y = kX0 + j * kDx;
            h[i + kNx * j] = 2.963 * (x * x + y * y);
            std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g\n", x, y, h[i + kNx * j]);
            text += line;
        }
    return cwtest::scratch_file("gap.csv", text);
}

cw_transient* library_handle(const cw_grid& g, const std::vector<double>& h)
{
    cw_params p;
    cw_params_init(&p);
    p.model = CW_MODEL_EXACT;
    p.gap = h.data();
    p.gap_len = h.size();
    p.normal_force = 0.4705;
    p.G = 1e6;
    p.nu = 0.28;
    p.mu = 0.4013;
    cw_transient* t = nullptr;
    assert_int_equal(cw_transient_create(&g, &p, &t, nullptr, 0), CW_OK);
    return t;
}

// Step k of catt_to_cart at Fx (k = 0: the shift; then dq = dx), committed.
cw_transient_result force_step(cw_transient* t, int k)
{
    cw_transient_input s;
    cw_transient_input_init(&s);
    s.dq = k == 0 ? 0.0 : kDx;
    s.prescribe = CW_PRESCRIBE_FX;
    s.Fx = kFx;
    cw_transient_result r;
    cw_transient_result_init(&r);
    assert_int_equal(cw_transient_step(t, &s, &r), CW_OK);
    assert_int_equal(cw_transient_commit(t), CW_OK);
    return r;
}

const std::vector<std::string> kContact = {"--N", "0.4705", "--G", "1e6", "--nu", "0.28",
                                           "--mu", "0.4013"};

void transient_json_matches_library(void**)
{
    std::vector<double> h;
    cw_grid g;
    const std::string gap = write_gap(h, g);
    std::string steps = "dq_m,Fx\n";
    char line[96];
    for (int k = 0; k < 6; ++k) {
        std::snprintf(line, sizeof line, "%.17g,%.17g\n", k == 0 ? 0.0 : kDx, kFx);
        steps += line;
    }
    const std::string file = cwtest::scratch_file("steps.csv", steps);
    const cwtest::Run r = cwtest::cli_ok(cwtest::with(
        {"transient", "--steps", file, "--gap", gap, "--prescribe", "forces", "--format", "json"},
        kContact));
    const cwtest::Json j = cwtest::parse_or_fail(r.out);
    assert_int_equal(j.array.size(), 6);
    cw_transient* t = library_handle(g, h);
    for (int k = 0; k < 6; ++k) {
        const cw_transient_result lib = force_step(t, k);
        const cwtest::Json& o = j.array[k];
        // The JSON prints each number's shortest exact text: the same bits.
        assert_true(o.num("xi_x") == lib.xi_x);
        assert_true(o.num("Fx") == lib.Fx);
        assert_true(o.num("Fy") == lib.Fy);
        assert_true(o.num("Mz") == lib.Mz);
        assert_true(o.num("W_step") == lib.W_step);
        assert_true(o.num("W_slip") == lib.W_slip);
        assert_int_equal(static_cast<int>(o.num("n_adhesion")), lib.n_adhesion);
        assert_int_equal(static_cast<int>(o.num("n_slip")), lib.n_slip);
        assert_int_equal(static_cast<int>(o.num("line")), k + 2);
    }
    // CONTACT's shift of case 1 [mm] and creepage of case 2, as it prints them.
    std::snprintf(line, sizeof line, "%.3E %.3E", j.array[0].num("xi_x") * 1e3,
                  j.array[1].num("xi_x"));
    assert_string_equal(line, "1.774E-02 1.824E-03");
    cw_transient_destroy(t);
}

void transient_steady_start_and_creepages(void**)
{
    std::vector<double> h;
    cw_grid g;
    const std::string gap = write_gap(h, g);
    const std::string file =
        cwtest::scratch_file("creep.csv", "# creepages prescribed\ndq_m,xi_x,xi_y\n0.00025,2e-3,1e-4\n"
                                          "0.000125,2e-3,1e-4\n");
    const cwtest::Run r = cwtest::cli_ok(cwtest::with(
        {"transient", "--steps", file, "--gap", gap, "--start", "steady", "--format", "json"},
        kContact));
    const cwtest::Json j = cwtest::parse_or_fail(r.out);
    assert_int_equal(j.array.size(), 2);
    cw_transient* t = library_handle(g, h);
    cw_transient_input s;
    cw_transient_input_init(&s);
    s.dq = kDx;
    s.xi_x = 2e-3;
    s.xi_y = 1e-4;
    assert_int_equal(cw_transient_start_steady(t, &s, nullptr), CW_OK);
    cw_transient_result lib;
    cw_transient_result_init(&lib);
    assert_int_equal(cw_transient_step(t, &s, &lib), CW_OK);
    assert_true(j.array[0].num("Fx") == lib.Fx);
    assert_true(j.array[0].num("Fy") == lib.Fy);
    assert_int_equal(cw_transient_commit(t), CW_OK);
    s.dq = 0.5 * kDx;
    assert_int_equal(cw_transient_step(t, &s, &lib), CW_OK);
    assert_true(j.array[1].num("Fx") == lib.Fx);
    cw_transient_destroy(t);
}

void transient_bad_inputs_fail_cleanly(void**)
{
    std::vector<double> h;
    cw_grid g;
    const std::string gap = write_gap(h, g);
    auto run = [&](const std::string& steps, const std::vector<std::string>& extra) {
        const std::string file = cwtest::scratch_file("bad.csv", steps);
        return cwtest::cli(cwtest::with(cwtest::with({"transient", "--steps", file, "--gap", gap}, kContact),
                                        extra));
    };
    cwtest::expect_refusal(run("xi_x\n1e-3\n", {}), 2, "dq_m", "no dq_m column");
    cwtest::expect_refusal(run("dq_m,Fx\n0,-0.1\n", {}), 2, "unknown column 'Fx'", "Fx without --prescribe");
    cwtest::expect_refusal(run("dq_m,xi_x\n0.00025,abc\n", {}), 2, "line 2, column xi_x", "not a number");
    cwtest::expect_refusal(run("dq_m,xi_x\n0.0003,1e-3\n", {}), 2, "line 2", "dq beyond dx");
    cwtest::expect_refusal(run("dq_m,xi_x\n0.0003,1e-3\n", {}), 2, "dq", "dq beyond dx names dq");
    cwtest::expect_refusal(run("dq_m,Fx\n0,-1\n", {"--prescribe", "forces"}), 2, "mu N",
                           "a force beyond mu N");
    cwtest::expect_refusal(run("dq_m\n", {}), 2, "no step", "no step");
    const std::string ok = cwtest::scratch_file("ok.csv", "dq_m\n0\n");
    cwtest::expect_refusal(cwtest::cli({"transient", "--steps", ok, "--gap", gap}), 2, "--N",
                           "no load");
    cwtest::expect_refusal(cwtest::cli({"transient", "--gap", gap, "--N", "1"}), 2, "--steps",
                           "no steps file");
    // World-fixed coordinates are the exact model's: FASTSIM's are refused.
    cwtest::expect_refusal(run("dq_m,xi_x\n0,1e-6\n", {"--model", "fastsim", "--coordinates",
                                                      "world"}),
                           2, "CW_MODEL_FASTSIM", "world-fixed FASTSIM");
}


// Rows of numbers of a CSV (header skipped) or whitespace data file (# skipped).
std::vector<std::vector<double>> number_rows(const std::string& path, char separator)
{
    std::vector<std::vector<double>> rows;
    std::ifstream f(path);
    std::string line;
    if (separator == ',') std::getline(f, line);
    while (std::getline(f, line)) {
        if (line.empty() || line[0] == '#') continue;
        for (char& c : line)
            if (c == separator) c = ' ';
        std::istringstream ss(line);
        std::vector<double> row;
        for (double v; ss >> v;) row.push_back(v);
        rows.push_back(row);
    }
    return rows;
}

std::string catt_to_cart_steps(const char* name, int n)
{
    std::string steps = "dq_m,Fx\n";
    char line[96];
    for (int k = 0; k < n; ++k) {
        std::snprintf(line, sizeof line, "%.17g,%.17g\n", k == 0 ? 0.0 : kDx, kFx);
        steps += line;
    }
    return cwtest::scratch_file(name, steps);
}

// --out: history.csv holds every step's numbers round-trip (the JSON's
// bits), and catt_to_cart's creepage overshoot at step 15 (CONTACT's
// 3.403E-03, the largest of steps 2 .. 15); --no-plots writes no picture.
void transient_out_writes_history(void**)
{
    std::vector<double> h;
    cw_grid g;
    const std::string gap = write_gap(h, g);
    const std::string file = catt_to_cart_steps("steps15.csv", 15);
    const std::string out = cwtest::g_tools.scratch + "/history";
    const std::vector<std::string> run = cwtest::with(
        {"transient", "--steps", file, "--gap", gap, "--prescribe", "forces", "--format", "json"},
        kContact);
    const cwtest::Json j =
        cwtest::parse_or_fail(cwtest::cli_ok(cwtest::with(run, {"--out", out, "--no-plots"})).out);
    const std::vector<std::vector<double>> rows = number_rows(out + "/history.csv", ',');
    assert_int_equal(rows.size(), 15);
    // step,line,dq_m,xi_x,xi_y,phi,Fx_N,Fy_N,Mz_N_m,n_contact,n_adhesion,n_slip,W_step_J,
    // W_slip_J
    const char* keys[] = {"xi_x", "xi_y", "phi", "Fx", "Fy", "Mz", "n_contact", "n_adhesion",
                          "n_slip", "W_step", "W_slip"};
    for (size_t k = 0; k < rows.size(); ++k) {
        assert_int_equal(rows[k].size(), 14);
        assert_true(rows[k][0] == double(k + 1));
        assert_true(rows[k][1] == j.array[k].num("line"));
        assert_true(rows[k][2] == (k == 0 ? 0.0 : kDx));
        for (size_t c = 0; c < 11; ++c)
            if (!(rows[k][3 + c] == j.array[k].num(keys[c])))
                fail_msg("step %zu %s: %.17g in history.csv, %.17g in the JSON", k + 1, keys[c],
                         rows[k][3 + c], j.array[k].num(keys[c]));
    }
    size_t peak = 1;
    for (size_t k = 1; k < rows.size(); ++k)
        if (rows[k][3] > rows[peak][3]) peak = k;
    char printed[32];
    std::snprintf(printed, sizeof printed, "%zu %.3E", peak + 1, rows[peak][3]);
    assert_string_equal(printed, "15 3.403E-03");
    assert_false(std::filesystem::exists(out + "/history.png"));
    assert_false(std::filesystem::exists(out + "/gnuplot"));
    cwtest::expect_refusal(cwtest::cli(cwtest::with(run, {"--out", out})), 2, "--out",
                           "an earlier output without --force");
}

// --out's pictures: step_NNN.png per step and history.png. The data drawn
// for the shift show Cattaneo's solution: along the centre row the
// adhesion elements are one run about x = 0 whose half-width is the stick
// radius a (1 - |Fx|/(mu N))^(1/3) = 0.700 x 3.5 mm (a the contact radius
// of catt_to_cart, issue material) to within one element, and in every
// slip element p_x = -mu p_z (Fx < 0) to 1e-9.
void transient_out_draws_steps(void**)
{
    if (std::getenv("CW_TEST_NO_GNUPLOT")) cw_skip();
    std::vector<double> h;
    cw_grid g;
    const std::string gap = write_gap(h, g);
    const std::string file = catt_to_cart_steps("steps3.csv", 3);
    const std::string out = cwtest::g_tools.scratch + "/pictures";
    cwtest::cli_ok(cwtest::with(
        {"transient", "--steps", file, "--gap", gap, "--prescribe", "forces", "--out", out},
        kContact));
    for (const char* png : {"step_001.png", "step_002.png", "step_003.png", "history.png"}) {
        const std::string data = cwtest::slurp(out + "/" + png);
        if (!(data.size() > 5000 && data.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0))
            fail_msg("%s is not a PNG picture (%zu bytes)", png, data.size());
    }
    assert_false(std::filesystem::exists(out + "/step_004.png"));
    // x [mm], p_x, mu p_z, -mu p_z [N/mm^2], state along y = 0
    const std::vector<std::vector<double>> row = number_rows(out + "/gnuplot/step_001_row.dat", ' ');
    assert_int_equal(row.size(), kNx);
    double lo = 1e9, hi = -1e9;
    int slip = 0;
    for (const std::vector<double>& e : row) {
        if (e[4] == CW_STATE_ADHESION) {
            lo = std::min(lo, e[0]);
            hi = std::max(hi, e[0]);
        }
        if (e[4] == CW_STATE_SLIP) {
            ++slip;
            assert_close(e[1], e[3], 1e-9, 0.0);
        }
    }
    for (const std::vector<double>& e : row) // one run: no slip between lo and hi
        if (e[0] >= lo && e[0] <= hi) assert_int_equal(static_cast<int>(e[4]), CW_STATE_ADHESION);
    const double c = 3.5 * std::cbrt(1.0 - 0.657);
    assert_close(0.5 * (hi - lo) + 0.5 * kDx * 1e3, c, 0.0, kDx * 1e3);
    assert_close(0.5 * (hi + lo), 0.0, 0.0, 1e-12);
    assert_true(slip >= 4);
}

} // namespace

// --coordinates world: the JSON equals, bit for bit, a library handle set
// to CW_COORDINATES_WORLD (the shift and two steps: the contact moves two
// elements, still on the grid), and its creepage the contact-fixed run's
// to 1e-6; a bad value names the option.
void transient_world_coordinates(void**)
{
    std::vector<double> h;
    cw_grid g;
    const std::string gap = write_gap(h, g);
    char line[96];
    std::string steps = "dq_m,Fx\n";
    for (int k = 0; k < 3; ++k) {
        std::snprintf(line, sizeof line, "%.17g,%.17g\n", k == 0 ? 0.0 : kDx, kFx);
        steps += line;
    }
    const std::string file = cwtest::scratch_file("steps_world.csv", steps);
    const std::vector<std::string> args = {"transient", "--steps", file, "--gap", gap,
                                           "--prescribe", "forces", "--format", "json"};
    std::vector<std::string> world = args;
    world.insert(world.end(), {"--coordinates", "world"});
    const cwtest::Json jw = cwtest::parse_or_fail(cwtest::cli_ok(cwtest::with(world, kContact)).out);
    const cwtest::Json jc = cwtest::parse_or_fail(cwtest::cli_ok(cwtest::with(args, kContact)).out);
    assert_int_equal(jw.array.size(), 3);
    cw_transient* t = library_handle(g, h);
    assert_int_equal(cw_transient_set_coordinates(t, CW_COORDINATES_WORLD), CW_OK);
    for (int k = 0; k < 3; ++k) {
        const cw_transient_result lib = force_step(t, k);
        assert_true(jw.array[k].num("xi_x") == lib.xi_x);
        assert_true(jw.array[k].num("W_step") == lib.W_step);
        assert_true(std::fabs(jw.array[k].num("xi_x") / jc.array[k].num("xi_x") - 1.0) <= 1e-6);
    }
    cw_transient_destroy(t);
    std::vector<std::string> bad = args;
    bad.insert(bad.end(), {"--coordinates", "ground"});
    cwtest::expect_refusal(cwtest::cli(cwtest::with(bad, kContact)), 2, "--coordinates",
                           "a coordinates value that is not contact or world");
}

// An elliptic contact (--a --b on the uniform grid --nx --ny --box-scale):
// the JSON equals, bit for bit, a library handle on CW_GRID_UNIFORM; a
// contact given both ways, or half an ellipse, is refused naming the option.
void transient_ellipse(void**)
{
    const std::string file =
        cwtest::scratch_file("steps_ellipse.csv", "dq_m,xi_x\n0,1e-7\n2.75e-4,1e-3\n2.75e-4,1e-3\n");
    const std::vector<std::string> args = {"transient", "--steps", file, "--a", "4e-3", "--b",
                                           "2.5e-3", "--nx", "32", "--ny", "24", "--box-scale",
                                           "1.1", "--format", "json"};
    const cwtest::Json j = cwtest::parse_or_fail(cwtest::cli_ok(cwtest::with(args, kContact)).out);
    assert_int_equal(j.array.size(), 3);
    cw_params p;
    const cw_grid g = cw_test_transient_ellipse(&p);
    cw_transient* t = nullptr;
    assert_int_equal(cw_transient_create(&g, &p, &t, nullptr, 0), CW_OK);
    for (int k = 0; k < 3; ++k) {
        cw_transient_input s;
        cw_transient_input_init(&s);
        s.dq = k == 0 ? 0.0 : 2.75e-4;
        s.xi_x = k == 0 ? 1e-7 : 1e-3;
        cw_transient_result lib;
        cw_transient_result_init(&lib);
        assert_int_equal(cw_transient_step(t, &s, &lib), CW_OK);
        assert_int_equal(cw_transient_commit(t), CW_OK);
        assert_true(j.array[k].num("Fx") == lib.Fx);
        assert_true(j.array[k].num("W_step") == lib.W_step);
    }
    cw_transient_destroy(t);
    std::vector<double> h;
    cw_grid gg;
    const std::string gap = write_gap(h, gg);
    cwtest::expect_refusal(
        cwtest::cli(cwtest::with({"transient", "--steps", file, "--gap", gap, "--a", "4e-3", "--b",
                                  "2.5e-3"},
                                 kContact)),
        2, "--gap", "a contact given both as a gap file and as an ellipse");
    cwtest::expect_refusal(
        cwtest::cli(cwtest::with({"transient", "--steps", file, "--a", "4e-3"}, kContact)), 2,
        "--b", "half an ellipse");
}

int main(int argc, char** argv)
{
    if (!cwtest::set_up(argc, argv, "test_cli_transient", {"creepwork", "scratch"})) return 2;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(transient_json_matches_library),
        cmocka_unit_test(transient_steady_start_and_creepages),
        cmocka_unit_test(transient_bad_inputs_fail_cleanly),
        cmocka_unit_test(transient_out_writes_history),
        cmocka_unit_test(transient_out_draws_steps),
        cmocka_unit_test(transient_world_coordinates),
        cmocka_unit_test(transient_ellipse),
    };
    return cw_run_tests(tests, cwtest::g_tools.test);
}
