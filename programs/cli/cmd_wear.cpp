// creepwork wear: a wear loop over a list of contact states read from a CSV
// file. Each state is solved (CW_SOLVE_FULL), its wear computed (USFD or
// Archard/KTH on the work map), and its lateral wear profile added, the
// state's number of passes times, to a profile grid at the state's s0 --
// once as the library computes it, once with the paper's parabola
// assumption (the same worn volume spread as (3V/4b)(1 - y^2/b^2)). Writes
// the two accumulated depth profiles, the per-state results and a picture.
// Only the public C ABI is used.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "cli_error.hpp"
#include "command_common.hpp"
#include "commands.hpp"
#include "contact_options.hpp"
#include "contact_rows.hpp"
#include "gnuplot.hpp"
#include "json.hpp"
#include "output_dir.hpp"
#include "progress.hpp"
#include "report.hpp"

namespace cwcli {

namespace {

constexpr double kPi = 3.14159265358979323846;

bool same_grid(const cw_grid& a, const cw_grid& b)
{
    return a.kind == b.kind && a.nx == b.nx && a.ny == b.ny &&
           (a.kind != CW_GRID_UNIFORM || a.box_scale == b.box_scale);
}

std::string grid_text(const cw_grid& g)
{
    return std::string(grid_kind_name(g.kind)) + " " + std::to_string(g.nx) + " x " +
           std::to_string(g.ny) +
           (g.kind == CW_GRID_UNIFORM ? " (box " + round_trip_text(g.box_scale) + ")" : "");
}

// ------------------------------------------------------------ the setup

struct Setup {
    bool wheel = false;
    double radius = 0;          // wheel radius [m] (0: not given)
    cw_wear_params wear;
    ContactInputs base;         // the options' material, pressure and grid
    std::vector<Input> base_given; // those the options give
    int orientation = 1;
    std::vector<std::string> notes;
};

Setup read_setup(const ParsedOptions& o)
{
    Setup u;
    u.wheel = o.text("body", "rail") == "wheel";
    if (o.has("wheel-radius")) {
        u.radius = o.number("wheel-radius", 0);
        if (!(u.radius > 0)) throw usage_error("--wheel-radius", "must be > 0 (metres)");
        if (!u.wheel) throw usage_error("--wheel-radius", "only used with --body wheel");
    }
    cw_wear_params_init(&u.wear);
    const std::string law = o.text("law", "usfd");
    u.wear.law = law == "archard" ? CW_WEAR_ARCHARD_KTH : CW_WEAR_USFD;
    const std::string src = o.text("source", "consistent");
    u.wear.source = src == "paper" ? CW_WEAR_SOURCE_PAPER
                    : src == "slip" ? CW_WEAR_SOURCE_SLIP
                                    : CW_WEAR_SOURCE_CONSISTENT;
    if (o.has("speed")) {
        u.wear.rolling_speed = o.number("speed", 0);
        if (!(u.wear.rolling_speed > 0)) throw usage_error("--speed", "must be > 0 (m/s)");
    }
    if (o.has("density")) {
        u.wear.density = o.number("density", 0);
        if (!(u.wear.density >= 1 && u.wear.density <= 1e5))
            throw usage_error("--density", "must lie in [1, 1e5] kg/m^3");
    }
    if (o.has("hardness")) {
        if (u.wear.law != CW_WEAR_ARCHARD_KTH)
            throw usage_error("--hardness", "only used with --law archard");
        u.wear.hardness = o.number("hardness", 0);
        if (!(u.wear.hardness >= 1e6 && u.wear.hardness <= 1e12))
            throw usage_error("--hardness", "must lie in [1e6, 1e12] Pa");
    }
    for (const std::string& w : wear_option_warnings(u.wear, u.radius))
        u.notes.push_back("warning: " + w);
    if (u.wheel && u.radius > 0) u.wear.pass_length = 2.0 * kPi * u.radius;
    u.orientation = o.text("orientation", "+1") == "-1" ? -1 : 1;
    // The options every row takes unless its own cell says otherwise, read
    // and checked by the rules of every door.
    const OptionSource options(o);
    u.base = read_contact_inputs(options, library_default_params(), library_default_grid());
    for (Input in : {Input::mu, Input::G, Input::nu})
        if (options.has(in)) u.base_given.push_back(in);
    return u;
}

// ------------------------------------------------------------ the input

// One row of the states file: its contact (SI) and its place on the profile.
struct State {
    long line = 0;
    cw_params params;
    cw_grid grid;
    WearPlacement place;
    double speed = 0; // the row's speed column [m/s]; 0: --speed
};

// Reads and checks every row before anything is solved. Throws
// usage_error("--in", "FILE line L, column C: ...").
std::vector<State> read_states(const std::string& path, const ParsedOptions& o, Setup& u)
{
    try {
        RowFileReader file(path, RowFile::wear);
        const RowHeader& header = file.header();
        for (const std::string& note : header.notes()) u.notes.push_back(note);
        const std::string defaults = defaults_note(header, u.base.params, path, u.base_given);
        if (!defaults.empty()) u.notes.push_back(defaults);
        if (u.wear.law == CW_WEAR_ARCHARD_KTH && !o.has("speed") && !header.has(Input::speed) &&
            !header.has(Input::V))
            throw usage_error("--speed", "missing: Archard's KTH map needs the rolling speed V "
                                         "[m/s] (sliding velocity = slip x V): --speed, or a "
                                         "speed or V column");
        WearRules rules;
        rules.default_body = u.wheel ? 1 : 0;
        rules.wheel_radius = u.radius;
        rules.speed_given = o.has("speed");
        rules.archard = u.wear.law == CW_WEAR_ARCHARD_KTH;
        std::vector<State> states;
        std::set<std::string> seen; // each warning once
        std::vector<std::string> cells;
        std::string error;
        long line = 0;
        while (file.next(cells, line, error)) {
            if (!error.empty()) throw RowError{error};
            const RowSource r(header, cells, line);
            r.require_values();
            State s;
            s.line = line;
            const ContactInputs c = read_contact_inputs(r, u.base.params, u.base.grid);
            s.params = c.params;
            s.grid = c.grid;
            s.place = read_wear_columns(r, rules);
            if (s.place.body != rules.default_body)
                r.fail(r.name(Input::body),
                       std::string("'") + r.text(Input::body) + "', but this run wears the " +
                           (u.wheel ? "wheel" : "rail") +
                           " (--body): creepwork wear wears one body; creepwork campaign --wear "
                           "wears both",
                       ContactSource::Refusal::unreadable);
            // One solver and one profile grid serve every row.
            if (!states.empty() && !same_grid(s.grid, states.front().grid))
                r.fail(header.has(Input::grid) || header.has(Input::nx) || header.has(Input::ny)
                           ? "grid/nx/ny"
                           : r.name(Input::model),
                       "gives the grid " + grid_text(s.grid) + ", line " +
                           std::to_string(states.front().line) + " " +
                           grid_text(states.front().grid) +
                           ": creepwork wear solves every state on one grid (give the grid "
                           "columns or --grid, --nx, --ny)",
                       ContactSource::Refusal::unreadable);
            std::vector<std::string> w = plausibility_warnings(s.grid, s.params, r);
            for (std::string& text : wear_row_warnings(s.place.s0, s.place.angle, s.place.passes, r))
                w.push_back(std::move(text));
            for (const std::string& text : w)
                if (seen.insert(text).second)
                    u.notes.push_back("warning: line " + std::to_string(line) + ": " + text);
            states.push_back(s);
        }
        if (states.empty()) throw usage_error("--in", path + ": the file has a header but no rows (no contact states)");
        return states;
    } catch (const RowFileError& e) {
        throw usage_error("--in", e.what());
    } catch (const RowError& e) {
        throw usage_error("--in", path + " " + e.message);
    }
}

// ------------------------------------------------------------ the loop

struct Handles {
    cw_solver* solver = nullptr;
    cw_wear* wear = nullptr;
    cw_wear_profile *local = nullptr, *parabola = nullptr;
    ~Handles()
    {
        cw_wear_profile_destroy(parabola);
        cw_wear_profile_destroy(local);
        cw_wear_destroy(wear);
        cw_solver_destroy(solver);
    }
};

struct StateResult {
    State s;
    cw_result contact{};
    cw_wear_result wear{};
};

struct Profiles {
    std::vector<double> s, normal, height, par_normal, par_height;
    cw_wear_profile_totals local{}, parabola{};
};

// The profile grid: --profile-from/-to/-step, else from the states: every
// patch (s0 -+ b) with a margin of 20 %, spacing a quarter of the narrowest
// strip (at most 20000 nodes).
std::vector<double> profile_nodes(const ParsedOptions& o, const std::vector<State>& states,
                                  const cw_grid& grid)
{
    double lo = 1e300, hi = -1e300, step = 1e300;
    for (const State& s : states) {
        lo = std::min(lo, s.place.s0 - s.params.b);
        hi = std::max(hi, s.place.s0 + s.params.b);
        const double strip =
            2.0 * s.params.b * (grid.kind == CW_GRID_UNIFORM ? grid.box_scale : 1.0) / grid.ny;
        step = std::min(step, 0.25 * strip);
    }
    const double margin = 0.2 * (hi - lo);
    lo -= margin;
    hi += margin;
    step = std::max(step, (hi - lo) / 20000.0);
    lo = o.number("profile-from", lo);
    hi = o.number("profile-to", hi);
    step = o.number("profile-step", step);
    if (!(step > 0)) throw usage_error("--profile-step", "must be > 0 (metres)");
    if (!(hi > lo)) throw usage_error("--profile-to", "must be greater than --profile-from");
    const double n = std::floor((hi - lo) / step + 1e-9) + 1;
    if (n < 2)
        throw usage_error("--profile-step", "leaves fewer than 2 nodes between --profile-from and "
                                            "--profile-to");
    if (n > 1e6) throw usage_error("--profile-step", "gives more than 1e6 nodes");
    std::vector<double> nodes(static_cast<size_t>(n));
    for (size_t k = 0; k < nodes.size(); ++k) nodes[k] = lo + step * static_cast<double>(k);
    return nodes;
}

void check(int status, const char* call, const std::string& detail)
{
    if (status != CW_OK)
        throw CliError(kExitUsage, std::string(call) + ": " + cw_status_string(status) +
                                       (detail.empty() ? "" : " (" + detail + ")"));
}

// ------------------------------------------------------------ the output

void write_profile_csv(const std::string& path, const Profiles& p)
{
    std::ofstream f(path);
    f.precision(17);
    f << "k,s_m,depth_normal_m,depth_height_m,parabola_depth_normal_m,parabola_depth_height_m\n";
    for (size_t k = 0; k < p.s.size(); ++k)
        f << k << "," << p.s[k] << "," << p.normal[k] << "," << p.height[k] << ","
          << p.par_normal[k] << "," << p.par_height[k] << "\n";
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
}

void write_states_csv(const std::string& path, const std::vector<StateResult>& rows)
{
    std::ofstream f(path);
    f.precision(17);
    f << "line,s0_m,a_m,b_m,N_N,xi_x,xi_y,spin_per_m,contact_angle_rad,passes,Fx_wheel_N,"
         "Fy_wheel_N,W_macro_J_per_m,work_J_per_m,mass_per_distance_kg_per_m,mass_per_pass_kg,"
         "max_depth_per_pass_m,area_regime1_m2,area_regime2_m2,area_regime3_m2,area_regime4_m2\n";
    for (const StateResult& r : rows) {
        const cw_params& p = r.s.params;
        f << r.s.line << "," << r.s.place.s0 << "," << p.a << "," << p.b << "," << p.normal_force
          << "," << p.xi_x << "," << p.xi_y << "," << p.phi << "," << r.s.place.angle << ","
          << r.s.place.passes << "," << r.contact.Fx << "," << r.contact.Fy << "," << r.contact.W_macro << ","
          << r.wear.work << "," << r.wear.mass_per_distance << "," << r.wear.mass_per_pass << ","
          << r.wear.max_depth;
        for (double a : r.wear.regime_area) f << "," << a;
        f << "\n";
    }
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
}

// Peak and where.
std::pair<double, double> peak(const std::vector<double>& s, const std::vector<double>& d)
{
    size_t k = static_cast<size_t>(std::max_element(d.begin(), d.end()) - d.begin());
    return {d[k], s[k]};
}

JsonObject summary_json(const Setup& u, const Profiles& p, const std::vector<StateResult>& rows,
                        double mass)
{
    const auto [pk, ps] = peak(p.s, p.height);
    const auto [qk, qs] = peak(p.s, p.par_height);
    JsonObject j;
    j.text("body", u.wheel ? "wheel" : "rail")
        .text("law", u.wear.law == CW_WEAR_USFD ? "usfd" : "archard")
        .text("source", u.wear.source == CW_WEAR_SOURCE_PAPER  ? "paper"
                        : u.wear.source == CW_WEAR_SOURCE_SLIP ? "slip"
                                                               : "consistent")
        .integer("states", static_cast<long>(rows.size()))
        .integer("nodes", static_cast<long>(p.s.size()))
        .number("passes", p.local.passes)
        .number("volume_m2", p.local.volume)
        .number("volume_lost_m2", p.local.volume_lost)
        .number("mass_kg", mass)
        .number("peak_depth_height_m", pk)
        .number("peak_s_m", ps)
        .number("parabola_peak_depth_height_m", qk)
        .number("parabola_peak_s_m", qs)
        .text("mass_per", u.wheel ? (u.radius > 0 ? "wheel (all revolutions)"
                                                  : "metre of wheel circumference")
                                  : "metre of rail");
    return j;
}

const char* source_name(int source)
{
    return source == CW_WEAR_SOURCE_PAPER  ? "paper's work map (eq. 36)"
           : source == CW_WEAR_SOURCE_SLIP ? "model's traction x micro-slip"
                                           : "energy-consistent work map";
}

void write_picture(const std::string& dir, const Profiles& p, const Setup& u)
{
    std::filesystem::create_directories(dir + "/gnuplot");
    {
        std::ofstream f(dir + "/gnuplot/wear.dat");
        f << "# s [mm]  depth (local) [um]  depth (paper's parabola) [um], along the height axis\n";
        for (size_t k = 0; k < p.s.size(); ++k)
            f << 1e3 * p.s[k] << " " << 1e6 * p.height[k] << " " << 1e6 * p.par_height[k] << "\n";
        if (!f) throw CliError(kExitFailure, "cannot write " + dir + "/gnuplot/wear.dat");
    }
    const auto [pk, ps] = peak(p.s, p.height);
    const auto [qk, qs] = peak(p.s, p.par_height);
    const std::string body = u.wheel ? "wheel" : "rail";
    const std::string law = u.wear.law == CW_WEAR_USFD ? "USFD (Braghin et al. 2006)"
                                                       : "Archard, KTH map (Jendel 2002)";
    std::ostringstream g;
    g << "# creepwork wear: accumulated wear depth. Run from the output directory:\n"
      << "#   gnuplot gnuplot/wear.gp\n"
      << gp_png("wear.png", 1000, 640) << "set grid\nset key top right box opaque\n"
      << "set offsets 0, 0, graph 0.22, 0\n"
      << "set xlabel " << gp_quote("profile coordinate s [mm]") << "\n"
      << "set ylabel "
      << gp_quote("wear depth along the profile's height axis [µm]") << "\n"
      << "set title "
      << gp_title({"Wear of the " + body + ": " + fmt(p.local.passes, 6) + " passes, " +
                            law,
                        "peak " + fmt(pk * 1e6, 4) + " µm at s = " + fmt(ps * 1e3, 4) +
                            " mm; with the paper's parabola " + fmt(qk * 1e6, 4) + " µm at " +
                            fmt(qs * 1e3, 4) + " mm; worn section " +
                            fmt(p.local.volume * 1e6, 4) + " mm^2 (both)"},
                  1000, 10)
      << "\n"
      << "plot 'gnuplot/wear.dat' using 1:2 with lines lw 2 lc rgb '#b2182b' title "
      << gp_quote(std::string("from the ") + source_name(u.wear.source)) << ", \\\n"
      << "     '' using 1:3 with lines lw 2 dt 2 lc rgb '#2166ac' title "
      << gp_quote("paper's assumption: parabolic lateral distribution, same volume") << "\n"
      << "unset output\n";
    run_gnuplot(dir, "gnuplot/wear.gp", g.str());
}

void print_text(std::ostream& out, const Setup& u, const Profiles& p,
                const std::vector<StateResult>& rows, double mass)
{
    const auto [pk, ps] = peak(p.s, p.height);
    const auto [qk, qs] = peak(p.s, p.par_height);
    out << "creepwork wear: " << rows.size() << " states, " << fmt(p.local.passes) << " passes on the "
        << (u.wheel ? "wheel" : "rail") << ", "
        << (u.wear.law == CW_WEAR_USFD ? "USFD" : "Archard/KTH") << "\n"
        << "  worn cross-section  " << fmt(p.local.volume) << " m^2"
        << (p.local.volume_lost > 0 ? " (" + fmt(p.local.volume_lost) + " m^2 beyond the grid)"
                                    : std::string())
        << "\n"
        << "  worn mass           " << fmt(mass) << " kg per "
        << (u.wheel ? (u.radius > 0 ? "wheel" : "metre of circumference") : "metre of rail") << "\n"
        << "  peak depth          " << fmt(pk) << " m at s = " << fmt(ps) << " m (height axis)\n"
        << "  paper's parabola    " << fmt(qk) << " m at s = " << fmt(qs) << " m\n";
}

} // namespace

int command_wear(int argc, char** argv, int first)
{
    using K = OptionKind;
    const std::vector<OptionSpec> own = {{"in", K::text, {}},
                                         {"body", K::choice, {"rail", "wheel"}},
                                         {"wheel-radius", K::number, {}},
                                         {"law", K::choice, {"usfd", "archard"}},
                                         {"source", K::choice, {"consistent", "paper", "slip"}},
                                         {"speed", K::number, {}},
                                         {"density", K::number, {}},
                                         {"hardness", K::number, {}},
                                         {"mu", K::number, {}},
                                         {"G", K::number, {}},
                                         {"nu", K::number, {}},
                                         {"pressure", K::choice, {"parabolic", "elliptic"}},
                                         {"exact-load", K::flag, {}},
                                         {"orientation", K::choice, {"+1", "1", "-1"}},
                                         {"profile-from", K::number, {}},
                                         {"profile-to", K::number, {}},
                                         {"profile-step", K::number, {}}};
    // output_options() without the patch pictures' --plot-sign/--plot-axes.
    const std::vector<OptionSpec> output = {{"format", K::choice, {"text", "json"}},
                                            {"out", K::text, {}},
                                            {"force", K::flag, {}},
                                            {"no-plots", K::flag, {}},
                                            {"help", K::flag, {}}};
    const auto specs = join(join(join(own, grid_options()), output), progress_option_specs());
    ParsedOptions opts;
    if (parse_or_help(specs, argc, argv, first, usage_wear(), opts)) return kExitOk;
    if (!opts.has("in")) throw usage_error("--in", "missing: the CSV file of contact states");
    if (!opts.has("out")) throw usage_error("--out", "missing: the output directory");
    const std::string file = opts.text("in", "");
    const std::string out = opts.text("out", "");
    check_output_target(out, "--out", opts.has("force"));
    const ProgressSchedule schedule = interactive_schedule(read_progress_options(opts));
    Setup u = read_setup(opts);
    // Every state checked before anything is solved or written.
    const std::vector<State> states = read_states(file, opts, u);
    const cw_grid grid = states.front().grid;

    Handles h;
    char message[512] = "";
    {
        const int st = cw_solver_create(&grid, &h.solver, message, sizeof message);
        if (st != CW_OK) throw usage_error("--nx/--ny", message);
    }
    check(cw_wear_create(h.solver, &h.wear), "cw_wear_create", "");
    Profiles prof;
    prof.s = profile_nodes(opts, states, grid);
    for (cw_wear_profile** p : {&h.local, &h.parabola})
        if (cw_wear_profile_create(prof.s.data(), prof.s.size(), p, message, sizeof message) !=
            CW_OK)
            throw usage_error("--profile-from/--profile-to/--profile-step", message);
    const size_t ny = static_cast<size_t>(grid.ny);
    std::vector<double> y(ny), width(ny), depth(ny), par(ny);
    std::vector<StateResult> rows;
    double mass = 0.0;
    Progress progress("wear", "states", states.size(), schedule);
    for (size_t k = 0; k < states.size(); ++k) {
        const State& s = states[k];
        const auto row_error = [&](const std::string& what) {
            throw usage_error("--in", file + " line " + std::to_string(s.line) + ": " + what);
        };
        StateResult r;
        r.s = s;
        cw_result_init(&r.contact);
        const int st = cw_solver_solve(h.solver, &s.params, CW_SOLVE_FULL, &r.contact);
        if (st != CW_OK)
            row_error(std::string(cw_status_string(st)) + ": " + cw_solver_last_error(h.solver));
        cw_wear_result_init(&r.wear);
        cw_wear_params wear = u.wear;
        if (s.place.speed > 0) wear.rolling_speed = s.place.speed;
        const int sw = cw_wear_compute(h.wear, h.solver, &wear, &r.wear);
        if (sw != CW_OK)
            throw usage_error(sw == CW_ERR_INVALID_INPUT ? "--law/--speed/--density/--hardness"
                                                         : "--in",
                              std::string(cw_status_string(sw)) + ": " + cw_wear_last_error(h.wear));
        check(cw_wear_get_strips(h.wear, y.data(), width.data(), depth.data(), par.data(), ny),
              "cw_wear_get_strips", cw_wear_last_error(h.wear));
        const double passes = s.place.passes;
        const int sa =
            cw_wear_profile_add(h.local, h.wear, s.place.s0, u.orientation, s.place.angle, passes);
        if (sa != CW_OK) row_error(cw_wear_profile_last_error(h.local));
        const int sp = cw_wear_profile_add_strips(h.parabola, y.data(), width.data(), par.data(),
                                                  ny, s.place.s0, u.orientation, s.place.angle,
                                                  passes);
        if (sp != CW_OK) row_error(cw_wear_profile_last_error(h.parabola));
        mass += passes * r.wear.mass_per_pass;
        rows.push_back(r);
        progress.update(k + 1);
    }
    const size_t n = prof.s.size();
    for (auto* v : {&prof.normal, &prof.height, &prof.par_normal, &prof.par_height}) v->resize(n);
    check(cw_wear_profile_get_depth(h.local, CW_WEAR_DEPTH_NORMAL, prof.normal.data(), n), "get", "");
    check(cw_wear_profile_get_depth(h.local, CW_WEAR_DEPTH_HEIGHT, prof.height.data(), n), "get", "");
    check(cw_wear_profile_get_depth(h.parabola, CW_WEAR_DEPTH_NORMAL, prof.par_normal.data(), n),
          "get", "");
    check(cw_wear_profile_get_depth(h.parabola, CW_WEAR_DEPTH_HEIGHT, prof.par_height.data(), n),
          "get", "");
    cw_wear_profile_totals_init(&prof.local);
    cw_wear_profile_totals_init(&prof.parabola);
    cw_wear_profile_get_totals(h.local, &prof.local);
    cw_wear_profile_get_totals(h.parabola, &prof.parabola);
    if (prof.local.volume_lost > 1e-9 * prof.local.volume)
        u.notes.push_back("note: " + fmt(100 * prof.local.volume_lost / prof.local.volume, 3) +
                          " % of the worn section fell beyond the profile grid "
                          "(--profile-from/--profile-to)");
    // The rail's mass is per metre of rail; a wheel's per wheel when its
    // radius is known (pass_length = 2 pi R), else per metre of circumference.
    if (!u.wheel || !(u.radius > 0)) mass = prof.local.volume * u.wear.density;

    const JsonObject json = summary_json(u, prof, rows, mass);
    const bool plots = should_plot(opts, 0);
    StagedOutput dir(out, "--out", opts.has("force"));
    write_profile_csv(dir.path("wear_profile.csv"), prof);
    write_states_csv(dir.path("states.csv"), rows);
    {
        std::ofstream f(dir.path("summary.json"));
        f << json.str(true) << "\n";
        if (!f) throw CliError(kExitFailure, "cannot write summary.json");
    }
    if (plots) write_picture(dir.path(), prof, u);
    for (const std::string& note : u.notes) std::fprintf(stderr, "creepwork: %s\n", note.c_str());
    dir.commit();
    if (opts.text("format", "text") == "json")
        std::cout << json.str(true) << "\n";
    else
        print_text(std::cout, u, prof, rows, mass);
    return kExitOk;
}

} // namespace cwcli
