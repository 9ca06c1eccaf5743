// `creepwork solve --gap FILE`: a contact of any shape from its undeformed
// distance on a regular grid (the library's CW_GRID_GAP, the exact model).
//
// FILE is a CSV file with the header x_m,y_m,h_m and one line per cell
// centre of a regular nx x ny grid (nx, ny >= 3, in any order): x along the
// rolling direction, y lateral, h the gap between the surfaces, positive =
// separation, all in metres whatever --units says. The cells are the
// potential contact area; the approach is measured from the file's h = 0 and
// Mz is taken about its origin x = y = 0. Either --N (the normal force) or
// --approach is given.
//
// JSON keys (stable; new keys are only ever added): Fx Fy Mz Fn W_macro
// p_max approach n_contact n_adhesion n_slip n_patches, W_micro_paper K
// W_consistent model iterations residual units sign_convention input{...}
// unit_of{...}, and patches: one object per separate contact patch
// (4-connected elements, the library's order) with Fx Fy Mz Fn W_macro p_max
// approach n_contact n_adhesion n_slip x_centroid y_centroid.
#pragma once

#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "options.hpp"

namespace cwcli {

// --gap FILE, --approach A, --normal-method exact|semi-hertz
std::vector<OptionSpec> gap_options();

struct GapFile {
    cw_grid grid; // CW_GRID_GAP: origin and spacing from the file
    std::vector<double> h; // [i + j*nx] [m]
};

// Reads and checks FILE: the header, three finite numbers per line, every
// cell of one regular grid exactly once. Throws CliError(kExitUsage) naming
// the file and the line (or the missing cell).
GapFile read_gap_file(const std::string& path);

// creepwork solve with --gap: the options of solve that describe an
// elliptical contact or its grid are errors here.
int command_solve_gap(const ParsedOptions& opts);

// Without --gap, --approach and --normal-method are errors naming --gap.
void reject_gap_options(const ParsedOptions& opts);

} // namespace cwcli
