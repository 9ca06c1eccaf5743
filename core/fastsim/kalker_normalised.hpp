// Kalker's original normalised FASTSIM interface (1982): unit-disk
// coordinates, parabolic bound 1 - x^2 - y^2, one flexibility folded into the
// normalised creepages, outputs F/(mu N) with the signs of Kalker's program.
#pragma once

namespace creepwork {

// The signs of Kalker's published check values (kalker1982_checks.csv),
// so that an old FASTSIM caller gets the numbers it always got: tx is the
// rail's x-force (sign of ux), ty the wheel's y-force (opposite sign to uy),
// each divided by mu N. In the library's convention (forces on the wheel):
// tx = -Fx/(mu N), ty = +Fy/(mu N).
struct NormalisedForces {
    double tx, ty;
};

// ux, uy: creepages; fx, fy: spin terms; rigid slip (ux - y fx, uy + x fy).
// mx elements per strip. my and tol set Kalker's strip layout: the strips
// are cut at the y of the spin pole (-uy/fy, ux/fx) when the pole lies in
// the contact (else at y = 0), my strips are shared between the two sides
// (each rounded up), and the strips next to the cut are bisected until
// their centres lie within tol of it (see kalker_normalised.cpp). This
// reproduces Kalker's published check values (kalker1982_checks.csv).
NormalisedForces kalker_fastsim_normalised(double ux, double uy, double fx, double fy, int mx,
                                           int my, double tol);

} // namespace creepwork
