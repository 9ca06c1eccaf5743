// Progress of long work on stderr, one line at a time:
//   creepwork: wear: 1200 of 10000 states done (12 %), 610 states/s, about 14 s to go
// a first line after `first` seconds, then one every `every` seconds, so
// work shorter than `first` prints nothing. `creepwork campaign` reports
// whenever it is not --quiet (a first line within 5 s, then every 30 s:
// campaigns run long and are often logged); the other commands that may
// run for more than a few seconds (wear, sweep) when stderr is a terminal
// (a first line after 2 s, then every 10 s). --progress S gives a line
// every S seconds, terminal or not; --quiet none.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "options.hpp"

namespace cwcli {

struct ProgressSchedule {
    bool on = false;
    double first = 5.0; // seconds to the first line
    double every = 30.0; // seconds between lines
};

// --progress S and --quiet as a command reads them (campaign too).
struct ProgressOptions {
    bool quiet = false;  // --quiet
    double every = 0.0;  // --progress S; 0: not given
};
std::vector<OptionSpec> progress_option_specs();
// Throws usage_error naming --progress (a value outside (0, 86400] s, or
// given with --quiet).
ProgressOptions read_progress_options(const ParsedOptions& o);

// The schedule of a command other than campaign: --progress S, else on
// when stderr is a terminal, and never with --quiet.
ProgressSchedule interactive_schedule(const ProgressOptions& p);

// The line, without "creepwork: " and the newline: `done` of `total`
// `unit` done, and the rate of the `done - already` solved in `seconds`.
std::string progress_text(const std::string& what, const std::string& unit, uint64_t done,
                          uint64_t total, uint64_t already, double seconds);

class Progress {
public:
    // `already`: units done before this run (a resumed campaign).
    Progress(std::string what, std::string unit, uint64_t total, ProgressSchedule schedule,
             uint64_t already = 0);
    // `done` units of `total` are done now: prints a line when one is due.
    void update(uint64_t done);

private:
    using Clock = std::chrono::steady_clock;
    std::string what_, unit_;
    uint64_t total_, already_;
    ProgressSchedule schedule_;
    Clock::time_point start_;
    double next_;
};

} // namespace cwcli
