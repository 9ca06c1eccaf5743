// creepwork solve: one contact; totals to stdout, fields, profile and
// pictures to --out.
#include <cstdio>
#include <fstream>
#include <iostream>

#include "cli_error.hpp"
#include "command_common.hpp"
#include "commands.hpp"
#include "contact_options.hpp"
#include "contact_solver.hpp"
#include "csv_output.hpp"
#include "output_dir.hpp"
#include "patch_plots.hpp"
#include "report.hpp"

namespace cwcli {

namespace {

void write_json_file(const std::string& path, const JsonObject& j)
{
    std::ofstream f(path);
    f << j.str(true) << "\n";
    f.close();
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
}

} // namespace

int command_solve(int argc, char** argv, int first)
{
    const auto specs =
        join(join(join(join(material_and_load_options(), model_options()), creepage_options()),
                  grid_options()),
             output_options());
    ParsedOptions opts;
    if (parse_or_help(specs, argc, argv, first, usage_solve(), opts)) return kExitOk;
    const ContactSetup c = read_contact(opts, library_default_params(), library_default_grid(),
                                        SizeAndLoad::required);
    const std::string out = opts.text("out", "");
    if (!out.empty()) check_output_target(out, "--out", opts.has("force"));

    ContactSolver solver(c.grid);
    const Solution s = solver.solve_full(c.params);
    print_notes(c);
    const JsonObject json = result_json(s.result, s.params, s.grid, c.units);

    if (!out.empty()) {
        const bool plots = should_plot(opts, static_cast<long>(s.size()));
        StagedOutput dir(out, "--out", opts.has("force"));
        write_fields_csv(dir.path("fields.csv"), s, c.units);
        write_profile_csv(dir.path("profile.csv"), s, c.units);
        write_json_file(dir.path("result.json"), json);
        // The run's text, JSON and CSV give the forces on the wheel.
        if (plots)
            write_patch_pictures(dir.path(), s, c.units, describe_case(s, c.units),
                                 read_plot_style(opts, ForceSign::wheel));
        dir.commit();
    }
    if (opts.text("format", "text") == "json")
        std::cout << json.str(true) << "\n";
    else
        print_result_text(std::cout, s.result, s.params, s.grid, c.units);
    return kExitOk;
}

} // namespace cwcli
