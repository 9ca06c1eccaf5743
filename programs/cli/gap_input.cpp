#include "gap_input.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli_error.hpp"
#include "command_common.hpp"
#include "contact_options.hpp"
#include "contact_solver.hpp"
#include "csv_output.hpp"
#include "gap_plots.hpp"
#include "surface_outputs.hpp"
#include "surface_plots.hpp"
#include "json.hpp"
#include "output_dir.hpp"
#include "report.hpp"

namespace cwcli {

std::vector<OptionSpec> gap_options()
{
    using K = OptionKind;
    return {{"gap", K::text, {}},
            {"approach", K::number, {}},
            {"normal-method", K::choice, {"exact", "semi_hertz"}}};
}

namespace {

struct Cell {
    double x, y, h;
    long line;
};

std::string show(double v)
{
    std::ostringstream s;
    s.precision(12);
    s << v;
    return s.str();
}

// The grid's axis from one coordinate of every line: the sorted distinct
// values (closer than tol merged: the file's printed digits round the
// coordinates) that at least half as many lines share as the most shared
// one. A stray value (a mistyped line) is left out, so the error names its
// line, not the grid's.
std::vector<double> axis_of(std::vector<double> v, double tol)
{
    std::sort(v.begin(), v.end());
    std::vector<double> values;
    std::vector<long> counts;
    for (double x : v) {
        if (values.empty() || x - values.back() > tol) {
            values.push_back(x);
            counts.push_back(0);
        }
        ++counts.back();
    }
    const long most = counts.empty() ? 0 : *std::max_element(counts.begin(), counts.end());
    std::vector<double> out;
    for (size_t k = 0; k < values.size(); ++k)
        if (2 * counts[k] >= most) out.push_back(values[k]);
    return out;
}

// A regular axis through the values: its first value, the spacing (on the
// median step between neighbours, so that shifted or missing values do not
// set it) and the number of values to the last one.
struct Axis {
    double x0 = 0, d = 0;
    int n = 0;
};

Axis regular_axis(const std::vector<double>& values)
{
    Axis a;
    a.n = static_cast<int>(values.size());
    if (values.size() < 2) return a;
    std::vector<double> steps;
    for (size_t k = 1; k < values.size(); ++k) steps.push_back(values[k] - values[k - 1]);
    std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
    const double step = steps[steps.size() / 2];
    a.x0 = values.front();
    // The spacing from the first to the farthest value on that step: the
    // printed coordinates give it best over the longest run.
    double last = a.x0;
    long k_last = 0;
    for (double v : values) {
        const double t = (v - a.x0) / step;
        if (std::fabs(t - std::lround(t)) < 1e-3) {
            last = v;
            k_last = std::lround(t);
        }
    }
    a.d = (last - a.x0) / static_cast<double>(k_last);
    a.n = static_cast<int>(std::lround((values.back() - a.x0) / a.d)) + 1;
    return a;
}

// Index of v on the regular axis x0 + k d (n values), or -1 if it is off.
int on_axis(double v, double x0, double d, int n)
{
    const double t = (v - x0) / d;
    const long k = std::lround(t);
    return k >= 0 && k < n && std::fabs(t - k) <= 1e-6 ? static_cast<int>(k) : -1;
}

} // namespace

GapFile read_gap_file(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw usage_error("--gap", "cannot open " + path);
    const auto at = [&](long line) { return path + ":" + std::to_string(line) + ": "; };
    std::string line;
    long number = 0;
    std::vector<Cell> cells;
    bool header = false;
    while (std::getline(in, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        if (!header) {
            std::string compact;
            for (char ch : line)
                if (ch != ' ' && ch != '\t') compact += ch;
            if (compact != "x_m,y_m,h_m")
                throw usage_error("--gap", at(number) + "the header must be x_m,y_m,h_m (got \"" +
                                               line + "\")");
            header = true;
            continue;
        }
        std::vector<std::string> fields;
        std::stringstream ss(line);
        std::string f;
        while (std::getline(ss, f, ',')) fields.push_back(f);
        if (fields.size() != 3)
            throw usage_error("--gap", at(number) + "expected 3 values x_m,y_m,h_m, got " +
                                           std::to_string(fields.size()));
        double v[3];
        for (int k = 0; k < 3; ++k) {
            std::string t = fields[k];
            t.erase(0, t.find_first_not_of(" \t"));
            t.erase(t.find_last_not_of(" \t") + 1);
            if (!parse_finite_double(t, v[k]))
                throw usage_error("--gap", at(number) + "\"" + fields[k] +
                                               "\" is not a finite number");
        }
        cells.push_back({v[0], v[1], v[2], number});
    }
    if (!header) throw usage_error("--gap", path + ": empty file (no header x_m,y_m,h_m)");

    std::vector<double> xs, ys;
    for (const Cell& c : cells) {
        xs.push_back(c.x);
        ys.push_back(c.y);
    }
    const auto span = [](const std::vector<double>& v) {
        return v.empty() ? 0.0
                         : *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
    };
    const Axis ax = regular_axis(axis_of(xs, 1e-9 * span(xs)));
    const Axis ay = regular_axis(axis_of(ys, 1e-9 * span(ys)));
    const int nx = ax.n, ny = ay.n;
    if (nx < CW_MIN_GAP_CELLS || ny < CW_MIN_GAP_CELLS)
        throw usage_error("--gap", path + ": " + std::to_string(nx) + " x " + std::to_string(ny) +
                                       " cells; a gap grid needs at least 3 x 3");
    if (nx > CW_MAX_EXACT_CELLS || ny > CW_MAX_EXACT_CELLS)
        throw usage_error("--gap", path + ": " + std::to_string(nx) + " x " + std::to_string(ny) +
                                       " cells; at most " + std::to_string(CW_MAX_EXACT_CELLS) +
                                       " per direction");
    GapFile g;
    cw_grid_init(&g.grid);
    g.grid.kind = CW_GRID_GAP;
    g.grid.nx = nx;
    g.grid.ny = ny;
    g.grid.x0 = ax.x0;
    g.grid.y0 = ay.x0;
    g.grid.dx = ax.d;
    g.grid.dy = ay.d;
    const size_t n = static_cast<size_t>(nx) * ny;
    g.h.assign(n, 0.0);
    std::vector<long> seen(n, 0);
    for (const Cell& c : cells) {
        const int i = on_axis(c.x, g.grid.x0, g.grid.dx, nx);
        const int j = on_axis(c.y, g.grid.y0, g.grid.dy, ny);
        if (i < 0 || j < 0)
            throw usage_error("--gap", at(c.line) + (i < 0 ? "x_m = " + show(c.x) : "y_m = " + show(c.y)) +
                                           " is off the regular grid of the other cells (their " +
                                           (i < 0 ? "x" : "y") + " values run from " +
                                           show(i < 0 ? g.grid.x0 : g.grid.y0) + " in steps of " +
                                           show(i < 0 ? g.grid.dx : g.grid.dy) + ")");
        const size_t k = static_cast<size_t>(i) + static_cast<size_t>(nx) * j;
        if (seen[k])
            throw usage_error("--gap", at(c.line) + "the cell at x_m = " + show(c.x) +
                                           ", y_m = " + show(c.y) + " is already on line " +
                                           std::to_string(seen[k]));
        seen[k] = c.line;
        g.h[k] = c.h;
    }
    for (size_t k = 0; k < n; ++k)
        if (!seen[k])
            throw usage_error("--gap", path + ": the cell at x_m = " +
                                           show(g.grid.x0 + (k % nx) * g.grid.dx) + ", y_m = " +
                                           show(g.grid.y0 + (k / nx) * g.grid.dy) +
                                           " is missing (" + std::to_string(cells.size()) +
                                           " lines for a " + std::to_string(nx) + " x " +
                                           std::to_string(ny) + " grid)");
    return g;
}

namespace {

// Options of solve that describe an ellipse, its grid or another model.
void reject_elliptic_options(const ParsedOptions& o)
{
    const char* unused[][2] = {
        {"a", "the gap file defines the contact: no semi-axes"},
        {"b", "the gap file defines the contact: no semi-axes"},
        {"grid", "the gap file defines the grid"},
        {"nx", "the gap file defines the grid"},
        {"ny", "the gap file defines the grid"},
        {"box-scale", "the gap file defines the grid"},
        {"pressure", "the normal problem is solved on the gap (--normal-method)"},
        {"L1", "on a gap the flexibilities come from G and nu"},
        {"L2", "on a gap the flexibilities come from G and nu"},
        {"L3", "on a gap the flexibilities come from G and nu"},
        {"flexibility-blending", "a FASTSIM option for an ellipse, not for a gap"}};
    for (const auto& u : unused)
        if (o.has(u[0])) throw usage_error(std::string("--") + u[0], u[1]);
    if (o.has("model") && o.text("model", "") != "exact" && o.text("model", "") != "fastsim")
        throw usage_error("--model", "a gap is solved by the exact model (--model exact, the "
                                     "default with --gap) or FASTSIM (--model fastsim)");
    if (o.text("plot-axes", "") == "normalised")
        throw usage_error("--plot-axes", "a gap has no semi-axes to normalise by: its pictures "
                                         "are drawn over x, y (mm, or in with --units paper)");
    if (o.has("N") == o.has("approach"))
        throw usage_error(o.has("N") ? "--N/--approach" : "--N",
                          o.has("N") ? "give the normal force or the approach, not both"
                                     : "missing: with --gap give the normal force --N or the "
                                       "approach --approach (from the file's h = 0)");
}

JsonObject totals_json(const cw_patch& p, double approach, const Units& u, bool centroid)
{
    JsonObject j;
    j.number("Fx", u.from_si(Quantity::force, p.Fx))
        .number("Fy", u.from_si(Quantity::force, p.Fy))
        .number("Mz", u.from_si(Quantity::moment, p.Mz))
        .number("Fn", u.from_si(Quantity::force, p.Fn))
        .number("W_macro", u.from_si(Quantity::work, p.W_macro))
        .number("p_max", u.from_si(Quantity::stress, p.p_max))
        .number("approach", u.from_si(Quantity::length, approach))
        .integer("n_contact", p.n_contact)
        .integer("n_adhesion", p.n_adhesion)
        .integer("n_slip", p.n_slip);
    if (centroid)
        j.number("x_centroid", u.from_si(Quantity::length, p.x_centroid))
            .number("y_centroid", u.from_si(Quantity::length, p.y_centroid));
    return j;
}

JsonObject gap_json(const Solution& s, const std::vector<cw_patch>& patches, const std::string& file,
                    const Units& u)
{
    const cw_result& r = s.result;
    cw_patch total;
    cw_patch_init(&total);
    total.Fx = r.Fx;
    total.Fy = r.Fy;
    total.Mz = r.Mz;
    total.Fn = r.normal_force;
    total.W_macro = r.W_macro;
    total.p_max = r.p_max;
    total.n_contact = r.n_contact;
    total.n_adhesion = r.n_adhesion;
    total.n_slip = r.n_slip;
    JsonObject j = totals_json(total, r.approach, u, false);
    j.integer("n_patches", r.n_patches)
        .number("W_micro_paper", u.from_si(Quantity::work, r.W_micro_paper))
        .number("K", r.K)
        .number("W_consistent", u.from_si(Quantity::work, r.W_consistent))
        .text("model", r.model == CW_MODEL_FASTSIM ? "fastsim" : "exact")
        .integer("iterations", r.iterations)
        .number("residual", r.residual)
        .text("units", u.name())
        .text("sign_convention",
              "Fx, Fy, Mz act on the wheel (Kalker, CONTACT): opposite to the creepages; Mz "
              "about the gap file's origin");
    std::vector<JsonObject> list;
    for (const cw_patch& p : patches) list.push_back(totals_json(p, r.approach, u, true));
    j.array("patches", list);
    const cw_params& p = s.params;
    JsonObject in;
    in.text("gap", file)
        .integer("nx", s.grid.nx)
        .integer("ny", s.grid.ny)
        .number("x0", u.from_si(Quantity::length, s.grid.x0))
        .number("y0", u.from_si(Quantity::length, s.grid.y0))
        .number("dx", u.from_si(Quantity::length, s.grid.dx))
        .number("dy", u.from_si(Quantity::length, s.grid.dy))
        .text("normal_load", p.normal_load == CW_NORMAL_APPROACH ? "approach" : "force");
    if (p.normal_load == CW_NORMAL_APPROACH)
        in.number("approach", u.from_si(Quantity::length, p.approach));
    else
        in.number("N", u.from_si(Quantity::force, p.normal_force));
    in.text("normal_method", p.normal_method == CW_NORMAL_SEMI_HERTZ ? "semi_hertz" : "exact")
        .number("mu", p.mu)
        .number("G", u.from_si(Quantity::stress, p.G))
        .number("nu", p.nu)
        .number("xi_x", p.xi_x)
        .number("xi_y", p.xi_y)
        .number("spin", u.from_si(Quantity::spin, p.phi))
        .integer("rolling_direction", p.rolling_direction)
        .number("tolerance", effective_tolerance(p))
        .integer("max_iterations", effective_max_iterations(p));
    j.object("input", in);
    JsonObject unit_of;
    unit_of.text("Fx", u.label(Quantity::force))
        .text("Mz", u.label(Quantity::moment))
        .text("W_macro", u.label(Quantity::work))
        .text("p_max", u.label(Quantity::stress))
        .text("approach", u.label(Quantity::length))
        .text("gap_file", "m");
    j.object("unit_of", unit_of);
    return j;
}

void print_gap_text(std::ostream& os, const Solution& s, const std::vector<cw_patch>& patches,
                    const std::string& file, const Units& u)
{
    const auto val = [&u](double si, Quantity q) {
        return fmt(u.from_si(q, si)) + (q == Quantity::dimensionless ? "" : " " + u.label(q));
    };
    const cw_result& r = s.result;
    const cw_params& p = s.params;
    os << "gap        " << file << ": " << s.grid.nx << " x " << s.grid.ny << " cells of "
       << val(s.grid.dx, Quantity::length) << " x " << val(s.grid.dy, Quantity::length) << "\n";
    os << "load       " << (p.normal_load == CW_NORMAL_APPROACH ? "approach given" : "normal force given")
       << ": N = " << val(r.normal_force, Quantity::force)
       << ", approach = " << val(r.approach, Quantity::length) << " from the file's h = 0, mu = "
       << fmt(p.mu) << "\n";
    os << "material   G = " << val(p.G, Quantity::stress) << ", nu = " << fmt(p.nu) << "\n";
    os << "creepage   xi_x = " << fmt(p.xi_x) << ", xi_y = " << fmt(p.xi_y)
       << ", spin = " << val(p.phi, Quantity::spin) << ", rolling towards "
       << (p.rolling_direction > 0 ? "+x" : "-x") << "\n";
    os << "model      "
       << (r.model == CW_MODEL_FASTSIM ? "fastsim (Kalker's simplified theory, each patch's "
                                         "flexibilities)"
                                       : "exact (Kalker's half-space theory)")
       << ", normal problem "
       << (p.normal_method == CW_NORMAL_SEMI_HERTZ ? "semi-Hertzian (per row)" : "exact") << ": p_max = "
       << val(r.p_max, Quantity::stress);
    if (r.model == CW_MODEL_EXACT) // FASTSIM's march does not iterate
        os << ", " << r.iterations << " iterations, residual " << fmt(r.residual, 3);
    os << "\n";
    os << "results    (forces and moment on the wheel, Mz about the file's origin)\n";
    const struct {
        const char* key;
        double v;
        Quantity q;
    } rows[] = {{"Fx", r.Fx, Quantity::force},       {"Fy", r.Fy, Quantity::force},
                {"Mz", r.Mz, Quantity::moment},      {"Fn", r.normal_force, Quantity::force},
                {"W_macro", r.W_macro, Quantity::work}, {"W_consistent", r.W_consistent, Quantity::work}};
    for (const auto& e : rows)
        os << "  " << e.key << std::string(16 - std::string(e.key).size(), ' ') << "= "
           << val(e.v, e.q) << "\n";
    os << "  elements        = " << r.n_contact << " (" << r.n_adhesion << " adhesion, " << r.n_slip
       << " slip) in " << r.n_patches << (r.n_patches == 1 ? " patch\n" : " patches\n");
    // A centroid on an axis of symmetry comes out as rounding noise
    // (-4.9e-19 m): shown as 0 below a millionth of a cell.
    const double noise = 1e-6 * std::min(s.grid.dx, s.grid.dy);
    const auto coordinate = [&](double v) { return val(std::fabs(v) < noise ? 0.0 : v, Quantity::length); };
    for (size_t k = 0; k < patches.size(); ++k) {
        const cw_patch& q = patches[k];
        os << "  patch " << k << "  at (" << coordinate(q.x_centroid) << ", "
           << coordinate(q.y_centroid) << "): " << q.n_contact << " elements, Fn = "
           << val(q.Fn, Quantity::force) << ", Fx = " << val(q.Fx, Quantity::force)
           << ", Fy = " << val(q.Fy, Quantity::force) << ", Mz = " << val(q.Mz, Quantity::moment)
           << ", p_max = " << val(q.p_max, Quantity::stress) << "\n";
    }
}

} // namespace

void reject_gap_options(const ParsedOptions& opts)
{
    for (const char* name : {"approach", "normal-method"})
        if (opts.has(name))
            throw usage_error(std::string("--") + name,
                              "only used with --gap (a contact of any shape from its gap)");
}

int command_solve_gap(const ParsedOptions& opts)
{
    reject_elliptic_options(opts);
    ContactSetup c = read_contact(opts, library_default_params(), library_default_grid(),
                                  SizeAndLoad::gap);
    const std::string file = opts.text("gap", "");
    GapFile g = read_gap_file(file);
    cw_params& p = c.params;
    p.model = opts.text("model", "exact") == "fastsim" ? CW_MODEL_FASTSIM : CW_MODEL_EXACT;
    p.gap = g.h.data();
    p.gap_len = g.h.size();
    if (opts.has("approach")) {
        p.normal_load = CW_NORMAL_APPROACH;
        p.approach = c.units.to_si(Quantity::length, opts.number("approach", 0.0));
    }
    if (opts.text("normal-method", "exact") == "semi_hertz") p.normal_method = CW_NORMAL_SEMI_HERTZ;
    for (const std::string& w : plausibility_warnings(g.grid, p, OptionSource(opts), file))
        c.notes.push_back("warning: " + w);
    const SurfaceRequest surface = read_surface_request(opts, p.rolling_direction, p.V);
    const std::string out = opts.text("out", "");
    if (!out.empty()) check_output_target(out, "--out", opts.has("force"));

    ContactSolver solver(g.grid);
    Solution s;
    const SurfaceOutput post = solve_with_surface(solver, p, surface, s);
    const std::vector<cw_patch> patches = solver.patches();
    print_notes(c);
    for (const std::string& w : surface.warnings) std::fprintf(stderr, "creepwork: %s\n", w.c_str());
    JsonObject json = gap_json(s, patches, file, c.units);
    add_surface_json(json, post);
    double J[CW_JACOBIAN_LEN] = {};
    const bool jacobian = opts.has("jacobian");
    if (jacobian) {
        solver.jacobian(p, J);
        json.object("jacobian", jacobian_json(J))
            .text("jacobian_units",
                  "SI whatever --units: rows Fx [N], Fy [N], Mz [N m], W_macro [J/m] per "
                  "xi_x [-], xi_y [-], phi [1/m], N [N] (d/dN along the solution, also with "
                  "--approach)");
    }
    if (!out.empty()) {
        const bool plots = should_plot(opts, static_cast<long>(s.size()));
        StagedOutput dir(out, "--out", opts.has("force"));
        write_fields_csv(dir.path("fields.csv"), s, c.units);
        write_profile_csv(dir.path("profile.csv"), s, c.units);
        write_json_file(dir.path("result.json"), json);
        // The run's text, JSON and CSV give the forces on the wheel.
        if (plots)
            write_gap_pictures(dir.path(), s, g.h, patches, file, c.units,
                               read_plot_style(opts, ForceSign::wheel));
        if (plots && (post.temperature || post.damage))
            write_surface_pictures(dir.path(), s, post, c.units);
        dir.commit();
    }
    if (opts.text("format", "text") == "json")
        std::cout << json.str(true) << "\n";
    else {
        print_gap_text(std::cout, s, patches, file, c.units);
        print_surface_text(std::cout, post);
        if (jacobian) print_jacobian_text(std::cout, J);
    }
    return kExitOk;
}

} // namespace cwcli
