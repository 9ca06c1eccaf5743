/* Tests of the CLI's model switch and of creepwork compare, run as a user
 * would run them:
 *   - solve --model exact --format json gives the C ABI's numbers bit for bit
 *     for the same inputs on the grid the CLI documents as the exact model's
 *     default (uniform, 24 x 24, box 1.2), and the new JSON keys;
 *   - invalid model inputs fail with status 2 and one stderr line naming the
 *     option; the calibrated model's library error is shown cleanly;
 *   - solve --model exact --out: adhesion at the leading edge, slip at the
 *     trailing edge, work zero in adhesion, no exterior element drawn;
 *   - compare: both models' totals equal the C ABI's, and every distribution
 *     metric equals an independent computation from the fields and profiles
 *     it writes; the Fig. 6 contact on CONTACT's 20-across layout holds the
 *     numbers doc/theory/exact.md quotes;
 *   - compare --simplified: the calibrated model's totals are solve --model
 *     calibrated's on the same grid to the bit, its map distances equal the
 *     ones recomputed from the fields it writes; --simplified all gives each
 *     of the three models the metrics it gets alone, and the work-map picture.
 *
 * usage: test_cli_models <creepwork binary> <scratch dir> [cmocka filter] */
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

// One contact given as CLI options and as the structs the library sees.
struct Contact {
    std::vector<std::string> args;
    cw_params params;
    cw_grid grid;
};

Contact spin_contact(int model)
{
    Contact c;
    cw_params_init(&c.params);
    cw_grid_init(&c.grid);
    c.args = {"--a",  "0.007",  "--b",    "0.004",  "--N",    "70000", "--mu",
              "0.5",  "--G",    "8e10",   "--nu",   "0.3",    "--xi-x", "0.0012",
              "--xi-y", "0.0008", "--spin", "1.0"};
    c.params.a = 0.007, c.params.b = 0.004, c.params.normal_force = 70000, c.params.mu = 0.5;
    c.params.G = 8e10, c.params.nu = 0.3;
    c.params.xi_x = 0.0012, c.params.xi_y = 0.0008, c.params.phi = 1.0;
    c.params.model = model;
    return c;
}

void same(double cli, double lib, const char* what)
{
    if (cli != lib) print_error("%s: CLI %.17g, library %.17g\n", what, cli, lib);
    assert_true(cli == lib);
}

/* ------------------------------------------------------------ solve --model */

// The calibrated model through the CLI is the library's calibrated model on the
// CLI's default grid (Kalker strips 20 x 20), to the last bit.
void solve_calibrated_matches_library(void**)
{
    Contact c = spin_contact(CW_MODEL_CALIBRATED);
    c.grid.kind = CW_GRID_KALKER_STRIPS, c.grid.nx = 20, c.grid.ny = 20;
    const Json j = parse_or_fail(
        cli_ok(with({"solve", "--model", "calibrated", "--format", "json"}, c.args)).out);
    const cw_result lib = library_solve(c.grid, c.params);
    same(j.num("Fx"), lib.Fx, "Fx");
    same(j.num("Fy"), lib.Fy, "Fy");
    same(j.num("Mz"), lib.Mz, "Mz");
    same(j.num("W_macro"), lib.W_macro, "W_macro");
    // Not FASTSIM's answer: the calibrated moment differs (doc/theory/calibrated.md).
    c.params.model = CW_MODEL_FASTSIM;
    assert_true(library_solve(c.grid, c.params).Mz != lib.Mz);
}

