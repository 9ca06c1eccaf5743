/* Tests of `creepwork wear`, run as a user runs it: its profile equals what
 * the C ABI gives for the same states (bitwise: both use the exact sums),
 * the files carry their units, bad input fails cleanly (status 2, one
 * stderr line naming the option or the file's line and column, nothing
 * written), implausible values are warned about, a wheel's distance becomes
 * revolutions, and the picture is drawn.
 *
 * usage: test_cli_wear <creepwork binary> <scratch dir> [cmocka filter] */
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

// Three states: a tread contact, a spin-dominated one on an angle, one with
// its own mu; on the rail, 200 + 300 + 500 passes.
const char* const kStates = "# three states\n"
                            "s0,a,b,N,xi_x,xi_y,spin,contact_angle,passes,mu\n"
                            "0.001,6e-3,4e-3,60e3,1e-3,-5e-4,0.5,0.02,200,0.3\n"
                            "\n"
                            "-0.003,5e-3,3e-3,70e3,5e-4,1e-3,4.0,-0.2,300,0.35\n"
                            "0.004,7e-3,5e-3,50e3,-2e-3,0,1.0,0.1,500,0.25\n";

struct StateRow {
    double s0, a, b, N, xi, eta, phi, angle, passes, mu;
};
const StateRow kRows[3] = {{0.001, 6e-3, 4e-3, 60e3, 1e-3, -5e-4, 0.5, 0.02, 200, 0.3},
                           {-0.003, 5e-3, 3e-3, 70e3, 5e-4, 1e-3, 4.0, -0.2, 300, 0.35},
                           {0.004, 7e-3, 5e-3, 50e3, -2e-3, 0, 1.0, 0.1, 500, 0.25}};

