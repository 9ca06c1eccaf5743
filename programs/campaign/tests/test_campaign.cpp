/* Tests of `creepwork campaign`, run as a user runs it: through the
 * creepwork program, under mpirun with 1, 2 and 3 ranks (oversubscribed on
 * a small machine) and without mpirun. The results must be bitwise the same
 * for any number of ranks, threads and chunk sizes; every row's numbers
 * must be the library's own for that contact (a one-by-one cw_solver_solve)
 * and what `creepwork solve` prints; a bad row gets its own error line; a
 * bad input or output directory fails cleanly; a killed run resumes without
 * redoing finished chunks and ends bitwise equal to an uninterrupted run;
 * a creep-force table's entries equal direct solves of physical contacts.
 *
 * usage: test_campaign <creepwork> <mpirun> <scratch dir> <test name> */
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

// Every row of results.csv against a one-by-one solve of its input row:
// the same status, the same digits in every column.
void expect_rows_match_library(const std::string& results, const std::vector<Row>& rows)
{
    const auto records = read_csv(results);
    assert_int_equal(records.size(), rows.size() + 1);
    const auto idx = header_index(records[0]);
    for (size_t k = 0; k < rows.size(); ++k) {
        const auto& rec = records[k + 1];
        assert_int_equal(rec.size(), records[0].size());
        assert_string_equal(rec[idx.at("id")].c_str(), rows[k].at("id").c_str());
        const Expected e = solve_directly(rows[k]);
        if (e.status != CW_OK) {
            // The library's verdict; the message is the reader's (the check
            // of `creepwork solve`, naming the line and column).
            assert_string_equal(rec[idx.at("status")].c_str(), status_name(e.status));
            expect_contains(rec[idx.at("message")], "line ");
            continue;
        }
        assert_string_equal(rec[idx.at("status")].c_str(), "ok");
        assert_string_equal(rec[idx.at("message")].c_str(), "");
        for (const auto& [name, text] : e.cells) {
            if (rec[idx.at(name)] != text)
                print_error("row %s, column %s: %s, the library gives %s\n",
                            rows[k].at("id").c_str(), name.c_str(), rec[idx.at(name)].c_str(),
                            text.c_str());
            assert_string_equal(rec[idx.at(name)].c_str(), text.c_str());
        }
    }
}

std::vector<Row> rows_with_failures()
{
    std::vector<Row> rows = mixed_rows();
    Row exact = rows[1]; // uniform grid, G and nu: the exact model's own domain
    exact["id"] = "exact-1";
    exact["model"] = "exact";
    exact["nx"] = "8";
    exact["ny"] = "8";
    rows.insert(rows.begin() + 5, exact);
    Row bad_nu = rows[0];
    bad_nu["id"] = "bad-nu";
    bad_nu["nu"] = "0.7";
    rows.insert(rows.begin() + 20, bad_nu);
    return rows;
}

// ------------------------------------------------------------------- tests

void ranks_and_threads_bitwise(void** state)
{
    (void)state;
    const std::vector<Row> rows = rows_with_failures();
    write_input(path("in.csv"), rows);
    struct Config {
        int np;
        std::vector<std::string> extra;
    };
    const std::vector<Config> configs = {
        {0, {"--threads", "1"}},                   // no mpirun: MPI's singleton
        {1, {"--threads", "2"}},                   // one rank, two threads
        {2, {"--threads", "1"}},                   // two ranks
        {3, {"--threads", "1"}},                   // three ranks on two cores
        {2, {"--threads", "2", "--chunk", "1"}},   // one row per chunk
        {3, {"--threads", "2", "--chunk", "5"}},   // odd chunks across ranks
    };
    std::string reference;
    for (size_t c = 0; c < configs.size(); ++c) {
        const std::string out = path("out" + std::to_string(c));
        std::vector<std::string> args = {"--in", path("in.csv"), "--out", out, "--quiet"};
        args.insert(args.end(), configs[c].extra.begin(), configs[c].extra.end());
        const Run r = expect_status(campaign(configs[c].np, args), 0);
        expect_contains(r.err, std::to_string(rows.size()) + " rows: ");
        const std::string results = slurp(out + "/results.csv");
        assert_true(results.size() > 1000);
        if (c == 0) {
            reference = results;
            expect_rows_match_library(out + "/results.csv", rows);
        } else if (results != reference) {
            print_error("np %d with %s: results.csv differs from the first run's\n",
                        configs[c].np, configs[c].extra[1].c_str());
            fail();
        }
        // The checkpoint is gone once the results are complete.
        assert_false(exists(out + "/checkpoint.cwj"));
    }
}