void solve_exact_matches_library(void**)
{
    Contact c = spin_contact(CW_MODEL_EXACT);
    // The documented default grid of --model exact: CONTACT's layout.
    c.grid.kind = CW_GRID_UNIFORM, c.grid.nx = 24, c.grid.ny = 24, c.grid.box_scale = 1.2;
    const Json j = parse_or_fail(cli_ok(with({"solve", "--model", "exact", "--format", "json"},
                                             c.args)).out);
    const cw_result lib = library_solve(c.grid, c.params);
    const struct {
        const char* key;
        double value;
    } expect[] = {{"Fx", lib.Fx},           {"Fy", lib.Fy},
                  {"Mz", lib.Mz},           {"W_macro", lib.W_macro},
                  {"W_micro_paper", lib.W_micro_paper}, {"K", lib.K},
                  {"W_consistent", lib.W_consistent}, {"p_max", lib.p_max},
                  {"approach", lib.approach}, {"residual", lib.residual},
                  {"adhesion_fraction", lib.adhesion_fraction}};
    for (const auto& e : expect) same(j.num(e.key), e.value, e.key);
    assert_int_equal(static_cast<int>(j.num("iterations")), lib.iterations);
    assert_true(lib.iterations > 0);
    assert_int_equal(static_cast<int>(j.num("n_slip")), lib.n_slip);
    assert_string_equal(j.at("model").string.c_str(), "exact");
    const Json& in = j.at("input");
    assert_string_equal(in.at("grid").string.c_str(), "uniform");
    assert_int_equal(static_cast<int>(in.num("nx")), 24);
    assert_int_equal(static_cast<int>(in.num("ny")), 24);
    assert_true(in.num("box_scale") == 1.2);
    assert_string_equal(in.at("model").string.c_str(), "exact");
    // The exact pressure is near Hertz's peak 3N/(2 pi a b) (Kalker 1990;
    // CONTACT: 1226.8 of 1229.3 N/mm^2 at 20 across, doc/theory/exact.md).
    const double p0 = 1.5 * 70000 / (M_PI * 0.007 * 0.004);
    assert_close(j.num("p_max"), p0, 0.01, 0.0);
    // Given options reach the library: tolerance, iteration bound, grid.
    Contact t = c;
    t.grid.nx = 16, t.grid.ny = 14, t.grid.box_scale = 1.1;
    t.params.tolerance = 1e-11, t.params.max_iterations = 40;
    const Json k = parse_or_fail(cli_ok(with({"solve", "--model", "exact", "--format", "json",
                                              "--tolerance", "1e-11", "--max-iterations", "40",
                                              "--grid", "uniform", "--nx", "16", "--ny", "14",
                                              "--box-scale", "1.1"},
                                             t.args)).out);
    const cw_result tight = library_solve(t.grid, t.params);
    same(k.num("Fx"), tight.Fx, "Fx (tolerance 1e-11)");
    same(k.num("Mz"), tight.Mz, "Mz (tolerance 1e-11)");
    assert_true(k.num("residual") <= 1e-11);
    // FASTSIM says so, and has no iterations.
    const Json f = parse_or_fail(cli_ok(with({"solve", "--model", "fastsim", "--format", "json"},
                                             c.args)).out);
    assert_string_equal(f.at("model").string.c_str(), "fastsim");
    assert_int_equal(static_cast<int>(f.num("iterations")), 0);
    assert_true(f.num("residual") == 0.0);
    assert_string_equal(f.at("input").at("grid").string.c_str(), "kalker_strips");
    // Text output names the model and the normal problem's results.
    const Run text = cli_ok(with({"solve", "--model", "exact"}, c.args));
    assert_non_null(std::strstr(text.out.c_str(), "model      exact"));
    assert_non_null(std::strstr(text.out.c_str(), "p_max = "));
}

struct Bad {
    std::vector<std::string> args;
    const char* names; // must appear in the one stderr line
};

void model_bad_inputs_fail_cleanly(void**)
{
    const std::vector<std::string> contact = {"--a", "0.007", "--b", "0.005", "--N", "90000"};
    const std::vector<Bad> bad = {
        {{"solve", "--model", "foo"}, "--model"},
        {{"solve", "--model", "exct"}, "did you mean exact?"},
        {{"solve", "--model", "exact", "--grid", "strips"}, "--grid"},
        {{"solve", "--model", "exact", "--L1", "1e-11", "--L2", "1e-11", "--L3", "1e-11"}, "--L1"},
        {{"solve", "--model", "exact", "--pressure", "elliptic"}, "--pressure"},
        {{"solve", "--model", "exact", "--flexibility-blending"}, "--flexibility-blending"},
        {{"solve", "--tolerance", "1e-6"}, "--tolerance"},
        {{"solve", "--max-iterations", "9"}, "--max-iterations"},
        {{"solve", "--model", "exact", "--tolerance", "0"}, "--tolerance"},
        {{"solve", "--model", "exact", "--tolerance", "1"}, "--tolerance"},
        {{"solve", "--model", "exact", "--max-iterations", "0"}, "--max-iterations"},
        {{"solve", "--model", "exact", "--nx", "300"}, "--nx"},
        {{"solve", "--model", "exact", "--ny", "257"}, "--ny"},
        // The library's own error, relayed: the calibrated model needs G and nu.
        {{"solve", "--model", "calibrated", "--L1", "1e-11", "--L2", "1e-11", "--L3", "1e-11"},
         "flexibility"},
        {{"solve", "--model", "exact", "--max-iterations", "1", "--tolerance", "1e-13", "--xi-x",
          "1e-3", "--spin", "1"},
         "--max-iterations"},
        {{"sweep", "--model", "exact", "--grid", "strips", "--out", g_tools.scratch + "/never"},
         "--grid"},
        {{"compare", "--grid", "strips"}, "--grid"},
        {{"compare", "--L1", "1e-11", "--L2", "1e-11", "--L3", "1e-11"}, "--L1"},
        {{"compare", "--pressure", "elliptic"}, "--pressure"},
        {{"compare", "--nx", "300"}, "--nx"},
        {{"compare", "--model", "exact"}, "--model"},
        {{"compare", "--simplified", "fastsm"}, "--simplified"},
        {{"compare", "--simplified", "exact"}, "--simplified"},
        {{"compar"}, "did you mean compare?"},
    };
    for (const Bad& b : bad) {
        std::vector<std::string> args = b.args;
        if (args[0] == "solve") args.insert(args.end(), contact.begin(), contact.end());
        std::string shown = "creepwork";
        for (const std::string& a : args) shown += " " + a;
        expect_refusal(cli(args), 2, b.names, shown);
    }
    assert_false(fs::exists(g_tools.scratch + "/never"));
    // The calibrated model's refusal is the library's message, not a crash or a guess;
    // with G and nu it solves.
    const Run cal = cli(
        with({"solve", "--model", "calibrated", "--L1", "1e-11", "--L2", "1e-11", "--L3", "1e-11"},
             contact));
    assert_non_null(std::strstr(cal.err.c_str(), "library rejected the input"));
    assert_non_null(std::strstr(cal.err.c_str(), "flexibility"));
}

