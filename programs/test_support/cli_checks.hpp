// The frame every CLI and campaign test program shares: its arguments (the
// creepwork program, mpirun, a scratch directory, the test's name), running
// creepwork there, and the checks a failed expectation reports with what it
// saw before failing the current cmocka test.
#pragma once

#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "json_reader.hpp"
#include "processes.hpp"
#include "test_files.hpp"

namespace cwtest {

struct Tools {
    std::string creepwork; // the creepwork program
    std::string mpirun;    // mpirun (Open MPI); campaign tests only
    std::string scratch;   // this test's directory, emptied at start
    const char* test = nullptr; // the test to run (cmocka name), nullptr: all
};
extern Tools g_tools;

// Reads main's arguments in the order `names` gives them ("creepwork",
// "mpirun", "scratch"), the next one (if any) into g_tools.test, and empties
// the scratch directory. False (usage printed) when one is missing.
bool set_up(int argc, char** argv, const char* program, const std::vector<std::string>& names);

// A file in this test's scratch directory; scratch_file also writes it
// (text) and returns its path.
std::string path(const std::string& name);
std::string scratch_file(const std::string& name, const std::string& text);

// `creepwork args...`, stdout and stderr captured (run.out, run.err in the
// scratch directory); cli_ok also checks that it exits 0 (stderr printed
// when not).
Run cli(const std::vector<std::string>& args, const std::vector<std::string>& env = {});
Run cli_ok(const std::vector<std::string>& args);
// argv, captured the same way (mpirun ... creepwork ...).
Run run(const std::vector<std::string>& argv, const std::vector<std::string>& env = {});

// Appends b to a.
std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b);

bool contains(const std::string& text, const std::string& part);
void expect_contains(const std::string& text, const std::string& part);
void expect_lacks(const std::string& text, const std::string& part);

// r, after checking its exit status (stderr printed when it differs).
Run expect_status(const Run& r, int status);

// A clean refusal: exit status, one stderr line starting "creepwork: " that
// holds `part`, nothing on stdout. `what` names the run in the report.
void expect_refusal(const Run& r, int status, const std::string& part, const std::string& what);

// The JSON document, or the test fails showing the text.
Json parse_or_fail(const std::string& text);

// "%.17g": a double as text that reads back exactly; round_trip: the
// shortest such text (std::to_chars), as creepwork echoes numbers.
std::string exact(double v);
std::string round_trip(double v);

// The library's own result for the contact (cw_solver_solve on a new solver);
// the test fails unless it solves.
cw_result library_solve(const cw_grid& g, const cw_params& p, int mode = CW_SOLVE_FULL);

} // namespace cwtest