void matches_creepwork_solve(void** state)
{
    (void)state;
    const std::vector<Row> all = mixed_rows();
    // Rows covering each option: both grids and box scale, elliptic
    // pressure, rolling towards -x, given flexibilities, CONTACT's options,
    // full slip.
    std::vector<Row> rows;
    for (int k : {0, 1, 2, 3, 4, 10, 15, 16, 27})
        rows.push_back(all[static_cast<size_t>(k)]);
    write_input(path("in.csv"), rows);
    expect_status(campaign(2, {"--in", path("in.csv"), "--out", path("out"), "--quiet"}), 0);
    const auto records = read_csv(path("out/results.csv"));
    const auto idx = header_index(records[0]);
    const char* keys[] = {"Fx", "Fy", "Mz", "W_macro", "W_micro_paper", "K", "W_consistent",
                          "balance_factor", "work_flags", "adhesion_fraction", "n_contact",
                          "n_adhesion", "n_slip", "a", "b", "L1", "L2", "L3", "C11", "C22",
                          "C23", "C33", "profile_max_diff", "profile_rms_diff"};
    for (size_t k = 0; k < rows.size(); ++k) {
        std::vector<std::string> argv = {g_tools.creepwork};
        const std::vector<std::string> args = row_to_solve_args(rows[k]);
        argv.insert(argv.end(), args.begin(), args.end());
        const Run r = expect_status(run(argv), 0);
        const Json j = parse_json(r.out);
        for (const char* key : keys) {
            const std::string& cell = records[k + 1][idx.at(key)];
            // Full precision: the same double, and the same digits.
            if (std::strtod(cell.c_str(), nullptr) != j.num(key))
                print_error("row %s, %s: campaign %s, creepwork solve %.17g\n",
                            rows[k].at("id").c_str(), key, cell.c_str(), j.num(key));
            assert_true(std::strtod(cell.c_str(), nullptr) == j.num(key));
            const std::string needle = "\"" + std::string(key) + "\": " + cell + ",";
            expect_contains(r.out, needle);
        }
    }
}

void bad_rows_get_error_lines(void** state)
{
    (void)state;
    const std::string good = "fastsim,strips,10,10,0.006,0.005,80000,0.3,82e9,0.28,0.001,0,0.5";
    const std::string header =
        "id,model,grid,nx,ny,a,b,N,mu,G,nu,xi_x,xi_y,phi,box_scale,L1,L2,L3\n";
    // A spreadsheet's UTF-8 byte-order mark before the header is not part of "id".
    std::string text = "\xEF\xBB\xBF" + header;
    text += "g1," + good + ",,,,\n";                                               // line 2
    text += "b1,fastsim,strips,10,10,0.006,0.005,80000,0.3,82e9,abc,0,0,0,,,,\n";   // line 3
    text += "b2,fastsim,strips,10,10,0.006,0.005,80000,0.3,82e9,0.28,0,0\n";        // line 4
    text += "b3,fastsm,strips,10,10,0.006,0.005,80000,0.3,82e9,0.28,0,0,0,,,,\n";   // line 5
    text += "g1," + good + ",,,,\n";                                               // line 6
    text += "b5,fastsim,strips,10,10,0.006,0.005,80000,0.3,82e9,0.28,0,0,0,1.2,,,\n"; // line 7
    text += "b6,fastsim,strips,10,10,0.006,0.005,80000,0.3,,,0,0,0,,5e-14,,\n";     // line 8
    text += "b7,fastsim,strips,10,10,0.006,0.005,80000,0.3,82e9,,0,0,0,,5e-14,5e-14,5e-14\n";
    text += "b8,fastsim,strips,10,10,0.006,0.005,80000,0.3,82e9,0.7,0,0,0,,,,\n";   // line 10
    text += "b9,fastsim,strips,0,10,0.006,0.005,80000,0.3,82e9,0.28,0,0,0,,,,\n";   // line 11
    text += "b10,exact,strips,10,10,0.006,0.005,80000,0.3,82e9,0.28,0,0,0,,,,\n";   // line 12
    text += "b11,fastsim,strips,10,10,0.006,0.005,80000,\"0.3\"x,82e9,0.28,0,0,0,,,,\n";
    text += "b12,fastsim,strips,10,10,,0.005,80000,0.3,82e9,0.28,0,0,0,,,,\n";      // line 14
    text += "b13,fastsim,strips,10,10,0.006,0.005,1e400,0.3,82e9,0.28,0,0,0,,,,\n"; // line 15
    text += "\n";                                                                  // line 16
    text += "\"g,2\"," + good + ",,,,\r\n";                                        // line 17
    write_text(path("in.csv"), text);
    const Run r = expect_status(
        campaign(2, {"--in", path("in.csv"), "--out", path("out"), "--threads", "1"}), 0);
    expect_contains(r.err, "15 rows: 2 solved, 13 failed");

    const auto records = read_csv(path("out/results.csv"));
    assert_int_equal(records.size(), 16);
    const auto idx = header_index(records[0]);
    const auto expect_row = [&](size_t k, const char* id, const char* status,
                                const std::string& message) {
        const auto& rec = records[k];
        assert_string_equal(rec[idx.at("id")].c_str(), id);
        assert_string_equal(rec[idx.at("status")].c_str(), status);
        assert_string_equal(rec[idx.at("message")].c_str(), message.c_str());
        if (std::string(status) != "ok") assert_string_equal(rec[idx.at("Fx")].c_str(), "");
    };
    // The library's own verdict on rows it rejects, from a one-by-one solve.
    const auto library = [](const std::string& line) {
        Row row;
        std::vector<std::string> cells;
        size_t pos = 0;
        for (;;) {
            const size_t comma = line.find(',', pos);
            cells.push_back(line.substr(pos, comma - pos));
            if (comma == std::string::npos) break;
            pos = comma + 1;
        }
        const char* names[] = {"id", "model", "grid", "nx", "ny", "a", "b", "N", "mu",
                               "G",  "nu",    "xi_x", "xi_y", "phi"};
        for (size_t k = 0; k < 14; ++k) row[names[k]] = cells[k];
        return solve_directly(row);
    };
    expect_row(1, "g1", "ok", "");
    expect_row(2, "b1", "ROW_UNREADABLE", "line 3, column nu: 'abc' is not a finite number");
    expect_row(3, "b2", "ROW_UNREADABLE", "line 4 has 13 fields, the header 18");
    expect_row(4, "b3", "ROW_UNREADABLE",
               "line 5, column model: 'fastsm' is not one of fastsim|exact|calibrated; did you "
               "mean fastsim?");
    expect_row(5, "g1", "ROW_UNREADABLE", "line 6, column id: 'g1' repeats the id of line 2");
    expect_row(6, "b5", "ROW_UNREADABLE", "line 7, column box_scale: only used with the uniform grid");
    expect_row(7, "b6", "ROW_UNREADABLE",
               "line 8, column L2: L1, L2 and L3 must be given together");
    expect_row(8, "b7", "ROW_UNREADABLE",
               "line 9, column G: not used when L1, L2, L3 give the flexibilities");
    // Values out of range get the checks and messages of `creepwork solve`
    // (the value as written) with the status the library gives them.
    const Expected nu = library("b8,fastsim,strips,10,10,0.006,0.005,80000,0.3,82e9,0.7,0,0,0");
    assert_int_equal(nu.status, CW_ERR_INVALID_INPUT);
    expect_row(9, "b8", "CW_ERR_INVALID_INPUT", "line 10, column nu: must lie in [0, 0.5] (got 0.7)");
    const Expected nx = library("b9,fastsim,strips,0,10,0.006,0.005,80000,0.3,82e9,0.28,0,0,0");
    assert_int_equal(nx.status, CW_ERR_GRID_OUT_OF_RANGE);
    expect_row(10, "b9", "CW_ERR_GRID_OUT_OF_RANGE", "line 11, column nx: must lie in 1..1000 (got 0)");
    // The exact model on a strip grid: the rule `creepwork solve --model
    // exact --grid strips` refuses with (the library refuses it too).
    const Expected ex = library("b10,exact,strips,10,10,0.006,0.005,80000,0.3,82e9,0.28,0,0,0");
    assert_int_not_equal(ex.status, CW_OK);
    expect_row(11, "b10", "ROW_UNREADABLE",
               "line 12, column grid: the exact model needs the uniform grid (give uniform, or no "
               "grid: it is then the default)");
    expect_row(12, "b11", "ROW_UNREADABLE", "line 13: text after the closing quote of a field");
    expect_row(13, "b12", "ROW_UNREADABLE", "line 14, column a: empty (a value is required)");
    expect_row(14, "b13", "ROW_UNREADABLE",
               "line 15, column N: '1e400' is not a finite number");
    expect_row(15, "g,2", "ok", ""); // quoted id, CRLF, after a blank line
    assert_string_equal(records[15][idx.at("Fx")].c_str(), records[1][idx.at("Fx")].c_str());
}

