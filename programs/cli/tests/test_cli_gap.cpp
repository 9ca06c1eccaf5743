// Tests of `creepwork solve --gap`, run as a user runs it: its JSON (the
// keys of gap_input.hpp) equals what the C ABI gives for the same gap, per
// patch too, and so does its Jacobian (--jacobian); the approach and the
// semi-Hertzian method; --out writes the
// fields; a gap file that is not one regular grid, and options that do not
// belong with a gap, fail cleanly (status 2, one stderr line naming the file
// and line or the option).
//
// usage: test_cli_gap <creepwork binary> <scratch dir> [cmocka filter]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "cli_checks.hpp"
// Last: cmocka defines macros (fail, skip) that clash with the C++ library.
#include "test_support.h"

namespace fs = std::filesystem;

namespace {


// Two Hertzian lobes 12 mm apart across, the upper one 2 um higher, on a
// 30 x 56 grid of 0.35 x 0.45 mm (x0, y0 chosen off the origin).
struct Gap {
    cw_grid grid;
    std::vector<double> h;
};

// The grid nx x ny of dx x dy from (x0, y0), h(x, y) at every cell centre.
Gap make_gap(int nx, int ny, double dx, double dy, double x0, double y0,
             const std::function<double(double, double)>& h)
{
    Gap g;
    cw_grid_init(&g.grid);
    g.grid.kind = CW_GRID_GAP;
    g.grid.nx = nx;
    g.grid.ny = ny;
    g.grid.dx = dx;
    g.grid.dy = dy;
    g.grid.x0 = x0;
    g.grid.y0 = y0;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) g.h.push_back(h(x0 + i * dx, y0 + j * dy));
    return g;
}

Gap two_lobes()
{
    const double dx = 0.35e-3, dy = 0.45e-3;
    return make_gap(30, 56, dx, dy, -14.5 * dx + 0.2e-3, -27.5 * dy, [](double x, double y) {
        const double a = x * x / 0.9 + (y + 6e-3) * (y + 6e-3) / 0.5;
        const double b = x * x / 0.8 + (y - 6e-3) * (y - 6e-3) / 0.3 + 2e-6;
        return std::min(a, b);
    });
}

// The gap file, lines in the order given (rows reversed: any order is valid).
std::string write_gap(const Gap& g, const std::string& name)
{
    const std::string path = cwtest::g_tools.scratch + "/" + name;
    std::ofstream f(path);
    f << "x_m,y_m,h_m\n";
    char line[128];
    for (int j = g.grid.ny - 1; j >= 0; --j)
        for (int i = 0; i < g.grid.nx; ++i) {
            std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g\n", g.grid.x0 + i * g.grid.dx,
                          g.grid.y0 + j * g.grid.dy, g.h[i + g.grid.nx * j]);
            f << line;
        }
    return path;
}

cw_params library_params(const Gap& g)
{
    cw_params p;
    cw_params_init(&p);
    p.model = CW_MODEL_EXACT;
    p.gap = g.h.data();
    p.gap_len = g.h.size();
    p.normal_force = 50e3;
    p.xi_x = 4e-4;
    p.xi_y = -6e-4;
    p.phi = 0.5;
    return p;
}

