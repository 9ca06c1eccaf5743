// The pictures of creepwork compare: a simplified model (FASTSIM, FASTSIM
// elliptic or the calibrated model; "FASTSIM" below) beside the exact theory
// for one contact on one uniform grid. compare.png holds, in two columns, each
// model's slip/adhesion map and energy-consistent work per unit area (one
// colour scale for both, slip elements outlined), the lateral work profiles
// of both, and where FASTSIM puts its work relative to the exact theory
// (the difference of the two maps scaled to unit totals). Each panel is also
// a file of its own.
#pragma once

#include <string>

#include "compare_metrics.hpp"
#include "contact_solver.hpp"
#include "plot_style.hpp"
#include "units.hpp"

namespace cwcli {

// Writes dir/gnuplot/{compare.dat,compare_profile.dat,compare.gp} and runs
// gnuplot in dir: compare.png, slip_adhesion_<label>.png,
// slip_adhesion_exact.png, work_<label>.png, work_exact.png,
// work_difference.png, profile.png. name titles the simplified model
// ("FASTSIM"), label names its files ("fastsim").
void write_compare_pictures(const std::string& dir, const Solution& fastsim, const Solution& exact,
                            const WorkComparison& metrics, const Units& u,
                            const std::string& caption, const PlotStyle& style,
                            const std::string& name, const std::string& label);

} // namespace cwcli
