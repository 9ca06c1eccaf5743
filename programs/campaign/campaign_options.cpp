#include "campaign_options.hpp"

#include <cmath>

#include "../cli/cli_error.hpp"
#include "../cli/contact_inputs.hpp"
#include "../cli/options.hpp"
#include "../cli/progress.hpp"
#include "../cli/surface_outputs.hpp"

namespace cwcampaign {

using cwcli::OptionKind;
using cwcli::OptionSpec;
using cwcli::usage_error;

const char* usage_campaign()
{
    return R"(usage: creepwork campaign --in FILE.csv --out DIR [options]
       creepwork campaign --table --out DIR [table options] [options]
       mpirun -np R creepwork campaign ...      (R ranks; without mpirun: one)

Solves many contacts -- the rows of FILE.csv, or the points of a creep-force
table -- over MPI ranks and the OpenMP threads of each rank, with dynamic
load balancing, and writes DIR/results.csv (DIR/table.csv) in input order.
The results are bitwise the same for any number of ranks and threads. A
row that cannot be read or solved gets a status and a message on its line;
the campaign goes on. Killed, it resumes with --resume, without redoing
finished chunks. doc/campaigns.md describes the files.

input (--in): a CSV file with a header, one contact per row, SI units;
the columns of `creepwork wear` and the options of `creepwork solve`
(doc/input-schema.md lists every column, unit and default):
  required  id (unique), a, b, N
  optional  model fastsim|exact|calibrated, grid kalker_strips|uniform, nx, ny,
            box_scale, mu, V (m/s), G, nu, L1, L2, L3 (m/Pa, instead of G
            and nu), xi_x, xi_y, phi (or spin), pressure (parabolic|elliptic),
            friction_law (coulomb|linear|rational|exponential|polach), mu_e1,
            s_h1, mu_e2, s_h2 (m/s), polach_A, polach_B (s/m), friction_speed
            (local|global), k0, alpha_inf, beta, memory_distance, memory_s0,
            layer_h (m), layer_G, tau_c0 (Pa), k_tau (Pa/m; the exact model's
            interface layer), rolling_direction (+1|-1), spin_offset,
            flexibility_blending (0|1), exact_load (0|1), tolerance,
            max_iterations (exact model); s0, distance (m; carried to
            results.csv)
  any shape gap_file: the CSV of `creepwork solve --gap` (x_m,y_m,h_m, a
            path relative to FILE.csv's directory, or absolute) instead of
            a, b and the grid; N or approach (m, from the file's h = 0);
            model exact (the default there) or fastsim; normal_method
            exact|semi_hertz; not with --wear
  wear      (with --wear; else ignored with a note) s0 (m, required),
            passes (axle passages or wheel revolutions) or distance (m,
            wheel: passes = distance / (2 pi R)), contact_angle (rad, default
            0), body (rail|wheel, default --body), speed (m/s, default --speed)
  an empty cell takes the default of `creepwork solve` (steel on steel,
  FASTSIM on Kalker's 20 x 20 strips; the exact model uniform 24 x 24)
  a row with a value out of range gets CW_ERR_INVALID_INPUT or
  CW_ERR_GRID_OUT_OF_RANGE, one that cannot be read ROW_UNREADABLE; one
  with an implausible value (a = 7.2 m, N = 100 for 100 kN, G in MPa) is
  solved with a warning in its message, counted on stderr
  --strict          reject those rows instead (status ROW_IMPLAUSIBLE)

output:
  --out DIR         the campaign's directory (created; doc/campaigns.md has
                    the rules on an existing one)
  --resume          continue the unfinished campaign in DIR (or start one)
  --force           start over in a DIR an earlier campaign wrote

wear (--wear): each row's USFD or Archard/KTH wear from its work map, per
row in results.csv (wear_* columns) and accumulated on a profile grid per
body, DIR/wear_profile_rail.csv and/or wear_profile_wheel.csv
(doc/campaigns.md, doc/theory/wear.md); the options of `creepwork wear`:
  --law usfd|archard  --source consistent|paper|slip  --speed V (m/s, Archard)
  --density RHO  --hardness H (Archard)  --body rail|wheel (default rail)
  --wheel-radius R (m)  --orientation +1|-1
  --profile-from S --profile-to S --profile-step H
                    the profile grid (m; default: every patch with a 20 %
                    margin, a quarter of the narrowest strip)

temperature and damage (doc/campaigns.md; the options of `creepwork solve`):
each row's flash temperature of both bodies (body 1 the rail, body 2 the
wheel) and its damage indices, from its work map, in results.csv:
  --temperature     columns T_max_1, T_max_2 (deg C), T_max_x, T_max_y (m);
                    the rolling speed is the row's V (or speed), else --speed
  --T0-1 --T0-2 T   bulk temperatures (deg C, default 20)
  --heat-capacity-1/-2 C (J/(kg K))  --conductivity-1/-2 L (W/(m K))
  --density-1/-2 RHO (kg/m^3)        (default steel: 450, 50, 7850)
  --temperature-discretisation consistent|contact
  --speed V         rolling speed (m/s) of rows without V (also --wear's)
  --mu-T "T1:mu1,T2:mu2,..."
                    friction mu(T), solved in a fixed-point loop per row
                    (a model without mu(T) fails the row); column
                    temperature_iterations
  --k-yield K       surface shear yield stress (Pa): columns rcf_index_max,
                    FI_surf, T_gamma (N), wlrm_damage (per pass)

creep-force table (--table): points over a/b, nu and Kalker's normalised
creepages xi' = G c^2 C11 xi_x/(3 mu N), eta' = G c^2 C22 xi_y/(3 mu N),
spin psi' = G c^3 C23 phi/(mu N), c = sqrt(a b); entries Fx/(mu N),
Fy/(mu N), Mz/(mu N c). Lists are comma-separated, strictly increasing;
the defaults are CONTACT's USETAB axes.
  --aob LIST        a/b values (default 24 values, 1/7 .. 200)
  --nu LIST         Poisson's ratios (default 0.28)
  --xi LIST --eta LIST --psi LIST
                    normalised creepages and spin (default 0, 1/7 .. 7, 7e5;
                    psi also negative)
  --model fastsim|exact|calibrated   --pressure parabolic|elliptic
  --grid kalker_strips|uniform   --nx N   --ny N   --box-scale S
                    the solver of every point (default fastsim, kalker_strips 20 x 20)

running:
  --threads N       OpenMP threads per rank (default: OMP_NUM_THREADS, else
                    the CPUs the rank may run on, shared among the ranks of
                    a node when they are not bound)
  --chunk N         rows per chunk (default: sized to about 0.25 s of work)
  --max-grids N     grid shapes each rank keeps ready (default 8)
  --progress S      a progress line on stderr every S seconds (default: the
                    first within 5 s, then every 30 s)
  --quiet           no progress lines on stderr

exit status: 0 done (rows that failed are in the results, counted on
stderr), 1 environment (cannot write, MPI) or a table with failed points
(it could not be interpolated), 2 bad input (options, the input file's
header or columns, an output directory the rules refuse)
)";
}

namespace {

std::vector<OptionSpec> specs()
{
    using K = OptionKind;
    return {{"in", K::text, {}},
            {"out", K::text, {}},
            {"resume", K::flag, {}},
            {"force", K::flag, {}},
            {"threads", K::integer, {}},
            {"chunk", K::integer, {}},
            {"max-grids", K::integer, {}},
            {"quiet", K::flag, {}},
            {"progress", K::number, {}},
            {"strict", K::flag, {}},
            {"help", K::flag, {}},
            {"table", K::flag, {}},
            {"aob", K::text, {}},
            {"nu", K::text, {}},
            {"xi", K::text, {}},
            {"eta", K::text, {}},
            {"psi", K::text, {}},
            {"model", K::choice, {"fastsim", "exact", "calibrated"}},
            {"pressure", K::choice, {"parabolic", "elliptic"}},
            {"grid", K::choice, {"kalker_strips", "uniform"}},
            {"nx", K::integer, {}},
            {"ny", K::integer, {}},
            {"box-scale", K::number, {}},
            {"wear", K::flag, {}},
            {"law", K::choice, {"usfd", "archard"}},
            {"source", K::choice, {"consistent", "paper", "slip"}},
            {"speed", K::number, {}},
            {"density", K::number, {}},
            {"hardness", K::number, {}},
            {"body", K::choice, {"rail", "wheel"}},
            {"wheel-radius", K::number, {}},
            {"orientation", K::choice, {"+1", "1", "-1"}},
            {"profile-from", K::number, {}},
            {"profile-to", K::number, {}},
            {"profile-step", K::number, {}}};
}

// specs() with the surface options of `creepwork solve` (--speed is there).
std::vector<OptionSpec> all_specs()
{
    std::vector<OptionSpec> s = specs();
    for (const OptionSpec& t : cwcli::temperature_options()) s.push_back(t);
    s.push_back({"mu-T", OptionKind::text, {}});
    s.push_back({"k-yield", OptionKind::number, {}});
    return s;
}

const char* const kSurfaceOnly[] = {"temperature",     "temperature-discretisation",
                                    "T0-1",            "T0-2",
                                    "heat-capacity-1", "heat-capacity-2",
                                    "conductivity-1",  "conductivity-2",
                                    "density-1",       "density-2",
                                    "mu-T",            "k-yield"};

// --temperature, --mu-T, --k-yield, as `creepwork solve` reads them; --speed
// is the rolling speed of rows without V (and --wear's).
void read_surface(const cwcli::ParsedOptions& o, CampaignOptions& c)
{
    double speed = 0.0;
    if (o.has("speed")) {
        if (!o.has("temperature") && !c.wear)
            throw usage_error("--speed", "only used with --wear or --temperature");
        speed = o.number("speed", 0);
        if (!(speed > 0 && speed <= 1e3))
            throw usage_error("--speed", "must lie in (0, 1000] m/s");
    }
    SurfaceSetup& s = c.surface;
    static_cast<cwcli::SurfaceRequest&>(s) = cwcli::read_surface_options(o, speed);
    s.speed = speed;
    if (s.damage && !(s.damage_params.k_yield > 0 && s.damage_params.k_yield <= 1e12))
        throw usage_error("--k-yield", "must lie in (0, 1e12] Pa (the surface shear yield stress)");
    for (const std::string& w : s.warnings) c.notes.push_back(w);
}

const char* const kWearOnly[] = {"law",          "source",      "speed",        "density",
                                 "hardness",     "body",        "wheel-radius", "orientation",
                                 "profile-from", "profile-to",  "profile-step"};

// --wear's options, checked as `creepwork wear` checks them.
void read_wear(const cwcli::ParsedOptions& o, WearSetup& w)
{
    cw_wear_params_init(&w.params);
    w.params.law = o.text("law", "usfd") == "archard" ? CW_WEAR_ARCHARD_KTH : CW_WEAR_USFD;
    const std::string src = o.text("source", "consistent");
    w.params.source = src == "paper"  ? CW_WEAR_SOURCE_PAPER
                      : src == "slip" ? CW_WEAR_SOURCE_SLIP
                                      : CW_WEAR_SOURCE_CONSISTENT;
    if (o.has("speed")) {
        w.params.rolling_speed = o.number("speed", 0);
        if (!(w.params.rolling_speed > 0 && w.params.rolling_speed <= 1e3))
            throw usage_error("--speed", "must lie in (0, 1000] m/s");
    }
    if (o.has("density")) {
        w.params.density = o.number("density", 0);
        if (!(w.params.density >= 1 && w.params.density <= 1e5))
            throw usage_error("--density", "must lie in [1, 1e5] kg/m^3");
    }
    if (o.has("hardness")) {
        if (w.params.law != CW_WEAR_ARCHARD_KTH)
            throw usage_error("--hardness", "only used with --law archard");
        w.params.hardness = o.number("hardness", 0);
        if (!(w.params.hardness >= 1e6 && w.params.hardness <= 1e12))
            throw usage_error("--hardness", "must lie in [1e6, 1e12] Pa");
    }
    w.default_body = o.text("body", "rail") == "wheel" ? kWheel : kRail;
    if (o.has("wheel-radius")) {
        w.wheel_radius = o.number("wheel-radius", 0);
        if (!(w.wheel_radius > 0 && w.wheel_radius <= 100))
            throw usage_error("--wheel-radius", "must lie in (0, 100] m");
    }
    w.orientation = o.text("orientation", "+1") == "-1" ? -1 : 1;
    if (o.has("profile-from")) w.profile_from = o.number("profile-from", 0);
    if (o.has("profile-to")) w.profile_to = o.number("profile-to", 0);
    if (o.has("profile-step")) w.profile_step = o.number("profile-step", 0);
    for (const char* name : {"profile-from", "profile-to"})
        if (o.has(name) && !(std::fabs(o.number(name, 0)) <= 1e6))
            throw usage_error(std::string("--") + name, "must lie within +-1e6 m");
}

const char* const kTableOnly[] = {"aob", "nu",   "xi", "eta", "psi",      "model",
                                  "pressure", "grid", "nx", "ny",  "box-scale"};

// "0,0.5,1" -> {0, 0.5, 1}: finite numbers, strictly increasing.
std::vector<double> read_list(const cwcli::ParsedOptions& o, const std::string& name,
                              std::vector<double> fallback)
{
    if (!o.has(name)) return fallback;
    const std::string text = o.text(name, "");
    std::vector<double> values;
    size_t pos = 0;
    for (;;) {
        const size_t comma = text.find(',', pos);
        const std::string item = text.substr(pos, comma == std::string::npos ? std::string::npos
                                                                              : comma - pos);
        double v = 0.0;
        if (!cwcli::parse_finite_double(item, v))
            throw usage_error("--" + name, "'" + item + "' is not a finite number (a list is "
                                                        "comma-separated, e.g. 0,0.5,1)");
        if (!values.empty() && !(v > values.back()))
            throw usage_error("--" + name, "values must be strictly increasing ('" + item +
                                               "' follows " +
                                               cwcli::round_trip_text(values.back()) + ")");
        values.push_back(v);
        if (comma == std::string::npos) break;
        pos = comma + 1;
    }
    return values;
}

void read_table(const cwcli::ParsedOptions& o, TableSpec& s)
{
    s.aob = read_list(o, "aob", s.aob);
    s.nu = read_list(o, "nu", s.nu);
    s.xi = read_list(o, "xi", s.xi);
    s.eta = read_list(o, "eta", s.eta);
    s.psi = read_list(o, "psi", s.psi);
    if (s.aob.front() < CW_MIN_ASPECT || s.aob.back() > CW_MAX_ASPECT)
        throw usage_error("--aob", "values must lie in [1e-3, 1e3], the range of Kalker's "
                                   "coefficients");
    if (s.nu.front() < 0.0 || s.nu.back() > 0.5)
        throw usage_error("--nu", "values must lie in [0, 0.5]");
    const std::string model = o.text("model", "fastsim");
    s.model = model == "exact" ? CW_MODEL_EXACT
              : model == "calibrated" ? CW_MODEL_CALIBRATED
                                      : CW_MODEL_FASTSIM;
    if (o.text("pressure", "parabolic") == "elliptic") s.pressure = CW_PRESSURE_ELLIPTIC;
    if (o.has("grid"))
        s.grid.kind = o.text("grid", "") == "uniform" ? CW_GRID_UNIFORM : CW_GRID_KALKER_STRIPS;
    s.grid.nx = o.integer("nx", s.grid.nx);
    s.grid.ny = o.integer("ny", s.grid.ny);
    for (const char* n : {"nx", "ny"}) {
        const int v = o.integer(n, 1);
        if (v < 1 || v > CW_MAX_GRID_CELLS)
            throw usage_error(std::string("--") + n, "must lie in 1..1000 (got " +
                                                         std::to_string(v) + ")");
    }
    if (o.has("box-scale")) {
        if (s.grid.kind != CW_GRID_UNIFORM)
            throw usage_error("--box-scale", "only used with --grid uniform");
        s.grid.box_scale = o.number("box-scale", 1.0);
        if (!(s.grid.box_scale >= 1.0 && s.grid.box_scale <= CW_MAX_BOX_SCALE))
            throw usage_error("--box-scale", "must lie in [1, 100]");
    }
    // Rank 0 holds every point (about 300 bytes each) while the table runs.
    if (table_points(s) > 10000000ull)
        throw usage_error("--table", std::to_string(table_points(s)) +
                                         " points is more than 1e7; use shorter axes or "
                                         "several tables");
}

} // namespace

CampaignOptions read_campaign_options(int argc, char** argv, int first)
{
    CampaignOptions c;
    for (int k = first; k < argc; ++k)
        if (std::string(argv[k]) == "--help" || std::string(argv[k]) == "-h") {
            c.help = true;
            return c;
        }
    const cwcli::ParsedOptions o = cwcli::parse_options(all_specs(), argc, argv, first);
    c.table = o.has("table");
    c.out = o.text("out", "");
    c.resume = o.has("resume");
    c.force = o.has("force");
    const cwcli::ProgressOptions progress = cwcli::read_progress_options(o);
    c.quiet = progress.quiet;
    c.progress = progress.every;
    c.strict = o.has("strict");
    if (c.resume && c.force)
        throw usage_error("--resume", "and --force contradict each other: continue, or start "
                                      "over?");
    if (c.out.empty()) throw usage_error("--out", "missing: the campaign's directory");
    if (c.table) {
        if (o.has("in"))
            throw usage_error("--in", "not used with --table (the table makes its own rows)");
        if (o.has("strict"))
            throw usage_error("--strict", "not used with --table (its points are Kalker's "
                                          "normalised contacts)");
        for (const char* name : kWearOnly)
            if (o.has(name)) throw usage_error(std::string("--") + name, "only used with --wear");
        if (o.has("wear"))
            throw usage_error("--wear", "not used with --table (a table has no wear)");
        for (const char* name : kSurfaceOnly)
            if (o.has(name))
                throw usage_error(std::string("--") + name,
                                  "not used with --table (its points are solved for forces "
                                  "only)");
        c.spec = usetab_axes();
        read_table(o, c.spec);
    } else {
        for (const char* name : kTableOnly)
            if (o.has(name))
                throw usage_error(std::string("--") + name,
                                  "only used with --table (a campaign's rows give their own "
                                  "values)");
        c.wear = o.has("wear");
        if (c.wear) {
            read_wear(o, c.wear_setup);
            for (const std::string& w :
                 cwcli::wear_option_warnings(c.wear_setup.params, c.wear_setup.wheel_radius))
                c.notes.push_back("warning: " + w);
        } else {
            for (const char* name : kWearOnly)
                if (o.has(name) && std::string(name) != "speed")
                    throw usage_error(std::string("--") + name, "only used with --wear");
        }
        read_surface(o, c);
        c.in = o.text("in", "");
        if (c.in.empty())
            throw usage_error("--in", "missing: the input CSV file (or --table for a creep-force "
                                      "table)");
    }
    c.threads = o.integer("threads", 0);
    if (o.has("threads") && (c.threads < 1 || c.threads > CW_MAX_BATCH_THREADS))
        throw usage_error("--threads", "must lie in 1..256 (got " + std::to_string(c.threads) +
                                           ")");
    if (o.has("chunk")) {
        const int chunk = o.integer("chunk", 0);
        if (chunk < 1 || chunk > 65536)
            throw usage_error("--chunk", "must lie in 1..65536 rows (got " +
                                             std::to_string(chunk) + ")");
        c.chunk = static_cast<uint64_t>(chunk);
    }
    c.max_grids = o.integer("max-grids", c.max_grids);
    if (c.max_grids < 1 || c.max_grids > 1000)
        throw usage_error("--max-grids", "must lie in 1..1000 (got " +
                                             std::to_string(c.max_grids) + ")");
    return c;
}

} // namespace cwcampaign
