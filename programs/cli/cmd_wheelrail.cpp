// creepwork wheelrail: one wheel on one rail from the profiles to the
// forces (cw_wheelrail_*): the wheelset height for a vertical force, every
// contact patch's position, creepages and forces by Kalker's exact theory or
// the fast model, in CONTACT's module-1 conventions (SI units); with --out
// the profiles, every patch's fields and their pictures. Only the public C
// ABI is used.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "cli_error.hpp"
#include "command_common.hpp"
#include "commands.hpp"
#include "contact_inputs.hpp"
#include "json.hpp"
#include "output_dir.hpp"
#include "surface_outputs.hpp"
#include "units.hpp"
#include "wheelrail_data.hpp"
#include "wheelrail_plots.hpp"

namespace cwcli {

namespace {

std::vector<OptionSpec> wheelrail_options()
{
    std::vector<OptionSpec> specs = {{"format", OptionKind::choice, {"text", "json"}},
            {"help", OptionKind::flag, {}},
            {"model", OptionKind::choice, {"exact", "fastsim"}},
            {"out", OptionKind::text, {}},
            {"force", OptionKind::flag, {}},
            {"no-plots", OptionKind::flag, {}},
            {"wheel-profile", OptionKind::text, {}},
            {"rail-profile", OptionKind::text, {}},
            {"profile-unit", OptionKind::number, {}},
            {"wheel-y-offset", OptionKind::number, {}},
            {"rail-y-offset", OptionKind::number, {}},
            {"mirror-wheel", OptionKind::flag, {}},
            {"y-shift", OptionKind::number, {}},
            {"yaw", OptionKind::number, {}},
            {"roll", OptionKind::number, {}},
            {"Fz", OptionKind::number, {}, {"N"}},
            {"mu", OptionKind::number, {}},
            {"friction-law", OptionKind::choice, {"coulomb", "linear", "rational", "exponential", "polach"}},
            {"mu-e1", OptionKind::number, {}},
            {"s-h1", OptionKind::number, {}},
            {"mu-e2", OptionKind::number, {}},
            {"s-h2", OptionKind::number, {}},
            {"polach-A", OptionKind::number, {}},
            {"polach-B", OptionKind::number, {}},
            {"memory-distance", OptionKind::number, {}},
            {"memory-s0", OptionKind::number, {}},
            {"layer-h", OptionKind::number, {}},
            {"layer-G", OptionKind::number, {}},
            {"tau-c0", OptionKind::number, {}},
            {"G", OptionKind::number, {}},
            {"nu", OptionKind::number, {}},
            {"V", OptionKind::number, {}},
            {"pitch-rate", OptionKind::number, {}},
            {"side", OptionKind::choice, {"right", "left"}},
            {"dx", OptionKind::number, {}},
            {"ds", OptionKind::number, {}}};
    for (const OptionSpec& s : temperature_options()) specs.push_back(s);
    return specs;
}

// --temperature: each patch's hottest rail and wheel element, through the C
// ABI (cw_temperature on cw_wheelrail_patch_solver at the patch's rolling
// speed veloc, rolling_direction 0: the patch's). Throws CliError naming the
// option on a library refusal.
struct PatchTemperature {
    double T_max_1 = 0, T_max_2 = 0;
};

std::vector<PatchTemperature> patch_temperatures(const cw_wheelrail* w,
                                                 const std::vector<cw_wheelrail_patch>& patches,
                                                 cw_temperature_params params)
{
    std::vector<PatchTemperature> out;
    for (size_t k = 0; k < patches.size(); ++k) {
        params.rolling_speed = patches[k].veloc;
        const cw_solver* view = cw_wheelrail_patch_solver(w, k);
        if (!view) throw CliError(kExitFailure, cw_wheelrail_last_error(w));
        cw_temperature* raw = nullptr;
        if (cw_temperature_create(view, &raw) != CW_OK)
            throw CliError(kExitFailure, "cw_temperature_create failed");
        const std::unique_ptr<cw_temperature, int (*)(cw_temperature*)> t(raw,
                                                                          cw_temperature_destroy);
        cw_temperature_result r;
        cw_temperature_result_init(&r);
        if (cw_temperature_compute(t.get(), view, &params, &r) != CW_OK)
            throw CliError(kExitUsage, std::string("--temperature: patch ") + std::to_string(k) +
                                           ": " + cw_temperature_last_error(t.get()));
        out.push_back({r.T_max_1, r.T_max_2});
    }
    return out;
}

// The library's findings (cw_wheelrail_check), each naming the option as
// typed: "--y-shift = 0.03 m is implausible for a wheel-rail contact: ...".
std::vector<std::string> warnings(const ParsedOptions& o, const cw_wheelrail* w)
{
    const std::pair<const char*, const char*> options[] = {
        {"y", "y-shift"}, {"roll", "roll"}, {"yaw", "yaw"}, {"Fz", "Fz"},
        {"vs", "V"},      {"vpitch", "pitch-rate"}, {"G", "G"}, {"mu", "mu"},
        {"dx", "dx"},     {"ds", "ds"},     {"wheel_y_offset", "wheel-y-offset"},
        {"layer_h", "layer-h"}, {"layer_G", "layer-G"}, {"tau_c0", "tau-c0"}};
    const std::pair<const char*, const char*> in_reasons[] = {
        {"wheel_y_offset", "--wheel-y-offset"}, {"mirror_wheel", "--mirror-wheel"},
        {"flange_back_position", "the flange-back position"}};
    size_t n = 0;
    if (cw_wheelrail_check(w, nullptr, 0, &n) != CW_OK) return {};
    std::vector<cw_check> checks(n);
    for (cw_check& c : checks) cw_check_init(&c);
    if (n > 0 && cw_wheelrail_check(w, checks.data(), n, &n) != CW_OK) return {};
    std::vector<std::string> out;
    for (size_t k = 0; k < n; ++k) {
        const cw_check& c = checks[k];
        std::string name = std::string("the wheelset height z_ws"); // "z": an output
        for (const auto& [input, option] : options)
            if (c.input == std::string(input)) name = "--" + o.typed(option);
        std::string reason = c.reason;
        for (const auto& [field, text] : in_reasons)
            for (size_t at = reason.find(field); at != std::string::npos; at = reason.find(field, at))
                reason.replace(at, std::string(field).size(), text);
        out.push_back(name + " = " + round_trip_text(c.value) + (*c.unit ? " " : "") + c.unit +
                      " is implausible for a wheel-rail contact: " + reason);
    }
    return out;
}

// --friction-law and its terms (creepwork solve's names) into the
// parameters; Polach's A and B through the library's cw_friction_polach.
// The library checks the terms' values and names them.
void read_friction(const ParsedOptions& o, cw_wheelrail_params& p)
{
    const std::string law = o.text("friction-law", "coulomb");
    for (const char* term : {"mu-e1", "s-h1", "mu-e2", "s-h2"})
        if (o.has(term) && (law == "coulomb" || law == "polach"))
            throw usage_error(std::string("--") + term, "not used with --friction-law " + law);
    for (const char* term : {"polach-A", "polach-B"})
        if (o.has(term) != (law == "polach"))
            throw usage_error(std::string("--") + term,
                              law == "polach" ? "missing: --friction-law polach takes --mu (its mu0), "
                                                "--polach-A and --polach-B"
                                              : "only used with --friction-law polach");
    if (law == "polach") {
        cw_params c;
        cw_params_init(&c);
        char message[256] = "";
        if (cw_friction_polach(p.mu, o.number("polach-A", 0.0), o.number("polach-B", 0.0), &c, message,
                               sizeof message) != CW_OK)
            throw usage_error("--polach-A", message);
        p.friction_law = c.friction_law;
        p.mu = c.mu;
        p.mu_e1 = c.mu_e1;
        p.s_h1 = c.s_h1;
        p.mu_e2 = c.mu_e2;
        p.s_h2 = c.s_h2;
    } else if (law != "coulomb") {
        p.friction_law = law == "linear"     ? CW_FRICTION_LINEAR
                         : law == "rational" ? CW_FRICTION_RATIONAL
                                             : CW_FRICTION_EXPONENTIAL;
        p.mu_e1 = o.number("mu-e1", 0.0);
        p.s_h1 = o.number("s-h1", 0.0);
        p.mu_e2 = o.number("mu-e2", 0.0);
        p.s_h2 = o.number("s-h2", 0.0);
    }
}

// --memory-distance, --memory-s0 (with a law) and --layer-h, --layer-G,
// --tau-c0 (creepwork solve's names, SI) into the parameters; the library
// checks their values and names them.
void read_memory_and_layer(const ParsedOptions& o, cw_wheelrail_params& p)
{
    for (const char* memory : {"memory-distance", "memory-s0"})
        if (o.has(memory) && o.text("friction-law", "coulomb") == "coulomb")
            throw usage_error(std::string("--") + memory,
                              "friction memory acts on a law of the slip speed (--friction-law)");
    p.memory_distance = o.number("memory-distance", 0.0);
    p.memory_s0 = o.number("memory-s0", 0.0);
    p.layer_h = o.number("layer-h", 0.0);
    p.layer_G = o.number("layer-G", 0.0);
    p.tau_c0 = o.number("tau-c0", 0.0);
}

JsonObject patch_json(const cw_wheelrail_patch& p)
{
    JsonObject j;
    j.number("y_contact_rail", p.y_contact_rail)
        .number("z_contact_rail", p.z_contact_rail)
        .number("contact_angle", p.contact_angle)
        .number("cksi", p.cksi)
        .number("ceta", p.ceta)
        .number("cphi", p.cphi)
        .number("Fn", p.Fn)
        .number("Fx_rail", p.Fx)
        .number("Fs_rail", p.Fs)
        .number("Mn_rail", p.Mn)
        .number("p_max", p.p_max)
        .integer("n_contact", p.n_contact)
        .integer("n_adhesion", p.n_adhesion)
        .integer("n_slip", p.n_slip)
        .number("x_contact", p.x_contact)
        .number("y_contact", p.y_contact)
        .number("z_contact", p.z_contact)
        .number("y_contact_wheel", p.y_contact_wheel)
        .number("z_contact_wheel", p.z_contact_wheel)
        .number("veloc", p.veloc)
        .number("approach", p.approach)
        .number("rolling_radius", p.rolling_radius)
        .number("Fx_track", p.Fx_track)
        .number("Fy_track", p.Fy_track)
        .number("Fz_track", p.Fz_track);
    return j;
}

const char* model_description(const std::string& model)
{
    return model == "fastsim" ? "FASTSIM with the semi-Hertzian normal problem"
                           : "Kalker's exact theory";
}

void print_text(std::ostream& out, const std::string& model, const cw_wheelrail_totals& t,
                const std::vector<cw_wheelrail_patch>& patches)
{
    out << "model " << model << ": " << model_description(model) << "\n";
    char line[512];
    std::snprintf(line, sizeof line, "wheelset height z_ws = %.6g mm, %d contact patch%s\n", 1e3 * t.z, t.n_patches,
                  t.n_patches == 1 ? "" : "es");
    out << line;
    out << "patch  y_rail[mm] z_rail[mm] angle[deg]  CKSI        CETA        CPHI[1/m]    Fn[N]      "
           "Fx[N]      Fs[N]      Mn[N m]    p_max[MPa] contact/adhesion/slip\n";
    for (size_t k = 0; k < patches.size(); ++k) {
        const cw_wheelrail_patch& p = patches[k];
        std::snprintf(line, sizeof line,
                      "%-6zu %10.4f %10.4f %10.4f  %-11.4e %-11.4e %-12.4e %-10.6g %-10.6g %-10.6g %-10.4g "
                      "%-10.5g %d/%d/%d\n",
                      k, 1e3 * p.y_contact_rail, 1e3 * p.z_contact_rail, p.contact_angle * 180.0 / 3.14159265358979323846,
                      p.cksi, p.ceta, p.cphi, p.Fn, p.Fx, p.Fs, p.Mn, 1e-6 * p.p_max, p.n_contact,
                      p.n_adhesion, p.n_slip);
        out << line;
    }
    std::snprintf(line, sizeof line, "total on the rail (track coordinates): Fx = %.6g N, Fy = %.6g N, Fz = %.6g N\n",
                  t.Fx, t.Fy, t.Fz);
    out << line;
}

// --out DIR: result.json, profiles.csv, patch_K_fields.csv and the pictures
// (wheelrail_data.hpp, wheelrail_plots.hpp).
void write_output(const std::string& out, const ParsedOptions& o, const cw_wheelrail* w,
                  const cw_wheelrail_params& p, const cw_wheelrail_totals& t,
                  const std::string& model, const JsonObject& json)
{
    const ProfilePoints rail = read_profile(w, CW_WHEELRAIL_RAIL);
    const ProfilePoints wheel = read_profile(w, CW_WHEELRAIL_WHEEL);
    std::vector<PatchView> views;
    long elements = 0;
    for (size_t k = 0; k < static_cast<size_t>(t.n_patches); ++k) {
        views.push_back(read_patch_view(w, k, p));
        elements += static_cast<long>(views.back().solution.size());
    }
    const bool plots = should_plot(o, elements);
    StagedOutput dir(out, "--out", o.has("force"));
    write_json_file(dir.path("result.json"), json);
    write_profiles_csv(dir.path("profiles.csv"), rail, wheel);
    for (size_t k = 0; k < views.size(); ++k)
        write_patch_fields_csv(dir.path("patch_" + std::to_string(k) + "_fields.csv"), w, k,
                               views[k].patch);
    if (plots) write_wheelrail_pictures(dir.path(), rail, wheel, views, t, model);
    dir.commit();
}

} // namespace

int command_wheelrail(int argc, char** argv, int first)
{
    ParsedOptions o;
    if (parse_or_help(wheelrail_options(), argc, argv, first, usage_wheelrail(), o)) return kExitOk;
    for (const char* req : {"wheel-profile", "rail-profile", "Fz"})
        if (!o.has(req)) throw usage_error(std::string("--") + req, "is required (see creepwork wheelrail --help)");
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    p.side = o.text("side", "right") == "left" ? CW_WHEELRAIL_LEFT : CW_WHEELRAIL_RIGHT;
    p.mu = o.number("mu", p.mu);
    p.G = o.number("G", p.G);
    p.nu = o.number("nu", p.nu);
    p.dx = o.number("dx", p.dx);
    p.ds = o.number("ds", p.ds);
    p.profile_unit = o.number("profile-unit", p.profile_unit);
    p.wheel_y_offset = o.number("wheel-y-offset", p.wheel_y_offset);
    p.rail_y_offset = o.number("rail-y-offset", p.rail_y_offset);
    p.mirror_wheel = o.has("mirror-wheel") ? 1 : 0;
    read_friction(o, p);
    read_memory_and_layer(o, p);
    const std::string model = o.text("model", "exact");
    if (model == "fastsim") {
        p.model = CW_MODEL_FASTSIM;
        p.normal_method = CW_NORMAL_SEMI_HERTZ;
    }
    const std::string fz_name = "--" + o.typed("Fz");
    const double fz = o.number("Fz", 0.0);
    const double V = o.number("V", 1.0);
    const double pitch_rate = o.number("pitch-rate", -V / p.nominal_radius);
    if (!(fz > 0.0)) throw usage_error(fz_name, "must be > 0 (N)");
    if (!(V > 0.0)) throw usage_error("--V", "must be > 0 (m/s)");
    if (!(p.dx > 0.0 && p.dx <= 0.1)) throw usage_error("--dx", "must lie in (0, 0.1] m");
    if (!(p.ds > 0.0 && p.ds <= 0.1)) throw usage_error("--ds", "must lie in (0, 0.1] m");
    if (!(p.profile_unit > 0.0 && p.profile_unit <= 1.0) && o.has("profile-unit"))
        throw usage_error("--profile-unit", "must lie in (0, 1] m per unit of the files (1e-3: mm)");
    for (const char* offset : {"wheel-y-offset", "rail-y-offset"})
        if (!(std::fabs(o.number(offset, 0.0)) <= 1.0))
            throw usage_error(std::string("--") + offset, "must lie within +-1 m");
    const cw_temperature_params temperature_params = read_temperature_params(o);
    const std::string out = o.text("out", "");
    if (!out.empty()) check_output_target(out, "--out", o.has("force"));
    else
        for (const char* only_with_out : {"force", "no-plots"})
            if (o.has(only_with_out))
                throw usage_error(std::string("--") + only_with_out, "only used with --out DIR");

    char message[1024] = "";
    cw_wheelrail* raw = nullptr;
    const int created = cw_wheelrail_create(&p, o.text("rail-profile", "").c_str(),
                                            o.text("wheel-profile", "").c_str(), &raw, message, sizeof message);
    if (created != CW_OK) throw CliError(kExitUsage, message);
    const std::unique_ptr<cw_wheelrail, int (*)(cw_wheelrail*)> w(raw, cw_wheelrail_destroy);
    cw_wheelrail_motion m;
    cw_wheelrail_motion_init(&m);
    m.y = o.number("y-shift", 0.0);
    m.yaw = o.number("yaw", 0.0);
    m.roll = o.number("roll", 0.0);
    m.vs = V;
    m.vpitch = pitch_rate;
    cw_wheelrail_totals t;
    cw_wheelrail_totals_init(&t);
    const int solved = cw_wheelrail_solve(w.get(), &m, CW_WHEELRAIL_FORCE, fz, &t);
    const std::string error = cw_wheelrail_last_error(w.get());
    // What looks wrong is said also when the solve failed: it may be why.
    for (const std::string& text : warnings(o, w.get()))
        std::cerr << "creepwork: warning: " << text << "\n";
    if (solved != CW_OK) throw CliError(kExitUsage, error);
    std::vector<cw_wheelrail_patch> patches(static_cast<size_t>(t.n_patches));
    for (size_t k = 0; k < patches.size(); ++k) {
        cw_wheelrail_patch_init(&patches[k]);
        if (cw_wheelrail_get_patch(w.get(), k, &patches[k]) != CW_OK)
            throw CliError(kExitFailure, cw_wheelrail_last_error(w.get()));
    }
    if (!o.has("V") || !o.has("pitch-rate"))
        std::cerr << "creepwork: note: " << (o.has("V") ? "" : "--V 1 m/s, ")
                  << "--pitch-rate " << round_trip_text(pitch_rate)
                  << " rad/s (-V / 0.46 m: rolling at the nominal radius) taken as defaults\n";
    const bool temperature = o.has("temperature");
    const std::vector<PatchTemperature> hot =
        temperature ? patch_temperatures(w.get(), patches, temperature_params)
                    : std::vector<PatchTemperature>();
    std::vector<JsonObject> list;
    for (size_t k = 0; k < patches.size(); ++k) {
        list.push_back(patch_json(patches[k]));
        if (temperature) list.back().number("T_max_1", hot[k].T_max_1).number("T_max_2", hot[k].T_max_2);
    }
    JsonObject total;
    total.number("Fx", t.Fx).number("Fy", t.Fy).number("Fz", t.Fz);
    JsonObject json;
    json.text("model", model)
        .text("sign_convention",
              "CONTACT's module 1: creepages cksi, ceta, cphi of the rail relative to the "
              "wheel; forces and moments *_rail on the rail (doc/reference/conventions.md)")
        .array("patches", list)
        .object("total_rail", total)
        .number("z_ws", t.z);
    if (!out.empty()) write_output(out, o, w.get(), p, t, model, json);
    if (o.text("format", "text") == "json")
        std::cout << json.str(true) << "\n";
    else {
        print_text(std::cout, model, t, patches);
        for (size_t k = 0; k < hot.size(); ++k) {
            char line[160];
            std::snprintf(line, sizeof line,
                          "patch %zu temperature: rail max %.2f degC, wheel max %.2f degC\n", k,
                          hot[k].T_max_1, hot[k].T_max_2);
            std::cout << line;
        }
    }
    return kExitOk;
}

} // namespace cwcli
