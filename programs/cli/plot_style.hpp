// How the pictures present a run: on which body the tractions, forces and
// moment act (one run, one convention: the default is the sign the run's
// text output uses), and whether the patch is drawn over normalised
// coordinates (x/a, y/b: every patch a circle, comparable with the paper's
// figures) or physical ones (x, y in mm or in: a 2:1 patch is a 2:1 ellipse).
#pragma once

#include <string>
#include <vector>

#include "options.hpp"

namespace cwcli {

enum class ForceSign { wheel, rail };

struct PlotStyle {
    ForceSign sign = ForceSign::wheel;
    bool physical = false;
};

// --plot-sign wheel|rail, --plot-axes normalised|physical
std::vector<OptionSpec> plot_options();

// The options given, else run_sign and normalised axes.
PlotStyle read_plot_style(const ParsedOptions& opts, ForceSign run_sign);

// "wheel" or "rail".
const char* body_name(ForceSign sign);

// A force, traction or moment given on the wheel (the library's sign), as it
// acts on the chosen body; an exact zero stays +0.
inline double on_body(ForceSign sign, double on_wheel)
{
    return sign == ForceSign::wheel || on_wheel == 0.0 ? on_wheel : -on_wheel;
}

} // namespace cwcli
