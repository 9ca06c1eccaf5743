#include "wheelrail/placement_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace creepwork::wheelrail {
namespace {

constexpr double kShiftLimit = 20e-3;   // [m] the flange meets the rail within about 10 mm
constexpr double kAngleLimit = 0.05;    // [rad] wheelset roll and yaw
constexpr double kHeightLimit = 5e-3;   // [m] |z| of a tread contact
constexpr double kTipDepth = 3e-3;      // [m] a patch this close to the tip is on the tip
constexpr double kFlangeHeight = 10e-3; // [m] a flange stands out at least this much
constexpr double kTreadAngle = 0.35;    // [rad] contact angles of tread contacts stay below
constexpr double kTipFromBack = 45e-3;  // [m] beyond the thickest flange

// A computed length shown to 10 um (the value of a finding).
double rounded(double metres) { return std::round(metres * 1e5) / 1e5; }

std::string mm(double metres)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%+.1f mm", 1e3 * metres);
    return buf;
}

// The wheel's flange: its tip, the knot of largest z (z down), and
// whether it stands out below both ends of the profile as a flange does.
struct Flange {
    double y_tip = 0, z_tip = 0;
    bool real = false; // stands out by kFlangeHeight or more
};

Flange flange_of(const Profile& wheel)
{
    Flange f;
    const auto& y = wheel.knots_y();
    const auto& z = wheel.knots_z();
    size_t tip = 0;
    for (size_t k = 1; k < z.size(); ++k)
        if (z[k] > z[tip]) tip = k;
    f.y_tip = y[tip];
    f.z_tip = z[tip];
    f.real = f.z_tip - std::min(z.front(), z.back()) >= kFlangeHeight;
    return f;
}

} // namespace

