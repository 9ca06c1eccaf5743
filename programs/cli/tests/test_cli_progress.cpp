/* Progress of long work on stderr (programs/cli/progress.hpp), run as a
 * user runs it: `creepwork wear` and `creepwork sweep` with --progress S
 * print the campaign's line, its counts rising to the total, and the same
 * results as without; with stderr not a terminal they print none, --quiet
 * none, and bad values of --progress are refused naming it. Whether a
 * command reports by default is decided by stderr being a terminal: checked
 * on the helper itself with stderr on a pseudo-terminal and on a pipe.
 *
 * usage: test_cli_progress <creepwork binary> <scratch dir> [cmocka filter] */
#include <cmath>
#include <cstdio>
#include <regex>
#include <string>
#include <vector>

#include <fcntl.h>
#include <pty.h>
#include <unistd.h>

#include "cli_checks.hpp"
#include "progress.hpp"
// Last: cmocka defines macros (fail, skip) that clash with the C++ library.
#include "test_support.h"

using namespace cwtest;

namespace {

// The progress lines of a run's stderr as (done, total); every other line
// left alone. A line that starts like one but differs fails the test.
std::vector<std::pair<long, long>> progress_lines(const std::string& err, const std::string& what,
                                                  const std::string& unit)
{
    const std::regex line("creepwork: " + what + ": ([0-9]+) of ([0-9]+) " + unit +
                          " done \\(([0-9]+) %\\), [0-9]+ " + unit + "/s, about [0-9]+ s to go");
    std::vector<std::pair<long, long>> out;
    size_t start = 0;
    while (start < err.size()) {
        size_t end = err.find('\n', start);
        if (end == std::string::npos) end = err.size();
        const std::string text = err.substr(start, end - start);
        start = end + 1;
        if (text.rfind("creepwork: " + what + ": ", 0) != 0) continue;
        std::smatch m;
        if (!std::regex_match(text, m, line)) {
            print_error("not a progress line: %s\n", text.c_str());
            fail();
        }
        const long done = std::stol(m[1]), total = std::stol(m[2]);
        assert_true(std::fabs(std::stod(m[3]) - 100.0 * done / total) <= 0.5); // rounded
        out.emplace_back(done, total);
    }
    return out;
}

// 120 states solved by the exact model (about a second): enough for lines
// every 0.02 s on any machine.
std::string exact_states()
{
    std::string text = "s0,a,b,N,xi_x,xi_y,spin,passes,model\n";
    for (int k = 0; k < 120; ++k)
        text += std::to_string(-0.01 + 1e-4 * k) + ",7e-3,5e-3,1e5," +
                std::to_string(1e-5 * (k % 40)) + ",2e-4,0.3,100,exact\n";
    return scratch_file("states.csv", text);
}

void wear_reports_progress(void**)
{
    const std::string in = exact_states();
    const std::vector<std::string> common = {"wear", "--in", in, "--no-plots", "--format", "json",
                                             "--mu", "0.3", "--G", "82e9", "--nu", "0.28"};
    const Run quiet = cli_ok(with(common, {"--out", path("plain")}));
    assert_true(progress_lines(quiet.err, "wear", "states").empty()); // stderr is a file here
    const Run loud = cli_ok(with(common, {"--out", path("loud"), "--progress", "0.02"}));
    const auto lines = progress_lines(loud.err, "wear", "states");
    assert_true(lines.size() >= 2);
    for (size_t k = 0; k < lines.size(); ++k) {
        assert_int_equal(lines[k].second, 120);
        assert_true(lines[k].first >= 1 && lines[k].first <= 120);
        if (k) assert_true(lines[k].first >= lines[k - 1].first);
    }
    assert_string_equal(loud.out.c_str(), quiet.out.c_str()); // the same summary
    assert_string_equal(slurp(path("loud") + "/wear_profile.csv").c_str(),
                        slurp(path("plain") + "/wear_profile.csv").c_str());
    const Run none = cli_ok(with(common, {"--out", path("none"), "--quiet"}));
    assert_true(progress_lines(none.err, "wear", "states").empty());
}

void sweep_reports_progress(void**)
{
    const std::vector<std::string> common = {"sweep", "--model", "exact", "--nx", "24", "--ny",
                                             "24", "--no-plots", "--format", "json"};
    const Run plain = cli_ok(with(common, {"--out", path("plain")}));
    const Run loud = cli_ok(with(common, {"--out", path("loud"), "--progress", "0.005"}));
    const auto lines = progress_lines(loud.err, "sweep", "maps");
    assert_true(!lines.empty());
    for (const auto& [done, total] : lines) {
        assert_int_equal(total, 32); // Figs. 2-5: 8 + 8 + 8 + 8 panels
        assert_true(done >= 1 && done <= total);
    }
    assert_true(progress_lines(plain.err, "sweep", "maps").empty());
    assert_string_equal(loud.out.c_str(), plain.out.c_str());
    assert_string_equal(slurp(path("loud") + "/cases.csv").c_str(),
                        slurp(path("plain") + "/cases.csv").c_str());
}

void progress_options_are_checked(void**)
{
    const std::string in = exact_states();
    for (const std::string command : {"wear", "sweep"}) {
        std::vector<std::string> base = {command, "--out", path("bad")};
        if (command == "wear") base = with(base, {"--in", in});
        expect_refusal(cli(with(base, {"--progress", "0"})), 2,
                       "--progress: must lie in (0, 86400] seconds (got 0)", command);
        expect_refusal(cli(with(base, {"--progress", "soon"})), 2, "--progress", command);
        expect_refusal(cli(with(base, {"--progress", "1", "--quiet"})), 2,
                       "--progress: and --quiet contradict each other", command);
    }
}

// The default: a command reports when stderr is a terminal, not on a pipe
// or with --quiet; --progress S reports anywhere. The first line comes
// after 2 s, then one every 10 s (the usage texts say so).
void a_terminal_decides(void**)
{
    const int saved = dup(STDERR_FILENO);
    int master = -1, slave = -1;
    if (openpty(&master, &slave, nullptr, nullptr, nullptr) != 0) {
        print_message("no pseudo-terminal here: skipped\n");
        close(saved);
        cw_skip();
        return;
    }
    int pipe_ends[2];
    assert_int_equal(pipe(pipe_ends), 0);
    const auto schedule_on = [&](int fd, cwcli::ProgressOptions o) {
        dup2(fd, STDERR_FILENO);
        const cwcli::ProgressSchedule s = cwcli::interactive_schedule(o);
        dup2(saved, STDERR_FILENO);
        return s;
    };
    const cwcli::ProgressOptions plain{}, quiet{true, 0.0}, every{false, 3.0};
    const cwcli::ProgressSchedule terminal = schedule_on(slave, plain);
    assert_true(terminal.on);
    assert_true(terminal.first == 2.0 && terminal.every == 10.0);
    assert_false(schedule_on(slave, quiet).on);
    assert_false(schedule_on(pipe_ends[1], plain).on);
    const cwcli::ProgressSchedule given = schedule_on(pipe_ends[1], every);
    assert_true(given.on && given.first == 3.0 && given.every == 3.0);
    for (int fd : {master, slave, pipe_ends[0], pipe_ends[1], saved}) close(fd);
}

// The line itself, as the campaign has always printed it.
void the_line(void**)
{
    assert_string_equal(cwcli::progress_text("campaign", "rows", 3656, 5000, 0, 30.0).c_str(),
                        "campaign: 3656 of 5000 rows done (73 %), 122 rows/s, about 11 s to go");
    // A resumed run: the rate counts this run's rows only.
    assert_string_equal(cwcli::progress_text("campaign", "rows", 3000, 5000, 2000, 10.0).c_str(),
                        "campaign: 3000 of 5000 rows done (60 %), 100 rows/s, about 20 s to go");
}

} // namespace

int main(int argc, char** argv)
{
    if (!set_up(argc, argv, "test_cli_progress", {"creepwork", "scratch"})) return 2;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(wear_reports_progress),
        cmocka_unit_test(sweep_reports_progress),
        cmocka_unit_test(progress_options_are_checked),
        cmocka_unit_test(a_terminal_decides),
        cmocka_unit_test(the_line),
    };
    return cw_run_tests(tests, g_tools.test);
}
