#include "contact_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

#include "options.hpp"

namespace cwcli {

const std::vector<InputInfo>& all_inputs()
{
    using Q = Quantity;
    using I = Input;
    static const std::vector<InputInfo> list = {
        {I::a, "a", "a", Q::length},
        {I::b, "b", "b", Q::length},
        {I::N, "N", "N", Q::force},
        {I::mu, "mu", "mu", Q::dimensionless},
        {I::G, "G", "G", Q::stress},
        {I::nu, "nu", "nu", Q::dimensionless},
        {I::L1, "L1", "L1", Q::flexibility},
        {I::L2, "L2", "L2", Q::flexibility},
        {I::L3, "L3", "L3", Q::flexibility},
        {I::xi_x, "xi-x", "xi_x", Q::dimensionless},
        {I::xi_y, "xi-y", "xi_y", Q::dimensionless},
        {I::phi, "spin", "phi", Q::spin},
        {I::model, "model", "model", Q::dimensionless},
        {I::grid, "grid", "grid", Q::dimensionless},
        {I::nx, "nx", "nx", Q::dimensionless},
        {I::ny, "ny", "ny", Q::dimensionless},
        {I::box_scale, "box-scale", "box_scale", Q::dimensionless},
        {I::pressure, "pressure", "pressure", Q::dimensionless},
        {I::rolling_direction, "rolling-direction", "rolling_direction", Q::dimensionless},
        {I::spin_offset, "spin-offset", "spin_offset", Q::dimensionless},
        {I::flexibility_blending, "flexibility-blending", "flexibility_blending",
         Q::dimensionless},
        {I::exact_load, "exact-load", "exact_load", Q::dimensionless},
        {I::tolerance, "tolerance", "tolerance", Q::dimensionless},
        {I::max_iterations, "max-iterations", "max_iterations", Q::dimensionless},
        {I::id, "", "id", Q::dimensionless},
        {I::s0, "", "s0", Q::length},
        {I::distance, "", "distance", Q::length},
        {I::body, "body", "body", Q::dimensionless},
        {I::contact_angle, "", "contact_angle", Q::dimensionless},
        {I::passes, "", "passes", Q::dimensionless},
        {I::speed, "speed", "speed", Q::dimensionless},
        {I::gap_file, "gap", "gap_file", Q::dimensionless},
        {I::approach, "approach", "approach", Q::length},
        {I::normal_method, "normal-method", "normal_method", Q::dimensionless},
        {I::V, "V", "V", Q::dimensionless}, // m/s in every unit system
        {I::friction_law, "friction-law", "friction_law", Q::dimensionless},
        {I::mu_e1, "mu-e1", "mu_e1", Q::dimensionless},
        {I::s_h1, "s-h1", "s_h1", Q::dimensionless}, // m/s in every unit system
        {I::mu_e2, "mu-e2", "mu_e2", Q::dimensionless},
        {I::s_h2, "s-h2", "s_h2", Q::dimensionless},
        {I::polach_A, "polach-A", "polach_A", Q::dimensionless},
        {I::polach_B, "polach-B", "polach_B", Q::dimensionless}, // s/m in every unit system
        {I::friction_speed, "friction-speed", "friction_speed", Q::dimensionless},
        {I::k0, "k0", "k0", Q::dimensionless},
        {I::alpha_inf, "alpha-inf", "alpha_inf", Q::dimensionless},
        {I::beta, "beta", "beta", Q::dimensionless},
        {I::memory_distance, "memory-distance", "memory_distance", Q::length},
        {I::memory_s0, "memory-s0", "memory_s0", Q::dimensionless}, // m/s
        {I::layer_h, "layer-h", "layer_h", Q::length},
        {I::layer_G, "layer-G", "layer_G", Q::stress},
        {I::tau_c0, "tau-c0", "tau_c0", Q::stress},
        {I::k_tau, "k-tau", "k_tau", Q::dimensionless}, // Pa/m in every unit system
    };
    return list;
}

const InputInfo& info(Input in) { return all_inputs()[static_cast<size_t>(in)]; }

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

cw_grid model_default_grid(int model)
{
    cw_grid g;
    cw_grid_init_model(&g, model);
    return g;
}

double effective_tolerance(const cw_params& p)
{
    return p.tolerance > 0.0 ? p.tolerance : CW_DEFAULT_TOLERANCE;
}

int effective_max_iterations(const cw_params& p)
{
    return p.max_iterations > 0 ? p.max_iterations : CW_DEFAULT_MAX_ITERATIONS;
}

const char* grid_kind_name(int kind)
{
    return kind == CW_GRID_UNIFORM ? "uniform" : "kalker_strips";
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

std::string value_text(const InputNames& names, Input in, double value_si)
{
    const Quantity q = info(in).quantity;
    const Units& u = names.units();
    std::string text = round_trip_text(u.from_si(q, value_si));
    if (q != Quantity::dimensionless) text += " " + u.label(q);
    return text;
}

namespace {

using Refusal = ContactSource::Refusal;

struct Reader {
    const ContactSource& s;

    // The input's value in SI into *si, if the source has it.
    void read(Input in, double* si) const
    {
        if (s.has(in)) *si = s.units().to_si(info(in).quantity, s.number(in));
    }
    [[noreturn]] void refuse(Input in, const std::string& problem, Refusal why) const
    {
        s.fail(s.name(in), problem, why);
    }
    // A value outside its range: "<rule> (got <value>)".
    void require(bool ok, Input in, const std::string& rule, double value_si,
                 Refusal why = Refusal::invalid_input) const
    {
        if (!ok) refuse(in, rule + " (got " + value_text(s, in, value_si) + ")", why);
    }
};

void read_flexibilities(const Reader& r, cw_params& p)
{
    const ContactSource& s = r.s;
    const int given = s.has(Input::L1) + s.has(Input::L2) + s.has(Input::L3);
    if (given == 0) return;
    const std::string together = s.name(Input::L1) + ", " + s.name(Input::L2) + " and " +
                                 s.name(Input::L3) + " must be given together";
    if (given != 3)
        r.refuse(!s.has(Input::L1) ? Input::L1 : !s.has(Input::L2) ? Input::L2 : Input::L3,
                 together, Refusal::unreadable);
    for (Input in : {Input::G, Input::nu})
        if (s.has(in))
            r.refuse(in, "not used when " + s.name(Input::L1) + ", " + s.name(Input::L2) + ", " +
                             s.name(Input::L3) + " give the flexibilities",
                     Refusal::unreadable);
    p.flexibility = CW_FLEX_GIVEN;
    const struct {
        Input in;
        double* value;
    } flex[] = {{Input::L1, &p.L1}, {Input::L2, &p.L2}, {Input::L3, &p.L3}};
    for (const auto& f : flex) {
        r.read(f.in, f.value);
        r.require(*f.value > 0.0, f.in, "must be > 0", *f.value);
    }
}

// The model and the inputs of the exact model. Inputs another model would
// silently ignore are refused, so a run never shows what was not asked for.
void read_model(const Reader& r, cw_params& p)
{
    const ContactSource& s = r.s;
    if (s.has(Input::model)) {
        const std::string m = s.choice(Input::model, {"fastsim", "exact", "calibrated"});
        p.model = m == "exact" ? CW_MODEL_EXACT : m == "calibrated" ? CW_MODEL_CALIBRATED
                                                                    : CW_MODEL_FASTSIM;
    }
    if (p.model != CW_MODEL_EXACT) {
        for (Input in : {Input::tolerance, Input::max_iterations})
            if (s.has(in))
                r.refuse(in, "only used with the exact model (" + s.name(Input::model) + " exact)",
                         Refusal::unreadable);
        return;
    }
    const std::string flex =
        "the exact model needs G and nu, not the flexibilities of the simplified theory";
    const struct {
        Input in;
        bool given;
        const char* why;
    } unused[] = {
        {Input::L1, s.has(Input::L1), flex.c_str()},
        {Input::L2, s.has(Input::L2), flex.c_str()},
        {Input::L3, s.has(Input::L3), flex.c_str()},
        {Input::pressure, s.has(Input::pressure),
         "not used by the exact model: it solves its own normal problem"},
        {Input::flexibility_blending, s.has(Input::flexibility_blending) &&
                                          s.flag(Input::flexibility_blending),
         "a FASTSIM option, not used by the exact model"}};
    for (const auto& u : unused)
        if (u.given) r.refuse(u.in, u.why, Refusal::unreadable);
    if (s.has(Input::tolerance)) {
        p.tolerance = s.number(Input::tolerance);
        r.require(p.tolerance >= 1e-13 && p.tolerance < 1.0, Input::tolerance,
                  "must lie in [1e-13, 1) (default 1e-8)", p.tolerance);
    }
    if (s.has(Input::max_iterations)) {
        p.max_iterations = s.integer(Input::max_iterations);
        r.require(p.max_iterations >= 1, Input::max_iterations, "must be >= 1 (default 50)",
                  p.max_iterations);
    }
}

const std::vector<std::string> kFrictionLaws = {"coulomb", "linear", "rational", "exponential",
                                                 "polach"};

// The friction law: CONTACT's terms, or Polach's A and B with mu as mu0
// written by the library (cw_friction_polach); where FASTSIM takes the slip
// speed, Spiryagin's reduction (global only) and the memory (local only).
// Inputs the chosen law does not read are refused.
void read_friction(const Reader& r, cw_params& p)
{
    const ContactSource& s = r.s;
    const std::string law = s.has(Input::friction_law)
                                ? s.choice(Input::friction_law, kFrictionLaws)
                                : "coulomb";
    const Input terms[] = {Input::mu_e1, Input::s_h1, Input::mu_e2, Input::s_h2};
    const Input polach[] = {Input::polach_A, Input::polach_B};
    const std::string named = s.name(Input::friction_law) + " " + law;
    for (Input in : terms)
        if (s.has(in) && (law == "coulomb" || law == "polach"))
            r.refuse(in, "not used with " + named, Refusal::unreadable);
    for (Input in : polach)
        if (s.has(in) && law != "polach")
            r.refuse(in, "only used with " + s.name(Input::friction_law) + " polach",
                     Refusal::unreadable);
    if (law == "polach") {
        for (Input in : polach)
            if (!s.has(in))
                r.refuse(in, "missing: " + named + " takes mu (its mu0), " +
                                 s.name(Input::polach_A) + " and " + s.name(Input::polach_B),
                         Refusal::unreadable);
        double A = 0.0, B = 0.0;
        r.read(Input::polach_A, &A);
        r.read(Input::polach_B, &B);
        r.require(A >= 0.0 && A <= 1.0, Input::polach_A, "must lie in [0, 1]", A);
        r.require(B > 0.0, Input::polach_B, "must be > 0 (s/m)", B);
        r.require(p.mu >= 0.0, Input::mu, "must be >= 0", p.mu);
        char message[256] = "";
        if (cw_friction_polach(p.mu, A, B, &p, message, sizeof message) != CW_OK)
            r.refuse(Input::polach_A, message, Refusal::invalid_input);
    } else if (law != "coulomb") {
        p.friction_law = law == "linear"     ? CW_FRICTION_LINEAR
                         : law == "rational" ? CW_FRICTION_RATIONAL
                                             : CW_FRICTION_EXPONENTIAL;
        for (const auto& [in, value] : {std::pair<Input, double*>{Input::mu_e1, &p.mu_e1},
                                        {Input::s_h1, &p.s_h1},
                                        {Input::mu_e2, &p.mu_e2},
                                        {Input::s_h2, &p.s_h2}})
            r.read(in, value);
        r.require(p.mu_e1 >= 0.0, Input::mu_e1, "must be >= 0", p.mu_e1);
        r.require(p.mu_e2 >= 0.0, Input::mu_e2, "must be >= 0", p.mu_e2);
        r.require(p.mu_e1 == 0.0 || p.s_h1 > 0.0, Input::s_h1,
                  "must be > 0 (m/s) when " + s.name(Input::mu_e1) + " > 0", p.s_h1);
        r.require(p.mu_e2 == 0.0 || p.s_h2 > 0.0, Input::s_h2,
                  "must be > 0 (m/s) when " + s.name(Input::mu_e2) + " > 0", p.s_h2);
    }
    if (s.has(Input::friction_speed))
        p.friction_speed = s.choice(Input::friction_speed, {"local", "global"}) == "global"
                               ? CW_FRICTION_SPEED_GLOBAL
                               : CW_FRICTION_SPEED_LOCAL;
    const bool global = p.friction_speed == CW_FRICTION_SPEED_GLOBAL;
    for (const auto& [in, value] : {std::pair<Input, double*>{Input::k0, &p.k0},
                                    {Input::alpha_inf, &p.alpha_inf},
                                    {Input::beta, &p.beta}}) {
        if (s.has(in) && !global)
            r.refuse(in, "Spiryagin's slope reduction is only used with " +
                             s.name(Input::friction_speed) + " global",
                     Refusal::unreadable);
        r.read(in, value);
    }
    r.require(p.k0 > 0.0, Input::k0, "must be > 0", p.k0);
    r.require(p.alpha_inf >= 0.0 && p.alpha_inf <= 1.0, Input::alpha_inf, "must lie in [0, 1]",
              p.alpha_inf);
    r.require(p.beta >= 0.0, Input::beta, "must be >= 0", p.beta);
    for (const auto& [in, value] : {std::pair<Input, double*>{Input::memory_distance,
                                                              &p.memory_distance},
                                    {Input::memory_s0, &p.memory_s0}}) {
        if (s.has(in) && global)
            r.refuse(in, "friction memory needs " + s.name(Input::friction_speed) + " local",
                     Refusal::unreadable);
        r.read(in, value);
        r.require(*value >= 0.0, in, "must be >= 0", *value);
    }
    if (p.friction_law != CW_FRICTION_COULOMB)
        r.require(p.V > 0.0, Input::V,
                  "must be > 0 (m/s): " + named + " is a law of the slip speed", p.V);
}

// The interface layer: an elastic compliance layer_h / layer_G and a yield
// stress; the library refuses it for a model without it.
void read_layer(const Reader& r, cw_params& p)
{
    const ContactSource& s = r.s;
    r.read(Input::layer_h, &p.layer_h);
    r.read(Input::layer_G, &p.layer_G);
    r.read(Input::tau_c0, &p.tau_c0);
    if (s.has(Input::k_tau)) p.k_tau = s.number(Input::k_tau);
    r.require(p.layer_h >= 0.0, Input::layer_h, "must be >= 0", p.layer_h);
    if (s.has(Input::layer_G) && !(p.layer_h > 0.0))
        r.refuse(Input::layer_G, "only used with " + s.name(Input::layer_h) + " > 0",
                 Refusal::unreadable);
    r.require(p.layer_h == 0.0 || p.layer_G > 0.0, Input::layer_G,
              "must be > 0 when " + s.name(Input::layer_h) + " > 0", p.layer_G);
    r.require(p.tau_c0 >= 0.0, Input::tau_c0, "must be >= 0 (0: no yield)", p.tau_c0);
    r.require(std::isfinite(p.k_tau), Input::k_tau, "must be a finite number", p.k_tau);
    if (s.has(Input::k_tau) && !(p.tau_c0 > 0.0))
        r.refuse(Input::k_tau, "only used with " + s.name(Input::tau_c0) + " > 0",
                 Refusal::unreadable);
}

void validate(const Reader& r, const cw_params& p)
{
    const ContactSource& s = r.s;
    r.require(p.a > 0.0, Input::a, "must be > 0", p.a);
    r.require(p.b > 0.0, Input::b, "must be > 0", p.b);
    const double ratio = p.a / p.b;
    if (!(ratio >= CW_MIN_ASPECT && ratio <= CW_MAX_ASPECT))
        s.fail(s.has(Input::a) == s.has(Input::b)
                   ? s.name(Input::a) + "/" + s.name(Input::b)
                   : s.name(s.has(Input::a) ? Input::a : Input::b),
               "a/b = " + round_trip_text(ratio) +
                   " is outside [1e-3, 1e3], the range of Kalker's coefficients",
               Refusal::invalid_input);
    r.require(p.normal_force >= 0.0, Input::N, "must be >= 0", p.normal_force);
    r.require(p.mu >= 0.0, Input::mu, "must be >= 0", p.mu);
    r.require(p.V >= 0.0, Input::V, "must be >= 0 (m/s)", p.V);
    if (p.flexibility == CW_FLEX_FROM_MATERIAL) {
        r.require(p.G > 0.0, Input::G, "must be > 0", p.G);
        r.require(p.nu >= 0.0 && p.nu <= 0.5, Input::nu, "must lie in [0, 0.5]", p.nu);
    }
}

cw_grid read_grid(const Reader& r, const cw_grid& defaults, int model)
{
    const ContactSource& s = r.s;
    cw_grid g = defaults;
    if (s.has(Input::grid))
        g.kind = s.choice(Input::grid, {"kalker_strips", "uniform"}) == "uniform" ? CW_GRID_UNIFORM
                                                                           : CW_GRID_KALKER_STRIPS;
    if (model == CW_MODEL_EXACT) {
        if (g.kind != CW_GRID_UNIFORM && s.has(Input::grid))
            r.refuse(Input::grid,
                     "the exact model needs the uniform grid (give uniform, or no grid: it is "
                     "then the default)",
                     Refusal::unreadable);
        if (g.kind != CW_GRID_UNIFORM) {
            // The library's default for the exact model, with the default
            // grid's element size (its box is box_scale times the ellipse).
            const cw_grid exact = model_default_grid(CW_MODEL_EXACT);
            g.kind = exact.kind;
            g.nx = static_cast<int>(std::lround(exact.box_scale * g.nx));
            g.ny = static_cast<int>(std::lround(exact.box_scale * g.ny));
            g.box_scale = exact.box_scale;
        }
    }
    if (s.has(Input::nx)) g.nx = s.integer(Input::nx);
    if (s.has(Input::ny)) g.ny = s.integer(Input::ny);
    const std::string range = "must lie in 1.." + std::to_string(CW_MAX_GRID_CELLS);
    r.require(g.nx >= 1 && g.nx <= CW_MAX_GRID_CELLS, Input::nx, range, g.nx,
              Refusal::grid_out_of_range);
    r.require(g.ny >= 1 && g.ny <= CW_MAX_GRID_CELLS, Input::ny, range, g.ny,
              Refusal::grid_out_of_range);
    if (s.has(Input::box_scale)) {
        if (g.kind != CW_GRID_UNIFORM)
            r.refuse(Input::box_scale, "only used with the uniform grid", Refusal::unreadable);
        g.box_scale = s.number(Input::box_scale);
    }
    r.require(g.box_scale >= 1.0 && g.box_scale <= CW_MAX_BOX_SCALE, Input::box_scale,
              "must lie in [1, 100] so the box holds the ellipse", g.box_scale,
              Refusal::grid_out_of_range);
    if (model == CW_MODEL_EXACT)
        for (const auto& [in, n] : {std::pair<Input, int>{Input::nx, g.nx}, {Input::ny, g.ny}})
            r.require(n <= CW_MAX_EXACT_CELLS, in,
                      "the exact model takes at most " + std::to_string(CW_MAX_EXACT_CELLS) +
                          " elements per direction",
                      n, Refusal::grid_out_of_range);
    return g;
}

} // namespace

ContactInputs read_contact_inputs(const ContactSource& s, const cw_params& defaults,
                                  const cw_grid& default_grid)
{
    const Reader r{s};
    cw_params p = defaults;
    r.read(Input::a, &p.a);
    r.read(Input::b, &p.b);
    r.read(Input::N, &p.normal_force);
    r.read(Input::mu, &p.mu);
    r.read(Input::V, &p.V);
    r.read(Input::G, &p.G);
    r.read(Input::nu, &p.nu);
    r.read(Input::xi_x, &p.xi_x);
    r.read(Input::xi_y, &p.xi_y);
    r.read(Input::phi, &p.phi);
    read_model(r, p);
    read_flexibilities(r, p);
    read_friction(r, p);
    read_layer(r, p);
    if (s.has(Input::pressure))
        p.pressure = s.choice(Input::pressure, {"parabolic", "elliptic"}) == "elliptic"
                         ? CW_PRESSURE_ELLIPTIC
                         : CW_PRESSURE_PARABOLIC;
    if (s.has(Input::rolling_direction))
        p.rolling_direction =
            s.choice(Input::rolling_direction, {"+1", "1", "-1"}) == "-1" ? -1 : 1;
    // CONTACT's FASTSIM options (doc/migrating.md).
    if (s.has(Input::spin_offset)) {
        p.spin_offset = s.number(Input::spin_offset);
        r.require(p.spin_offset >= 0.0 && p.spin_offset <= 1.0, Input::spin_offset,
                  "must lie in [0, 1] element lengths (CONTACT: 1/6)", p.spin_offset);
    }
    if (s.has(Input::flexibility_blending))
        p.flexibility_blending = s.flag(Input::flexibility_blending) ? 1 : 0;
    if (s.has(Input::exact_load)) p.exact_load = s.flag(Input::exact_load) ? 1 : 0;
    validate(r, p);
    return {p, read_grid(r, default_grid, p.model)};
}

std::vector<cw_check> library_checks(const cw_grid& grid, const cw_params* params, size_t count)
{
    size_t n = 0;
    if (cw_params_check(&grid, params, count, nullptr, 0, &n) != CW_OK) return {};
    std::vector<cw_check> checks(n);
    for (cw_check& c : checks) cw_check_init(&c);
    if (n > 0 && cw_params_check(&grid, params, count, checks.data(), n, &n) != CW_OK) return {};
    checks.resize(n);
    return checks;
}

std::vector<std::string> plausibility_warnings(const cw_grid& grid, const cw_params& p,
                                               const InputNames& names,
                                               const std::string& gap_path)
{
    // The library's inputs by the command's names; a gap's spacing and
    // heights by the gap file's.
    const std::pair<const char*, Input> inputs[] = {
        {"a", Input::a},       {"b", Input::b},       {"normal_force", Input::N},
        {"mu", Input::mu},     {"G", Input::G},       {"L1", Input::L1},
        {"L2", Input::L2},     {"L3", Input::L3},     {"xi_x", Input::xi_x},
        {"xi_y", Input::xi_y}, {"phi", Input::phi},   {"approach", Input::approach},
        {"V", Input::V},       {"s_h1", Input::s_h1}, {"s_h2", Input::s_h2},
        {"layer_h", Input::layer_h}, {"layer_G", Input::layer_G}, {"tau_c0", Input::tau_c0}};
    std::vector<std::string> w;
    for (const cw_check& c : library_checks(grid, &p, 1)) {
        // Every command requires a, b and N, or takes documented defaults.
        if (c.rule == CW_CHECK_DEFAULT_GEOMETRY) continue;
        const std::string tail = " is implausible for a wheel-rail contact: " + std::string(c.reason);
        const auto found = std::find_if(std::begin(inputs), std::end(inputs),
                                        [&](const auto& i) { return c.input == std::string(i.first); });
        if (found != std::end(inputs))
            w.push_back(names.label(found->second) + " = " +
                        value_text(names, found->second, c.value) + tail);
        else { // dx, dy, gap: of the gap file, read in metres (to 6 digits: from its coordinates)
            char value[32];
            std::snprintf(value, sizeof value, "%.6g", c.value);
            w.push_back(names.label(Input::gap_file) + ": " + gap_path + ": " + c.input + " = " +
                        value + " " + c.unit + tail);
        }
    }
    return w;
}

std::vector<std::string> wear_row_warnings(double s0, double contact_angle, double passes,
                                           const InputNames& names)
{
    std::vector<std::string> w;
    if (std::fabs(s0) > 0.2)
        w.push_back(names.label(Input::s0) + " = " + value_text(names, Input::s0, s0) +
                    " is implausible: profile coordinates lie within +-0.1 m (mm typed as m?)");
    if (std::fabs(contact_angle) > 1.3)
        w.push_back(names.label(Input::contact_angle) + " = " + round_trip_text(contact_angle) +
                    " rad is implausible: flange angles stay below 75 degrees (degrees typed as "
                    "radians?)");
    if (passes > 1e9)
        w.push_back(names.label(Input::passes) + " = " + round_trip_text(passes) +
                    " is implausible for one state (rails see ~1e7 axles a year)");
    return w;
}

std::vector<std::string> wear_option_warnings(const cw_wear_params& p, double wheel_radius)
{
    std::vector<std::string> w;
    if (wheel_radius > 0 && (wheel_radius > 2.0 || wheel_radius < 0.1))
        w.push_back("--wheel-radius = " + round_trip_text(wheel_radius) +
                    " m is implausible for a railway wheel: radii are 0.3-0.65 m (mm typed as m?)");
    if (p.rolling_speed > 150)
        w.push_back("--speed = " + round_trip_text(p.rolling_speed) +
                    " m/s is implausible: trains run below 150 m/s (km/h typed as m/s?)");
    if (p.density > 0 && (p.density < 1000 || p.density > 25000))
        w.push_back("--density = " + round_trip_text(p.density) +
                    " kg/m^3 is implausible for steel (7800 kg/m^3; g/cm^3 typed?)");
    if (p.law == CW_WEAR_ARCHARD_KTH && p.hardness > 0 && p.hardness < 5e8)
        w.push_back("--hardness = " + round_trip_text(p.hardness) +
                    " Pa is implausible for rail or wheel steel (2-4e9 Pa; MPa or HB typed as "
                    "Pa?)");
    return w;
}

} // namespace cwcli
