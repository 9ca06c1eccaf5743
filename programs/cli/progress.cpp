#include "progress.hpp"

#include <cstdio>

#include <unistd.h>

#include "cli_error.hpp"

namespace cwcli {

std::vector<OptionSpec> progress_option_specs()
{
    return {{"progress", OptionKind::number, {}}, {"quiet", OptionKind::flag, {}}};
}

ProgressOptions read_progress_options(const ParsedOptions& o)
{
    ProgressOptions p;
    p.quiet = o.has("quiet");
    if (o.has("progress")) {
        if (p.quiet) throw usage_error("--progress", "and --quiet contradict each other");
        p.every = o.number("progress", 0);
        if (!(p.every > 0 && p.every <= 86400))
            throw usage_error("--progress", "must lie in (0, 86400] seconds (got " +
                                                round_trip_text(p.every) + ")");
    }
    return p;
}

ProgressSchedule interactive_schedule(const ProgressOptions& p)
{
    ProgressSchedule s;
    if (p.every > 0) {
        s.on = true;
        s.first = s.every = p.every;
        return s;
    }
    s.on = !p.quiet && isatty(STDERR_FILENO);
    s.first = 2.0;
    s.every = 10.0;
    return s;
}

std::string progress_text(const std::string& what, const std::string& unit, uint64_t done,
                          uint64_t total, uint64_t already, double seconds)
{
    const double here = static_cast<double>(done - already);
    const double rate = seconds > 0.0 ? here / seconds : 0.0;
    const double left = rate > 0.0 ? static_cast<double>(total - done) / rate : 0.0;
    char line[256];
    std::snprintf(line, sizeof line,
                  "%s: %llu of %llu %s done (%.0f %%), %.0f %s/s, about %.0f s to go",
                  what.c_str(), static_cast<unsigned long long>(done),
                  static_cast<unsigned long long>(total), unit.c_str(),
                  total ? 100.0 * static_cast<double>(done) / static_cast<double>(total) : 100.0,
                  rate, unit.c_str(), left);
    return line;
}

Progress::Progress(std::string what, std::string unit, uint64_t total, ProgressSchedule schedule,
                   uint64_t already)
    : what_(std::move(what)), unit_(std::move(unit)), total_(total), already_(already),
      schedule_(schedule), start_(Clock::now()), next_(schedule.first)
{
}

void Progress::update(uint64_t done)
{
    if (!schedule_.on) return;
    const double seconds = std::chrono::duration<double>(Clock::now() - start_).count();
    if (seconds < next_) return;
    std::fprintf(stderr, "creepwork: %s\n",
                 progress_text(what_, unit_, done, total_, already_, seconds).c_str());
    std::fflush(stderr);
    next_ = seconds + schedule_.every;
}

} // namespace cwcli
