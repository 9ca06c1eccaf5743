// Running gnuplot and the pieces of script every picture shares (terminal,
// palettes, quoting). Pictures are scripts plus whitespace data files kept
// in <out>/gnuplot/, so a user can restyle and re-run them:
//   cd <out> && gnuplot gnuplot/<name>.gp
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace cwcli {

// True when a "gnuplot" executable is on PATH.
bool gnuplot_available();

// Writes text to dir/script (kept, so the user can re-run it) and runs
// "gnuplot <script>" with working directory dir; gnuplot's output goes to
// dir/gnuplot/gnuplot.log (removed when empty). Throws CliError(kExitFailure)
// quoting gnuplot's first error line.
void run_gnuplot(const std::string& dir, const std::string& script, const std::string& text);

// Writes one row of a whitespace data file ("%.9g" each, then a newline)
// and appends each value to its column, for the colour scales.
void gp_data_row(std::ostream& out, const double* row, size_t n,
                 std::vector<std::vector<double>>& cols);

// A gnuplot string literal ('...' with ' doubled).
std::string gp_quote(const std::string& text);

// A double-quoted gnuplot string of several lines.
std::string gp_text_lines(const std::vector<std::string>& lines);

// The same for a title that must fit a picture width_px wide in a font of
// font_pt points: a line longer than the width holds (DejaVu Sans averages
// 0.66 font_pt pixels a character in these titles, taken as 0.7; 20 px
// margins) is broken after its last "; " or ", " (else space) that fits.
std::string gp_title(const std::vector<std::string>& lines, int width_px, int font_pt);

// "set terminal pngcairo ..." and "set output ..." for a picture.
std::string gp_png(const std::string& file, int width, int height);

// Colour scale for one heat map: white at zero; sequential when all values
// are >= 0, diverging blue-white-red with a symmetric range otherwise.
std::string gp_colour_scale(const std::vector<double>& values, const std::string& label);

// boxxyerror columns x:y:dx:dy of data files in normalised coordinates,
// each box padded by about one pixel so antialiasing leaves no seams
// (moire) between elements.
extern const char* const kPaddedBoxes;

// A further plot element (it starts with a comma and a line continuation)
// that outlines the slip elements (state 2 in data column state_column) of
// the current data file in grey, over a heat map.
std::string gp_slip_outline(int state_column);

// Two-colour scale for element states: adhesion (1) blue, slip (2) orange.
std::string gp_state_scale();

// The axes a patch is drawn on: semi-axes ax, by in plot coordinates (1, 1
// for x/a, y/b) about the centre cx, cy, and the axis labels. A gap grid
// has no ellipse: its frame is the grid's extent, ellipse false.
struct PatchAxes {
    double ax = 1.0, by = 1.0;
    std::string xlabel = "x/a", ylabel = "y/b";
    double cx = 0.0, cy = 0.0;
    bool ellipse = true;
};

// The ellipse outline (when axes.ellipse), ranges, labels and the
// rolling-direction arrow.
std::string gp_patch_frame(int rolling_direction, const PatchAxes& axes = PatchAxes());

} // namespace cwcli
