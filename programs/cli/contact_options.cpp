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
            {"V", K::number, {}},
            {"G", K::number, {}},
            {"nu", K::number, {}},
            {"L1", K::number, {}},
            {"L2", K::number, {}},
            {"L3", K::number, {}},
            {"pressure", K::choice, {"parabolic", "elliptic"}},
            {"rolling-direction", K::choice, {"+1", "1", "-1"}},
            {"units", K::choice, {"si", "paper"}},
            {"spin-offset", K::number, {}},
            {"flexibility-blending", K::flag, {}},
            {"exact-load", K::flag, {}}};
}

std::vector<OptionSpec> friction_options()
{
    using K = OptionKind;
    return {{"friction-law", K::choice, {"coulomb", "linear", "rational", "exponential", "polach"}},
            {"mu-e1", K::number, {}},
            {"s-h1", K::number, {}},
            {"mu-e2", K::number, {}},
            {"s-h2", K::number, {}},
            {"polach-A", K::number, {}},
            {"polach-B", K::number, {}},
            {"polach", K::text, {}},
            {"friction-speed", K::choice, {"local", "global"}},
            {"k0", K::number, {}},
            {"alpha-inf", K::number, {}},
            {"beta", K::number, {}},
            {"memory-distance", K::number, {}},
            {"memory-s0", K::number, {}},
            {"layer-h", K::number, {}},
            {"layer-G", K::number, {}},
            {"tau-c0", K::number, {}},
            {"k-tau", K::number, {}}};
}

std::vector<OptionSpec> creepage_options()
{
    using K = OptionKind;
    return {{"xi-x", K::number, {}}, {"xi-y", K::number, {}}, {"spin", K::number, {}, {"phi"}}};
}

std::vector<OptionSpec> grid_options()
{
    using K = OptionKind;
    return {{"grid", K::choice, {"kalker_strips", "uniform"}},
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

OptionSource::OptionSource(const ParsedOptions& opts)
    : opts_(opts), units_(Units::named(opts.text("units", "si")))
{
}

std::string OptionSource::name(Input in) const
{
    return "--" + opts_.typed(info(in).option);
}

bool OptionSource::has(Input in) const { return *info(in).option && opts_.has(info(in).option); }

double OptionSource::number(Input in) const { return opts_.number(info(in).option, 0.0); }

int OptionSource::integer(Input in) const { return opts_.integer(info(in).option, 0); }

// parse_options has checked the value against the option's choices.
std::string OptionSource::choice(Input in, const std::vector<std::string>&) const
{
    return opts_.text(info(in).option, "");
}

void OptionSource::raise(const std::string& names, const std::string& problem, Refusal) const
{
    throw usage_error(names, problem);
}

namespace {

std::string show(double v, const std::string& unit)
{
    return round_trip_text(v) + (!unit.empty() && unit != "-" ? " " + unit : "");
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
    if (!o.has("polach")) add("mu", "mu = " + show(p.mu, ""));
    if (p.flexibility == CW_FLEX_FROM_MATERIAL) {
        add("G", "G = " + show(u.from_si(Quantity::stress, p.G), u.label(Quantity::stress)));
        add("nu", "nu = " + show(p.nu, ""));
    }
    if (!used.empty())
        notes.push_back("note: not given, so the library's defaults (steel on steel) were used: " +
                        used);
}

// --polach MU0,A,B: Polach's law written into p by the library
// (cw_friction_polach), in place of --friction-law and its terms and --mu.
void read_polach(const ParsedOptions& o, cw_params& p)
{
    if (!o.has("polach")) return;
    for (const char* other : {"friction-law", "mu", "mu-e1", "s-h1", "mu-e2", "s-h2", "polach-A",
                              "polach-B"})
        if (o.has(other))
            throw usage_error("--polach/--" + o.typed(other),
                              "--polach MU0,A,B sets the friction law and mu: give one of them");
    const std::string text = o.text("polach", "");
    double v[3] = {};
    std::istringstream in(text);
    char comma[2] = {};
    if (!(in >> v[0] >> comma[0] >> v[1] >> comma[1] >> v[2]) || comma[0] != ',' ||
        comma[1] != ',' || !(in >> std::ws).eof())
        throw usage_error("--polach", "must be MU0,A,B (e.g. 0.36,0.38,0.7; B in s/m), got \"" +
                                          text + "\"");
    char message[256] = "";
    if (cw_friction_polach(v[0], v[1], v[2], &p, message, sizeof message) != CW_OK)
        throw usage_error("--polach", message);
    if (!(p.V > 0.0))
        throw usage_error("--V", "must be > 0 (m/s): --polach is a law of the slip speed");
}

} // namespace

void print_notes(const ContactSetup& c)
{
    for (const std::string& note : c.notes) std::fprintf(stderr, "creepwork: %s\n", note.c_str());
}

ContactSetup read_contact(const ParsedOptions& o, const cw_params& defaults,
                          const cw_grid& default_grid, SizeAndLoad size_and_load)
{
    if (size_and_load == SizeAndLoad::required) require_given(o);
    const OptionSource source(o);
    // solve --gap: the gap file gives the grid (its options are refused
    // there) and the exact model is the default.
    const bool gap = size_and_load == SizeAndLoad::gap;
    cw_params start = defaults;
    if (gap) start.model = CW_MODEL_EXACT;
    const ContactInputs in =
        read_contact_inputs(source, start, gap ? library_default_grid() : default_grid);
    ContactSetup c;
    c.units = source.units();
    c.params = in.params;
    read_polach(o, c.params);
    c.grid = size_and_load == SizeAndLoad::gap ? default_grid : in.grid;
    // A gap's contact is checked with its file (command_solve_gap).
    if (!gap)
        for (const std::string& warning : plausibility_warnings(c.grid, c.params, source))
            c.notes.push_back("warning: " + warning);
    if (size_and_load != SizeAndLoad::defaulted) note_defaults(o, c.params, c.units, c.notes);
    return c;
}

} // namespace cwcli
