// The paper's Fig. 6 for every model at once (creepwork compare --simplified
// all): each model's energy-consistent work per unit area over the patch,
// side by side on one colour scale, adhesion elements shaded light blue and
// slip elements outlined, axes x/a and y/b (work is drawn wherever there is
// some: with no slip at all the library puts it at the trailing edge,
// CW_WORK_UNRESOLVED). Equal colours are equal work in
// every panel, so a reader sees both where each model puts its work and how
// much there is.
#pragma once

#include <string>
#include <vector>

#include "contact_solver.hpp"
#include "units.hpp"

namespace cwcli {

struct MapPanel {
    std::string name;   // the panel title's model name
    const Solution* solution; // full solve; every panel on one uniform grid
    double map_l1;      // L1 distance of its unit map from the last panel's (NaN: none)
};

// Writes dir/gnuplot/{work_maps.dat,work_maps.gp} and runs gnuplot in dir:
// work_maps.png, two panels per row, the last panel the reference (exact).
void write_work_maps_picture(const std::string& dir, const std::vector<MapPanel>& panels,
                             const Units& u, const std::string& caption);

} // namespace cwcli