// Adhesion where material enters (leading edge), slip where it leaves,
// frictional work only in slip: the exact model's fields as written, and
// the pictures drawn from them without the exterior elements.
void solve_exact_writes_fields_and_pictures(void**)
{
    const std::string dir = g_tools.scratch + "/exact_out";
    const Contact c = spin_contact(CW_MODEL_EXACT);
    std::vector<std::string> args = with({"solve", "--model", "exact", "--out", dir}, c.args);
    const bool pictures = !std::getenv("CW_TEST_NO_GNUPLOT");
    if (!pictures) args.push_back("--no-plots");
    cli_ok(args);
    const auto rows = read_numbers(dir + "/fields.csv"); // i,j,x,y,area,state,...,work_consistent
    assert_int_equal(rows.size(), 24u * 24u);
    const int nx = 24, ny = 24;
    int slip = 0, adhesion = 0;
    for (const auto& r : rows) {
        const int state = static_cast<int>(r[5]);
        if (state == CW_STATE_EXTERIOR) assert_true(r[4] == 0.0); // area
        if (state == CW_STATE_ADHESION) {
            ++adhesion;
            assert_true(r[13] == 0.0); // energy-consistent work
            assert_true(r[12] == 0.0); // frictional power
        }
        if (state == CW_STATE_SLIP) {
            ++slip;
            assert_true(r[13] >= 0.0);
        }
    }
    assert_true(slip > 0 && adhesion > 0);
    // Middle rows: the trailing contact element slips, and the leading part
    // adheres -- the element at x = +a/2 (the very edge elements, with almost
    // no pressure, may slip).
    for (int j = ny / 2 - 2; j < ny / 2 + 2; ++j) {
        int trail = -1, half = -1;
        for (int i = 0; i < nx; ++i) {
            const auto& r = rows[i + j * nx];
            if (r[5] != CW_STATE_EXTERIOR && trail < 0) trail = i;
            if (half < 0 && r[2] >= 0.5 * 0.007) half = i;
        }
        assert_int_equal(static_cast<int>(rows[trail + j * nx][5]), CW_STATE_SLIP);
        assert_int_equal(static_cast<int>(rows[half + j * nx][5]), CW_STATE_ADHESION);
    }
    if (!pictures) return;
    for (const char* png : {"patch.png", "slip_adhesion.png", "work.png", "profile.png"}) {
        const std::string data = slurp(dir + "/" + png);
        assert_true(data.size() > 5000 && data.compare(0, 4, "\x89PNG") == 0);
    }
    // Only contact elements are drawn: one patch.dat row per contact
    // element, and the area field is 0 outside the contact (creepwork.h).
    std::ifstream dat(dir + "/gnuplot/patch.dat");
    std::string line;
    int drawn = 0;
    while (std::getline(dat, line))
        if (!line.empty() && line[0] != '#') ++drawn;
    assert_int_equal(drawn, slip + adhesion);
}

