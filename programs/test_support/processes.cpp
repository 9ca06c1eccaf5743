#include "processes.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <fcntl.h>
#include <spawn.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include "test_files.hpp"

extern char** environ;

namespace cwtest {

namespace {

std::vector<char*> c_argv(const std::vector<std::string>& v)
{
    std::vector<char*> out;
    for (const std::string& s : v) out.push_back(const_cast<char*>(s.c_str()));
    out.push_back(nullptr);
    return out;
}

std::vector<std::string> environment(const std::vector<std::string>& extra)
{
    std::vector<std::string> env;
    for (char** e = environ; *e; ++e) env.emplace_back(*e);
    env.insert(env.end(), extra.begin(), extra.end());
    return env;
}

pid_t spawn(const std::vector<std::string>& argv, const std::vector<std::string>& env,
            const std::string& out_file, const std::string& err_file, bool own_group)
{
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    posix_spawn_file_actions_addopen(&fa, 2, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    if (own_group) {
        posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
        posix_spawnattr_setpgroup(&attr, 0);
    }
    const std::vector<std::string> full_env = environment(env);
    std::vector<char*> a = c_argv(argv), e = c_argv(full_env);
    pid_t pid = -1;
    if (posix_spawnp(&pid, argv[0].c_str(), &fa, &attr, a.data(), e.data()) != 0) pid = -1;
    posix_spawn_file_actions_destroy(&fa);
    posix_spawnattr_destroy(&attr);
    return pid;
}

// State and parent of a process from /proc/PID/stat ("pid (comm) state ppid
// ..."; comm may hold spaces and parentheses, so parse after the last ')').
bool read_stat(pid_t pid, char& state, long& ppid)
{
    const std::string stat = slurp("/proc/" + std::to_string(pid) + "/stat");
    const size_t close = stat.rfind(')');
    return close != std::string::npos &&
           std::sscanf(stat.c_str() + close + 1, " %c %ld", &state, &ppid) == 2;
}

} // namespace

Run run_captured(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                 const std::string& out_file, const std::string& err_file)
{
    Run r;
    const pid_t pid = spawn(argv, env, out_file, err_file, false);
    if (pid > 0) {
        int status = 0;
        waitpid(pid, &status, 0);
        r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    r.out = slurp(out_file);
    r.err = slurp(err_file);
    return r;
}

pid_t start_group(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                  const std::string& out_file, const std::string& err_file)
{
    return spawn(argv, env, out_file, err_file, true);
}

bool process_alive(pid_t pid)
{
    char state = 0;
    long ppid = 0;
    return read_stat(pid, state, ppid) && state != 'Z' && state != 'X';
}

bool file_locked(const std::string& path)
{
    const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool locked = flock(fd, LOCK_EX | LOCK_NB) != 0;
    close(fd); // releases the lock if this call took it
    return locked;
}

std::vector<pid_t> live_descendants(pid_t root)
{
    std::vector<std::pair<pid_t, long>> all; // pid, parent
    for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
        const std::string name = entry.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        const pid_t pid = static_cast<pid_t>(std::atol(name.c_str()));
        char state = 0;
        long ppid = 0;
        if (read_stat(pid, state, ppid) && state != 'Z' && state != 'X') all.emplace_back(pid, ppid);
    }
    std::vector<pid_t> out, frontier = {root};
    while (!frontier.empty()) {
        const pid_t parent = frontier.back();
        frontier.pop_back();
        for (const auto& [pid, ppid] : all)
            if (ppid == parent) {
                out.push_back(pid);
                frontier.push_back(pid);
            }
    }
    return out;
}

} // namespace cwtest
