// The knobs of the calibrated simplified theory (calibrated_model.hpp): how
// it departs from plain FASTSIM for one contact. The fitted table
// (calibration_table.hpp) gives them per a/b, nu and normalised creepage.
#pragma once

#include "contact/params.hpp"

namespace creepwork {

struct CalibrationParams {
    // Pressure and traction bound of the march.
    PressureKind pressure = PressureKind::elliptic;
    // Factors on the normalised rigid slip over flexibility
    // (march/march_setup.hpp, NormalisedKinematics), after the spin part of
    // the x-slip has been put on the moment-consistent flexibility L_M
    // (moment_flexibility.hpp):
    double k_long = 1.0;   // ux: a xi / (L1 mu p0)
    double k_lat = 1.0;    // uy: a eta / (L2 mu p0)
    double k_spin_x = 1.0; // cx: a b phi / (L_M mu p0)
    double k_spin_y = 1.0; // cy: a^2 phi / (L3 mu p0)
    // Exponent h of the flexibility equalisation: each component's
    // flexibility L_i (L1, L2, L_M, L3) is replaced by L_i^(1-h) Lc^h, Lc
    // the creepage-weighted geometric mean, so that towards full sliding the
    // tractions oppose the rigid slip, not the rigid slip over flexibility
    // (FASTSIM's direction error when L1 != L2). 0: off.
    double equalise = 0.0;
    // Weight of the x-slip term that gives Kalker's C23 moment for the
    // lateral creepage (calibrated_model.cpp): 1 in the linear limit, faded
    // towards saturation by the table; 0 leaves FASTSIM's Mz(eta).
    double lateral_moment = 1.0;
    // Lateral modulation of the rigid slip (calibrated_rigid_slip in
    // calibrated_model.hpp): exact theory's slip zone reaches further in
    // near y = +-b than FASTSIM's. 0: none.
    double edge_gain = 0.0;
    // Traction bound (and reported pressure) between the laws
    // (blended_bound.hpp): with the parabolic pressure, blended towards the
    // elliptic law, N unchanged; clamped to [0, 1]. 0: the parabolic law.
    double bound_blend = 0.0;
};

} // namespace creepwork