std::vector<Implausible> check_wheelrail(const WheelRailGeometry& g, const WheelRailInputs& in)
{
    std::vector<Implausible> out;
    const auto add = [&out](CheckRule rule, const char* input, double value, const char* unit,
                            const std::string& reason) {
        out.push_back({rule, input, value, unit, reason});
    };
    const Wheelset& ws = g.wheelset();
    const Flange flange = flange_of(g.wheel_profile());
    // A flange tip lies 10-30 mm from the flange back (S1002: 16 mm); a wheel
    // profile measured from its flange back (MiniProf) and placed by
    // flange_back_position as if its origin were on the tread is not.
    const double from_back = flange.y_tip - ws.flange_back_position;
    const bool origin_off = flange.real && (from_back < 0.0 || from_back > kTipFromBack);
    if (origin_off) {
        const double y_back = g.wheel_profile().y_min();
        const bool measured_from_back = std::fabs(y_back) < 5e-3 && from_back > 0.0;
        char where[160];
        std::snprintf(where, sizeof where,
                      "the flange tip lies at y = %+.1f mm, %.1f mm from the flange back at "
                      "flange_back_position = %+.1f mm (a tip lies 10-30 mm from it)",
                      1e3 * flange.y_tip, 1e3 * from_back, 1e3 * ws.flange_back_position);
        add(CheckRule::profile_origin, "wheel_y_offset", 0.0, "m",
            std::string(where) +
                (measured_from_back
                     ? ": the profile starts at its flange back (y = " + mm(y_back) +
                           "): offset it by wheel_y_offset = flange_back_position"
                     : ": offset the profile (wheel_y_offset) so that its origin lies on the tread"));
    }

    // The parameters: units.
    if (in.G > 0.0 && in.G < 1e6)
        add(CheckRule::modulus, "G", in.G, "Pa", "steel is 8.2e10 Pa (a modulus in MPa or N/mm^2 typed as Pa?)");
    else if (in.G > 1e12)
        add(CheckRule::modulus, "G", in.G, "Pa", "steel is 8.2e10 Pa, no solid exceeds 1e12 Pa");
    if (in.mu > 1.5) add(CheckRule::friction, "mu", in.mu, "", "dry steel on steel is 0.1-0.6");
    const struct {
        const char* name;
        double v;
    } elements[] = {{"dx", g.options().dx}, {"ds", g.options().ds}};
    for (const auto& e : elements)
        if (e.v > 5e-3)
            add(CheckRule::patch_element, e.name, e.v, "m",
                "patch elements are 0.1-2 mm (millimetres typed as metres?)");
    // The interface layer's, by a single contact's rules (only its fields set:
    // no other rule reads a zero).
    ContactPlausibility layer;
    layer.layer_h = in.layer_h;
    layer.layer_G = in.layer_G;
    layer.tau_c0 = in.tau_c0;
    std::vector<int> rows;
    check_contact(layer, out, rows);
    if (!in.has_motion) return out;

    // The motion.
    const WheelsetPosition& p = in.position;
    if (std::fabs(p.y) > kShiftLimit)
        add(CheckRule::wheelset_shift, "y", p.y, "m",
            "lateral shifts stay within +-20 mm: the flange meets the rail within about 10 mm "
            "(millimetres typed as metres?)");
    const struct {
        const char* name;
        double v;
    } angles[] = {{"roll", p.roll}, {"yaw", p.yaw}};
    for (const auto& a : angles)
        if (std::fabs(a.v) > kAngleLimit)
            add(CheckRule::wheelset_angle, a.name, a.v, "rad",
                "wheelset angles stay within +-0.05 rad, 3 degrees (degrees or mrad typed as rad?)");
    if (in.force_given && in.Fz > 0.0 && in.Fz < 1000.0)
        add(CheckRule::normal_force, "Fz", in.Fz, "N",
            "wheel loads are 1-500 kN, not below 1 kN (kN typed where N are read?)");
    if (in.vs > kSpeedLimit) add(CheckRule::speed, "vs", in.vs, "m/s", kSpeedReason);
    if (in.vs > 0.0) {
        const double ratio = -in.vpitch * ws.nominal_radius / in.vs;
        if (!(ratio > 0.5 && ratio < 2.0))
            add(CheckRule::pitch_rate, "vpitch", in.vpitch, "rad/s",
                "a wheel rolling at vs turns at about -vs / nominal_radius (rpm typed as rad/s, or "
                "the sign?)");
    }
    if (!in.solved) return out;

    // The solution: where the wheel touches, and the height that follows.
    const WheelRailState& st = g.state();
    bool on_flange = false;
    for (size_t k = 0; k < st.patches.size(); ++k) {
        const ContactPatch& cp = st.patches[k];
        const double depth = flange.z_tip - g.wheel_profile().at(cp.s_w).z;
        if (std::fabs(cp.delta) >= kTreadAngle) on_flange = true;
        if (!flange.real || depth > kTipDepth) continue;
        on_flange = true;
        char where[96];
        std::snprintf(where, sizeof where, "patch %zu touches the wheel %.1f mm from its flange tip", k,
                      1e3 * depth);
        char lifted[64];
        std::snprintf(lifted, sizeof lifted, "%.1f mm %s", 1e3 * std::fabs(in.z),
                      in.z < 0.0 ? "above" : "below");
        add(CheckRule::flange_tip, "z", rounded(in.z), "m",
            std::string(where) + ": the wheelset rides on its flange tip, " + lifted +
                " its nominal height; " +
                (origin_off ? "the wheel profile's origin is off (see wheel_y_offset)"
                            : "the lateral shift y = " + mm(p.y) +
                                  " has lifted it onto the flange (millimetres typed as metres, "
                                  "or the sign of y?)"));
        break;
    }
    if (!on_flange && !st.patches.empty() && std::fabs(in.z) > kHeightLimit)
        add(CheckRule::wheelset_height, "z", rounded(in.z), "m",
            "a tread contact keeps the wheelset within a few mm of its nominal height: a profile's "
            "origin is off by about that much (the wheel's on its tread, nominal_radius from the "
            "axle; the rail's by gauge_height, or rail_y0, rail_z0)");
    return out;
}

} // namespace creepwork::wheelrail
