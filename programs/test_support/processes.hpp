// Running programs as a test sees them -- exit status, stdout, stderr -- and
// watching the processes a run leaves (a campaign's ranks). Shared by the
// CLI tests (programs/cli/tests) and the campaign tests
// (programs/campaign/tests).
#pragma once

#include <string>
#include <vector>

#include <sys/types.h>

namespace cwtest {

struct Run {
    int status = -1; // exit status; -1 when killed or not started
    std::string out, err;
};

// Runs argv[0] (searched on PATH when it has no '/') with argv, extra
// environment entries ("NAME=value") added, stdout and stderr captured
// through the files out_file and err_file; waits for it.
Run run_captured(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                 const std::string& out_file, const std::string& err_file);

// Starts argv in a process group of its own, output to files; returns the
// pid (= the group id), or -1 when it cannot start.
pid_t start_group(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                  const std::string& out_file, const std::string& err_file);

// The live (not zombie) descendants of pid, from /proc.
std::vector<pid_t> live_descendants(pid_t pid);
// Whether pid exists and is not a zombie.
bool process_alive(pid_t pid);
// Whether another process holds an exclusive flock on path.
bool file_locked(const std::string& path);

} // namespace cwtest