void json_matches_library(void**)
{
    const Gap g = two_lobes();
    const std::string file = write_gap(g, "lobes.csv");
    const cwtest::Run r = cwtest::cli_ok({"solve", "--gap", file, "--N", "50e3", "--xi-x", "4e-4", "--xi-y", "-6e-4", "--spin",
         "0.5", "--format", "json"});
    const cwtest::Json j = cwtest::parse_json(r.out);
    // The grid the CLI read (spacing from the printed coordinates) is the
    // library's to rounding: compare with the library on the same grid.
    cw_solver* s = nullptr;
    assert_int_equal(cw_solver_create(&g.grid, &s, nullptr, 0), CW_OK);
    cw_params p = library_params(g);
    cw_result lib;
    cw_result_init(&lib);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &lib), CW_OK);
    const double muN = 0.3 * 50e3;
    assert_close(j.num("Fx"), lib.Fx, 0.0, 1e-7 * muN);
    assert_close(j.num("Fy"), lib.Fy, 0.0, 1e-7 * muN);
    assert_close(j.num("Mz"), lib.Mz, 0.0, 1e-9 * muN);
    assert_close(j.num("Fn"), 50e3, 1e-12, 0.0);
    assert_close(j.num("W_macro"), lib.W_macro, 1e-7, 0.0);
    assert_close(j.num("p_max"), lib.p_max, 1e-9, 0.0);
    assert_close(j.num("approach"), lib.approach, 1e-9, 0.0);
    assert_int_equal(static_cast<int>(j.num("n_contact")), lib.n_contact);
    assert_int_equal(static_cast<int>(j.num("n_adhesion")), lib.n_adhesion);
    assert_int_equal(static_cast<int>(j.num("n_slip")), lib.n_slip);
    assert_int_equal(static_cast<int>(j.num("n_patches")), 2);
    cw_patch P[2];
    cw_patch_init(&P[0]);
    cw_patch_init(&P[1]);
    size_t count = 0;
    assert_int_equal(cw_solver_get_patches(s, P, 2, &count), CW_OK);
    const cwtest::Json& list = j.at("patches");
    assert_int_equal(list.array.size(), 2);
    double fx = 0.0;
    for (size_t k = 0; k < 2; ++k) {
        const cwtest::Json& q = list.array[k];
        for (const char* key : {"Fx", "Fy", "Mz", "Fn", "W_macro", "p_max", "approach", "n_contact",
                                "n_adhesion", "n_slip", "x_centroid", "y_centroid"})
            assert_true(q.has(key));
        assert_close(q.num("Fn"), P[k].Fn, 1e-9, 0.0);
        assert_close(q.num("Fy"), P[k].Fy, 0.0, 1e-7 * muN);
        assert_close(q.num("y_centroid"), P[k].y_centroid, 1e-9, 0.0);
        assert_int_equal(static_cast<int>(q.num("n_contact")), P[k].n_contact);
        fx += q.num("Fx");
    }
    assert_close(fx, j.num("Fx"), 0.0, 1e-9 * muN);
    assert_true(list.array[0].num("y_centroid") < 0.0); // the lower lobe first

    // The approach found, given: the force back; the semi-Hertzian method.
    char approach[32];
    std::snprintf(approach, sizeof approach, "%.17g", j.num("approach"));
    const cwtest::Run a = cwtest::cli_ok({"solve", "--gap", file, "--approach", approach, "--format", "json"});
    assert_close(cwtest::parse_json(a.out).num("Fn"), 50e3, 1e-8, 0.0);
    const cwtest::Run f = cwtest::cli_ok({"solve", "--gap", file, "--N", "50e3", "--normal-method", "semi-hertz", "--format", "json"});
    const cwtest::Json fj = cwtest::parse_json(f.out);
    assert_close(fj.num("Fn"), 50e3, 1e-12, 0.0);
    assert_true(std::fabs(fj.num("n_contact") - lib.n_contact) <= 0.1 * lib.n_contact);

    // FASTSIM with the semi-Hertzian method: the library's numbers, the
    // same keys, its patches adding up.
    const cwtest::Run fs_run = cwtest::cli_ok({"solve", "--gap", file, "--N", "50e3", "--xi-x", "4e-4",
                                        "--xi-y", "-6e-4", "--spin", "0.5", "--model", "fastsim",
                                        "--normal-method", "semi-hertz", "--format", "json"});
    const cwtest::Json fsj = cwtest::parse_json(fs_run.out);
    cw_params pf = library_params(g);
    pf.model = CW_MODEL_FASTSIM;
    pf.normal_method = CW_NORMAL_SEMI_HERTZ;
    cw_result libf;
    cw_result_init(&libf);
    assert_int_equal(cw_solver_solve(s, &pf, CW_SOLVE_FULL, &libf), CW_OK);
    assert_true(fsj.at("model").string == "fastsim");
    assert_close(fsj.num("Fx"), libf.Fx, 0.0, 1e-7 * muN);
    assert_close(fsj.num("Fy"), libf.Fy, 0.0, 1e-7 * muN);
    assert_close(fsj.num("Mz"), libf.Mz, 0.0, 1e-9 * muN);
    assert_int_equal(static_cast<int>(fsj.num("n_patches")), 2);
    double fsx = 0.0;
    for (const cwtest::Json& q : fsj.at("patches").array) fsx += q.num("Fx");
    assert_close(fsx, fsj.num("Fx"), 0.0, 1e-9 * muN);

    // --out: the fields of every cell.
    const std::string out = cwtest::g_tools.scratch + "/out";
    cwtest::cli_ok({"solve", "--gap", file, "--N", "50e3", "--out", out, "--format",
                              "json"});
    std::ifstream fields(out + "/fields.csv");
    int lines = 0;
    for (std::string line; std::getline(fields, line);) ++lines;
    assert_int_equal(lines, 1 + 30 * 56);
    assert_true(fs::exists(out + "/result.json"));
    cw_solver_destroy(s);
}

