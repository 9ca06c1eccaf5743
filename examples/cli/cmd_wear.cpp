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
#include "gnuplot.hpp"
#include "json.hpp"
#include "output_dir.hpp"
#include "report.hpp"

namespace cwcli {

namespace {

constexpr double kPi = 3.14159265358979323846;

// ------------------------------------------------------------ the input

// One row of the states file, SI.
struct State {
    int line = 0;
    double s0 = 0, a = 0, b = 0, N = 0, xi_x = 0, xi_y = 0, spin = 0, angle = 0;
    double passes = -1, distance = -1, mu = -1;
    int model = CW_MODEL_FASTSIM;
};

const std::vector<std::string> kColumns = {"s0",   "a",             "b",      "N",
                                           "xi_x", "xi_y",          "spin",   "contact_angle",
                                           "passes", "distance",    "mu",     "model"};

std::string trim(const std::string& s)
{
    size_t b = 0, e = s.size();
    while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
    return s.substr(b, e - b);
}

std::vector<std::string> split(const std::string& line)
{
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(trim(cell));
    if (!line.empty() && line.back() == ',') cells.push_back("");
    return cells;
}

std::string lower(std::string s)
{
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// Reads the states file. Throws usage_error("--in", "FILE line L, column C: ...").
std::vector<State> read_states(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw usage_error("--in", "cannot open '" + path + "'");
    const std::string where = path + " line ";
    std::vector<std::string> header;
    std::map<std::string, size_t> column;
    std::vector<State> states;
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const std::string t = trim(line);
        if (t.empty() || t[0] == '#') continue;
        const std::vector<std::string> cells = split(t);
        if (header.empty()) {
            header = cells;
            for (size_t c = 0; c < header.size(); ++c) {
                const std::string& name = header[c];
                if (std::find(kColumns.begin(), kColumns.end(), name) == kColumns.end()) {
                    const std::string hint = nearest(name, kColumns);
                    throw usage_error("--in", where + std::to_string(number) + ": unknown column '" +
                                                  name + "'" +
                                                  (hint.empty() ? "" : "; did you mean " + hint + "?") +
                                                  " (columns: s0, a, b, N, xi_x, xi_y, spin, "
                                                  "contact_angle, passes, distance, mu, model)");
                }
                if (column.count(name))
                    throw usage_error("--in", where + std::to_string(number) + ": column '" +
                                                  name + "' appears twice");
                column[name] = c;
            }
            for (const char* need : {"s0", "a", "b", "N"})
                if (!column.count(need))
                    throw usage_error("--in", path + ": no column '" + need +
                                                  "' (s0, a, b and N are required)");
            continue;
        }
        if (cells.size() != header.size())
            throw usage_error("--in", where + std::to_string(number) + ": " +
                                          std::to_string(cells.size()) + " values for " +
                                          std::to_string(header.size()) + " columns");
        State s;
        s.line = number;
        const auto value = [&](const char* name, double fallback) {
            const auto it = column.find(name);
            if (it == column.end()) return fallback;
            const std::string& text = cells[it->second];
            double v = 0;
            if (!parse_finite_double(text, v))
                throw usage_error("--in", where + std::to_string(number) + ", column " + name +
                                              ": '" + text + "' is not a finite number");
            return v;
        };
        s.s0 = value("s0", 0);
        s.a = value("a", 0);
        s.b = value("b", 0);
        s.N = value("N", 0);
        s.xi_x = value("xi_x", 0);
        s.xi_y = value("xi_y", 0);
        s.spin = value("spin", 0);
        s.angle = value("contact_angle", 0);
        s.passes = value("passes", -1);
        s.distance = value("distance", -1);
        s.mu = value("mu", -1);
        if (column.count("model")) {
            const std::string m = lower(cells[column["model"]]);
            if (m == "fastsim" || m.empty())
                s.model = CW_MODEL_FASTSIM;
            else if (m == "exact")
                s.model = CW_MODEL_EXACT;
            else if (m == "calibrated")
                s.model = CW_MODEL_CALIBRATED;
            else
                throw usage_error("--in", where + std::to_string(number) +
                                              ", column model: '" + cells[column["model"]] +
                                              "' is not fastsim, exact or calibrated");
        }
        states.push_back(s);
    }
    if (header.empty()) throw usage_error("--in", path + " has no header line");
    if (states.empty()) throw usage_error("--in", path + " has no contact states");
    return states;
}

// ------------------------------------------------------------ the setup

struct Setup {
    bool wheel = false;
    double radius = 0;          // wheel radius [m] (0: not given)
    cw_wear_params wear;
    cw_params base;             // material and friction defaults
    cw_grid grid;
    int orientation = 1;
    std::vector<std::string> notes;
};

std::string row_text(const State& s) { return "line " + std::to_string(s.line); }

[[noreturn]] void row_error(const std::string& file, const State& s, const std::string& what)
{
    throw usage_error("--in", file + " " + row_text(s) + ": " + what);
}

// The passes a state stands for (validated).
double passes_of(const State& s, const Setup& u, const std::string& file)
{
    if (s.passes >= 0 && s.distance >= 0)
        row_error(file, s, "give passes or distance, not both");
    if (s.distance >= 0) {
        if (!u.wheel)
            row_error(file, s,
                      "distance is for --body wheel (passes = distance / (2 pi R)); a rail "
                      "state needs passes (axle passages)");
        if (!(u.radius > 0))
            row_error(file, s, "distance needs --wheel-radius (passes = distance / (2 pi R))");
        return s.distance / (2.0 * kPi * u.radius);
    }
    if (s.passes < 0)
        row_error(file, s,
                  u.wheel ? "needs passes (wheel revolutions) or distance (rolled, with "
                            "--wheel-radius): add a column"
                          : "needs passes (axle passages): add a column passes");
    return s.passes;
}

Setup read_setup(const ParsedOptions& o)
{
    Setup u;
    u.wheel = o.text("body", "rail") == "wheel";
    if (o.has("wheel-radius")) {
        u.radius = o.number("wheel-radius", 0);
        if (!(u.radius > 0)) throw usage_error("--wheel-radius", "must be > 0 (metres)");
        if (!u.wheel) throw usage_error("--wheel-radius", "only used with --body wheel");
        if (u.radius > 2.0 || u.radius < 0.1)
            u.notes.push_back("warning: --wheel-radius = " + fmt(u.radius) +
                              " m is implausible for a railway wheel: radii are 0.3-0.65 m "
                              "(mm typed as m?)");
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
        if (u.wear.rolling_speed > 150)
            u.notes.push_back("warning: --speed = " + fmt(u.wear.rolling_speed) +
                              " m/s is implausible: trains run below 150 m/s (km/h typed as m/s?)");
    }
    if (u.wear.law == CW_WEAR_ARCHARD_KTH && !o.has("speed"))
        throw usage_error("--speed", "missing: Archard's KTH map needs the rolling speed V [m/s] "
                                     "(sliding velocity = slip x V)");
    if (o.has("density")) {
        u.wear.density = o.number("density", 0);
        if (!(u.wear.density >= 1 && u.wear.density <= 1e5))
            throw usage_error("--density", "must lie in [1, 1e5] kg/m^3");
        if (u.wear.density < 1000 || u.wear.density > 25000)
            u.notes.push_back("warning: --density = " + fmt(u.wear.density) +
                              " kg/m^3 is implausible for steel (7800 kg/m^3; g/cm^3 typed?)");
    }
    if (o.has("hardness")) {
        if (u.wear.law != CW_WEAR_ARCHARD_KTH)
            throw usage_error("--hardness", "only used with --law archard");
        u.wear.hardness = o.number("hardness", 0);
        if (!(u.wear.hardness >= 1e6 && u.wear.hardness <= 1e12))
            throw usage_error("--hardness", "must lie in [1e6, 1e12] Pa");
        if (u.wear.hardness < 5e8)
            u.notes.push_back("warning: --hardness = " + fmt(u.wear.hardness) +
                              " Pa is implausible for rail or wheel steel (2-4e9 Pa; MPa or HB "
                              "typed as Pa?)");
    }
    if (u.wheel && u.radius > 0) u.wear.pass_length = 2.0 * kPi * u.radius;
    u.orientation = o.text("orientation", "+1") == "-1" ? -1 : 1;
    cw_params_init(&u.base);
    if (o.has("mu")) u.base.mu = o.number("mu", 0);
    if (o.has("G")) u.base.G = o.number("G", 0);
    if (o.has("nu")) u.base.nu = o.number("nu", 0);
    if (!(u.base.mu >= 0)) throw usage_error("--mu", "must be >= 0");
    if (!(u.base.G > 0)) throw usage_error("--G", "must be > 0 (Pa)");
    if (!(u.base.nu >= 0 && u.base.nu <= 0.5)) throw usage_error("--nu", "must lie in [0, 0.5]");
    if (o.has("pressure"))
        u.base.pressure =
            o.text("pressure", "") == "elliptic" ? CW_PRESSURE_ELLIPTIC : CW_PRESSURE_PARABOLIC;
    u.grid = library_default_grid();
    if (o.has("grid"))
        u.grid.kind = o.text("grid", "") == "uniform" ? CW_GRID_UNIFORM : CW_GRID_KALKER_STRIPS;
    u.grid.nx = o.integer("nx", u.grid.nx);
    u.grid.ny = o.integer("ny", u.grid.ny);
    u.grid.box_scale = o.number("box-scale", u.grid.box_scale);
    if (u.grid.nx < 1 || u.grid.nx > CW_MAX_GRID_CELLS)
        throw usage_error("--nx", "must lie in 1..1000 (got " + std::to_string(u.grid.nx) + ")");
    if (u.grid.ny < 1 || u.grid.ny > CW_MAX_GRID_CELLS)
        throw usage_error("--ny", "must lie in 1..1000 (got " + std::to_string(u.grid.ny) + ")");
    if (o.has("box-scale") && u.grid.kind != CW_GRID_UNIFORM)
        throw usage_error("--box-scale", "only used with --grid uniform");
    if (!(u.grid.box_scale >= 1.0 && u.grid.box_scale <= CW_MAX_BOX_SCALE))
        throw usage_error("--box-scale", "must lie in [1, 100]");
    return u;
}

// The library's contact for a state, checked here with the file's names.
cw_params params_of(const State& s, const Setup& u, const std::string& file)
{
    cw_params p = u.base;
    p.a = s.a;
    p.b = s.b;
    p.normal_force = s.N;
    if (s.mu >= 0) p.mu = s.mu;
    p.xi_x = s.xi_x;
    p.xi_y = s.xi_y;
    p.phi = s.spin;
    p.model = s.model;
    if (!(s.a > 0)) row_error(file, s, "a = " + fmt(s.a) + " must be > 0 (metres)");
    if (!(s.b > 0)) row_error(file, s, "b = " + fmt(s.b) + " must be > 0 (metres)");
    const double ratio = s.a / s.b;
    if (!(ratio >= CW_MIN_ASPECT && ratio <= CW_MAX_ASPECT))
        row_error(file, s, "a/b = " + fmt(ratio) + " is outside [1e-3, 1e3]");
    if (!(s.N >= 0)) row_error(file, s, "N = " + fmt(s.N) + " must be >= 0 (newtons)");
    if (!(p.mu >= 0)) row_error(file, s, "mu = " + fmt(p.mu) + " must be >= 0");
    if (!(std::fabs(s.angle) <= CW_WEAR_MAX_CONTACT_ANGLE))
        row_error(file, s, "contact_angle = " + fmt(s.angle) +
                               " rad must lie within +-85 degrees (+-1.4835 rad)");
    if (!(std::fabs(s.s0) <= 1e6)) row_error(file, s, "s0 = " + fmt(s.s0) + " m is out of range");
    return p;
}

// The CLI's plausibility warnings for a row, with the file's column names.
void row_warnings(const State& s, const cw_params& p, double passes, Setup& u,
                  std::set<std::string>& seen)
{
    std::vector<std::string> w = plausibility_warnings(p, Units::si());
    const std::map<std::string, std::string> names = {{"--xi-x", "xi_x"}, {"--xi-y", "xi_y"},
                                                      {"--spin", "spin"}, {"--a", "a"},
                                                      {"--b", "b"},       {"--N", "N"},
                                                      {"--mu", "mu"}};
    for (std::string& text : w)
        for (const auto& [option, column] : names)
            if (text.rfind(option + " ", 0) == 0) text = "column " + column + text.substr(option.size());
    if (std::fabs(s.s0) > 0.2)
        w.push_back("column s0 = " + fmt(s.s0) +
                    " m is implausible: profile coordinates lie within +-0.1 m (mm typed as m?)");
    if (std::fabs(s.angle) > 1.3)
        w.push_back("column contact_angle = " + fmt(s.angle) +
                    " rad is implausible: flange angles stay below 75 degrees (degrees typed as "
                    "radians?)");
    if (passes > 1e9)
        w.push_back("column passes = " + fmt(passes) +
                    " is implausible for one state (rails see ~1e7 axles a year)");
    for (const std::string& text : w)
        if (seen.insert(text).second)
            u.notes.push_back("warning: " + row_text(s) + ": " + text);
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
    double passes = 0;
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
        lo = std::min(lo, s.s0 - s.b);
        hi = std::max(hi, s.s0 + s.b);
        const double strip = 2.0 * s.b * (grid.kind == CW_GRID_UNIFORM ? grid.box_scale : 1.0) /
                             grid.ny;
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
        f << r.s.line << "," << r.s.s0 << "," << r.s.a << "," << r.s.b << "," << r.s.N << ","
          << r.s.xi_x << "," << r.s.xi_y << "," << r.s.spin << "," << r.s.angle << "," << r.passes
          << "," << r.contact.Fx << "," << r.contact.Fy << "," << r.contact.W_macro << ","
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
      << gp_text_lines({"Wear of the " + body + ": " + fmt(p.local.passes, 6) + " passes, " +
                            law,
                        "peak " + fmt(pk * 1e6, 4) + " µm at s = " + fmt(ps * 1e3, 4) +
                            " mm; with the paper's parabola " + fmt(qk * 1e6, 4) + " µm at " +
                            fmt(qs * 1e3, 4) + " mm; worn section " +
                            fmt(p.local.volume * 1e6, 4) + " mm^2 (both)"})
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
    const auto specs = join(join(own, grid_options()), output);
    ParsedOptions opts;
    if (parse_or_help(specs, argc, argv, first, usage_wear(), opts)) return kExitOk;
    if (!opts.has("in")) throw usage_error("--in", "missing: the CSV file of contact states");
    if (!opts.has("out")) throw usage_error("--out", "missing: the output directory");
    const std::string file = opts.text("in", "");
    const std::string out = opts.text("out", "");
    check_output_target(out, "--out", opts.has("force"));
    Setup u = read_setup(opts);
    const std::vector<State> states = read_states(file);

    // Every state checked before anything is solved or written.
    struct Prepared {
        cw_params params;
        double passes;
    };
    std::vector<Prepared> prepared;
    std::set<std::string> seen;
    for (const State& s : states) {
        Prepared q;
        q.passes = passes_of(s, u, file);
        if (!(q.passes <= CW_WEAR_MAX_PASSES))
            row_error(file, s, "passes = " + fmt(q.passes) + " exceeds 1e15");
        q.params = params_of(s, u, file);
        row_warnings(s, q.params, q.passes, u, seen);
        prepared.push_back(q);
    }

    Handles h;
    char message[512] = "";
    {
        const int st = cw_solver_create(&u.grid, &h.solver, message, sizeof message);
        if (st != CW_OK) throw usage_error("--nx/--ny", message);
    }
    check(cw_wear_create(h.solver, &h.wear), "cw_wear_create", "");
    Profiles prof;
    prof.s = profile_nodes(opts, states, u.grid);
    for (cw_wear_profile** p : {&h.local, &h.parabola})
        if (cw_wear_profile_create(prof.s.data(), prof.s.size(), p, message, sizeof message) !=
            CW_OK)
            throw usage_error("--profile-from/--profile-to/--profile-step", message);
    const size_t ny = static_cast<size_t>(u.grid.ny);
    std::vector<double> y(ny), width(ny), depth(ny), par(ny);
    std::vector<StateResult> rows;
    double mass = 0.0;
    for (size_t k = 0; k < states.size(); ++k) {
        const State& s = states[k];
        const cw_params& p = prepared[k].params;
        StateResult r;
        r.s = s;
        r.passes = prepared[k].passes;
        cw_result_init(&r.contact);
        const int st = cw_solver_solve(h.solver, &p, CW_SOLVE_FULL, &r.contact);
        if (st != CW_OK)
            row_error(file, s, std::string(cw_status_string(st)) + ": " +
                                   cw_solver_last_error(h.solver));
        cw_wear_result_init(&r.wear);
        const int sw = cw_wear_compute(h.wear, h.solver, &u.wear, &r.wear);
        if (sw != CW_OK)
            throw usage_error(sw == CW_ERR_INVALID_INPUT ? "--law/--speed/--density/--hardness"
                                                         : "--in",
                              std::string(cw_status_string(sw)) + ": " + cw_wear_last_error(h.wear));
        check(cw_wear_get_strips(h.wear, y.data(), width.data(), depth.data(), par.data(), ny),
              "cw_wear_get_strips", cw_wear_last_error(h.wear));
        const int sa = cw_wear_profile_add(h.local, h.wear, s.s0, u.orientation, s.angle, r.passes);
        if (sa != CW_OK) row_error(file, s, cw_wear_profile_last_error(h.local));
        const int sp = cw_wear_profile_add_strips(h.parabola, y.data(), width.data(), par.data(),
                                                  ny, s.s0, u.orientation, s.angle, r.passes);
        if (sp != CW_OK) row_error(file, s, cw_wear_profile_last_error(h.parabola));
        mass += r.passes * r.wear.mass_per_pass;
        rows.push_back(r);
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
