#include "contact_options.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "cli_error.hpp"

namespace cwcli {

std::vector<OptionSpec> material_and_load_options()
{
    using K = OptionKind;
    return {{"a", K::number, {}},
            {"b", K::number, {}},
            {"N", K::number, {}},
            {"mu", K::number, {}},
            {"G", K::number, {}},
            {"nu", K::number, {}},
            {"L1", K::number, {}},
            {"L2", K::number, {}},
            {"L3", K::number, {}},
            {"pressure", K::choice, {"parabolic", "elliptic"}},
            {"rolling-direction", K::choice, {"+1", "1", "-1"}},
            {"units", K::choice, {"si", "paper"}},
            {"spin-offset", K::number, {}},
            {"flexibility-blending", K::flag, {}}};
}

std::vector<OptionSpec> creepage_options()
{
    using K = OptionKind;
    return {{"xi-x", K::number, {}}, {"xi-y", K::number, {}}, {"spin", K::number, {}}};
}

std::vector<OptionSpec> grid_options()
{
    using K = OptionKind;
    return {{"grid", K::choice, {"strips", "uniform"}},
            {"nx", K::integer, {}},
            {"ny", K::integer, {}},
            {"box-scale", K::number, {}}};
}

std::vector<OptionSpec> model_options()
{
    using K = OptionKind;
    return {{"model", K::choice, {"fastsim", "exact", "calibrated"}},
            {"tolerance", K::number, {}},
            {"max-iterations", K::integer, {}}};
}

cw_params library_default_params()
{
    cw_params p;
    cw_params_init(&p);
    return p;
}

cw_grid library_default_grid()
{
    cw_grid g;
    cw_grid_init(&g);
    return g;
}

const char* grid_kind_name(int kind)
{
    return kind == CW_GRID_UNIFORM ? "uniform" : "strips";
}

const char* model_name(int model)
{
    return model == CW_MODEL_EXACT        ? "exact"
           : model == CW_MODEL_CALIBRATED ? "calibrated"
                                          : "fastsim";
}

const char* pressure_name(int pressure)
{
    return pressure == CW_PRESSURE_ELLIPTIC ? "elliptic" : "parabolic";
}

namespace {

std::string show(double v, const std::string& unit)
{
    std::ostringstream s;
    s.precision(10);
    s << v;
    if (!unit.empty() && unit != "-") s << " " << unit;
    return s.str();
}

// Reads --name (in user units) into *si if present.
void read(const ParsedOptions& o, const Units& u, const char* name, Quantity q, double* si)
{
    if (o.has(name)) *si = u.to_si(q, o.number(name, 0.0));
}

void require(bool ok, const char* name, const std::string& rule, double si_value, Quantity q,
             const Units& u)
{
    if (!ok)
        throw usage_error(std::string("--") + name,
                          rule + " (got " + show(u.from_si(q, si_value), u.label(q)) + ")");
}

void read_flexibilities(const ParsedOptions& o, const Units& u, cw_params& p)
{
    const int given = o.has("L1") + o.has("L2") + o.has("L3");
    if (given == 0) return;
    if (given != 3) {
        const char* missing = !o.has("L1") ? "--L1" : !o.has("L2") ? "--L2" : "--L3";
        throw usage_error(missing, "--L1, --L2 and --L3 must be given together");
    }
    if (o.has("G") || o.has("nu"))
        throw usage_error(o.has("G") ? "--G" : "--nu",
                          "not used when --L1, --L2, --L3 give the flexibilities");
    p.flexibility = CW_FLEX_GIVEN;
    const struct {
        const char* name;
        double* value;
    } flex[] = {{"L1", &p.L1}, {"L2", &p.L2}, {"L3", &p.L3}};
    for (const auto& f : flex) {
        read(o, u, f.name, Quantity::flexibility, f.value);
        require(*f.value > 0.0, f.name, "must be > 0", *f.value, Quantity::flexibility, u);
    }
}

void validate_params(const ParsedOptions& o, const cw_params& p, const Units& u)
{
    require(p.a > 0.0, "a", "must be > 0", p.a, Quantity::length, u);
    require(p.b > 0.0, "b", "must be > 0", p.b, Quantity::length, u);
    const double ratio = p.a / p.b;
    if (!(ratio >= CW_MIN_ASPECT && ratio <= CW_MAX_ASPECT))
        throw usage_error(o.has("a") == o.has("b") ? "--a/--b"
                          : o.has("a")             ? "--a"
                                                   : "--b",
                          "a/b = " + show(ratio, "") +
                              " is outside [1e-3, 1e3], the range of Kalker's coefficients");
    require(p.normal_force >= 0.0, "N", "must be >= 0", p.normal_force, Quantity::force, u);
    require(p.mu >= 0.0, "mu", "must be >= 0", p.mu, Quantity::dimensionless, u);
    if (p.flexibility == CW_FLEX_FROM_MATERIAL) {
        require(p.G > 0.0, "G", "must be > 0", p.G, Quantity::stress, u);
        require(p.nu >= 0.0 && p.nu <= 0.5, "nu", "must lie in [0, 0.5]", p.nu,
                Quantity::dimensionless, u);
    }
}

cw_grid read_grid(const ParsedOptions& o, const cw_grid& defaults, int model)
{
    cw_grid g = defaults;
    if (o.has("grid"))
        g.kind = o.text("grid", "") == "uniform" ? CW_GRID_UNIFORM : CW_GRID_KALKER_STRIPS;
    if (model == CW_MODEL_EXACT) {
        if (g.kind != CW_GRID_UNIFORM && o.has("grid"))
            throw usage_error("--grid", "the exact model needs the uniform grid (give --grid "
                                        "uniform, or no --grid: it is then the default)");
        if (g.kind != CW_GRID_UNIFORM) {
            // CONTACT's layout (doc/theory/exact.md): the ellipse inside a
            // box 1.2 times larger, two guard cells on each side at 20 across.
            g.kind = CW_GRID_UNIFORM;
            g.nx = static_cast<int>(std::lround(kExactBoxScale * g.nx));
            g.ny = static_cast<int>(std::lround(kExactBoxScale * g.ny));
            g.box_scale = kExactBoxScale;
        }
    }
    g.nx = o.integer("nx", g.nx);
    g.ny = o.integer("ny", g.ny);
    g.box_scale = o.number("box-scale", g.box_scale);
    const std::string range = "must lie in 1.." + std::to_string(CW_MAX_GRID_CELLS);
    if (g.nx < 1 || g.nx > CW_MAX_GRID_CELLS)
        throw usage_error("--nx", range + " (got " + std::to_string(g.nx) + ")");
    if (g.ny < 1 || g.ny > CW_MAX_GRID_CELLS)
        throw usage_error("--ny", range + " (got " + std::to_string(g.ny) + ")");
    if (o.has("box-scale") && g.kind != CW_GRID_UNIFORM)
        throw usage_error("--box-scale", "only used with --grid uniform");
    if (!(g.box_scale >= 1.0 && g.box_scale <= CW_MAX_BOX_SCALE))
        throw usage_error("--box-scale", "must lie in [1, 100] so the box holds the ellipse (got " +
                                             show(g.box_scale, "") + ")");
    if (model == CW_MODEL_EXACT)
        for (const auto& [name, n] : {std::pair<const char*, int>{"--nx", g.nx}, {"--ny", g.ny}})
            if (n > CW_MAX_EXACT_CELLS)
                throw usage_error(name, "the exact model takes at most " +
                                            std::to_string(CW_MAX_EXACT_CELLS) +
                                            " elements per direction (got " + std::to_string(n) +
                                            ")");
    return g;
}

// --model and the options of the exact model. Options another model would
// silently ignore are errors, so a run never shows what was not asked for.
void read_model(const ParsedOptions& o, cw_params& p)
{
    if (o.has("model"))
        p.model = o.text("model", "") == "exact"        ? CW_MODEL_EXACT
                  : o.text("model", "") == "calibrated" ? CW_MODEL_CALIBRATED
                                                        : CW_MODEL_FASTSIM;
    if (p.model != CW_MODEL_EXACT) {
        for (const char* name : {"tolerance", "max-iterations"})
            if (o.has(name))
                throw usage_error(std::string("--") + name, "only used with --model exact");
        return;
    }
    const char* unused[][2] = {
        {"L1", "the exact model needs G and nu, not the flexibilities of the simplified theory"},
        {"L2", "the exact model needs G and nu, not the flexibilities of the simplified theory"},
        {"L3", "the exact model needs G and nu, not the flexibilities of the simplified theory"},
        {"pressure", "not used by the exact model: it solves its own normal problem"},
        {"flexibility-blending", "a FASTSIM option, not used by the exact model"}};
    for (const auto& u : unused)
        if (o.has(u[0])) throw usage_error(std::string("--") + u[0], u[1]);
    if (o.has("tolerance")) {
        p.tolerance = o.number("tolerance", 0.0);
        if (!(p.tolerance >= 1e-13 && p.tolerance < 1.0))
            throw usage_error("--tolerance", "must lie in [1e-13, 1) (got " +
                                                 show(p.tolerance, "") + "; default 1e-8)");
    }
    if (o.has("max-iterations")) {
        p.max_iterations = o.integer("max-iterations", 0);
        if (p.max_iterations < 1)
            throw usage_error("--max-iterations", "must be >= 1 (got " +
                                                      std::to_string(p.max_iterations) +
                                                      "; default 50)");
    }
}

void require_given(const ParsedOptions& o)
{
    std::string missing;
    for (const char* name : {"a", "b", "N"})
        if (!o.has(name)) missing += std::string(missing.empty() ? "" : ", ") + "--" + name;
    if (!missing.empty())
        throw usage_error(missing, "missing: the contact's semi-axes and load have no sensible "
                                   "default (e.g. --a 6e-3 --b 6e-3 --N 80e3: a 6 mm circle "
                                   "under 80 kN; a, b from wheel and rail radii: "
                                   "doc/tutorial.md)");
}

// The library's material and friction defaults, named when they are used.
void note_defaults(const ParsedOptions& o, const cw_params& p, const Units& u,
                   std::vector<std::string>& notes)
{
    std::string used;
    const auto add = [&](const char* name, const std::string& text) {
        if (!o.has(name)) used += (used.empty() ? "" : ", ") + text;
    };
    add("mu", "mu = " + show(p.mu, ""));
    if (p.flexibility == CW_FLEX_FROM_MATERIAL) {
        add("G", "G = " + show(u.from_si(Quantity::stress, p.G), u.label(Quantity::stress)));
        add("nu", "nu = " + show(p.nu, ""));
    }
    if (!used.empty())
        notes.push_back("note: not given, so the library's defaults (steel on steel) were used: " +
                        used);
}

} // namespace

void print_notes(const ContactSetup& c)
{
    for (const std::string& note : c.notes) std::fprintf(stderr, "creepwork: %s\n", note.c_str());
}

std::vector<std::string> plausibility_warnings(const cw_params& p, const Units& u)
{
    std::vector<std::string> w;
    const auto warn = [&](const char* option, double si, Quantity q, const std::string& why) {
        w.push_back(std::string("--") + option + " = " + show(u.from_si(q, si), u.label(q)) +
                    " is implausible for a wheel-rail contact: " + why);
    };
    for (const auto& [name, v] : {std::pair<const char*, double>{"a", p.a}, {"b", p.b}}) {
        if (v > 0.1)
            warn(name, v, Quantity::length,
                 "semi-axes are 1-20 mm (were millimetres typed as metres? the CLI reads SI "
                 "unless --units paper)");
        else if (v < 1e-4)
            warn(name, v, Quantity::length, "semi-axes are 1-20 mm, not below 0.1 mm");
    }
    if (p.normal_force > 1e7)
        warn("N", p.normal_force, Quantity::force, "wheel loads are below 1 MN (kN typed as N?)");
    else if (p.normal_force > 0.0 && p.normal_force < 100.0)
        warn("N", p.normal_force, Quantity::force,
             "wheel loads are 1-500 kN (kN typed where N are read?)");
    if (p.mu > 1.5) warn("mu", p.mu, Quantity::dimensionless, "dry steel on steel is 0.1-0.6");
    if (p.flexibility == CW_FLEX_FROM_MATERIAL) {
        if (p.G < 1e6)
            warn("G", p.G, Quantity::stress,
                 "steel is 8.2e10 Pa (a modulus in MPa or N/mm^2 typed as Pa?)");
        else if (p.G > 1e12)
            warn("G", p.G, Quantity::stress, "steel is 8.2e10 Pa, no solid exceeds 1e12 Pa");
    } else {
        for (const auto& [name, v] :
             {std::pair<const char*, double>{"L1", p.L1}, {"L2", p.L2}, {"L3", p.L3}})
            if (v > 1e-10 || v < 1e-18)
                warn(name, v, Quantity::flexibility,
                     "Kalker's flexibilities of steel contacts are ~5e-14 m/Pa (mm^3/N are "
                     "1e-9 m^3/N)");
    }
    for (const auto& [name, v] :
         {std::pair<const char*, double>{"xi-x", p.xi_x}, {"xi-y", p.xi_y}})
        if (std::fabs(v) > 0.5)
            warn(name, v, Quantity::dimensionless,
                 "creepages are ratios, usually below 0.02 (a per cent typed as a ratio?)");
    if (std::fabs(p.phi) > 50.0)
        warn("spin", p.phi, Quantity::spin,
             "spin of wheel-rail contacts stays below ~20 1/m (1/mm typed as 1/m?)");
    return w;
}

ContactSetup read_contact(const ParsedOptions& o, const cw_params& defaults,
                          const cw_grid& default_grid, SizeAndLoad size_and_load)
{
    if (size_and_load == SizeAndLoad::required) require_given(o);
    ContactSetup c;
    c.units = Units::named(o.text("units", "si"));
    const Units& u = c.units;
    cw_params p = defaults;
    read(o, u, "a", Quantity::length, &p.a);
    read(o, u, "b", Quantity::length, &p.b);
    read(o, u, "N", Quantity::force, &p.normal_force);
    read(o, u, "mu", Quantity::dimensionless, &p.mu);
    read(o, u, "G", Quantity::stress, &p.G);
    read(o, u, "nu", Quantity::dimensionless, &p.nu);
    read(o, u, "xi-x", Quantity::dimensionless, &p.xi_x);
    read(o, u, "xi-y", Quantity::dimensionless, &p.xi_y);
    read(o, u, "spin", Quantity::spin, &p.phi);
    read_model(o, p);
    read_flexibilities(o, u, p);
    if (o.has("pressure"))
        p.pressure =
            o.text("pressure", "") == "elliptic" ? CW_PRESSURE_ELLIPTIC : CW_PRESSURE_PARABOLIC;
    if (o.has("rolling-direction"))
        p.rolling_direction = o.text("rolling-direction", "+1") == "-1" ? -1 : 1;
    // CONTACT's FASTSIM defaults (doc/migrating.md).
    if (o.has("spin-offset")) {
        p.spin_offset = o.number("spin-offset", 0.0);
        if (!(p.spin_offset >= 0.0 && p.spin_offset <= 1.0))
            throw usage_error("--spin-offset", "must lie in [0, 1] element lengths (got " +
                                                   show(p.spin_offset, "") + "; CONTACT: 1/6)");
    }
    if (o.has("flexibility-blending")) p.flexibility_blending = 1;
    validate_params(o, p, u);
    for (const std::string& warning : plausibility_warnings(p, u))
        c.notes.push_back("warning: " + warning);
    if (size_and_load == SizeAndLoad::required) note_defaults(o, p, u, c.notes);
    c.params = p;
    c.grid = read_grid(o, default_grid, p.model);
    return c;
}

} // namespace cwcli