// Three Hertzian lobes along y (centres below, 0, 1 and 3 um above the
// datum), on a 28 x 64 grid of 0.4 mm: each lobe is the gap where it is the
// smallest of the three.
struct Lobe {
    double x, y, dh, rx, ry; // h = (x - x)^2/rx + (y - y)^2/ry + dh [m]
};
const Lobe kLobes[3] = {{-1e-3, -8e-3, 0.0, 0.3, 0.25},
                        {1e-3, 0.0, 1e-6, 0.25, 0.2},
                        {0.0, 8e-3, 3e-6, 0.3, 0.15}};

int nearest_lobe(double x, double y, double* h = nullptr)
{
    int best = 0;
    double least = 0.0;
    for (int k = 0; k < 3; ++k) {
        const Lobe& L = kLobes[k];
        const double v = (x - L.x) * (x - L.x) / L.rx + (y - L.y) * (y - L.y) / L.ry + L.dh;
        if (k == 0 || v < least) {
            best = k;
            least = v;
        }
    }
    if (h) *h = least;
    return best;
}

Gap three_lobes()
{
    const double d = 0.4e-3;
    return make_gap(28, 64, d, d, -13.5 * d, -31.5 * d, [](double x, double y) {
        double h = 0.0;
        nearest_lobe(x, y, &h);
        return h;
    });
}

