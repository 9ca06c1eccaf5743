#include "work_maps_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_error.hpp"
#include "gnuplot.hpp"
#include "report.hpp"

namespace cwcli {

namespace {

// work_maps.dat: x/a y/b half_dx half_dy, then state and work per unit area
// of each panel in turn, one row per element in contact in any model.
// Returns every work value drawn (for the shared colour scale).
std::vector<double> write_work_maps_data(const std::string& path,
                                         const std::vector<MapPanel>& panels, const Units& u)
{
    const Solution& ref = *panels.back().solution;
    const double S = ref.grid.box_scale;
    const double half_x = S / ref.nx, half_y = S / ref.ny;
    const double area = (2.0 * ref.result.a * half_x) * (2.0 * ref.result.b * half_y);
    const double per_area = u.plot_factor(Quantity::work_per_area);
    std::vector<double> drawn;
    std::ofstream out(path);
    out << "# x/a y/b half_dx/a half_dy/b, then per model: state work_consistent/area ("
        << u.plot_label(Quantity::work_per_area) << ")\n";
    for (size_t k = 0; k < ref.size(); ++k) {
        bool inside = false;
        for (const MapPanel& p : panels) inside |= p.solution->state[k] != CW_STATE_EXTERIOR;
        if (!inside) continue;
        char buf[96];
        std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g %.9g", ref.x[k] / ref.result.a,
                      ref.y[k] / ref.result.b, half_x + 0.004, half_y + 0.004);
        out << buf;
        for (const MapPanel& p : panels) {
            const double w = per_area * p.solution->work_consistent[k] / area;
            std::snprintf(buf, sizeof buf, " %d %.9g", p.solution->state[k], w);
            out << buf;
            drawn.push_back(w);
        }
        out << "\n";
    }
    if (!out) throw CliError(kExitFailure, "cannot write " + path);
    return drawn;
}

std::string panel_commands(const MapPanel& p, int state_column, bool outline,
                           const std::string& wunit, double work_factor)
{
    const cw_result& r = p.solution->result;
    std::string title = p.name + ": W = " + fmt(r.W_consistent * work_factor, 4) + wunit +
                        ", adhesion " + fmt(100.0 * r.adhesion_fraction, 3) + " %";
    if (std::isfinite(p.map_l1)) title += ", map L1 from exact " + fmt(p.map_l1, 3);
    const int s = state_column, w = state_column + 1;
    std::ostringstream g;
    g << "set title " << gp_title({title}, 700, 10) << "\n"
      << "plot 'gnuplot/work_maps.dat' using ($" << s << " == 1 ? $1 : NaN):2:3:4 "
      << "with boxxyerror fs solid 1.0 noborder lc rgb '#deebf7' notitle, \\\n"
      // Slip elements, and any element with work: when no element slips the
      // library puts the (unresolved) work at the trailing edge anyway.
      << "     '' using ($" << s << " == 2 || $" << w << " > 0 ? $1 : NaN):2:3:4:" << w
      << " with boxxyerror fs solid 1.0 noborder fc palette z notitle";
    if (outline)
        g << gp_slip_outline(s);
    g << "\n";
    return g.str();
}

} // namespace

void write_work_maps_picture(const std::string& dir, const std::vector<MapPanel>& panels,
                             const Units& u, const std::string& caption)
{
    std::filesystem::create_directories(dir + "/gnuplot");
    const std::vector<double> drawn = write_work_maps_data(dir + "/gnuplot/work_maps.dat", panels, u);
    const Solution& ref = *panels.back().solution;
    // Normalised axes always: the Fig. 6 layout compares shapes across models.
    const std::string frame = gp_patch_frame(ref.params.rolling_direction, PatchAxes());
    const bool outline = std::max(ref.nx, ref.ny) <= 60;
    const int rows = static_cast<int>((panels.size() + 1) / 2);
    std::ostringstream g;
    g << "# creepwork compare --simplified all: the work maps side by side. Run from the "
         "output directory:\n#   gnuplot gnuplot/work_maps.gp\n"
      << "set datafile missing NaN\nset style fill solid 1.0 noborder\n"
      << gp_png("work_maps.png", 1400, 560 * rows + 80) << "set multiplot layout " << rows
      << ",2 title "
      << gp_title({caption, "energy-consistent work per unit area on one colour scale, " +
                                std::to_string(ref.nx) + " x " + std::to_string(ref.ny) +
                                " uniform grid; adhesion light blue, slip elements "
                                "outlined; rolling towards " +
                                (ref.params.rolling_direction > 0 ? "+x" : "-x")},
                  1400, 12)
      << " font ',12'\n"
      << gp_colour_scale(drawn, "work per unit area [" +
                                    u.plot_label(Quantity::work_per_area) + "]");
    const std::string wunit = " " + u.plot_label(Quantity::work);
    for (size_t k = 0; k < panels.size(); ++k)
        g << frame
          << panel_commands(panels[k], 5 + 2 * static_cast<int>(k), outline, wunit,
                            u.plot_factor(Quantity::work));
    g << "unset multiplot\nunset output\n";
    run_gnuplot(dir, "gnuplot/work_maps.gp", g.str());
}

} // namespace cwcli
