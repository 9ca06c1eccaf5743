// Pictures of a sweep: one PNG per figure, a grid of slip/adhesion maps over
// the normalised patch (x/a, y/b), one panel per creepage case, drawn
// element by element as in patch_plots.hpp.
#pragma once

#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "sweep_series.hpp"
#include "units.hpp"

namespace cwcli {

struct SweepPanel {
    SweepCase c;
    cw_result result;
    std::vector<int> state; // [i + j*nx]
};

// Element geometry shared by all panels (the grid does not change), in
// normalised coordinates, one entry per element [i + j*nx].
struct PatchGeometry {
    std::vector<double> X, Y, half_x, half_y;
    std::vector<char> inside;
};

// Writes dir/gnuplot/<fig>.dat and .gp for each figure and runs gnuplot.
void write_sweep_pictures(const std::string& dir, const std::vector<SweepFigure>& figs,
                          const std::vector<std::vector<SweepPanel>>& panels,
                          const PatchGeometry& geometry, int rolling_direction,
                          const std::string& caption, const Units& u);

} // namespace cwcli