// Data rows (not comments) of a whitespace-separated gnuplot data file.
std::vector<std::vector<double>> data_rows(const std::string& path)
{
    std::vector<std::vector<double>> rows;
    std::ifstream f(path);
    for (std::string line; std::getline(f, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream ss(line);
        std::vector<double> row;
        for (double v; ss >> v;) row.push_back(v);
        rows.push_back(row);
    }
    return rows;
}

// solve --gap --out draws its pictures (gap_plots.hpp) from files in
// gnuplot/: patches.dat holds one row per separate patch, the labels of the
// slip/adhesion map at the patches' centroids.
void writes_pictures(void**)
{
    const Gap g = three_lobes();
    const std::string file = write_gap(g, "three_lobes.csv");
    const std::string out = cwtest::g_tools.scratch + "/pictures";
    const std::vector<std::string> run = {"solve", "--gap", file, "--N", "30e3", "--xi-x", "1e-3",
                                          "--xi-y", "-5e-4", "--spin", "0.2", "--format", "json"};
    if (std::getenv("CW_TEST_NO_GNUPLOT")) cw_skip();
    const cwtest::Json j =
        cwtest::parse_json(cwtest::cli_ok(cwtest::with(run, {"--out", out})).out);

    // Three patches by construction: a contact cell has h < approach (the
    // surfaces' displacement there is positive), and every cell next to a
    // cell of another lobe lies above the approach, so no contact path joins
    // two lobes (61 um against 40 um); each lobe's lowest point lies at least
    // 30 um below it.
    const double approach = j.num("approach");
    const int nx = g.grid.nx, ny = g.grid.ny;
    const auto lobe_of = [&g](int i, int jy) {
        return nearest_lobe(g.grid.x0 + i * g.grid.dx, g.grid.y0 + jy * g.grid.dy);
    };
    double ridge = 1.0; // the lowest cell of a 4-neighbour pair from two lobes
    for (int jy = 0; jy < ny; ++jy)
        for (int i = 0; i < nx; ++i) {
            const double h = g.h[i + nx * jy];
            if (i + 1 < nx && lobe_of(i + 1, jy) != lobe_of(i, jy))
                ridge = std::min({ridge, h, g.h[i + 1 + nx * jy]});
            if (jy + 1 < ny && lobe_of(i, jy + 1) != lobe_of(i, jy))
                ridge = std::min({ridge, h, g.h[i + nx * (jy + 1)]});
        }
    assert_true(ridge > approach);
    for (const Lobe& L : kLobes) assert_true(L.dh < approach - 30e-6);
    assert_int_equal(static_cast<int>(j.num("n_patches")), 3);

    for (const char* png : {"patch.png", "gap.png", "pressure.png", "slip_adhesion.png",
                            "traction_x.png", "traction_y.png", "work.png"}) {
        const std::string data = cwtest::slurp(out + "/" + png);
        if (!(data.size() > 5000 && data.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0))
            fail_msg("%s is not a PNG picture (%zu bytes)", png, data.size());
    }
    // The labels: one row per patch of result.json, at its centroid (mm in
    // SI pictures), each inside its own lobe, in the library's order.
    const cwtest::Json file_json = cwtest::parse_json(cwtest::slurp(out + "/result.json"));
    const std::vector<std::vector<double>> rows = data_rows(out + "/gnuplot/patches.dat");
    assert_int_equal(rows.size(), static_cast<size_t>(file_json.num("n_patches")));
    assert_int_equal(rows.size(), 3);
    for (size_t k = 0; k < rows.size(); ++k) {
        const cwtest::Json& p = file_json.at("patches").array[k];
        assert_int_equal(static_cast<int>(rows[k][0]), static_cast<int>(k));
        assert_close(rows[k][1], 1e3 * p.num("x_centroid"), 1e-8, 1e-12);
        assert_close(rows[k][2], 1e3 * p.num("y_centroid"), 1e-8, 1e-12);
        assert_int_equal(static_cast<int>(rows[k][3]), static_cast<int>(p.num("n_contact")));
        assert_int_equal(nearest_lobe(p.num("x_centroid"), p.num("y_centroid")), static_cast<int>(k));
    }
    // The gap map covers every cell; the script draws the labels from patches.dat.
    assert_int_equal(data_rows(out + "/gnuplot/gap.dat").size(), 28 * 64);
    assert_true(cwtest::contains(cwtest::slurp(out + "/gnuplot/gap.gp"),
                                 "'gnuplot/patches.dat' using 2:3:(sprintf('patch %d', int($1)))"));

    // --no-plots: the data files only.
    const std::string bare = cwtest::g_tools.scratch + "/bare";
    cwtest::cli_ok(cwtest::with(run, {"--out", bare, "--no-plots"}));
    assert_true(fs::exists(bare + "/result.json"));
    assert_false(fs::exists(bare + "/patch.png"));
    assert_false(fs::exists(bare + "/gnuplot"));
}

// --jacobian with a gap: the JSON's "jacobian" equals the C ABI's
// cw_solver_solve_jacobian on the same gap (the exact model with the force
// given, FASTSIM with the approach given and the semi-Hertzian method, under
// Coulomb's law and under the exponential law at every element), to
// the rounding of the grid the CLI read from the printed coordinates: each
// entry within 1e-7 of its row's scale sum_c |J[r][c]| s_c (s: 1e-3 for the
// creepages, 1e-3 / 5 mm for the spin, N for the load).
void jacobian_matches_library(void**)
{
    const Gap g = two_lobes();
    const std::string file = write_gap(g, "lobes_jacobian.csv");
    cw_solver* s = nullptr;
    assert_int_equal(cw_solver_create(&g.grid, &s, nullptr, 0), CW_OK);
    for (int k = 0; k < 3; ++k) {
        std::vector<std::string> args = {"solve", "--gap", file, "--xi-x", "4e-4", "--xi-y",
                                         "-6e-4", "--spin", "0.5", "--format", "json",
                                         "--jacobian"};
        cw_params p = library_params(g);
        if (k == 2) {
            p.friction_law = CW_FRICTION_EXPONENTIAL;
            p.mu = 0.14;
            p.mu_e1 = 0.19;
            p.s_h1 = 1.25;
            p.V = 10.0;
            for (const char* a : {"--friction-law", "exponential", "--mu", "0.14", "--mu-e1",
                                  "0.19", "--s-h1", "1.25", "--V", "10"})
                args.push_back(a);
        }
        if (k >= 1) {
            p.model = CW_MODEL_FASTSIM;
            p.normal_load = CW_NORMAL_APPROACH;
            p.approach = 60e-6;
            p.normal_method = CW_NORMAL_SEMI_HERTZ;
            for (const char* a : {"--model", "fastsim", "--approach", "60e-6", "--normal-method",
                                  "semi-hertz"})
                args.push_back(a);
        } else {
            args.push_back("--N");
            args.push_back("50e3");
        }
        const cwtest::Json j = cwtest::parse_json(cwtest::cli_ok(args).out).at("jacobian");
        double J[CW_JACOBIAN_LEN];
        cw_result lib;
        cw_result_init(&lib);
        assert_int_equal(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, &lib, J, CW_JACOBIAN_LEN),
                         CW_OK);
        const char* rows[4] = {"Fx", "Fy", "Mz", "W_macro"};
        const char* cols[4] = {"xi_x", "xi_y", "phi", "N"};
        const double scale[4] = {1e-3, 1e-3, 1e-3 / 5e-3, lib.normal_force};
        for (int r = 0; r < 4; ++r) {
            double row = 0.0;
            for (int c = 0; c < 4; ++c) row += std::fabs(J[4 * r + c]) * scale[c];
            assert_true(row > 0.0);
            for (int c = 0; c < 4; ++c)
                assert_close(j.at(rows[r]).num(cols[c]), J[4 * r + c], 0.0, 1e-7 * row / scale[c]);
        }
    }
    cw_solver_destroy(s);
}