// The CLI's profile equals the C ABI's for the same states, node grid and
// options: the profile columns read back (17 digits) equal, bitwise, the
// library's depths; summary.json's totals agree; every file has its units.
void wear_matches_library(void**)
{
    const std::string in = scratch_file("states.csv", kStates);
    const std::string out = g_tools.scratch + "/match";
    const Run r = cli_ok({"wear", "--in", in, "--out", out, "--nx", "12", "--ny", "10",
                          "--profile-from", "-0.012", "--profile-to", "0.012",
                          "--profile-step", "2e-4", "--no-plots", "--format", "json"});
    const Json j = parse_json(r.out);
    const auto rows = read_csv(out + "/wear_profile.csv");
    assert_string_equal(rows[0][0].c_str(), "k");
    const std::vector<std::string> header = {"k", "s_m", "depth_normal_m", "depth_height_m",
                                             "parabola_depth_normal_m",
                                             "parabola_depth_height_m"};
    assert_true(rows[0] == header);
    const size_t n = rows.size() - 1;
    assert_int_equal(n, 121);

    // The library, by hand.
    std::vector<double> s(n);
    for (size_t k = 0; k < n; ++k) s[k] = -0.012 + 2e-4 * static_cast<double>(k);
    cw_grid g;
    cw_grid_init(&g);
    g.nx = 12;
    g.ny = 10;
    cw_solver* sv = nullptr;
    cw_wear* w = nullptr;
    cw_wear_profile *local = nullptr, *par = nullptr;
    assert_int_equal(cw_solver_create(&g, &sv, nullptr, 0), CW_OK);
    assert_int_equal(cw_wear_create(sv, &w), CW_OK);
    assert_int_equal(cw_wear_profile_create(s.data(), n, &local, nullptr, 0), CW_OK);
    assert_int_equal(cw_wear_profile_create(s.data(), n, &par, nullptr, 0), CW_OK);
    cw_wear_params wp;
    cw_wear_params_init(&wp);
    double y[10], width[10], depth[10], parabola[10];
    for (const StateRow& row : kRows) {
        cw_params p;
        cw_params_init(&p);
        p.a = row.a, p.b = row.b, p.normal_force = row.N, p.mu = row.mu;
        p.xi_x = row.xi, p.xi_y = row.eta, p.phi = row.phi;
        assert_int_equal(cw_solver_solve(sv, &p, CW_SOLVE_FULL, nullptr), CW_OK);
        assert_int_equal(cw_wear_compute(w, sv, &wp, nullptr), CW_OK);
        assert_int_equal(cw_wear_get_strips(w, y, width, depth, parabola, 10), CW_OK);
        assert_int_equal(cw_wear_profile_add(local, w, row.s0, 1, row.angle, row.passes), CW_OK);
        assert_int_equal(cw_wear_profile_add_strips(par, y, width, parabola, 10, row.s0, 1,
                                                    row.angle, row.passes),
                         CW_OK);
    }
    std::vector<double> dn(n), dh(n), pn(n), ph(n);
    cw_wear_profile_get_depth(local, CW_WEAR_DEPTH_NORMAL, dn.data(), n);
    cw_wear_profile_get_depth(local, CW_WEAR_DEPTH_HEIGHT, dh.data(), n);
    cw_wear_profile_get_depth(par, CW_WEAR_DEPTH_NORMAL, pn.data(), n);
    cw_wear_profile_get_depth(par, CW_WEAR_DEPTH_HEIGHT, ph.data(), n);
    double peak = 0;
    for (size_t k = 0; k < n; ++k) {
        const auto& c = rows[k + 1];
        assert_true(std::stod(c[1]) == s[k]);
        assert_true(std::stod(c[2]) == dn[k]);
        assert_true(std::stod(c[3]) == dh[k]);
        assert_true(std::stod(c[4]) == pn[k]);
        assert_true(std::stod(c[5]) == ph[k]);
        peak = std::max(peak, dh[k]);
    }
    assert_true(peak > 0);
    cw_wear_profile_totals t;
    cw_wear_profile_totals_init(&t);
    cw_wear_profile_get_totals(local, &t);
    assert_true(j.num("passes") == 1000.0);
    assert_true(j.num("volume_m2") == t.volume);
    assert_true(j.num("peak_depth_height_m") == peak);
    assert_close(j.num("mass_kg"), t.volume * 7800.0, 1e-15, 0.0); // per metre of rail
    assert_string_equal(j.at("body").string.c_str(), "rail");
    const auto st = read_csv(out + "/states.csv");
    assert_int_equal(st.size(), 4);
    assert_string_equal(st[0][1].c_str(), "s0_m");
    assert_string_equal(st[0][14].c_str(), "mass_per_distance_kg_per_m");
    assert_string_equal(st[2][0].c_str(), "5"); // the file's line of the second state
    cw_wear_profile_destroy(local);
    cw_wear_profile_destroy(par);
    cw_wear_destroy(w);
    cw_solver_destroy(sv);
}

// A wheel: distance becomes revolutions distance / (2 pi R), and the mass is
// One rolling speed for Archard's map: a V column (the solve's V) without
// --speed gives the profile of --speed given the same, byte for byte; a row
// whose speed and V columns differ is refused naming its line.
void wear_speed_from_V(void**)
{
    const char* const rows = "s0,a,b,N,xi_x,xi_y,spin,passes%s\n"
                             "0.001,6e-3,4e-3,60e3,1e-3,-5e-4,0.5,200%s\n"
                             "-0.003,5e-3,3e-3,70e3,5e-4,1e-3,4.0,300%s\n";
    char with_V[256], without[256];
    std::snprintf(with_V, sizeof with_V, rows, ",V", ",25", ",25");
    std::snprintf(without, sizeof without, rows, "", "", "");
    const std::vector<std::string> common = {"--nx", "12", "--ny", "10", "--law", "archard",
                                             "--no-plots"};
    const std::string from_V = g_tools.scratch + "/from_V", given = g_tools.scratch + "/given";
    cli_ok(with({"wear", "--in", scratch_file("states_v.csv", with_V), "--out", from_V}, common));
    cli_ok(with({"wear", "--in", scratch_file("states_nov.csv", without), "--out", given,
                 "--speed", "25"},
                common));
    const auto a = read_csv(from_V + "/wear_profile.csv"), b = read_csv(given + "/wear_profile.csv");
    assert_true(a == b);
    bool worn = false;
    for (size_t k = 1; k < a.size(); ++k) worn |= std::stod(a[k][2]) > 0.0;
    assert_true(worn);
    const std::string both = scratch_file("states_speed_V.csv",
                                          "s0,a,b,N,xi_x,passes,speed,V\n"
                                          "0.001,6e-3,4e-3,60e3,1e-3,200,25,30\n");
    const Run r = cli({"wear", "--in", both, "--out", g_tools.scratch + "/never_v", "--nx", "12",
                       "--ny", "10", "--law", "archard", "--no-plots"});
    expect_refusal(r, 2, "line 2", "a row with speed 25 and V 30");
    expect_contains(r.err, "V 30");
}

