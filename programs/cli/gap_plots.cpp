#include "gap_plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_error.hpp"
#include "gnuplot.hpp"
#include "patch_maps.hpp"
#include "report.hpp"

namespace cwcli {

namespace {

// The grid's extent [x0 - dx/2, x_last + dx/2] x [...] in plot units: the
// frame of every picture.
PatchAxes gap_axes(const cw_grid& g, int nx, int ny, const Units& u, const std::string& lateral)
{
    const double k = u.plot_factor(Quantity::length);
    PatchAxes axes;
    axes.ax = 0.5 * k * nx * g.dx;
    axes.by = 0.5 * k * ny * g.dy;
    axes.cx = k * (g.x0 + 0.5 * (nx - 1) * g.dx);
    axes.cy = k * (g.y0 + 0.5 * (ny - 1) * g.dy);
    axes.xlabel = "x [" + u.plot_label(Quantity::length) + "]";
    axes.ylabel = lateral + " [" + u.plot_label(Quantity::length) + "]";
    axes.ellipse = false;
    return axes;
}

// gap.dat: x y h of every cell, one scan line (fixed j) per block, as
// gnuplot's `with image` reads a regular grid. Returns the h drawn.
std::vector<double> write_gap_data(const std::string& path, const Solution& s,
                                   const std::vector<double>& gap, const Units& u)
{
    const double k = u.plot_factor(Quantity::length);
    std::vector<double> drawn;
    std::ofstream f(path);
    f << "# x y [" << u.plot_label(Quantity::length) << "], h the undeformed distance ["
      << u.plot_label(Quantity::length) << "], every cell of the gap file\n";
    char buf[80];
    for (int j = 0; j < s.ny; ++j) {
        for (int i = 0; i < s.nx; ++i) {
            const double h = k * gap[static_cast<size_t>(i) + static_cast<size_t>(s.nx) * j];
            std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g\n", k * (s.grid.x0 + i * s.grid.dx),
                          k * (s.grid.y0 + j * s.grid.dy), h);
            f << buf;
            drawn.push_back(h);
        }
        f << "\n";
    }
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
    return drawn;
}

// patches.dat: one row per separate patch, in the library's order (the
// numbers of result.json's "patches" and of the text output).
void write_patches_data(const std::string& path, const std::vector<cw_patch>& patches,
                        const Units& u, ForceSign sign)
{
    const double k = u.plot_factor(Quantity::length), force = u.plot_factor(Quantity::force);
    const double moment = u.plot_factor(Quantity::moment), stress = u.plot_factor(Quantity::stress);
    std::ofstream f(path);
    f << "# patch x_centroid y_centroid [" << u.plot_label(Quantity::length)
      << "] n_contact n_adhesion n_slip Fn Fx Fy [" << u.plot_label(Quantity::force) << "] Mz ["
      << u.plot_label(Quantity::moment) << "] p_max [" << u.plot_label(Quantity::stress)
      << "]; Fx Fy Mz on the " << body_name(sign) << "\n";
    char buf[256];
    for (size_t n = 0; n < patches.size(); ++n) {
        const cw_patch& p = patches[n];
        std::snprintf(buf, sizeof buf, "%zu %.9g %.9g %d %d %d %.9g %.9g %.9g %.9g %.9g\n", n,
                      k * p.x_centroid, k * p.y_centroid, p.n_contact, p.n_adhesion, p.n_slip,
                      force * p.Fn, force * on_body(sign, p.Fx), force * on_body(sign, p.Fy),
                      moment * on_body(sign, p.Mz), stress * p.p_max);
        f << buf;
    }
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
}

// Text gnuplot's enhanced mode prints as is (a file name's _ is no subscript).
std::string enhanced_literal(const std::string& text)
{
    std::string out;
    for (char c : text) {
        if (c == '_' || c == '^' || c == '{' || c == '}' || c == '@' || c == '&' || c == '~')
            out += '\\';
        out += c;
    }
    return out;
}

// The overview's caption: inputs, totals, then each patch (at most eight).
std::vector<std::string> gap_caption(const Solution& s, const std::vector<cw_patch>& patches,
                                     const std::string& file, const Units& u, ForceSign sign)
{
    const cw_params& p = s.params;
    const cw_result r = shown_totals(s);
    // Coordinates below 1e-9 of the grid's extent (a centroid on an axis of
    // symmetry) are rounding noise: shown as 0.
    const double extent = std::max(s.nx * s.grid.dx, s.ny * s.grid.dy);
    const auto len = [&u, extent](double m) {
        if (std::fabs(m) < 1e-9 * extent) m = 0.0;
        return fmt(m * u.plot_factor(Quantity::length), 4) + " " + u.plot_label(Quantity::length);
    };
    const auto force = [&](double f) { return plot_total(on_body(sign, f), Quantity::force, u, 5); };
    std::ostringstream in, totals, each;
    in << "gap " << enhanced_literal(std::filesystem::path(file).filename().string()) << ": "
       << s.nx << "x" << s.ny << " cells of " << len(s.grid.dx) << " x " << len(s.grid.dy)
       << "; ";
    const std::string N = plot_total(r.normal_force, Quantity::force, u, 5);
    if (p.normal_load == CW_NORMAL_APPROACH)
        in << "approach " << len(r.approach) << " from the file's h = 0 given (N = " << N << ")";
    else
        in << "N = " << N << " given (approach " << len(r.approach) << " from the file's h = 0)";
    in << ", μ = " << fmt(p.mu, 4)
       << ", G = " << plot_total(p.G, Quantity::stress, u, 6) << ", ν = " << fmt(p.nu, 4)
       << "; ξ_x = " << fmt(p.xi_x, 5) << ", ξ_y = " << fmt(p.xi_y, 5)
       << ", φ = " << fmt(u.from_si(Quantity::spin, p.phi), 5) << " " << u.label(Quantity::spin)
       << "; " << (r.model == CW_MODEL_FASTSIM ? "FASTSIM" : "exact model") << ", "
       << (p.normal_method == CW_NORMAL_SEMI_HERTZ ? "semi-Hertzian" : "exact")
       << " normal problem";
    totals << "Fn = " << plot_total(r.normal_force, Quantity::force, u, 5)
           << ", Fx = " << force(r.Fx) << ", Fy = " << force(r.Fy)
           << ", Mz = " << plot_total(on_body(sign, r.Mz), Quantity::moment, u, 5)
           << " (about the file's origin), W = " << plot_total(r.W_consistent, Quantity::work, u, 5)
           << "; " << r.n_patches << (r.n_patches == 1 ? " patch" : " patches");
    const size_t shown = std::min<size_t>(patches.size(), 8);
    for (size_t n = 0; n < shown; ++n) {
        const cw_patch q = shown_patch(s, patches[n]);
        each << (n ? "; " : "") << "patch " << n << " at (" << len(q.x_centroid) << ", "
             << len(q.y_centroid) << "): Fn = " << plot_total(q.Fn, Quantity::force, u, 4)
             << ", Fx = " << plot_total(on_body(sign, q.Fx), Quantity::force, u, 4)
             << ", Fy = " << plot_total(on_body(sign, q.Fy), Quantity::force, u, 4);
    }
    if (shown < patches.size()) each << "; ... (patches.dat lists all)";
    std::vector<std::string> lines = {in.str(), totals.str()};
    if (shown > 1) lines.push_back(each.str());
    lines.push_back(sign_note(sign) + "; rolling towards " + (p.rolling_direction > 0 ? "+x" : "-x"));
    return lines;
}

std::string gap_map_commands(const Solution& s, const std::vector<double>& h, const Units& u,
                             const std::string& outline)
{
    const double lo = *std::min_element(h.begin(), h.end());
    std::ostringstream g;
    g << "set title "
      << gp_title({"Undeformed distance h (contact outlined): min h = " +
                   fmt(lo, 4) + " " + u.plot_label(Quantity::length) + ", approach " +
                   fmt(s.result.approach * u.plot_factor(Quantity::length), 4) + " " +
                   u.plot_label(Quantity::length)},
                  700, 10)
      << "\n"
      << gp_colour_scale(h, "h, undeformed distance [" + u.plot_label(Quantity::length) + "]")
      << "plot 'gnuplot/gap.dat' using 1:2:3 with image notitle" << outline << "\n";
    return g.str();
}

} // namespace

