/* Temperature and damage columns of campaigns (`creepwork campaign
 * --temperature`, `--mu-T`, `--k-yield`): every new column of every row
 * equal, bitwise, to the key of the same name in `creepwork solve --format
 * json` for the same contact and options (the campaign prints the digits the
 * JSON prints, the shortest that read back as the same double), for elliptic
 * rows (FASTSIM on Kalker's strips, the exact model on the uniform grid, in
 * partial and full slip) and a row of any shape (a gap file); the same
 * bytes for 1 and 2 ranks; after a SIGKILL and --resume; and every invalid
 * input refused naming it.
 *
 * usage: test_campaign_surface <creepwork> <mpirun> <scratch dir> <test name> */
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "campaign_test_support.hpp"
// Last: cmocka defines macros (fail, skip) that clash with the C++ library.
#include "test_support.h"

namespace fs = std::filesystem;
using namespace cwtest;

namespace {

double num(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

// One contact as a campaign row (CSV cells) and as `creepwork solve` options.
struct Contact {
    std::string id;
    std::string cells;              // the row after its id, in kColumns' order
    std::vector<std::string> solve; // the same contact for creepwork solve
};

const char* const kHeader = "id,model,grid,nx,ny,box_scale,a,b,N,mu,G,nu,xi_x,xi_y,phi,V,gap_file";

// A Hertzian gap h = x^2/0.92 + y^2/0.6 on 20 x 20 cells of 0.5 mm (a wheel
// of radius 0.46 m on a rail crown of 0.3 m), as doc/campaigns.md's.
void write_gap_file(const std::string& file)
{
    std::string text = "x_m,y_m,h_m\n";
    char line[128];
    for (int j = 0; j < 20; ++j)
        for (int i = 0; i < 20; ++i) {
            const double x = (i - 9.5) * 5e-4, y = (j - 9.5) * 5e-4;
            std::snprintf(line, sizeof line, "%.6g,%.6g,%.12g\n", x, y,
                          x * x / 0.92 + y * y / 0.6);
            text += line;
        }
    write_text(file, text);
}

std::vector<std::string> ellipse_args(const std::string& model, const std::string& grid,
                                      const std::string& n, const std::string& a,
                                      const std::string& b, const std::string& N,
                                      const std::string& xi_x, const std::string& xi_y,
                                      const std::string& phi)
{
    std::vector<std::string> s = {"--model", model, "--grid", grid, "--nx", n, "--ny", n,
                                  "--a", a, "--b", b, "--N", N, "--mu", "0.3", "--G", "82e9",
                                  "--nu", "0.28", "--xi-x", xi_x, "--xi-y", xi_y, "--spin", phi};
    if (grid == "uniform") s.insert(s.end(), {"--box-scale", "1.2"});
    return s;
}

// Elliptic rows (FASTSIM in partial and full slip, the exact model; with V,
// and one without, which takes the options' --speed) and a gap row.
std::vector<Contact> contacts(const std::string& gap_file)
{
    std::vector<Contact> c;
    c.push_back({"strips", "fastsim,kalker_strips,20,20,,0.0072,0.0054,100e3,0.3,82e9,0.28,2e-3,0,0.5,30,",
                 ellipse_args("fastsim", "kalker_strips", "20", "0.0072", "0.0054", "100e3",
                              "2e-3", "0", "0.5")});
    c.back().solve.insert(c.back().solve.end(), {"--V", "30"});
    c.push_back({"full-slip", "fastsim,kalker_strips,16,16,,0.0068,0.0057,95e3,0.3,82e9,0.28,1e-2,-2e-3,-0.5,30,",
                 ellipse_args("fastsim", "kalker_strips", "16", "0.0068", "0.0057", "95e3",
                              "1e-2", "-2e-3", "-0.5")});
    c.back().solve.insert(c.back().solve.end(), {"--V", "30"});
    c.push_back({"exact-no-V", "exact,uniform,16,16,1.2,0.006,0.005,80e3,0.3,82e9,0.28,1e-3,5e-4,0.4,,",
                 ellipse_args("exact", "uniform", "16", "0.006", "0.005", "80e3", "1e-3",
                              "5e-4", "0.4")});
    c.push_back({"gap", "exact,,,,,,,60e3,0.3,82e9,0.28,1e-3,0,0.3,30," + gap_file,
                 {"--gap", gap_file, "--N", "60e3", "--mu", "0.3", "--G", "82e9", "--nu", "0.28",
                  "--xi-x", "1e-3", "--xi-y", "0", "--spin", "0.3", "--V", "30"}});
    return c;
}

void write_contacts(const std::string& file, const std::vector<Contact>& rows)
{
    std::string text = std::string(kHeader) + "\n";
    for (const Contact& r : rows) text += r.id + "," + r.cells + "\n";
    write_text(file, text);
}

const std::vector<std::string> kTemperatureKeys = {"T_max_1", "T_max_2", "T_max_x", "T_max_y"};
const std::vector<std::string> kDamageKeys = {"rcf_index_max", "FI_surf", "T_gamma",
                                              "wlrm_damage"};

// Each row of dir/results.csv against `creepwork solve --format json` with
// the row's options and `options` (minus --speed where the row has V): the
// keys `keys` and the forces, bitwise; keys absent from the header are
// absent. Returns the campaign's T_max_1 per row (NaN without it).
std::vector<double> expect_equals_solve(const std::string& dir, const std::vector<Contact>& rows,
                                        const std::vector<std::string>& options,
                                        const std::vector<std::string>& keys,
                                        const std::vector<std::string>& absent)
{
    const auto records = read_csv(dir + "/results.csv");
    assert_int_equal(records.size(), rows.size() + 1);
    const auto idx = header_index(records[0]);
    for (const std::string& k : absent) assert_true(idx.count(k) == 0);
    std::vector<double> hottest;
    for (size_t r = 0; r < rows.size(); ++r) {
        const auto& rec = records[r + 1];
        assert_string_equal(rec[idx.at("id")].c_str(), rows[r].id.c_str());
        if (rec[idx.at("status")] != "ok") {
            print_error("row %s: %s\n", rows[r].id.c_str(), rec[idx.at("message")].c_str());
            fail();
        }
        std::vector<std::string> args = {"solve", "--format", "json"};
        args.insert(args.end(), rows[r].solve.begin(), rows[r].solve.end());
        const bool has_V =
            std::find(rows[r].solve.begin(), rows[r].solve.end(), "--V") != rows[r].solve.end();
        for (size_t k = 0; k < options.size(); ++k) {
            if (has_V && options[k] == "--speed") {
                ++k; // the row's V is the speed
                continue;
            }
            args.push_back(options[k]);
        }
        const Json j = parse_or_fail(cli_ok(args).out);
        std::vector<std::string> compared = keys;
        compared.insert(compared.end(), {"Fx", "Fy", "W_macro"});
        for (const std::string& key : compared) {
            const double mine = num(rec[idx.at(key)]);
            if (!(mine == j.num(key))) {
                print_error("row %s, %s: campaign %s, creepwork solve %.17g\n",
                            rows[r].id.c_str(), key.c_str(), rec[idx.at(key)].c_str(),
                            j.num(key));
                fail();
            }
        }
        hottest.push_back(idx.count("T_max_1") ? num(rec[idx.at("T_max_1")]) : NAN);
    }
    return hottest;
}

// Every row of dir/results.csv has T_max_1 != T_max_2 (by more than 0.1
// degC), so that a column with the other body's maximum shows.
void expect_bodies_differ(const std::string& dir)
{
    const auto records = read_csv(dir + "/results.csv");
    const auto idx = header_index(records[0]);
    for (size_t r = 1; r < records.size(); ++r)
        assert_true(std::fabs(num(records[r][idx.at("T_max_1")]) -
                              num(records[r][idx.at("T_max_2")])) > 0.1);
}

// ------------------------------------------------------------------- tests

void surface_matches_creepwork_solve(void** state)
{
    (void)state;
    write_gap_file(path("hertz.csv"));
    const std::vector<Contact> rows = contacts(path("hertz.csv"));
    write_contacts(path("in.csv"), rows);

    // Both bodies' properties apart from the defaults (body 2 conducts less),
    // and the damage indices.
    const std::vector<std::string> options = {"--temperature", "--speed", "30", "--T0-1", "25",
                                              "--conductivity-2", "40", "--k-yield", "3e8"};
    std::vector<std::string> args = {"--in", path("in.csv"), "--out", path("one"), "--quiet",
                                     "--threads", "2"};
    args.insert(args.end(), options.begin(), options.end());
    expect_status(campaign(0, args), 0);
    std::vector<std::string> keys = kTemperatureKeys;
    keys.insert(keys.end(), kDamageKeys.begin(), kDamageKeys.end());
    const std::vector<double> hottest =
        expect_equals_solve(path("one"), rows, options, keys, {"temperature_iterations"});
    for (double T : hottest) assert_true(T > 26.0); // the rows heat up: not 0 against 0

    // Two ranks, a chunk per row: the same bytes.
    args[3] = path("two");
    args.insert(args.end(), {"--chunk", "1"});
    expect_status(campaign(2, args), 0);
    assert_true(slurp(path("one/results.csv")) == slurp(path("two/results.csv")));

    // CONTACT's discretisation, without damage: no damage columns. With
    // dissimilar bodies it gives each its own temperature in contact.
    const std::vector<std::string> contact = {
        "--temperature", "--speed", "30", "--temperature-discretisation", "contact",
        "--T0-2", "40", "--conductivity-2", "25", "--heat-capacity-2", "600"};
    args = {"--in", path("in.csv"), "--out", path("contact"), "--quiet"};
    args.insert(args.end(), contact.begin(), contact.end());
    expect_status(campaign(0, args), 0);
    expect_equals_solve(path("contact"), rows, contact, kTemperatureKeys, kDamageKeys);
    expect_bodies_differ(path("contact"));

    // Damage alone needs no rolling speed: no temperature columns.
    const std::vector<std::string> damage = {"--k-yield", "2.5e8"};
    args = {"--in", path("in.csv"), "--out", path("damage"), "--quiet"};
    args.insert(args.end(), damage.begin(), damage.end());
    expect_status(campaign(0, args), 0);
    expect_equals_solve(path("damage"), rows, damage, kDamageKeys, kTemperatureKeys);
}

// Friction mu(T): the fixed-point loop of each row (the exact model on the
// uniform grid) equals `creepwork solve --mu-T`'s, iterations included,
// whichever thread or rank solved the rows before it.
void surface_mu_T_matches_creepwork_solve(void** state)
{
    (void)state;
    std::vector<Contact> rows;
    const char* const creepages[] = {"1e-3", "3e-3", "1e-3"};
    for (int k = 0; k < 3; ++k) {
        const std::string xi = creepages[k];
        rows.push_back({"mu-T-" + std::to_string(k),
                        "exact,uniform,12,12,1.2,0.006,0.005,80e3,0.3,82e9,0.28," + xi + ",5e-4,0.4,30,",
                        ellipse_args("exact", "uniform", "12", "0.006", "0.005", "80e3", xi,
                                     "5e-4", "0.4")});
        rows.back().solve.insert(rows.back().solve.end(), {"--V", "30"});
    }
    write_contacts(path("in.csv"), rows);
    // CONTACT's discretisation, which tells the bodies apart (the consistent
    // one gives both one temperature in contact), as CONTACT's euro_tractcurv.
    const std::vector<std::string> options = {
        "--temperature", "--temperature-discretisation", "contact", "--T0-2", "10",
        "--conductivity-2", "25", "--heat-capacity-2", "600", "--mu-T", "0:0.4,300:0.2",
        "--k-yield", "3e8"};
    std::vector<std::string> keys = kTemperatureKeys;
    keys.push_back("temperature_iterations");
    keys.insert(keys.end(), kDamageKeys.begin(), kDamageKeys.end());
    std::string reference;
    for (int np : {0, 2}) {
        const std::string out = path("out" + std::to_string(np));
        std::vector<std::string> args = {"--in", path("in.csv"), "--out", out, "--quiet",
                                         "--threads", "1", "--chunk", np ? "1" : "3"};
        args.insert(args.end(), options.begin(), options.end());
        expect_status(campaign(np, args), 0);
        if (np == 0) {
            expect_equals_solve(out, rows, options, keys, {});
            reference = slurp(out + "/results.csv");
        } else {
            assert_true(slurp(out + "/results.csv") == reference);
        }
    }
    expect_bodies_differ(path("out0"));
    // The loop ran: more than one pass, and the first and last rows (the
    // same contact, one solved after another on the same thread) agree.
    const auto records = read_csv(path("out0/results.csv"));
    const auto idx = header_index(records[0]);
    assert_true(num(records[1][idx.at("temperature_iterations")]) >= 3);
    for (const char* key : {"Fx", "T_max_1", "temperature_iterations"})
        assert_string_equal(records[1][idx.at(key)].c_str(), records[3][idx.at(key)].c_str());
}

void surface_resume_after_kill(void** state)
{
    (void)state;
    const std::vector<Row> rows = mixed_rows();
    write_input(path("in.csv"), rows);
    const std::vector<std::string> options = {"--temperature", "--speed", "30", "--k-yield",
                                              "3e8", "--quiet"};
    const auto args_for = [&](const std::string& out) {
        std::vector<std::string> a = {"--in", path("in.csv"), "--out", out};
        a.insert(a.end(), options.begin(), options.end());
        return a;
    };
    std::vector<std::string> args = args_for(path("ref"));
    args.insert(args.end(), {"--threads", "1"});
    expect_status(campaign(2, args), 0);
    const std::string reference = slurp(path("ref/results.csv"));
    assert_true(reference.find("T_max_1") != std::string::npos);

    const std::string checkpoint = path("run/checkpoint.cwj");
    args = args_for(path("run"));
    args.insert(args.end(), {"--threads", "1", "--chunk", "3"});
    kill_midway(2, args, 150, checkpoint, 4000);
    assert_false(exists(path("run/results.csv")));
    fs::resize_file(checkpoint, fs::file_size(checkpoint) - 5); // a torn last record

    // Other temperature options are another campaign: refused, nothing lost.
    args = args_for(path("run"));
    args.insert(args.end(), {"--resume", "--T0-1", "30"});
    Run r = expect_status(campaign(0, args), 2);
    expect_contains(r.err, "belongs to another input");

    args = args_for(path("run"));
    args.insert(args.end(), {"--resume", "--threads", "1"});
    expect_status(campaign(3, args), 0);
    if (slurp(path("run/results.csv")) != reference) {
        print_error("the resumed run's results differ from the uninterrupted run's\n");
        fail();
    }
    expect_resumed_part(path("run"), rows.size());
}

void surface_bad_inputs_fail_cleanly(void** state)
{
    (void)state;
    write_gap_file(path("hertz.csv"));
    write_contacts(path("in.csv"), contacts(path("hertz.csv")));
    const std::string out = path("out");
    struct Case {
        std::vector<std::string> args;
        std::string message;
    };
    const std::vector<Case> cases = {
        {{"--T0-1", "30"}, "--T0-1: needs --temperature"},
        {{"--mu-T", "0:0.3,400:0.2"}, "--mu-T: needs --temperature"},
        {{"--temperature", "--mu-T", "0:0.3;400:0.2"}, "--mu-T: \"0:0.3;400:0.2\" is not a pair"},
        {{"--k-yield", "-1"}, "--k-yield: must lie in (0, 1e12] Pa"},
        {{"--speed", "30"}, "--speed: only used with --wear or --temperature"},
        {{"--temperature", "--speed", "0"}, "--speed: must lie in (0, 1000] m/s"},
        {{"--temperature", "--temperature-discretisation", "exact"},
         "--temperature-discretisation"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args = {"--in", path("in.csv"), "--out", out};
        args.insert(args.end(), c.args.begin(), c.args.end());
        expect_refusal(campaign(0, args), 2, c.message, c.message);
        assert_false(exists(out + "/results.csv"));
    }
    expect_refusal(campaign(0, {"--table", "--out", out, "--temperature"}), 2,
                   "--temperature: not used with --table", "--table --temperature");

    // Rows: one without a rolling speed, one whose V differs from --speed;
    // each fails alone, naming its line and column.
    write_text(path("speeds.csv"),
               std::string(kHeader) + "\n"
               "no-speed,fastsim,,,,,0.006,0.005,80e3,0.3,82e9,0.28,1e-3,0,0,,\n"
               "with-V,fastsim,,,,,0.006,0.005,80e3,0.3,82e9,0.28,1e-3,0,0,30,\n");
    expect_status(campaign(0, {"--in", path("speeds.csv"), "--out", path("speeds"),
                               "--temperature"}), 0);
    std::string results = slurp(path("speeds/results.csv"));
    expect_contains(results, "no-speed,ROW_UNREADABLE");
    expect_contains(results, "line 2, column V: empty: --temperature needs the rolling speed");
    expect_contains(results, "with-V,ok");
    expect_status(campaign(0, {"--in", path("speeds.csv"), "--out", path("speeds2"),
                               "--temperature", "--speed", "20"}), 0);
    results = slurp(path("speeds2/results.csv"));
    expect_contains(results, "no-speed,ok");
    expect_contains(results, "line 3, column V: 30 m/s differs from --speed 20 m/s");

    // Values the library refuses: every row fails with its message, which
    // names the option.
    write_text(path("exact.csv"),
               std::string(kHeader) + "\n"
               "e1,exact,uniform,12,12,1.2,0.006,0.005,80e3,0.3,82e9,0.28,1e-3,0,0,30,\n"
               "e2,exact,uniform,12,12,1.2,0.006,0.005,80e3,0.3,82e9,0.28,2e-3,0,0,30,\n");
    const Run bad_T = expect_status(
        campaign(0, {"--in", path("exact.csv"), "--out", path("bad-mu-T"), "--temperature",
                     "--mu-T", "400:0.3,0:0.2"}),
        0);
    expect_contains(bad_T.err, "0 solved, 2 failed");
    expect_contains(slurp(path("bad-mu-T/results.csv")), "(options --mu-T)");
    const Run bad_k = expect_status(
        campaign(0, {"--in", path("speeds.csv"), "--out", path("bad-conductivity"),
                     "--temperature", "--speed", "30", "--conductivity-1", "1e9"}),
        0);
    expect_contains(bad_k.err, "0 solved, 2 failed");
    expect_contains(slurp(path("bad-conductivity/results.csv")), "(options --conductivity-1)");
}

} // namespace

int main(int argc, char** argv)
{
    if (!set_up(argc, argv, "test_campaign_surface", {"creepwork", "mpirun", "scratch"})) return 2;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(surface_matches_creepwork_solve),
        cmocka_unit_test(surface_mu_T_matches_creepwork_solve),
        cmocka_unit_test(surface_resume_after_kill),
        cmocka_unit_test(surface_bad_inputs_fail_cleanly),
    };
    return cw_run_tests(tests, g_tools.test);
}
