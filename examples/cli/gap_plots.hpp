// The pictures of a contact of any shape (creepwork solve --gap FILE --out
// DIR): the undeformed distance over the whole grid with the contact
// outlined, and patch_maps.hpp's heat maps -- pressure, slip/adhesion with
// each separate patch labelled at its centroid, tractions, work -- over the
// same frame, the grid's extent in x, y (mm, or in with --units paper; a gap
// has no semi-axes to normalise by).
//
// Every cell of a gap grid is the same dx x dy rectangle, so the gap map is
// an image and the heat maps draw each contact cell as one box. Signs as in
// patch_maps.hpp: the body PlotStyle names, the wheel by default (solve's
// text, JSON and CSV).
#pragma once

#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "contact_solver.hpp"
#include "plot_style.hpp"
#include "units.hpp"

namespace cwcli {

// Writes dir/gnuplot/{gap.dat,outline.dat,patches.dat,patch.dat,gap.gp} and
// runs gnuplot in dir, which draws patch.png (the overview, headed by the
// inputs and totals), gap.png, pressure.png, slip_adhesion.png,
// traction_x.png, traction_y.png and work.png. gap is the file's h per cell
// [i + j*nx] [m], patches the solver's (cw_solver_get_patches), file the
// gap file's name for the caption.
void write_gap_pictures(const std::string& dir, const Solution& s, const std::vector<double>& gap,
                        const std::vector<cw_patch>& patches, const std::string& file,
                        const Units& u, const PlotStyle& style);

} // namespace cwcli
