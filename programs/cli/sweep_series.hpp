// The creepage series behind the paper's Figs. 2-5 (slip/adhesion maps for
// a/b = 2). The paper prints no values for them, so each series is set in
// multiples of the contact's own saturation creepages -- the creepages at
// which the centre strip (y = 0) of the simplified theory slips entirely:
//   xi_c  = 2 mu p0 L1 / a     (longitudinal: traction xi (a - x)/L1 meets
//                               the bound mu p0 (1 - x^2/a^2) at the leading edge)
//   eta_c = 2 mu p0 L2 / a     (lateral, likewise)
//   phi_c = 2 mu p0 L3 / a^2   (spin: traction phi (a^2 - x^2)/(2 L3) over
//                               the bound is constant along the strip)
// with p0 the peak pressure. So the maps keep their meaning for any contact.
#pragma once

#include <string>
#include <vector>

#include <creepwork/creepwork.h>

namespace cwcli {

struct Saturation {
    double xi_c, eta_c, phi_c; // -, -, 1/m
};

// From the contact's flexibilities (a solve's cw_result) and peak pressure.
Saturation saturation_creepages(const cw_params& p, const cw_result& r);

struct SweepCase {
    double sx, sy, sphi;    // multiples of xi_c, eta_c, phi_c
    double xi_x, xi_y, phi; // the creepages (SI)
};

struct SweepFigure {
    std::string name;    // "fig2": file fig2.png
    std::string caption; // what the series varies
    int rows, cols;
    std::vector<SweepCase> cases; // row by row
};

std::vector<SweepFigure> paper_sweep_figures(const Saturation& s);

} // namespace cwcli
