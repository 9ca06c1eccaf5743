#include "surface_plots.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <vector>

#include "cli_error.hpp"
#include "gap_plots.hpp"
#include "gnuplot.hpp"
#include "report.hpp"

namespace cwcli {

// Helpers in a namespace of their own: the program is built in unity
// batches, where the files' anonymous namespaces are one.
namespace surface_plots_detail {

enum SurfaceColumn { kX = 1, kY, kHalfX, kHalfY, kState, kRail, kWheel, kRcf, kColumns = kRcf };

// Half sizes of element k [m], exterior elements included: a gap grid's
// cells; the uniform grid's box S a x S b over nx x ny; a strip's element
// length from its area (every element of a strip grid is in contact).
void half_size(const Solution& s, size_t k, double& hx, double& hy)
{
    const cw_grid& g = s.grid;
    if (g.kind == CW_GRID_GAP) {
        hx = 0.5 * g.dx;
        hy = 0.5 * g.dy;
    } else if (g.kind == CW_GRID_UNIFORM) {
        hx = g.box_scale * s.result.a / s.nx;
        hy = g.box_scale * s.result.b / s.ny;
    } else {
        hy = s.result.b / s.ny;
        hx = s.area[k] / (4.0 * hy);
    }
}

PatchAxes surface_axes(const Solution& s, const Units& u)
{
    const double k = u.plot_factor(Quantity::length);
    PatchAxes axes;
    axes.xlabel = "x [" + u.plot_label(Quantity::length) + "]";
    axes.ylabel = "y [" + u.plot_label(Quantity::length) + "]";
    const cw_grid& g = s.grid;
    if (g.kind == CW_GRID_GAP) {
        axes.ax = 0.5 * k * s.nx * g.dx;
        axes.by = 0.5 * k * s.ny * g.dy;
        axes.cx = k * (g.x0 + 0.5 * (s.nx - 1) * g.dx);
        axes.cy = k * (g.y0 + 0.5 * (s.ny - 1) * g.dy);
        axes.ellipse = false;
    } else {
        axes.ax = k * s.result.a;
        axes.by = k * s.result.b;
    }
    return axes;
}

std::vector<std::vector<double>> write_surface_data(const std::string& path, const Solution& s,
                                                    const SurfaceOutput& o, const Units& u)
{
    const double k = u.plot_factor(Quantity::length);
    std::vector<std::vector<double>> cols(kColumns);
    std::ofstream f(path);
    f << "# x y half_dx half_dy [" << u.plot_label(Quantity::length)
      << "] state T_rail T_wheel [degC] rcf_index [-]\n";
    for (size_t e = 0; e < s.size(); ++e) {
        double hx = 0.0, hy = 0.0;
        half_size(s, e, hx, hy);
        if (!(hx > 0.0)) continue;
        // Padded by about a pixel so that antialiasing leaves no seams.
        const double row[kColumns] = {k * s.x[e],
                                      k * s.y[e],
                                      k * hx * 1.004,
                                      k * hy * 1.004,
                                      static_cast<double>(s.state[e]),
                                      o.temperature ? o.rail[e] : 0.0,
                                      o.temperature ? o.wheel[e] : 0.0,
                                      o.damage ? o.rcf_index[e] : -0.5};
        gp_data_row(f, row, kColumns, cols);
    }
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
    return cols;
}

std::string temperature_scale(const std::vector<double>& T)
{
    double lo = *std::min_element(T.begin(), T.end()), hi = *std::max_element(T.begin(), T.end());
    if (!(hi > lo)) {
        lo -= 1.0;
        hi += 1.0;
    }
    std::ostringstream g;
    g.precision(9);
    g << "set palette defined (0 '#fff5eb', 0.3 '#fdae6b', 0.65 '#e6550d', 1 '#7f2704')\n"
      << "set cbrange [" << lo << ":" << hi << "]\nset cblabel 'surface temperature [°C]'\n"
      << "set cbtics auto\n";
    return g.str();
}

// The maximum marked: a ring at the element and its value beside it.
std::string mark(double x, double y, const std::string& text)
{
    std::ostringstream g;
    g.precision(9);
    g << "set label 10 " << gp_quote(text) << " at " << x << "," << y
      << " offset 1.2,1.2 front font ',9' tc rgb 'black'\n"
      << "set object 10 circle at " << x << "," << y
      << " size screen 0.012 front fillstyle empty border lc rgb 'black' lw 2\n";
    return g.str();
}

} // namespace surface_plots_detail

using namespace surface_plots_detail;

void write_surface_pictures(const std::string& dir, const Solution& s, const SurfaceOutput& o,
                            const Units& u)
{
    const auto cols = write_surface_data(dir + "/gnuplot/surface.dat", s, o, u);
    const PatchAxes axes = surface_axes(s, u);
    const bool gap = s.grid.kind == CW_GRID_GAP;
    std::string outline;
    if (gap) {
        write_outline_data(dir + "/gnuplot/outline.dat", s, u);
        outline = ", \\\n     'gnuplot/outline.dat' with lines lw 1.5 lc rgb 'black' notitle";
    }
    const double k = u.plot_factor(Quantity::length);
    const double S = s.grid.kind == CW_GRID_UNIFORM ? s.grid.box_scale : 1.0;
    std::ostringstream g;
    g.precision(9);
    const auto frame = [&] {
        g << gp_patch_frame(s.params.rolling_direction, axes);
        if (!gap)
            g << "set xrange [" << -1.08 * S * axes.ax << ":" << 1.08 * S * axes.ax
              << "]\nset yrange [" << -1.08 * S * axes.by << ":" << 1.4 * S * axes.by << "]\n";
    };
    const std::string boxes = "using 1:2:3:4:";
    if (o.temperature) {
        const cw_temperature_result& t = o.temperature_result;
        const char* how = t.discretisation == CW_TEMPERATURE_CONTACT ? "CONTACT's discretisation"
                                                                     : "consistent discretisation";
        struct Body {
            const char* png;
            const char* name;
            int column;
            double T, x, y;
        } bodies[] = {{"temperature_rail.png", "Rail (body 1)", kRail, t.T_max_1, t.x_max_1,
                       t.y_max_1},
                      {"temperature_wheel.png", "Wheel (body 2)", kWheel, t.T_max_2, t.x_max_2,
                       t.y_max_2}};
        for (const Body& b : bodies) {
            g << gp_png(b.png, 760, 640);
            frame();
            g << mark(k * b.x, k * b.y, "max " + fmt(b.T, 4) + " °C")
              << "set title "
              << gp_title({std::string(b.name) + " surface temperature, max " + fmt(b.T, 5) +
                               " °C in the contact",
                           std::string(how) + "; the contact outlined, its hottest element ringed"},
                          760, 10)
              << "\n"
              << temperature_scale(cols[b.column - 1]) << "plot 'gnuplot/surface.dat' " << boxes
              << b.column << " with boxxyerror fs solid 1.0 noborder fc palette z notitle"
              << outline << "\n";
        }
    }
    if (o.damage) {
        const cw_damage_result& d = o.damage_result;
        g << gp_png("rcf_index.png", 760, 640);
        frame();
        g << mark(k * d.x_rcf_max, k * d.y_rcf_max, "max " + fmt(d.rcf_index_max, 3))
          << "set title "
          << gp_title({"RCF index (|p_t| - k)/p_n, floor -0.5: max " + fmt(d.rcf_index_max, 4),
                       "FI_{surf} = " + fmt(d.FI_surf, 4) + ", contact outlined"},
                      760, 10)
          << "\n"
          << gp_colour_scale(cols[kRcf - 1], "RCF index [-]") << "plot 'gnuplot/surface.dat' "
          << boxes << kRcf << " with boxxyerror fs solid 1.0 noborder fc palette z notitle"
          << outline << "\n";
    }
    run_gnuplot(dir, "gnuplot/surface.gp", g.str());
}

} // namespace cwcli
