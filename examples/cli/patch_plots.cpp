#include "patch_plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_error.hpp"
#include "contact_options.hpp"
#include "gnuplot.hpp"
#include "report.hpp"

namespace cwcli {

namespace {

// One heat-map panel: a column of patch.dat and how to present it.
struct Panel {
    std::string png;   // individual picture
    std::string title; // with the total
    int column;        // in patch.dat
    std::string scale; // colour-bar label: quantity [unit]
    bool outline_slip; // draw the slip elements' borders over it
};

// Data columns of patch.dat (1-based for gnuplot).
enum Column {
    kX = 1,
    kY,
    kHalfX, // half widths, padded by about a pixel so antialiasing leaves no seams
    kHalfY,
    kState,
    kWork,
    kWorkPaperK,
    kTractionX,
    kTractionY,
    kSlipX,
    kSlipY,
    kMoment,
    kUtilisation,
    kColumns = kUtilisation
};

// A total in the pictures' units (kN, N m, J/m in SI).
std::string total(double si, Quantity q, const Units& u, int digits = 6)
{
    return fmt(si * u.plot_factor(q), digits) + " " + u.plot_label(q);
}

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

// Writes one row per contact element in plot coordinates and units; returns
// the columns (index = Column - 1) for the colour scales.
std::vector<std::vector<double>> write_patch_data(const std::string& path, const Solution& s,
                                                  const Units& u, const PlotStyle& style,
                                                  const PatchAxes& axes)
{
    const cw_result& r = s.result;
    const double half_y = (s.grid.kind == CW_GRID_UNIFORM ? s.grid.box_scale : 1.0) / s.ny;
    const double stress = u.plot_factor(Quantity::stress);
    const double work = u.plot_factor(Quantity::work_per_area);
    const double moment = u.plot_factor(Quantity::moment_per_area);
    const ForceSign sign = style.sign;
    std::vector<std::vector<double>> cols(kColumns);
    std::ofstream f(path);
    f << "# x y half_dx half_dy (" << axes.xlabel << ", " << axes.ylabel
      << ") state work/area K*work_paper/area px py sx sy mz/area utilisation; px py mz on the "
      << body_name(sign) << ", sx sy of the " << body_name(sign) << "\n";
    for (size_t k = 0; k < s.size(); ++k) {
        const double area = s.area[k];
        // Exterior: not part of the patch (area 0; the state says so too).
        if (!(area > 0.0) || s.state[k] == CW_STATE_EXTERIOR) continue;
        const double bound = s.params.mu * s.pz[k];
        const double utilisation = bound > 0.0 ? std::hypot(s.px[k], s.py[k]) / bound : 0.0;
        const double row[kColumns] = {axes.ax * s.x[k] / r.a,
                                      axes.by * s.y[k] / r.b,
                                      axes.ax * (area / (4.0 * r.a * r.b * half_y) + 0.004),
                                      axes.by * (half_y + 0.004),
                                      static_cast<double>(s.state[k]),
                                      work * s.work_consistent[k] / area,
                                      work * r.K * s.work_paper[k] / area,
                                      stress * on_body(sign, s.px[k]),
                                      stress * on_body(sign, s.py[k]),
                                      on_body(sign, s.sx[k]),
                                      on_body(sign, s.sy[k]),
                                      moment * on_body(sign, s.mz[k]) / area,
                                      utilisation};
        char buf[40];
        for (int c = 0; c < kColumns; ++c) {
            std::snprintf(buf, sizeof buf, c ? " %.9g" : "%.9g", row[c]);
            f << buf;
            cols[c].push_back(row[c]);
        }
        f << "\n";
    }
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
    return cols;
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

std::vector<Panel> panels(const Solution& s, const Units& u, ForceSign sign)
{
    // Totals that vanish by symmetry (Fx of pure lateral creepage with spin)
    // come out as rounding noise; show them as 0.
    cw_result r = s.result;
    const double force_scale = s.params.mu * s.params.normal_force;
    if (std::fabs(r.Fx) < 1e-9 * force_scale) r.Fx = 0.0;
    if (std::fabs(r.Fy) < 1e-9 * force_scale) r.Fy = 0.0;
    if (std::fabs(r.Mz) < 1e-9 * force_scale * r.a) r.Mz = 0.0;
    const std::string body = body_name(sign);
    const std::string stress = " [" + u.plot_label(Quantity::stress) + "]";
    const std::string on = " on the " + body, of = " of the " + body;
    const std::string per_area = " [" + u.plot_label(Quantity::work_per_area) + "]";
    return {
        {"work.png",
         "Work per unit area (energy-consistent; slip elements outlined), W = " +
             total(r.W_consistent, Quantity::work, u),
         kWork, "work per unit area" + per_area, true},
        {"traction_x.png",
         "Longitudinal traction" + on + ", Fx = " + total(on_body(sign, r.Fx), Quantity::force, u),
         kTractionX, "p_x" + on + stress, false},
        {"slip_x.png", "Longitudinal micro-slip W_x/V" + of + " (0 in adhesion)", kSlipX,
         "W_x/V" + of + " [-]", false},
        {"traction_y.png",
         "Lateral traction" + on + ", Fy = " + total(on_body(sign, r.Fy), Quantity::force, u),
         kTractionY, "p_y" + on + stress, false},
        {"slip_y.png", "Lateral micro-slip W_y/V" + of + " (0 in adhesion)", kSlipY,
         "W_y/V" + of + " [-]", false},
        {"moment.png",
         "Creep moment per unit area" + on + ", Mz = " +
             total(on_body(sign, r.Mz), Quantity::moment, u),
         kMoment, "m_z per unit area" + on + " [" + u.plot_label(Quantity::moment_per_area) + "]",
         false},
        {"utilisation.png", "Traction-bound utilisation |p|/(μ p_z): 1 in slip", kUtilisation,
         "|p|/(μ p_z) [-]", false},
        {"work_paper.png",
         "Paper's local work x K per unit area (slip elements outlined), K = " + fmt(r.K, 4) +
             ", K W_{micro} = " + total(r.K * r.W_micro_paper, Quantity::work, u),
         kWorkPaperK, "K x local work per unit area" + per_area, true},
    };
}

std::string slip_map_commands(const Solution& s)
{
    const cw_result& r = s.result;
    std::ostringstream g;
    g << "set title "
      << gp_quote("Slip/adhesion: " + std::to_string(r.n_adhesion) + " adhesion, " +
                  std::to_string(r.n_slip) + " slip elements (adhesion " +
                  fmt(100.0 * r.adhesion_fraction, 3) + " %)")
      << "\n"
      << gp_state_scale();
    // Element outlines help on coarse grids and would hide the map on fine ones.
    g << "plot 'gnuplot/patch.dat' using 1:2:3:4:5 with boxxyerror fs solid 1.0 "
      << (std::max(s.nx, s.ny) <= 30 ? "border lc rgb '#808080'" : "noborder")
      << " fc palette z notitle\n";
    return g.str();
}

std::string heat_commands(const Panel& p, const std::vector<double>& values, bool outline)
{
    std::ostringstream g;
    g << "set title " << gp_title({p.title}, 700, 10) << "\n"
      << gp_colour_scale(values, p.scale)
      << "plot 'gnuplot/patch.dat' using 1:2:3:4:" << p.column
      << " with boxxyerror fs solid 1.0 noborder fc palette z notitle";
    if (p.outline_slip && outline)
        g << gp_slip_outline(5);
    g << "\n";
    return g.str();
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
      << gp_quote("Lateral work profile, W = " + total(r.W_consistent, Quantity::work, u) +
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
      << ", N = " << total(p.normal_force, Quantity::force, u) << ", μ = " << fmt(p.mu, 4)
      << "; " << grid_kind_name(s.grid.kind) << " grid " << s.nx << "x" << s.ny;
    return d.str();
}

void write_patch_pictures(const std::string& dir, const Solution& s, const Units& u,
                          const std::string& caption, const PlotStyle& style)
{
    std::filesystem::create_directories(dir + "/gnuplot");
    const PatchAxes axes = axes_of(s, u, style);
    const auto cols = write_patch_data(dir + "/gnuplot/patch.dat", s, u, style, axes);
    write_profile_data(dir + "/gnuplot/profile.dat", s, u, axes);
    const std::vector<Panel> heat = panels(s, u, style.sign);
    const std::string frame = gp_patch_frame(s.params.rolling_direction, axes);
    // Outlines help as long as elements are a few pixels wide.
    const bool outline = std::max(s.nx, s.ny) <= 60;
    // One body per figure: tractions, forces and moment act on it, micro-slips are its own.
    const std::string sign_note =
        style.sign == ForceSign::wheel
            ? "tractions, forces, moment on and micro-slips of the wheel (creepwork's, Kalker's "
              "and CONTACT's sign)"
            : "tractions, forces, moment on and micro-slips of the rail (the paper's sign)";

    std::ostringstream g;
    g << "# creepwork: pictures of one contact. Run from the output directory:\n"
      << "#   gnuplot gnuplot/patch.gp\n"
      << "set datafile missing NaN\nset style fill solid 1.0 noborder\n";
    // The overview in the paper's layout: slip map | work, then force | slip
    // pairs, then moment | utilisation.
    g << gp_png("patch.png", 1400, 2100) << "set multiplot layout 4,2 title "
      << gp_title({caption, sign_note + "; rolling towards " +
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
