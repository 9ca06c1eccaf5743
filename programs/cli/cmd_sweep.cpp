// creepwork sweep: the slip/adhesion maps of the paper's Figs. 2-5.
#include <cstdio>
#include <fstream>
#include <iostream>

#include "cli_error.hpp"
#include "command_common.hpp"
#include "commands.hpp"
#include "contact_options.hpp"
#include "contact_solver.hpp"
#include "json.hpp"
#include "output_dir.hpp"
#include "progress.hpp"
#include "report.hpp"
#include "sweep_plots.hpp"
#include "sweep_series.hpp"

namespace cwcli {

namespace {

// The paper's Fig. 6 contact as fit-fig6 reproduces it (a/b = 2 as in
// Figs. 2-5), on a finer grid so the zone boundaries are visible.
void fig6_contact(cw_params& p, cw_grid& g)
{
    p = library_default_params();
    p.a = 6.6323e-3;
    p.b = p.a / 2.0;
    p.normal_force = 10000.0 * kNewtonPerLbf;
    p.mu = 0.6;
    p.G = 82e9;
    p.nu = 0.3;
    g = library_default_grid();
    g.nx = 40;
    g.ny = 40;
}

PatchGeometry geometry_of(const Solution& s)
{
    PatchGeometry g;
    const double half_y = (s.grid.kind == CW_GRID_UNIFORM ? s.grid.box_scale : 1.0) / s.ny;
    for (size_t k = 0; k < s.size(); ++k) {
        g.X.push_back(s.x[k] / s.result.a);
        g.Y.push_back(s.y[k] / s.result.b);
        g.half_x.push_back(s.area[k] / (4.0 * s.result.a * s.result.b * half_y));
        g.half_y.push_back(half_y);
        // Area 0 outside the contact; the state says so too.
        g.inside.push_back(s.area[k] > 0.0 && s.state[k] != CW_STATE_EXTERIOR);
    }
    return g;
}

void write_cases_csv(const std::string& path, const std::vector<SweepFigure>& figs,
                     const std::vector<std::vector<SweepPanel>>& panels, const Units& u)
{
    std::ofstream f(path);
    f << "figure,panel,xi_x,xi_y,spin,Fx,Fy,Mz,adhesion_fraction,n_slip,n_contact\n";
    for (size_t k = 0; k < figs.size(); ++k)
        for (size_t p = 0; p < panels[k].size(); ++p) {
            const SweepPanel& s = panels[k][p];
            const double values[] = {s.c.xi_x,
                                     s.c.xi_y,
                                     u.from_si(Quantity::spin, s.c.phi),
                                     u.from_si(Quantity::force, s.result.Fx),
                                     u.from_si(Quantity::force, s.result.Fy),
                                     u.from_si(Quantity::moment, s.result.Mz),
                                     s.result.adhesion_fraction};
            f << figs[k].name << "," << p;
            for (double v : values) f << "," << shortest_exact(v);
            f << "," << s.result.n_slip << "," << s.result.n_contact << "\n";
        }
    f.close();
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
}

} // namespace

int command_sweep(int argc, char** argv, int first)
{
    const auto specs =
        join(join(join(join(material_and_load_options(), model_options()), grid_options()),
                  output_options()),
             progress_option_specs());
    ParsedOptions opts;
    if (parse_or_help(specs, argc, argv, first, usage_sweep(), opts)) return kExitOk;
    cw_params defaults;
    cw_grid default_grid;
    fig6_contact(defaults, default_grid);
    const ContactSetup c = read_contact(opts, defaults, default_grid);
    const std::string out = opts.text("out", "");
    if (out.empty()) throw usage_error("--out", "missing: sweep writes its maps to a directory");
    check_output_target(out, "--out", opts.has("force"));
    const ProgressSchedule schedule = interactive_schedule(read_progress_options(opts));

    ContactSolver solver(c.grid);
    // One full solve at zero creepage gives the flexibilities and the grid geometry.
    const Solution base = solver.solve_full(c.params);
    print_notes(c);
    const Saturation sat = saturation_creepages(c.params, base.result);
    const std::vector<SweepFigure> figs = paper_sweep_figures(sat);
    std::vector<std::vector<SweepPanel>> panels(figs.size());
    size_t total = 0, done = 0;
    for (const SweepFigure& f : figs) total += f.cases.size();
    Progress progress("sweep", "maps", total, schedule);
    for (size_t k = 0; k < figs.size(); ++k)
        for (const SweepCase& sc : figs[k].cases) {
            cw_params p = c.params;
            p.xi_x = sc.xi_x;
            p.xi_y = sc.xi_y;
            p.phi = sc.phi;
            SweepPanel panel{sc, {}, {}};
            panel.result = solver.solve_states(p, panel.state);
            panels[k].push_back(std::move(panel));
            progress.update(++done);
        }

    const Units& u = c.units;
    {
        const bool plots = should_plot(opts, static_cast<long>(base.size()));
        StagedOutput dir(out, "--out", opts.has("force"));
        write_cases_csv(dir.path("cases.csv"), figs, panels, u);
        if (plots) {
            const std::string caption =
                "a/b = " + fmt(base.result.a / base.result.b, 3) +
                ", a = " + fmt(u.from_si(Quantity::length, base.result.a), 4) + " " +
                u.label(Quantity::length) + ", μ = " + fmt(c.params.mu, 3) +
                "; ξ_c = " + fmt(sat.xi_c, 3) + ", η_c = " + fmt(sat.eta_c, 3) +
                ", φ_c = " + fmt(u.from_si(Quantity::spin, sat.phi_c), 3) + " " +
                u.label(Quantity::spin);
            write_sweep_pictures(dir.path(), figs, panels, geometry_of(base),
                                 c.params.rolling_direction, caption, u);
        }
        dir.commit();
    }

    if (opts.text("format", "text") == "json") {
        std::vector<JsonObject> cases;
        for (size_t k = 0; k < figs.size(); ++k)
            for (const SweepPanel& s : panels[k])
                cases.push_back(JsonObject()
                                    .text("figure", figs[k].name)
                                    .number("xi_x", s.c.xi_x)
                                    .number("xi_y", s.c.xi_y)
                                    .number("spin", u.from_si(Quantity::spin, s.c.phi))
                                    .number("Fx", u.from_si(Quantity::force, s.result.Fx))
                                    .number("Fy", u.from_si(Quantity::force, s.result.Fy))
                                    .number("Mz", u.from_si(Quantity::moment, s.result.Mz))
                                    .number("adhesion_fraction", s.result.adhesion_fraction));
        std::cout << JsonObject()
                         .text("units", u.name())
                         .number("xi_c", sat.xi_c)
                         .number("eta_c", sat.eta_c)
                         .number("phi_c", u.from_si(Quantity::spin, sat.phi_c))
                         .array("cases", cases)
                         .str(true)
                  << "\n";
        return kExitOk;
    }
    std::cout << "saturation creepages: xi_c = " << fmt(sat.xi_c, 4)
              << ", eta_c = " << fmt(sat.eta_c, 4)
              << ", phi_c = " << fmt(u.from_si(Quantity::spin, sat.phi_c), 4) << " "
              << u.label(Quantity::spin) << "\n";
    std::printf("%-6s %12s %12s %12s %9s\n", "figure", "xi_x", "xi_y", "spin", "adhesion");
    for (size_t k = 0; k < figs.size(); ++k)
        for (const SweepPanel& s : panels[k])
            std::printf("%-6s %12.4g %12.4g %12.4g %7.1f %%\n", figs[k].name.c_str(), s.c.xi_x,
                        s.c.xi_y, u.from_si(Quantity::spin, s.c.phi),
                        100 * s.result.adhesion_fraction);
    std::printf("maps: %s/fig2.png .. fig5.png, table: %s/cases.csv\n", out.c_str(), out.c_str());
    return kExitOk;
}

} // namespace cwcli