void bad_inputs_fail_cleanly(void** state)
{
    (void)state;
    write_input(path("good.csv"), {mixed_rows()[0]});
    write_text(path("empty.csv"), "");
    write_text(path("header.csv"), "id,model,grid,nx,ny,a,b,N,mu,G,nu,xi_x,xi_y,phi\n");
    write_text(path("typo.csv"), "id,model,grid,nx,ny,a,b,N,mu,G,nu,xi_X,xi_y,phi\nx\n");
    write_text(path("twice.csv"), "id,model,grid,nx,ny,a,b,N,mu,G,nu,xi_x,xi_y,phi,mu\nx\n");
    write_text(path("lacks.csv"), "id,model,grid,nx,ny,b,mu,xi_x,xi_y,phi\nx\n");
    write_text(path("a-file"), "not a directory\n");
    fs::create_directories(path("foreign"));
    write_text(path("foreign/keep.txt"), "someone's data\n");

    struct Case {
        std::vector<std::string> args;
        int status;
        std::string message;
        std::string must_not_exist;
    };
    const std::string in = path("good.csv"), out = path("out");
    const std::vector<Case> cases = {
        {{"--in", in}, 2, "creepwork: --out: missing", ""},
        {{"--out", out}, 2, "creepwork: --in: missing", out},
        {{"--in", path("none.csv"), "--out", out}, 2,
         "--in: " + path("none.csv") + ": cannot open the input file", out},
        {{"--in", path("empty.csv"), "--out", out}, 2, "the file is empty", out},
        {{"--in", path("header.csv"), "--out", out}, 2, "has a header but no rows", out},
        {{"--in", path("typo.csv"), "--out", out}, 2,
         "column 'xi_X' (header field 12) is unknown; did you mean xi_x?", out},
        {{"--in", path("twice.csv"), "--out", out}, 2, "column 'mu' appears twice", out},
        {{"--in", path("lacks.csv"), "--out", out}, 2, "lacks the required column(s) a,N", out},
        {{"--in", in, "--out", path("a-file")}, 2, "exists and is not a directory", ""},
        {{"--in", in, "--out", path("foreign")}, 2, "was not written by a campaign",
         path("foreign/results.csv")},
        {{"--in", in, "--out", path("a-file/sub")}, 1, "--out: cannot create", ""},
        {{"--in", in, "--out", out, "--resume", "--force"}, 2, "--resume: and --force", out},
        {{"--in", in, "--out", out, "--threads", "0"}, 2, "--threads: must lie in 1..256", out},
        {{"--in", in, "--out", out, "--chunk", "0"}, 2, "--chunk: must lie in", out},
        {{"--in", in, "--out", out, "--thread", "2"}, 2, "did you mean --threads?", out},
        {{"--in", in, "--out", out, "--aob", "1"}, 2, "--aob: only used with --table", out},
        {{"--table", "--in", in, "--out", out}, 2, "--in: not used with --table", out},
        {{"--table", "--out", out, "--aob", "2,1"}, 2, "--aob: values must be strictly increasing",
         out},
        {{"--table", "--out", out, "--aob", "0,1"}, 2, "--aob: values must lie in [1e-3, 1e3]",
         out},
        {{"--table", "--out", out, "--psi", "0,x"}, 2, "--psi: 'x' is not a finite number", out},
    };
    for (const Case& c : cases) {
        const Run r = campaign(0, c.args);
        if (r.status != c.status || !contains(r.err, c.message)) {
            std::string line;
            for (const auto& a : c.args) line += a + " ";
            print_error("campaign %s: exit %d (expected %d), stderr:\n%s\n", line.c_str(),
                        r.status, c.status, r.err.c_str());
            fail();
        }
        // One line, starting "creepwork: ".
        assert_int_equal(std::count(r.err.begin(), r.err.end(), '\n'), 1);
        assert_true(r.err.rfind("creepwork: ", 0) == 0);
        if (!c.must_not_exist.empty()) assert_false(exists(c.must_not_exist));
    }
    assert_string_equal(slurp(path("foreign/keep.txt")).c_str(), "someone's data\n");
    // --help: the usage, on stdout.
    const Run help = expect_status(campaign(0, {"--help"}), 0);
    expect_contains(help.out, "usage: creepwork campaign --in FILE.csv --out DIR");
}