// sweep --model exact: the exact model on the uniform grid the CLI documents
// (--nx/--ny given, so 12 x 12 over 1.2 a x 1.2 b), from almost full
// adhesion to full slip; a panel's forces equal a cold C ABI solve to the
// solver tolerance (the sweep warm-starts one handle: doc/theory/exact.md,
// warm and cold agree to ~1e-10 of |F|).
void sweep_exact_model(void**)
{
    const std::string dir = g_tools.scratch + "/sweep";
    const Json j = parse_or_fail(cli_ok({"sweep", "--model", "exact", "--nx", "12", "--ny", "12",
                                         "--format", "json", "--no-plots", "--out", dir})
                                     .out);
    const auto& cases = j.at("cases").array;
    assert_true(cases.size() >= 24);
    assert_true(cases.front().num("adhesion_fraction") > 0.9);
    double last_fig2 = 1;
    const Json* probe = nullptr;
    for (const Json& c : cases)
        if (c.at("figure").string == "fig2") {
            last_fig2 = c.num("adhesion_fraction");
            if (!probe && last_fig2 < 0.6) probe = &c; // a partial-slip panel
        }
    assert_true(last_fig2 == 0.0);
    assert_non_null(probe);
    // sweep's default contact (its --help): the paper's Fig. 6 contact.
    cw_params p;
    cw_params_init(&p);
    p.model = CW_MODEL_EXACT;
    p.a = 6.6323e-3, p.b = p.a / 2, p.normal_force = 10000 * 4.4482216152605, p.mu = 0.6;
    p.G = 82e9, p.nu = 0.3;
    p.xi_x = probe->num("xi_x"), p.xi_y = probe->num("xi_y"), p.phi = probe->num("spin");
    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_UNIFORM, g.nx = 12, g.ny = 12, g.box_scale = 1.2;
    const cw_result r = library_solve(g, p);
    const double F = std::hypot(r.Fx, r.Fy);
    assert_close(probe->num("Fx"), r.Fx, 0.0, 1e-7 * F);
    assert_close(probe->num("Fy"), r.Fy, 0.0, 1e-7 * F);
    assert_close(probe->num("adhesion_fraction"), r.adhesion_fraction, 0.0, 1e-12);
}

/* ---------------------------------------------------------------- compare */

double sum(const std::vector<double>& v)
{
    double s = 0;
    for (double x : v) s += x;
    return s;
}

double l1(const std::vector<double>& a, const std::vector<double>& b)
{
    const double ta = sum(a), tb = sum(b);
    double d = 0;
    for (size_t k = 0; k < a.size(); ++k) d += std::fabs(a[k] / ta - b[k] / tb);
    return d;
}

void compare_metrics_from_its_files(void**)
{
    const std::string dir = g_tools.scratch + "/compare";
    const Contact c = spin_contact(CW_MODEL_EXACT);
    const Json j = parse_or_fail(cli_ok(with({"compare", "--nx", "20", "--ny", "18",
                                              "--box-scale", "1.15", "--format", "json",
                                              "--no-plots", "--out", dir},
                                             c.args)).out);
    // Totals: the C ABI's for each model on the same grid.
    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_UNIFORM, g.nx = 20, g.ny = 18, g.box_scale = 1.15;
    cw_params pf = c.params;
    pf.model = CW_MODEL_FASTSIM;
    const cw_result rf = library_solve(g, pf), re = library_solve(g, c.params);
    const Json &jf = j.at("fastsim"), &je = j.at("exact");
    for (const auto& [key, lf, le] :
         {std::tuple<const char*, double, double>{"Fx", rf.Fx, re.Fx}, {"Fy", rf.Fy, re.Fy},
          {"Mz", rf.Mz, re.Mz}, {"W_macro", rf.W_macro, re.W_macro}, {"K", rf.K, re.K}}) {
        same(jf.num(key), lf, key);
        same(je.num(key), le, key);
    }
    assert_string_equal(jf.at("model").string.c_str(), "fastsim");
    assert_string_equal(je.at("model").string.c_str(), "exact");
    // totals.csv: the same numbers, one row per model.
    const auto totals = read_numbers(dir + "/totals.csv");
    assert_int_equal(totals.size(), 2);
    same(totals[0][1], rf.Fx, "totals.csv FASTSIM Fx");
    same(totals[1][3], re.Mz, "totals.csv exact Mz");
    same(totals[1][6], re.K, "totals.csv exact K");
    // Every metric again from the fields and profiles compare wrote.
    const auto ff = read_numbers(dir + "/fastsim/fields.csv");
    const auto fe = read_numbers(dir + "/exact/fields.csv");
    const auto pfp = read_numbers(dir + "/fastsim/profile.csv");
    const auto pep = read_numbers(dir + "/exact/profile.csv");
    assert_int_equal(ff.size(), 360);
    assert_int_equal(fe.size(), 360);
    std::vector<double> wf, we, df, de, prof_f, prof_e;
    double in_f_adh = 0, f_in_e_adh = 0, mf = 0, me = 0;
    int differ = 0;
    for (size_t k = 0; k < ff.size(); ++k) {
        // One grid: the same element centres (each model computes its own, to rounding).
        assert_close(ff[k][2], fe[k][2], 1e-14, 0.0);
        assert_close(ff[k][3], fe[k][3], 1e-14, 0.0);
        wf.push_back(ff[k][13]), we.push_back(fe[k][13]);
        df.push_back(ff[k][12]), de.push_back(fe[k][12]);
        const int sf = static_cast<int>(ff[k][5]), se = static_cast<int>(fe[k][5]);
        if (sf == CW_STATE_ADHESION) in_f_adh += fe[k][12];
        if (se == CW_STATE_ADHESION) f_in_e_adh += ff[k][13];
        if (sf != 0 && se != 0 && sf != se) ++differ;
        mf += ff[k][13] * ff[k][2];
        me += fe[k][13] * fe[k][2];
    }
    for (const auto& r : pfp) prof_f.push_back(r[2]);
    for (const auto& r : pep) prof_e.push_back(r[2]);
    const Json& m = j.at("metrics");
    const double a = je.num("a");
    const struct {
        const char* key;
        double independent;
    } expect[] = {{"map_l1_consistent", l1(wf, we)},
                  {"map_l1_paper", l1(df, de)},
                  {"profile_l1", l1(prof_f, prof_e)},
                  {"exact_power_in_fastsim_adhesion", in_f_adh / sum(de)},
                  {"fastsim_work_in_exact_adhesion", f_in_e_adh / sum(wf)},
                  {"centroid_fastsim", mf / (sum(wf) * a)},
                  {"centroid_exact", me / (sum(we) * a)}};
    for (const auto& e : expect) {
        if (!(std::fabs(m.num(e.key) - e.independent) <= 1e-12 * (1 + std::fabs(e.independent))))
            print_error("%s: CLI %.17g, independent %.17g\n", e.key, m.num(e.key), e.independent);
        assert_close(m.num(e.key), e.independent, 1e-12, 1e-12);
    }
    assert_int_equal(static_cast<int>(m.num("state_differences")), differ);
    // The energy-consistent maps sum to each model's W_macro (doc/theory/work.md).
    assert_close(sum(wf), rf.W_macro, 1e-12, 0.0);
    assert_close(sum(we), re.W_macro, 1e-12, 0.0);
    // Metrics in range: L1 of unit-total maps lies in [0, 2], shares in [0, 1].
    for (const char* key : {"map_l1_consistent", "map_l1_paper", "profile_l1"})
        assert_true(m.num(key) > 0.0 && m.num(key) < 2.0);
    assert_true(m.num("exact_power_in_fastsim_adhesion") >= 0.0 &&
                m.num("exact_power_in_fastsim_adhesion") <= 1.0);
}

