#include "contact/plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace creepwork {

namespace {

using C = ContactPlausibility;

const char* const kSemiLarge = "semi-axes are 1-20 mm (were millimetres typed as metres?)";
const char* const kSemiSmall = "semi-axes are 1-20 mm, not below 0.1 mm";
const char* const kFlex =
    "Kalker's flexibilities of steel contacts are ~5e-14 m/Pa (mm^3/N are 1e-9 m^3/N)";
const char* const kCreepage =
    "creepages are ratios, usually below 0.02 (a per cent typed as a ratio?)";
const char* const kHalfSpeed =
    "friction halves over 0.1-10 m/s of slip speed, not above 50 m/s (mm/s typed as m/s?)";
const char* const kSpacing =
    "gap cells are 0.05-1 mm (a gap grid in millimetres typed as metres?)";

// One row of the table: the rule, the input it reads and when it is broken.
struct Row {
    CheckRule rule;
    const char* input;
    const char* unit;
    const char* reason;
    double (*value)(const C&);
    bool (*broken)(const C&, double v);
};

bool elliptic(const C& c) { return !c.gap_grid; }
bool from_material(const C& c) { return !c.flexibilities_given; }

// The spread max - min of the gap's heights (0 without a gap).
double gap_spread(const C& c)
{
    if (!c.gap || c.gap_count == 0) return 0.0;
    double lo = c.gap[0], hi = c.gap[0];
    for (std::size_t k = 1; k < c.gap_count; ++k) {
        lo = std::min(lo, c.gap[k]);
        hi = std::max(hi, c.gap[k]);
    }
    return std::round((hi - lo) * 1e6) / 1e6; // shown to 1 um
}

const Row kRows[] = {
    {CheckRule::default_geometry, "normal_force", "N",
     "a, b and normal_force all hold cw_params_init's values (6 mm, 6 mm, 80 kN): were the "
     "contact's semi-axes and load left out? They have no sensible default",
     [](const C& c) { return c.normal_force; },
     [](const C& c, double) { return elliptic(c) && c.default_geometry; }},
    {CheckRule::semi_axis, "a", "m", kSemiLarge, [](const C& c) { return c.a; },
     [](const C& c, double v) { return elliptic(c) && v > 0.1; }},
    {CheckRule::semi_axis, "a", "m", kSemiSmall, [](const C& c) { return c.a; },
     [](const C& c, double v) { return elliptic(c) && v > 0.0 && v < 1e-4; }},
    {CheckRule::semi_axis, "b", "m", kSemiLarge, [](const C& c) { return c.b; },
     [](const C& c, double v) { return elliptic(c) && v > 0.1; }},
    {CheckRule::semi_axis, "b", "m", kSemiSmall, [](const C& c) { return c.b; },
     [](const C& c, double v) { return elliptic(c) && v > 0.0 && v < 1e-4; }},
    {CheckRule::normal_force, "normal_force", "N", "wheel loads are below 1 MN (kN typed as N?)",
     [](const C& c) { return c.normal_force; }, [](const C&, double v) { return v > 1e7; }},
    // 1-999 is what a load in kN typed as N gives.
    {CheckRule::normal_force, "normal_force", "N",
     "wheel loads are 1-500 kN, not below 1 kN (kN typed where N are read?)",
     [](const C& c) { return c.normal_force; },
     [](const C&, double v) { return v > 0.0 && v < 1000.0; }},
    {CheckRule::friction, "mu", "", "dry steel on steel is 0.1-0.6",
     [](const C& c) { return c.mu; }, [](const C&, double v) { return v > 1.5; }},
    {CheckRule::modulus, "G", "Pa", "steel is 8.2e10 Pa (a modulus in MPa or N/mm^2 typed as Pa?)",
     [](const C& c) { return c.G; },
     [](const C& c, double v) { return from_material(c) && v > 0.0 && v < 1e6; }},
    {CheckRule::modulus, "G", "Pa", "steel is 8.2e10 Pa, no solid exceeds 1e12 Pa",
     [](const C& c) { return c.G; },
     [](const C& c, double v) { return from_material(c) && v > 1e12; }},
    {CheckRule::flexibility, "L1", "m/Pa", kFlex, [](const C& c) { return c.L1; },
     [](const C& c, double v) { return elliptic(c) && !from_material(c) && (v > 1e-10 || v < 1e-18); }},
    {CheckRule::flexibility, "L2", "m/Pa", kFlex, [](const C& c) { return c.L2; },
     [](const C& c, double v) { return elliptic(c) && !from_material(c) && (v > 1e-10 || v < 1e-18); }},
    {CheckRule::flexibility, "L3", "m/Pa", kFlex, [](const C& c) { return c.L3; },
     [](const C& c, double v) { return elliptic(c) && !from_material(c) && (v > 1e-10 || v < 1e-18); }},
    {CheckRule::creepage, "xi_x", "", kCreepage, [](const C& c) { return c.xi_x; },
     [](const C&, double v) { return std::fabs(v) > 0.5; }},
    {CheckRule::creepage, "xi_y", "", kCreepage, [](const C& c) { return c.xi_y; },
     [](const C&, double v) { return std::fabs(v) > 0.5; }},
    {CheckRule::spin, "phi", "1/m",
     "spin of wheel-rail contacts stays below ~20 1/m (1/mm typed as 1/m?)",
     [](const C& c) { return c.phi; }, [](const C&, double v) { return std::fabs(v) > 50.0; }},
    {CheckRule::speed, "V", "m/s", "rail vehicles run below 150 m/s (km/h typed as m/s?)",
     [](const C& c) { return c.V; }, [](const C&, double v) { return v > 150.0; }},
    // CONTACT's examples and the measured laws halve mu over 0.1-10 m/s of
    // slip; a half speed in mm/s typed as m/s gives 100-10000.
    {CheckRule::half_speed, "s_h1", "m/s", kHalfSpeed, [](const C& c) { return c.s_h1; },
     [](const C&, double v) { return v > 50.0; }},
    {CheckRule::half_speed, "s_h2", "m/s", kHalfSpeed, [](const C& c) { return c.s_h2; },
     [](const C&, double v) { return v > 50.0; }},
    {CheckRule::gap_spacing, "dx", "m", kSpacing, [](const C& c) { return c.dx; },
     [](const C& c, double v) { return c.gap_grid && (v > 5e-3 || (v > 0.0 && v < 1e-6)); }},
    {CheckRule::gap_spacing, "dy", "m", kSpacing, [](const C& c) { return c.dy; },
     [](const C& c, double v) { return c.gap_grid && (v > 5e-3 || (v > 0.0 && v < 1e-6)); }},
    // A wheel-rail gap over its potential contact area spans a fraction of
    // a millimetre; 10 mm is far beyond any, and heights in millimetres
    // typed as metres span a thousand times more.
    {CheckRule::gap_heights, "gap", "m",
     "its heights span this much (max - min), a wheel-rail gap a fraction of a millimetre over "
     "its potential contact area (heights in millimetres typed as metres?)",
     gap_spread, [](const C& c, double v) { return c.gap_grid && v > 1e-2; }},
    {CheckRule::approach, "approach", "m",
     "approaches are 10-200 um (millimetres typed as metres?)",
     [](const C& c) { return c.approach; },
     [](const C& c, double v) { return c.gap_grid && c.approach_given && std::fabs(v) > 1e-3; }},
    // Third-body layers are micrometres thick; CONTACT's fitted effective
    // layer of its traction-curve example is 1.25 mm. Millimetres typed as
    // metres give metres.
    {CheckRule::layer_thickness, "layer_h", "m",
     "interface layers are micrometres to about a millimetre thick, not above 10 mm "
     "(millimetres typed as metres?)",
     [](const C& c) { return c.layer_h; }, [](const C&, double v) { return v > 1e-2; }},
    {CheckRule::modulus, "layer_G", "Pa",
     "layer moduli are 10 MPa (MoS2) to 100 GPa, inside 1e6 .. 1e12 Pa (MPa typed as Pa?)",
     [](const C& c) { return c.layer_G; },
     [](const C& c, double v) { return c.layer_h > 0.0 && (v < 1e6 || v > 1e12); }},
    {CheckRule::yield_stress, "tau_c0", "Pa",
     "layers yield at 10-1000 MPa, not below 1e6 Pa (MPa typed as Pa?)",
     [](const C& c) { return c.tau_c0; }, [](const C&, double v) { return v > 0.0 && v < 1e6; }},
};

} // namespace

std::string implausible_message(const Implausible& w, const std::string& where)
{
    char value[48];
    std::snprintf(value, sizeof value, "%.10g", w.value);
    return w.input + " = " + value + (w.unit.empty() ? "" : " " + w.unit) + where +
           " is implausible for a wheel-rail contact: " + w.reason;
}

void check_contact(const ContactPlausibility& c, std::vector<Implausible>& out,
                   std::vector<int>& index_out)
{
    int k = 0;
    for (const Row& r : kRows) {
        const double v = r.value(c);
        // NaN breaks no rule: the solve refuses it with its own message.
        if (std::isfinite(v) && r.broken(c, v)) {
            out.push_back({r.rule, r.input, v, r.unit, r.reason});
            index_out.push_back(k);
        }
        ++k;
    }
}

} // namespace creepwork