// per wheel: sum of passes x mass per revolution.
void wear_wheel_distance(void**)
{
    const std::string in = scratch_file("wheel.csv", "s0,a,b,N,xi_x,spin,distance\n"
                                                   "0.0,6e-3,4e-3,60e3,1e-3,0.5,1000\n"
                                                   "0.002,6e-3,4e-3,60e3,2e-3,0.5,500\n");
    const Run r = cli_ok({"wear", "--in", in, "--out", g_tools.scratch + "/wheel", "--body", "wheel",
                          "--wheel-radius", "0.46", "--no-plots", "--format", "json"});
    const Json j = parse_json(r.out);
    const double rev = 2.0 * M_PI * 0.46;
    assert_close(j.num("passes"), 1500.0 / rev, 1e-14, 0.0);
    const auto st = read_csv(g_tools.scratch + "/wheel/states.csv");
    double mass = 0;
    for (size_t k = 1; k < st.size(); ++k) {
        const double passes = std::stod(st[k][9]);
        assert_close(std::stod(st[k][15]), std::stod(st[k][14]) * rev, 1e-14, 0.0);
        mass += passes * std::stod(st[k][15]);
    }
    assert_close(j.num("mass_kg"), mass, 1e-14, 0.0);
    assert_string_equal(j.at("body").string.c_str(), "wheel");
    // The worn volume over the circumference is that mass / density.
    assert_close(j.num("volume_m2") * rev * 7800.0, mass, 1e-12, 0.0);
}

struct Bad {
    std::vector<std::string> args;
    std::string names; // what the single stderr line must contain
};