// outline.dat: the contact's boundary as the cell edges between a contact
// cell and a cell out of contact (or the grid's edge), one segment per block.
void write_outline_data(const std::string& path, const Solution& s, const Units& u)
{
    const double k = u.plot_factor(Quantity::length);
    const cw_grid& g = s.grid;
    const auto inside = [&s](int i, int j) {
        return i >= 0 && j >= 0 && i < s.nx && j < s.ny &&
               s.state[static_cast<size_t>(i) + static_cast<size_t>(s.nx) * j] !=
                   CW_STATE_EXTERIOR;
    };
    std::ofstream f(path);
    f << "# x y [" << u.plot_label(Quantity::length)
      << "]: the edges between contact cells and the rest, one segment per block\n";
    char buf[96];
    const auto segment = [&](double xa, double ya, double xb, double yb) {
        std::snprintf(buf, sizeof buf, "%.9g %.9g\n%.9g %.9g\n\n", k * xa, k * ya, k * xb, k * yb);
        f << buf;
    };
    for (int j = 0; j < s.ny; ++j)
        for (int i = 0; i < s.nx; ++i) {
            if (!inside(i, j)) continue;
            const double xl = g.x0 + (i - 0.5) * g.dx, xr = xl + g.dx;
            const double yl = g.y0 + (j - 0.5) * g.dy, yr = yl + g.dy;
            if (!inside(i - 1, j)) segment(xl, yl, xl, yr);
            if (!inside(i + 1, j)) segment(xr, yl, xr, yr);
            if (!inside(i, j - 1)) segment(xl, yl, xr, yl);
            if (!inside(i, j + 1)) segment(xl, yr, xr, yr);
        }
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
}

