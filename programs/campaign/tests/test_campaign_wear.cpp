/* Wear campaigns (`creepwork campaign --wear`): every
 * row's wear and the accumulated wear-depth profiles of the rail and the
 * wheel must be bitwise the same for 1, 2 and 3 ranks, threads and chunk
 * sizes; equal, bitwise, to a direct accumulation through the C ABI (each
 * row solved cold with CW_SOLVE_FULL, cw_wear_compute, cw_wear_profile_add)
 * and to `creepwork wear` on the same states; the same after a SIGKILL and
 * --resume (no row counted twice); and a bad wear row gets its own error
 * line; the contact columns are those of the same campaign without wear.
 * FASTSIM rows and exact-model rows (uniform 12 x 12).
 *
 * usage: test_campaign_wear <creepwork> <mpirun> <scratch dir> <test name> */
#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <creepwork/creepwork.h>

#include "campaign_test_support.hpp"
// Last: cmocka defines macros (fail, skip) that clash with the C++ library.
#include "test_support.h"

namespace fs = std::filesystem;
using namespace cwtest;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 0.46; // --wheel-radius of these tests [m]
// The profile grid of these tests: -20 .. 20 mm every 0.25 mm (161 nodes).
const std::vector<std::string> kGrid = {"--profile-from", "-0.02", "--profile-to", "0.02",
                                        "--profile-step", "0.00025"};

