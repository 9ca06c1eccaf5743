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
    std::string unit;  // colour-bar label
};

// Data columns of patch.dat (1-based for gnuplot).
enum Column {
    kX = 1,
    kY,
    kHalfX,
    kHalfY,
    kState,
    kWork,
    kWorkPaperK,
    kTractionX,
    kTractionY,
    kSlipX,
    kSlipY,
    kMoment,
    kSpin,
    kColumns = kSpin
};

std::string total(double si, Quantity q, const Units& u, int digits = 6)
{
    return fmt(u.from_si(q, si), digits) + " " + u.label(q);
}

// The same force or moment as it acts on the rail (an exact zero stays +0).
double on_rail(double on_wheel)
{
    return on_wheel == 0.0 ? 0.0 : -on_wheel;
}

// Writes one row per contact element in normalised coordinates and plot
// units; returns the columns (index = Column - 1) for the colour scales.
std::vector<std::vector<double>> write_patch_data(const std::string& path, const Solution& s,
                                                  const Units& u)
{
    const cw_result& r = s.result;
    const double half_y = (s.grid.kind == CW_GRID_UNIFORM ? s.grid.box_scale : 1.0) / s.ny;
    const std::vector<double> spin = spin_distribution(s);
    const double stress = u.plot_factor(Quantity::stress);
    const double work = u.plot_factor(Quantity::work_per_area);
    const double moment = u.plot_factor(Quantity::moment_per_area);
    const double spin_f = u.plot_factor(Quantity::spin);
    std::vector<std::vector<double>> cols(kColumns);
    std::ofstream f(path);
    f << "# x/a y/b half_dx/a half_dy/b state work/area K*work_paper/area px_rail py_rail sx sy "
         "mz_rail/area spin\n";
    for (size_t k = 0; k < s.size(); ++k) {
        const double area = s.area[k];
        if (!(area > 0.0)) continue; // exterior: not part of the patch
        const double row[kColumns] = {s.x[k] / r.a,
                                      s.y[k] / r.b,
                                      area / (4.0 * r.a * r.b * half_y),
                                      half_y,
                                      static_cast<double>(s.state[k]),
                                      work * s.work_consistent[k] / area,
                                      work * r.K * s.work_paper[k] / area,
                                      -stress * s.px[k],
                                      -stress * s.py[k],
                                      s.sx[k],
                                      s.sy[k],
                                      -moment * s.mz[k] / area,
                                      spin_f * spin[k]};
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

void write_profile_data(const std::string& path, const Solution& s, const Units& u)
{
    std::ofstream f(path);
    f << "# y/b w parabola (" << u.plot_label(Quantity::profile) << ")\n";
    const double k = u.plot_factor(Quantity::profile);
    for (int j = 0; j < s.ny; ++j)
        f << s.profile_y[j] / s.result.b << " " << k * s.profile_w[j] << " "
          << k * s.profile_parabola[j] << "\n";
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
}

std::vector<Panel> panels(const Solution& s, const Units& u)
{
    // Totals that vanish by symmetry (Fx of pure lateral creepage with spin)
    // come out as rounding noise; show them as 0.
    cw_result r = s.result;
    const double force_scale = s.params.mu * s.params.normal_force;
    if (std::fabs(r.Fx) < 1e-9 * force_scale) r.Fx = 0.0;
    if (std::fabs(r.Fy) < 1e-9 * force_scale) r.Fy = 0.0;
    if (std::fabs(r.Mz) < 1e-9 * force_scale * r.a) r.Mz = 0.0;
    const std::string stress = u.plot_label(Quantity::stress);
    return {
        {"work.png",
         "Work per unit area (energy-consistent), W = " + total(r.W_consistent, Quantity::work, u),
         kWork, u.plot_label(Quantity::work_per_area)},
        {"traction_x.png",
         "Longitudinal traction on the rail, Fx = " + total(on_rail(r.Fx), Quantity::force, u),
         kTractionX, stress},
        {"slip_x.png", "Longitudinal micro-slip W_x/V (0 in adhesion)", kSlipX, "-"},
        {"traction_y.png",
         "Lateral traction on the rail, Fy = " + total(on_rail(r.Fy), Quantity::force, u),
         kTractionY, stress},
        {"slip_y.png", "Lateral micro-slip W_y/V (0 in adhesion)", kSlipY, "-"},
        {"moment.png",
         "Creep moment per unit area on the rail, Mz = " +
             total(on_rail(r.Mz), Quantity::moment, u),
         kMoment, u.plot_label(Quantity::moment_per_area)},
        {"spin.png",
         "Spin in slip elements (0 in adhesion), spin = " + total(s.params.phi, Quantity::spin, u),
         kSpin, u.plot_label(Quantity::spin)},
        {"work_paper.png",
         "Paper's local work x K per unit area, K = " + fmt(r.K, 4) +
             ", K W_{micro} = " + total(r.K * r.W_micro_paper, Quantity::work, u),
         kWorkPaperK, u.plot_label(Quantity::work_per_area)},
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
    if (std::max(s.nx, s.ny) <= 30)
        g << "plot 'gnuplot/patch.dat' using 1:2:3:4:5 with boxxyerror fs solid 1.0 border lc rgb "
             "'#808080' fc palette z notitle\n";
    else
        g << "plot 'gnuplot/patch.dat' using " << kPaddedBoxes
          << ":5 with boxxyerror fs solid 1.0 noborder fc palette z notitle\n";
    return g.str();
}

std::string heat_commands(const Panel& p, const std::vector<double>& values)
{
    std::ostringstream g;
    g << "set title " << gp_quote(p.title) << "\n"
      << gp_colour_scale(values, p.unit == "-" ? "" : p.unit) << "plot 'gnuplot/patch.dat' using "
      << kPaddedBoxes << ":" << p.column
      << " with boxxyerror fs solid 1.0 noborder fc palette z notitle\n";
    return g.str();
}

std::string profile_commands(const Solution& s, const Units& u)
{
    const cw_result& r = s.result;
    // Equal-area parabola (3W/4b)(1 - Y^2) in plot units, Y = y/b.
    const double peak = 0.75 * r.W_consistent / r.b * u.plot_factor(Quantity::profile);
    std::ostringstream g;
    g.precision(9);
    g << "unset arrow; unset label; unset object\nset size noratio\nunset colorbox\n"
      << "set xrange [-1.05:1.05]\nset yrange [0:*]\nset xtics auto\nset ytics auto\n"
      << "set xlabel 'y/b'\nset ylabel "
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
      << "     parabola(x) with lines dt 2 lw 2 lc rgb '#2166ac' title 'parabola of equal area'\n"
      << "unset grid\nset bmargin\n";
    return g.str();
}

} // namespace

std::string describe_case(const Solution& s, const Units& u)
{
    const cw_params& p = s.params;
    std::ostringstream d;
    // UTF-8 Greek and gnuplot's enhanced-text subscripts (pngcairo renders both).
    d << "ξ_x = " << fmt(p.xi_x, 5) << ", ξ_y = " << fmt(p.xi_y, 5)
      << ", φ = " << total(p.phi, Quantity::spin, u, 5)
      << ", a = " << total(s.result.a, Quantity::length, u, 5)
      << ", a/b = " << fmt(s.result.a / s.result.b, 4)
      << ", N = " << total(p.normal_force, Quantity::force, u, 6) << ", μ = " << fmt(p.mu, 4)
      << "; " << grid_kind_name(s.grid.kind) << " grid " << s.nx << "x" << s.ny;
    return d.str();
}

void write_patch_pictures(const std::string& dir, const Solution& s, const Units& u,
                          const std::string& caption)
{
    std::filesystem::create_directories(dir + "/gnuplot");
    const auto cols = write_patch_data(dir + "/gnuplot/patch.dat", s, u);
    write_profile_data(dir + "/gnuplot/profile.dat", s, u);
    const std::vector<Panel> heat = panels(s, u);
    const std::string frame = gp_patch_frame(s.params.rolling_direction);

    std::ostringstream g;
    g << "# creepwork: pictures of one contact. Run from the output directory:\n"
      << "#   gnuplot gnuplot/patch.gp\n"
      << "set datafile missing NaN\nset style fill solid 1.0 noborder\n";
    // The overview in the paper's layout: slip map | work, then force | slip
    // pairs, then moment | spin.
    g << gp_png("patch.png", 1400, 2100) << "set multiplot layout 4,2 title "
      << gp_text_lines({caption, std::string("tractions and moment on the rail (the paper's sign); "
                                             "rolling towards ") +
                                     (s.params.rolling_direction > 0 ? "+x" : "-x")})
      << " font ',12'\n"
      << frame << slip_map_commands(s);
    for (size_t k = 0; k < 7; ++k) g << heat_commands(heat[k], cols[heat[k].column - 1]);
    g << "unset multiplot\n";
    // The same panels one per file.
    g << gp_png("slip_adhesion.png", 800, 700) << frame << slip_map_commands(s);
    for (const Panel& p : heat)
        g << gp_png(p.png, 800, 700) << frame << heat_commands(p, cols[p.column - 1]);
    g << gp_png("profile.png", 900, 600) << profile_commands(s, u) << "unset output\n";

    run_gnuplot(dir, "gnuplot/patch.gp", g.str());
}

} // namespace cwcli
