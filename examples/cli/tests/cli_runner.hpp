// Runs the creepwork program as a test sees it: its exit status, stdout and
// stderr. Shared by the CLI test executables (test_cli*, one per area).
#pragma once

#include <string>
#include <vector>

namespace cli_test {

struct Run {
    int status = -1; // exit status; -1 if it could not start or did not exit
    std::string out, err;
};

// The whole file, or "" if it cannot be read.
std::string slurp(const std::string& path);

// program args..., stdout and stderr captured through files in scratch.
Run run_program(const std::string& program, const std::string& scratch,
                const std::vector<std::string>& args);

// The same, failing the current cmocka test (with stderr shown) unless it exits 0.
Run run_program_ok(const std::string& program, const std::string& scratch,
                   const std::vector<std::string>& args);

} // namespace cli_test