void expect_usage_error(const std::vector<std::string>& args, const std::string& names)
{
    const cwtest::Run r = cwtest::cli(args);
    if (r.status != 2 || r.err.find(names) == std::string::npos ||
        std::count(r.err.begin(), r.err.end(), '\n') != 1)
        fail_msg("status %d, stderr '%s' (expected status 2 naming '%s')", r.status, r.err.c_str(),
                 names.c_str());
    assert_true(r.out.empty());
}

void bad_gaps_fail_cleanly(void**)
{
    const auto file = [](const std::string& name, const std::string& text) {
        const std::string path = cwtest::g_tools.scratch + "/" + name;
        std::ofstream(path) << text;
        return path;
    };
    const std::string ok = "x_m,y_m,h_m\n"
                           "0,0,1e-5\n0.001,0,1e-6\n0.002,0,1e-5\n"
                           "0,0.001,1e-6\n0.001,0.001,0\n0.002,0.001,1e-6\n"
                           "0,0.002,1e-5\n0.001,0.002,1e-6\n0.002,0.002,1e-5\n";
    const std::string good = file("good.csv", ok);
    std::string dup = ok, off = ok, miss = ok, head = ok, word = ok;
    dup.replace(dup.find("0.002,0.002,1e-5"), 16, "0.001,0.002,1e-5");
    off.replace(off.find("0.001,0.001,0"), 13, "0.0013,0.001,0");
    miss.erase(miss.find("0.002,0.002,1e-5"));
    head.replace(0, 11, "x,y,h");
    word.replace(word.find("1e-6"), 4, "abc");
    expect_usage_error({"solve", "--gap", file("dup.csv", dup), "--N", "1e3"},
                       "dup.csv:10: the cell at x_m = 0.001, y_m = 0.002 is already on line 9");
    expect_usage_error({"solve", "--gap", file("off.csv", off), "--N", "1e3"}, "off.csv:6: x_m = 0.0013");
    expect_usage_error({"solve", "--gap", file("miss.csv", miss), "--N", "1e3"},
                       "x_m = 0.002, y_m = 0.002 is missing");
    expect_usage_error({"solve", "--gap", file("head.csv", head), "--N", "1e3"},
                       "head.csv:1: the header must be x_m,y_m,h_m");
    expect_usage_error({"solve", "--gap", file("word.csv", word), "--N", "1e3"},
                       "word.csv:3: \"abc\" is not a finite number");
    expect_usage_error({"solve", "--gap", cwtest::g_tools.scratch + "/none.csv", "--N", "1e3"}, "cannot open");
    expect_usage_error({"solve", "--gap", file("small.csv", "x_m,y_m,h_m\n0,0,0\n1,0,0\n0,1,0\n1,1,0\n"),
                        "--N", "1e3"},
                       "2 x 2 cells");
    // Options that do not belong with a gap.
    expect_usage_error({"solve", "--gap", good, "--N", "1e3", "--a", "6e-3"}, "--a");
    expect_usage_error({"solve", "--gap", good, "--N", "1e3", "--nx", "20"}, "--nx");
    expect_usage_error({"solve", "--gap", good, "--N", "1e3", "--model", "calibrated"}, "--model");
    expect_usage_error({"solve", "--gap", good}, "--N");
    expect_usage_error({"solve", "--gap", good, "--N", "1e3", "--approach", "1e-5"}, "not both");
    expect_usage_error({"solve", "--gap", good, "--N", "1e3", "--plot-axes", "normalised"},
                       "--plot-axes");
    expect_usage_error({"solve", "--a", "6e-3", "--b", "6e-3", "--N", "1e3", "--approach", "1e-5"},
                       "--approach: only used with --gap");
    // The good file solves.
    cwtest::cli_ok({"solve", "--gap", good, "--N", "1e3"});
}