void output_directory_rules(void** state)
{
    (void)state;
    const std::vector<Row> rows = mixed_rows();
    write_input(path("in.csv"), std::vector<Row>(rows.begin(), rows.begin() + 6));
    write_input(path("other.csv"), std::vector<Row>(rows.begin() + 6, rows.begin() + 12));
    const std::vector<std::string> base = {"--in", path("in.csv"), "--out", path("out")};
    expect_status(campaign(0, base), 0);
    const std::string first = slurp(path("out/results.csv"));
    Run r = expect_status(campaign(0, base), 2);
    expect_contains(r.err, "holds a finished campaign; add --force");
    std::vector<std::string> args = base;
    args.push_back("--resume");
    r = expect_status(campaign(0, args), 0);
    expect_contains(r.err, "nothing to do");
    args = {"--in", path("other.csv"), "--out", path("out"), "--resume"};
    r = expect_status(campaign(0, args), 2);
    expect_contains(r.err, "holds a finished campaign of another input");
    args = base;
    args.push_back("--force");
    expect_status(campaign(0, args), 0);
    assert_true(slurp(path("out/results.csv")) == first);
    // --resume where nothing was started begins a campaign.
    args = {"--in", path("in.csv"), "--out", path("fresh"), "--resume"};
    expect_status(campaign(0, args), 0);
    assert_true(slurp(path("fresh/results.csv")) == first);

    // While a run uses a directory, a second is refused (--resume or
    // --force alike, before anything is removed). The first run is slowed
    // to a minute per row so that it certainly outlives the attempts, then
    // killed and resumed to the same results.
    const pid_t busy = start_group(
        campaign_argv(0, {"--in", path("in.csv"), "--out", path("busy"), "--chunk", "1",
                          "--threads", "1", "--quiet"}),
        {"CREEPWORK_CAMPAIGN_TEST_CHUNK_DELAY_MS=60000"}, path("busy.out"), path("busy.err"));
    assert_true(busy > 0);
    const std::string checkpoint = path("busy/checkpoint.cwj");
    bool locked = false;
    for (int k = 0; k < 12000 && !locked; ++k) {
        locked = exists(checkpoint) && file_locked(checkpoint);
        if (!locked) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    assert_true(locked);
    for (const char* flag : {"--resume", "--force"}) {
        r = expect_status(campaign(0, {"--in", path("in.csv"), "--out", path("busy"), flag}), 2);
        expect_contains(r.err, "is in use by a running campaign");
    }
    assert_true(process_alive(busy)); // the attempts ran while it was busy
    for (pid_t p : live_descendants(busy)) kill(p, SIGKILL);
    kill(busy, SIGKILL);
    int status = 0;
    waitpid(busy, &status, 0);
    args = {"--in", path("in.csv"), "--out", path("busy"), "--resume"};
    expect_status(campaign(0, args), 0);
    assert_true(slurp(path("busy/results.csv")) == first);
}

void resume_after_kill(void** state)
{
    (void)state;
    std::vector<Row> rows = mixed_rows();
    for (Row r : mixed_rows()) {
        r["id"] += "b";
        rows.push_back(r);
    }
    write_input(path("in.csv"), rows);
    expect_status(campaign(2, {"--in", path("in.csv"), "--out", path("ref"), "--threads", "1",
                               "--quiet"}),
                  0);
    const std::string reference = slurp(path("ref/results.csv"));

    // A run slowed to 150 ms per chunk of 3 rows (32 chunks on 2 ranks:
    // seconds), killed once a few chunks are in the checkpoint.
    const std::string checkpoint = path("run/checkpoint.cwj");
    const size_t ranks = kill_midway(2, {"--in", path("in.csv"), "--out", path("run"), "--threads",
                                         "1", "--chunk", "3", "--quiet"},
                                     150, checkpoint, 3000);
    if (ranks < 2) print_error("%zu processes under mpirun, expected >= 2\n", ranks);
    assert_true(ranks >= 2);
    assert_false(exists(path("run/results.csv")));

    // A kill during an append leaves a torn record: make sure there is one.
    const auto size = fs::file_size(checkpoint);
    fs::resize_file(checkpoint, size - 5);

    // Resumed on another number of ranks.
    const Run r = expect_status(
        campaign(3, {"--in", path("in.csv"), "--out", path("run"), "--resume", "--threads", "1"}),
        0);
    expect_contains(r.err, "campaign: resuming '" + path("run") + "': ");
    expect_contains(r.err, "(a torn last chunk was dropped)");
    if (slurp(path("run/results.csv")) != reference) {
        print_error("the resumed run's results.csv differs from the uninterrupted run's\n");
        fail();
    }
    expect_resumed_part(path("run"), rows.size());
}

// A resume whose pending work is a single row: the last row of two, the
// first finished before the kill (one row per chunk, one thread, slowed so
// that the kill falls inside the second chunk).
void resume_with_one_row_pending(void** state)
{
    (void)state;
    const std::vector<Row> all = mixed_rows();
    const std::vector<Row> rows(all.begin(), all.begin() + 2);
    write_input(path("in.csv"), rows);
    expect_status(campaign(0, {"--in", path("in.csv"), "--out", path("ref"), "--quiet"}), 0);
    const std::string reference = slurp(path("ref/results.csv"));
    // The checkpoint's header is written at once; the first chunk's record
    // follows after the first delay, the second after another.
    const std::string checkpoint = path("run/checkpoint.cwj");
    kill_midway(0, {"--in", path("in.csv"), "--out", path("run"), "--chunk", "1", "--threads", "1",
                    "--quiet"},
                1500, checkpoint, 100);
    const Run r = expect_status(
        campaign(0, {"--in", path("in.csv"), "--out", path("run"), "--resume"}), 0);
    expect_contains(r.err, "resuming '" + path("run") + "': 1 of 2 rows were done");
    const Json j = parse_json(slurp(path("run/campaign.json")));
    assert_true(j.num("resumed_rows") == 1 && j.num("solved_this_run") == 1);
    if (slurp(path("run/results.csv")) != reference) {
        print_error("the resumed run's results.csv differs from the uninterrupted run's\n");
        fail();
    }
}

// Unit mistakes (mm typed as m, kN as N, MPa as Pa) are solved with a
// warning in the row's message that names the column and the likely unit,
// in the words `creepwork solve` uses for the same value; --strict rejects
// those rows. A value out of range is echoed as written.
void unit_mistakes_are_warned(void** state)
{
    (void)state;
    const std::string header = "id,model,grid,nx,ny,a,b,N,mu,G,nu,xi_x,xi_y,phi\n";
    const std::string tail = ",0.3,82e9,0.28,1e-3,0,0.5\n";
    write_text(path("in.csv"),
               header + "ok,fastsim,strips,20,20,0.0072,0.0054,100e3" + tail +
                   "mm,fastsim,strips,20,20,7.2,5.4,100e3" + tail +
                   "kN,fastsim,strips,20,20,0.0072,0.0054,100" + tail +
                   "MPa,fastsim,strips,20,20,0.0072,0.0054,100e3,0.3,82e3,0.28,1e-3,0,0.5\n"
                   "nu,fastsim,strips,20,20,0.0072,0.0054,100e3,0.3,82e9,0.6,1e-3,0,0.5\n");
    const Run r = expect_status(campaign(0, {"--in", path("in.csv"), "--out", path("out")}), 0);
    expect_contains(r.err, "5 rows: 4 solved, 1 failed");
    expect_contains(r.err, "3 rows were solved with warnings in their messages (id mm: line 3: "
                           "warning: column a = 7.2 m is implausible");
    auto records = read_csv(path("out/results.csv"));
    auto idx = header_index(records[0]);
    const auto cell = [&](size_t row, const char* column) { return records[row][idx.at(column)]; };
    assert_string_equal(cell(1, "status").c_str(), "ok");
    assert_string_equal(cell(1, "message").c_str(), "");
    for (size_t row : {2, 3, 4}) assert_string_equal(cell(row, "status").c_str(), "ok");
    const std::string mm = "= 7.2 m is implausible for a wheel-rail contact: semi-axes are 1-20 "
                           "mm (were millimetres typed as metres?";
    expect_contains(cell(2, "message"), "warning: column a " + mm);
    expect_contains(cell(2, "message"), "column b = 5.4 m is implausible");
    expect_contains(cell(3, "message"), "warning: column N = 100 N is implausible for a "
                                        "wheel-rail contact: wheel loads are 1-500 kN, not below "
                                        "1 kN (kN typed where N are read?)");
    expect_contains(cell(4, "message"), "warning: column G = 82000 Pa is implausible for a "
                                        "wheel-rail contact: steel is 8.2e10 Pa (a modulus in "
                                        "MPa or N/mm^2 typed as Pa?)");
    assert_string_equal(cell(5, "status").c_str(), "CW_ERR_INVALID_INPUT");
    assert_string_equal(cell(5, "message").c_str(),
                        "line 6, column nu: must lie in [0, 0.5] (got 0.6)");
    // The same words as creepwork solve's warning for the same value.
    const Run solve = expect_status(
        run({g_tools.creepwork, "solve", "--a", "7.2", "--b", "5.4", "--N", "100e3"}), 0);
    expect_contains(solve.err, "warning: --a " + mm);

    // --strict: the three rows are rejected with their warnings.
    const Run strict = expect_status(
        campaign(0, {"--in", path("in.csv"), "--out", path("strict"), "--strict"}), 0);
    expect_contains(strict.err, "5 rows: 1 solved, 4 failed");
    records = read_csv(path("strict/results.csv"));
    idx = header_index(records[0]);
    assert_string_equal(cell(1, "status").c_str(), "ok");
    for (size_t row : {2, 3, 4}) {
        assert_string_equal(cell(row, "status").c_str(), "ROW_IMPLAUSIBLE");
        assert_string_equal(cell(row, "Fx").c_str(), "");
    }
    expect_contains(cell(2, "message"), "line 3: column a " + mm);
    // --strict is part of the campaign: resuming without it is refused.
    const Run mixed = expect_status(
        campaign(0, {"--in", path("in.csv"), "--out", path("strict"), "--resume"}), 2);
    expect_contains(mixed.err, "another input");
}

// The columns of `creepwork solve`'s options, with its defaults: a file of
// id, a, b, N and the creepages runs (the material, model and grid of solve);
// spin is another name for phi; the exact model gets solve's uniform grid;
// a wear states file runs as a plain campaign, its wear columns noted.
void schema_defaults_and_aliases(void** state)
{
    (void)state;
    write_text(path("min.csv"), "id,a,b,N,xi_x,xi_y,phi\n"
                                "r1,0.0072,0.0054,100e3,1e-3,0,0.5\n"
                                "r2,0.006,0.006,80e3,-2e-4,1e-3,1.5\n");
    const Run r = expect_status(campaign(0, {"--in", path("min.csv"), "--out", path("min")}), 0);
    expect_contains(r.err, "min.csv: no column mu, G, nu: every row takes the library's defaults "
                           "(steel on steel), as creepwork solve: mu = 0.3, G = 8.2e+10 Pa, nu = "
                           "0.28");
    const auto records = read_csv(path("min/results.csv"));
    const auto idx = header_index(records[0]);
    const std::vector<std::vector<std::string>> solve_args = {
        {"--a", "0.0072", "--b", "0.0054", "--N", "100e3", "--xi-x", "1e-3", "--spin", "0.5"},
        {"--a", "0.006", "--b", "0.006", "--N", "80e3", "--xi-x", "-2e-4", "--xi-y", "1e-3",
         "--spin", "1.5"}};
    for (size_t k = 0; k < 2; ++k) {
        const Run s = expect_status(
            run(with(with({g_tools.creepwork, "solve"}, solve_args[k]), {"--format", "json"})), 0);
        for (const char* key : {"Fx", "Fy", "Mz", "W_macro", "adhesion_fraction"})
            expect_contains(s.out, "\"" + std::string(key) + "\": " + records[k + 1][idx.at(key)] + ",");
    }
    // spin for phi: the same results.
    write_text(path("spin.csv"), "id,a,b,N,xi_x,xi_y,spin\n"
                                 "r1,0.0072,0.0054,100e3,1e-3,0,0.5\n"
                                 "r2,0.006,0.006,80e3,-2e-4,1e-3,1.5\n");
    expect_status(campaign(0, {"--in", path("spin.csv"), "--out", path("spin"), "--quiet"}), 0);
    assert_true(slurp(path("spin/results.csv")) == slurp(path("min/results.csv")));
    // The exact model without a grid: solve's uniform 24 x 24 over 1.2 a, 1.2 b.
    write_text(path("exact.csv"), "id,model,a,b,N,xi_x,spin\nx1,exact,0.006,0.005,80e3,1e-3,0.4\n");
    expect_status(campaign(0, {"--in", path("exact.csv"), "--out", path("exact"), "--quiet"}), 0);
    const auto ex = read_csv(path("exact/results.csv"));
    const Run se = expect_status(run({g_tools.creepwork, "solve", "--model", "exact", "--a", "0.006",
                                      "--b", "0.005", "--N", "80e3", "--xi-x", "1e-3", "--spin",
                                      "0.4", "--format", "json"}),
                                 0);
    for (const char* key : {"Fx", "Fy", "Mz", "n_contact"})
        expect_contains(se.out, "\"" + std::string(key) + "\": " + ex[1][header_index(ex[0]).at(key)] + ",");
    // exact_load: the load scale of `creepwork solve --exact-load`.
    write_text(path("load.csv"), "id,a,b,N,mu,xi_x,exact_load\nr,7.17e-3,5.42e-3,100e3,0.3,0.3,1\n");
    expect_status(campaign(0, {"--in", path("load.csv"), "--out", path("load"), "--quiet"}), 0);
    const auto load = read_csv(path("load/results.csv"));
    const Run sl = expect_status(run({g_tools.creepwork, "solve", "--a", "7.17e-3", "--b",
                                      "5.42e-3", "--N", "100e3", "--mu", "0.3", "--xi-x", "0.3",
                                      "--exact-load", "--format", "json"}),
                                 0);
    for (const char* key : {"Fx", "Fy", "W_macro"})
        expect_contains(sl.out, "\"" + std::string(key) + "\": " + load[1][header_index(load[0]).at(key)] + ",");
    // Columns: both spellings, a misspelling, a wear file without --wear.
    write_text(path("both.csv"), "id,a,b,N,phi,spin\nr,0.006,0.006,8e4,1,1\n");
    Run bad = campaign(0, {"--in", path("both.csv"), "--out", path("never")});
    expect_refusal(bad, 2, "column 'spin' appears twice in the header (as 'phi': spin is another "
                           "name for phi)", "campaign both.csv");
    write_text(path("spn.csv"), "id,a,b,N,spn\nr,0.006,0.006,8e4,1\n");
    bad = campaign(0, {"--in", path("spn.csv"), "--out", path("never")});
    expect_refusal(bad, 2, "column 'spn' (header field 5) is unknown; did you mean spin?",
                   "campaign spn.csv");
    assert_false(exists(path("never")));
    write_text(path("states.csv"), "id,s0,a,b,N,xi_x,xi_y,spin,contact_angle,passes\n"
                                   "r1,0.001,0.0072,0.0054,100e3,1e-3,0,0.5,0.02,200\n"
                                   "r2,0,0.006,0.006,80e3,-2e-4,1e-3,1.5,0,300\n");
    const Run states = expect_status(
        campaign(0, {"--in", path("states.csv"), "--out", path("states"), "--quiet"}), 0);
    expect_contains(states.err, "columns contact_angle, passes (read with --wear only) not read by "
                                "creepwork campaign: ignored");
    const auto st = read_csv(path("states/results.csv"));
    const auto si = header_index(st[0]);
    for (size_t k = 1; k <= 2; ++k)
        assert_string_equal(st[k][si.at("Fx")].c_str(), records[k][idx.at("Fx")].c_str());
}

// Progress on stderr: by default a first line within 5 s, then every 30 s;
// --progress S every S seconds. Rows slowed to a known time per chunk.
void progress_lines(void** state)
{
    (void)state;
    const std::vector<Row> all = mixed_rows();
    write_input(path("three.csv"), std::vector<Row>(all.begin(), all.begin() + 3));
    const std::vector<std::string> slow = {"--chunk", "1", "--threads", "1"};
    // 3 rows of 2 s: about 6 s, one line at 5 s.
    Run r = expect_status(
        campaign(0, with({"--in", path("three.csv"), "--out", path("default")}, slow),
                 {"CREEPWORK_CAMPAIGN_TEST_CHUNK_DELAY_MS=2000"}),
        0);
    expect_contains(r.err, "creepwork: campaign: ");
    expect_contains(r.err, " of 3 rows done (");
    // 2 rows of 1 s with a line every 0.5 s: at least three lines.
    write_input(path("two.csv"), std::vector<Row>(all.begin(), all.begin() + 2));
    r = expect_status(campaign(0, with({"--in", path("two.csv"), "--out", path("often"),
                                        "--progress", "0.5"},
                                       slow),
                               {"CREEPWORK_CAMPAIGN_TEST_CHUNK_DELAY_MS=1000"}),
                      0);
    size_t lines = 0;
    for (size_t at = 0; (at = r.err.find(" rows done (", at)) != std::string::npos; ++at) ++lines;
    if (lines < 3) print_error("%zu progress lines:\n%s\n", lines, r.err.c_str());
    assert_true(lines >= 3);
    // Bad values, and --quiet with --progress.
    for (const auto& [args, message] : std::vector<std::pair<std::vector<std::string>, std::string>>{
             {{"--progress", "0"}, "--progress: must lie in (0, 86400] seconds (got 0)"},
             {{"--progress", "x"}, "--progress"},
             {{"--progress", "5", "--quiet"}, "--progress: and --quiet contradict each other"}})
        expect_refusal(campaign(0, with({"--in", path("two.csv"), "--out", path("never")}, args)),
                       2, message, "campaign --progress");
}

// Direct solve of a table point on a physical contact: Kalker's
// normalisation undone with c = 6 mm, N = 80 kN, mu = 0.3, G = 82 GPa.
struct Direct {
    double fx, fy, mz;
};

Direct solve_point(double aob, double nu, double xi, double eta, double psi, int n)
{
    const double c = 0.006, N = 80e3, mu = 0.3, G = 82e9;
    double C[4];
    assert_int_equal(cw_kalker_coefficients(aob, nu, C, nullptr, 0), CW_OK);
    cw_grid g;
    cw_grid_init(&g);
    g.nx = n, g.ny = n;
    cw_params p;
    cw_params_init(&p);
    p.a = c * std::sqrt(aob), p.b = c / std::sqrt(aob);
    p.normal_force = N, p.mu = mu, p.G = G, p.nu = nu;
    p.xi_x = 3 * mu * N * xi / (G * c * c * C[0]);
    p.xi_y = 3 * mu * N * eta / (G * c * c * C[1]);
    p.phi = mu * N * psi / (G * c * c * c * C[2]);
    cw_solver* s = nullptr;
    assert_int_equal(cw_solver_create(&g, &s, nullptr, 0), CW_OK);
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &r), CW_OK);
    cw_solver_destroy(s);
    return {r.Fx / (mu * N), r.Fy / (mu * N), r.Mz / (mu * N * c)};
}

