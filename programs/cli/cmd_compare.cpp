// creepwork compare: one contact solved with a simplified model (FASTSIM by
// default; --simplified picks FASTSIM elliptic, the calibrated model, or all
// three) and with Kalker's exact theory on the same uniform grid; the
// models' totals, how far each simplified model's work distribution is from
// the exact one (compare_metrics.hpp), and the pictures side by side
// (compare_plots.hpp; with all three, work_maps_plot.hpp).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iostream>
#include <vector>

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
#include "work_maps_plot.hpp"

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
    g.box_scale = model_default_grid(CW_MODEL_EXACT).box_scale;
}

// "contact: a = ..., b = ...": the contact solved, in --units, and where
// its values come from when options leave some out.
std::string contact_line(const ParsedOptions& o, const ContactSetup& c)
{
    const OptionSource names(o);
    const cw_params& p = c.params;
    std::string line = "contact: ";
    const auto add = [&](Input in, double si, const char* separator) {
        line += std::string(info(in).column) + " = " + value_text(names, in, si) + separator;
    };
    add(Input::a, p.a, ", ");
    add(Input::b, p.b, ", ");
    add(Input::N, p.normal_force, ", ");
    add(Input::mu, p.mu, ", ");
    add(Input::G, p.G, ", ");
    add(Input::nu, p.nu, "; ");
    add(Input::xi_x, p.xi_x, ", ");
    add(Input::xi_y, p.xi_y, ", ");
    line += "spin = " + value_text(names, Input::phi, p.phi);
    int given = 0;
    const Input contact[] = {Input::a,  Input::b,    Input::N,    Input::mu,  Input::G,
                             Input::nu, Input::xi_x, Input::xi_y, Input::phi};
    for (Input in : contact) given += names.has(in);
    if (given == 0) line += " (the paper's Fig. 6 contact, compare's default)";
    else if (given < 9) line += " (options not given take the paper's Fig. 6 values)";
    return line;
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

// One row per model, named by its label; every column names its unit.
std::string totals_csv(const std::vector<const Solution*>& models,
                       const std::vector<std::string>& labels, const Units& u)
{
    using Q = Quantity;
    std::string out = "model,Fx_wheel_" + u.csv_suffix(Q::force) + ",Fy_wheel_" +
                      u.csv_suffix(Q::force) + ",Mz_wheel_" + u.csv_suffix(Q::moment) +
                      ",W_macro_" + u.csv_suffix(Q::work) + ",W_micro_paper_" +
                      u.csv_suffix(Q::work) + ",K,adhesion_fraction,n_contact,n_adhesion,n_slip," +
                      "p_max_" + u.csv_suffix(Q::stress) + "\n";
    for (size_t k = 0; k < models.size(); ++k) {
        const cw_result& r = models[k]->result;
        out += labels[k];
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

// The simplified models compare solves, in the order of --simplified all.
struct Simplified {
    const char* option;  // --simplified value
    const char* label;   // JSON key, totals.csv row and sub-directory
    const char* display; // in text and pictures
    int model, pressure;
};

const Simplified kSimplified[] = {
    {"fastsim", "fastsim", "FASTSIM", CW_MODEL_FASTSIM, CW_PRESSURE_PARABOLIC},
    {"fastsim-elliptic", "fastsim_elliptic", "FASTSIM elliptic", CW_MODEL_FASTSIM,
     CW_PRESSURE_ELLIPTIC},
    {"calibrated", "calibrated", "calibrated", CW_MODEL_CALIBRATED, CW_PRESSURE_PARABOLIC},
};

std::vector<Simplified> chosen_simplified(const std::string& option)
{
    std::vector<Simplified> out;
    for (const Simplified& s : kSimplified)
        if (option == "all" || option == s.option) out.push_back(s);
    // Beside the elliptic variant, plain FASTSIM is named by its bound.
    if (option == "all") out.front().display = "FASTSIM parabolic";
    return out;
}

// One column per simplified model, then exact, then each simplified model
// relative to exact; with FASTSIM alone the table compare always printed.
void print_text(std::ostream& os, const std::string& contact, const std::vector<Simplified>& names,
                const std::vector<Solution>& sims, const Solution& e,
                const std::vector<WorkComparison>& ms, const Units& u)
{
    os << contact << "\n";
    using Q = Quantity;
    const auto val = [&u](double si, Q q) { return u.from_si(q, si); };
    char cell[64];
    const Solution& f = sims.front();
    os << "one contact, " << (sims.size() + 1) << " models on the same uniform grid " << f.nx
       << " x " << f.ny << " (box " << fmt(f.grid.box_scale, 4) << " a x "
       << fmt(f.grid.box_scale, 4) << " b); forces on the wheel\n";
    std::snprintf(cell, sizeof cell, "  %-26s", "");
    os << cell;
    for (const Simplified& n : names) {
        std::snprintf(cell, sizeof cell, " %16s", n.display);
        os << cell;
    }
    std::snprintf(cell, sizeof cell, " %14s", "exact");
    os << cell;
    for (const Simplified& n : names) {
        std::snprintf(cell, sizeof cell, " %18s", (std::string(n.display) + "/exact-1").c_str());
        os << cell;
    }
    os << "\n";
    const struct {
        const char* name;
        Q quantity;
        bool has_unit;
        double cw_result::*field;
    } rows[] = {
        {"Fx", Q::force, true, &cw_result::Fx},
        {"Fy", Q::force, true, &cw_result::Fy},
        {"Mz", Q::moment, true, &cw_result::Mz},
        {"W_macro", Q::work, true, &cw_result::W_macro},
        {"W_micro_paper", Q::work, true, &cw_result::W_micro_paper},
        {"K", Q::force, false, &cw_result::K},
        {"adhesion_fraction", Q::force, false, &cw_result::adhesion_fraction},
    };
    for (const auto& r : rows) {
        const auto shown = [&](const Solution& s) {
            return r.has_unit ? val(s.result.*r.field, r.quantity) : s.result.*r.field;
        };
        const std::string name =
            r.has_unit ? std::string(r.name) + " [" + u.label(r.quantity) + "]" : r.name;
        std::snprintf(cell, sizeof cell, "  %-26s", name.c_str());
        os << cell;
        for (const Solution& s : sims) {
            std::snprintf(cell, sizeof cell, " %16.6g", shown(s));
            os << cell;
        }
        const double ev = shown(e);
        std::snprintf(cell, sizeof cell, " %14.6g", ev);
        os << cell;
        for (const Solution& s : sims) {
            const double rel = ev != 0.0 ? shown(s) / ev - 1.0 : NAN;
            std::snprintf(cell, sizeof cell, " %+16.1f %%", 100.0 * rel);
            os << cell;
        }
        os << "\n";
    }
    os << "work distribution (each map scaled to unit total; 0 = same shape, 2 = disjoint):\n";
    // One line per metric; "@S" in its text names the simplified model.
    const bool one = names.size() == 1;
    const auto metric = [&](std::string what, const std::function<std::string(size_t)>& value) {
        const std::string who = one ? names[0].display : "the model";
        for (size_t at; (at = what.find("@S")) != std::string::npos;) what.replace(at, 2, who);
        std::string values;
        for (size_t k = 0; k < names.size(); ++k)
            values += (k ? "; " : "") + (one ? "" : std::string(names[k].display) + " ") + value(k);
        char line[200];
        std::snprintf(line, sizeof line, "  %-58s ", what.c_str());
        os << line << values << "\n";
    };
    metric("L1 distance of the energy-consistent work maps",
           [&](size_t k) { return shown_metric(ms[k].map_l1_consistent); });
    metric("L1 distance of @S's eq. 36 map and the exact D_I",
           [&](size_t k) { return shown_metric(ms[k].map_l1_paper); });
    metric("L1 distance of the lateral work profiles",
           [&](size_t k) { return shown_metric(ms[k].profile_l1); });
    metric("exact dissipation in elements @S calls adhesion", [&](size_t k) {
        return shown_metric(100.0 * ms[k].exact_power_in_fastsim_adhesion, 3) + " %";
    });
    metric("@S's work in elements exact calls adhesion", [&](size_t k) {
        return shown_metric(100.0 * ms[k].fastsim_work_in_exact_adhesion, 3) + " %";
    });
    metric("elements in contact for both whose states differ", [&](size_t k) {
        return std::to_string(ms[k].state_differences) + " of " +
               std::to_string(e.result.n_contact);
    });
    std::string centroids;
    for (size_t k = 0; k < names.size(); ++k)
        centroids += (k ? "; " : "") + std::string(names[k].display) + " " +
                     shown_metric(ms[k].centroid_fastsim, 3);
    char line[200];
    std::snprintf(line, sizeof line, "  %-58s ", "work centroid along rolling, x/a (+1 leading edge)");
    os << line << centroids << ", exact " << shown_metric(ms[0].centroid_exact, 3) << "\n";
}

// --format markdown: one table row per simplified model with its distances
// and ratios to exact (the tables of doc/validation/fastsim-vs-exact.md);
// the grid is named by the elements across the ellipse.
void print_markdown(std::ostream& os, const std::vector<Simplified>& names,
                    const std::vector<Solution>& sims, const Solution& e,
                    const std::vector<WorkComparison>& ms)
{
    os << "| model | elements across | L1 work maps (energy-consistent) | L1 eq. 36 map vs "
          "exact D_I | L1 lateral profiles | exact dissipation in the model's adhesion | "
          "model's work in exact adhesion | Mz model / exact - 1 | W_macro model / exact - 1 | "
          "adhesion model / exact |\n|---|---|---|---|---|---|---|---|---|---|\n";
    const auto metric = [](double v) {
        char b[32];
        std::snprintf(b, sizeof b, "%.3f", v);
        return std::isfinite(v) ? std::string(b) : std::string("-");
    };
    // Shares of 1 % and more to 0.1 %, smaller ones to two digits.
    const auto share = [](double v) {
        char b[32];
        std::snprintf(b, sizeof b, std::fabs(v) >= 0.01 ? "%.1f %%" : "%.2g %%", 100.0 * v);
        return std::isfinite(v) ? std::string(b) : std::string("-");
    };
    const auto ratio = [](double m, double x) {
        char b[32];
        std::snprintf(b, sizeof b, "%+.1f %%", 100.0 * (m / x - 1.0));
        return x != 0.0 ? std::string(b) : std::string("-");
    };
    for (size_t k = 0; k < sims.size(); ++k) {
        const cw_result& r = sims[k].result;
        char across[32], adhesion[64];
        std::snprintf(across, sizeof across, "%.0f", e.nx / e.grid.box_scale);
        std::snprintf(adhesion, sizeof adhesion, "%.1f %% / %.1f %%",
                      100.0 * r.adhesion_fraction, 100.0 * e.result.adhesion_fraction);
        os << "| " << names[k].display << " | " << across << " | "
           << metric(ms[k].map_l1_consistent) << " | " << metric(ms[k].map_l1_paper) << " | "
           << metric(ms[k].profile_l1) << " | " << share(ms[k].exact_power_in_fastsim_adhesion)
           << " | " << share(ms[k].fastsim_work_in_exact_adhesion) << " | "
           << ratio(r.Mz, e.result.Mz) << " | " << ratio(r.W_macro, e.result.W_macro) << " | "
           << adhesion << " |\n";
    }
}

} // namespace

int command_compare(int argc, char** argv, int first)
{
    const auto specs =
        join(join(join(join(material_and_load_options(), creepage_options()), grid_options()),
                  {{"tolerance", OptionKind::number, {}},
                   {"max-iterations", OptionKind::integer, {}},
                   {"simplified", OptionKind::choice,
                    {"fastsim", "fastsim-elliptic", "calibrated", "all"}}}),
             output_options_with_markdown());
    ParsedOptions opts;
    if (parse_or_help(specs, argc, argv, first, usage_compare(), opts)) return kExitOk;
    cw_params defaults;
    cw_grid default_grid;
    compare_default_contact(defaults, default_grid);
    // Read as exact-model inputs: the uniform grid, G and nu are required.
    const ContactSetup c = read_contact(opts, defaults, default_grid);
    const std::string out = opts.text("out", "");
    if (!out.empty()) check_output_target(out, "--out", opts.has("force"));

    const std::vector<Simplified> names = chosen_simplified(opts.text("simplified", "fastsim"));
    ContactSolver solver(c.grid);
    std::vector<Solution> sims;
    for (const Simplified& n : names) {
        cw_params p = c.params;
        p.model = n.model;
        p.pressure = n.pressure;
        p.tolerance = 0.0;
        p.max_iterations = 0;
        sims.push_back(solver.solve_full(p));
    }
    const Solution e = solver.solve_full(c.params);
    print_notes(c);
    std::vector<WorkComparison> ms;
    for (const Solution& s : sims) ms.push_back(compare_work(s, e));
    const Units& u = c.units;
    JsonObject json;
    json.text("units", u.name());
    for (size_t k = 0; k < sims.size(); ++k)
        json.object(names[k].label,
                    result_json(sims[k].result, sims[k].params, sims[k].grid, u));
    json.object("exact", result_json(e.result, e.params, e.grid, u));
    if (names.size() == 1)
        json.object("metrics", metrics_json(ms[0]));
    else {
        JsonObject by_model;
        for (size_t k = 0; k < ms.size(); ++k) by_model.object(names[k].label, metrics_json(ms[k]));
        json.object("metrics", by_model);
    }

    if (!out.empty()) {
        const bool plots = should_plot(opts, static_cast<long>(e.size()));
        StagedOutput dir(out, "--out", opts.has("force"));
        write_compare_file(dir.path("summary.json"), json.str(true) + "\n");
        std::vector<const Solution*> all;
        std::vector<std::string> labels;
        for (size_t k = 0; k < sims.size(); ++k) {
            all.push_back(&sims[k]);
            labels.push_back(names[k].label);
        }
        all.push_back(&e);
        labels.push_back("exact");
        write_compare_file(dir.path("totals.csv"), totals_csv(all, labels, u));
        for (size_t k = 0; k < all.size(); ++k) {
            const std::string sub = dir.path(labels[k]);
            std::filesystem::create_directories(sub);
            write_fields_csv(sub + "/fields.csv", *all[k], u);
            write_profile_csv(sub + "/profile.csv", *all[k], u);
        }
        const PlotStyle style = read_plot_style(opts, ForceSign::wheel);
        if (plots && names.size() == 1)
            write_compare_pictures(dir.path(), sims[0], e, ms[0], u, describe_case(e, u), style,
                                   names[0].display, names[0].label);
        else if (plots) {
            std::vector<MapPanel> panels;
            for (size_t k = 0; k < sims.size(); ++k)
                panels.push_back({names[k].display, &sims[k], ms[k].map_l1_consistent});
            panels.push_back({"exact", &e, NAN}); // the reference: no distance to show
            write_work_maps_picture(dir.path(), panels, u, describe_case(e, u));
        }
        dir.commit();
    }
    if (opts.text("format", "text") == "json")
        std::cout << json.str(true) << "\n";
    else if (opts.text("format", "text") == "markdown")
        print_markdown(std::cout, names, sims, e, ms);
    else
        print_text(std::cout, contact_line(opts, c), names, sims, e, ms, u);
    return kExitOk;
}

} // namespace cwcli
