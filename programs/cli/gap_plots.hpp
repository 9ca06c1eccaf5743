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

// The data files of one contact's maps, relative to the output directory:
// the elements (patch_maps.hpp's columns), the contact's outline and its
// separate patches, labelled "<label> N" at their centroids.
struct GridMapFiles {
    std::string elements = "gnuplot/patch.dat";
    std::string outline = "gnuplot/outline.dat";
    std::string patches = "gnuplot/patches.dat";
    std::string label = "patch";
};

// outline.dat: the contact's boundary on a gap grid as the cell edges between
// a contact cell and a cell out of contact (or the grid's edge), one segment
// per block, in the picture units of u.
void write_outline_data(const std::string& path, const Solution& s, const Units& u);

// One map: its own picture's name and its gnuplot commands.
struct GridPanel {
    std::string png, commands;
};

// The maps of one contact on a regular grid, each over the grid's extent
// with the contact outlined: `frame` (ranges, labels, rolling direction)
// first, then any panel's commands.
struct GridMaps {
    std::string frame;
    std::string contact; // the outline as a further plot element (", \\\n...")
    GridPanel pressure, slip, work, traction_x, traction_y;
};

// Writes the files (into dir) of a contact solved on a regular grid of
// s.grid's cells (kind CW_GRID_GAP: x0, y0, dx, dy) and returns its maps;
// the slip map labels each of `patches` (none: no labels). The lateral axis
// is named `lateral` in labels and titles.
GridMaps write_grid_maps(const std::string& dir, const GridMapFiles& files, const Solution& s,
                         const std::vector<cw_patch>& patches, const Units& u,
                         const PlotStyle& style, const std::string& lateral = "y");

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