void table_entries_match_direct_solves(void** state)
{
    (void)state;
    const Run run_ = expect_status(
        campaign(2, {"--table", "--out", path("table"), "--aob", "0.5,1,2", "--nu", "0.25,0.3",
                     "--xi", "0,0.01,0.3,700000", "--eta", "0,0.4", "--psi", "-0.6,0,0.9",
                     "--nx", "12", "--ny", "12", "--threads", "1", "--quiet"}),
        0);
    expect_contains(run_.err, "144 rows: 144 solved, 0 failed");
    const auto records = read_csv(path("table/table.csv"));
    assert_int_equal(records.size(), 145);
    const std::vector<std::string> header = {"aob", "nu", "xi", "eta", "psi", "status",
                                             "fx",  "fy", "mz", "message"};
    assert_true(records[0] == header);
    const Json meta = parse_json(slurp(path("table/table.json")));
    assert_int_equal(static_cast<int>(meta.num("points")), 144);
    assert_int_equal(meta.at("axes").at("psi").array.size(), 3);
    assert_int_equal(meta.at("axes").at("xi").array.size(), 4);
    assert_true(meta.at("axes").at("xi").array[3].number == 700000);

    const std::vector<double> aob = {0.5, 1, 2}, nu = {0.25, 0.3}, xi = {0, 0.01, 0.3, 700000},
                              eta = {0, 0.4}, psi = {-0.6, 0, 0.9};
    size_t k = 1;
    for (double a : aob)
        for (double n : nu)
            for (double x : xi)
                for (double e : eta)
                    for (double s : psi) {
                        const auto& rec = records[k++];
                        // The documented order: psi fastest, then eta, xi, nu, a/b.
                        assert_true(std::strtod(rec[0].c_str(), nullptr) == a);
                        assert_true(std::strtod(rec[1].c_str(), nullptr) == n);
                        assert_true(std::strtod(rec[2].c_str(), nullptr) == x);
                        assert_true(std::strtod(rec[3].c_str(), nullptr) == e);
                        assert_true(std::strtod(rec[4].c_str(), nullptr) == s);
                        assert_string_equal(rec[5].c_str(), "ok");
                        const double fx = std::strtod(rec[6].c_str(), nullptr),
                                     fy = std::strtod(rec[7].c_str(), nullptr),
                                     mz = std::strtod(rec[8].c_str(), nullptr);
                        // Kalker's theory is self-similar in these variables:
                        // a 6 mm, 80 kN steel contact gives the table's
                        // numbers up to rounding.
                        const Direct d = solve_point(a, n, x, e, s, 12);
                        assert_close(fx, d.fx, 1e-9, 1e-13);
                        assert_close(fy, d.fy, 1e-9, 1e-13);
                        assert_close(mz, d.mz, 1e-9, 1e-13);
                        if (x == 0 && e == 0 && s == 0)
                            assert_true(fx == 0 && fy == 0 && mz == 0);
                        // Linear theory (Kalker 1990, Table E.3; FASTSIM's
                        // flexibility L1 = 8a/(3 C11 G) is chosen to give it):
                        // fx = -3 xi for small xi; 0.35 % off on 12 x 12.
                        if (x == 0.01 && e == 0 && s == 0) assert_close(fx, -3 * x, 0.01, 0);
                        // Full sliding: |F| = mu N, the pressure integrated on
                        // the 12 x 12 strip grid (0.44 % above N here).
                        if (x == 700000 && e == 0 && s == 0) assert_close(fx, -1.0, 0.01, 0);
                    }

    // And through the creepwork program itself, for one point.
    const double a = 2, n = 0.3, x = 0.3, e = 0.4, s = 0.9;
    double C[4];
    cw_kalker_coefficients(a, n, C, nullptr, 0);
    const double c = 0.006, N = 80e3, mu = 0.3, G = 82e9;
    char buf[7][32];
    std::snprintf(buf[0], 32, "%.17g", c * std::sqrt(a));
    std::snprintf(buf[1], 32, "%.17g", c / std::sqrt(a));
    std::snprintf(buf[2], 32, "%.17g", 3 * mu * N * x / (G * c * c * C[0]));
    std::snprintf(buf[3], 32, "%.17g", 3 * mu * N * e / (G * c * c * C[1]));
    std::snprintf(buf[4], 32, "%.17g", mu * N * s / (G * c * c * c * C[2]));
    const Run r = expect_status(
        run({g_tools.creepwork, "solve", "--a", buf[0], "--b", buf[1], "--N", "80000", "--mu",
             "0.3", "--G", "82e9", "--nu", "0.3", "--xi-x", buf[2], "--xi-y", buf[3], "--spin",
             buf[4], "--nx", "12", "--ny", "12", "--format", "json"}),
        0);
    const Json j = parse_json(r.out);
    // Point (a/b 2, nu 0.3, xi 0.3, eta 0.4, psi 0.9): k = 2*48 + 1*24 + 2*6 + 1*3 + 2.
    const auto& rec = records[1 + 2 * 48 + 1 * 24 + 2 * 6 + 1 * 3 + 2];
    assert_true(std::strtod(rec[2].c_str(), nullptr) == 0.3 &&
                std::strtod(rec[4].c_str(), nullptr) == 0.9);
    assert_close(std::strtod(rec[6].c_str(), nullptr), j.num("Fx") / (mu * N), 1e-9, 1e-13);
    assert_close(std::strtod(rec[7].c_str(), nullptr), j.num("Fy") / (mu * N), 1e-9, 1e-13);
    assert_close(std::strtod(rec[8].c_str(), nullptr), j.num("Mz") / (mu * N * c), 1e-9, 1e-13);
}

} // namespace

int main(int argc, char** argv)
{
    if (!set_up(argc, argv, "test_campaign", {"creepwork", "mpirun", "scratch"})) return 2;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(ranks_and_threads_bitwise),
        cmocka_unit_test(matches_creepwork_solve),
        cmocka_unit_test(bad_rows_get_error_lines),
        cmocka_unit_test(bad_inputs_fail_cleanly),
        cmocka_unit_test(output_directory_rules),
        cmocka_unit_test(resume_after_kill),
        cmocka_unit_test(table_entries_match_direct_solves),
        cmocka_unit_test(resume_with_one_row_pending),
        cmocka_unit_test(unit_mistakes_are_warned),
        cmocka_unit_test(schema_defaults_and_aliases),
        cmocka_unit_test(progress_lines),
    };
    return cw_run_tests(tests, g_tools.test);
}
