// creepwork transient: transient rolling (doc/theory/transient.md) of a
// contact given by its gap, one step per line of a steps file, every step
// committed. Only the public C ABI is used (cw_transient).
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "cli_error.hpp"
#include "command_common.hpp"
#include "commands.hpp"
#include "contact_inputs.hpp"
#include "contact_options.hpp"
#include "gap_input.hpp"
#include "json.hpp"
#include "options.hpp"
#include "output_dir.hpp"
#include "transient_plots.hpp"

namespace cwcli {

namespace {

std::vector<OptionSpec> transient_options()
{
    return {{"steps", OptionKind::text, {}},
            {"model", OptionKind::choice, {"exact", "fastsim"}},
            {"gap", OptionKind::text, {}},
            {"a", OptionKind::number, {}},
            {"b", OptionKind::number, {}},
            {"nx", OptionKind::integer, {}},
            {"ny", OptionKind::integer, {}},
            {"box-scale", OptionKind::number, {}},
            {"N", OptionKind::number, {}},
            {"approach", OptionKind::number, {}},
            {"normal-method", OptionKind::choice, {"exact", "semi_hertz"}},
            {"G", OptionKind::number, {}},
            {"nu", OptionKind::number, {}},
            {"mu", OptionKind::number, {}},
            {"tolerance", OptionKind::number, {}},
            {"max-iterations", OptionKind::integer, {}},
            {"spin-offset", OptionKind::number, {}},
            {"prescribe", OptionKind::choice, {"creepages", "forces"}},
            {"start", OptionKind::choice, {"zero", "steady"}},
            {"coordinates", OptionKind::choice, {"contact", "world"}},
            {"format", OptionKind::choice, {"text", "json"}},
            {"out", OptionKind::text, {}},
            {"force", OptionKind::flag, {}},
            {"no-plots", OptionKind::flag, {}},
            {"help", OptionKind::flag, {}}};
}

struct StepRow {
    long line = 0;
    cw_transient_input input;
};

// The steps file: a header naming the columns, then one step per line;
// '#' lines and blank lines are skipped. Throws usage_error("--steps", ...)
// naming the file, the line and the column.
std::vector<StepRow> read_steps(const std::string& path, bool forces)
{
    std::ifstream in(path);
    if (!in) throw usage_error("--steps", "cannot read " + path);
    std::vector<std::string> header;
    std::vector<StepRow> rows;
    std::string text;
    long line = 0;
    auto cells_of = [](const std::string& s) {
        std::vector<std::string> cells;
        std::stringstream ss(s);
        std::string c;
        while (std::getline(ss, c, ',')) {
            const size_t b = c.find_first_not_of(" \t"), e = c.find_last_not_of(" \t\r");
            cells.push_back(b == std::string::npos ? std::string() : c.substr(b, e - b + 1));
        }
        return cells;
    };
    const std::vector<std::string> known =
        forces ? std::vector<std::string>{"dq_m", "Fx", "Fy", "xi_y", "phi"}
               : std::vector<std::string>{"dq_m", "xi_x", "xi_y", "phi"};
    auto where = [&](const std::string& column) {
        return path + " line " + std::to_string(line) + ", column " + column + ": ";
    };
    while (std::getline(in, text)) {
        ++line;
        if (text.find_first_not_of(" \t\r") == std::string::npos || text[text.find_first_not_of(" \t")] == '#')
            continue;
        const std::vector<std::string> cells = cells_of(text);
        if (header.empty()) {
            header = cells;
            for (const std::string& h : header) {
                bool ok = false;
                for (const std::string& k : known) ok = ok || h == k;
                if (!ok)
                    throw usage_error("--steps", path + " line " + std::to_string(line) +
                                                     ": unknown column '" + h + "' (" +
                                                     (forces ? "with --prescribe forces: dq_m, Fx, "
                                                               "Fy, xi_y, phi"
                                                             : "dq_m, xi_x, xi_y, phi; Fx, Fy with "
                                                               "--prescribe forces") +
                                                     ")");
            }
            auto has = [&](const char* c) {
                for (const std::string& h : header)
                    if (h == c) return true;
                return false;
            };
            if (!has("dq_m"))
                throw usage_error("--steps", path + ": the header has no column dq_m (the distance "
                                                    "rolled per step [m]; 0 is a shift)");
            if (forces && !has("Fx"))
                throw usage_error("--steps", path + ": --prescribe forces needs a column Fx [N]");
            if (forces && has("Fy") && has("xi_y"))
                throw usage_error("--steps", path + ": Fy and xi_y together: give one of them");
            continue;
        }
        if (cells.size() != header.size())
            throw usage_error("--steps", path + " line " + std::to_string(line) + ": " +
                                             std::to_string(cells.size()) + " values for " +
                                             std::to_string(header.size()) + " columns");
        StepRow r;
        r.line = line;
        cw_transient_input_init(&r.input);
        r.input.prescribe = CW_PRESCRIBE_CREEPAGES;
        if (forces) r.input.prescribe = CW_PRESCRIBE_FX;
        for (size_t c = 0; c < header.size(); ++c) {
            double v = 0.0;
            if (!parse_finite_double(cells[c], v))
                throw usage_error("--steps", where(header[c]) + "'" + cells[c] +
                                                 "' is not a finite number");
            const std::string& h = header[c];
            if (h == "dq_m") r.input.dq = v;
            if (h == "xi_x") r.input.xi_x = v;
            if (h == "xi_y") r.input.xi_y = v;
            if (h == "phi") r.input.phi = v;
            if (h == "Fx") r.input.Fx = v;
            if (h == "Fy") {
                r.input.Fy = v;
                r.input.prescribe = CW_PRESCRIBE_FORCES;
            }
        }
        rows.push_back(r);
    }
    if (rows.empty()) throw usage_error("--steps", path + " holds no step");
    return rows;
}

JsonObject step_json(const cw_transient_result& r, long line)
{
    JsonObject j;
    j.integer("line", line)
        .number("xi_x", r.xi_x)
        .number("xi_y", r.xi_y)
        .number("phi", r.phi)
        .number("Fx", r.Fx)
        .number("Fy", r.Fy)
        .number("Mz", r.Mz)
        .integer("n_contact", r.n_contact)
        .integer("n_adhesion", r.n_adhesion)
        .integer("n_slip", r.n_slip)
        .number("W_step", r.W_step)
        .number("W_slip", r.W_slip)
        .integer("iterations", r.iterations);
    return j;
}

// A failed call: the handle's message, naming the steps file's line.
[[noreturn]] void library_failure(int status, const std::string& where, const std::string& message)
{
    throw CliError(status == CW_ERR_NOT_CONVERGED ? kExitFailure : kExitUsage,
                   where + ": " + message);
}

struct Transient {
    cw_transient* t = nullptr;
    ~Transient() { cw_transient_destroy(t); }
};

} // namespace

int command_transient(int argc, char** argv, int first)
{
    ParsedOptions o;
    if (parse_or_help(transient_options(), argc, argv, first, usage_transient(), o)) return kExitOk;
    if (!o.has("steps"))
        throw usage_error("--steps", "is required (see creepwork transient --help)");
    // The contact: a gap file, or an ellipse (--a --b) on the uniform grid.
    const bool ellipse = o.has("a") || o.has("b");
    if (ellipse == o.has("gap"))
        throw usage_error("--gap", "give the contact's gap file --gap or its semi-axes --a and --b "
                                   "(one of them)");
    if (ellipse && !(o.has("a") && o.has("b")))
        throw usage_error(o.has("a") ? "--b" : "--a", "is required with an elliptic contact "
                                                      "(--a and --b)");
    if (ellipse && o.has("approach"))
        throw usage_error("--approach", "is for a gap file: an elliptic contact takes --N");
    if (o.has("N") == o.has("approach"))
        throw usage_error("--N", "give the normal force --N or the approach --approach (one of them)");
    const std::string out_dir = o.text("out", "");
    if (!out_dir.empty()) check_output_target(out_dir, "--out", o.has("force"));
    const bool forces = o.text("prescribe", "creepages") == "forces";
    const std::vector<StepRow> rows = read_steps(o.text("steps", ""), forces);
    GapFile g;
    if (ellipse) {
        g.grid = library_default_grid();
        g.grid.kind = CW_GRID_UNIFORM;
        g.grid.nx = o.integer("nx", g.grid.nx);
        g.grid.ny = o.integer("ny", g.grid.ny);
        g.grid.box_scale = o.number("box-scale", g.grid.box_scale);
    } else {
        g = read_gap_file(o.text("gap", ""));
    }

    cw_params p = library_default_params();
    p.model = o.text("model", "exact") == "fastsim" ? CW_MODEL_FASTSIM : CW_MODEL_EXACT;
    if (ellipse) {
        p.a = o.number("a", 0.0);
        p.b = o.number("b", 0.0);
    } else {
        p.gap = g.h.data();
        p.gap_len = g.h.size();
    }
    if (o.has("approach")) {
        p.normal_load = CW_NORMAL_APPROACH;
        p.approach = o.number("approach", 0.0);
    } else {
        p.normal_force = o.number("N", 0.0);
    }
    if (o.text("normal-method", "exact") == "semi_hertz") p.normal_method = CW_NORMAL_SEMI_HERTZ;
    p.G = o.number("G", p.G);
    p.nu = o.number("nu", p.nu);
    p.mu = o.number("mu", p.mu);
    p.tolerance = o.number("tolerance", p.tolerance);
    p.max_iterations = o.integer("max-iterations", p.max_iterations);
    p.spin_offset = o.number("spin-offset", p.spin_offset);

    // The library's plausibility rules, as every door prints them (with the
    // results: a refusal prints only its line).
    const std::vector<std::string> warnings =
        plausibility_warnings(g.grid, p, OptionSource(o), o.text("gap", ""));

    Transient h;
    char message[512] = "";
    const int made = cw_transient_create(&g.grid, &p, &h.t, message, sizeof message);
    if (made != CW_OK) library_failure(made, "creepwork transient", message);
    if (o.text("coordinates", "contact") == "world") {
        const int s = cw_transient_set_coordinates(h.t, CW_COORDINATES_WORLD);
        if (s != CW_OK)
            library_failure(s, "creepwork transient --coordinates world", cw_transient_last_error(h.t));
    }
    const std::string steps = o.text("steps", "");
    if (o.text("start", "zero") == "steady") {
        const int s = cw_transient_start_steady(h.t, &rows.front().input, nullptr);
        if (s != CW_OK)
            library_failure(s, steps + " line " + std::to_string(rows.front().line) + " (--start steady)",
                            cw_transient_last_error(h.t));
    }
    const bool json = o.text("format", "text") == "json";
    const bool plots = !out_dir.empty() && should_plot(o, static_cast<long>(g.grid.nx) * g.grid.ny);
    std::vector<TransientRecord> records; // for --out
    // Printed when every step succeeded: a refusal prints only its line.
    std::ostringstream out;
    if (!json)
        out << "# step  line  dq_m  xi_x  xi_y  phi  Fx  Fy  Mz  n_adhesion  n_slip  W_step  W_slip\n";
    else
        out << "[\n";
    for (size_t k = 0; k < rows.size(); ++k) {
        cw_transient_result r;
        cw_transient_result_init(&r);
        const int s = cw_transient_step(h.t, &rows[k].input, &r);
        if (s != CW_OK)
            library_failure(s, steps + " line " + std::to_string(rows[k].line),
                            cw_transient_last_error(h.t));
        cw_transient_commit(h.t);
        if (!out_dir.empty()) {
            TransientRecord rec;
            rec.line = rows[k].line;
            rec.input = rows[k].input;
            rec.result = r;
            rec.drawn = plots && transient_step_drawn(k, rows.size());
            // The first step's pressure gives mu N for the history.
            if (rec.drawn || k == 0) rec.fields = transient_fields(h.t, g.grid, p, r);
            records.push_back(std::move(rec));
        }
        if (json) {
            out << "  " << step_json(r, rows[k].line).str() << (k + 1 < rows.size() ? ",\n" : "\n");
        } else {
            out << k + 1 << "  " << rows[k].line << "  " << round_trip_text(rows[k].input.dq);
            for (double v : {r.xi_x, r.xi_y, r.phi, r.Fx, r.Fy, r.Mz})
                out << "  " << round_trip_text(v);
            out << "  " << r.n_adhesion << "  " << r.n_slip << "  "
                      << round_trip_text(r.W_step) << "  " << round_trip_text(r.W_slip) << "\n";
        }
    }
    if (json) out << "]\n";
    if (!out_dir.empty()) {
        StagedOutput dir(out_dir, "--out", o.has("force"));
        write_transient_history(dir.path(), records);
        if (plots) write_transient_pictures(dir.path(), records, p, o.text("gap", ""));
        dir.commit();
    }
    for (const std::string& w : warnings) std::cerr << "creepwork: warning: " << w << "\n";
    std::cout << out.str();
    return kExitOk;
}

} // namespace cwcli