std::string fmt(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

double num(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

std::string cell(const Row& r, const std::string& name)
{
    const auto it = r.find(name);
    return it == r.end() ? std::string() : it->second;
}

const std::vector<std::string>& wear_input_columns()
{
    static std::vector<std::string> c = [] {
        std::vector<std::string> v = input_columns();
        for (const char* w : {"s0", "contact_angle", "passes", "distance", "body"}) v.push_back(w);
        return v;
    }();
    return c;
}

void write_wear_input(const std::string& file, const std::vector<Row>& rows)
{
    write_input(file, rows, wear_input_columns());
}

Row exact_row(const std::string& id, double xi_x)
{
    Row r;
    r["id"] = id, r["model"] = "exact", r["grid"] = "uniform", r["nx"] = "12", r["ny"] = "12";
    r["box_scale"] = "1.2", r["a"] = "0.006", r["b"] = "0.005", r["N"] = "80000";
    r["mu"] = "0.3", r["G"] = "82e9", r["nu"] = "0.28", r["xi_x"] = fmt(xi_x);
    r["xi_y"] = "5e-4", r["phi"] = "0.4";
    return r;
}

// The 48 mixed FASTSIM rows placed across the profile, a quarter on the
// wheel (passes, or a rolled distance), two exact-model rows (partial and
// full slip), and three bad rows: a contact angle beyond 85 degrees (out of
// range), a rail row with only a distance (unreadable), and nu = 0.7 (out
// of range, as the library says too).
std::vector<Row> wear_rows()
{
    std::vector<Row> rows = mixed_rows();
    for (size_t k = 0; k < rows.size(); ++k) {
        Row& r = rows[k];
        r["s0"] = fmt((static_cast<int>(k % 9) - 4) * 1.5e-3);
        r["contact_angle"] = fmt((k % 3) * 0.1);
        if (k % 4 == 3) {
            r["body"] = "wheel";
            if (k % 8 == 7)
                r["distance"] = fmt(50.0 + k);
            else
                r["passes"] = fmt(20.0 + k);
        } else {
            r["passes"] = fmt(100.0 + k);
        }
    }
    Row e1 = exact_row("exact-partial", 1e-3), e2 = exact_row("exact-full", 8e-3);
    e1["s0"] = "0.002", e1["passes"] = "500", e1["contact_angle"] = "0.05";
    e2["s0"] = "-0.003", e2["passes"] = "50", e2["body"] = "wheel";
    rows.insert(rows.begin() + 3, e1);
    rows.insert(rows.begin() + 30, e2);
    Row angle = rows[0], rail_distance = rows[1], nu = rows[2];
    angle["id"] = "bad-angle", angle["contact_angle"] = "2";
    rail_distance["id"] = "bad-distance", rail_distance["passes"] = "",
    rail_distance["distance"] = "10", rail_distance["body"] = "rail";
    nu["id"] = "bad-nu", nu["nu"] = "0.7", nu["G"] = "82e9", nu["L1"] = nu["L2"] = nu["L3"] = "";
    rows.insert(rows.begin() + 10, angle);
    rows.insert(rows.begin() + 20, rail_distance);
    rows.insert(rows.begin() + 40, nu);
    return rows;
}

std::vector<double> grid_nodes()
{
    const double lo = -0.02, hi = 0.02, step = 0.00025;
    const size_t n = static_cast<size_t>(std::floor((hi - lo) / step + 1e-9) + 1);
    std::vector<double> s(n);
    for (size_t k = 0; k < n; ++k) s[k] = lo + step * static_cast<double>(k);
    return s;
}

// The campaign's work done directly through the C ABI, row by row.
struct Direct {
    std::vector<int> status;                // per row (CW_OK or not)
    std::vector<cw_wear_result> wear;       // per row
    std::vector<double> passes;             // per row
    std::vector<double> depth[2][2];        // [body][normal, height]
    double volume[2] = {0, 0};              // sum passes x volume per distance
};

Direct direct(const std::vector<Row>& rows)
{
    Direct d;
    const std::vector<double> s = grid_nodes();
    cw_wear_profile* prof[2] = {nullptr, nullptr};
    for (auto& p : prof) assert_int_equal(cw_wear_profile_create(s.data(), s.size(), &p, nullptr, 0), CW_OK);
    for (const Row& row : rows) {
        cw_grid g;
        cw_params p;
        row_to_structs(row, g, p);
        p.warm_start = 0;
        const bool wheel = cell(row, "body") == "wheel";
        const double angle = num(cell(row, "contact_angle")), s0 = num(cell(row, "s0"));
        const double passes = !cell(row, "passes").empty()
                                  ? num(cell(row, "passes"))
                                  : num(cell(row, "distance")) / (2 * kPi * kRadius);
        cw_wear_result w;
        cw_wear_result_init(&w);
        // The two rows the reader must reject (bad-angle, bad-distance).
        int status = std::fabs(angle) > 1.4835 || (!wheel && !cell(row, "distance").empty())
                         ? -1
                         : CW_OK;
        cw_solver* solver = nullptr;
        if (status == CW_OK) status = cw_solver_create(&g, &solver, nullptr, 0);
        if (status == CW_OK) status = cw_solver_solve(solver, &p, CW_SOLVE_FULL, nullptr);
        if (status == CW_OK) {
            cw_wear* wear = nullptr;
            assert_int_equal(cw_wear_create(solver, &wear), CW_OK);
            cw_wear_params wp;
            cw_wear_params_init(&wp);
            wp.pass_length = wheel ? 2 * kPi * kRadius : 1.0;
            assert_int_equal(cw_wear_compute(wear, solver, &wp, &w), CW_OK);
            assert_int_equal(cw_wear_profile_add(prof[wheel], wear, s0, 1, angle, passes), CW_OK);
            d.volume[wheel] += passes * w.volume_per_distance;
            cw_wear_destroy(wear);
        }
        cw_solver_destroy(solver);
        d.status.push_back(status);
        d.wear.push_back(w);
        d.passes.push_back(passes);
    }
    for (int b = 0; b < 2; ++b)
        for (int kind = 0; kind < 2; ++kind) {
            d.depth[b][kind].resize(s.size());
            assert_int_equal(cw_wear_profile_get_depth(prof[b], kind, d.depth[b][kind].data(), s.size()), CW_OK);
        }
    for (auto* p : prof) cw_wear_profile_destroy(p);
    return d;
}

// The campaign in dir against the direct accumulation: each row's wear
// columns and both profiles, bitwise (the files print the shortest digits
// that read back as the same double).
void expect_equals_direct(const std::string& dir, const std::vector<Row>& rows, const Direct& d)
{
    const auto records = read_csv(dir + "/results.csv");
    assert_int_equal(records.size(), rows.size() + 1);
    const auto idx = header_index(records[0]);
    for (size_t k = 0; k < rows.size(); ++k) {
        const auto& rec = records[k + 1];
        assert_string_equal(rec[idx.at("id")].c_str(), rows[k].at("id").c_str());
        if (d.status[k] != CW_OK) {
            assert_string_not_equal(rec[idx.at("status")].c_str(), "ok");
            assert_string_equal(rec[idx.at("wear_mass")].c_str(), "");
            continue;
        }
        assert_string_equal(rec[idx.at("status")].c_str(), "ok");
        const cw_wear_result& w = d.wear[k];
        assert_true(num(rec[idx.at("passes")]) == d.passes[k]);
        assert_true(num(rec[idx.at("wear_work")]) == w.work);
        assert_true(num(rec[idx.at("wear_mass_per_distance")]) == w.mass_per_distance);
        assert_true(num(rec[idx.at("wear_mass_per_pass")]) == w.mass_per_pass);
        assert_true(num(rec[idx.at("wear_max_depth")]) == w.max_depth);
        assert_true(num(rec[idx.at("wear_mass")]) == d.passes[k] * w.mass_per_pass);
        assert_true(num(rec[idx.at("wear_area_regime2")]) == w.regime_area[1]);
    }
    for (int b = 0; b < 2; ++b) {
        const auto prof = read_csv(dir + (b ? "/wear_profile_wheel.csv" : "/wear_profile_rail.csv"));
        const std::vector<double> s = grid_nodes();
        assert_int_equal(prof.size(), s.size() + 1);
        assert_string_equal(prof[0][3].c_str(), "depth_height_m");
        double peak = 0;
        for (size_t k = 0; k < s.size(); ++k) {
            assert_true(num(prof[k + 1][1]) == s[k]);
            if (num(prof[k + 1][2]) != d.depth[b][0][k] || num(prof[k + 1][3]) != d.depth[b][1][k]) {
                print_error("%s node %zu: %s %s, directly %.17g %.17g\n", b ? "wheel" : "rail", k,
                            prof[k + 1][2].c_str(), prof[k + 1][3].c_str(), d.depth[b][0][k],
                            d.depth[b][1][k]);
                fail();
            }
            peak = std::max(peak, d.depth[b][0][k]);
        }
        assert_true(peak > 1e-9); // the comparison is not between zeros
    }
    // The accumulated cross-section is the rows' passes x worn volume per
    // rolled distance (cw_wear_result, mass / density): the remap keeps it.
    const Json j = parse_json(slurp(dir + "/campaign.json"));
    assert_close(j.num("wear_rail_volume_m2"), d.volume[0], 1e-12, 0);
    assert_close(j.num("wear_wheel_volume_m2"), d.volume[1], 1e-12, 0);
    assert_true(j.num("wear_rail_volume_lost_m2") == 0 && j.num("wear_wheel_volume_lost_m2") == 0);
}

std::vector<std::string> wear_args(const std::string& in, const std::string& out)
{
    std::vector<std::string> a = {"--in", in, "--out", out, "--wear", "--wheel-radius", "0.46",
                                  "--quiet"};
    a.insert(a.end(), kGrid.begin(), kGrid.end());
    return a;
}

std::string outputs(const std::string& dir)
{
    return slurp(dir + "/results.csv") + slurp(dir + "/wear_profile_rail.csv") +
           slurp(dir + "/wear_profile_wheel.csv");
}

// ------------------------------------------------------------------- tests

void wear_ranks_bitwise(void** state)
{
    (void)state;
    const std::vector<Row> rows = wear_rows();
    write_wear_input(path("in.csv"), rows);
    struct Config {
        int np;
        std::vector<std::string> extra;
    };
    const std::vector<Config> configs = {
        {0, {"--threads", "1"}},
        {1, {"--threads", "2"}},
        {2, {"--threads", "1", "--chunk", "1"}},
        {3, {"--threads", "2", "--chunk", "5"}},
    };
    std::string reference;
    for (size_t c = 0; c < configs.size(); ++c) {
        const std::string out = path("out" + std::to_string(c));
        std::vector<std::string> args = wear_args(path("in.csv"), out);
        args.insert(args.end(), configs[c].extra.begin(), configs[c].extra.end());
        const Run r = expect_status(campaign(configs[c].np, args), 0);
        expect_contains(r.err, std::to_string(rows.size()) + " rows: " +
                                   std::to_string(rows.size() - 3) + " solved, 3 failed");
        expect_contains(r.err, "wear_profile_rail.csv, wear_profile_wheel.csv");
        if (c == 0) {
            reference = outputs(out);
            expect_equals_direct(out, rows, direct(rows));
        } else if (outputs(out) != reference) {
            print_error("np %d with %s %s: the outputs differ from the first run's\n",
                        configs[c].np, configs[c].extra[0].c_str(), configs[c].extra[1].c_str());
            fail();
        }
    }
    // Every contact column equals, bitwise, a campaign without --wear (its
    // rows through cw_batch_solve) of the same rows, wear columns dropped.
    write_input(path("plain.csv"), rows);
    expect_status(campaign(0, {"--in", path("plain.csv"), "--out", path("plain"), "--quiet"}), 0);
    {
        const auto worn = read_csv(path("out0/results.csv"));
        const auto plain = read_csv(path("plain/results.csv"));
        assert_int_equal(worn.size(), plain.size());
        const auto wi = header_index(worn[0]);
        size_t compared = 0;
        for (size_t k = 1; k < plain.size(); ++k) {
            if (worn[k][wi.at("status")] != "ok") continue;
            for (size_t c = 0; c < plain[0].size(); ++c) {
                const std::string& name = plain[0][c];
                if (worn[k][wi.at(name)] != plain[k][c]) {
                    print_error("row %zu, column %s: %s with --wear, %s without\n", k,
                                name.c_str(), worn[k][wi.at(name)].c_str(), plain[k][c].c_str());
                    fail();
                }
            }
            ++compared;
        }
        assert_int_equal(compared, rows.size() - 3);
    }

    // The bad rows' lines.
    const auto records = read_csv(path("out0/results.csv"));
    const auto idx = header_index(records[0]);
    const auto line_of = [&](const std::string& id) -> const std::vector<std::string>& {
        for (const auto& rec : records)
            if (rec[idx.at("id")] == id) return rec;
        fail();
        return records[0];
    };
    assert_string_equal(line_of("bad-angle")[idx.at("status")].c_str(), "CW_ERR_INVALID_INPUT");
    expect_contains(line_of("bad-angle")[idx.at("message")],
                    "column contact_angle: must lie within +-85 degrees");
    expect_contains(line_of("bad-distance")[idx.at("message")],
                    "column distance: is for a wheel");
    assert_string_equal(line_of("bad-nu")[idx.at("status")].c_str(), "CW_ERR_INVALID_INPUT");
    expect_contains(line_of("bad-nu")[idx.at("message")], "column nu: must lie in [0, 0.5] (got 0.7)");
    assert_string_equal(line_of("exact-full")[idx.at("status")].c_str(), "ok");
    assert_string_equal(line_of("exact-full")[idx.at("body")].c_str(), "wheel");
}

// `creepwork wear` on the same states (one grid, FASTSIM; and one exact
// state, alone so that its solve is cold there too) writes the same
// profile, bitwise.
void wear_matches_creepwork_wear(void** state)
{
    (void)state;
    std::vector<Row> rows;
    std::string states = "s0,a,b,N,xi_x,xi_y,spin,contact_angle,passes,mu,model\n";
    for (int k = 0; k < 12; ++k) {
        Row r;
        r["id"] = "w" + std::to_string(k), r["model"] = "fastsim", r["grid"] = "strips";
        r["nx"] = "12", r["ny"] = "10", r["G"] = "82e9", r["nu"] = "0.28";
        r["a"] = fmt(0.004 + 0.0005 * (k % 6)), r["b"] = fmt(0.003 + 0.0007 * (k % 5));
        r["N"] = fmt(40e3 + 5e3 * (k % 7)), r["mu"] = fmt(0.25 + 0.05 * (k % 3));
        r["xi_x"] = fmt((k % 5 - 2) * 4e-4 * (k % 8 == 7 ? 20 : 1)); // some in full slip
        r["xi_y"] = fmt(((k * 3) % 7 - 3) * 2e-4), r["phi"] = fmt(((k * 5) % 9 - 4) * 0.3);
        r["s0"] = fmt((k % 5 - 2) * 2e-3), r["contact_angle"] = "0.1";
        r["passes"] = fmt(100.0 + k);
        rows.push_back(r);
        states += r["s0"] + "," + r["a"] + "," + r["b"] + "," + r["N"] + "," + r["xi_x"] + "," +
                  r["xi_y"] + "," + r["phi"] + ",0.1," + r["passes"] + "," + r["mu"] +
                  ",fastsim\n";
    }
    assert_true(rows.size() >= 10);
    write_wear_input(path("fastsim.csv"), rows);
    write_text(path("fastsim-states.csv"), states);
    Row e = exact_row("exact", 2e-3);
    e["s0"] = "0.001", e["contact_angle"] = "0", e["passes"] = "1000";
    write_wear_input(path("exact.csv"), {e});
    write_text(path("exact-states.csv"),
               "s0,a,b,N,xi_x,xi_y,spin,contact_angle,passes,mu,model\n"
               "0.001,0.006,0.005,80000,0.002,5e-4,0.4,0,1000,0.3,exact\n");

    struct Case {
        std::string name;
        std::vector<std::string> grid;
    };
    for (const Case& c : {Case{"fastsim", {"--grid", "strips", "--nx", "12", "--ny", "10"}},
                          Case{"exact", {"--grid", "uniform", "--nx", "12", "--ny", "12",
                                         "--box-scale", "1.2"}}}) {
        expect_status(campaign(2, wear_args(path(c.name + ".csv"), path(c.name + "-campaign"))), 0);
        std::vector<std::string> argv = {g_tools.creepwork, "wear", "--in",
                                         path(c.name + "-states.csv"), "--out",
                                         path(c.name + "-wear"), "--G", "82e9", "--nu", "0.28",
                                         "--no-plots"};
        argv.insert(argv.end(), c.grid.begin(), c.grid.end());
        argv.insert(argv.end(), kGrid.begin(), kGrid.end());
        expect_status(run(argv), 0);
        const auto mine = read_csv(path(c.name + "-campaign/wear_profile_rail.csv"));
        const auto theirs = read_csv(path(c.name + "-wear/wear_profile.csv"));
        assert_int_equal(mine.size(), theirs.size());
        assert_int_equal(mine.size(), grid_nodes().size() + 1);
        double peak = 0;
        for (size_t k = 1; k < mine.size(); ++k)
            for (int col = 1; col <= 3; ++col) {
                if (num(mine[k][col]) != num(theirs[k][col])) {
                    print_error("%s: node %zu column %d: campaign %s, creepwork wear %s\n",
                                c.name.c_str(), k - 1, col, mine[k][col].c_str(),
                                theirs[k][col].c_str());
                    fail();
                }
                peak = std::max(peak, num(mine[k][2]));
            }
        assert_true(peak > 1e-9);
        assert_false(exists(path(c.name + "-campaign/wear_profile_wheel.csv")));
    }
}

void wear_resume_after_kill(void** state)
{
    (void)state;
    const std::vector<Row> rows = wear_rows();
    write_wear_input(path("in.csv"), rows);
    std::vector<std::string> args = wear_args(path("in.csv"), path("ref"));
    args.insert(args.end(), {"--threads", "1"});
    expect_status(campaign(2, args), 0);
    const std::string reference = outputs(path("ref"));

    // Slowed to 150 ms per chunk of 3 rows, killed (mpirun and every rank)
    // once a few chunks are in the checkpoint.
    const std::string checkpoint = path("run/checkpoint.cwj");
    args = wear_args(path("in.csv"), path("run"));
    args.insert(args.end(), {"--threads", "1", "--chunk", "3"});
    // Each chunk's record holds its profile states (~26 kB on 161 nodes).
    kill_midway(2, args, 150, checkpoint, 60000);
    assert_false(exists(path("run/results.csv")));
    fs::resize_file(checkpoint, fs::file_size(checkpoint) - 5); // a torn last record

    // Other wear options are another campaign: refused, nothing lost.
    args = wear_args(path("in.csv"), path("run"));
    args.insert(args.end(), {"--resume", "--law", "archard", "--speed", "20"});
    Run r = expect_status(campaign(0, args), 2);
    expect_contains(r.err, "belongs to another input or other --wear options");

    args = wear_args(path("in.csv"), path("run"));
    args.erase(std::find(args.begin(), args.end(), "--quiet")); // to see the resume message
    args.insert(args.end(), {"--resume", "--threads", "1"});
    r = expect_status(campaign(3, args), 0);
    expect_contains(r.err, "(a torn last chunk was dropped)");
    if (outputs(path("run")) != reference) {
        print_error("the resumed run's outputs differ from the uninterrupted run's\n");
        fail();
    }
    expect_resumed_part(path("run"), rows.size());
}

void wear_bad_inputs_fail_cleanly(void** state)
{
    (void)state;
    const std::vector<Row> rows = wear_rows();
    write_wear_input(path("in.csv"), rows);
    write_input(path("plain.csv"), {mixed_rows()[0]});
    const std::string out = path("out");
    struct Case {
        std::vector<std::string> args;
        std::string message;
    };
    const std::vector<Case> cases = {
        {{"--in", path("plain.csv"), "--out", out, "--law", "archard"},
         "--law: only used with --wear"},
        {{"--in", path("plain.csv"), "--out", out, "--wear"}, "lacks the required column(s) s0 (creepwork campaign --wear requires id,s0,a,b,N"},
        {{"--in", path("in.csv"), "--out", out, "--wear", "--speed", "0"},
         "--speed: must lie in (0, 1000] m/s"},
        {{"--in", path("in.csv"), "--out", out, "--wear", "--hardness", "2e9"},
         "--hardness: only used with --law archard"},
        {{"--in", path("in.csv"), "--out", out, "--wear", "--profile-from", "0.01",
          "--profile-to", "0"},
         "--profile-to: must be greater than --profile-from"},
        {{"--table", "--out", out, "--wear"}, "--wear: not used with --table"},
    };
    for (const Case& c : cases) {
        const Run r = campaign(0, c.args);
        if (r.status != 2 || !contains(r.err, c.message)) {
            print_error("exit %d, stderr:\n%s\nexpected 2 and %s\n", r.status, r.err.c_str(),
                        c.message.c_str());
            fail();
        }
        assert_false(exists(out + "/results.csv"));
    }
    // Without --wear the wear columns are ignored, with a note.
    const Run plain = expect_status(campaign(0, {"--in", path("in.csv"), "--out", path("plain")}), 0);
    expect_contains(plain.err, "columns contact_angle, passes, body (read with --wear only) not "
                               "read by creepwork campaign: ignored");
    assert_false(exists(path("plain/wear_profile_rail.csv")));
    // Archard without a speed: each row says so on its own line.
    const Run r = expect_status(campaign(0, {"--in", path("in.csv"), "--out", out, "--wear",
                                             "--law", "archard", "--wheel-radius", "0.46"}),
                                0);
    expect_contains(r.err, "0 solved");
    expect_contains(slurp(out + "/results.csv"),
                    "column speed: empty: Archard's KTH map needs the rolling speed");
}

} // namespace

int main(int argc, char** argv)
{
    if (!set_up(argc, argv, "test_campaign_wear", {"creepwork", "mpirun", "scratch"})) return 2;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(wear_ranks_bitwise),
        cmocka_unit_test(wear_matches_creepwork_wear),
        cmocka_unit_test(wear_resume_after_kill),
        cmocka_unit_test(wear_bad_inputs_fail_cleanly),
    };
    return cw_run_tests(tests, g_tools.test);
}
