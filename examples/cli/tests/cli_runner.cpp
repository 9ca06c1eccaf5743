#include "cli_runner.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <fstream>
#include <sstream>

// Last: cmocka defines macros (fail, skip) that clash with the C++ library.
#include "test_support.h"

extern char** environ;

namespace cli_test {

std::string slurp(const std::string& path)
{
    std::ifstream f(path);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

Run run_program(const std::string& program, const std::string& scratch,
                const std::vector<std::string>& args)
{
    const std::string out = scratch + "/stdout.txt", err = scratch + "/stderr.txt";
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&fa, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(program.c_str()));
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = 0;
    Run r;
    if (posix_spawn(&pid, program.c_str(), &fa, nullptr, argv.data(), environ) == 0) {
        int status = 0;
        waitpid(pid, &status, 0);
        r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    posix_spawn_file_actions_destroy(&fa);
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

Run run_program_ok(const std::string& program, const std::string& scratch,
                   const std::vector<std::string>& args)
{
    Run r = run_program(program, scratch, args);
    if (r.status != 0) print_error("exit %d, stderr: %s\n", r.status, r.err.c_str());
    assert_int_equal(r.status, 0);
    return r;
}

} // namespace cli_test
