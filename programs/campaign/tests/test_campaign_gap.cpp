/* Tests of campaign rows with a gap_file (contacts of any shape), run as a
 * user runs them: a campaign mixing elliptic rows with rows on two of
 * CONTACT's DEV gaps (tests/data/nonhertz/dev: D03_twolobes, two
 * Hertzian lobes; D14_prof_y5, S1002 on UIC60 at a 5 mm lateral shift, a
 * tread and a flange-root patch), by the exact model and FASTSIM, with the
 * force or the approach prescribed and both normal methods. Every gap row's
 * numbers must be what `creepwork solve --gap` gives for the same inputs
 * (another path: its own reader, a cw_solver instead of a cw_batch) and,
 * for the exact model, CONTACT's; results.csv must be bitwise the same on
 * one and two ranks and in chunks of one row; a bad row fails alone with a
 * message naming its line and column (and the gap file's line); units that
 * look like millimetres typed as metres are warned about.
 *
 * usage: test_campaign_gap <creepwork> <mpirun> <scratch dir> <test name> */
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "campaign_test_support.hpp"
// Last: cmocka defines macros (fail, skip) that clash with the C++ library.
#include "test_support.h"

namespace fs = std::filesystem;
using namespace cwtest;

namespace {

const std::string kDev = std::string(CW_TEST_DATA_DIR) + "/nonhertz/dev";

// CONTACT's DEV cases: the inputs and results of dev/cases.csv, by case id.
std::map<std::string, std::map<std::string, std::string>> dev_cases()
{
    const auto records = read_csv(kDev + "/cases.csv");
    const auto idx = header_index(records.at(0));
    std::map<std::string, std::map<std::string, std::string>> out;
    for (size_t k = 1; k < records.size(); ++k)
        for (const auto& [name, column] : idx) out[records[k][idx.at("case_id")]][name] = records[k][column];
    return out;
}

const std::vector<std::string> kColumns = {
    "id",     "gap_file", "model", "grid", "nx", "ny", "a", "b", "N", "approach",
    "normal_method", "mu", "G", "nu", "xi_x", "xi_y", "phi"};

// The campaign's rows: elliptic ones around gap rows on D03 (relative to the
// input's directory) and D14 (absolute), with the creepages and loads of
// CONTACT's cases.
std::vector<Row> mixed_gap_rows(const std::string& d03, const std::string& d14)
{
    auto dev = dev_cases();
    const auto gap_row = [&](const char* id, const std::string& file, const char* dev_case) {
        const auto& c = dev.at(dev_case);
        return Row{{"id", id}, {"gap_file", file}, {"N", c.at("N_N")}, {"mu", c.at("mu")},
                   {"G", c.at("G_Pa")}, {"nu", c.at("nu")}, {"xi_x", c.at("xi_x")},
                   {"xi_y", c.at("xi_y")}, {"phi", c.at("phi_per_m")}};
    };
    std::vector<Row> rows;
    rows.push_back({{"id", "e1"}, {"model", "fastsim"}, {"grid", "strips"}, {"nx", "12"},
                    {"ny", "12"}, {"a", "0.006"}, {"b", "0.005"}, {"N", "80000"}, {"mu", "0.3"},
                    {"G", "82e9"}, {"nu", "0.28"}, {"xi_x", "0.001"}, {"phi", "0.5"}});
    rows.push_back(gap_row("d03-exact", d03, "D03_twolobes"));
    rows.push_back(gap_row("d14-exact", d14, "D14_prof_y5"));
    Row r = gap_row("d03-fastsim", d03, "D03_twolobes");
    r["model"] = "fastsim";
    rows.push_back(r);
    rows.push_back({{"id", "e2"}, {"model", "exact"}, {"grid", "uniform"}, {"nx", "10"},
                    {"ny", "10"}, {"a", "0.007"}, {"b", "0.0054"}, {"N", "100000"},
                    {"mu", "0.3"}, {"G", "82e9"}, {"nu", "0.28"}, {"xi_y", "0.0008"}});
    r = gap_row("d14-approach-semi", d14, "D14_prof_y5");
    r["N"] = "";
    r["approach"] = "4e-5";
    r["normal_method"] = "semi-hertz";
    rows.push_back(r);
    r = gap_row("d03-approach", d03, "D03_twolobes");
    r["N"] = "";
    r["approach"] = "5e-5";
    rows.push_back(r);
    r = gap_row("d14-fastsim-semi", d14, "D14_prof_y5");
    r["model"] = "fastsim";
    r["normal_method"] = "semi-hertz";
    rows.push_back(r);
    return rows;
}

// `creepwork solve --gap` for a gap row (its JSON).
Json solve_gap(const Row& row, const std::string& file)
{
    std::vector<std::string> args = {"solve", "--gap", file, "--format", "json"};
    for (const char* key : {"model", "N", "approach", "normal_method", "mu", "G", "nu", "xi_x",
                            "xi_y", "phi"}) {
        const auto it = row.find(key);
        if (it == row.end() || it->second.empty()) continue;
        const std::string option = std::string(key) == "normal_method" ? "normal-method"
                                   : std::string(key) == "xi_x"        ? "xi-x"
                                   : std::string(key) == "xi_y"        ? "xi-y"
                                   : std::string(key) == "phi"         ? "spin"
                                                                       : key;
        args.push_back("--" + option);
        args.push_back(it->second);
    }
    return parse_or_fail(expect_status(cli(args), 0).out);
}

double number(const std::string& cell) { return std::strtod(cell.c_str(), nullptr); }

// ------------------------------------------------------------------- tests

// Each gap row equals `creepwork solve --gap`, the exact ones CONTACT, the
// elliptic rows the library's one-by-one solve; one rank, two ranks and
// chunks of one row give the same bytes.
void gap_rows_match_solve_gap_on_any_ranks(void** state)
{
    (void)state;
    fs::create_directories(path("gaps"));
    fs::copy_file(kDev + "/gaps/D03_twolobes.csv", path("gaps/D03.csv"));
    const std::string d14 = kDev + "/gaps/D14_prof_y5.csv";
    const std::vector<Row> rows = mixed_gap_rows("gaps/D03.csv", d14);
    write_input(path("in.csv"), rows, kColumns);

    struct Config {
        int np;
        std::vector<std::string> extra;
    };
    const std::vector<Config> configs = {{1, {"--threads", "1"}},
                                         {2, {"--threads", "1"}},
                                         {2, {"--threads", "2", "--chunk", "1"}}};
    std::string reference;
    for (size_t c = 0; c < configs.size(); ++c) {
        const std::string out = path("out" + std::to_string(c));
        std::vector<std::string> args = {"--in", path("in.csv"), "--out", out, "--quiet"};
        args.insert(args.end(), configs[c].extra.begin(), configs[c].extra.end());
        const Run r = expect_status(campaign(configs[c].np, args), 0);
        expect_contains(r.err, "8 rows: 8 solved, 0 failed");
        const std::string results = slurp(out + "/results.csv");
        if (c == 0) {
            reference = results;
        } else if (results != reference) {
            print_error("np %d %s %s: results.csv differs from one rank's\n", configs[c].np,
                        configs[c].extra[0].c_str(), configs[c].extra[1].c_str());
            fail();
        }
    }

    const auto records = read_csv(path("out0/results.csv"));
    assert_int_equal(records.size(), rows.size() + 1);
    const auto idx = header_index(records[0]);
    const auto dev = dev_cases();
    for (size_t k = 0; k < rows.size(); ++k) {
        const Row& row = rows[k];
        const auto& rec = records[k + 1];
        assert_string_equal(rec[idx.at("status")].c_str(), "ok");
        assert_string_equal(rec[idx.at("message")].c_str(), "");
        if (row.count("gap_file") == 0) {
            // Elliptic rows: the library's own digits, Fn = N, one patch.
            const Expected e = solve_directly(row);
            assert_int_equal(e.status, CW_OK);
            for (const auto& [name, text] : e.cells)
                assert_string_equal(rec[idx.at(name)].c_str(), text.c_str());
            assert_true(number(rec[idx.at("Fn")]) == number(row.at("N")));
            assert_string_equal(rec[idx.at("n_patches")].c_str(), "1");
            continue;
        }
        const std::string file = row.at("gap_file") == d14 ? d14 : path("gaps/D03.csv");
        const Json j = solve_gap(row, file);
        const double muN = number(row.at("mu")) * j.num("Fn");
        // To rounding: 1e-12 of the case's scale (mu Fn, and for Mz mu Fn
        // times 10 mm, an arm larger than both files' patches).
        const struct {
            const char* key;
            double tol;
        } checks[] = {{"Fx", 1e-12 * muN},        {"Fy", 1e-12 * muN},
                      {"Mz", 1e-14 * muN},        {"Fn", 1e-12 * j.num("Fn")},
                      {"W_macro", 1e-12 * muN},   {"p_max", 1e-12 * j.num("p_max")},
                      {"approach", 1e-12 * j.num("approach")}};
        for (const auto& c : checks) {
            const double cell = number(rec[idx.at(c.key)]);
            if (!(std::fabs(cell - j.num(c.key)) <= c.tol))
                print_error("row %s, %s: campaign %.17g, creepwork solve --gap %.17g\n",
                            row.at("id").c_str(), c.key, cell, j.num(c.key));
            assert_true(std::fabs(cell - j.num(c.key)) <= c.tol);
        }
        for (const char* key : {"n_contact", "n_adhesion", "n_slip", "n_patches"})
            assert_int_equal(std::atol(rec[idx.at(key)].c_str()), static_cast<long>(j.num(key)));
        assert_int_equal(std::atol(rec[idx.at("n_patches")].c_str()), 2);
        // Exact model, force prescribed: CONTACT's results for the case, at
        // 1e-4 of mu N (tests/nonhertz holds the model to 1e-5).
        if (row.at("N").empty() || row.count("model")) continue;
        const auto& ref = dev.at(row.at("gap_file") == d14 ? "D14_prof_y5" : "D03_twolobes");
        for (const char* key : {"Fx", "Fy"}) {
            const double contact = number(ref.at(std::string(key) + "_N"));
            assert_close(number(rec[idx.at(key)]), contact, 0.0, 1e-4 * muN);
        }
        assert_close(number(rec[idx.at("p_max")]), number(ref.at("p_max_Pa")), 1e-4, 0.0);
        assert_int_equal(std::atol(rec[idx.at("n_patches")].c_str()),
                         std::atol(ref.at("n_patches").c_str()));
    }
}

// A row with a bad gap file or bad gap columns fails alone: its status, a
// message naming its line and column (and the file's line), the others solved.
void gap_bad_rows_fail_alone(void** state)
{
    (void)state;
    const std::string d03 = kDev + "/gaps/D03_twolobes.csv";
    std::string text = slurp(d03);
    // Line 4 of the copy: a value that is not a number.
    size_t at = 0;
    for (int line = 1; line < 4; ++line) at = text.find('\n', at) + 1;
    const size_t comma = text.rfind(',', text.find('\n', at));
    text.replace(comma + 1, text.find('\n', at) - comma - 1, "0.1.2");
    scratch_file("bad.csv", text);
    const std::string good = ",60000,,,0.3,82e9,0.28,0.001706,0,0.3248";
    const std::string header =
        "id,gap_file,model,a,b,N,approach,normal_method,mu,G,nu,xi_x,xi_y,phi\n";
    std::string in = header;
    in += "ok," + d03 + ",exact,," + good + "\n";                               // line 2
    in += "missing,nowhere.csv,exact,," + good + "\n";                           // line 3
    in += "malformed,bad.csv,exact,," + good + "\n";                             // line 4
    in += "with-a," + d03 + ",exact,0.006," + good + "\n";                         // line 5
    in += "calibrated," + d03 + ",calibrated,," + good + "\n";                    // line 6
    in += "both," + d03 + ",exact,,,60000,4e-5,,0.3,82e9,0.28,0.001706,0,0.3248\n"; // line 7
    in += "neither," + d03 + ",exact,,,,,,0.3,82e9,0.28,0.001706,0,0.3248\n";    // line 8
    in += "method," + d03 + ",exact,,,60000,,semi,0.3,82e9,0.28,0.001706,0,0.3248\n"; // line 9
    in += "elliptic-approach,,fastsim,0.006,0.005,60000,4e-5,,0.3,82e9,0.28,0,0,0\n"; // line 10
    in += "ok2," + d03 + ",fastsim,," + good + "\n";                              // line 11
    scratch_file("in.csv", in);
    const Run r = expect_status(campaign(2, {"--in", path("in.csv"), "--out", path("out")}), 0);
    expect_contains(r.err, "10 rows: 2 solved, 8 failed");
    const auto records = read_csv(path("out/results.csv"));
    assert_int_equal(records.size(), 11);
    const auto idx = header_index(records[0]);
    const auto expect_row = [&](size_t k, const char* id, const char* status,
                                const std::string& message) {
        const auto& rec = records[k];
        assert_string_equal(rec[idx.at("id")].c_str(), id);
        if (rec[idx.at("status")] != status || rec[idx.at("message")] != message)
            print_error("row %s: %s \"%s\", expected %s \"%s\"\n", id,
                        rec[idx.at("status")].c_str(), rec[idx.at("message")].c_str(), status,
                        message.c_str());
        assert_string_equal(rec[idx.at("status")].c_str(), status);
        assert_string_equal(rec[idx.at("message")].c_str(), message.c_str());
        if (std::string(status) != "ok") assert_string_equal(rec[idx.at("Fx")].c_str(), "");
    };
    const std::string dir = fs::absolute(g_tools.scratch).lexically_normal().string();
    expect_row(1, "ok", "ok", "");
    expect_row(2, "missing", "ROW_UNREADABLE",
               "line 3, column gap_file: cannot open " + dir + "/nowhere.csv");
    expect_row(3, "malformed", "ROW_UNREADABLE",
               "line 4, column gap_file: " + dir + "/bad.csv:4: \"0.1.2\" is not a finite number");
    expect_row(4, "with-a", "ROW_UNREADABLE",
               "line 5, column a: must be empty on a row with a gap_file: the gap file defines "
               "the contact (no semi-axes)");
    expect_row(5, "calibrated", "CW_ERR_INVALID_INPUT",
               "line 6, column model: calibrated is not available on a row with a gap_file: a "
               "gap is solved by the exact model (the default there) or fastsim");
    expect_row(6, "both", "ROW_UNREADABLE",
               "line 7, column N/approach: give the normal force or the approach, not both");
    expect_row(7, "neither", "ROW_UNREADABLE",
               "line 8, column N: empty: a row with a gap_file needs the normal force N or the "
               "approach");
    expect_row(8, "method", "ROW_UNREADABLE",
               "line 9, column normal_method: 'semi' is not one of exact|semi_hertz");
    expect_row(9, "elliptic-approach", "ROW_UNREADABLE",
               "line 10, column approach: only used on a row with a gap_file (a contact of any "
               "shape)");
    expect_row(10, "ok2", "ok", "");

    // A wear campaign takes elliptic rows only: the file is refused.
    write_text(path("wear.csv"), "id,s0,passes,gap_file,N\nw,0,1," + d03 + ",60000\n");
    const Run wear = expect_status(
        campaign(0, {"--in", path("wear.csv"), "--out", path("wear"), "--wear"}), 2);
    expect_contains(wear.err, "column gap_file: creepwork campaign --wear takes elliptic rows only");
    // Without N and approach columns no gap row can be read.
    write_text(path("noload.csv"), "id,gap_file\nx," + d03 + "\n");
    const Run noload = expect_status(
        campaign(0, {"--in", path("noload.csv"), "--out", path("noload")}), 2);
    expect_contains(noload.err, "the header lacks N and approach");
}

// A gap file written in millimetres, and an approach in millimetres, are
// solved with warnings in the row's message (--strict rejects the row).
void gap_unit_mistakes_are_warned(void** state)
{
    (void)state;
    // D03 with every value in millimetres: cells of 0.3485 "m", gaps of 0.2 "m".
    const auto records = read_csv(kDev + "/gaps/D03_twolobes.csv");
    std::string mm = "x_m,y_m,h_m\n";
    for (size_t k = 1; k < records.size(); ++k)
        mm += round_trip(number(records[k][0]) * 1e3) + "," +
              round_trip(number(records[k][1]) * 1e3) + "," +
              round_trip(number(records[k][2]) * 1e3) + "\n";
    scratch_file("mm.csv", mm);
    const std::string d03 = kDev + "/gaps/D03_twolobes.csv";
    scratch_file("in.csv", "id,gap_file,N,approach,xi_x\n"
                           "mm,mm.csv,60000,,0.001\n"
                           "approach-mm," + d03 + ",,0.05,0.001\n"
                           "fine," + d03 + ",60000,,0.001\n");
    const Run r = expect_status(campaign(0, {"--in", path("in.csv"), "--out", path("out")}), 0);
    expect_contains(r.err, "3 rows: 3 solved, 0 failed");
    expect_contains(r.err, "2 rows were solved with warnings");
    const auto out = read_csv(path("out/results.csv"));
    const auto idx = header_index(out[0]);
    const std::string file = fs::absolute(path("mm.csv")).lexically_normal().string();
    const std::string& m = out[1][idx.at("message")];
    expect_contains(m, "warning: column gap_file: " + file + ": dx = 0.3485 m is "
                       "implausible for a wheel-rail contact: gap cells are 0.05-1 mm (a gap "
                       "grid in millimetres typed as metres?)");
    expect_contains(m, ": dy = 0.417143 m is implausible");
    // the heights' spread, to 1 um
    expect_contains(m, ": gap = 0.203864 m is implausible for a wheel-rail contact: its heights "
                       "span this much");
    expect_contains(out[2][idx.at("message")],
                    "warning: column approach = 0.05 m is implausible for a wheel-rail contact: "
                    "approaches are 10-200 um (millimetres typed as metres?");
    assert_string_equal(out[3][idx.at("message")].c_str(), "");
    // mm.csv and D03 have the same cell counts but other cells: each row is
    // solved on its own grid (one batch per distinct gap grid), as solve --gap.
    for (const auto& [row, gap] : {std::pair<size_t, std::string>{1, path("mm.csv")}, {3, d03}}) {
        const Json j = parse_or_fail(
            expect_status(cli({"solve", "--gap", gap, "--N", "60000", "--xi-x", "0.001",
                               "--format", "json"}),
                          0)
                .out);
        for (const char* key : {"Fx", "p_max", "approach"})
            assert_true(number(out[row][idx.at(key)]) == j.num(key));
    }
    assert_true(number(out[1][idx.at("p_max")]) < 1e-3 * number(out[3][idx.at("p_max")]));
    const Run strict = expect_status(
        campaign(0, {"--in", path("in.csv"), "--out", path("strict"), "--strict"}), 0);
    expect_contains(strict.err, "3 rows: 1 solved, 2 failed");
}

// A gap file is an input: resuming after it changed is refused as another
// campaign; unchanged, the finished campaign resumes with nothing to do.
void gap_files_are_part_of_the_identity(void** state)
{
    (void)state;
    const std::string text = slurp(kDev + "/gaps/D03_twolobes.csv");
    scratch_file("gap.csv", text);
    scratch_file("in.csv", "id,gap_file,N,xi_x\ng,gap.csv,60000,0.001\n");
    const std::vector<std::string> args = {"--in", path("in.csv"), "--out", path("out"),
                                           "--quiet"};
    expect_status(campaign(0, args), 0);
    expect_status(campaign(0, with(args, {"--resume"})), 0);
    // One gap value's last digit changed.
    std::string changed = text;
    const size_t end = changed.find('\n', changed.find('\n') + 1);
    changed[end - 1] = changed[end - 1] == '1' ? '2' : '1';
    scratch_file("gap.csv", changed);
    const Run r = expect_status(campaign(0, with(args, {"--resume"})), 2);
    expect_contains(r.err, "another input");
}

} // namespace

int main(int argc, char** argv)
{
    if (!set_up(argc, argv, "test_campaign_gap", {"creepwork", "mpirun", "scratch"})) return 2;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(gap_rows_match_solve_gap_on_any_ranks),
        cmocka_unit_test(gap_bad_rows_fail_alone),
        cmocka_unit_test(gap_unit_mistakes_are_warned),
        cmocka_unit_test(gap_files_are_part_of_the_identity),
    };
    return cw_run_tests(tests, g_tools.test);
}
