// creepwork compare: one contact solved with FASTSIM and with Kalker's exact
// theory on the same uniform grid; both models' totals, how far FASTSIM's
// work distribution is from the exact one (compare_metrics.hpp), and the
// pictures side by side (compare_plots.hpp).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli_error.hpp"
#include "command_common.hpp"
#include "commands.hpp"
#include "compare_metrics.hpp"
#include "compare_plots.hpp"
#include "contact_options.hpp"
#include "contact_solver.hpp"
#include "csv_output.hpp"
#include "json.hpp"
#include "output_dir.hpp"
#include "patch_plots.hpp"
#include "report.hpp"
#include "units.hpp"

namespace cwcli {

namespace {

// The paper's Fig. 6 contact as fit-fig6 reproduces it (a = 6.6323 mm,
// b = a/2, N = 10000 lbf, mu = 0.6, G = 82 GPa, nu = 0.3; xi_x = 0.0019,
// xi_y = 0.0011, spin = 0.144 1/ft) on CONTACT's layout with 40 elements
// across the ellipse: 48 x 48 over 1.2 times the semi-axes.
void compare_default_contact(cw_params& p, cw_grid& g)
{
    p = library_default_params();
    p.model = CW_MODEL_EXACT; // read_contact then applies the exact model's rules
    p.a = 6.6323e-3;
    p.b = p.a / 2.0;
    p.normal_force = 10000.0 * kNewtonPerLbf;
    p.mu = 0.6;
    p.G = 82e9;
    p.nu = 0.3;
    p.xi_x = 0.0019;
    p.xi_y = 0.0011;
    p.phi = 0.144 / kMetrePerFoot;
    g = library_default_grid();
    g.kind = CW_GRID_UNIFORM;
    g.nx = 48;
    g.ny = 48;
    g.box_scale = kExactBoxScale;
}

JsonObject metrics_json(const WorkComparison& m)
{
    JsonObject j;
    j.number("map_l1_consistent", m.map_l1_consistent)
        .number("map_l1_paper", m.map_l1_paper)
        .number("profile_l1", m.profile_l1)
        .number("exact_power_in_fastsim_adhesion", m.exact_power_in_fastsim_adhesion)
        .number("fastsim_work_in_exact_adhesion", m.fastsim_work_in_exact_adhesion)
        .integer("state_differences", m.state_differences)
        .number("centroid_fastsim", m.centroid_fastsim)
        .number("centroid_exact", m.centroid_exact);
    return j;
}

void write_compare_file(const std::string& path, const std::string& text)
{
    std::ofstream f(path);
    f << text;
    f.close();
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
}

// One row per model; every column names its unit.
std::string totals_csv(const Solution& f, const Solution& e, const Units& u)
{
    using Q = Quantity;
    std::string out = "model,Fx_wheel_" + u.csv_suffix(Q::force) + ",Fy_wheel_" +
                      u.csv_suffix(Q::force) + ",Mz_wheel_" + u.csv_suffix(Q::moment) +
                      ",W_macro_" + u.csv_suffix(Q::work) + ",W_micro_paper_" +
                      u.csv_suffix(Q::work) + ",K,adhesion_fraction,n_contact,n_adhesion,n_slip," +
                      "p_max_" + u.csv_suffix(Q::stress) + "\n";
    for (const Solution* s : {&f, &e}) {
        const cw_result& r = s->result;
        out += model_name(r.model);
        for (double v : {u.from_si(Q::force, r.Fx), u.from_si(Q::force, r.Fy),
                         u.from_si(Q::moment, r.Mz), u.from_si(Q::work, r.W_macro),
                         u.from_si(Q::work, r.W_micro_paper), r.K, r.adhesion_fraction})
            out += "," + shortest_exact(v);
        out += "," + std::to_string(r.n_contact) + "," + std::to_string(r.n_adhesion) + "," +
               std::to_string(r.n_slip) + "," + shortest_exact(u.from_si(Q::stress, r.p_max)) +
               "\n";
    }
    return out;
}

std::string shown_metric(double v, int digits = 4)
{
    return std::isfinite(v) ? fmt(v, digits) : std::string("undefined");
}

void print_text(std::ostream& os, const Solution& f, const Solution& e, const WorkComparison& m,
                const Units& u)
{
    using Q = Quantity;
    const auto val = [&u](double si, Q q) { return u.from_si(q, si); };
    char line[200];
    os << "one contact, two models on the same uniform grid " << f.nx << " x " << f.ny
       << " (box " << fmt(f.grid.box_scale, 4) << " a x " << fmt(f.grid.box_scale, 4)
       << " b); forces on the wheel\n";
    std::snprintf(line, sizeof line, "  %-26s %14s %14s %16s\n", "", "FASTSIM", "exact",
                  "FASTSIM/exact-1");
    os << line;
    const struct {
        const char* name;
        double fv, ev;
        std::string unit;
    } rows[] = {
        {"Fx", val(f.result.Fx, Q::force), val(e.result.Fx, Q::force), u.label(Q::force)},
        {"Fy", val(f.result.Fy, Q::force), val(e.result.Fy, Q::force), u.label(Q::force)},
        {"Mz", val(f.result.Mz, Q::moment), val(e.result.Mz, Q::moment), u.label(Q::moment)},
        {"W_macro", val(f.result.W_macro, Q::work), val(e.result.W_macro, Q::work),
         u.label(Q::work)},
        {"W_micro_paper", val(f.result.W_micro_paper, Q::work),
         val(e.result.W_micro_paper, Q::work), u.label(Q::work)},
        {"K", f.result.K, e.result.K, ""},
        {"adhesion_fraction", f.result.adhesion_fraction, e.result.adhesion_fraction, ""},
    };
    for (const auto& r : rows) {
        const std::string name = r.unit.empty() ? r.name : std::string(r.name) + " [" + r.unit + "]";
        const double rel = r.ev != 0.0 ? r.fv / r.ev - 1.0 : NAN;
        std::snprintf(line, sizeof line, "  %-26s %14.6g %14.6g %+14.1f %%\n", name.c_str(), r.fv,
                      r.ev, 100.0 * rel);
        os << line;
    }
    os << "work distribution (each map scaled to unit total; 0 = same shape, 2 = disjoint):\n";
    const auto metric = [&os](const char* what, const std::string& value) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "  %-58s %s\n", what, value.c_str());
        os << buf;
    };
    metric("L1 distance of the energy-consistent work maps", shown_metric(m.map_l1_consistent));
    metric("L1 distance of FASTSIM's eq. 36 map and the exact D_I", shown_metric(m.map_l1_paper));
    metric("L1 distance of the lateral work profiles", shown_metric(m.profile_l1));
    metric("exact dissipation in elements FASTSIM calls adhesion",
           shown_metric(100.0 * m.exact_power_in_fastsim_adhesion, 3) + " %");
    metric("FASTSIM work in elements the exact theory calls adhesion",
           shown_metric(100.0 * m.fastsim_work_in_exact_adhesion, 3) + " %");
    metric("elements in contact for both whose states differ",
           std::to_string(m.state_differences) + " of " + std::to_string(e.result.n_contact));
    metric("work centroid along rolling, x/a (+1 leading edge)",
           "FASTSIM " + shown_metric(m.centroid_fastsim, 3) + ", exact " +
               shown_metric(m.centroid_exact, 3));
}

} // namespace