// The map distances of compare's metrics object, recomputed from the fields
// and profiles it wrote in dir/<label>/ and dir/exact/.
void metrics_match_files(const Json& m, const std::string& dir, const std::string& label)
{
    const auto fs_ = read_numbers(dir + "/" + label + "/fields.csv");
    const auto fe = read_numbers(dir + "/exact/fields.csv");
    const auto ps = read_numbers(dir + "/" + label + "/profile.csv");
    const auto pe = read_numbers(dir + "/exact/profile.csv");
    assert_int_equal(fs_.size(), fe.size());
    std::vector<double> ws, we, ds, de, prof_s, prof_e;
    for (size_t k = 0; k < fs_.size(); ++k) {
        ws.push_back(fs_[k][13]), we.push_back(fe[k][13]);
        ds.push_back(fs_[k][12]), de.push_back(fe[k][12]);
    }
    for (const auto& r : ps) prof_s.push_back(r[2]);
    for (const auto& r : pe) prof_e.push_back(r[2]);
    const struct {
        const char* key;
        double independent;
    } expect[] = {{"map_l1_consistent", l1(ws, we)},
                  {"map_l1_paper", l1(ds, de)},
                  {"profile_l1", l1(prof_s, prof_e)}};
    for (const auto& e : expect) {
        if (!(std::fabs(m.num(e.key) - e.independent) <= 1e-12 * (1 + e.independent)))
            print_error("%s %s: CLI %.17g, independent %.17g\n", label.c_str(), e.key,
                        m.num(e.key), e.independent);
        assert_close(m.num(e.key), e.independent, 1e-12, 1e-12);
        assert_true(e.independent > 0.0 && e.independent < 2.0);
    }
}

const std::vector<std::string> kCompareGrid = {"--nx", "20", "--ny", "18", "--box-scale", "1.15"};