// A gap file in millimetres is solved -- it is a valid gap -- with a
// warning naming the file and what looks like millimetres (the library's
// cw_params_check): heights whose spread exceeds 10 mm, cells of more than
// 5 mm. The same file in metres warns about nothing.
void unit_mistakes_warn(void**)
{
    Gap g = two_lobes();
    const std::string metres = write_gap(g, "metres.csv");
    const cwtest::Run fine = cwtest::cli_ok({"solve", "--gap", metres, "--N", "50e3", "--xi-x", "1e-3"});
    assert_true(fine.err.find("implausible") == std::string::npos);
    // the heights in mm, the coordinates in metres
    double lo = g.h[0], hi = g.h[0];
    for (double& h : g.h) {
        lo = std::min(lo, h);
        hi = std::max(hi, h);
        h *= 1e3;
    }
    const std::string heights = write_gap(g, "heights_mm.csv");
    const cwtest::Run r = cwtest::cli_ok({"solve", "--gap", heights, "--N", "50e3", "--xi-x", "1e-3"});
    char spread[64];
    std::snprintf(spread, sizeof spread, "gap = %.6g m is implausible", std::round((hi - lo) * 1e9) / 1e6);
    cwtest::expect_contains(r.err, "creepwork: warning: --gap: " + heights + ": " + spread +
                                       " for a wheel-rail contact: its heights span this much");
    cwtest::expect_contains(r.err, "(heights in millimetres typed as metres?)");
    assert_true(r.err.find("dx = ") == std::string::npos);
    // every value in mm: the cells too
    Gap all = two_lobes();
    all.grid.dx *= 1e3, all.grid.dy *= 1e3, all.grid.x0 *= 1e3, all.grid.y0 *= 1e3;
    for (double& h : all.h) h *= 1e3;
    const cwtest::Run m = cwtest::cli_ok({"solve", "--gap", write_gap(all, "all_mm.csv"), "--N", "50e3"});
    cwtest::expect_contains(m.err, ": dx = 0.35 m is implausible for a wheel-rail contact: gap cells are 0.05-1 mm");
    cwtest::expect_contains(m.err, ": dy = 0.45 m is implausible");
    cwtest::expect_contains(m.err, ": gap = ");
    // an approach in mm
    const cwtest::Run a = cwtest::cli_ok({"solve", "--gap", metres, "--approach", "0.05"});
    cwtest::expect_contains(a.err, "warning: --approach = 0.05 m is implausible for a wheel-rail contact: "
                                   "approaches are 10-200 um");
}

