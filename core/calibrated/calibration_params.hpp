// The knobs of the calibrated simplified theory (calibrated_model.hpp): how
// it departs from plain FASTSIM for one contact. The fitted table
// (calibration_table.hpp) gives them per a/b, nu and normalised creepage.
#pragma once

#include "contact/params.hpp"

namespace creepwork {

struct CalibrationParams {
    // Pressure and traction bound of the march.
    PressureKind pressure = PressureKind::elliptic;
    // Factors on the normalised rigid slip over flexibility (fastsim_setup.hpp,
    // NormalisedKinematics), after the spin part of the x-slip has been put on
    // the moment-consistent flexibility L_M (moment_flexibility.hpp):
    double k_long = 1.0;   // ux: a xi / (L1 mu p0)
    double k_lat = 1.0;    // uy: a eta / (L2 mu p0)
    double k_spin_x = 1.0; // cx: a b phi / (L_M mu p0)
    double k_spin_y = 1.0; // cy: a^2 phi / (L3 mu p0)
};

} // namespace creepwork