// compare --simplified calibrated: the calibrated side is exactly what solve
// --model calibrated gives on the same uniform grid (and the C ABI), and its
// metrics are recomputed from its files.
void compare_simplified_calibrated(void**)
{
    const std::string dir = g_tools.scratch + "/calibrated";
    const Contact c = spin_contact(CW_MODEL_EXACT);
    const Json j = parse_or_fail(
        cli_ok(with(with({"compare", "--simplified", "calibrated", "--format", "json",
                          "--no-plots", "--out", dir},
                         kCompareGrid),
                    c.args))
            .out);
    assert_false(j.has("fastsim"));
    const Json& jc = j.at("calibrated");
    assert_string_equal(jc.at("model").string.c_str(), "calibrated");
    const Json solo = parse_or_fail(
        cli_ok(with(with({"solve", "--model", "calibrated", "--grid", "uniform", "--format",
                          "json"},
                         kCompareGrid),
                    c.args))
            .out);
    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_UNIFORM, g.nx = 20, g.ny = 18, g.box_scale = 1.15;
    cw_params pc = c.params;
    pc.model = CW_MODEL_CALIBRATED;
    const cw_result lib = library_solve(g, pc);
    for (const auto& [key, value] :
         {std::pair<const char*, double>{"Fx", lib.Fx}, {"Fy", lib.Fy}, {"Mz", lib.Mz},
          {"W_macro", lib.W_macro}, {"W_consistent", lib.W_consistent},
          {"adhesion_fraction", lib.adhesion_fraction}}) {
        same(jc.num(key), solo.num(key), key);
        same(jc.num(key), value, key);
    }
    // totals.csv: calibrated then exact, by label.
    const std::string totals = slurp(dir + "/totals.csv");
    assert_non_null(std::strstr(totals.c_str(), "\ncalibrated,"));
    assert_non_null(std::strstr(totals.c_str(), "\nexact,"));
    same(read_numbers(dir + "/totals.csv")[0][3], lib.Mz, "totals.csv calibrated Mz");
    metrics_match_files(j.at("metrics"), dir, "calibrated");
    // Not FASTSIM's distribution (doc/theory/calibrated.md: its moment differs).
    const Json f = parse_or_fail(
        cli_ok(with(with({"compare", "--format", "json"}, kCompareGrid), c.args)).out);
    assert_true(f.at("fastsim").num("Mz") != jc.num("Mz"));
    assert_true(f.at("metrics").num("map_l1_consistent") !=
                j.at("metrics").num("map_l1_consistent"));
}

// compare --simplified all: three simplified models and exact in one run;
// each model's metrics are those it gets alone, and the work maps are drawn.
void compare_simplified_all(void**)
{
    const std::string dir = g_tools.scratch + "/all";
    const Contact c = spin_contact(CW_MODEL_EXACT);
    std::vector<std::string> args =
        with(with({"compare", "--simplified", "all", "--format", "json", "--out", dir},
                  kCompareGrid),
             c.args);
    const bool plots = !std::getenv("CW_TEST_NO_GNUPLOT");
    if (!plots) args.push_back("--no-plots");
    const Json j = parse_or_fail(cli_ok(args).out);
    const struct {
        const char* option;
        const char* label;
        int model, pressure;
    } models[] = {{"fastsim", "fastsim", CW_MODEL_FASTSIM, CW_PRESSURE_PARABOLIC},
                  {"fastsim-elliptic", "fastsim_elliptic", CW_MODEL_FASTSIM, CW_PRESSURE_ELLIPTIC},
                  {"calibrated", "calibrated", CW_MODEL_CALIBRATED, CW_PRESSURE_PARABOLIC}};
    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_UNIFORM, g.nx = 20, g.ny = 18, g.box_scale = 1.15;
    const cw_result exact = library_solve(g, c.params);
    same(j.at("exact").num("Mz"), exact.Mz, "exact Mz");
    for (const auto& m : models) {
        cw_params p = c.params;
        p.model = m.model, p.pressure = m.pressure;
        const cw_result lib = library_solve(g, p);
        same(j.at(m.label).num("Fx"), lib.Fx, m.label);
        same(j.at(m.label).num("Mz"), lib.Mz, m.label);
        same(j.at(m.label).num("W_macro"), lib.W_macro, m.label);
        const Json alone = parse_or_fail(
            cli_ok(with(with({"compare", "--simplified", m.option, "--format", "json"},
                             kCompareGrid),
                        c.args))
                .out);
        const Json& mine = j.at("metrics").at(m.label);
        for (const char* key : {"map_l1_consistent", "map_l1_paper", "profile_l1",
                                "exact_power_in_fastsim_adhesion", "centroid_fastsim"})
            same(mine.num(key), alone.at("metrics").num(key), key);
        metrics_match_files(mine, dir, m.label);
    }
    // The elliptic bound changes FASTSIM's distribution (its map median over
    // the evaluation set differs, doc/validation/calibrated.md): not the
    // parabolic one's metrics.
    assert_true(j.at("metrics").at("fastsim").num("map_l1_consistent") !=
                j.at("metrics").at("fastsim_elliptic").num("map_l1_consistent"));
    assert_int_equal(read_numbers(dir + "/totals.csv").size(), 4);
    if (!plots) return;
    const std::string data = slurp(dir + "/work_maps.png");
    if (!(data.size() > 5000 && data.compare(0, 4, "\x89PNG") == 0))
        print_error("work_maps.png is not a PNG picture\n");
    assert_true(data.size() > 5000 && data.compare(0, 4, "\x89PNG") == 0);
    // The picture's data: per element state and work of each model, exact
    // last; work only where that model slips (zero in adhesion).
    std::ifstream dat(dir + "/gnuplot/work_maps.dat");
    std::string line;
    std::getline(dat, line);
    int rows = 0;
    while (std::getline(dat, line)) {
        std::stringstream r(line);
        double v[12];
        for (double& x : v) r >> x;
        for (int m = 0; m < 4; ++m)
            if (v[4 + 2 * m] != CW_STATE_SLIP) assert_true(v[5 + 2 * m] == 0.0);
        ++rows;
    }
    assert_true(rows >= exact.n_contact);
}

