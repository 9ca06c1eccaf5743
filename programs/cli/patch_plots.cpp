#include "patch_plots.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_error.hpp"
#include "contact_options.hpp"
#include "gnuplot.hpp"
#include "patch_maps.hpp"
#include "report.hpp"

namespace cwcli {

namespace {

PatchAxes axes_of(const Solution& s, const Units& u, const PlotStyle& style)
{
    PatchAxes axes;
    if (style.physical) {
        const double k = u.plot_factor(Quantity::length);
        axes.ax = k * s.result.a;
        axes.by = k * s.result.b;
        axes.xlabel = "x [" + u.plot_label(Quantity::length) + "]";
        axes.ylabel = "y [" + u.plot_label(Quantity::length) + "]";
    }
    return axes;
}

void write_profile_data(const std::string& path, const Solution& s, const Units& u,
                        const PatchAxes& axes)
{
    std::ofstream f(path);
    f << "# " << axes.ylabel << ", w and parabola (" << u.plot_label(Quantity::profile) << ")\n";
    const double k = u.plot_factor(Quantity::profile);
    for (int j = 0; j < s.ny; ++j)
        f << axes.by * s.profile_y[j] / s.result.b << " " << k * s.profile_w[j] << " "
          << k * s.profile_parabola[j] << "\n";
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
}

std::string profile_commands(const Solution& s, const Units& u, const PatchAxes& axes)
{
    const cw_result& r = s.result;
    // Equal-area parabola (3W/4b)(1 - Y^2) in plot units, Y = y/b.
    const double peak = 0.75 * r.W_consistent / r.b * u.plot_factor(Quantity::profile);
    const double b = axes.by;
    std::ostringstream g;
    g.precision(9);
    g << "unset arrow; unset label; unset object\nset size noratio\nunset colorbox\n"
      << "set xrange [" << -1.05 * b << ":" << 1.05 * b << "]\nset yrange [0:*]\n"
      << "set xtics auto\nset ytics auto\n"
      << "set xlabel " << gp_quote(axes.ylabel) << "\nset ylabel "
      << gp_quote("work per unit width [" + u.plot_label(Quantity::profile) + "]")
      << "\nset bmargin 6\nset key at screen 0.5,0.02 center bottom horizontal\nset grid\n"
      << "set title "
      << gp_quote("Lateral work profile, W = " + plot_total(r.W_consistent, Quantity::work, u) +
                  "; max |diff| to parabola " + fmt(100 * r.profile_max_diff, 3) + " % of peak")
      << "\nparabola(Y) = abs(Y) <= 1 ? " << peak << " * (1 - Y*Y) : NaN\n"
      << "set samples 201\n"
      << "plot 'gnuplot/profile.dat' using 1:2 with histeps lw 2 lc rgb '#b2182b' title "
         "'creepwork: work integrated along x, per strip', \\\n"
      << "     '' using 1:2 with points pt 7 ps 0.6 lc rgb '#b2182b' notitle, \\\n"
      << "     parabola(x / " << b
      << ") with lines dt 2 lw 2 lc rgb '#2166ac' title 'parabola of equal area'\n"
      << "unset grid\nset bmargin\n";
    return g.str();
}

} // namespace

std::string describe_case(const Solution& s, const Units& u)
{
    const cw_params& p = s.params;
    std::ostringstream d;
    // UTF-8 Greek and gnuplot's enhanced-text subscripts (pngcairo renders both).
    const double length = u.plot_factor(Quantity::length);
    d << "ξ_x = " << fmt(p.xi_x, 5) << ", ξ_y = " << fmt(p.xi_y, 5)
      << ", φ = " << fmt(u.from_si(Quantity::spin, p.phi), 5) << " " << u.label(Quantity::spin)
      << ", a = " << fmt(length * s.result.a, 5) << " " << u.plot_label(Quantity::length)
      << ", b = " << fmt(length * s.result.b, 5) << " " << u.plot_label(Quantity::length)
      << ", N = " << plot_total(p.normal_force, Quantity::force, u) << ", μ = " << fmt(p.mu, 4)
      << "; " << grid_kind_name(s.grid.kind) << " grid " << s.nx << "x" << s.ny;
    return d.str();
}

void write_patch_pictures(const std::string& dir, const Solution& s, const Units& u,
                          const std::string& caption, const PlotStyle& style)
{
    std::filesystem::create_directories(dir + "/gnuplot");
    const PatchAxes axes = axes_of(s, u, style);
    const auto cols = write_patch_data(dir + "/gnuplot/patch.dat", s, u, style.sign, axes,
                                       axes.ax / s.result.a, axes.by / s.result.b);
    write_profile_data(dir + "/gnuplot/profile.dat", s, u, axes);
    const std::vector<Panel> heat = patch_panels(s, u, style.sign);
    const std::string frame = gp_patch_frame(s.params.rolling_direction, axes);
    // Outlines help as long as elements are a few pixels wide.
    const bool outline = std::max(s.nx, s.ny) <= 60;

    std::ostringstream g;
    g << "# creepwork: pictures of one contact. Run from the output directory:\n"
      << "#   gnuplot gnuplot/patch.gp\n"
      << "set datafile missing NaN\nset style fill solid 1.0 noborder\n";
    // The overview in the paper's layout: slip map | work, then force | slip
    // pairs, then moment | utilisation.
    g << gp_png("patch.png", 1400, 2100) << "set multiplot layout 4,2 title "
      << gp_title({caption, sign_note(style.sign) + "; rolling towards " +
                                (s.params.rolling_direction > 0 ? "+x" : "-x")},
                  1400, 12)
      << " font ',12'\n"
      << frame << slip_map_commands(s);
    for (size_t k = 0; k < 7; ++k) g << heat_commands(heat[k], cols[heat[k].column - 1], outline);
    g << "unset multiplot\n";
    // The same panels one per file.
    g << gp_png("slip_adhesion.png", 800, 700) << frame << slip_map_commands(s);
    for (const Panel& p : heat)
        g << gp_png(p.png, 800, 700) << frame << heat_commands(p, cols[p.column - 1], outline);
    g << gp_png("profile.png", 900, 600) << profile_commands(s, u, axes) << "unset output\n";

    run_gnuplot(dir, "gnuplot/patch.gp", g.str());
}

} // namespace cwcli
