// The Whole Life Rail Model's rolling-contact-fatigue damage per pass as a
// function of the contact's T_gamma [N] (the frictional work per rolled
// distance, F_x xi_x + F_y xi_y (+ M_z phi)): Burstow's piecewise-linear
// damage function (M. C. Burstow, Whole Life Rail Model application and
// development for RSSB, AEA Technology Rail, 2004): no damage below an
// onset, rising linearly to a peak, falling linearly to zero where wear
// removes the cracks as fast as they grow, zero beyond.
//
// Defaults: onset 20 N, peak 1e-5 per pass at 65 N, zero at 175 N, as
// coded in the open-source aliSaleh123/railway_project
// (crack_initiation/create_di_df.py: 2.22e-7 T - 4.44e-6 up to 65 N,
// -9.09e-8 T + 1.59e-5 up to 175 N, the rounded slopes of these points).
// Burstow's report is also quoted with an onset of 15 N; the thresholds are
// parameters: check them against your copy of the report.
#pragma once

namespace creepwork::damage {

struct WlrmFunction {
    double onset = 20.0;       // T_gamma where damage starts [N]
    double peak = 65.0;        // T_gamma of the largest damage [N]
    double zero = 175.0;       // T_gamma where damage is zero again [N]
    double peak_damage = 1e-5; // damage per pass at the peak [-]
};

// Throws Error(invalid_input) naming the parameter (wlrm_onset, ...):
// 0 <= onset < peak < zero <= 1e6 N, peak_damage in [0, 1].
void validate(const WlrmFunction& f);

// Damage per pass [-] (a fraction of the life to crack initiation).
double wlrm_damage(double T_gamma, const WlrmFunction& f);

} // namespace creepwork::damage