int command_compare(int argc, char** argv, int first)
{
    const auto specs =
        join(join(join(join(material_and_load_options(), creepage_options()), grid_options()),
                  {{"tolerance", OptionKind::number, {}},
                   {"max-iterations", OptionKind::integer, {}}}),
             output_options());
    ParsedOptions opts;
    if (parse_or_help(specs, argc, argv, first, usage_compare(), opts)) return kExitOk;
    cw_params defaults;
    cw_grid default_grid;
    compare_default_contact(defaults, default_grid);
    // Read as exact-model inputs: the uniform grid, G and nu are required.
    const ContactSetup c = read_contact(opts, defaults, default_grid);
    const std::string out = opts.text("out", "");
    if (!out.empty()) check_output_target(out, "--out", opts.has("force"));

    cw_params fastsim = c.params;
    fastsim.model = CW_MODEL_FASTSIM;
    fastsim.tolerance = 0.0;
    fastsim.max_iterations = 0;
    ContactSolver solver(c.grid);
    const Solution f = solver.solve_full(fastsim);
    const Solution e = solver.solve_full(c.params);
    print_notes(c);
    const WorkComparison m = compare_work(f, e);
    const Units& u = c.units;
    const JsonObject json = JsonObject()
                                .text("units", u.name())
                                .object("fastsim", result_json(f.result, f.params, f.grid, u))
                                .object("exact", result_json(e.result, e.params, e.grid, u))
                                .object("metrics", metrics_json(m));

    if (!out.empty()) {
        const bool plots = should_plot(opts, static_cast<long>(f.size()));
        StagedOutput dir(out, "--out", opts.has("force"));
        write_compare_file(dir.path("summary.json"), json.str(true) + "\n");
        write_compare_file(dir.path("totals.csv"), totals_csv(f, e, u));
        for (const Solution* s : {&f, &e}) {
            const std::string sub = dir.path(model_name(s->result.model));
            std::filesystem::create_directories(sub);
            write_fields_csv(sub + "/fields.csv", *s, u);
            write_profile_csv(sub + "/profile.csv", *s, u);
        }
        if (plots)
            write_compare_pictures(dir.path(), f, e, m, u, describe_case(e, u),
                                   read_plot_style(opts, ForceSign::wheel));
        dir.commit();
    }
    if (opts.text("format", "text") == "json")
        std::cout << json.str(true) << "\n";
    else
        print_text(std::cout, f, e, m, u);
    return kExitOk;
}

} // namespace cwcli
