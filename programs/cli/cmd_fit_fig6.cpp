// creepwork fit-fig6: the paper's Figs. 6 and 7 reproduced. The paper gives
// neither the semi-axes nor the material, so a is fitted to the printed
// forces (paper_cases.hpp explains the choices); the comparison with every
// printed number is printed and the pictures are written.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli_error.hpp"
#include "command_common.hpp"
#include "commands.hpp"
#include "contact_options.hpp"
#include "csv_output.hpp"
#include "output_dir.hpp"
#include "paper_cases.hpp"
#include "patch_plots.hpp"
#include "report.hpp"
#include "units.hpp"

namespace cwcli {

namespace {

struct CaseRun {
    PaperCase paper;
    SemiAxisFit fit;
    Solution solution; // full solve at the chosen a
};

// The fit's material and grid: defaults documented in paper_cases.hpp,
// overridable to see how much the reproduction depends on them.
FitChoices read_choices(const ParsedOptions& o, const Units& u)
{
    FitChoices c;
    if (o.has("G")) c.G = u.to_si(Quantity::stress, o.number("G", 0.0));
    c.nu = o.number("nu", c.nu);
    c.nx = o.integer("nx", c.nx);
    c.ny = o.integer("ny", c.ny);
    if (!(c.G > 0.0)) throw usage_error("--G", "must be > 0");
    if (!(c.nu >= 0.0 && c.nu <= 0.5)) throw usage_error("--nu", "must lie in [0, 0.5]");
    const std::string range = "must lie in 1.." + std::to_string(CW_MAX_GRID_CELLS);
    if (c.nx < 1 || c.nx > CW_MAX_GRID_CELLS) throw usage_error("--nx", range);
    if (c.ny < 1 || c.ny > CW_MAX_GRID_CELLS) throw usage_error("--ny", range);
    return c;
}

CaseRun run_case(const PaperCase& paper, const FitChoices& choices, ContactSolver& solver)
{
    CaseRun run{paper, fit_semi_axis(paper, solver, choices), {}};
    run.solution = solver.solve_full(paper_params(paper, run.fit.best().a, choices));
    return run;
}

std::string pct(double ours, double printed)
{
    if (printed == 0.0) return "";
    const double diff = 100.0 * (ours - printed) / std::fabs(printed);
    if (std::fabs(diff) < 0.005) return "0"; // no "-0.00 %" for an exact fit
    char buf[32];
    std::snprintf(buf, sizeof buf, "%+.2f %%", diff);
    return buf;
}

// One line of the comparison: printed value, ours in the paper's units and
// in SI, relative difference. Values below 1e-9 of the scale are rounding
// noise of an exact zero (Fx of Fig. 7) and print as 0.
std::string row(const char* name, const char* printed, double ours_paper, const char* paper_unit,
                double ours_si, const char* si_unit, double printed_value, double scale)
{
    const auto clean = [scale](double v) { return std::fabs(v) < 1e-9 * scale ? 0.0 : v; };
    char buf[200];
    std::snprintf(buf, sizeof buf, "  %-15s %10s %12.3f %-10s %12.5g %-4s %s\n", name, printed,
                  clean(ours_paper), paper_unit, clean(ours_si), si_unit,
                  pct(ours_paper, printed_value).c_str());
    return buf;
}

std::string printed(double v, int decimals)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

void print_minima(std::ostream& os, const CaseRun& run)
{
    const double lbf = kNewtonPerLbf, ft = kMetrePerFoot;
    // Force on the rail in lbf; rounding noise of an exact zero prints as 0.
    const auto rail_lbf = [](double on_wheel) {
        return std::fabs(on_wheel) < 1e-9 * kNewtonPerLbf ? 0.0 : -on_wheel / kNewtonPerLbf;
    };
    os << "  least squares on the printed forces; local minima over a = 1..40 mm:\n";
    for (size_t k = 0; k < run.fit.candidates.size(); ++k) {
        const FitCandidate& c = run.fit.candidates[k];
        char buf[240];
        std::snprintf(
            buf, sizeof buf,
            "    a = %7.4f mm: Fx %7.1f, Fy %7.1f lbf (rms misfit %6.2f lbf), Mz %7.3f lbf ft, "
            "W_macro %6.3f, adhesion %3.0f %%%s\n",
            c.a * 1e3, rail_lbf(c.result.Fx), rail_lbf(c.result.Fy), c.rms_lbf,
            -c.result.Mz / (lbf * ft), c.result.W_macro / lbf, 100 * c.result.adhesion_fraction,
            k == run.fit.chosen ? "  <- chosen: closest to the printed Mz" : "");
        os << buf;
    }
}

void print_case(std::ostream& os, const CaseRun& run)
{
    const PaperCase& p = run.paper;
    const cw_result& r = run.solution.result;
    const double lbf = kNewtonPerLbf, ft = kMetrePerFoot, F = p.N_lbf;
    os << p.name << ": xi_x = " << p.xi_x << ", xi_y = " << p.xi_y << ", spin = " << p.spin_per_ft
       << " 1/ft, a/b = " << p.a_over_b << ", mu = " << p.mu << ", N = " << p.N_lbf << " lbf ("
       << p.slip << ")\n";
    print_minima(os, run);
    os << "  fitted a = " << fmt(r.a * 1e3, 6) << " mm = " << fmt(r.a / ft, 6)
       << " ft, b = " << fmt(r.b * 1e3, 6) << " mm = " << fmt(r.b / ft, 6) << " ft\n";
    os << "  on the rail (the paper's sign; the library, JSON and CSV give the wheel's):\n";
    char head[160];
    std::snprintf(head, sizeof head, "  %-15s %10s %12s %-10s %12s %-4s %s\n", "", "paper",
                  "creepwork", "", "creepwork", "", "diff");
    os << head;
    os << row("Fx", printed(p.Fx_lbf, 3).c_str(), -r.Fx / lbf, "lbf", -r.Fx, "N", p.Fx_lbf, F);
    os << row("Fy", printed(p.Fy_lbf, 3).c_str(), -r.Fy / lbf, "lbf", -r.Fy, "N", p.Fy_lbf, F);
    os << row("Mz", printed(p.Mz_lbf_ft, 3).c_str(), -r.Mz / (lbf * ft), "lbf ft", -r.Mz, "N m",
              p.Mz_lbf_ft, F);
    os << row("W_macro (Wd)", printed(p.Wd, 3).c_str(), r.W_macro / lbf, "lbf ft/ft", r.W_macro,
              "J/m", p.Wd, F);
    os << row("W_micro_paper", ("(" + printed(p.Wd / p.K, 3) + ")").c_str(), r.W_micro_paper / lbf,
              "lbf ft/ft", r.W_micro_paper, "J/m", p.Wd / p.K, F);
    os << row("K", printed(p.K, 3).c_str(), r.K, "", r.K, "", p.K, 1.0);
    os << row("W_consistent", "", r.W_consistent / lbf, "lbf ft/ft", r.W_consistent, "J/m", 0.0, F);
    os << "  adhesion " << fmt(100 * r.adhesion_fraction, 3) << " % (" << r.n_adhesion << " of "
       << r.n_contact << " elements); paper: " << p.slip << ". (W_micro_paper printed = Wd/K.)\n";
    os << "  printed Fx xi_x + Fy xi_y + Mz spin = "
       << printed(p.Fx_lbf * p.xi_x + p.Fy_lbf * p.xi_y + p.Mz_lbf_ft * p.spin_per_ft, 3)
       << " = printed Wd.\n"
       << "  The printed Mz is compared with our creep moment itself (sum of (x py - y px) dA, no\n"
          "  extra factor): the paper's Mz is the moment in lbf ft.\n";
}

JsonObject case_json(const CaseRun& run, const Units& u)
{
    const PaperCase& p = run.paper;
    JsonObject printed, j;
    printed.number("Fx_lbf", p.Fx_lbf)
        .number("Fy_lbf", p.Fy_lbf)
        .number("Mz_lbf_ft", p.Mz_lbf_ft)
        .number("Wd_lbf_ft_per_ft", p.Wd)
        .number("K", p.K)
        .text("slip", p.slip);
    std::vector<JsonObject> minima;
    for (const FitCandidate& c : run.fit.candidates)
        minima.push_back(JsonObject()
                             .number("a", u.from_si(Quantity::length, c.a))
                             .number("rms_misfit_lbf", c.rms_lbf)
                             .number("Fx", u.from_si(Quantity::force, c.result.Fx))
                             .number("Fy", u.from_si(Quantity::force, c.result.Fy))
                             .number("Mz", u.from_si(Quantity::moment, c.result.Mz))
                             .number("adhesion_fraction", c.result.adhesion_fraction));
    j.text("case", p.name)
        .object("paper_printed_on_rail", printed)
        .integer("chosen_minimum", static_cast<long>(run.fit.chosen))
        .array("minima", minima)
        .object("result",
                result_json(run.solution.result, run.solution.params, run.solution.grid, u));
    return j;
}

// The paper's Table 1 on the fitted contacts: row 5 on Fig. 7's, the others
// on Fig. 6's (paper_cases.hpp). K needs the paper's micro work: full solves.
struct Table1Result {
    Table1Row row;
    cw_result result;
};

std::vector<Table1Result> run_table1(const CaseRun& fig6, const CaseRun& fig7,
                                     const FitChoices& choices, ContactSolver& solver)
{
    std::vector<Table1Result> out;
    for (const Table1Row& row : paper_table1()) {
        const CaseRun& on = row.fig7_contact ? fig7 : fig6;
        PaperCase c = on.paper;
        c.xi_x = row.xi_x;
        c.xi_y = row.xi_y;
        c.spin_per_ft = row.spin_per_ft;
        out.push_back({row, solver.solve_full(paper_params(c, on.fit.best().a, choices)).result});
    }
    return out;
}

void print_table1(std::ostream& os, const std::vector<Table1Result>& table)
{
    os << "Table 1 (K = Wd / W_micro, eq. 39) on the fitted contacts (row 5 on Fig. 7's,\n"
          "the others on Fig. 6's: the paper does not say which contact they used):\n";
    char buf[200];
    std::snprintf(buf, sizeof buf, "  %6s %6s %6s | %6s %-12s | %9s %8s  %s\n", "xi_x", "xi_y",
                  "spin", "paper", "", "creepwork", "adhesion", "diff");
    os << buf;
    for (const Table1Result& t : table) {
        std::snprintf(buf, sizeof buf, "  %6.4g %6.4g %6.4g | %6.3f %-12s | %9.4f %7.1f %%  %s\n",
                      t.row.xi_x, t.row.xi_y, t.row.spin_per_ft, t.row.K, t.row.slip, t.result.K,
                      100 * t.result.adhesion_fraction, pct(t.result.K, t.row.K).c_str());
        os << buf;
    }
}

std::vector<JsonObject> table1_json(const std::vector<Table1Result>& table)
{
    std::vector<JsonObject> rows;
    for (const Table1Result& t : table)
        rows.push_back(JsonObject()
                           .number("xi_x", t.row.xi_x)
                           .number("xi_y", t.row.xi_y)
                           .number("spin_per_ft", t.row.spin_per_ft)
                           .number("K_paper", t.row.K)
                           .text("slip_paper", t.row.slip)
                           .text("contact", t.row.fig7_contact ? "fig7" : "fig6")
                           .number("K", t.result.K)
                           .number("adhesion_fraction", t.result.adhesion_fraction));
    return rows;
}

// The comparison as Markdown tables (--format markdown), the tables of the
// documentation's doc/validation/paper.md: forces on the rail in the
// paper's units, as the paper prints them.
void print_case_markdown(std::ostream& os, const CaseRun& run)
{
    const PaperCase& p = run.paper;
    const cw_result& r = run.solution.result;
    const double lbf = kNewtonPerLbf, ft = kMetrePerFoot;
    const auto clean = [&](double v) { return std::fabs(v) < 1e-9 * p.N_lbf ? 0.0 : v; };
    char buf[240];
    std::snprintf(buf, sizeof buf,
                  "| %s (xi_x %g, xi_y %g, spin %g 1/ft, a/b %g, mu %g, N %g lbf), a = %.3f mm "
                  "| paper | creepwork | diff |\n|---|---|---|---|\n",
                  p.name.c_str(), p.xi_x, p.xi_y, p.spin_per_ft, p.a_over_b, p.mu, p.N_lbf,
                  r.a * 1e3);
    os << buf;
    const auto line = [&](const char* name, double printed_value, double ours) {
        std::snprintf(buf, sizeof buf, "| %s | %.3f | %.3f | %s |\n", name, printed_value,
                      clean(ours), pct(clean(ours), printed_value).c_str());
        os << buf;
    };
    const bool fitted_x = p.Fx_lbf != 0.0;
    if (fitted_x) line("Fx on the rail [lbf] (fitted)", p.Fx_lbf, -r.Fx / lbf);
    line("Fy on the rail [lbf] (fitted)", p.Fy_lbf, -r.Fy / lbf);
    line("Mz on the rail [lbf ft]", p.Mz_lbf_ft, -r.Mz / (lbf * ft));
    line("Wd = W_macro [lbf ft per ft]", p.Wd, r.W_macro / lbf);
    std::snprintf(buf, sizeof buf, "| K | %.3f | %.3f | %s |\n", p.K, r.K, pct(r.K, p.K).c_str());
    os << buf;
    std::snprintf(buf, sizeof buf, "| slip region | %s | %.0f %% adhesion | |\n", p.slip.c_str(),
                  100 * r.adhesion_fraction);
    os << buf;
}

void print_table1_markdown(std::ostream& os, const std::vector<Table1Result>& table)
{
    os << "| xi_x | xi_y | spin [1/ft] | contact | paper K | creepwork K | diff | slip: paper / "
          "creepwork |\n|---|---|---|---|---|---|---|---|\n";
    char buf[200];
    for (const Table1Result& t : table) {
        std::snprintf(buf, sizeof buf, "| %g | %g | %g | %s | %.3f | %.4f | %s | %s / %.0f %% "
                      "adhesion |\n",
                      t.row.xi_x, t.row.xi_y, t.row.spin_per_ft,
                      t.row.fig7_contact ? "Fig. 7" : "Fig. 6", t.row.K, t.result.K,
                      pct(t.result.K, t.row.K).c_str(), t.row.slip,
                      100 * t.result.adhesion_fraction);
        os << buf;
    }
}

// Hertz scaling for comparison: a ~ N^(1/3) at fixed curvatures.
double hertz_scaled_a(const CaseRun& from, const PaperCase& to)
{
    return from.solution.result.a * std::cbrt(to.N_lbf / from.paper.N_lbf);
}

void write_case_files(const std::string& dir, const CaseRun& run, const Units& u, bool plots,
                      const PlotStyle& style)
{
    write_fields_csv(dir + "/fields.csv", run.solution, u);
    write_profile_csv(dir + "/profile.csv", run.solution, u);
    std::ofstream f(dir + "/result.json");
    f << case_json(run, u).str(true) << "\n";
    f.close();
    if (!f) throw CliError(kExitFailure, "cannot write " + dir + "/result.json");
    if (plots)
        write_patch_pictures(
            dir, run.solution, u,
            "Paper " + run.paper.name +
                " reproduced (a fitted to the printed forces): " + describe_case(run.solution, u),
            style);
}

} // namespace

int command_fit_fig6(int argc, char** argv, int first)
{
    using K = OptionKind;
    const auto specs = join({{"G", K::number, {}},
                             {"nu", K::number, {}},
                             {"nx", K::integer, {}},
                             {"ny", K::integer, {}},
                             {"units", K::choice, {"si", "SI", "paper"}}},
                            output_options_with_markdown());
    ParsedOptions opts;
    if (parse_or_help(specs, argc, argv, first, usage_fit_fig6(), opts)) return kExitOk;
    const Units units = Units::named(opts.text("units", "si"));
    const FitChoices choices = read_choices(opts, units);
    const std::string out = opts.text("out", "");
    if (!out.empty()) check_output_target(out, "--out", opts.has("force"));

    cw_grid grid = library_default_grid();
    grid.kind = CW_GRID_KALKER_STRIPS;
    grid.nx = choices.nx;
    grid.ny = choices.ny;
    ContactSolver solver(grid);
    const CaseRun fig6 = run_case(paper_fig6(), choices, solver);
    const CaseRun fig7 = run_case(paper_fig7(), choices, solver);
    const double a7_hertz = hertz_scaled_a(fig6, fig7.paper);
    const cw_result hertz = solver.solve_totals(paper_params(fig7.paper, a7_hertz, choices));
    const std::vector<Table1Result> table1 = run_table1(fig6, fig7, choices, solver);

    if (!out.empty()) {
        const bool plots = should_plot(opts);
        // The comparison printed here is on the rail, as the paper prints it.
        const PlotStyle style = read_plot_style(opts, ForceSign::rail);
        StagedOutput dir(out, "--out", opts.has("force"));
        write_case_files(dir.path(), fig6, units, plots, style);
        std::filesystem::create_directories(dir.path("fig7"));
        write_case_files(dir.path("fig7"), fig7, units, plots, style);
        dir.commit();
    }

    if (opts.text("format", "text") == "json") {
        JsonObject j;
        j.text("units", units.name())
            .object("choices", JsonObject()
                                   .number("G", units.from_si(Quantity::stress, choices.G))
                                   .number("nu", choices.nu)
                                   .text("grid", "kalker_strips")
                                   .integer("nx", choices.nx)
                                   .integer("ny", choices.ny)
                                   .text("pressure", "parabolic"))
            .object("fig6", case_json(fig6, units))
            .object("fig7", case_json(fig7, units))
            .array("table1", table1_json(table1))
            .number("fig7_hertz_scaled_a", units.from_si(Quantity::length, a7_hertz))
            .number("fig7_hertz_scaled_Fy", units.from_si(Quantity::force, hertz.Fy));
        std::cout << j.str(true) << "\n";
        return kExitOk;
    }
    std::ostream& os = std::cout;
    if (opts.text("format", "text") == "markdown") {
        print_case_markdown(os, fig6);
        os << "\n";
        print_case_markdown(os, fig7);
        os << "\n";
        print_table1_markdown(os, table1);
        return kExitOk;
    }
    os << "The paper's Figs. 6 and 7 reproduced. The paper gives neither the semi-axes nor the\n"
          "material. Choices (see creepwork fit-fig6 --help for why): steel G = "
       << fmt(choices.G / 1e9, 4) << " GPa = " << fmt(choices.G / kPascalPerPsi, 8)
       << " psi, nu = " << choices.nu << ";\nparabolic pressure (paper eq. 16); Kalker strip grid "
       << choices.nx << " x " << choices.ny
       << " (K depends on the grid; about 10 x 10 gives Table 1's K).\n"
       << "Forces, moment and work per rolled distance: paper units and SI.\n\n";
    print_case(os, fig6);
    os << "\n";
    print_case(os, fig7);
    os << "  for comparison, Hertz scaling of Fig. 6's a (a ~ N^(1/3), same curvatures, a/b "
          "ignored):\n"
       << "  a = " << fmt(a7_hertz * 1e3, 5)
       << " mm gives Fy = " << fmt(-hertz.Fy / kNewtonPerLbf, 6) << " lbf ("
       << pct(-hertz.Fy / kNewtonPerLbf, fig7.paper.Fy_lbf)
       << "), Mz = " << fmt(-hertz.Mz / (kNewtonPerLbf * kMetrePerFoot), 4) << " lbf ft\n";
    os << "\n";
    print_table1(os, table1);
    if (!out.empty())
        os << "\npictures and data: " << out << " (Fig. 6), " << out << "/fig7 (Fig. 7)\n";
    return kExitOk;
}

} // namespace cwcli