// Messages that point at the cause: a grid whose cells beyond x = 4 mm are
// shifted names a shifted cell's line (not the first, correct one); a patch
// centred on the x axis prints 0, not the rounding noise of its centroid.
void messages_name_the_cause(void**)
{
    const double d = 0.4e-3;
    Gap g = make_gap(32, 40, d, d, -15.5 * d, -19.5 * d,
                     [](double x, double y) { return x * x / 0.9 + y * y / 0.5; });
    std::string text = "x_m,y_m,h_m\n";
    long first_shifted = 0, line = 1;
    char row[128];
    for (int j = 0; j < g.grid.ny; ++j)
        for (int i = 0; i < g.grid.nx; ++i) {
            double x = g.grid.x0 + i * d;
            if (x > 4e-3) {
                x += 0.05e-3;
                if (!first_shifted) first_shifted = line + 1;
            }
            std::snprintf(row, sizeof row, "%.17g,%.17g,%.17g\n", x, g.grid.y0 + j * d, g.h[i + 32 * j]);
            text += row;
            ++line;
        }
    const std::string path = cwtest::g_tools.scratch + "/shifted.csv";
    std::ofstream(path) << text;
    expect_usage_error({"solve", "--gap", path, "--N", "50e3"},
                       "shifted.csv:" + std::to_string(first_shifted) + ": x_m = ");
    const cwtest::Run r = cwtest::cli({"solve", "--gap", path, "--N", "50e3"});
    cwtest::expect_contains(r.err, "is off the regular grid of the other cells (their x values run from");
    cwtest::expect_contains(r.err, "in steps of 0.0004)");

    // symmetric about y = 0: the centroid's y is rounding noise
    const std::string sym = write_gap(make_gap(31, 31, d, d, -15 * d, -15 * d,
                                               [](double x, double y) { return x * x / 0.9 + y * y / 0.5; }),
                                      "symmetric.csv");
    const cwtest::Run s = cwtest::cli_ok({"solve", "--gap", sym, "--N", "50e3", "--xi-x", "1e-3"});
    const size_t at = s.out.find("  patch 0  at (");
    assert_true(at != std::string::npos);
    const std::string centroid = s.out.substr(at, s.out.find("):", at) - at);
    if (centroid.find("e-") != std::string::npos)
        fail_msg("a centroid shows rounding noise: %s", centroid.c_str());
    cwtest::expect_contains(centroid, "at (0 m, 0 m");
}

} // namespace

int main(int argc, char** argv)
{
    if (!cwtest::set_up(argc, argv, "test_cli_gap", {"creepwork", "scratch"})) return 2;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(json_matches_library),
        cmocka_unit_test(jacobian_matches_library),
        cmocka_unit_test(bad_gaps_fail_cleanly),
        cmocka_unit_test(writes_pictures),
        cmocka_unit_test(unit_mistakes_warn),
        cmocka_unit_test(messages_name_the_cause),
    };
    return cw_run_tests(tests, cwtest::g_tools.test);
}
