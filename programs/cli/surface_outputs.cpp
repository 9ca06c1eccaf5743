#include "surface_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "cli_error.hpp"
#include "contact_solver.hpp"
#include "options.hpp"
#include "report.hpp"

namespace cwcli {

// Helpers in a namespace of their own: the program is built in unity
// batches, where the files' anonymous namespaces are one.
namespace surface_options_detail {

const char* const kTemperatureNumbers[][2] = {
    {"T0-1", "T0_1"}, {"T0-2", "T0_2"}, {"heat-capacity-1", "heat_capacity_1"},
    {"heat-capacity-2", "heat_capacity_2"}, {"conductivity-1", "conductivity_1"},
    {"conductivity-2", "conductivity_2"}, {"density-1", "density_1"}, {"density-2", "density_2"}};

// The option that sets a field the library's checks name.
std::string option_of(const std::string& field)
{
    if (field == "rolling_speed") return "speed";
    if (field == "k_yield") return "k-yield";
    for (const auto& n : kTemperatureNumbers)
        if (field == n[1]) return n[0];
    return field;
}

double* temperature_field(cw_temperature_params& p, const std::string& field)
{
    if (field == "T0_1") return &p.T0_1;
    if (field == "T0_2") return &p.T0_2;
    if (field == "heat_capacity_1") return &p.heat_capacity_1;
    if (field == "heat_capacity_2") return &p.heat_capacity_2;
    if (field == "conductivity_1") return &p.conductivity_1;
    if (field == "conductivity_2") return &p.conductivity_2;
    if (field == "density_1") return &p.density_1;
    return &p.density_2;
}

// The library's message, with the options that set the fields it names.
[[noreturn]] void rejected(int status, const char* detail, const char* call)
{
    const std::string text = detail && *detail ? detail : cw_status_string(status);
    throw CliError(status == CW_ERR_INTERNAL ? kExitFailure : kExitUsage,
                   std::string("library rejected the input (") + call + "): " + text +
                       options_named_in(text));
}

template <class T>
struct Destroy {
    int (*destroy)(T*);
    void operator()(T* p) const { destroy(p); }
};

// The library's checks of the surface parameters (cw_temperature_params_check,
// cw_damage_params_check), each input named by its option. At most 7
// findings (6 thermal properties and the speed; 4 of damage).
void add_checks(int (*check)(const void*, cw_check*, size_t, size_t*), const void* params,
                std::vector<std::string>& w)
{
    cw_check c[16];
    size_t found = 0;
    for (cw_check& k : c) cw_check_init(&k);
    if (check(params, c, 16, &found) != CW_OK) return;
    for (size_t k = 0; k < found; ++k) {
        const std::string input = c[k].input;
        w.push_back("warning: --" + option_of(input) + (c[k].message + input.size()));
    }
}

int temperature_check(const void* p, cw_check* out, size_t len, size_t* found)
{
    return cw_temperature_params_check(static_cast<const cw_temperature_params*>(p), out, len,
                                       found);
}

int damage_check(const void* p, cw_check* out, size_t len, size_t* found)
{
    return cw_damage_params_check(static_cast<const cw_damage_params*>(p), out, len, found);
}

std::vector<std::string> implausible(const SurfaceRequest& r)
{
    std::vector<std::string> w;
    if (r.temperature) add_checks(temperature_check, &r.temperature_params, w);
    if (r.damage) add_checks(damage_check, &r.damage_params, w);
    return w;
}

// "T1:mu1,T2:mu2,...": the pairs as written; their values (order, range,
// count) are the library's to check.
void read_mu_T(const std::string& text, std::vector<double>& T, std::vector<double>& mu)
{
    size_t at = 0;
    while (at <= text.size()) {
        const size_t end = std::min(text.find(',', at), text.size());
        const std::string pair = text.substr(at, end - at);
        const size_t colon = pair.find(':');
        double t = 0.0, m = 0.0;
        if (colon == std::string::npos || !parse_finite_double(pair.substr(0, colon), t) ||
            !parse_finite_double(pair.substr(colon + 1), m))
            throw usage_error("--mu-T", "\"" + pair +
                                            "\" is not a pair T:mu (deg C and the coefficient), "
                                            "as in \"0:0.33,400:0.14\"");
        T.push_back(t);
        mu.push_back(m);
        at = end + 1;
    }
}

} // namespace surface_options_detail

using namespace surface_options_detail;

std::vector<OptionSpec> temperature_options()
{
    using K = OptionKind;
    std::vector<OptionSpec> specs = {{"temperature", K::flag, {}},
                                     {"temperature-discretisation", K::choice,
                                      {"consistent", "contact"}}};
    for (const auto& n : kTemperatureNumbers) specs.push_back({n[0], K::number, {}});
    return specs;
}

std::vector<OptionSpec> surface_options()
{
    using K = OptionKind;
    std::vector<OptionSpec> specs = temperature_options();
    specs.push_back({"mu-T", K::text, {}});
    specs.push_back({"speed", K::number, {}});
    specs.push_back({"k-yield", K::number, {}});
    return specs;
}

cw_temperature_params read_temperature_params(const ParsedOptions& opts)
{
    cw_temperature_params p;
    cw_temperature_params_init(&p);
    const bool on = opts.has("temperature");
    for (const char* name : {"temperature-discretisation", "T0-1", "T0-2", "heat-capacity-1",
                             "heat-capacity-2", "conductivity-1", "conductivity-2", "density-1",
                             "density-2"})
        if (opts.has(name) && !on)
            throw usage_error(std::string("--") + name, "needs --temperature");
    for (const auto& n : kTemperatureNumbers)
        if (opts.has(n[0])) *temperature_field(p, n[1]) = opts.number(n[0], 0.0);
    p.rolling_speed = 0.0;   // the solve's
    p.rolling_direction = 0; // the solve's
    p.discretisation = opts.text("temperature-discretisation", "consistent") == "contact"
                           ? CW_TEMPERATURE_CONTACT
                           : CW_TEMPERATURE_CONSISTENT;
    return p;
}

SurfaceRequest read_surface_options(const ParsedOptions& opts, double speed)
{
    SurfaceRequest r;
    r.temperature = opts.has("temperature");
    r.temperature_params = read_temperature_params(opts);
    cw_damage_params_init(&r.damage_params);
    if (r.temperature) r.temperature_params.rolling_speed = speed; // 0: the solve's V
    if (opts.has("mu-T")) {
        if (!r.temperature) throw usage_error("--mu-T", "needs --temperature");
        read_mu_T(opts.text("mu-T", ""), r.mu_T_temperature, r.mu_T_mu);
    }
    r.damage = opts.has("k-yield");
    if (r.damage) r.damage_params.k_yield = opts.number("k-yield", 0.0);
    r.warnings = implausible(r);
    return r;
}

SurfaceRequest read_surface_request(const ParsedOptions& opts, int rolling_direction, double V)
{
    (void)read_temperature_params(opts); // its refusals come first
    const bool speed = opts.has("speed");
    if (opts.has("temperature")) {
        if (!speed && !(V > 0.0))
            throw usage_error("--temperature", "needs the rolling speed (m/s): --V or --speed");
        const double given = opts.number("speed", 0.0);
        if (speed && V > 0.0 && std::fabs(given - V) > 1e-9 * V)
            throw usage_error("--speed", round_trip_text(given) + " differs from --V " +
                                             round_trip_text(V) +
                                             ": give the rolling speed once, or the same in both");
    } else if (speed) {
        throw usage_error("--speed", "is the rolling speed of --temperature; give that too");
    }
    SurfaceRequest r = read_surface_options(opts, opts.number("speed", 0.0));
    if (r.temperature) r.temperature_params.rolling_direction = rolling_direction;
    return r;
}

namespace surface_options_detail {

using TemperatureHandle = std::unique_ptr<cw_temperature, Destroy<cw_temperature>>;

TemperatureHandle make_temperature(const cw_solver* solver)
{
    cw_temperature* raw = nullptr;
    if (const int st = cw_temperature_create(solver, &raw)) rejected(st, nullptr, "cw_temperature_create");
    return TemperatureHandle(raw, {cw_temperature_destroy});
}

// Both bodies' temperature fields of t's last compute into o.
void read_temperatures(const cw_temperature* t, size_t n, SurfaceOutput& o)
{
    o.rail.resize(n);
    o.wheel.resize(n);
    if (cw_temperature_get_field(t, CW_TEMPERATURE_FIELD_RAIL, o.rail.data(), n) ||
        cw_temperature_get_field(t, CW_TEMPERATURE_FIELD_WHEEL, o.wheel.data(), n))
        throw CliError(kExitFailure, std::string("cw_temperature_get_field failed: ") +
                                         cw_temperature_last_error(t));
}

size_t element_count(const cw_solver* solver)
{
    int nx = 0, ny = 0;
    cw_solver_grid_size(solver, &nx, &ny);
    return static_cast<size_t>(nx) * static_cast<size_t>(ny);
}

// The damage indices of the request on solver's last solve, into o.
void compute_damage(const cw_solver* solver, const SurfaceRequest& request, SurfaceOutput& o)
{
    o.damage = request.damage;
    if (!request.damage) return;
    cw_damage* raw = nullptr;
    if (const int st = cw_damage_create(solver, &raw)) rejected(st, nullptr, "cw_damage_create");
    std::unique_ptr<cw_damage, Destroy<cw_damage>> d(raw, {cw_damage_destroy});
    cw_damage_result_init(&o.damage_result);
    if (const int st = cw_damage_compute(d.get(), solver, &request.damage_params, &o.damage_result))
        rejected(st, cw_damage_last_error(d.get()), "cw_damage_compute");
    const size_t n = element_count(solver);
    o.rcf_index.resize(n);
    if (cw_damage_get_field(d.get(), CW_DAMAGE_FIELD_RCF_INDEX, o.rcf_index.data(), n))
        throw CliError(kExitFailure, std::string("cw_damage_get_field failed: ") +
                                         cw_damage_last_error(d.get()));
}

} // namespace surface_options_detail

SurfaceOutput compute_surface(const cw_solver* solver, const SurfaceRequest& request)
{
    SurfaceOutput o;
    o.temperature = request.temperature;
    if (request.temperature) {
        const TemperatureHandle t = make_temperature(solver);
        cw_temperature_result_init(&o.temperature_result);
        if (const int st = cw_temperature_compute(t.get(), solver, &request.temperature_params,
                                                  &o.temperature_result))
            rejected(st, cw_temperature_last_error(t.get()), "cw_temperature_compute");
        read_temperatures(t.get(), element_count(solver), o);
    }
    compute_damage(solver, request, o);
    return o;
}

namespace {

SurfaceOutput solve_surface_mu_T(cw_solver* solver, const cw_params& params,
                                 const SurfaceRequest& request)
{
    SurfaceOutput o;
    o.temperature = true;
    const TemperatureHandle t = make_temperature(solver);
    cw_mu_temperature m;
    cw_mu_temperature_init(&m);
    m.count = request.mu_T_temperature.size();
    m.temperature = request.mu_T_temperature.data();
    m.mu = request.mu_T_mu.data();
    cw_temperature_result_init(&o.temperature_result);
    if (const int st = cw_temperature_solve(t.get(), solver, &params, &request.temperature_params,
                                            &m, nullptr, &o.temperature_result))
        rejected(st, cw_temperature_last_error(t.get()), "cw_temperature_solve");
    read_temperatures(t.get(), element_count(solver), o);
    compute_damage(solver, request, o);
    return o;
}

} // namespace

SurfaceOutput solve_with_surface(ContactSolver& solver, const cw_params& params,
                                 const SurfaceRequest& request, Solution& s)
{
    if (!request.mu_T()) {
        s = solver.solve_full(params);
        return compute_surface(solver.handle(), request);
    }
    // The temperature's fixed-point loop solves.
    SurfaceOutput o = solve_surface_mu_T(solver.handle(), params, request);
    s = read_solution(solver.handle(), params, solver.grid());
    return o;
}

void hottest_point(const cw_temperature_result& t, double& x, double& y)
{
    const bool rail = t.T_max_1 >= t.T_max_2;
    x = rail ? t.x_max_1 : t.x_max_2;
    y = rail ? t.y_max_1 : t.y_max_2;
}

void add_surface_json(JsonObject& json, const SurfaceOutput& o)
{
    if (o.temperature) {
        const cw_temperature_result& t = o.temperature_result;
        double x = 0.0, y = 0.0;
        hottest_point(t, x, y);
        json.number("T_max_1", t.T_max_1)
            .number("T_max_2", t.T_max_2)
            .number("T_max_x", x)
            .number("T_max_y", y)
            .number("contact_temperature", t.contact_temperature)
            .number("power", t.power)
            .integer("temperature_iterations", t.iterations)
            .text("temperature_discretisation",
                  t.discretisation == CW_TEMPERATURE_CONTACT ? "contact" : "consistent");
    }
    if (o.damage) {
        const cw_damage_result& d = o.damage_result;
        json.number("rcf_index_max", d.rcf_index_max)
            .number("rcf_index_x", d.x_rcf_max)
            .number("rcf_index_y", d.y_rcf_max)
            .number("mu_eff", d.mu_eff)
            .number("FI_surf", d.FI_surf)
            .number("T_gamma", d.T_gamma)
            .number("wlrm_damage", d.wlrm_damage);
    }
}

void print_surface_text(std::ostream& out, const SurfaceOutput& o)
{
    if (o.temperature) {
        const cw_temperature_result& t = o.temperature_result;
        out << "temperature (" << (t.discretisation == CW_TEMPERATURE_CONTACT ? "CONTACT's" : "consistent")
            << " discretisation): rail max " << fmt(t.T_max_1, 5) << " degC at x = "
            << fmt(1e3 * t.x_max_1, 4) << " mm, y = " << fmt(1e3 * t.y_max_1, 4)
            << " mm; wheel max " << fmt(t.T_max_2, 5) << " degC; in contact from "
            << fmt(t.contact_temperature, 5) << " degC; frictional power " << fmt(t.power, 5) << " W\n";
    }
    if (o.damage) {
        const cw_damage_result& d = o.damage_result;
        out << "damage: RCF index max " << fmt(d.rcf_index_max, 4) << ", FI_surf "
            << fmt(d.FI_surf, 4) << " (mu_eff " << fmt(d.mu_eff, 4) << "), T_gamma "
            << fmt(d.T_gamma, 5) << " N, WLRM damage " << fmt(d.wlrm_damage, 4) << " per pass\n";
    }
}

} // namespace cwcli
