// The pictures of one contact, as in the paper's Figs. 6-9: heat maps over
// the patch of the slip/adhesion map, work per unit area, tractions,
// micro-slips, moment per unit area and the traction-bound utilisation
// |p|/(mu pz), each titled with its total; an eight-panel overview; and the
// lateral work profile against the equal-area parabola.
//
// The maps are patch_maps.hpp's (one rectangle per element, work and moment
// per unit area). Slip elements are outlined in the work maps, so a reader
// sees that the work lives in the slip zone.
//
// Signs and units: tractions, forces and moment act on the body PlotStyle
// names (the run's own convention by default) and the micro-slips are that
// body's, stated in every title; every colour bar names its quantity and
// unit; the picture units are Units::plot_label's (SI: mm, N/mm^2, kN).
#pragma once

#include <string>
#include <vector>

#include "contact_solver.hpp"
#include "plot_style.hpp"
#include "units.hpp"

namespace cwcli {

// Writes dir/gnuplot/{patch.dat,profile.dat,patch.gp} and runs gnuplot in
// dir, which draws patch.png (the overview, headed by caption),
// slip_adhesion.png, work.png, traction_x.png, slip_x.png, traction_y.png,
// slip_y.png, moment.png, utilisation.png, work_paper.png and profile.png.
void write_patch_pictures(const std::string& dir, const Solution& s, const Units& u,
                          const std::string& caption, const PlotStyle& style);

// One-line description of the inputs, e.g. for captions.
std::string describe_case(const Solution& s, const Units& u);

} // namespace cwcli
