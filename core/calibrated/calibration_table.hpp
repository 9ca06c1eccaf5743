// The fitted table of the calibrated model: its parameters as functions of
// a/b, nu and the creepages normalised by their saturation values.
#pragma once

#include "calibrated/calibration_params.hpp"
#include "contact/params.hpp"

namespace creepwork {

// Creepages as fractions of the ones at which Kalker's linear theory reaches
// mu N: xi_x G c^2 C11 / (mu N), xi_y G c^2 C22 / (mu N), phi G c^3 C23 /
// (mu N), c = sqrt(ab). Zero when mu N = 0.
struct NormalisedCreepage {
    double s_long = 0, s_lat = 0, s_spin = 0;
};
NormalisedCreepage normalised_creepage(const ContactInput& in);

// The parameters for one contact (a valid input, flexibilities from G, nu).
CalibrationParams calibration_for(const ContactInput& in);

} // namespace creepwork