// doc/theory/exact.md quotes compare's numbers for the paper's Fig. 6
// contact on CONTACT's 20-across layout (24 x 24, box 1.2): held to the
// digits printed there.
constexpr double DOC_L1_CONSISTENT = 0.456, DOC_L1_PAPER = 0.534,
                 DOC_L1_PROFILE = 0.136, DOC_EXACT_IN_FASTSIM_ADHESION = 13.7, // %
    DOC_MZ_RATIO = 0.851; // FASTSIM's Mz / exact Mz

void compare_fig6_readme_numbers(void**)
{
    std::vector<std::string> args = {"compare", "--nx", "24", "--ny", "24", "--format", "json"};
    const std::string dir = g_tools.scratch + "/fig6";
    if (!std::getenv("CW_TEST_NO_GNUPLOT")) args.insert(args.end(), {"--out", dir});
    const Json j = parse_or_fail(cli_ok(args).out);
    const Json& m = j.at("metrics");
    const auto held = [](double ours, double shown, double half_unit) {
        if (!(std::fabs(ours - shown) <= half_unit * (1 + 1e-9)))
            print_error("%.17g is not %g to the printed digits\n", ours, shown);
        assert_close(ours, shown, 0.0, half_unit * (1 + 1e-9));
    };
    held(m.num("map_l1_consistent"), DOC_L1_CONSISTENT, 5e-3);
    held(m.num("map_l1_paper"), DOC_L1_PAPER, 5e-3);
    held(m.num("profile_l1"), DOC_L1_PROFILE, 5e-3);
    held(100 * m.num("exact_power_in_fastsim_adhesion"), DOC_EXACT_IN_FASTSIM_ADHESION, 0.05);
    held(j.at("fastsim").num("Mz") / j.at("exact").num("Mz"), DOC_MZ_RATIO, 5e-3);
    if (std::getenv("CW_TEST_NO_GNUPLOT")) return;
    for (const char* png : {"compare.png", "slip_adhesion_fastsim.png", "slip_adhesion_exact.png",
                            "work_fastsim.png", "work_exact.png", "work_difference.png",
                            "profile.png"}) {
        const std::string data = slurp(dir + "/" + png);
        if (!(data.size() > 5000 && data.compare(0, 4, "\x89PNG") == 0))
            print_error("%s is not a PNG picture\n", png);
        assert_true(data.size() > 5000 && data.compare(0, 4, "\x89PNG") == 0);
    }
}

// compare's text names the contact it solved, the defaults included.
void compare_names_its_contact(void**)
{
    const Run r = cli_ok({"compare", "--nx", "12", "--ny", "12"});
    // The paper's Fig. 6 contact (a = 6.6323 mm, b = a/2, N = 10000 lbf,
    // spin 0.144 1/ft) in SI, as the values read back.
    expect_contains(r.out, "contact: a = 0.0066323 m, b = 0.00331615 m, N = " +
                               round_trip(10000 * 4.4482216152605) + " N, mu = 0.6, G = " +
                               round_trip(82e9) + " Pa, nu = 0.3; xi_x = 0.0019, xi_y = 0.0011, "
                               "spin = " + round_trip(0.144 / 0.3048) + " 1/m (the paper's Fig. 6 "
                               "contact, compare's default)");
    const Run some = cli_ok({"compare", "--nx", "12", "--ny", "12", "--a", "0.007"});
    expect_contains(some.out, "contact: a = 0.007 m, b = 0.00331615 m");
    expect_contains(some.out, "(options not given take the paper's Fig. 6 values)");
}

