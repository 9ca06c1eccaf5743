// Kalker's original normalised FASTSIM interface (1982): unit-disk
// coordinates, parabolic bound 1 - x^2 - y^2, one flexibility folded into the
// normalised creepages, outputs F/(mu N) with the sign of the creepages.
#pragma once

namespace creepwork {

struct NormalisedForces {
    double tx, ty; // force on the rail (body 2) / (mu N)
};

// ux, uy: creepages; fx, fy: spin terms; rigid slip (ux - y fx, uy + x fy).
// mx elements per strip, my strips; tol: strip-split tolerance.
NormalisedForces kalker_fastsim_normalised(double ux, double uy, double fx, double fy, int mx,
                                           int my, double tol);

} // namespace creepwork
