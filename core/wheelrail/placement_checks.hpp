// Plausibility of a wheel/rail case (cw_wheelrail_check): inputs in the
// wrong unit (a lateral shift in mm typed as m, angles in degrees) and
// placements that no running wheel has -- a patch on the wheel's flange
// tip, a wheelset lifted or lowered by centimetres on a tread contact, a
// wheel profile whose flange lies on the field side of its origin --
// each with its likely cause. The findings are the contact's
// (contact/plausibility.hpp), so every door prints them the same way.
#pragma once

#include <vector>

#include "contact/plausibility.hpp"
#include "wheelrail/wheelrail_geometry.hpp"

namespace creepwork::wheelrail {

// The case's inputs that are not in the geometry (SI).
struct WheelRailInputs {
    double mu = 0, G = 0;
    double layer_h = 0, layer_G = 0, tau_c0 = 0; // the interface layer's (contact/plausibility.hpp)
    // The last solve's motion, when one was asked (also when it failed).
    bool has_motion = false;
    WheelsetPosition position;
    double vs = 0, vpitch = 0;
    bool force_given = false;
    double Fz = 0;
    // Whether that solve succeeded: then the geometry's state is its
    // position's, and z its wheelset height.
    bool solved = false;
    double z = 0;
};

// The rules the case breaks, in a fixed order: the profiles, the
// parameters, the motion, the solution.
std::vector<Implausible> check_wheelrail(const WheelRailGeometry& g, const WheelRailInputs& in);

} // namespace creepwork::wheelrail
