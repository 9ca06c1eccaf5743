#include "compare_plots.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "cli_error.hpp"
#include "gnuplot.hpp"
#include "report.hpp"

namespace cwcli {

namespace {

// Columns of compare.dat (1-based for gnuplot).
enum Column {
    kX = 1,
    kY,
    kHalfX,
    kHalfY,
    kStateFastsim,
    kStateExact,
    kWorkFastsim,   // energy-consistent work per unit area
    kWorkExact,
    kShareDifference, // 100 (f/F - e/E): per cent of the total, per element (equal areas)
    kColumns = kShareDifference
};

PatchAxes compare_axes(const Solution& s, const Units& u, const PlotStyle& style)
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

double consistent_total(const Solution& s)
{
    double t = 0.0;
    for (double w : s.work_consistent) t += w;
    return t;
}

// Rows for the elements in contact in either model; returns the columns.
std::vector<std::vector<double>> write_compare_data(const std::string& path, const Solution& f,
                                            const Solution& e, const Units& u,
                                            const PatchAxes& axes)
{
    const double a = e.result.a, b = e.result.b, S = e.grid.box_scale;
    // The uniform grid: every element has the same size.
    const double half_x = S / e.nx, half_y = S / e.ny;
    const double area = (2.0 * a * half_x) * (2.0 * b * half_y);
    const double per_area = u.plot_factor(Quantity::work_per_area);
    const double tf = consistent_total(f), te = consistent_total(e);
    std::vector<std::vector<double>> cols(kColumns);
    std::ofstream out(path);
    out << "# x y half_dx half_dy (" << axes.xlabel << ", " << axes.ylabel
        << ") state_fastsim state_exact work_fastsim/area work_exact/area "
           "100*(f/F - e/E)\n";
    for (size_t k = 0; k < e.size(); ++k) {
        if (f.state[k] == CW_STATE_EXTERIOR && e.state[k] == CW_STATE_EXTERIOR) continue;
        const double share =
            tf > 0.0 && te > 0.0 ? 100.0 * (f.work_consistent[k] / tf - e.work_consistent[k] / te)
                                 : 0.0;
        const double row[kColumns] = {axes.ax * e.x[k] / a,
                                      axes.by * e.y[k] / b,
                                      axes.ax * (half_x + 0.004),
                                      axes.by * (half_y + 0.004),
                                      static_cast<double>(f.state[k]),
                                      static_cast<double>(e.state[k]),
                                      per_area * f.work_consistent[k] / area,
                                      per_area * e.work_consistent[k] / area,
                                      share};
        gp_data_row(out, row, kColumns, cols);
    }
    if (!out) throw CliError(kExitFailure, "cannot write " + path);
    return cols;
}

void write_compare_profile(const std::string& path, const Solution& f, const Solution& e,
                        const Units& u, const PatchAxes& axes)
{
    std::ofstream out(path);
    out << "# " << axes.ylabel << ", w of the simplified model and of the exact theory ("
        << u.plot_label(Quantity::profile) << ")\n";
    const double k = u.plot_factor(Quantity::profile);
    for (int j = 0; j < e.ny; ++j)
        out << axes.by * e.profile_y[j] / e.result.b << " " << k * f.profile_w[j] << " "
            << k * e.profile_w[j] << "\n";
    if (!out) throw CliError(kExitFailure, "cannot write " + path);
}

std::string compare_state_map(const std::string& model, const cw_result& r, int column, bool borders)
{
    std::ostringstream g;
    g << "set title "
      << gp_quote(model + ": " + std::to_string(r.n_adhesion) + " adhesion, " +
                  std::to_string(r.n_slip) + " slip elements (adhesion " +
                  fmt(100.0 * r.adhesion_fraction, 3) + " %)")
      << "\n"
      << gp_state_scale() << "plot 'gnuplot/compare.dat' using ($" << column
      << " > 0 ? $1 : NaN):2:3:4:" << column << " with boxxyerror fs solid 1.0 "
      << (borders ? "border lc rgb '#808080'" : "noborder") << " fc palette z notitle\n";
    return g.str();
}

std::string compare_work_map(const std::string& title, int column, int state_column,
                     const std::vector<double>& scale_values, const std::string& unit,
                     bool outline)
{
    std::ostringstream g;
    g << "set title " << gp_title({title}, 700, 10) << "\n"
      << gp_colour_scale(scale_values, unit) << "plot 'gnuplot/compare.dat' using ";
    // state_column 0: every row (each is in contact for one model at least).
    if (state_column > 0)
        g << "($" << state_column << " > 0 ? $1 : NaN)";
    else
        g << "1";
    g << ":2:3:4:" << column
      << " with boxxyerror fs solid 1.0 noborder fc palette z notitle";
    if (outline)
        g << gp_slip_outline(state_column);
    g << "\n";
    return g.str();
}

std::string compare_profile_plot(const Solution& f, const Solution& e, const WorkComparison& m,
                         const Units& u, const PatchAxes& axes, const std::string& name)
{
    const double b = axes.by;
    std::ostringstream g;
    g.precision(9);
    g << "unset arrow; unset label; unset object\nset size noratio\nunset colorbox\n"
      << "set xrange [" << -1.05 * b * e.grid.box_scale << ":" << 1.05 * b * e.grid.box_scale
      << "]\nset yrange [0:*]\nset xtics auto\nset ytics auto\n"
      << "set xlabel " << gp_quote(axes.ylabel) << "\nset ylabel "
      << gp_quote("work per unit width [" + u.plot_label(Quantity::profile) + "]")
      << "\nset key top right\nset grid\n"
      << "set title "
      << gp_quote("Lateral work profile: " + name + " W = " +
                  fmt(f.result.W_consistent * u.plot_factor(Quantity::work), 5) + ", exact W = " +
                  fmt(e.result.W_consistent * u.plot_factor(Quantity::work), 5) + " " +
                  u.plot_label(Quantity::work) + "; L1 of the shapes " +
                  (std::isfinite(m.profile_l1) ? fmt(m.profile_l1, 3) : std::string("undefined")))
      << "\nplot 'gnuplot/compare_profile.dat' using 1:2 with histeps lw 2 lc rgb '#2166ac' "
         "title " << gp_quote(name) << ", \\\n"
      << "     '' using 1:3 with histeps lw 2 lc rgb '#b2182b' title 'exact theory'\n"
      << "unset grid\n";
    return g.str();
}

} // namespace

void write_compare_pictures(const std::string& dir, const Solution& f, const Solution& e,
                            const WorkComparison& m, const Units& u, const std::string& caption,
                            const PlotStyle& style, const std::string& name,
                            const std::string& label)
{
    std::filesystem::create_directories(dir + "/gnuplot");
    const PatchAxes axes = compare_axes(e, u, style);
    const auto cols = write_compare_data(dir + "/gnuplot/compare.dat", f, e, u, axes);
    write_compare_profile(dir + "/gnuplot/compare_profile.dat", f, e, u, axes);
    const std::string frame = gp_patch_frame(e.params.rolling_direction, axes);
    const bool borders = std::max(e.nx, e.ny) <= 30, outline = std::max(e.nx, e.ny) <= 60;
    // One colour scale for both work maps, so equal colours are equal work.
    std::vector<double> both = cols[kWorkFastsim - 1];
    both.insert(both.end(), cols[kWorkExact - 1].begin(), cols[kWorkExact - 1].end());
    const std::string unit = "work per unit area [" + u.plot_label(Quantity::work_per_area) + "]";
    const double wf = f.result.W_consistent * u.plot_factor(Quantity::work);
    const double we = e.result.W_consistent * u.plot_factor(Quantity::work);
    const std::string wunit = " " + u.plot_label(Quantity::work);
    const std::string share_unit = "difference of work shares [% of the total, per element]";
    const struct {
        std::string png, text;
    } panels[] = {
        {"slip_adhesion_" + label + ".png", compare_state_map(name, f.result, kStateFastsim, borders)},
        {"slip_adhesion_exact.png", compare_state_map("Exact theory", e.result, kStateExact, borders)},
        {"work_" + label + ".png",
         compare_work_map(name + ": work per unit area (energy-consistent), W = " + fmt(wf, 5) + wunit,
                  kWorkFastsim, kStateFastsim, both, unit, outline)},
        {"work_exact.png",
         compare_work_map("Exact theory: work per unit area (energy-consistent), W = " + fmt(we, 5) +
                      wunit,
                  kWorkExact, kStateExact, both, unit, outline)},
        {"work_difference.png",
         compare_work_map("Work share " + name + " minus exact (maps scaled to unit totals), L1 = " +
                      (std::isfinite(m.map_l1_consistent) ? fmt(m.map_l1_consistent, 3)
                                                          : std::string("undefined")),
                  kShareDifference, 0, cols[kShareDifference - 1], share_unit, false)},
    };
    std::ostringstream g;
    g << "# creepwork compare: " << name << " beside the exact theory. Run from the output directory:\n"
      << "#   gnuplot gnuplot/compare.gp\n"
      << "set datafile missing NaN\nset style fill solid 1.0 noborder\n";
    g << gp_png("compare.png", 1400, 1600) << "set multiplot layout 3,2 title "
      << gp_title({caption, name + " (left) and Kalker's exact theory (right) on one " +
                                std::to_string(e.nx) + " x " + std::to_string(e.ny) +
                                " uniform grid; rolling towards " +
                                (e.params.rolling_direction > 0 ? "+x" : "-x")},
                  1400, 12)
      << " font ',12'\n";
    for (const auto& p : panels) g << frame << p.text;
    g << compare_profile_plot(f, e, m, u, axes, name) << "unset multiplot\n";
    for (const auto& p : panels) g << gp_png(p.png, 800, 700) << frame << p.text;
    g << gp_png("profile.png", 900, 600) << compare_profile_plot(f, e, m, u, axes, name) << "unset output\n";
    run_gnuplot(dir, "gnuplot/compare.gp", g.str());
}

} // namespace cwcli