GridMaps write_grid_maps(const std::string& dir, const GridMapFiles& files, const Solution& s,
                         const std::vector<cw_patch>& patches, const Units& u,
                         const PlotStyle& style, const std::string& lateral)
{
    std::filesystem::create_directories(dir + "/gnuplot");
    const PatchAxes axes = gap_axes(s.grid, s.nx, s.ny, u, lateral);
    const double k = u.plot_factor(Quantity::length);
    const auto cols =
        write_patch_data(dir + "/" + files.elements, s, u, style.sign, axes, k, k);
    write_outline_data(dir + "/" + files.outline, s, u);
    if (!patches.empty()) write_patches_data(dir + "/" + files.patches, patches, u, style.sign);

    const std::vector<Panel> all = patch_panels(s, u, style.sign, lateral);
    const auto panel = [&all](int column) {
        return *std::find_if(all.begin(), all.end(),
                             [column](const Panel& p) { return p.column == column; });
    };
    const bool outline_slip = std::max(s.nx, s.ny) <= 60;
    GridMaps maps;
    maps.frame = gp_patch_frame(s.params.rolling_direction, axes);
    maps.contact = ", \\\n     " + gp_quote(files.outline) +
                   " using 1:2 with lines lw 1.5 lc rgb 'black' notitle";
    const auto heat = [&](const Panel& p) {
        return GridPanel{p.png, heat_commands(p, cols[p.column - 1], outline_slip, maps.contact,
                                              files.elements)};
    };
    maps.pressure = heat(pressure_panel(s, u));
    maps.work = heat(panel(kPatchWork));
    maps.traction_x = heat(panel(kPatchTractionX));
    maps.traction_y = heat(panel(kPatchTractionY));
    const std::string labels =
        patches.empty() ? ""
                        : ", \\\n     " + gp_quote(files.patches) +
                              " using 2:3:(sprintf('" + files.label + " %d', int($1))) "
                              "with labels boxed font ',10' notitle";
    maps.slip = {"slip_adhesion.png", slip_map_commands(s, maps.contact + labels, files.elements)};
    return maps;
}

void write_gap_pictures(const std::string& dir, const Solution& s, const std::vector<double>& gap,
                        const std::vector<cw_patch>& patches, const std::string& file,
                        const Units& u, const PlotStyle& style)
{
    const GridMaps maps = write_grid_maps(dir, GridMapFiles(), s, patches, u, style);
    const std::vector<double> h = write_gap_data(dir + "/gnuplot/gap.dat", s, gap, u);

    std::ostringstream g;
    g << "# creepwork solve --gap: pictures of one contact of any shape. Run from the output "
         "directory:\n#   gnuplot gnuplot/gap.gp\n"
      << "set datafile missing NaN\nset style fill solid 1.0 noborder\n"
      << "set style textbox opaque fillcolor rgb 'white' border lc rgb 'black'\n";
    // The overview: the gap and what it carries, then where it slips and
    // what that costs, then the tractions.
    g << gp_png("patch.png", 1400, 2000) << "set multiplot layout 3,2 title "
      << gp_title(gap_caption(s, patches, file, u, style.sign), 1400, 12) << " font ',12'\n"
      << maps.frame << gap_map_commands(s, h, u, maps.contact) << maps.pressure.commands
      << maps.slip.commands << maps.work.commands << maps.traction_x.commands
      << maps.traction_y.commands << "unset multiplot\n";
    // The same panels one per file.
    g << gp_png("gap.png", 800, 700) << maps.frame << gap_map_commands(s, h, u, maps.contact);
    for (const GridPanel* p :
         {&maps.slip, &maps.pressure, &maps.work, &maps.traction_x, &maps.traction_y})
        g << gp_png(p->png, 800, 700) << maps.frame << p->commands;
    g << "unset output\n";
    run_gnuplot(dir, "gnuplot/gap.gp", g.str());
}

} // namespace cwcli
