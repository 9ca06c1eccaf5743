// The heat maps of one contact that every picture set shares -- the
// elliptic contact's (patch_plots.hpp) and the gap grid's (gap_plots.hpp):
// gnuplot/patch.dat, one row per contact element; the panels drawn from it
// (file, title with its total, colour-bar quantity and unit); and the gnuplot
// commands of the slip/adhesion map and of one heat map.
//
// Each element is drawn as its own rectangle (boxxyerror), because Kalker's
// strip grid is not rectangular: every strip has its own chord and element
// length. Work and moment are shown per unit area for the same reason.
// Signs and units: tractions, forces and moment act on the body the
// ForceSign names, the micro-slips are that body's, stated in every title;
// the picture units are Units::plot_label's (SI: mm, N/mm^2, kN).
#pragma once

#include <string>
#include <vector>

#include "contact_solver.hpp"
#include "gnuplot.hpp"
#include "plot_style.hpp"
#include "units.hpp"

namespace cwcli {

// Data columns of patch.dat (1-based for gnuplot).
enum PatchColumn {
    kPatchX = 1,
    kPatchY,
    kPatchHalfX, // half widths, padded by about a pixel so antialiasing leaves no seams
    kPatchHalfY,
    kPatchState,
    kPatchWork,
    kPatchWorkPaperK,
    kPatchTractionX,
    kPatchTractionY,
    kPatchSlipX,
    kPatchSlipY,
    kPatchMoment,
    kPatchUtilisation,
    kPatchPressure,
    kPatchColumns = kPatchPressure
};

// One heat-map panel: a column of patch.dat and how to present it.
struct Panel {
    std::string png;   // individual picture
    std::string title; // with the total
    int column;        // in patch.dat
    std::string scale; // colour-bar label: quantity [unit]
    bool outline_slip; // draw the slip elements' borders over it
};

// A total in the pictures' units (kN, N m, J/m in SI).
std::string plot_total(double si, Quantity q, const Units& u, int digits = 6);

// One body per figure: the caption line saying that tractions, forces and
// moment act on it and the micro-slips are its own.
std::string sign_note(ForceSign sign);

// The totals, and one patch's, as the pictures show them: those that vanish
// by symmetry (Fx of pure lateral creepage with spin) come out as rounding
// noise, shown as 0.
cw_result shown_totals(const Solution& s);
cw_patch shown_patch(const Solution& s, cw_patch p);

// Writes path: one row per contact element, at (per_metre_x x, per_metre_y y)
// in the coordinates of axes (the frame the map is drawn in). Returns the
// columns (index = PatchColumn - 1) for the colour scales.
std::vector<std::vector<double>> write_patch_data(const std::string& path, const Solution& s,
                                                  const Units& u, ForceSign sign,
                                                  const PatchAxes& axes, double per_metre_x,
                                                  double per_metre_y);

// Work, traction and micro-slip along x and y, moment, utilisation and the
// paper's work x K, in that order, each titled with its total; `lateral`
// names the lateral axis ("s" in a wheel/rail patch frame).
std::vector<Panel> patch_panels(const Solution& s, const Units& u, ForceSign sign,
                                const std::string& lateral = "y");

// The normal pressure, titled with Fn and p_max.
Panel pressure_panel(const Solution& s, const Units& u);

// The data file the maps read, relative to the output directory.
extern const char* const kPatchData; // "gnuplot/patch.dat"

// The slip/adhesion map of `data` (write_patch_data's file); `extra` is
// further plot elements (each starting with ", \\\n"), drawn over it.
std::string slip_map_commands(const Solution& s, const std::string& extra = "",
                              const std::string& data = kPatchData);

// One heat map of p's column; slip elements outlined when p asks and
// `outline` allows (elements a few pixels wide); `extra`, `data` as above.
std::string heat_commands(const Panel& p, const std::vector<double>& values, bool outline,
                          const std::string& extra = "", const std::string& data = kPatchData);

} // namespace cwcli
