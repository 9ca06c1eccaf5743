// The pictures of the surface post-processors (creepwork solve --temperature
// / --k-yield --out DIR): the surface temperature of the rail (body 1) and
// of the wheel (body 2), and the RCF index, as heat maps over the grid in
// mm (in with --units paper), every element drawn (the trail behind the
// contact too, where the grid has one), the contact outlined (the ellipse,
// or a gap grid's contact cells), the maximum marked and labelled.
#pragma once

#include <string>

#include "contact_solver.hpp"
#include "surface_outputs.hpp"
#include "units.hpp"

namespace cwcli {

// Writes dir/gnuplot/{surface.dat,surface.gp} (and outline.dat on a gap
// grid) and draws temperature_rail.png and temperature_wheel.png (with
// --temperature) and rcf_index.png (with --k-yield).
void write_surface_pictures(const std::string& dir, const Solution& s, const SurfaceOutput& o,
                            const Units& u);

} // namespace cwcli