void wear_bad_inputs_fail_cleanly(void**)
{
    const std::string good = scratch_file("good.csv", kStates);
    const auto file = [](const std::string& name, const std::string& text) {
        return scratch_file(name, text);
    };
    const std::string never = g_tools.scratch + "/never";
    const std::string earlier = g_tools.scratch + "/earlier";
    cli_ok({"wear", "--in", good, "--out", earlier, "--no-plots"});
    const std::vector<Bad> bad = {
        {{"wear", "--out", never}, "--in"},
        {{"wear", "--in", good}, "--out"},
        {{"wear", "--in", g_tools.scratch + "/missing.csv", "--out", never}, "cannot open"},
        {{"wear", "--in", file("empty.csv", ""), "--out", never}, "no header"},
        {{"wear", "--in", file("head.csv", "s0,a,b,N,passes\n"), "--out", never},
         "no contact states"},
        {{"wear", "--in", file("col.csv", "s0,a,b,N,pases\n0,6e-3,4e-3,6e4,1\n"), "--out", never},
         "did you mean passes?"},
        {{"wear", "--in", file("noN.csv", "s0,a,b,passes\n0,6e-3,4e-3,1\n"), "--out", never},
         "lacks the required column(s) N"},
        {{"wear", "--in", file("num.csv", "s0,a,b,N,passes\n0,6e-3,abc,6e4,1\n"), "--out", never},
         "line 2, column b"},
        {{"wear", "--in", file("nan.csv", "s0,a,b,N,passes\n0,6e-3,nan,6e4,1\n"), "--out", never},
         "column b"},
        {{"wear", "--in", file("cells.csv", "s0,a,b,N,passes\n0,6e-3,4e-3\n"), "--out", never},
         "line 2 has 3 fields, the header 5"},
        {{"wear", "--in", file("nopass.csv", "s0,a,b,N\n0,6e-3,4e-3,6e4\n"), "--out", never},
         "passes"},
        {{"wear", "--in", file("dist.csv", "s0,a,b,N,distance\n0,6e-3,4e-3,6e4,10\n"), "--out",
          never},
         "column distance: is for a wheel"},
        {{"wear", "--in", file("dist2.csv", "s0,a,b,N,distance\n0,6e-3,4e-3,6e4,10\n"), "--out",
          never, "--body", "wheel"},
         "--wheel-radius"},
        {{"wear", "--in", file("neg.csv", "s0,a,b,N,passes\n0,6e-3,-4e-3,6e4,1\n"), "--out", never},
         "line 2, column b: must be > 0 (got -0.004 m)"},
        {{"wear", "--in", file("ang.csv", "s0,a,b,N,passes,contact_angle\n0,6e-3,4e-3,6e4,1,2\n"),
          "--out", never},
         "contact_angle"},
        {{"wear", "--in", file("pneg.csv", "s0,a,b,N,passes\n0,6e-3,4e-3,6e4,-1\n"), "--out",
          never},
         "passes"},
        {{"wear", "--in", file("model.csv", "s0,a,b,N,passes,model\n0,6e-3,4e-3,6e4,1,magic\n"),
          "--out", never},
         "column model"},
        {{"wear", "--in", good, "--out", never, "--law", "archard"}, "--speed"},
        {{"wear", "--in", good, "--out", never, "--law", "archerd"}, "did you mean archard?"},
        {{"wear", "--in", good, "--out", never, "--speed", "-3"}, "--speed"},
        {{"wear", "--in", good, "--out", never, "--hardness", "2e9"}, "--hardness"},
        {{"wear", "--in", good, "--out", never, "--density", "0"}, "--density"},
        {{"wear", "--in", good, "--out", never, "--wheel-radius", "0.46"}, "--wheel-radius"},
        {{"wear", "--in", good, "--out", never, "--profile-step", "0"}, "--profile-step"},
        {{"wear", "--in", good, "--out", never, "--profile-from", "1", "--profile-to", "0"},
         "--profile-to"},
        {{"wear", "--in", good, "--out", never, "--nx", "0"}, "--nx"},
        {{"wear", "--in", good, "--out", never, "--plot-sign", "rail"}, "--plot-sign"},
        {{"wear", "--in", good, "--out", earlier}, "--force"},
    };
    for (const Bad& b : bad) {
        std::string shown = "creepwork";
        for (const std::string& a : b.args) shown += " " + a;
        expect_refusal(cli(b.args), 2, b.names, shown);
        assert_false(fs::exists(never));
    }
    for (const auto& e : fs::directory_iterator(g_tools.scratch))
        assert_true(e.path().filename().string().find(".tmp-") == std::string::npos);
    // --force replaces the earlier output.
    cli_ok({"wear", "--in", good, "--out", earlier, "--no-plots", "--force"});
}

// Values the library accepts but a wheel-rail contact never has are warned
// about, naming the line and column; the run succeeds.
void wear_warns_about_implausible_values(void**)
{
    const std::string in = scratch_file("odd.csv", "s0,a,b,N,passes,contact_angle\n"
                                                 "0,6e-3,4e-3,60,1,0\n"
                                                 "0.5,6e-3,4e-3,6e4,1,0\n"
                                                 "0,6e-3,4e-3,6e4,1,1.4\n");
    const Run r = cli_ok({"wear", "--in", in, "--out", g_tools.scratch + "/odd", "--no-plots"});
    assert_non_null(std::strstr(r.err.c_str(), "line 2: column N = 60"));
    assert_non_null(std::strstr(r.err.c_str(), "line 3: column s0 = 0.5"));
    assert_non_null(std::strstr(r.err.c_str(), "line 4: column contact_angle = 1.4"));
}

