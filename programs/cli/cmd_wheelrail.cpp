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
#include "units.hpp"
#include "wheelrail_data.hpp"
#include "wheelrail_plots.hpp"

namespace cwcli {

namespace {

std::vector<OptionSpec> wheelrail_options()
{
    return {{"format", OptionKind::choice, {"text", "json"}},
            {"help", OptionKind::flag, {}},
            {"model", OptionKind::choice, {"exact", "fast"}},
            {"out", OptionKind::text, {}},
            {"force", OptionKind::flag, {}},
            {"no-plots", OptionKind::flag, {}},
            {"wheel-profile", OptionKind::text, {}},
            {"rail-profile", OptionKind::text, {}},
            {"y-shift", OptionKind::number, {}},
            {"yaw", OptionKind::number, {}},
            {"roll", OptionKind::number, {}},
            {"Fz", OptionKind::number, {}},
            {"mu", OptionKind::number, {}},
            {"G", OptionKind::number, {}},
            {"nu", OptionKind::number, {}},
            {"V", OptionKind::number, {}},
            {"pitch-rate", OptionKind::number, {}},
            {"side", OptionKind::choice, {"right", "left"}},
            {"dx", OptionKind::number, {}},
            {"ds", OptionKind::number, {}}};
}

// The command's names for the inputs the shared plausibility checks know.
class WheelrailNames : public InputNames {
public:
    std::string name(Input in) const override
    {
        return in == Input::N ? "--Fz" : std::string("--") + info(in).option;
    }
    std::string label(Input in) const override { return name(in); }
    const Units& units() const override { return units_; }
    std::string units_note() const override { return "creepwork wheelrail reads SI units"; }

private:
    Units units_ = Units::si();
};

std::vector<std::string> warnings(const ParsedOptions& o, const cw_wheelrail_params& p, double fz,
                                  double V, double pitch_rate)
{
    cw_params c = library_default_params();
    c.a = c.b = 5e-3; // not an input here
    c.normal_force = fz;
    c.mu = p.mu;
    c.G = p.G;
    c.nu = p.nu;
    std::vector<std::string> w = plausibility_warnings(c, WheelrailNames());
    const auto warn = [&](const std::string& opt, double v, const std::string& why) {
        w.push_back("--" + opt + " = " + round_trip_text(v) + " is implausible for a wheelset: " + why);
    };
    const double y = o.number("y-shift", 0.0);
    if (std::fabs(y) > 0.05) warn("y-shift", y, "lateral shifts stay within +-20 mm (millimetres typed as metres?)");
    for (const char* a : {"yaw", "roll"}) {
        const double v = o.number(a, 0.0);
        if (std::fabs(v) > 0.1) warn(a, v, "wheelset angles stay within +-0.05 rad (degrees or mrad typed as rad?)");
    }
    for (const char* d : {"dx", "ds"}) {
        const double v = o.number(d, 0.2e-3);
        if (v > 5e-3) warn(d, v, "patch elements are 0.1-2 mm (millimetres typed as metres?)");
    }
    if (V > 150.0) warn("V", V, "rail vehicles run below 150 m/s (km/h typed as m/s?)");
    const double ratio = V > 0.0 ? -pitch_rate * p.nominal_radius / V : 1.0;
    if (!(ratio > 0.5 && ratio < 2.0))
        warn("pitch-rate", pitch_rate,
             "a wheel rolling at V turns at about -V / 0.46 m rad/s (rpm typed as rad/s, or the sign?)");
    return w;
}

JsonObject patch_json(const cw_wheelrail_patch& p)
{
    JsonObject j;
    j.number("y_contact_rail", p.y_contact_rail)
        .number("z_contact_rail", p.z_contact_rail)
        .number("contact_angle", p.contact_angle)
        .number("xi_x", p.cksi)
        .number("xi_y", p.ceta)
        .number("phi", p.cphi)
        .number("Fn", p.Fn)
        .number("Fx", p.Fx)
        .number("Fs", p.Fs)
        .number("Mn", p.Mn)
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
    return model == "fast" ? "FASTSIM with the semi-Hertzian normal problem"
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
                      k + 1, 1e3 * p.y_contact_rail, 1e3 * p.z_contact_rail, p.contact_angle * 180.0 / 3.14159265358979323846,
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
    const std::string model = o.text("model", "exact");
    if (model == "fast") {
        p.model = CW_MODEL_FASTSIM;
        p.normal_method = CW_NORMAL_SEMI_HERTZ;
    }
    const double fz = o.number("Fz", 0.0);
    const double V = o.number("V", 1.0);
    const double pitch_rate = o.number("pitch-rate", -V / p.nominal_radius);
    if (!(fz > 0.0)) throw usage_error("--Fz", "must be > 0 (N)");
    if (!(V > 0.0)) throw usage_error("--V", "must be > 0 (m/s)");
    if (!(p.dx > 0.0 && p.dx <= 0.1)) throw usage_error("--dx", "must lie in (0, 0.1] m");
    if (!(p.ds > 0.0 && p.ds <= 0.1)) throw usage_error("--ds", "must lie in (0, 0.1] m");
    for (const std::string& w : warnings(o, p, fz, V, pitch_rate)) std::cerr << "creepwork: warning: " << w << "\n";
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
    if (cw_wheelrail_solve(w.get(), &m, CW_WHEELRAIL_FORCE, fz, &t) != CW_OK)
        throw CliError(kExitUsage, cw_wheelrail_last_error(w.get()));
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
    std::vector<JsonObject> list;
    for (const cw_wheelrail_patch& q : patches) list.push_back(patch_json(q));
    JsonObject total;
    total.number("Fx", t.Fx).number("Fy", t.Fy).number("Fz", t.Fz);
    JsonObject json;
    json.text("model", model).array("patches", list).object("total_rail", total).number("z_ws", t.z);
    if (!out.empty()) write_output(out, o, w.get(), p, t, model, json);
    if (o.text("format", "text") == "json")
        std::cout << json.str(true) << "\n";
    else
        print_text(std::cout, model, t, patches);
    return kExitOk;
}

} // namespace cwcli
