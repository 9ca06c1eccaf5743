// Pieces every subcommand shares: the output options and the picture policy.
#pragma once

#include <string>
#include <vector>

#include "options.hpp"

namespace cwcli {

// --format text|json, --out DIR, --force, --no-plots, --help, and the
// picture options --plot-sign, --plot-axes (plot_style.hpp)
std::vector<OptionSpec> output_options();
// output_options() whose --format also takes "markdown": the tables the
// documentation shows, printed by the command that computes them
// (scripts/doc-tables.sh pastes them into doc/).
std::vector<OptionSpec> output_options_with_markdown();

// Appends b to a.
std::vector<OptionSpec> join(std::vector<OptionSpec> a, const std::vector<OptionSpec>& b);

// Pictures are made unless --no-plots; without gnuplot on PATH a note goes
// to stderr and only the data files are written (still exit status 0).
// Grids above kMaxPictureElements elements (gnuplot would take minutes)
// get a note instead of pictures.
bool should_plot(const ParsedOptions& opts, long elements = 0);
constexpr long kMaxPictureElements = 250000;

// Parses, and prints usage and returns true when --help was given.
bool parse_or_help(const std::vector<OptionSpec>& specs, int argc, char** argv, int first,
                   const char* usage, ParsedOptions& opts);

} // namespace cwcli
