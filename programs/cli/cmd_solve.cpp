// creepwork solve: one contact; totals to stdout, fields, profile and
// pictures to --out.
#include <cstdio>
#include <iostream>

#include "cli_error.hpp"
#include "command_common.hpp"
#include "commands.hpp"
#include "contact_options.hpp"
#include "contact_solver.hpp"
#include "csv_output.hpp"
#include "gap_input.hpp"
#include "output_dir.hpp"
#include "patch_plots.hpp"
#include "report.hpp"
#include "surface_outputs.hpp"
#include "surface_plots.hpp"

namespace cwcli {

int command_solve(int argc, char** argv, int first)
{
    auto specs =
        join(join(join(join(material_and_load_options(), model_options()), creepage_options()),
                  grid_options()),
             output_options());
    specs = join(specs, friction_options());
    specs.push_back({"jacobian", OptionKind::flag, {}});
    specs = join(join(specs, gap_options()), surface_options());
    ParsedOptions opts;
    if (parse_or_help(specs, argc, argv, first, usage_solve(), opts)) return kExitOk;
    if (opts.has("gap")) return command_solve_gap(opts);
    reject_gap_options(opts);
    const ContactSetup c = read_contact(opts, library_default_params(), library_default_grid(),
                                        SizeAndLoad::required);
    const SurfaceRequest surface = read_surface_request(opts, c.params.rolling_direction, c.params.V);
    const std::string out = opts.text("out", "");
    if (!out.empty()) check_output_target(out, "--out", opts.has("force"));

    ContactSolver solver(c.grid);
    Solution s;
    const SurfaceOutput post = solve_with_surface(solver, c.params, surface, s);
    print_notes(c);
    for (const std::string& w : surface.warnings) std::fprintf(stderr, "creepwork: %s\n", w.c_str());
    JsonObject json = result_json(s.result, s.params, s.grid, c.units);
    add_surface_json(json, post);
    double J[CW_JACOBIAN_LEN] = {};
    const bool jacobian = opts.has("jacobian");
    if (jacobian) {
        solver.jacobian(c.params, J);
        json.object("jacobian", jacobian_json(J))
            .text("jacobian_units",
                  "SI whatever --units: rows Fx [N], Fy [N], Mz [N m], W_macro [J/m] per "
                  "xi_x [-], xi_y [-], phi [1/m], N [N]");
    }

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
        if (plots && (post.temperature || post.damage))
            write_surface_pictures(dir.path(), s, post, c.units);
        dir.commit();
    }
    if (opts.text("format", "text") == "json")
        std::cout << json.str(true) << "\n";
    else {
        print_result_text(std::cout, s.result, s.params, s.grid, c.units);
        print_surface_text(std::cout, post);
        if (jacobian) print_jacobian_text(std::cout, J);
    }
    return kExitOk;
}

} // namespace cwcli