// A campaign's file feeds creepwork wear: the campaign's id (ignored, with
// a note), its column names (phi for spin) and its grid columns; the
// profile and the states are those of the same states in wear's own
// spelling with the grid given as options. A bad value is named with the
// value as written.
void wear_reads_campaign_files(void**)
{
    const std::string campaign = scratch_file(
        "campaign.csv", "id,model,grid,nx,ny,a,b,N,mu,G,nu,xi_x,xi_y,phi,s0,passes\n"
                        "t1,fastsim,strips,12,10,6e-3,4e-3,60e3,0.3,82e9,0.28,1e-3,-5e-4,0.5,0.001,200\n"
                        "t2,fastsim,strips,12,10,5e-3,3e-3,70e3,0.35,82e9,0.28,5e-4,1e-3,4.0,-0.003,300\n");
    const std::string own = scratch_file("own.csv", "s0,a,b,N,xi_x,xi_y,spin,passes,mu\n"
                                                    "0.001,6e-3,4e-3,60e3,1e-3,-5e-4,0.5,200,0.3\n"
                                                    "-0.003,5e-3,3e-3,70e3,5e-4,1e-3,4.0,300,0.35\n");
    const Run r = cli_ok({"wear", "--in", campaign, "--out", path("campaign"), "--no-plots"});
    expect_contains(r.err, "campaign.csv: column id not read by creepwork wear: ignored");
    cli_ok({"wear", "--in", own, "--out", path("own"), "--nx", "12", "--ny", "10", "--no-plots"});
    assert_true(slurp(path("campaign/wear_profile.csv")) == slurp(path("own/wear_profile.csv")));
    assert_true(slurp(path("campaign/states.csv")) == slurp(path("own/states.csv")));
    // Rows on different grids cannot share one profile solver.
    const std::string grids = scratch_file(
        "grids.csv", "s0,a,b,N,nx,passes\n0,6e-3,4e-3,6e4,12,1\n0,6e-3,4e-3,6e4,14,1\n");
    expect_refusal(cli({"wear", "--in", grids, "--out", path("never"), "--no-plots"}), 2,
                   "line 3, column grid/nx/ny: gives the grid kalker_strips 14 x 20, line 2 kalker_strips 12 x 20",
                   "wear grids.csv");
    // The value that is wrong, as written.
    const std::string negative =
        scratch_file("negative.csv", "s0,a,b,N,xi_x,passes\n0.0,6e-3,4e-3,60e3,0.001,-5\n");
    expect_refusal(cli({"wear", "--in", negative, "--out", path("never"), "--no-plots"}), 2,
                   "negative.csv line 2, column passes: must lie in [0, 1e15] (got -5)",
                   "wear negative.csv");
    assert_false(exists(path("never")));
}

// The unit mistakes a campaign warns about get the same words from wear.
void wear_warns_like_solve(void**)
{
    const std::string in = scratch_file("mm.csv", "s0,a,b,N,passes\n0,7.2,5.4,100e3,1\n");
    const Run r = cli_ok({"wear", "--in", in, "--out", path("mm"), "--no-plots"});
    expect_contains(r.err, "warning: line 2: column a = 7.2 m is implausible for a wheel-rail "
                           "contact: semi-axes are 1-20 mm (were millimetres typed as metres?");
    const Run solve = cli_ok({"solve", "--a", "7.2", "--b", "5.4", "--N", "100e3"});
    expect_contains(solve.err, "warning: --a = 7.2 m is implausible for a wheel-rail contact: "
                               "semi-axes are 1-20 mm (were millimetres typed as metres?");
}

// The picture: written with its script, unless gnuplot is missing.
void wear_writes_picture(void**)
{
    if (std::getenv("CW_TEST_NO_GNUPLOT")) {
        cw_skip();
        return;
    }
    const std::string in = scratch_file("pic.csv", kStates);
    const std::string out = g_tools.scratch + "/pic";
    cli_ok({"wear", "--in", in, "--out", out});
    assert_true(fs::file_size(out + "/wear.png") > 10000);
    assert_true(fs::exists(out + "/gnuplot/wear.gp"));
    assert_non_null(std::strstr(slurp(out + "/gnuplot/wear.gp").c_str(), "parabol"));
}

} // namespace

int main(int argc, char** argv)
{
    if (!set_up(argc, argv, "test_cli_wear", {"creepwork", "scratch"})) return 2;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(wear_matches_library),
        cmocka_unit_test(wear_wheel_distance),
        cmocka_unit_test(wear_speed_from_V),
        cmocka_unit_test(wear_bad_inputs_fail_cleanly),
        cmocka_unit_test(wear_warns_about_implausible_values),
        cmocka_unit_test(wear_writes_picture),
        cmocka_unit_test(wear_reads_campaign_files),
        cmocka_unit_test(wear_warns_like_solve),
    };
    return cw_run_tests(tests, g_tools.test);
}