// --exact-load (cw_params.exact_load): in full sliding (xi_x = 0.3) |F| is
// mu N to rounding for FASTSIM and the calibrated model, and never above
// it for the exact model; the numbers are the library's with exact_load = 1
// (bitwise), and without the option FASTSIM's are unchanged (exact_load =
// 0). Sweep, compare, wear and campaign rows (column exact_load) take it too.
void exact_load_bounds_the_force(void**)
{
    const double mu = 0.3, N = 100e3;
    const std::vector<std::string> contact = {"--a",  "7.17e-3", "--b",    "5.42e-3", "--N",
                                              "100e3", "--mu",   "0.3",    "--xi-x",  "0.3",
                                              "--format", "json"};
    for (const char* model : {"fastsim", "calibrated", "exact"}) {
        const Json j = parse_or_fail(
            cli_ok(with({"solve", "--exact-load", "--model", model}, contact)).out);
        const double F = std::hypot(j.num("Fx"), j.num("Fy"));
        if (!(F <= mu * N * (1 + 1e-12))) print_error("%s: |F| = %.17g > mu N\n", model, F);
        assert_true(F <= mu * N * (1 + 1e-12));
        if (std::string(model) != "exact") assert_close(F, mu * N, 1e-12, 0.0);
        assert_int_equal(static_cast<int>(j.at("input").num("exact_load")), 1);
    }
    // The library's own numbers, with and without.
    cw_params p;
    cw_params_init(&p);
    p.a = 7.17e-3, p.b = 5.42e-3, p.normal_force = N, p.mu = mu, p.xi_x = 0.3;
    cw_grid g;
    cw_grid_init(&g);
    const cw_result plain = library_solve(g, p);
    p.exact_load = 1;
    const cw_result exact = library_solve(g, p);
    const Json without = parse_or_fail(cli_ok(with({"solve"}, contact)).out);
    const Json with_option = parse_or_fail(cli_ok(with({"solve", "--exact-load"}, contact)).out);
    assert_true(without.num("Fx") == plain.Fx && without.num("W_macro") == plain.W_macro);
    assert_true(with_option.num("Fx") == exact.Fx && with_option.num("W_macro") == exact.W_macro);
    assert_true(plain.Fx != exact.Fx); // the option does something: 1.0015 mu N before
    assert_int_equal(static_cast<int>(without.at("input").num("exact_load")), 0);

    // sweep: every panel of Figs. 2-5 within mu N (full-slip panels included).
    const std::string sweep = path("sweep");
    cli_ok({"sweep", "--exact-load", "--nx", "12", "--ny", "12", "--out", sweep, "--no-plots"});
    const auto cases = read_csv(sweep + "/cases.csv");
    const auto ci = header_index(cases[0]);
    const double bound = 0.6 * 10000 * 4.4482216152605; // the Fig. 6 contact's mu N
    double largest = 0;
    for (size_t k = 1; k < cases.size(); ++k)
        largest = std::max(largest, std::hypot(std::stod(cases[k][ci.at("Fx")]),
                                               std::stod(cases[k][ci.at("Fy")])) / bound);
    if (!(largest <= 1 + 1e-12)) print_error("sweep: |F| / mu N up to %.17g\n", largest);
    assert_true(largest <= 1 + 1e-12 && largest > 0.999);
    // compare: the simplified models' |F| within mu N.
    const Json cmp = parse_or_fail(
        cli_ok({"compare", "--exact-load", "--xi-x", "0.3", "--nx", "12", "--ny", "12",
                "--format", "json"})
            .out);
    const double fs = std::hypot(cmp.at("fastsim").num("Fx"), cmp.at("fastsim").num("Fy"));
    assert_true(fs <= bound * (1 + 1e-12) && fs > 0.999 * bound);
    assert_int_equal(static_cast<int>(cmp.at("fastsim").at("input").num("exact_load")), 1);
    // wear and a campaign's column: the same forces as solve --exact-load.
    const std::string states = scratch_file(
        "states.csv", "s0,a,b,N,mu,xi_x,passes,exact_load\n0,7.17e-3,5.42e-3,100e3,0.3,0.3,1,1\n");
    cli_ok({"wear", "--in", states, "--out", path("wear"), "--no-plots"});
    const auto st = read_csv(path("wear/states.csv"));
    assert_true(std::stod(st[1][header_index(st[0]).at("Fx_wheel_N")]) == exact.Fx);
    cli_ok({"wear", "--in", scratch_file("plain.csv", "s0,a,b,N,mu,xi_x,passes\n"
                                                      "0,7.17e-3,5.42e-3,100e3,0.3,0.3,1\n"),
            "--out", path("wear-option"), "--no-plots", "--exact-load"});
    const auto so = read_csv(path("wear-option/states.csv"));
    assert_true(std::stod(so[1][header_index(so[0]).at("Fx_wheel_N")]) == exact.Fx);
}

} // namespace

int main(int argc, char** argv)
{
    if (!set_up(argc, argv, "test_cli_models", {"creepwork", "scratch"})) return 2;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(solve_exact_matches_library),
        cmocka_unit_test(solve_calibrated_matches_library),
        cmocka_unit_test(model_bad_inputs_fail_cleanly),
        cmocka_unit_test(solve_exact_writes_fields_and_pictures),
        cmocka_unit_test(sweep_exact_model),
        cmocka_unit_test(compare_metrics_from_its_files),
        cmocka_unit_test(compare_fig6_readme_numbers),
        cmocka_unit_test(compare_simplified_calibrated),
        cmocka_unit_test(compare_simplified_all),
        cmocka_unit_test(compare_names_its_contact),
        cmocka_unit_test(exact_load_bounds_the_force),
    };
    return cw_run_tests(tests, g_tools.test);
}
