// Plausibility of inputs: values a solve accepts but no wheel-rail contact
// has, the signature of a unit mistake (millimetres typed as metres, kN as
// N, MPa as Pa, a per cent as a ratio) or of an input left out. One table
// of rules behind every door (cw_params_check, cw_wheelrail_check; the
// surface post-processors' in contact/surface_plausibility.hpp): the
// command line, Python, Octave and Fortran print what it finds. Nothing
// here warns by itself: a solve in other consistent units stays silent.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace creepwork {

// What the rule found (the values of the header's CW_CHECK_* list).
enum class CheckRule {
    semi_axis = 1,        // a, b outside 0.1 mm .. 0.1 m
    normal_force = 2,     // N (or a wheel load) outside 1 kN .. 10 MN
    friction = 3,         // mu above 1.5
    modulus = 4,          // G (and a layer's layer_G) outside 1 MPa .. 1 TPa
    flexibility = 5,      // L1..L3 outside 1e-18 .. 1e-10 m/Pa
    creepage = 6,         // |xi| above 0.5
    spin = 7,             // |phi| above 50 1/m
    gap_spacing = 8,      // a gap grid's dx, dy outside 1 um .. 5 mm
    gap_heights = 9,      // a gap spanning more than 10 mm
    approach = 10,        // |approach| above 1 mm
    default_geometry = 11, // a, b and N all at cw_params_init's values
    half_speed = 12,      // a friction law's s_h1, s_h2 above 50 m/s
    layer_thickness = 13, // an interface layer's layer_h above 10 mm
    wheelset_shift = 20,  // |y| above 20 mm
    wheelset_angle = 21,  // |roll|, |yaw| above 0.05 rad
    patch_element = 22,   // dx, ds above 5 mm
    speed = 23,           // V (a contact's, a wheelset's forward speed) above 150 m/s
    pitch_rate = 24,      // not about -V / nominal radius
    wheelset_height = 25, // |z| of a tread contact beyond 5 mm
    flange_tip = 26,      // a patch on the wheel's flange tip
    profile_origin = 27,  // the wheel's flange tip on the field side of its origin
    conductivity = 30,    // lambda outside 1 .. 1000 W/(m K)
    heat_capacity = 31,   // c outside 100 .. 5000 J/kg/K
    density = 32,         // rho outside 1000 .. 25000 kg/m^3
    yield_stress = 33,    // k_yield (and a layer's tau_c0 > 0) below 1e6 Pa
    wlrm_threshold = 34,  // a WLRM threshold in (0, 1) N
};

// Rail vehicles run below 150 m/s (540 km/h): a speed above that is in km/h
// (CheckRule::speed, of the wheel/rail case and of the temperature).
constexpr double kSpeedLimit = 150.0;
constexpr const char* kSpeedReason = "rail vehicles run below 150 m/s (km/h typed as m/s?)";

// One rule broken: by which input (a field name of the C structs), its
// value in SI (for gap heights their spread), the unit of that value ("" if
// none) and why it is implausible, with the likely mistake.
struct Implausible {
    CheckRule rule;
    std::string input;
    double value;
    std::string unit;
    std::string reason;
};

// "<input> = <value> <unit> is implausible for a wheel-rail contact:
// <reason>", the value to 10 significant digits; where (e.g. " (2 of 10
// contacts)") follows the value.
std::string implausible_message(const Implausible& w, const std::string& where = "");

// The numbers of one contact that the rules read (SI).
struct ContactPlausibility {
    double a = 0, b = 0, normal_force = 0, mu = 0, G = 0;
    double L1 = 0, L2 = 0, L3 = 0, xi_x = 0, xi_y = 0, phi = 0;
    double V = 0; // the rolling speed [m/s] (0: not given)
    // A friction law's half speeds [m/s] (0: no law, or the term absent).
    double s_h1 = 0, s_h2 = 0;
    // An interface layer's thickness [m], shear modulus [Pa] (read when the
    // thickness is > 0) and yield stress [Pa] (0: none).
    double layer_h = 0, layer_G = 0, tau_c0 = 0;
    bool flexibilities_given = false;
    // A contact of any shape (a gap grid): a and b are not used, the
    // spacing and the gap's heights are.
    bool gap_grid = false;
    double dx = 0, dy = 0;
    const double* gap = nullptr; // nx*ny heights, or nullptr
    std::size_t gap_count = 0;
    bool approach_given = false;
    double approach = 0;
    // a, b and N hold cw_params_init's values: left out?
    bool default_geometry = false;
};

// The rules one contact breaks, in a fixed order (one entry per rule and
// input; the order of the rule table, so several contacts' findings merge
// by their index): index_out[k] is the table row of out[k].
void check_contact(const ContactPlausibility& c, std::vector<Implausible>& out,
                   std::vector<int>& index_out);

} // namespace creepwork
